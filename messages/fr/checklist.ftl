### Ce que dit la liste de contrôle des exercices (`cargo test` dans la crate du
### cours et dans une crate d'exercices) : chaque échec en mots, avec les entrées
### et les deux réponses.

## checklist

checklist-checklist-passed-failed = liste de contrôle : { $passed } réussis ; { $failed } en échec
checklist-exercise-further-down-fails-its-known = l'exercice { $exercise }, plus bas, échoue sur ses réponses connues : cette image en a peut-être besoin d'abord
checklist-the-stage = l'étape `{ $name }` : { $look }
checklist-next =  ; ensuite : { $next }
checklist-progress-session-exercises-the-name-filter = progression : séance { $session } : exercices choisis par le filtre de noms : { $chosen } sur { $total }, faits : { $done }{ $next } ; cargo test sans nom les vérifie tous
checklist-progress-session-of-exercises-done-next = progression : séance { $session } : { $done } exercices faits sur { $total } ; ensuite : { $next }
checklist-progress-session-all-exercises-done = progression : séance { $session } : les { $total } exercices sont faits
checklist-failed = ÉCHEC
checklist-exercise-still-todo-write-it = exercice { $stub } : encore todo!() ; à écrire
checklist-needs-exercise-first-it-is-still = il faut d'abord l'exercice { $stub } : il est encore todo!()
checklist-exercise = exercice { $exercise } : { $why }
checklist-exercise-fails-the-image-needs-it = l'exercice { $exercise } échoue : l'image en a besoin d'abord
checklist-it-calls-exercise-which-fails-too = il appelle l'exercice { $need }, qui échoue aussi : corrigez d'abord celui-là

## generated-common

generated-common-on-a-generated-input-the-simplest = { $what } sur une entrée générée, la plus simple qui diffère de la réponse du cours : { $why_message }
generated-common-on-generated-numbers = { $what } sur des nombres générés : { $why }
generated-common-message =  ; { $w }
generated-common-yours-gave-the-course-s-gives = { $case } : le vôtre a obtenu { $gave }, celui du cours obtient { $expected }{ $why }

## generated-s1

