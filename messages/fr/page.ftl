### Les pages interactives du livre (book/src/live/) : les réglages des démos des
### séances, ce que leurs images disent à un lecteur d'écran, leurs lignes d'état,
### et la page de vérification.

page-field-of-view = champ de vision (degrés)
page-light-axis = lumière { $axis }
page-albedo = albédo de la sphère
page-gamma = correction gamma ({ NUMBER(2.2) })
page-shadow-offset = décalage du rayon d'ombre
page-offset-robust = juste au-delà de l'erreur d'arrondi du point (celle de la crate)
page-offset = ε = { $epsilon }
page-offset-none = ε = 0 : acné d'ombre
page-centre-sphere = la sphère centrale
page-diffuse = diffuse
page-mirror = miroir
page-glass = verre
page-refractive-index = indice de réfraction
page-samples = échantillons par pixel
page-bounces = rebonds
page-antialiasing = anticrénelage
page-light-radius = rayon de la source
page-light-sampling = échantillonnage de la lumière
page-aperture = ouverture
page-focus = distance de mise au point
page-search = recherche dans le maillage
page-brute-force = force brute
page-bounding-box = boîte englobante
page-bvh = BVH
page-smooth-normals = normales lissées
page-plunge = plongée (degrés) ; faites glisser l'image ou utilisez les flèches pour tourner
page-texture = texture
page-fast = le moteur rapide (au-delà du cours : la même image)
page-number = { $value }
page-stage = étape
# Le titre d'une étape (de son fichier de scène) est en anglais : le nom seul.
page-stage-option = { $stage }

page-on = oui
page-off = non
page-setting = { $control } : { $value }
page-turned = tournée de { $degrees } degrés
page-samples-done =
    { $samples ->
        [one] { $samples } échantillon par pixel
       *[other] { $samples } échantillons par pixel
    }
page-not-done = calcul en cours…
page-image = séance { $session }, étape { $stage } ; { $settings } ; { $done }
page-image-orbit = { page-image }. Les flèches tournent la caméra, comme le glisser.
page-separator = {" ; "}

page-loading = chargement du moteur de rendu…
page-error = erreur : { $message }
page-rendering = calcul de { $stage }…
page-pass = { $stage }, { $size } × { $size } : { page-samples-done } en { $time }
page-pass-done = { page-pass } ({ $workers } workers)
page-pass-refining = { page-pass } ; affinage…
page-pass-look = { $stage }, { $size } × { $size } : un premier aperçu, un échantillon par bloc de { $scale } × { $scale } pixels, en { $time } ; affinage…
page-milliseconds = { NUMBER($ms, maximumFractionDigits: 0) } ms
page-seconds = { NUMBER($seconds, minimumFractionDigits: 1, maximumFractionDigits: 1) } s

page-cost-caption = coût : tests par rayon primaire
page-cost-image = l'image du coût, { $caption }
page-cost-fast = coût : compté pour les recherches du cours seulement
page-cost-mean = coût : { NUMBER($mean, minimumFractionDigits: 1, maximumFractionDigits: 1) } tests par rayon primaire en moyenne
page-functions-course = les fonctions du cours qui ont fait cette image
page-functions-fast = la fonction du moteur rapide qui a fait cette image (au-delà du cours)
page-times-fast = { $search }, moteur rapide
page-times-time = { $time } ({ $samples } échantillons, { $size } × { $size })
page-times-cost = { NUMBER($cost, minimumFractionDigits: 1, maximumFractionDigits: 1) } tests par rayon primaire
page-times-search = recherche
page-times-duration = temps
page-times-cost-head = coût

page-check-stage = séance { $session } : { $stage }
page-check-image = votre image
page-check = vérifier
page-check-differences = les différences : pixels ou blocs différents en rouge
page-check-choose = choisissez d'abord votre image (un fichier PNG, JPEG ou PPM)
page-check-rendering = calcul de la référence…
page-check-rows = calcul de la référence : { $rows } lignes
page-check-matches = correspond
page-check-differs = diffère
page-grade-legend = Une classe, notée comme le fait check --all
page-grade-folder = le dossier de la classe (un dossier par étudiant)
page-grade-images = ou les images d'un étudiant, nommées d'après leurs étapes
page-grade = noter
page-grade-sheet = la feuille de notes, grades.csv
page-grade-choose = choisissez d'abord le dossier d'une classe ou les images d'un étudiant
page-grading = notation…
page-graded = dossiers notés : { $done } / { $count }
page-grade-matching = toutes les images correspondent
page-grade-differing = des images diffèrent
