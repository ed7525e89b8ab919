### Les graphiques de `raycourse plot` : l'erreur d'un rendu selon ses échantillons
### par pixel et son temps, pour le chapitre du livre sur la vitesse et la précision.

plot-samples = échantillons par pixel
plot-seconds = secondes
plot-error = RMSE (luminance linéaire)
plot-slope = pente -1/2

plot-number = { NUMBER($value, useGrouping: "false") }

plot-word-bounces = rebonds
plot-word-bounce = rebond
plot-word-brute-force = force brute
plot-word-bounding-box = boîte englobante
plot-word-fast-bvh = BVH rapide
plot-word-light-sampling = échantillonnage de la lumière
plot-word-naive = naïf
plot-word-limit = limite
plot-word-leaf = feuille
plot-word-bilinear = bilinéaire
plot-word-nearest = plus proche
plot-word-single-fast = simple, moteur rapide
plot-word-double-fast = double, moteur rapide
plot-word-single = simple
plot-word-independent = indépendant
plot-word-stratified = stratifié
plot-word-sobol = Sobol
plot-word-adaptive = adaptatif
