### Ce qu'affiche `raycourse probe` : un échantillon d'un pixel, rayon par rayon, dans
### la notation du livre. Les symboles (O, d, t, P, N, Le, L) sont ceux du livre dans
### toutes les langues. Le matériau est écrit comme la valeur du code, tel que
### `--json` le donne.

probe-pixel = pixel (x { $x }, y { $y }), échantillon { $sample } sur { $samples } (à partir de 0)
probe-camera-ray = niveau { $level } : le rayon de la caméra
probe-bounce = niveau { $level } : rebond { $level }
probe-sample-radiance = luminance de l'échantillon  L = { $radiance }
probe-pixel-mean = pixel            moyenne de { $samples } { $samples ->
        [one] échantillon
       *[other] échantillons
    } { $pixel } -> gamma { $gamma } -> ({ $red } ; { $green } ; { $blue })
probe-ray = {"  "}rayon    O = { $origin }  d = { $direction }
probe-hit = {"  "}impact   t = { $t }  P = { $point }  N = { $normal }
probe-object = {"           "}{ $shape } (objet { $object }), { $material }, { $face }
probe-front-face = face avant
probe-back-face = face arrière (depuis l'intérieur)
probe-emitted = {"  "}émis     Le = { $emitted }{ $glow }
probe-glow-not-counted = {" "}(non compté : l'échantillonnage de la lumière l'a compté à l'impact précédent)
probe-end = {"  "}fin      { $end }
probe-arriving = {"  "}arrivant L = { $arriving }   ajoute { $throughput } × (Le + direct) = { $adds }
probe-shadow-ray = {"  "}{ $light }  rayon d'ombre O = { $origin }  d = { $direction }
probe-shadow-distance = {"           "}distance { $distance }, { $blocked }
probe-no-distance = -
probe-blocked = bloqué par l'objet { $object } à t = { $t }
probe-not-blocked = non bloqué
probe-no-shadow-ray = {"  "}{ $light }  aucun rayon d'ombre tracé
probe-direct = {"  "}direct   { $brings }
probe-next = {"  "}suite    { $kind } : d' = { $direction }
probe-cos-pdf = {"           "}cos(theta) = { $cos }, pdf = cos(theta) / pi = { $pdf }
probe-fresnel = {"           "}F = { $fresnel }
probe-roulette = {"           "}au-delà de la limite de rebonds : la roulette russe l'a laissé continuer (probabilité { $survival }), poids × 1/{ $survival }
probe-bounces-left = {"           "}rebonds encore permis : { $left }
probe-weight = {"           "}poids { $weight }
probe-triple = ({ $x } ; { $y } ; { $z })

## Comment le chemin continue après un impact (`--json` garde ces mots en anglais).
probe-next-diffuse = rebond diffus, tiré avec la densité cos(theta) / pi
probe-next-mirror = réflexion sur le miroir
probe-next-total-internal-reflection = réflexion totale interne : au-delà de l'angle critique
probe-next-reflection = réflexion
probe-next-refraction = réfraction, eta = n1 / n2 = { NUMBER($eta, minimumFractionDigits: 4, maximumFractionDigits: 4) }
probe-next-fresnel-reflection = réflexion, choisie par Fresnel avec la probabilité F
probe-next-fresnel-refraction = réfraction, eta = n1 / n2 = { NUMBER($eta, minimumFractionDigits: 4, maximumFractionDigits: 4) }, choisie par Fresnel avec la probabilité 1 - F

## Pourquoi le chemin s'arrête là (`--json` garde ces mots en anglais).
probe-end-leaves = le rayon quitte la scène : il rapporte du noir
probe-end-no-indirect = pas d'éclairage indirect dans cette scène : le chemin s'arrête à son impact diffus
probe-end-roulette = au-delà de la limite de rebonds, la roulette russe a arrêté le chemin (il continue avec la probabilité { $survival })
probe-end-bounce-limit = la limite de rebonds ({ $bounces }) est atteinte
probe-end-here = le chemin s'arrête ici

## Un nombre en notation scientifique, sa mantisse comme l'écrit la langue.
probe-number = { $value }

## Les noms que le moteur donne à une source et à une forme (`--json` les garde).
probe-light-no-light = pas de source
probe-light-point-light = source ponctuelle
probe-light-sphere-light = source sphérique
probe-shape-sphere = sphère
probe-shape-mesh = maillage

## Pourquoi la sonde ne peut pas suivre un pixel, et ce que la commande refuse.
probe-outside = le pixel ({ NUMBER($x, useGrouping: "false") }, { NUMBER($y, useGrouping: "false") }) est hors de l'image, qui fait { NUMBER($width, useGrouping: "false") } × { NUMBER($height, useGrouping: "false") }
probe-no-such-sample = l'échantillon { $sample } n'existe pas : le pixel en prend { $samples } (à partir de 0)
probe-no-stage = pas d'étape `{ $name }` dans cette compilation : l'une de { $names }
probe-scene-and-stage = avec --scene, donnez seulement X Y
probe-give-stage = donnez ÉTAPE X Y (ou --scene FICHIER X Y)
probe-beyond-the-course = la sonde suit le code du cours ; cette scène demande { $what }
probe-not-a-coordinate = `{ $text }` n'est pas une coordonnée de pixel (0, 1, 2…)
probe-cannot-write-json = impossible d'écrire la sonde en JSON : { $why }
probe-cannot-write-output = impossible d'écrire sur la sortie standard : { $why }
