### Les mots que les outils du livre écrivent dans le livre : les légendes de ses
### listings et l'en-tête de ses tableaux d'exercices (le préprocesseur de
### `cargo xtask book`, xtask/src/listings.rs), les mots des tableaux de `bench` que
### l'édition française traduit (xtask/src/timings.rs), les étiquettes des figures de
### comparaison (book/figures/) et les titres des graphiques de l'édition française
### (book/french-plots.sh).

## La légende d'un listing : `src/file.rs, séance 3, lignes marquées ...`.
book-session = séance
book-gained = , lignes marquées `// +` nouvelles dans cette séance
book-unchanged = , inchangé depuis la séance précédente
book-beyond = au-delà du cours
book-exercises-header = | exercice | ce que vous écrivez | fonction | fichier | ligne de la liste de contrôle |
book-and = {" "}et{" "}

## Les mots d'un tableau de `bench`, tels que la commande les affiche : les plus
## longs d'abord quand l'un en contient un autre. Un nombre d'un tel tableau, ses
## chiffres tels que mesurés.
bench-course-s-code = code du cours
bench-speed-up = accélération
bench-settings = réglages
bench-stage = étape
bench-mrays = Mrayons/s
bench-rays = rayons
bench-course = cours
bench-about = environ
bench-spp = éch./pixel
bench-bounces = rebonds
bench-shadows = ombres
bench-light-sampling = échantillonnage de la lumière
bench-russian-roulette = roulette russe
bench-number = { $value }
bench-seconds = { $value } s
bench-size = { $width } × { $height }
bench-speed-up-times = { $value }×

## Les étiquettes des figures de comparaison (book/src/figures/compare/).
figure-without-antialiasing = sans antialiasing
figure-with-antialiasing = avec antialiasing
figure-with-shadow-rays = avec rayons d'ombre
figure-without-shadow-rays = sans
figure-flat-normals = normales plates
figure-smooth-normals = normales lissées
figure-bounces = { $bounces } { $bounces ->
        [one] rebond
       *[other] rebonds
    }
figure-bounces-and-roulette = { $bounces } { $bounces ->
        [one] rebond
       *[other] rebonds
    } + roulette
figure-converted-to-linear = convertie en linéaire
figure-used-as-it-is = utilisée telle quelle
figure-cost = { $search ->
        [brute-force] force brute
        [box] boîte
       *[bvh] BVH
    } : { NUMBER($mean, minimumFractionDigits: 1, maximumFractionDigits: 1) } tests
figure-at-scale = { $offset ->
        [fixed] epsilon fixe
       *[bound] borne d'erreur
    }, { $scale }

## Les titres des graphiques du chapitre « Vitesse contre précision » : une étape (et son
## étude), puis ce que montre le graphique. book/french-plots.sh lit ces titres.
plot-title-study = { $study } : erreur selon les échantillons et le temps
plot-title-precision = { $study } : les deux précisions, les deux moteurs et Mitsuba 3
