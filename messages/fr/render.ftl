### Ce que dit un rendu terminé (`raycourse render`, les commandes `sN`, `animate`) : sa ligne
### de fin, avec les réglages de la scène en quelques mots ; et la ligne d'une
### commande qui échoue.

command-error = erreur : { $why }

## Pourquoi une commande de rendu ne peut pas continuer : ses fils d'exécution, le fichier qu'elle écrit.
command-too-many-threads = --threads { NUMBER($threads, useGrouping: "false") } : { NUMBER($most, useGrouping: "false") } au plus (un par cœur est le plus rapide)
command-cannot-start-threads = impossible de démarrer { $threads } { $threads ->
        [one] fil d'exécution
       *[other] fils d'exécution
    } : { $why }
command-cannot-write = { $file }: impossible d'écrire le fichier : { $why }
command-not-a-file = { $file }: pas un fichier ordinaire (un dossier, un périphérique ou un tube) : donnez le chemin d'un fichier à écrire
command-link-loop = { $file }: une boucle de liens symboliques
command-fast-differs = { $stage } : l'image du moteur rapide diffère de celle du code du cours

## La ligne de fin : `camera : 512 × 512, 50 échantillons par pixel, ... -> out/camera.png`.
render-done = { $label } : { $summary }, { NUMBER($seconds, minimumFractionDigits: 3, maximumFractionDigits: 3) } s, { NUMBER($rays) } { $rays ->
        [one] rayon
       *[other] rayons
    }, { NUMBER($speed, minimumFractionDigits: 2, maximumFractionDigits: 2) } Mrayons/s, { $threads } { $threads ->
        [one] fil d'exécution
       *[other] fils d'exécution
    }{ $adaptive }{ $dropped } -> { $out }
render-adaptive = , { NUMBER($average, minimumFractionDigits: 1, maximumFractionDigits: 1) } échantillons par pixel en moyenne
render-dropped = , { $dropped } { $dropped ->
        [one] échantillon non fini écarté
       *[other] échantillons non finis écartés
    }

## Les réglages de la scène en quelques mots.
summary-settings = { NUMBER($width, useGrouping: "false") } × { NUMBER($height, useGrouping: "false") }, { $samples } { $samples ->
        [one] échantillon
       *[other] échantillons
    } par pixel, { $bounces } { $bounces ->
        [one] rebond
       *[other] rebonds
    }
summary-gamma = , gamma { $gamma }
summary-shadows = , ombres
summary-indirect = , éclairage indirect
summary-light-sampling = , échantillonnage de la lumière
summary-russian-roulette = , roulette russe

## La ligne de fin de `--aov` : `glass : image des normales, de 0 (violet) à 1 (jaune) -> out`.
render-aov-done = { $label } : image { $aov ->
        [normal] des normales
        [depth] de la profondeur
        [albedo] de l'albédo
        [object] des objets
       *[cost] du coût
    }{ $range }{ $mean } -> { $out }
render-aov-range = , de { $low } (violet) à { $high } (jaune)
render-aov-mean = , coût moyen de { $mean } tests par rayon
render-cost-not-fast = { $label } : `--aov cost` compte les tests des recherches du cours, que le moteur rapide ne fait pas : retirez `--fast` (ou `fast = true` du fichier de scène)
render-noise-map = { $label } : échantillons par pixel de { $fewest } (noir) à { $most } (blanc) -> { $out }

## `raycourse animate` : l'étiquette et le temps de chaque image, et la ligne de fin.
animate-frame-label = { $name } image { $frame }/{ $frames }
animate-frame = { $label } : { NUMBER($seconds, minimumFractionDigits: 2, maximumFractionDigits: 2) } s
animate-cannot-encode = impossible d'encoder l'animation : { $why }
animate-done = { $name } : { $frames } { $frames ->
        [one] image
       *[other] images
    }, plongée de { $from } à { $to } degrés, { NUMBER($seconds, minimumFractionDigits: 1, maximumFractionDigits: 1) } s -> { $out }