generated-s1-w-h-alpha-degrees-pixel-row = W = { $w }, H = { $h }, alpha = { $value }°, pixel (ligne { $row }, colonne { $column })
generated-s1-h-2-tan-alpha-would-change = {" "}(H / (2 tan alpha) changerait de signe au-delà de 90 degrés)
generated-s1-the-camera-looks-down-z-the = la caméra regarde selon -z : le plan image est en z = -H / (2 tan(alpha/2)){ $wide }
generated-s1-message =  ;{" "}
generated-s1-the-centre-of-pixel-j-is = le centre du pixel j est en x = j - W/2 + 1/2 pour tout W : ici W = { $w } est impair, donc W/2 = { $w2 } (une division entière perd la moitié)
generated-s1-the-centre-of-pixel-j-is-2 = le centre du pixel j est en x = j - W/2 + 1/2 : le demi-pixel est faux
generated-s1-the-centre-of-pixel-j-is-3 = le centre du pixel j est en x = j - W/2 + 1/2 (ici j = { $j }, x = { $value }) : le vôtre est décalé de { $off }
generated-s1-rows-count-from-the-top-of = les lignes se comptent depuis le haut de l'image et y depuis le bas : y = i - H/2 + 1/2 avec i = H - 1 - ligne = { $i }
generated-s1-the-centre-of-row-i-is = le centre de la ligne i est en y = i - H/2 + 1/2 pour tout H : ici H = { $h } est impair, donc H/2 = { $h2 } (une division entière perd la moitié)
generated-s1-the-centre-of-row-i-h = le centre de la ligne i = H - 1 - ligne = { $i } est en y = i - H/2 + 1/2 = { $y } : le vôtre est décalé de { $off }
generated-s1-yours-is-h-2-tan-alpha = {" "}(la vôtre est H / (2 tan alpha))
generated-s1-yours-uses-w-the-field-of = {" "}(la vôtre prend W : le champ de vision est vertical)
generated-s1-the-image-plane-lies-at-h = le plan image est à H / (2 tan(alpha/2)) = { $plane } de l'œil, alpha le champ de vision vertical en radians ; le vôtre à { $theirs }{ $detail }
generated-s1-a-sphere-of-radius-at-the = une sphère de rayon { $radius } en { $centre }, le rayon issu de { $origin } selon { $direction }
generated-s1-no-hit = aucune intersection
generated-s1-the-sphere-is-radii-away-the = la sphère est à { $distance } rayons : le discriminant du manuel (s.d)^2 - (|s|^2 - R^2) perd R^2 dans l'arrondi de |s|^2 ; calculez-le comme R^2 - |s - (s.d) d|^2
generated-s1-the-sphere-is-behind-the-ray = la sphère est derrière le rayon : les deux racines sont négatives, et seul t > 0 est une intersection
generated-s1-the-ray-starts-on-the-sphere = le rayon part de la sphère : t = 0 est son propre départ, pas une intersection ; seul t > 0 en est une (ici là où il sort, s'il entre)
generated-s1-only-t-0-is-a-hit = seul t > 0 est une intersection : la vôtre est derrière l'origine du rayon
generated-s1-from-inside-the-sphere-the-near = depuis l'intérieur de la sphère la racine proche -s.d - sqrt(Delta) est négative : l'intersection est la racine lointaine -s.d + sqrt(Delta)
generated-s1-from-outside-the-hit-is-the = depuis l'extérieur, l'intersection est la racine proche -s.d - sqrt(Delta), où le rayon entre ; la vôtre est où il sort
generated-s1-the-ray-starts-on-the-sphere-2 = le rayon part de la sphère et y entre : sa racine proche vaut 0, son propre départ, mais la racine lointaine -s.d + sqrt(Delta) est une intersection
generated-s1-from-inside-the-sphere-the-near-2 = depuis l'intérieur de la sphère la racine proche est négative, mais la racine lointaine -s.d + sqrt(Delta) est une intersection
generated-s1-the-ray-grazes-the-sphere-its = le rayon frôle la sphère, sa droite à { $miss } rayon du centre : Delta = R^2 - |s - (s.d) d|^2 décide, et son signe doit être juste
generated-s1-radius-at = { $i } : rayon { $r } en { $c }
generated-s1-spheres-the-ray-from-the-origin = sphères { $s1_message }, le rayon issu de l'origine selon { $d }
generated-s1-sphere-at-t = sphère { $i } en t = { $value }
generated-s1-spheres-and-are-met-at-the = les sphères { $j } et { $i } sont rencontrées à la même distance : la première de la liste l'emporte (une sphère plus loin dans la liste ne remplace la plus proche que si elle est strictement plus proche, t < t_plus_proche)
generated-s1-the-nearest-hit-is-the-smallest = l'intersection la plus proche est le plus petit t de toutes les sphères rencontrées, pas la première rencontrée dans la liste
generated-s1-a-light-of-power-at-the = une source de puissance { $intensity } en { $light_position }, le point { $point } de normale { $normal } et d'albédo { $albedo }
generated-s1-the-surface-faces-away-from-the = la surface tourne le dos à la source (<N, l> = { $cos }) : elle ne reçoit rien, max(0, <N, l>)
generated-s1-l-points-from-the-shaded-point = l va du point éclairé P vers la source : l = (P_source - P) / |P_source - P|, et non P_source / |P_source|
generated-s1-the-diffuse-brdf-is-albedo-pi = la BRDF diffuse est albédo / pi : il manque le 1/pi
generated-s1-a-point-light-of-power-i = une source ponctuelle de puissance I donne I / (4 pi d^2) : il manque le 1/(4 pi)
generated-s1-yours-is-d-times-the-course = le vôtre vaut d fois celui du cours : la lumière décroît en 1/d^2, et l est le vecteur unitaire vers la source (le vecteur divisé par d)
generated-s1-the-light-falls-off-as-1 = la lumière décroît en 1/d^2 : la décroissance manque
generated-s1-lambert-s-cosine-n-l-is = il manque le cosinus de Lambert <N, l>
generated-s1-1-pi-is-counted-twice = le 1/pi est compté deux fois

## generated-s2

generated-s2-l-gamma = L = { $radiance }, gamma = { $gamma }
generated-s2-a-negative-or-nan-radiance-shows = une luminance négative ou NaN s'affiche en noir, 0 : ramenez-la à 0 avant la puissance
generated-s2-an-infinite-radiance-is-the-brightest = une luminance infinie est la plus claire qui soit : min(255, L^(1/gamma)) = 255
generated-s2-the-level-is-l-1-gamma = le niveau est L^(1/gamma) = { $exact } arrondi au plus proche, pas par défaut
generated-s2-use-the-gamma-given-here-not = utilisez le gamma donné, ici { $gamma }, et non 2,2
generated-s2-the-level-is-l-1-gamma-2 = le niveau est L^(1/gamma) : l'exposant est 1/gamma, pas gamma
generated-s2-or =  ; ou{" "}
generated-s2-the-hit-point-with-normal-on = le point d'intersection { $hit_point } de normale { $hit_normal } sur une sphère de rayon { $radius } en { $centre }, le nouveau rayon selon { $d }
generated-s2-yours-starts-at = { $case } : le vôtre part de { $ray_origin } ; { $why }
generated-s2-the-new-ray-keeps-the-direction = le nouveau rayon garde la direction donnée
generated-s2-leaving-outwards = En sortant
generated-s2-going-in = En entrant
generated-s2-it-meets-its-sphere-at-t = { $going_in } il rencontre sa sphère en t = { $again } : la normale N de l'intersection a été tournée vers le rayon, elle pointe donc ici dans la sphère ; le côté d'où part un nouveau rayon est celui que prend sa direction par rapport au décalage (tiré de la normale géométrique), pas par rapport à N
generated-s2-leaving-outwards-it-meets-its-own = en sortant il rencontre de nouveau sa propre sphère en t = { $again } (acné d'ombre) : décalez l'origine hors de la surface de la borne d'erreur, selon N du côté où il part
generated-s2-nothing = rien
generated-s2-going-in-it-should-meet-the = en entrant il devrait rencontrer le côté opposé, à environ { $chord }, et rencontre { $s2_nothing } : l'origine doit être décalée du côté où part le rayon, ici vers l'intérieur (-N)
generated-s2-the-origin-moved-from-the-hit = l'origine s'est éloignée de { $moved } du point d'intersection, plus d'un millième du rayon { $radius } : le décalage suit la borne d'erreur du point, pas un epsilon fixe
generated-s2-the-hit-point-with-normal-a = le point d'intersection { $hit_point } de normale { $hit_normal }, une source en { $light }
generated-s2-the-direction-at-distance = la direction { $ray_direction } à la distance { $gave }
generated-s2-the-direction-at-distance-2 = la direction { $towards } à la distance { $expected }
generated-s2-the-direction-is-a-unit-vector = la direction est un vecteur unitaire : divisez le vecteur vers la source par sa longueur
generated-s2-the-direction-is-the-unit-vector = la direction est le vecteur unitaire du point d'intersection vers la source
generated-s2-the-distance-is-the-light-s = la distance est celle de la source depuis l'origine du rayon, que le décalage a déplacée, pas depuis le point d'intersection
generated-s2-the-distance-is-light-origin-the = la distance est |source - origine|, la longueur de l'origine du rayon à la source
generated-s2-yours-points-the-other-way-r = le vôtre pointe dans l'autre sens : r = d - 2 (d . N) N
generated-s2-yours-leaves-d-as-it-is = le vôtre laisse d tel quel ; tout rayon qui touche le miroir repart, même rasant, ici d . N = { $along } : r = d - 2 (d . N) N
generated-s2-yours-removes-the-normal-part-subtracted = le vôtre retire la partie normale ; retranchée deux fois, elle se retourne : r = d - 2 (d . N) N
generated-s2-the-sign-r-d-2-d = le signe : r = d - 2 (d . N) N
generated-s2-r-d-2-d-n-n = r = d - 2 (d . N) N
generated-s2-d-n = d = { $d }, N = { $normal }
generated-s2-none-total-internal-reflection = aucune direction (réflexion totale interne)
generated-s2-d-n-eta = d = { $d }, N = { $normal }, eta = { $eta }
generated-s2-eta-is-n1-n2-the-index = eta vaut n1 / n2, l'indice que le rayon quitte sur celui où il entre ; le vôtre a pris n2 / n1
generated-s2-total-internal-reflection-eta-2-sin = réflexion totale interne : eta^2 sin^2(theta_1) = { $sin2 } > 1, donc pas de rayon réfracté
generated-s2-eta-2-sin-2-theta-1 = eta^2 sin^2(theta_1) = { $sin2 } <= 1 : le rayon est réfracté
generated-s2-the-refracted-ray-goes-on-through = le rayon réfracté traverse la surface : sa partie normale vaut -cos(theta_2) N
generated-s2-t-eta-d-d-n-n = t = eta (d - (d . N) N) - sqrt(1 - eta^2 sin^2(theta_1)) N

## generated-s3

generated-s3-gave-expected-a-unit-vector-with = { $u1_u2 } donne { $w }, au lieu d'un vecteur unitaire avec z >= 0
generated-s3-every-u-in-0-1-gives = { $gave } ; tout u de [0, 1) donne une direction, 0 compris : une division par u (ou par 0) n'y est pas définie, comme avec tan^2(theta) = (1 - u2) / u2 ; r = sqrt(1 - u2) et z = sqrt(u2) ne divisent par rien
generated-s3-n = N = { $normal }
generated-s3-n-itself-is-the-frame-s = N lui-même est le troisième axe du repère : gardez la normale donnée
generated-s3-t1-x-t2-n-the-frame = T1 x T2 = -N : le repère est indirect ; celui du chapitre est direct, T1 x T2 = N (échangez T1 et T2, ou retournez l'un d'eux)
generated-s3-the-frame-has-a-nan-or = le repère a une composante NaN ou infinie : une division par un nombre nul pour cette normale
generated-s3-has-the-length-the-tangents-are = { $name } a pour longueur { $length } : les tangentes sont des vecteurs unitaires
generated-s3-the-three-axes-are-at-right = { $name } = { $dot } : les trois axes sont à angle droit, chaque produit nul
generated-s3-near-n-z-1-n-z =  ; près de N = -z, 1 + n_z vaut 0 ou n'est plus qu'arrondi : le chapitre divise par sign + n_z, avec sign = copysign(1, n_z), jamais inférieur à 1 en valeur absolue
generated-s3-the-furnace-of-radius-around-wall = le four de rayon { $radius } centré en { $centre }, d'albédo de paroi { $wall }, le sol en { $point } d'albédo { $albedo }, rebonds permis : { $bounces }, la moyenne de { $value } rebonds
generated-s3-it-brought-back-nothing-the-bounce = il n'a rien rapporté : le rayon du rebond doit quitter le sol et rencontrer la paroi (faites-le partir avec hit.spawn(direction), dont le décalage suit l'arrondi du point, quelle que soit la taille du four)
generated-s3-the-channels-are-off-by-different = les canaux sont décalés de facteurs différents { $ratio } : chaque canal de l'albédo pondère son propre canal, albédo * L composante par composante
generated-s3-it-is-what-one-bounce-fewer = c'est ce que rapporte un rebond de moins : le rayon du rebond continue avec les rebonds qui restent après celui-ci, bounces - 1
generated-s3-sigma-gave-expected-finite-numbers-the = sigma = { $sigma }, { $u1_u2 } : obtenu ({ $value } ; { $y }), attendu des nombres finis (le logarithme de 1 - u1, jamais de 0)
generated-s3-sigma-the-offsets-spread-as-sigma = sigma = { $sigma } : { $why } ; les décalages s'étalent comme avec sigma = { $measured } (E[x^2 + y^2] = 2 sigma^2) : le décalage est sigma fois une paire normale centrée réduite, avec le sigma donné

## generated-s4

generated-s4-the-cone-of-sin-2-theta = le cône de sin^2(theta_max) = { $sin2 } (1 - cos(theta_max) = { $cone_one_minus_cos_max }), { $u1_u2 } : obtenu { $w }, attendu un vecteur unitaire du cône, 1 - z <= 1 - cos(theta_max)
generated-s4-the-cone-of-sin-2-theta-2 = le cône de sin^2(theta_max) = { $sin2 } : { $why }
generated-s4-for-so-small-a-cone-1 =  ; pour un cône si petit, 1 - cos(theta_max) tiré du cosinus, et sin(theta) de 1 - cos^2(theta), se perdent dans l'arrondi : prenez 1 - cos(theta) = xi1 * one_minus_cos_max et sin^2(theta) = (1 - cos)(1 + cos), comme le chapitre
generated-s4-the-cone-of-sin-2-theta-3 = le cône de sin^2(theta_max) = { $sin2 } (cos(theta_max) = { $cone_cos_max }), cos(theta) = { $cone_cos_max2 }
generated-s4-outside-the-cone-cos-theta-cos = hors du cône, cos(theta) < cos(theta_max), aucune direction n'est tirée : la densité est nulle
generated-s4-this-direction-is-inside-the-cone = cette direction est dans le cône, cos(theta) >= cos(theta_max) : la densité vaut 1 / (2 pi (1 - cos(theta_max)))
generated-s4-1-cos-theta-max-taken-from = 1 - cos(theta_max) tiré du cosinus se perd dans l'arrondi pour un cône si petit : utilisez one_minus_cos_max, que le cône garde
generated-s4-the-density-is-one-over-the = la densité est l'inverse de l'angle solide du cône, 1 / (2 pi (1 - cos(theta_max))) = { $inside }
generated-s4-gave-expected-a-point-of-the = { $u1_u2 } donne ({ $value } ; { $y }), au lieu d'un point du disque unité, x^2 + y^2 <= 1
generated-s4-1-3-is-the-mean-of = {" "}(1/3 est la moyenne de r = xi : les points se massent au centre)
generated-s4-the-mean-of-o-start-2 = { $start_d } : la moyenne de |o - start|^2 / aperture^2 sur { $LENS_DRAWS } rayons vaut { $mean }, attendu 1/2 : les départs sont uniformes sur l'aire de la lentille{ $of_new }
generated-s4-the-lens-of-radius-focused-at = la lentille de rayon { $lens_aperture } mise au point à { $lens_focus }, le rayon du sténopé issu de { $start } selon { $d }
generated-s4-the-ray-from-along = le rayon issu de { $origin } selon { $direction }
generated-s4-starts-off-the-lens-a-ray = { $case } : { $shown } part hors de la lentille : un rayon à travers la lentille part du plan de l'œil z = { $start_z }, à moins de l'ouverture { $lens_aperture } de l'œil (l'œil plus l'ouverture fois un point du disque unité)
generated-s4-misses-the-point-where-the-pinhole = { $case } : { $shown } manque le point { $focus_point } où le rayon du sténopé rencontre le plan de mise au point, à { $miss } près : { $origin_direction }
generated-s4-the-focus-plane-lies-at-the = le plan de mise au point est à la distance focus selon -z : le rayon du sténopé le rencontre en t = focus / -d_z, et non après une longueur focus le long du rayon
generated-s4-the-pinhole-ray-starts-at-the = le rayon du sténopé part de l'œil, start, et non de l'origine
generated-s4-every-ray-through-the-lens-passes = chaque rayon à travers la lentille passe par ce point : la direction est focus_point - origin

## generated-s5

generated-s5-the-triangle-a-b-c-the = le triangle A = { $a }, B = { $b }, C = { $c }, le rayon issu de { $ray_origin } selon { $ray_direction }, t_max = { $case_t_max }
generated-s5-det-0-the-ray-is-parallel = det = 0 : le rayon est parallèle au plan du triangle, ou le triangle n'a pas d'aire ; le test échoue
generated-s5-a-hit-at-or-beyond-t = une intersection en t_max ou au-delà n'en est pas une : t < t_max
generated-s5-the-point-is-outside-the-triangle = le point est hors du triangle, ou derrière le rayon : une intersection demande b_B >= 0, b_C >= 0, b_B + b_C <= 1 et t > 0
generated-s5-b-b-and-b-c-are = b_B et b_C sont échangés : b_B est le poids de B, selon e1 = B - A, et b_C celui de C, selon e2 = C - A
generated-s5-the-point-is-on-the-triangle = le point est sur une arête ou un sommet du triangle (b_B = { $beta }, b_C = { $gamma }) : les arêtes appartiennent au triangle, b_B >= 0, b_C >= 0 et b_B + b_C <= 1, au sens large
generated-s5-the-ray-meets-the-triangle-from = le rayon rencontre le triangle par l'arrière (det = { $det } < 0) : les deux faces sont touchées
generated-s5-a-hit-at-t-nearer-than = une intersection en t = { $value }, plus proche qu'un epsilon fixe, en est une : seul t > 0 décide
generated-s5-for-a-triangle-this-small-det = pour un triangle si petit, det = { $det } est minuscule mais non nul : seul det = 0 signifie parallèle (un seuil fixe manque les petits triangles)
generated-s5-the-point-is-inside-the-triangle = le point est dans le triangle (b_B >= 0, b_C >= 0, b_B + b_C <= 1) et devant le rayon, avant t_max
generated-s5-or =  ; ou{" "}
generated-s5-the-box-from-to-the-ray = la boîte de { $case_bounds } à { $case_bounds2 }, le rayon issu de { $ray_origin } selon { $ray_direction }, t_max = { $case_t_max }
generated-s5-a-flat-box-no-thickness-along = une boîte plate (sans épaisseur selon un axe, la boîte d'un triangle couché dans un plan) est touchée là où near = far : ne manquez que si near > far, et élargissez la sortie de 1 + 2 gamma_3 pour que l'arrondi ne place jamais near au-delà de far
generated-s5-from-inside-the-box-the-ray = depuis l'intérieur de la boîte, le rayon y est tout de suite : l'entrée vaut 0 (near part de 0, pas de -l'infini)
generated-s5-an-entry-at-or-beyond-t = une entrée en t_max ou au-delà n'en est pas une : far part de t_max
generated-s5-a-zero-component-of-the-direction = une composante nulle de la direction donne 1 / d = +-l'infini, et 0 × l'infini = NaN là où le rayon est couché dans une face : ordonnez les plans selon le signe de 1 / d et comparez de sorte qu'un NaN laisse l'intervalle tel quel

## generated-s6

generated-s6-no-hit = aucune intersection
generated-s6-message = { $case } : { $fault }
generated-s6-the-course-s-walk-through-your = { $case } : le parcours du cours dans votre hiérarchie trouve { $show_gave }, le test de chaque triangle { $show_expected } ; chaque boîte doit contenir ses triangles
generated-s6-only-hits-closer-than-t-max = seules les intersections plus proches que t_max = { $t_max } comptent, dans les triangles des feuilles comme dans les boîtes
generated-s6-a-nearer-hit-lies-in-a = une intersection plus proche se trouve dans une boîte que le parcours a laissée de côté : un nœud n'est sauté que si le rayon entre dans sa boîte au-delà de l'intersection la plus proche trouvée, et le parcours continue avec le reste de la pile
generated-s6-the-ray-starts-inside-the-mesh = le rayon part de l'intérieur de la boîte du maillage, où il entre en t = 0 : chaque boîte qu'il traverse est visitée
generated-s6-the-walk-missed-a-hit-every = le parcours a manqué une intersection : chaque boîte où le rayon entre avant l'intersection la plus proche trouvée est visitée, ses enfants aussi
generated-s6-the-nearest-hit-is-the-one = l'intersection la plus proche est celle que trouve le test de chaque triangle, plus proche que t_max
generated-s6-without-vertex-normals-the-shading-normal = sans normales aux sommets la normale d'ombrage est la normale géométrique
generated-s6-here-b-a-n-a-b = ici b_A N_A + b_B N_B + b_C N_C = 0 (les normales aux sommets s'annulent, ou sont nulles), et il n'y a aucune direction à normaliser : la normale d'ombrage se rabat sur la normale géométrique
generated-s6-the-shading-normal-is-turned-to = la normale d'ombrage est tournée du côté de la normale géométrique : là où N_s . N_g < 0, elle vaut -N_s
generated-s6-b-a-n-a-b-b = b_A N_A + b_B N_B + b_C N_C est plus court que 1 partout où les normales aux sommets diffèrent (ici { $gave_length }) : normalisez-le
generated-s6-n-s-normalize-b-a-n = N_s = normalize(b_A N_A + b_B N_B + b_C N_C), tournée du côté de la normale géométrique
generated-s6-or =  ; ou{" "}
generated-s6-weight-k-goes-with-corner-k = le poids k va avec le sommet k : b_A N_A + b_B N_B + b_C N_C, avec b_B = beta et b_C = gamma
generated-s6-corner-k-s-normal-is-that = la normale du sommet k est celle du sommet que nomme le triangle : ici normals[{ $i }], normals[{ $j }], normals[{ $k }], et non normals[0], normals[1], normals[2]

## generated-s6-hierarchy

generated-s6-hierarchy-bvh-order-lists-triangle-but-the = Bvh::order liste le triangle { $t }, mais le maillage en a { $count }, numérotés depuis 0
generated-s6-hierarchy-bvh-order-lacks-triangle-every-triangle = il manque le triangle { $t } dans Bvh::order : chaque triangle est dans exactement une feuille
generated-s6-hierarchy-bvh-order-lists-triangle-times-every = Bvh::order liste { $seen } fois le triangle { $t } : chaque triangle est dans exactement une feuille
generated-s6-hierarchy-the-hierarchy-has-no-node-node = la hiérarchie n'a aucun nœud : le nœud 0 est la racine
generated-s6-hierarchy-the-hierarchy-is-deeper-than-levels = la hiérarchie dépasse { $DEPTH } niveaux de profondeur au nœud { $index }
generated-s6-hierarchy-triangle-bvh-order-is-in-no = le triangle { $order_slot } (Bvh::order[{ $slot }]) n'est dans aucune feuille, donc aucun rayon ne le trouve : les plages des feuilles couvrent tout Bvh::order
generated-s6-hierarchy-leaf-node-covers-bvh-order-which = la feuille du nœud { $index } couvre Bvh::order[{ $range_start }..{ $range_end }], qui dépasse sa fin ou appartient aussi à une autre feuille : chaque triangle est dans exactement une feuille
generated-s6-hierarchy-the-box-of-leaf-node-to = la boîte de la feuille du nœud { $index }, de { $node_bounds } à { $node_bounds2 }, ne contient pas son triangle { $t }, { $a } { $b } { $c } : la boîte d'une feuille est le min et le max des sommets de ses triangles
generated-s6-hierarchy-if-yours-cut-it-along-where =  ; si la vôtre l'a coupée selon { $names_a }, où ils tombent tous d'un côté : la boîte est coupée en travers de son plus grand côté, ici { $names_axis }
generated-s6-hierarchy-leaf-node-holds-triangles-its-box = la feuille du nœud { $index } contient { $node_count } triangles, sa boîte longue de { $bounds_axis } selon { $names_axis }, son plus grand côté, avec des centroïdes des deux côtés du milieu de ce côté : la division s'arrête à { $LEAF_SIZE } triangles, ou quand tous les centroïdes tombent d'un côté, quelle que soit la taille de la boîte{ $across }
generated-s6-hierarchy-node-is-an-inner-node-count = le nœud { $index } est un nœud interne (count = 0) dont les enfants, les nœuds { $first } et { $first2 }, sont au-delà des { $bvh_nodes } nœuds
generated-s6-hierarchy-the-box-of-node-to-sticks = la boîte du nœud { $child }, de { $child_bounds } à { $child_bounds2 }, dépasse de celle de son parent, le nœud { $index }, de { $node_bounds } à { $node_bounds2 } : la boîte de chaque enfant est dans celle de son parent

## generated-s6-meshes

generated-s6-meshes-scattered = dispersés
generated-s6-meshes-copies-of-one-triangle-the-same = des copies d'un même triangle (le même centroïde) et quelques autres
generated-s6-meshes-all-in-the-plane-x = tous dans le plan x = { $at }
generated-s6-meshes-some-degenerate-two-corners-the-same = dont certains dégénérés (deux sommets confondus, ou trois alignés)
generated-s6-meshes-a-mesh-of-triangles-of-size = un maillage de { $count } triangles, { $layout }, de taille { $size } autour de { $at }
generated-s6-meshes-triangle = , triangle { $t } : { $a } { $b } { $c }
generated-s6-meshes-the-ray-from-along = le rayon issu de { $origin } selon { $direction }{ $reach }
generated-s6-meshes-no-vertex-normals = aucune normale aux sommets
generated-s6-meshes-the-vertex-normals-as-the-file = les normales aux sommets { $listed } telles que le fichier les donne
generated-s6-meshes-triangle-of-the-vertices-the-weights = le triangle { $triangle } des sommets ({ $i }{ $s }{ $j }{ $s }{ $k }), { $normals }, les poids (b_A{ $s }b_B{ $s }b_C) = ({ $a }{ $s }{ $b }{ $s }{ $c }), la normale géométrique { $geometric }

## generated-s7-camera

generated-s7-camera-the-camera-at-looking-at-up = la caméra en { $eye } regardant { $target }, up { $up }, plongée de { $plunge }°
generated-s7-camera-no-frame = aucune orientation
generated-s7-camera-the-eye-at-right-up-back = l'œil en { $eye }, right { $r }, up' { $u }, back { $b }
generated-s7-camera-the-camera-looks-at-the-target = la caméra regarde la cible, ici { $camera_target }, et non l'origine : forward = normalize(target - eye)
generated-s7-camera-the-plunge-is-in-degrees-turn = la plongée est en degrés : convertissez-la en radians, psi pi / 180, pour la rotation
generated-s7-camera-the-eye-turns-around-the-target = l'œil tourne autour de la cible et reste à la même distance d'elle, { $offset_length } ; le vôtre en est à { $target_length }
generated-s7-camera-the-eye-rises-around-the-target = l'œil s'élève autour de la cible : target + q (eye - target), q la rotation de la plongée autour de normalize((eye - target) x up)
generated-s7-camera-right-forward-x-up-not-up = right = forward x up, et non up x forward, qui renverse l'image en miroir
generated-s7-camera-right-normalize-forward-x-up-forward = right = normalize(forward x up) : forward x up n'est unitaire que si up l'est et est perpendiculaire à la vue ; ici up mesure { $up_length } et forward x up { $right_length }
generated-s7-camera-back-forward-camera-space-z-points = back = -forward : le z de la caméra pointe de la scène vers l'œil
generated-s7-camera-forward-normalize-target-eye-right-normalize = forward = normalize(target - eye), right = normalize(forward x up), up' = right x forward, back = -forward
generated-s7-camera-the-camera-looks-exactly-along-up = la caméra regarde exactement le long de up : forward x up = 0 ne donne aucune direction vers la droite, et aim donne None
generated-s7-camera-the-view-is-radians-from-up = la vue est à { $angle } radians de up : seule une caméra regardant exactement le long de up n'a pas d'orientation, et right = normalize(forward x up) quelle que soit la longueur de forward x up

## generated-s7-texture

generated-s7-texture-a-x-texture-rows-from-the = une texture de { $w } × { $h }, lignes depuis le haut : { $rows }, lecture { $lookup } ({ $filter_debug }) en (u{ $s }v) = ({ $u }{ $s }{ $v })
generated-s7-texture-v-runs-from-the-bottom-v = v va du bas (v = 0) vers le haut (v = 1) tandis que les lignes se comptent depuis le haut : y = (1 - v) H, et non v H
generated-s7-texture-u-runs-along-the-width-and = u court selon la largeur et v selon la hauteur, x = u W et y = (1 - v) H avec W = { $w } et H = { $h } : le vôtre échange u et v, ou W et H, ce que seule une texture non carrée montre
generated-s7-texture-a-point-s-texel-is-floor = le texel d'un point est floor(x), vers moins l'infini : floor(-0,5) = -1, là où une conversion en entier tronque vers zéro, à 0
generated-s7-texture-texel-k-s-centre-is-at = le centre du texel k est en k + 1/2 : le filtre bilinéaire décale le point d'un demi-texel, x' = x - 1/2 et y' = y - 1/2, avant de le découper
generated-s7-texture-or =  ; ou{" "}

## generated-sampling

generated-sampling-from-to-the-azimuth-from-to = { $radial } de { $band } à { $band2 }, l'azimut de { $low }° à { $high }°
generated-sampling-of-draws-fell-where-the-chapter = { $counts_worst } des { $draws } tirages tombent là où la densité du chapitre en met { $PER_CELL } : { $describe_worst }, les tirages ne sont donc pas répartis comme le dit la densité (khi-deux de { $statistic_written } sur { $cells } cases de même probabilité, au-dessus de { $limit_written }, ce qu'une bonne réponse ne dépasse qu'une fois sur un million)

## images

images-yours-is =  ; votre image est { $yours }
images-the-stage-at-x-differs-from = l'étape `{ $stage_name }` en { $film_width } × { $film_height } diffère de { $reference }{ $place } : { $why }{ $traced }
images-of-pixels-differ-by-more-than = { $d_count } pixels sur { $outcome_differs } diffèrent de plus de { $TOLERANCE } niveaux d'affichage (l'écart maximal, { $worst } niveaux, en colonne { $at }, ligne { $at2 })
images-of-blocks-of-8-x-8 = { $d_count } blocs de 8 × 8 pixels sur { $outcome_differs } diffèrent au-delà du bruit
images-message =  ; { $hint }
images-it-is-the-reference-upside-down = l'image est la référence à l'envers : la ligne 0 (row) est le haut de l'image, donc la hauteur du pixel se compte depuis le bas, i = H - 1 - row
images-it-is-the-reference-mirrored-left = l'image est la référence inversée de gauche à droite : la colonne j croît vers la droite, x = j - W/2 + 0,5
images-it-shows-the-radiance-without-the = l'image montre la luminance sans le gamma de l'écran : un pixel vaut L^(1/gamma), ici gamma = { $gamma }
images-the-display-s-gamma-is-applied = le gamma de l'écran est appliqué deux fois : un pixel vaut L^(1/gamma), une seule fois
images-about-pi-times-too-bright-a = l'image est environ pi fois trop claire : une surface diffuse renvoie albédo / pi (la BRDF), et la puissance de la source se répartit sur 4 pi r^2
images-about-pi-times-too-dark-is = l'image est environ pi fois trop sombre : le 1 / pi est-il compté deux fois, ou le pi de la densité de probabilité (pdf) pondérée par le cosinus n'est-il pas simplifié ?
images-about-pi-times-too-dark-is-2 = l'image est environ pi fois trop sombre : le 1 / pi est-il compté deux fois ? Une surface diffuse renvoie albédo / pi, une seule fois
images-about-twice-too-bright-or-too = l'image est environ deux fois trop claire ou trop sombre : le poids d'un échantillon doit correspondre à la densité avec laquelle il a été tiré (une direction dans le cône de la source : 1 / (2 pi (1 - cos theta_max)) ; un rebond pondéré par le cosinus : cos(theta) / pi)
images-about-twice-too-bright-or-too-2 = l'image est environ deux fois trop claire ou trop sombre : le poids d'un rebond doit correspondre à la façon dont sa direction a été tirée (pour une direction pondérée par le cosinus, le cosinus et pi se simplifient, il reste l'albédo)
images-brighter-than-the-reference-overall-per = l'image est { $percent } % plus claire que la référence dans l'ensemble (par canal × { $r }{ $s }× { $g }{ $s }× { $b })
images-darker-than-the-reference-overall-per = l'image est { $percent } % plus sombre que la référence dans l'ensemble (par canal × { $r }{ $s }× { $g }{ $s }× { $b })
images-brightness-against-the-reference-x = { $hint } (luminosité par rapport à la référence : × { $mean })
images-message-2 = { $path } : { $error }

## isolation

isolation-it-did-not-end-within-s = il ne s'est pas terminé en { $seconds } s : une boucle ne s'arrête peut-être jamais
isolation-it-never-ended-the-stack-overflowed = il ne s'est jamais terminé : la pile a débordé, comme avec une récursion sans fin (chaque appel descend-il d'un niveau, vers un dernier niveau où il s'arrête ?)
isolation-it-asked-for-more-than-gib = il a demandé plus de { $gib } Gio de mémoire : une boucle ou une récursion sans fin ? (une hiérarchie doit cesser de se diviser, chaque nœud ayant moins de triangles que son parent)
isolation-it-stopped = il s'est arrêté : { $last }

## known

known-gave-expected-within = { $what } : obtenu { $gave }, attendu { $expected } (à { $tolerance } près)
known-no-hit = aucune intersection
known-sphere-at-t = sphère { $i } en t = { $t }

## mistakes-common

mistakes-common-the-right-answer-of-exercise-fails = la bonne réponse « { $right_what } » de l'exercice { $right_exercise } échoue à sa vérification générée : { $why }
mistakes-common-the-mistake-of-exercise-passes-its = l'erreur « { $mistake_what } » de l'exercice { $mistake_exercise } passe sa vérification générée
mistakes-common-the-mistake-of-exercise-fails-without = l'erreur « { $mistake_what } » de l'exercice { $mistake_exercise } échoue sans nommer sa règle (« { $words } ») : { $why }

## panics

panics-message =  ; { $r }
panics-panicked-in-exercise-at = panique dans l'exercice { $title_marker }, en { $place } : { $message }{ $rule }
panics-panicked = panique : { $message } ({ $place }){ $rule }
panics-an-unsigned-integer-u32-usize-went = un entier non signé (u32, usize) est passé sous 0 : convertissez en Real avant de soustraire, car le chapitre calcule en nombres réels
panics-an-integer-went-past-its-largest = un entier a dépassé sa plus grande valeur : calculez en Real
panics-an-index-past-the-end-of = un indice au-delà de la fin d'une liste : une liste de n éléments s'indexe de 0 à n - 1
panics-unwrap-on-none-none-no-hit = unwrap() sur None : None (l'absence d'intersection, par exemple) est un cas à part entière, à traiter avec match ou if let
panics-an-integer-division-by-0-divide = une division entière par 0 : divisez en Real, ou testez le diviseur

## s1

s1-pixel-row-column-gave-the-direction = le pixel (ligne { $row }, colonne { $column }) donne la direction { $vec_gave }
s1-the-direction-through-pixel-row-column = la direction à travers le pixel (ligne { $row }, colonne { $column }), { $place } d'une image de 4 × 2 avec un champ de vision de 90 degrés, normalisée
s1-pixel-direction-pixel-direction-0-0 = pixel_direction({ $row }, { $column }) - pixel_direction(0, 0), { $step } dans une image de 8 × 4 avec un champ de vision de 60 degrés (la direction est en unités de pixel : la séance 3 lui ajoute sa perturbation, en pixels)
s1-a-sphere-of-radius-at-the = { $test } : une sphère de rayon { $radius } en { $vec_centre }, { $what }, le rayon issu de { $vec } selon { $ray_direction } : obtenu { $maybe_gave }, attendu { $maybe_expected }
s1-sphere-intersect-a-sphere-of-radius = Sphere::intersect : une sphère de rayon 1 en (0,5 ; 0 ; -{ $far }), le rayon issu de l'origine selon -z : obtenu { $maybe_gave }, attendu { $maybe_expected } (le discriminant du manuel perd 0,75 dans l'arrondi à côté de { $far }^2 : calculez-le comme R^2 - |s - (s.d) d|^2)
s1-spheres-at-z-10-5-and = des sphères en z = -10, -5 et 3 (numéros 0, 1, 2), le rayon issu de l'origine selon -z : obtenu { $nearest_gave }, attendu { $nearest }
s1-the-same-spheres-the-ray-along = les mêmes sphères, le rayon selon +y : obtenu { $nearest_gave }, attendu { $nearest }
s1-albedo-at-normal-under-a-light = albédo { $vec_albedo } en { $vec_point }, normale { $vec_normal }, { $what }, sous une source de puissance 400 pi^2 en { $light_position }

## s2

s2-radiance-with-gamma-gave-expected = luminance { $radiance } avec un gamma de { $gamma } : obtenu { $gave }, attendu { $expected }
s2-on-a-wall-a-sphere-of = sur un mur, une sphère de rayon { $radius } en { $at }
s2-on-a-sphere-of-radius-at = sur une sphère de rayon { $radius } en { $at }
s2-the-ray-going-starts-at-from = { $what }, le rayon { $way } part de { $ray_origin }, à { $hit_point } du point d'intersection { $hit_point2 } : attendu un départ à moins de 1e-3
s2-a-ray-leaving-outwards-from-the = { $what }, un rayon qui quitte le point d'intersection vers l'extérieur rencontre de nouveau la sphère en { $maybe_again } : attendu { $maybe } (son origine doit être décalée hors de la surface, vers l'extérieur)
s2-a-ray-going-into-the-sphere = { $what }, un rayon qui entre dans la sphère depuis le point d'intersection donne { $maybe_through }, au lieu du côté opposé, à environ { $ball_radius } (son origine doit être décalée hors de la surface, vers l'intérieur)
s2-the-direction-towards-a-light-13 = { $what }, la direction vers une source à une distance de 13 selon { $vec_new }
s2-the-distance-to-that-light = { $what }, la distance à cette source
s2-the-shadow-ray-starts-at-not = { $what }, le rayon d'ombre part de { $ray_origin }, et non près du point d'intersection { $hit_point }
s2-d-reflected-about-n = d = { $vec_d } réfléchi par rapport à N = { $vec }
s2-none-total-internal-reflection = aucune direction (réflexion totale interne)
s2-d-n-eta-n1-n2-gave = { $what } : d = { $vec_d }, N = { $vec }, eta = n1 / n2 = { $eta } : obtenu { $show_gave }, attendu { $show_expected }

## s3

s3-u1-u2-gave-expected-a-unit = (u1{ $s }u2) = ({ $u1 }{ $s }{ $u2 }) donne { $vec_w }, au lieu d'un vecteur unitaire avec z >= 0
s3-the-mean-of-cos-theta-z = la moyenne de cos(theta) = z
s3-uniform-directions-would-give-1-2 = { $e } ; des directions uniformes donneraient 1/2 : la densité doit être cos(theta) / pi
s3-the-azimuth-phi-2-pi-u = { $e } : l'azimut phi = 2 pi u parcourt tout le cercle, uniformément, si bien que x et y ont une moyenne nulle
s3-the-mean-of = la moyenne de { $what }
s3-the-frame-of-n = le repère de N = { $vec }
s3-message =  :
s3-its-axis-n = { $what } : son axe N
s3-the-length-of = { $what } : la longueur de { $name } = { $vec }
s3-inside-a-furnace-whose-wall-glows = dans un four dont la paroi émet une luminance 1, la moyenne de { $n } rebonds depuis le sol d'albédo { $albedo } donne { $vec_mean } au lieu de { $albedo }{ $mean_element_sum } : le rebond rapporte albédo * L(w) quand sa direction a pour densité cos(theta) / pi
s3-a-bounce-from-the-furnace-s = un rebond depuis le sol du four a rencontré le sol lui-même en t = { $h_h } : faites partir le rayon du rebond hors de la surface avec hit.spawn(direction) (séance 2), et non du point d'intersection
s3-the-wall-was-seen-with-no =  : la paroi a été vue sans rebond restant ; le rayon du rebond continue avec les rebonds qui restent après celui-ci, bounces - 1
s3-inside-the-same-furnace-with-3 = dans le même four, avec 3 rebonds permis, le rebond moyen depuis le sol donne { $vec_mean } au lieu de 1,75 albédo = { $vec } : la paroi vue avec 2 rebonds restants renvoie 1 + 0,5 (1 + 0,5){ $hint }
s3-2-3-of-it-is-the =  ; 2/3 de la valeur attendue, c'est le cosinus moyen : le cosinus est compté alors que la densité de la direction le contient déjà
s3-1-pi-of-it-the-brdf =  ; 1/pi de la valeur attendue : le 1/pi de la BRDF est compté alors que le pi de la densité l'annule
s3-twice-it-the-weight-divides-by =  ; le double de la valeur attendue : le poids divise par la densité d'une direction uniforme, 1 / (2 pi), et non par celle d'une direction pondérée par le cosinus
s3-the-share-of-offsets-within-sigma = la part des décalages à moins de sigma du centre
s3-u1-gave-expected-finite-numbers-the = u1 = { $u1 } : obtenu ({ $x }{ $s }{ $y }), attendu des nombres finis (le logarithme de 1 - u1, jamais de 0)

## s4

s4-the-cone-of-half-angle-30 = le cône de demi-angle 30 degrés autour de +z, (u1{ $s }u2) = ({ $u1 }{ $s }{ $u2 }) : obtenu { $vec_w }, attendu un vecteur unitaire avec z >= cos(30) = 0,866
s4-the-cone-of-half-angle-30-2 = le cône de demi-angle 30 degrés : la moyenne de cos(theta)
s4-uniform-over-the-cone-s-solid = { $e } : uniformes sur l'angle solide du cône, les directions ont un cos(theta) uniforme entre cos(theta_max) et 1 (et non un theta uniforme entre 0 et theta_max)
s4-the-density-of-the-30-degree = la densité du cône de 30 degrés en cos(theta) = { $cos }
s4-outside-it = , hors du cône
s4-gave-the-point-outside-the-unit = donne le point ({ $x }{ $s }{ $y }), hors du disque unité
s4-with-r-xi-the-points-crowd = { $e } ; avec r = xi, les points se massent au centre (1/3) : une répartition uniforme sur l'aire demande r = sqrt(xi)
s4-the-share-of-points-within-r = la part des points à une distance r <= 1/2 du centre
s4-a-ray-through-the-lens-of = un rayon à travers la lentille de rayon 0,5 part de { $vec_origin } : attendu un point de la lentille (z = 0, à moins de 0,5 de l'œil)
s4-the-ray-from-along-never-reaches = le rayon issu de { $vec_origin } selon { $vec_direction } n'atteint jamais le plan de mise au point z = -10 : il doit aller de son point de la lentille vers (2,5 ; 5 ; -10), où le rayon du sténopé rencontre ce plan
s4-the-ray-from-along-where-it = le rayon issu de { $vec_origin } selon { $vec_direction }, là où il traverse le plan de mise au point z = -10 (un plan à la distance de mise au point le long de la visée, non une sphère autour de l'œil : la direction du sténopé est mise à l'échelle pour que son z vaille -focus)
s4-the-mean-of-x-2-y = la moyenne de x^2 + y^2 sur les points de départ de la lentille

## s5

s5-the-triangle-a-ray-gave-expected = le triangle { $vec_a }, { $vec_b }, { $vec_c }, un rayon { $what } : obtenu { $h_gamma }, attendu { $show_expected }
s5-the-box-from-to-a-ray = la boîte de { $vec_cube } à { $vec_cube2 }, un rayon { $what } (d = { $ray_direction }) : obtenu { $maybe_gave }, attendu { $maybe_expected }

## s6

s6-bvh-order-holds-the-triangle-number = Bvh::order contient le triangle numéro { $t }, mais Spot n'en a que { $n }
s6-bvh-order-must-list-each-of = Bvh::order doit lister une fois chacun des { $n } triangles de Spot : il compte { $bvh_order } entrées, il lui manque le triangle { $missing } et il liste plus d'une fois le triangle { $twice }
s6-the-hierarchy-has-no-node-node = la hiérarchie n'a aucun nœud : le nœud 0 est la racine
s6-the-hierarchy-is-deeper-than-64 = la hiérarchie dépasse 64 niveaux de profondeur au nœud { $index }
s6-a-node-points-to-node-past = un nœud pointe vers le nœud { $index }, au-delà des { $bvh_nodes } nœuds
s6-the-leaf-at-node-covers-bvh = la feuille du nœud { $index } couvre Bvh::order[{ $range_start }..{ $range_end }], qu'une autre feuille couvre aussi ou qui dépasse la fin
s6-the-box-of-leaf-node-to = la boîte de la feuille du nœud { $index }, de { $node_bounds } à { $node_bounds2 }, ne contient pas son triangle { $order_slot }
s6-node-points-to-node-past-the = le nœud { $index } pointe vers le nœud { $child }, au-delà des { $bvh_nodes } nœuds : les enfants d'un nœud interne sont les nœuds first et first + 1, ajoutés côte à côte quand on le divise
s6-the-box-of-node-sticks-out = la boîte du nœud { $child } dépasse de celle de son parent, le nœud { $index }
s6-triangle-bvh-order-is-in-no = le triangle { $triangle } (Bvh::order[{ $slot }]) n'est dans aucune feuille : aucun rayon ne peut le trouver ; les plages des feuilles doivent couvrir tout Bvh::order
s6-spot-s-triangles-end-in-leaves = les { $n } triangles de Spot aboutissent dans { $leaves } feuilles : attendu des boîtes divisées jusqu'à environ 4 triangles par feuille
s6-a-nearer-hit-lies-in-a =  : une intersection plus proche se trouve dans un nœud que le parcours a laissé pour plus tard ; continuez avec le reste de la pile, en ne sautant que les nœuds où le rayon entre au-delà de l'intersection la plus proche trouvée
s6-every-node-whose-box-the-ray =  : chaque nœud dont le rayon traverse la boîte doit être parcouru, et les triangles de chaque feuille testés
s6-ray-at-spot-from-along-the = rayon { $k } vers Spot, issu de { $ray_origin } selon { $ray_direction } : le parcours donne { $maybe_gave }, le test de chaque triangle { $maybe_expected }{ $why }
s6-the-triangle-s-shading-normal = la normale d'ombrage du triangle { $what }
s6-a-triangle-without-vertex-normals = un triangle sans normales aux sommets

## s7

s7-a-2-x-2-texture-red = une texture de 2 × 2 (rouge, vert / bleu, blanc), lecture { $lookup } ({ $filter_debug }) en (u{ $s }v) = ({ $u }{ $s }{ $v }), { $what }
s7-the-camera-at-looking-at-the = la caméra en { $vec_eye } regardant l'origine, up { $vec }, plongée de { $plunge }°
s7-gave-no-aimed-orientation = { $what } : ne donne aucune orientation visée (Orientation::Aimed)
s7-the-eye = { $what } : l'œil
s7-right-forward-x-up-normalised-the = { $what } : right (vers la droite) = forward x up, normalisé (l'ordre du produit vectoriel en donne le signe)
s7-up = { $what } : up (vers le haut)
s7-back = { $what } : back (vers l'arrière)
s7-none = aucune orientation
s7-a-camera-at = une caméra en { $vec_eye }
s7-the-camera-at-looking-straight-down = la caméra en { $vec_new } regardant droit vers le bas, le long de up : obtenu { $vec_eye }, attendu aucune orientation (pas de direction vers la droite)

## trace

trace-pixel-row-column = le pixel (ligne { $row }, colonne { $column })
trace-followed-ray-by-ray-differs-first = suivi rayon par rayon, { $pixel } diffère d'abord à cet endroit : { $found }
trace-the-number-of-rays-yours-traced = le nombre de rayons : le vôtre en a tracé { $yours }, celui du cours { $theirs } (une limite de rebonds, ou une surface qui arrête ou poursuit le chemin)
trace-exercise = l'exercice { $id }, { $function }
trace-the-camera-ray-pixel-direction-row = le rayon de la caméra, { $s1_pixel_direction } : pixel_direction(ligne = { $row }, colonne = { $column }) de la caméra { $camera_width } × { $camera_height } : le vôtre a obtenu { $gave }, celui du cours obtient { $expected }
trace-the-camera-ray-yours-from-along = le rayon de la caméra : le vôtre issu de { $y_origin } selon { $y_direction }, celui du cours issu de { $c_origin } selon { $c_direction } : fait par le filtre du pixel (exercice s3.4), la lentille mince (s4.4) ou la visée (s7.2), selon la séance
trace-a-ray-after-a-miss-yours = un rayon après une absence d'intersection : le vôtre issu de { $y_origin } selon { $y_direction }, celui du cours issu de { $c_origin } selon { $c_direction }
trace-the-ray-leaving-the-hit-at = le rayon qui quitte l'intersection en P = { $at_point } (N = { $at_normal }) selon { $c_direction }
trace-its-origin-yours-the-course-s = { $from }, { $s2_spawn } : son origine, la vôtre { $y_origin }, celle du cours { $c_origin }
trace-the-incoming-direction-d-its-direction = { $from }, { $id_function }, la direction d'arrivée d = { $before_direction } : sa direction, la vôtre { $y_direction }, celle du cours { $c_direction }
trace-the-ray-from-along = le rayon issu de { $c_origin } selon { $c_direction }
trace-and-sphere-centre-radius-yours-gave = { $shown } et la sphère { $index } (centre { $course_centre }, rayon { $course_radius }), { $s1_intersect } : le vôtre a obtenu { $distance_gave }, celui du cours obtient { $distance_expected }
trace-yours-met-the-course-s-every = { $shown } : le vôtre a rencontré { $y_hit }, celui du cours { $c_hit } ; le test de chaque sphère concorde, donc la plus proche d'entre elles (exercice s1.3, Scene::nearest_sphere), ou les tests des maillages (s5.1, s5.2, s6.1, s6.2) ou la normale (s6.3), selon la séance
trace-no-hit = aucune intersection
trace-nothing = rien
trace-object-at-t-n = l'objet { $h_object } en t = { $h } (N = { $h_normal })
trace-the-display-of-the-same-radiance = l'affichage de la même luminance { $theirs }, { $exercise_s2 } : le vôtre a obtenu { $yours }, celui du cours obtient { $course_levels }
trace-the-light-computed-along-the-same = la lumière calculée le long des mêmes rayons et intersections : la vôtre { $yours }, celle du cours { $theirs } : Lambert (exercice s1.4), le poids du rebond (s3.3), le cône de la source et sa densité (s4.1, s4.2) ou la texture (s7.1), selon la séance

checklist-number = { $value }
checklist-separator = {" ; "}

exercise-s1-1 = le rayon de la caméra à travers un pixel
    .section = livre, séance 1, « Un disque blanc »
exercise-s1-2 = la distance rayon-sphère
    .section = livre, séance 1, « Un disque blanc »
exercise-s1-3 = l'intersection la plus proche
    .section = livre, séance 1, « Plusieurs sphères »
exercise-s1-4 = l'ombrage de Lambert avec la décroissance de la lumière
    .section = livre, séance 1, « Ombrage de Lambert »
exercise-s2-1 = le gamma
    .section = livre, séance 2, « Correction gamma »
exercise-s2-2 = l'origine décalée d'un nouveau rayon
    .section = livre, séance 2, « Ombres portées »
exercise-s2-3 = le rayon d'ombre vers la source
    .section = livre, séance 2, « Ombres portées »
exercise-s2-4 = la direction réfléchie
    .section = livre, séance 2, « Miroirs »
exercise-s2-5 = la réfraction et la réflexion totale interne
    .section = livre, séance 2, « Verre »
exercise-s3-1 = la direction pondérée par le cosinus
    .section = livre, séance 3, « Éclairage indirect »
exercise-s3-2 = le repère autour de la normale
    .section = livre, séance 3, « Éclairage indirect »
exercise-s3-3 = le rebond indirect
    .section = livre, séance 3, « Éclairage indirect »
exercise-s3-4 = le filtre gaussien du pixel
    .section = livre, séance 3, « Anticrénelage »
exercise-s4-1 = une direction dans le cône de la source
    .section = livre, séance 4, « Échantillonnage de la lumière »
exercise-s4-2 = la densité du cône
    .section = livre, séance 4, « Échantillonnage de la lumière »
exercise-s4-3 = un point de la lentille
    .section = livre, séance 4, « Profondeur de champ »
exercise-s4-4 = la lentille mince
    .section = livre, séance 4, « Profondeur de champ »
exercise-s5-1 = le test rayon-triangle
    .section = livre, séance 5, « Un maillage »
exercise-s5-2 = le test des tranches
    .section = livre, séance 5, « La boîte englobante »
exercise-s6-1 = la construction de la BVH
    .section = livre, séance 6, « BVH »
exercise-s6-2 = le parcours de la BVH
    .section = livre, séance 6, « BVH »
exercise-s6-3 = la normale interpolée
    .section = livre, séance 6, « Normales lissées »
exercise-s7-1 = la lecture de la texture
    .section = livre, séance 7, « Textures »
exercise-s7-2 = l'orientation de la caméra
    .section = livre, séance 7, « Le déplacement de la caméra »

checklist-look-again = chaque exercice réussit ses réponses connues : revoyez donc comment l'image se sert de l'exercice { $exercises }
checklist-exercise-separator = {" ; de l'exercice "}

s1-case-the-top-left = en haut à gauche
s1-case-the-bottom-right = en bas à droite
s1-case-the-top-right-of-the-centre = en haut et à droite du centre
s1-case-one-pixel-to-the-right = un pixel à droite
s1-case-one-pixel-down = un pixel plus bas
s1-case-in-front = devant l'œil
s1-case-around-the-eye = autour de l'œil
s1-case-behind-the-eye = derrière l'œil
s1-case-beside-the-ray-2-24-from = à côté du rayon, à 2,24 de la droite qui le porte
s1-case-on-an-oblique-ray = sur un rayon oblique
s1-case-facing-the-light-10-away = face à la source, à une distance de 10
s1-case-tilted-by-45-degrees = inclinée de 45 degrés
s1-case-facing-the-light-20-away = face à la source, à une distance de 20
s1-case-facing-away = dos à la source
s2-case-out = sortant
s2-case-in = entrant
s2-case-30-degrees-air-into-glass = 30 degrés, de l'air vers le verre
s2-case-straight-in = en incidence normale
s2-case-45-degrees-glass-into-air = 45 degrés, du verre vers l'air
s2-case-40-degrees-glass-into-air = 40 degrés, du verre vers l'air
s5-case-straight-down-through-0-25-0 = descendant à la verticale par (0,25 ; 0,5)
s5-case-straight-up-from-below-through-0 = montant à la verticale depuis le dessous par (0,2 ; 0,2)
s5-case-down-through-0-6-0-6 = descendant par (0,6 ; 0,6), au-delà du grand côté
s5-case-down-through-0-25-0-5 = descendant par (0,25 ; 0,5) avec t_max = 0,5
s5-case-parallel-to-the-triangle-s-plane = parallèle au plan du triangle
s5-case-pointing-away-up-from-above = qui s'en éloigne, montant depuis le dessus
s5-case-from-0-0-5-along-z = issu de (0 ; 0 ; 5) selon -z
s5-case-from-5-0-5-0-along = issu de (-5 ; 0,5 ; 0) selon +x
s5-case-from-5-0-0-along-x = issu de (5 ; 0 ; 0) selon -x
s5-case-from-inside-at-0-5-0 = issu de l'intérieur, en (0,5 ; 0 ; 0), selon -z
s5-case-from-3-0-5-along-z = issu de (3 ; 0 ; 5) selon -z, à côté de la boîte
s5-case-from-0-0-5-along-z-2 = issu de (0 ; 0 ; 5) selon +z, qui s'éloigne de la boîte
s5-case-from-0-0-5-along-z-3 = issu de (0 ; 0 ; 5) selon -z avec t_max = 3 (entré en t = 4, au-delà de t_max : manqué, car l'intervalle part de [0, t_max])
s5-case-from-4-4-0-along-1 = issu de (4 ; 4 ; 0) selon (-1 ; -1 ; 0) / sqrt 2
s5-case-lying-in-the-face-x-1 = couché dans la face x = -1, issu de (-1 ; 0 ; 5) selon (-0 ; 0 ; -1) (l'encadré du chapitre sur NaN : 1 / -0 vaut -l'infini, et 0 × l'infini vaut NaN)
s6-case-at-a-weights-1-0-0 = en A, poids (1 ; 0 ; 0)
s6-case-halfway-along-bc-weights-0-0 = au milieu de BC, poids (0 ; 0,5 ; 0,5)
s6-case-at-the-centre-weights-1-3 = au centre, poids (1/3 ; 1/3 ; 1/3)
s6-case-at-the-centre-seen-from-below = au centre, vu de dessous (la normale d'ombrage est tournée du côté où regarde la normale géométrique)
s7-case-the-top-left-texel-s-centre = le centre du texel en haut à gauche
s7-case-the-bottom-right-texel-s-centre = le centre du texel en bas à droite
s7-case-near-the-top-right-corner = près du coin en haut à droite
s7-case-one-texture-to-the-right-of = une largeur de texture à droite du centre du texel en haut à gauche
s7-case-a-quarter-of-a-texture-left = un quart de texture à gauche de son bord, qui revient au texel en haut à droite (le reste euclidien du chapitre : -1 revient à 1, là où % donne -1)
s7-case-the-top-left-texel-s-centre-2 = le centre du texel en haut à gauche
s7-case-the-texture-s-centre = le centre de la texture
s7-case-between-the-two-top-texels = entre les deux texels du haut

checklist-filter-nearest = au plus proche
checklist-filter-bilinear = bilinéaire

## rules

# La règle que chaque erreur de la liste de contrôle enfreint, en mots que son échec doit
# contenir (tests/exercises/mistakes/) : les mêmes que le message de sa vérification générée.
rule-s1-1-an-integer-division-drops-the = une division entière perd la moitié
rule-s1-1-rows-count-from-the-top = les lignes se comptent depuis le haut
rule-s1-1-h-2-tan-alpha = H / (2 tan alpha)
rule-s1-2-yours-is-where-it-leaves = la vôtre est où il sort
rule-s1-2-only-t-0-is-a = seul t > 0 est une intersection
rule-s1-2-t-0-is-its-own = t = 0 est son propre départ
rule-s1-2-but-the-far-root-s = mais la racine lointaine -s.d + sqrt(Delta) est une intersection
rule-s1-2-loses-r-2-in-the = perd R^2 dans l'arrondi de |s|^2
rule-s1-3-the-first-of-the-list = la première de la liste l'emporte
rule-s1-3-the-smallest-t-of-all = le plus petit t de toutes les sphères
rule-s1-4-the-1-pi-is-missing = il manque le 1/pi
rule-s1-4-it-gets-no-light-max = elle ne reçoit rien, max(0, <N, l>)
rule-s1-4-not-p-light-p-light = et non P_source / |P_source|
rule-s1-4-l-is-the-unit-vector = l est le vecteur unitaire vers la source
rule-s2-1-rounded-to-the-nearest-not = arrondi au plus proche, pas par défaut
rule-s2-1-use-the-gamma-given = utilisez le gamma donné
rule-s2-1-an-infinite-radiance-is-the = une luminance infinie est la plus claire qui soit
rule-s2-2-not-a-fixed-epsilon = pas un epsilon fixe
rule-s2-2-here-inwards-n = ici vers l'intérieur (-N)
rule-s2-2-not-against-n = pas par rapport à N
rule-s2-3-not-from-the-hit-point = pas depuis le point d'intersection
rule-s2-3-divide-the-vector-to-the = divisez le vecteur vers la source par sa longueur
rule-s2-4-subtracted-twice-it-turns-around = retranchée deux fois, elle se retourne
rule-s2-4-even-a-grazing-one = même rasant
rule-s2-5-eta-is-n1-n2 = eta vaut n1 / n2
rule-s2-5-total-internal-reflection-eta-2 = réflexion totale interne : eta^2
rule-s2-5-1-the-ray-refracts = <= 1 : le rayon est réfracté
rule-s3-1-0-included = 0 compris
rule-s3-2-the-frame-is-left-handed = le repère est indirect
rule-s3-2-near-n-z-1-n = près de N = -z, 1 + n_z
rule-s3-3-hit-spawn-direction = hit.spawn(direction)
rule-s3-4-with-the-sigma-given = avec le sigma donné
rule-s4-1-sin-2-theta-1-cos = sin^2(theta) = (1 - cos)(1 + cos)
rule-s4-2-use-the-cone-s-one = utilisez one_minus_cos_max
rule-s4-3-not-spread-as-the-density = pas répartis comme le dit la densité
rule-s4-4-starts-at-the-eye-start = part de l'œil, start
rule-s4-4-starts-in-the-eye-s = part du plan de l'œil
rule-s5-1-only-det-0-means-parallel = seul det = 0 signifie parallèle
rule-s5-1-only-t-0-decides = seul t > 0 décide
rule-s5-1-edges-belong-to-the-triangle = les arêtes appartiennent au triangle
rule-s5-2-miss-only-when-near-far = ne manquez que si near > far
rule-s6-1-whatever-the-box-s-size = quelle que soit la taille de la boîte
rule-s6-1-the-box-is-cut-across = la boîte est coupée en travers de son plus grand côté
rule-s6-2-closer-than-t-max = plus proches que t_max
rule-s6-2-goes-on-with-the-rest = continue avec le reste de la pile
rule-s6-3-weight-k-goes-with-corner = le poids k va avec le sommet k
rule-s6-3-the-vertex-the-triangle-names = du sommet que nomme le triangle
rule-s6-3-falls-back-to-the-geometric = se rabat sur la normale géométrique
rule-s6-3-normalise-it = normalisez-le
rule-s6-3-turned-to-the-geometric-normal = tournée du côté de la normale géométrique
rule-s7-1-y-1-v-h-not = y = (1 - v) H, et non v H
rule-s7-1-yours-swaps-u-and-v = le vôtre échange u et v, ou W et H
rule-s7-1-towards-minus-infinity = vers moins l'infini
rule-s7-1-by-half-a-texel = d'un demi-texel
rule-s7-2-not-at-the-origin = et non l'origine
rule-s7-2-which-mirrors-the-image = qui renverse l'image en miroir
rule-s7-2-back-forward = back = -forward
rule-s7-2-the-plunge-is-in-degrees = la plongée est en degrés
rule-s7-2-keeps-its-distance-to-it = reste à la même distance d'elle
rule-s7-2-right-normalize-forward-x-up = right = normalize(forward x up)
rule-s7-2-only-a-camera-looking-exactly = seule une caméra regardant exactement le long de up
