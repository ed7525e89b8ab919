### Ce que dit le moteur d'un fichier de scène qu'il ne peut pas utiliser
### (`raycourse render`, les commandes `sN`, `probe`) : une ligne qui nomme le
### fichier, la ligne et la colonne quand TOML les connaît, et la clé. La place dans
### le fichier s'écrit comme l'écrivent les compilateurs (`room.toml:16:1:`), ce que
### lisent les éditeurs, dans toutes les langues.

scene-cannot-read = { $file }: impossible de lire le fichier de scène : { $why }
scene-invalid = { $file }:{ $line }:{ $column }: { $message }
scene-invalid-key = { $file }:{ $line }:{ $column }: clé `{ $key }` : { $message }
scene-inconsistent = { $file }: clé `{ $key }` : { $message }
scene-asset = { $file }: { $message } (demandé par { $scene })
scene-needs-feature = { $file }: clé `{ $key }` : { $what } { $remedy }

## Ce que dit le lecteur de TOML (serde) d'une clé, avec les mots que connaît le catalogue.
scene-unknown-field = champ inconnu `{ $field }`, attendu l'un de { $expected }
scene-missing-field = champ manquant `{ $field }`

## Les règles du fichier de scène pour une valeur (src/maths/values.rs).
scene-not-finite = nombre fini attendu, trouvé { $value }
scene-not-positive = nombre supérieur à 0 attendu, trouvé { $value }
scene-negative = nombre positif ou nul attendu, trouvé { $value }
scene-not-probability = probabilité supérieure à 0 et au plus égale à 1 attendue, trouvé { $value }
scene-not-angle = angle entre 0 et 180 degrés attendu, trouvé { $value }
scene-not-albedo = albédo entre 0 et 1 attendu, trouvé { $value }

## Des valeurs acceptables chacune, mais pas ensemble.
scene-too-many-pixels = { $width } × { $height } font { NUMBER($pixels) } pixels ; { NUMBER($most) } au plus sont permis
scene-aim-needs-look-at = `up` et `plunge` orientent la caméra : donnez-lui un point `look_at`
scene-shadows-need-point-light = les rayons d'ombre sont pour une source ponctuelle ; les ombres d'une source sphérique viennent de light_sampling ou des rayons indirects
scene-light-sampling-needs-sphere = l'échantillonnage de la lumière demande une source sphérique : donnez un rayon (radius) à [light]
scene-camera-cannot-aim = la caméra ne doit regarder ni le long de `up`, ni sa propre position
scene-leaf-size-needs-fast = seule la hiérarchie du moteur rapide a une taille de feuille : `fast = true` avec `acceleration = "bvh"`

## Un maillage ou une texture que nomme la scène.
scene-cannot-load-mesh = impossible de charger le maillage : { $why }
scene-cannot-read-texture = impossible de lire la texture : { $why }

## Ce qu'une scène demande qu'une séance suivante apporte, et comment l'obtenir.
scene-needs-feature-s = demande la fonctionnalité s{ $later } : cargo run --features s{ $later } -- ...
scene-comes-with-view = vient avec la séance { $later } : cette crate s'arrête à la séance { $session } (`cargo xtask view s{ $later } DIR` dans la crate du cours écrit celle de la séance { $later })
scene-comes-with-exercises = vient avec la séance { $later } : vous l'écrirez alors ; cette crate contient les exercices de la séance { $session }
scene-part-mirror = un matériau miroir
scene-part-glass = un matériau verre
scene-part-fresnel-glass = un matériau verre de Fresnel
scene-part-gamma = la correction gamma
scene-part-shadows = les rayons d'ombre
scene-part-shadow-offset = un décalage fixe des rayons d'ombre
scene-part-indirect = l'éclairage indirect
scene-part-antialiasing = l'antialiasing
scene-part-light-sampling = l'échantillonnage de la lumière
scene-part-russian-roulette = la roulette russe
scene-part-lens = une lentille mince
scene-part-sphere-light = une source sphérique
scene-part-meshes = les maillages de triangles
scene-part-acceleration = une structure d'accélération
scene-part-bvh = une hiérarchie de volumes englobants
scene-part-aimed-camera = une caméra orientée
scene-part-smooth-normals = les normales lissées
scene-part-textures = les textures
