### Ce que `raycourse check` dit de l'image d'une étape faite par un étudiant, ligne
### par ligne ; la page de vérification du livre montre les mêmes lignes.

check-unit =
    { $cell ->
        [1] des pixels
       *[other] des blocs de { $cell } × { $cell } pixels
    }
check-matches = { $stage } : correspond ({ NUMBER($share, minimumFractionDigits: 1, maximumFractionDigits: 1) } % { check-unit } diffèrent, dans la tolérance)
check-differs = { $stage } : diffère ({ NUMBER($share, minimumFractionDigits: 1, maximumFractionDigits: 1) } % { check-unit } diffèrent)

check-brightness = {"  "}luminosité par rapport à la référence : rouge × { NUMBER($red, minimumFractionDigits: 2, maximumFractionDigits: 2) }, vert × { NUMBER($green, minimumFractionDigits: 2, maximumFractionDigits: 2) }, bleu × { NUMBER($blue, minimumFractionDigits: 2, maximumFractionDigits: 2) }

check-where = {"  "}où : { $places }
check-place = { $place } ({ NUMBER($share, maximumFractionDigits: 0) } %)
check-place-separator = {", "}

place-background = le fond
place-light = la source
place-mesh = le maillage
place-sphere = la sphère
place-floor = le sol
place-ceiling = le plafond
place-left-wall = le mur de gauche
place-right-wall = le mur de droite
place-back-wall = le mur du fond
place-wall-behind-camera = le mur derrière la caméra
place-wall = un mur
place-top-half = la moitié haute
place-bottom-half = la moitié basse

check-noise = {"  "}bruit : { NUMBER($ratio, minimumFractionDigits: 2, maximumFractionDigits: 2) } fois la variance d'un rendu aux { $samples } échantillons par pixel du cours (comme avec environ { NUMBER($equivalent, maximumFractionDigits: 0, useGrouping: "false") } échantillons)

check-hint = {"  "}indice ({ $name }) : { $hint }
check-no-hint = {"  "}indice : aucune erreur classique n'explique la différence ; comparez avec `{ $command }`

check-unreadable = ce n'est pas une image PNG, JPEG ou PPM lisible : { $error }

check-cannot-read = impossible de lire l'image : { $error }
check-not-a-folder = ce n'est pas un dossier
check-no-stage = aucune image d'une étape ici, ni dans le dossier d'un étudiant : nommez chaque image d'après son étape, comme glass.png
check-no-stage-command = { check-no-stage } (`raycourse list` donne les étapes)
check-sheet-written = feuille de notes -> { $path }

mistake-no-gamma = pas de gamma
    .hint = l'image semble affichée sans correction gamma : écrivez min(255, L^(1/{ NUMBER(2.2) })), et non min(255, L)
mistake-gamma-twice = gamma deux fois
    .hint = l'image semble corrigée deux fois du gamma : appliquez L^(1/{ NUMBER(2.2) }) une seule fois, en écrivant le pixel
mistake-one-over-pi-missing = 1/pi manquant
    .hint = l'image est environ pi fois trop claire : la BRDF diffuse vaut albédo / pi ; vérifiez le 1/pi, et que l'intensité de la source est prise telle quelle
mistake-one-over-pi-twice = 1/pi deux fois
    .hint = l'image est environ pi fois trop sombre : le 1/pi de la BRDF diffuse est compté deux fois
mistake-no-falloff = pas de décroissance
    .hint = la lumière ne décroît pas avec la distance : une source ponctuelle donne I / (4 pi d^2), d étant la distance à la source
mistake-upside-down = à l'envers
    .hint = l'image est à l'envers : les lignes de l'image partent du haut, donc la ligne i, comptée depuis le bas, est H - 1 - ligne
mistake-mirrored = en miroir
    .hint = l'image est inversée de gauche à droite : l'axe x de la caméra pointe vers la droite (vérifiez le signe de x dans la direction du pixel)
mistake-half-a-turn = un demi-tour
    .hint = l'image a fait un demi-tour : les lignes et les colonnes vont toutes deux dans le mauvais sens (la ligne i, comptée depuis le bas, est H - 1 - ligne, et x croît avec la colonne j)
mistake-rows-and-columns-swapped = lignes et colonnes échangées
    .hint = les lignes et les colonnes sont échangées : le pixel de la colonne j et de la ligne i est écrit à la colonne i et à la ligne j (l'indice d'un pixel dans l'image est ligne * W + colonne)
mistake-shifted-a-pixel = décalée d'un pixel
    .hint = l'image est celle de l'étape décalée d'un pixel : la ligne i, comptée depuis le bas, est H - 1 - ligne (et non H - ligne), et le centre d'un pixel est à un demi-pixel du bord, x = j - W/2 + { NUMBER(0.5) }
mistake-shadow-acne = acné d'ombre
    .hint = les surfaces éclairées sont mouchetées de points sombres (acné d'ombre) : faites partir les rayons d'ombre un peu au-dessus de la surface, de P + epsilon N et non de P
mistake-inverted-index = indice inversé
    .hint = le verre dévie les rayons dans le mauvais sens : en entrant dans le verre, eta = n1 / n2 = 1 / { NUMBER(1.5) } ; en sortant, { NUMBER(1.5) }
mistake-light-counted-twice = source comptée deux fois
    .hint = la lumière est comptée deux fois : avec l'échantillonnage de la lumière, un rayon rebondi qui rencontre la source ne doit pas ajouter son émission une seconde fois
mistake-bounce-limit = limite de rebonds
    .hint = les chemins s'arrêtent trop tôt : un chemin suit jusqu'à `bounces` rebonds (le réglage de l'étape), et ne s'arrête qu'ensuite ; vérifiez où votre compteur de rebonds est testé et décrémenté
mistake-bounce-weight = poids du rebond
    .hint = la lumière indirecte est fausse alors que la lumière directe est juste : le poids d'un rebond doit correspondre à la façon dont sa direction a été tirée (directions pondérées par le cosinus : albédo ; uniformes : 2 albédo cos(theta))
mistake-texture-gamma = gamma de la texture
    .hint = la texture paraît délavée : les valeurs des texels sont encodées en gamma ; prenez (v / 255)^{ NUMBER(2.2) } comme albédo
mistake-texture-v-flipped = v de texture inversé
    .hint = la texture est à l'envers sur le maillage : v part du bas de l'image, donc la ligne du texel est (1 - v) H
