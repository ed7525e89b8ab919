### What the exercises' checklist says (`cargo test` in the course's crate and in
### an exercise crate): each failure in words, with the inputs and both answers.
### Its sections follow the checklist's files (tests/exercises/).

## checklist

checklist-checklist-passed-failed = checklist: { $passed } passed; { $failed } failed
checklist-exercise-further-down-fails-its-known = exercise { $exercise }, further down, fails its known answers: this image may need it right first
checklist-the-stage = the stage `{ $name }`: { $look }
checklist-next = ; next: { $next }
checklist-progress-session-exercises-the-name-filter = progress: session { $session }: exercises the name filter chose: { $chosen } of { $total }, done: { $done }{ $next }; cargo test without a name checks them all
checklist-progress-session-of-exercises-done-next = progress: session { $session }: { $done } of { $total } exercises done; next: { $next }
checklist-progress-session-all-exercises-done = progress: session { $session }: all { $total } exercises done
checklist-failed = FAILED
checklist-exercise-still-todo-write-it = exercise { $stub }: still todo!(); write it
checklist-needs-exercise-first-it-is-still = needs exercise { $stub } first: it is still todo!()
checklist-exercise = exercise { $exercise }: { $why }
checklist-exercise-fails-the-image-needs-it = exercise { $exercise } fails: the image needs it right first
checklist-it-calls-exercise-which-fails-too = it calls exercise { $need }, which fails too: fix that one first

## generated-common

generated-common-on-a-generated-input-the-simplest = { $what } on a generated input, the simplest that differs from the course's answer: { $why_message }
generated-common-on-generated-numbers = { $what } on generated numbers: { $why }
generated-common-message = ; { $w }
generated-common-yours-gave-the-course-s-gives = { $case }: yours gave { $gave }, the course's gives { $expected }{ $why }

## generated-s1

generated-s1-w-h-alpha-degrees-pixel-row = W = { $w }, H = { $h }, alpha = { $value }°, pixel (row { $row }, column { $column })
generated-s1-h-2-tan-alpha-would-change = {" "}(H / (2 tan alpha) would change sign past 90 degrees)
generated-s1-the-camera-looks-down-z-the = the camera looks down -z: the image plane is at z = -H / (2 tan(alpha/2)){ $wide }
generated-s1-message = ;{" "}
generated-s1-the-centre-of-pixel-j-is = the centre of pixel j is at x = j - W/2 + 1/2 for any W: here W = { $w } is odd, so W/2 = { $w2 } (an integer division drops the half)
generated-s1-the-centre-of-pixel-j-is-2 = the centre of pixel j is at x = j - W/2 + 1/2: the half pixel is off
generated-s1-the-centre-of-pixel-j-is-3 = the centre of pixel j is at x = j - W/2 + 1/2 (here j = { $j }, x = { $value }): yours is { $off } off
generated-s1-rows-count-from-the-top-of = rows count from the top of the image and y from the bottom: y = i - H/2 + 1/2 with i = H - 1 - row = { $i }
generated-s1-the-centre-of-row-i-is = the centre of row i is at y = i - H/2 + 1/2 for any H: here H = { $h } is odd, so H/2 = { $h2 } (an integer division drops the half)
generated-s1-the-centre-of-row-i-h = the centre of row i = H - 1 - row = { $i } is at y = i - H/2 + 1/2 = { $y }: yours is { $off } off
generated-s1-yours-is-h-2-tan-alpha = {" "}(yours is H / (2 tan alpha))
generated-s1-yours-uses-w-the-field-of = {" "}(yours uses W: the field of view is vertical)
generated-s1-the-image-plane-lies-at-h = the image plane lies at H / (2 tan(alpha/2)) = { $plane } from the eye, alpha the vertical field of view in radians; yours at { $theirs }{ $detail }
generated-s1-a-sphere-of-radius-at-the = a sphere of radius { $radius } at { $centre }, the ray from { $origin } along { $direction }
generated-s1-no-hit = no hit
generated-s1-the-sphere-is-radii-away-the = the sphere is { $distance } radii away: the textbook discriminant (s.d)^2 - (|s|^2 - R^2) loses R^2 in the rounding of |s|^2; compute it as R^2 - |s - (s.d) d|^2
generated-s1-the-sphere-is-behind-the-ray = the sphere is behind the ray: both roots are negative, and only t > 0 is a hit
generated-s1-the-ray-starts-on-the-sphere = the ray starts on the sphere, so t = 0 is its own start, not a hit: only t > 0 is a hit (here where it leaves, if it goes in)
generated-s1-only-t-0-is-a-hit = only t > 0 is a hit: yours is behind the ray's origin
generated-s1-from-inside-the-sphere-the-near = from inside the sphere the near root -s.d - sqrt(Delta) is negative: the hit is the far root -s.d + sqrt(Delta)
generated-s1-from-outside-the-hit-is-the = from outside, the hit is the nearer root -s.d - sqrt(Delta), where the ray enters; yours is where it leaves
generated-s1-the-ray-starts-on-the-sphere-2 = the ray starts on the sphere and goes in: its near root is 0, its own start, but the far root -s.d + sqrt(Delta) is a hit
generated-s1-from-inside-the-sphere-the-near-2 = from inside the sphere the near root is negative, but the far root -s.d + sqrt(Delta) is a hit
generated-s1-the-ray-grazes-the-sphere-its = the ray grazes the sphere, its line { $miss } radius from the centre: Delta = R^2 - |s - (s.d) d|^2 decides, and its sign must be right
generated-s1-radius-at = { $i }: radius { $r } at { $c }
generated-s1-spheres-the-ray-from-the-origin = spheres { $s1_message }, the ray from the origin along { $d }
generated-s1-sphere-at-t = sphere { $i } at t = { $value }
generated-s1-spheres-and-are-met-at-the = spheres { $j } and { $i } are met at the same distance: the first of the list wins (a later sphere replaces the nearest only when strictly nearer, t < t_nearest)
generated-s1-the-nearest-hit-is-the-smallest = the nearest hit is the smallest t of all the spheres met, not the first met in the list
generated-s1-a-light-of-power-at-the = a light of power { $intensity } at { $light_position }, the point { $point } with normal { $normal } and albedo { $albedo }
generated-s1-the-surface-faces-away-from-the = the surface faces away from the light (<N, l> = { $cos }): it gets no light, max(0, <N, l>)
generated-s1-l-points-from-the-shaded-point = l points from the shaded point P to the light: l = (P_light - P) / |P_light - P|, not P_light / |P_light|
generated-s1-the-diffuse-brdf-is-albedo-pi = the diffuse BRDF is albedo / pi: the 1/pi is missing
generated-s1-a-point-light-of-power-i = a point light of power I gives I / (4 pi d^2): the 1/(4 pi) is missing
generated-s1-yours-is-d-times-the-course = yours is d times the course's: the light falls off as 1/d^2, and l is the unit vector to the light (the vector to it divided by d)
generated-s1-the-light-falls-off-as-1 = the light falls off as 1/d^2: the falloff is missing
generated-s1-lambert-s-cosine-n-l-is = Lambert's cosine <N, l> is missing
generated-s1-1-pi-is-counted-twice = 1/pi is counted twice

## generated-s2

generated-s2-l-gamma = L = { $radiance }, gamma = { $gamma }
generated-s2-a-negative-or-nan-radiance-shows = a negative or NaN radiance shows as black, 0: clamp it at 0 before the power
generated-s2-an-infinite-radiance-is-the-brightest = an infinite radiance is the brightest there is: min(255, L^(1/gamma)) = 255
generated-s2-the-level-is-l-1-gamma = the level is L^(1/gamma) = { $exact } rounded to the nearest, not down
generated-s2-use-the-gamma-given-here-not = use the gamma given, here { $gamma }, not 2.2
generated-s2-the-level-is-l-1-gamma-2 = the level is L^(1/gamma): the exponent is 1/gamma, not gamma
generated-s2-or = ; or{" "}
generated-s2-the-hit-point-with-normal-on = the hit point { $hit_point } with normal { $hit_normal } on a sphere of radius { $radius } at { $centre }, the new ray along { $d }
generated-s2-yours-starts-at = { $case }: yours starts at { $ray_origin }; { $why }
generated-s2-the-new-ray-keeps-the-direction = the new ray keeps the direction it is given
generated-s2-leaving-outwards = Leaving outwards
generated-s2-going-in = Going in
generated-s2-it-meets-its-sphere-at-t = { $going_in } it meets its sphere at t = { $again }: the hit's normal N was turned to face the ray, so it points into the sphere here; the side a new ray starts on is the side its direction takes against the offset (from the geometric normal), not against N
generated-s2-leaving-outwards-it-meets-its-own = leaving outwards it meets its own sphere again at t = { $again } (shadow acne): push the origin off the surface by the error bound, along N on the side it leaves by
generated-s2-nothing = nothing
generated-s2-going-in-it-should-meet-the = going in it should meet the far side, about { $chord } away, and meets { $s2_nothing }: the origin must be pushed to the side the ray leaves by, here inwards (-N)
generated-s2-the-origin-moved-from-the-hit = the origin moved { $moved } from the hit point, more than a thousandth of the radius { $radius }: the offset follows the point's error bound, not a fixed epsilon
generated-s2-the-hit-point-with-normal-a = the hit point { $hit_point } with normal { $hit_normal }, a light at { $light }
generated-s2-the-direction-at-distance = the direction { $ray_direction } at distance { $gave }
generated-s2-the-direction-at-distance-2 = the direction { $towards } at distance { $expected }
generated-s2-the-direction-is-a-unit-vector = the direction is a unit vector: divide the vector to the light by its length
generated-s2-the-direction-is-the-unit-vector = the direction is the unit vector from the hit point to the light
generated-s2-the-distance-is-the-light-s = the distance is the light's from the ray's own origin, which the offset moved, not from the hit point
generated-s2-the-distance-is-light-origin-the = the distance is |light - origin|, the length from the ray's origin to the light
generated-s2-yours-points-the-other-way-r = yours points the other way: r = d - 2 (d . N) N
generated-s2-yours-leaves-d-as-it-is = yours leaves d as it is; every ray the mirror meets turns, even a grazing one, here d . N = { $along }: r = d - 2 (d . N) N
generated-s2-yours-removes-the-normal-part-subtracted = yours removes the normal part; subtracted twice, it turns around: r = d - 2 (d . N) N
generated-s2-the-sign-r-d-2-d = the sign: r = d - 2 (d . N) N
generated-s2-r-d-2-d-n-n = r = d - 2 (d . N) N
generated-s2-d-n = d = { $d }, N = { $normal }
generated-s2-none-total-internal-reflection = none (total internal reflection)
generated-s2-d-n-eta = d = { $d }, N = { $normal }, eta = { $eta }
generated-s2-eta-is-n1-n2-the-index = eta is n1 / n2, the index the ray leaves over the index it enters; yours used n2 / n1
generated-s2-total-internal-reflection-eta-2-sin = total internal reflection: eta^2 sin^2(theta_1) = { $sin2 } > 1, so there is no refracted ray
generated-s2-eta-2-sin-2-theta-1 = eta^2 sin^2(theta_1) = { $sin2 } <= 1: the ray refracts
generated-s2-the-refracted-ray-goes-on-through = the refracted ray goes on through the surface: its normal part is -cos(theta_2) N
generated-s2-t-eta-d-d-n-n = t = eta (d - (d . N) N) - sqrt(1 - eta^2 sin^2(theta_1)) N

## generated-s3

generated-s3-gave-expected-a-unit-vector-with = { $u1_u2 } gave { $w }: expected a unit vector with z >= 0
generated-s3-every-u-in-0-1-gives = { $gave }; every u in [0, 1) gives a direction, 0 included: a division by u (or by 0) is undefined there, as with tan^2(theta) = (1 - u2) / u2; r = sqrt(1 - u2) and z = sqrt(u2) divide by nothing
generated-s3-n = N = { $normal }
generated-s3-n-itself-is-the-frame-s = N itself is the frame's third axis: keep the normal given
generated-s3-t1-x-t2-n-the-frame = T1 x T2 = -N: the frame is left-handed; the chapter's is right-handed, T1 x T2 = N (exchange T1 and T2, or turn one over)
generated-s3-the-frame-has-a-nan-or = the frame has a NaN or infinite component: a division by a number that is 0 for this normal
generated-s3-has-the-length-the-tangents-are = { $name } has the length { $length }: the tangents are unit vectors
generated-s3-the-three-axes-are-at-right = { $name } = { $dot }: the three axes are at right angles, each product 0
generated-s3-near-n-z-1-n-z = ; near N = -z, 1 + n_z is 0 or all rounding: the chapter divides by sign + n_z, with sign = copysign(1, n_z), never less than 1 in size
generated-s3-the-furnace-of-radius-around-wall = the furnace of radius { $radius } around { $centre }, wall albedo { $wall }, the floor at { $point } with albedo { $albedo }, bounces allowed: { $bounces }, the mean of { $value } bounces
generated-s3-it-brought-back-nothing-the-bounce = it brought back nothing: the bounce's ray must leave the floor and meet the wall (start it with hit.spawn(direction), which scales its offset with the hit's rounding, whatever the furnace's size)
generated-s3-the-channels-are-off-by-different = the channels are off by different factors { $ratio }: each channel of the albedo weights its own channel, albedo * L component by component
generated-s3-it-is-what-one-bounce-fewer = it is what one bounce fewer brings back: the bounce's ray goes on with the bounces left after this one, bounces - 1
generated-s3-sigma-gave-expected-finite-numbers-the = sigma = { $sigma }, { $u1_u2 }: gave ({ $value }, { $y }), expected finite numbers (the logarithm of 1 - u1, never of 0)
generated-s3-sigma-the-offsets-spread-as-sigma = sigma = { $sigma }: { $why }; the offsets spread as sigma = { $measured } would (E[x^2 + y^2] = 2 sigma^2): the offset is sigma times a standard normal pair, with the sigma given

## generated-s4

generated-s4-the-cone-of-sin-2-theta = the cone of sin^2(theta_max) = { $sin2 } (1 - cos(theta_max) = { $cone_one_minus_cos_max }), { $u1_u2 }: gave { $w }, expected a unit vector of the cone, 1 - z <= 1 - cos(theta_max)
generated-s4-the-cone-of-sin-2-theta-2 = the cone of sin^2(theta_max) = { $sin2 }: { $why }
generated-s4-for-so-small-a-cone-1 = ; for so small a cone, 1 - cos(theta_max) taken from the cosine, and sin(theta) from 1 - cos^2(theta), are lost to rounding: take 1 - cos(theta) = xi1 * one_minus_cos_max and sin^2(theta) = (1 - cos)(1 + cos), as the chapter does
generated-s4-the-cone-of-sin-2-theta-3 = the cone of sin^2(theta_max) = { $sin2 } (cos(theta_max) = { $cone_cos_max }), cos(theta) = { $cone_cos_max2 }
generated-s4-outside-the-cone-cos-theta-cos = outside the cone, cos(theta) < cos(theta_max), no direction is drawn: the density is 0
generated-s4-this-direction-is-inside-the-cone = this direction is inside the cone, cos(theta) >= cos(theta_max): the density is 1 / (2 pi (1 - cos(theta_max)))
generated-s4-1-cos-theta-max-taken-from = 1 - cos(theta_max) taken from the cosine is lost to rounding for so small a cone: use the cone's one_minus_cos_max
generated-s4-the-density-is-one-over-the = the density is one over the cone's solid angle, 1 / (2 pi (1 - cos(theta_max))) = { $inside }
generated-s4-gave-expected-a-point-of-the = { $u1_u2 } gave ({ $value }, { $y }): expected a point of the unit disk, x^2 + y^2 <= 1
generated-s4-1-3-is-the-mean-of = {" "}(1/3 is the mean of r = xi: it crowds the centre)
generated-s4-the-mean-of-o-start-2 = { $start_d }: the mean of |o - start|^2 / aperture^2 over { $LENS_DRAWS } rays is { $mean }, expected 1/2: the starts are uniform over the lens's area{ $of_new }
generated-s4-the-lens-of-radius-focused-at = the lens of radius { $lens_aperture } focused at { $lens_focus }, the pinhole ray from { $start } along { $d }
generated-s4-the-ray-from-along = the ray from { $origin } along { $direction }
generated-s4-starts-off-the-lens-a-ray = { $case }: { $shown } starts off the lens: a ray through the lens starts in the eye's plane z = { $start_z }, within the aperture { $lens_aperture } of the eye (the eye plus aperture times a point of the unit disk)
generated-s4-misses-the-point-where-the-pinhole = { $case }: { $shown } misses the point { $focus_point } where the pinhole ray meets the focus plane, by { $miss }: { $origin_direction }
generated-s4-the-focus-plane-lies-at-the = the focus plane lies at the distance focus along -z, so the pinhole ray meets it at t = focus / -d_z, not after a length focus along the ray
generated-s4-the-pinhole-ray-starts-at-the = the pinhole ray starts at the eye, start, not at the origin
generated-s4-every-ray-through-the-lens-passes = every ray through the lens passes through that point, the direction is focus_point - origin

## generated-s5

generated-s5-the-triangle-a-b-c-the = the triangle A = { $a }, B = { $b }, C = { $c }, the ray from { $ray_origin } along { $ray_direction }, t_max = { $case_t_max }
generated-s5-det-0-the-ray-is-parallel = det = 0: the ray is parallel to the triangle's plane, or the triangle has no area; the test misses
generated-s5-a-hit-at-or-beyond-t = a hit at or beyond t_max is no hit: t < t_max
generated-s5-the-point-is-outside-the-triangle = the point is outside the triangle, or behind the ray: a hit needs b_B >= 0, b_C >= 0, b_B + b_C <= 1 and t > 0
generated-s5-b-b-and-b-c-are = b_B and b_C are exchanged: b_B is the weight of B, along e1 = B - A, and b_C of C, along e2 = C - A
generated-s5-the-point-is-on-the-triangle = the point is on the triangle's edge or corner (b_B = { $beta }, b_C = { $gamma }): edges belong to the triangle, b_B >= 0, b_C >= 0 and b_B + b_C <= 1, not strict
generated-s5-the-ray-meets-the-triangle-from = the ray meets the triangle from its back (det = { $det } < 0): both sides are hit
generated-s5-a-hit-at-t-nearer-than = a hit at t = { $value }, nearer than a fixed epsilon, is a hit: only t > 0 decides
generated-s5-for-a-triangle-this-small-det = for a triangle this small det = { $det } is tiny, not 0: only det = 0 means parallel (a fixed threshold misses small triangles)
generated-s5-the-point-is-inside-the-triangle = the point is inside the triangle (b_B >= 0, b_C >= 0, b_B + b_C <= 1) and in front of the ray before t_max
generated-s5-or = ; or{" "}
generated-s5-the-box-from-to-the-ray = the box from { $case_bounds } to { $case_bounds2 }, the ray from { $ray_origin } along { $ray_direction }, t_max = { $case_t_max }
generated-s5-a-flat-box-no-thickness-along = a flat box (no thickness along an axis, the box of a triangle lying in a plane) is met where near = far: miss only when near > far, and widen the exit by 1 + 2 gamma_3 so that rounding never puts near past far
generated-s5-from-inside-the-box-the-ray = from inside the box the ray is in it at once: the entry is 0 (near starts at 0, not at -infinity)
generated-s5-an-entry-at-or-beyond-t = an entry at or beyond t_max is no hit: far starts at t_max
generated-s5-a-zero-component-of-the-direction = a zero component of the direction gives 1 / d = +-infinity, and 0 x infinity = NaN where the ray lies in a face: order the planes by the sign of 1 / d and compare so that NaN leaves the interval as it is

## generated-s6

generated-s6-no-hit = no hit
generated-s6-message = { $case }: { $fault }
generated-s6-the-course-s-walk-through-your = { $case }: the course's walk through your hierarchy finds { $show_gave }, testing every triangle { $show_expected }; each box must hold its triangles
generated-s6-only-hits-closer-than-t-max = only hits closer than t_max = { $t_max } count, in the leaves' triangles as in the boxes
generated-s6-a-nearer-hit-lies-in-a = a nearer hit lies in a box the walk left out: a node is skipped only when the ray enters its box beyond the nearest hit so far, and the walk goes on with the rest of the stack
generated-s6-the-ray-starts-inside-the-mesh = the ray starts inside the mesh's box, which it enters at t = 0: every box it passes through is visited
generated-s6-the-walk-missed-a-hit-every = the walk missed a hit: every box the ray enters before the nearest hit so far is visited, its children too
generated-s6-the-nearest-hit-is-the-one = the nearest hit is the one testing every triangle finds, closer than t_max
generated-s6-without-vertex-normals-the-shading-normal = without vertex normals the shading normal is the geometric normal
generated-s6-here-b-a-n-a-b = here b_A N_A + b_B N_B + b_C N_C = 0 (the vertex normals cancel, or are zero), and there is no direction to normalise: the shading normal falls back to the geometric normal
generated-s6-the-shading-normal-is-turned-to = the shading normal is turned to the geometric normal's side: where N_s . N_g < 0, it is -N_s
generated-s6-b-a-n-a-b-b = b_A N_A + b_B N_B + b_C N_C is shorter than 1 wherever the vertex normals differ (here { $gave_length } long): normalise it
generated-s6-n-s-normalize-b-a-n = N_s = normalize(b_A N_A + b_B N_B + b_C N_C), turned to the geometric normal's side
generated-s6-or = ; or{" "}
generated-s6-weight-k-goes-with-corner-k = weight k goes with corner k: b_A N_A + b_B N_B + b_C N_C, with b_B = beta and b_C = gamma
generated-s6-corner-k-s-normal-is-that = corner k's normal is that of the vertex the triangle names: here normals[{ $i }], normals[{ $j }], normals[{ $k }], not normals[0], normals[1], normals[2]

## generated-s6-hierarchy

generated-s6-hierarchy-bvh-order-lists-triangle-but-the = Bvh::order lists triangle { $t }, but the mesh has { $count }, numbered from 0
generated-s6-hierarchy-bvh-order-lacks-triangle-every-triangle = Bvh::order lacks triangle { $t }: every triangle is in exactly one leaf
generated-s6-hierarchy-bvh-order-lists-triangle-times-every = Bvh::order lists triangle { $t } { $seen } times: every triangle is in exactly one leaf
generated-s6-hierarchy-the-hierarchy-has-no-node-node = the hierarchy has no node: node 0 is the root
generated-s6-hierarchy-the-hierarchy-is-deeper-than-levels = the hierarchy is deeper than { $DEPTH } levels at node { $index }
generated-s6-hierarchy-triangle-bvh-order-is-in-no = triangle { $order_slot } (Bvh::order[{ $slot }]) is in no leaf, so no ray finds it: the leaves' ranges cover the whole of Bvh::order
generated-s6-hierarchy-leaf-node-covers-bvh-order-which = leaf node { $index } covers Bvh::order[{ $range_start }..{ $range_end }], which lies past its end or is another leaf's too: every triangle is in exactly one leaf
generated-s6-hierarchy-the-box-of-leaf-node-to = the box of leaf node { $index }, { $node_bounds } to { $node_bounds2 }, does not hold its triangle { $t }, { $a } { $b } { $c }: a leaf's box is the min and max of its triangles' corners
generated-s6-hierarchy-if-yours-cut-it-along-where = ; if yours cut it along { $names_a }, where they all fall on one side: the box is cut across its longest side, here { $names_axis }
generated-s6-hierarchy-leaf-node-holds-triangles-its-box = leaf node { $index } holds { $node_count } triangles, its box { $bounds_axis } long along { $names_axis }, its longest side, with centroids on both sides of that side's middle: splitting stops at { $LEAF_SIZE } triangles, or when every centroid falls on one side, whatever the box's size{ $across }
generated-s6-hierarchy-node-is-an-inner-node-count = node { $index } is an inner node (count = 0) whose children, nodes { $first } and { $first2 }, lie past the { $bvh_nodes } nodes
generated-s6-hierarchy-the-box-of-node-to-sticks = the box of node { $child }, { $child_bounds } to { $child_bounds2 }, sticks out of its parent's, node { $index }, { $node_bounds } to { $node_bounds2 }: each child's box lies inside its parent's

## generated-s6-meshes

generated-s6-meshes-scattered = scattered
generated-s6-meshes-copies-of-one-triangle-the-same = copies of one triangle (the same centroid) and a few others
generated-s6-meshes-all-in-the-plane-x = all in the plane x = { $at }
generated-s6-meshes-some-degenerate-two-corners-the-same = some degenerate (two corners the same, or three in a line)
generated-s6-meshes-a-mesh-of-triangles-of-size = a mesh of { $count } triangles, { $layout }, of size { $size } around { $at }
generated-s6-meshes-triangle = , triangle { $t }: { $a } { $b } { $c }
generated-s6-meshes-the-ray-from-along = the ray from { $origin } along { $direction }{ $reach }
generated-s6-meshes-no-vertex-normals = no vertex normals
generated-s6-meshes-the-vertex-normals-as-the-file = the vertex normals { $listed } as the file gives them
generated-s6-meshes-triangle-of-the-vertices-the-weights = triangle { $triangle } of the vertices ({ $i }{ $s }{ $j }{ $s }{ $k }), { $normals }, the weights (b_A, b_B, b_C) = ({ $a }{ $s }{ $b }{ $s }{ $c }), the geometric normal { $geometric }

## generated-s7-camera

generated-s7-camera-the-camera-at-looking-at-up = the camera at { $eye } looking at { $target }, up { $up }, plunge { $plunge }°
generated-s7-camera-no-frame = no frame
generated-s7-camera-the-eye-at-right-up-back = the eye at { $eye }, right { $r }, up' { $u }, back { $b }
generated-s7-camera-the-camera-looks-at-the-target = the camera looks at the target, here { $camera_target }, not at the origin: forward = normalize(target - eye)
generated-s7-camera-the-plunge-is-in-degrees-turn = the plunge is in degrees: turn it into radians, psi pi / 180, for the rotation
generated-s7-camera-the-eye-turns-around-the-target = the eye turns around the target and keeps its distance to it, { $offset_length }; yours is { $target_length } from it
generated-s7-camera-the-eye-rises-around-the-target = the eye rises around the target: target + q (eye - target), q the rotation by the plunge about normalize((eye - target) x up)
generated-s7-camera-right-forward-x-up-not-up = right = forward x up, not up x forward, which mirrors the image
generated-s7-camera-right-normalize-forward-x-up-forward = right = normalize(forward x up): forward x up is a unit vector only when up is one and perpendicular to the view; here up is { $up_length } long and forward x up { $right_length } long
generated-s7-camera-back-forward-camera-space-z-points = back = -forward: camera-space z points from the scene towards the eye
generated-s7-camera-forward-normalize-target-eye-right-normalize = forward = normalize(target - eye), right = normalize(forward x up), up' = right x forward, back = -forward
generated-s7-camera-the-camera-looks-exactly-along-up = the camera looks exactly along up: forward x up = 0 gives no right-hand direction, and aim gives None
generated-s7-camera-the-view-is-radians-from-up = the view is { $angle } radians from up: only a camera looking exactly along up has no frame, and right = normalize(forward x up) for any length of forward x up

## generated-s7-texture

generated-s7-texture-a-x-texture-rows-from-the = a { $w } x { $h } texture, rows from the top: { $rows }, { $lookup } lookup ({ $filter_debug }) at (u{ $s }v) = ({ $u }{ $s }{ $v })
generated-s7-texture-v-runs-from-the-bottom-v = v runs from the bottom (v = 0) to the top (v = 1) while rows count from the top: y = (1 - v) H, not v H
generated-s7-texture-u-runs-along-the-width-and = u runs along the width and v along the height, x = u W and y = (1 - v) H with W = { $w } and H = { $h }: yours swaps u and v, or W and H, which only a texture that is not square shows
generated-s7-texture-a-point-s-texel-is-floor = a point's texel is floor(x), towards minus infinity: floor(-0.5) = -1, where a cast to an integer truncates towards zero, to 0
generated-s7-texture-texel-k-s-centre-is-at = texel k's centre is at k + 1/2: the bilinear filter shifts the point by half a texel, x' = x - 1/2 and y' = y - 1/2, before splitting it
generated-s7-texture-or = ; or{" "}

## generated-sampling

generated-sampling-from-to-the-azimuth-from-to = { $radial } from { $band } to { $band2 }, the azimuth from { $low }° to { $high }°
generated-sampling-of-draws-fell-where-the-chapter = { $counts_worst } of { $draws } draws fell where the chapter's density puts { $PER_CELL }: { $describe_worst }, so the draws are not spread as the density says (chi-square { $statistic_written } over { $cells } cells of equal probability, above { $limit_written }, which a right answer passes but once in a million)

## images

images-yours-is = ; yours is { $yours }
images-the-stage-at-x-differs-from = the stage `{ $stage_name }` at { $film_width } x { $film_height } differs from { $reference }{ $place }: { $why }{ $traced }
images-of-pixels-differ-by-more-than = { $d_count } of { $outcome_differs } pixels differ by more than { $TOLERANCE } display levels (the most, { $worst } levels, at column { $at }, row { $at2 })
images-of-blocks-of-8-x-8 = { $d_count } of { $outcome_differs } blocks of 8 x 8 pixels differ beyond the noise
images-message = ; { $hint }
images-it-is-the-reference-upside-down = it is the reference upside down: row 0 is the top of the image, so the pixel's height counts from the bottom, i = H - 1 - row
images-it-is-the-reference-mirrored-left = it is the reference mirrored left to right: column j grows to the right, x = j - W/2 + 0.5
images-it-shows-the-radiance-without-the = it shows the radiance without the display's gamma: a pixel is L^(1/gamma), here gamma = { $gamma }
images-the-display-s-gamma-is-applied = the display's gamma is applied twice: a pixel is L^(1/gamma), once
images-about-pi-times-too-bright-a = about pi times too bright: a diffuse surface reflects albedo / pi (the BRDF), and the light's power spreads over 4 pi r^2
images-about-pi-times-too-dark-is = about pi times too dark: is 1 / pi counted twice, or the cosine-weighted pdf's pi not cancelled?
images-about-pi-times-too-dark-is-2 = about pi times too dark: is 1 / pi counted twice? A diffuse surface reflects albedo / pi, once
images-about-twice-too-bright-or-too = about twice too bright or too dark: a sample's weight must match the density it was drawn with (a direction in the light's cone: 1 / (2 pi (1 - cos theta_max)); a cosine-weighted bounce: cos(theta) / pi)
images-about-twice-too-bright-or-too-2 = about twice too bright or too dark: the weight of a bounce must match how its direction was drawn (for a cosine-weighted direction the cosine and pi cancel, leaving the albedo)
images-brighter-than-the-reference-overall-per = { $percent }% brighter than the reference overall (per channel { $r }x{ $s }{ $g }x{ $s }{ $b }x)
images-darker-than-the-reference-overall-per = { $percent }% darker than the reference overall (per channel { $r }x{ $s }{ $g }x{ $s }{ $b }x)
images-brightness-against-the-reference-x = { $hint } (brightness against the reference: { $mean }x)
images-message-2 = { $path }: { $error }

## isolation

isolation-it-did-not-end-within-s = it did not end within { $seconds } s: is there a loop that never stops?
isolation-it-never-ended-the-stack-overflowed = it never ended: the stack overflowed, as a recursion without an end makes it (does each call go one level deeper, towards a last level where it stops?)
isolation-it-asked-for-more-than-gib = it asked for more than { $gib } GiB of memory: a loop or a recursion without an end? (a hierarchy must stop splitting, each node holding fewer triangles than its parent)
isolation-it-stopped = it stopped: { $last }

## known

known-gave-expected-within = { $what }: gave { $gave }, expected { $expected } (within { $tolerance })
known-no-hit = no hit
known-sphere-at-t = sphere { $i } at t = { $t }

## mistakes-common

mistakes-common-the-right-answer-of-exercise-fails = the right answer "{ $right_what }" of exercise { $right_exercise } fails its generated check: { $why }
mistakes-common-the-mistake-of-exercise-passes-its = the mistake "{ $mistake_what }" of exercise { $mistake_exercise } passes its generated check
mistakes-common-the-mistake-of-exercise-fails-without = the mistake "{ $mistake_what }" of exercise { $mistake_exercise } fails without naming its rule ("{ $words }"): { $why }

## panics

panics-message = ; { $r }
panics-panicked-in-exercise-at = panicked in exercise { $title_marker }, at { $place }: { $message }{ $rule }
panics-panicked = panicked: { $message } ({ $place }){ $rule }
panics-an-unsigned-integer-u32-usize-went = an unsigned integer (u32, usize) went below 0: convert to Real before subtracting, since the chapter computes in real numbers
panics-an-integer-went-past-its-largest = an integer went past its largest value: compute in Real
panics-an-index-past-the-end-of = an index past the end of a list: a list of n things is indexed from 0 to n - 1
panics-unwrap-on-none-none-no-hit = unwrap() on None: None (no hit, say) is a case of its own, to handle with match or if let
panics-an-integer-division-by-0-divide = an integer division by 0: divide in Real, or test the divisor

## s1

s1-pixel-row-column-gave-the-direction = pixel (row { $row }, column { $column }) gave the direction { $vec_gave }
s1-the-direction-through-pixel-row-column = the direction through pixel (row { $row }, column { $column }), { $place } of a 4 x 2 image with a 90-degree field of view, normalised
s1-pixel-direction-pixel-direction-0-0 = pixel_direction({ $row }, { $column }) - pixel_direction(0, 0), { $step } in an 8 x 4 image with a 60-degree field of view (the direction is in pixel units: session 3 adds its jitter, in pixels, to it)
s1-a-sphere-of-radius-at-the = { $test }: a sphere of radius { $radius } at { $vec_centre } { $what }, the ray from { $vec } along { $ray_direction }: gave { $maybe_gave }, expected { $maybe_expected }
s1-sphere-intersect-a-sphere-of-radius = Sphere::intersect: a sphere of radius 1 at (0.5, 0, -{ $far }), the ray from the origin along -z: gave { $maybe_gave }, expected { $maybe_expected } (the textbook discriminant loses 0.75 to rounding next to { $far }^2: compute it as R^2 - |s - (s.d) d|^2)
s1-spheres-at-z-10-5-and = spheres at z = -10, -5 and 3 (numbers 0, 1, 2), the ray from the origin along -z: gave { $nearest_gave }, expected { $nearest }
s1-the-same-spheres-the-ray-along = the same spheres, the ray along +y: gave { $nearest_gave }, expected { $nearest }
s1-albedo-at-normal-under-a-light = albedo { $vec_albedo } at { $vec_point }, normal { $vec_normal }, { $what }, under a light of power 400 pi^2 at { $light_position }

## s2

s2-radiance-with-gamma-gave-expected = radiance { $radiance } with gamma { $gamma }: gave { $gave }, expected { $expected }
s2-on-a-wall-a-sphere-of = on a wall, a sphere of radius { $radius } at { $at }
s2-on-a-sphere-of-radius-at = on a sphere of radius { $radius } at { $at }
s2-the-ray-going-starts-at-from = { $what }, the ray going { $way } starts at { $ray_origin }, { $hit_point } from the hit point { $hit_point2 }: expected a start within 1e-3
s2-a-ray-leaving-outwards-from-the = { $what }, a ray leaving outwards from the hit point meets the sphere again at { $maybe_again }: expected { $maybe } (its origin must be pushed off the surface, outwards)
s2-a-ray-going-into-the-sphere = { $what }, a ray going into the sphere from the hit point gave { $maybe_through }: expected the far side, about { $ball_radius } away (its origin must be pushed off the surface, inwards)
s2-the-direction-towards-a-light-13 = { $what }, the direction towards a light 13 away along { $vec_new }
s2-the-distance-to-that-light = { $what }, the distance to that light
s2-the-shadow-ray-starts-at-not = { $what }, the shadow ray starts at { $ray_origin }, not near the hit point { $hit_point }
s2-d-reflected-about-n = d = { $vec_d } reflected about N = { $vec }
s2-none-total-internal-reflection = none (total internal reflection)
s2-d-n-eta-n1-n2-gave = { $what }: d = { $vec_d }, N = { $vec }, eta = n1 / n2 = { $eta }: gave { $show_gave }, expected { $show_expected }

## s3

s3-u1-u2-gave-expected-a-unit = (u1{ $s }u2) = ({ $u1 }{ $s }{ $u2 }) gave { $vec_w }: expected a unit vector with z >= 0
s3-the-mean-of-cos-theta-z = the mean of cos(theta) = z
s3-uniform-directions-would-give-1-2 = { $e }; uniform directions would give 1/2: the density must be cos(theta) / pi
s3-the-azimuth-phi-2-pi-u = { $e }: the azimuth phi = 2 pi u covers the whole circle, evenly, so that x and y average 0
s3-the-mean-of = the mean of { $what }
s3-the-frame-of-n = the frame of N = { $vec }
s3-message = :
s3-its-axis-n = { $what }: its axis N
s3-the-length-of = { $what }: the length of { $name } = { $vec }
s3-inside-a-furnace-whose-wall-glows = inside a furnace whose wall glows with radiance 1, the mean of { $n } bounces from the floor with albedo { $albedo } gave { $vec_mean }, expected { $albedo }{ $mean_element_sum }: the bounce brings back albedo * L(w) when its direction has density cos(theta) / pi
s3-a-bounce-from-the-furnace-s = a bounce from the furnace's floor met the floor itself at t = { $h_h }: start the bounce's ray off the surface with hit.spawn(direction) (session 2), not at the hit point
s3-the-wall-was-seen-with-no = : the wall was seen with no bounce left; the bounce's ray goes on with the bounces left after this one, bounces - 1
s3-inside-the-same-furnace-with-3 = inside the same furnace, with 3 bounces allowed, the mean bounce from the floor gave { $vec_mean }, expected 1.75 albedo = { $vec }: the wall seen with 2 bounces left sends 1 + 0.5 (1 + 0.5){ $hint }
s3-2-3-of-it-is-the = ; 2/3 of it is the mean cosine: the cosine is counted although the direction's density already holds it
s3-1-pi-of-it-the-brdf = ; 1/pi of it: the BRDF's 1/pi is counted although the density's pi cancels it
s3-twice-it-the-weight-divides-by = ; twice it: the weight divides by the density of a uniform direction, 1 / (2 pi), not of a cosine-weighted one
s3-the-share-of-offsets-within-sigma = the share of offsets within sigma of the centre
s3-u1-gave-expected-finite-numbers-the = u1 = { $u1 }: gave ({ $x }{ $s }{ $y }), expected finite numbers (the logarithm of 1 - u1, never of 0)

## s4

s4-the-cone-of-half-angle-30 = the cone of half-angle 30 degrees around +z, (u1{ $s }u2) = ({ $u1 }{ $s }{ $u2 }): gave { $vec_w }, expected a unit vector with z >= cos(30) = 0.866
s4-the-cone-of-half-angle-30-2 = the cone of half-angle 30 degrees: the mean of cos(theta)
s4-uniform-over-the-cone-s-solid = { $e }: uniform over the cone's solid angle, cos(theta) is uniform between cos(theta_max) and 1 (not theta between 0 and theta_max)
s4-the-density-of-the-30-degree = the density of the 30-degree cone at cos(theta) = { $cos }
s4-outside-it = , outside it
s4-gave-the-point-outside-the-unit = gave the point ({ $x }{ $s }{ $y }), outside the unit disk
s4-with-r-xi-the-points-crowd = { $e }; with r = xi the points crowd the centre (1/3): uniform over the area needs r = sqrt(xi)
s4-the-share-of-points-within-r = the share of points within r = 1/2
s4-a-ray-through-the-lens-of = a ray through the lens of radius 0.5 starts at { $vec_origin }: expected a point of the lens (z = 0, within 0.5 of the eye)
s4-the-ray-from-along-never-reaches = the ray from { $vec_origin } along { $vec_direction } never reaches the focus plane z = -10: it must head from its point of the lens towards (2.5, 5, -10), where the pinhole ray meets that plane
s4-the-ray-from-along-where-it = the ray from { $vec_origin } along { $vec_direction }, where it crosses the focus plane z = -10 (a plane at the focus distance along the view, not a sphere around the eye: the pinhole direction is scaled so that its z is -focus)
s4-the-mean-of-x-2-y = the mean of x^2 + y^2 over the starts on the lens

## s5

s5-the-triangle-a-ray-gave-expected = the triangle { $vec_a }, { $vec_b }, { $vec_c }, a ray { $what }: gave { $h_gamma }, expected { $show_expected }
s5-the-box-from-to-a-ray = the box from { $vec_cube } to { $vec_cube2 }, a ray { $what } (d = { $ray_direction }): gave { $maybe_gave }, expected { $maybe_expected }

## s6

s6-bvh-order-holds-the-triangle-number = Bvh::order holds the triangle number { $t }, but Spot has { $n }
s6-bvh-order-must-list-each-of = Bvh::order must list each of Spot's { $n } triangles once: it has { $bvh_order } entries, lacks triangle { $missing } and lists triangle { $twice } more than once
s6-the-hierarchy-has-no-node-node = the hierarchy has no node: node 0 is the root
s6-the-hierarchy-is-deeper-than-64 = the hierarchy is deeper than 64 levels at node { $index }
s6-a-node-points-to-node-past = a node points to node { $index }, past the { $bvh_nodes } nodes
s6-the-leaf-at-node-covers-bvh = the leaf at node { $index } covers Bvh::order[{ $range_start }..{ $range_end }], which another leaf covers too or lies past the end
s6-the-box-of-leaf-node-to = the box of leaf node { $index }, { $node_bounds } to { $node_bounds2 }, does not hold its triangle { $order_slot }
s6-node-points-to-node-past-the = node { $index } points to node { $child }, past the { $bvh_nodes } nodes: an inner node's children are the nodes first and first + 1, pushed side by side when it is split
s6-the-box-of-node-sticks-out = the box of node { $child } sticks out of its parent's, node { $index }
s6-triangle-bvh-order-is-in-no = triangle { $triangle } (Bvh::order[{ $slot }]) is in no leaf: a ray can never find it; the leaves' ranges must cover the whole of Bvh::order
s6-spot-s-triangles-end-in-leaves = Spot's { $n } triangles end in { $leaves } leaves: expected the boxes split until about 4 triangles a leaf
s6-a-nearer-hit-lies-in-a = : a nearer hit lies in a node the walk left for later; go on with the rest of the stack, and skip only the nodes entered beyond the nearest hit so far
s6-every-node-whose-box-the-ray = : every node whose box the ray enters must be walked, and each leaf's triangles tested
s6-ray-at-spot-from-along-the = ray { $k } at Spot, from { $ray_origin } along { $ray_direction }: the walk gave { $maybe_gave }, testing every triangle { $maybe_expected }{ $why }
s6-the-triangle-s-shading-normal = the triangle's shading normal { $what }
s6-a-triangle-without-vertex-normals = a triangle without vertex normals

## s7

s7-a-2-x-2-texture-red = a 2 x 2 texture (red, green / blue, white), { $lookup } lookup ({ $filter_debug }) at (u{ $s }v) = ({ $u }{ $s }{ $v }), { $what }
s7-the-camera-at-looking-at-the = the camera at { $vec_eye } looking at the origin, up { $vec }, plunge { $plunge }°
s7-gave-no-aimed-orientation = { $what }: gave no aimed orientation
s7-the-eye = { $what }: the eye
s7-right-forward-x-up-normalised-the = { $what }: right = forward x up, normalised (the cross product's order gives its sign)
s7-up = { $what }: up
s7-back = { $what }: back
s7-none = none
s7-a-camera-at = a camera at { $vec_eye }
s7-the-camera-at-looking-straight-down = the camera at { $vec_new } looking straight down along up: gave { $vec_eye }, expected none (no right-hand direction)

## trace

trace-pixel-row-column = pixel (row { $row }, column { $column })
trace-followed-ray-by-ray-differs-first = followed ray by ray, { $pixel } differs first at { $found }
trace-the-number-of-rays-yours-traced = the number of rays: yours traced { $yours }, the course's { $theirs } (a bounce limit, or a surface that stops or goes on)
trace-exercise = exercise { $id }, { $function }
trace-the-camera-ray-pixel-direction-row = the camera ray, { $s1_pixel_direction }: pixel_direction(row = { $row }, column = { $column }) of the camera { $camera_width } x { $camera_height }: yours gave { $gave }, the course's gives { $expected }
trace-the-camera-ray-yours-from-along = the camera ray: yours from { $y_origin } along { $y_direction }, the course's from { $c_origin } along { $c_direction }: made by the pixel filter (exercise s3.4), the thin lens (s4.4) or the aim (s7.2), as far as the session goes
trace-a-ray-after-a-miss-yours = a ray after a miss: yours from { $y_origin } along { $y_direction }, the course's from { $c_origin } along { $c_direction }
trace-the-ray-leaving-the-hit-at = the ray leaving the hit at P = { $at_point } (N = { $at_normal }) along { $c_direction }
trace-its-origin-yours-the-course-s = { $from }, { $s2_spawn }: its origin, yours { $y_origin }, the course's { $c_origin }
trace-the-incoming-direction-d-its-direction = { $from }, { $id_function }, the incoming direction d = { $before_direction }: its direction, yours { $y_direction }, the course's { $c_direction }
trace-the-ray-from-along = the ray from { $c_origin } along { $c_direction }
trace-and-sphere-centre-radius-yours-gave = { $shown } and sphere { $index } (centre { $course_centre }, radius { $course_radius }), { $s1_intersect }: yours gave { $distance_gave }, the course's gives { $distance_expected }
trace-yours-met-the-course-s-every = { $shown }: yours met { $y_hit }, the course's { $c_hit }; every sphere's test agrees, so the nearest of them (exercise s1.3, Scene::nearest_sphere), or the meshes' tests (s5.1, s5.2, s6.1, s6.2) or the normal (s6.3), as far as the session goes
trace-no-hit = no hit
trace-nothing = nothing
trace-object-at-t-n = object { $h_object } at t = { $h } (N = { $h_normal })
trace-the-display-of-the-same-radiance = the display of the same radiance { $theirs }, { $exercise_s2 }: yours gave { $yours }, the course's gives { $course_levels }
trace-the-light-computed-along-the-same = the light computed along the same rays and hits: yours { $yours }, the course's { $theirs }: Lambert (exercise s1.4), the bounce's weight (s3.3), the light's cone and density (s4.1, s4.2) or the texture (s7.1), as far as the session goes

## Numbers and vectors: a number with the digits the checklist chose (the decimal
## mark is the language's), and the separator between a vector's components.

checklist-number = { $value }
checklist-separator = {", "}

## Each exercise's title and the book's section that teaches it. English takes
## them from the exercise's marker in the course's code ($title, $section); a
## translation writes its own.
exercise-s1-1 = { $title }
    .section = { $section }
exercise-s1-2 = { $title }
    .section = { $section }
exercise-s1-3 = { $title }
    .section = { $section }
exercise-s1-4 = { $title }
    .section = { $section }
exercise-s2-1 = { $title }
    .section = { $section }
exercise-s2-2 = { $title }
    .section = { $section }
exercise-s2-3 = { $title }
    .section = { $section }
exercise-s2-4 = { $title }
    .section = { $section }
exercise-s2-5 = { $title }
    .section = { $section }
exercise-s3-1 = { $title }
    .section = { $section }
exercise-s3-2 = { $title }
    .section = { $section }
exercise-s3-3 = { $title }
    .section = { $section }
exercise-s3-4 = { $title }
    .section = { $section }
exercise-s4-1 = { $title }
    .section = { $section }
exercise-s4-2 = { $title }
    .section = { $section }
exercise-s4-3 = { $title }
    .section = { $section }
exercise-s4-4 = { $title }
    .section = { $section }
exercise-s5-1 = { $title }
    .section = { $section }
exercise-s5-2 = { $title }
    .section = { $section }
exercise-s6-1 = { $title }
    .section = { $section }
exercise-s6-2 = { $title }
    .section = { $section }
exercise-s6-3 = { $title }
    .section = { $section }
exercise-s7-1 = { $title }
    .section = { $section }
exercise-s7-2 = { $title }
    .section = { $section }

## A stage that differs while every exercise passes its known answers: the
## exercises its image uses, joined by the separator.
checklist-look-again = every exercise passes its known answers, so look again at how the image uses exercise { $exercises }
checklist-exercise-separator = {"; exercise "}

## The known answers' cases, as the failures name them.

s1-case-the-top-left = the top left
s1-case-the-bottom-right = the bottom right
s1-case-the-top-right-of-the-centre = the top, right of the centre
s1-case-one-pixel-to-the-right = one pixel to the right
s1-case-one-pixel-down = one pixel down
s1-case-in-front = in front
s1-case-around-the-eye = around the eye
s1-case-behind-the-eye = behind the eye
s1-case-beside-the-ray-2-24-from = beside the ray, 2.24 from its line
s1-case-on-an-oblique-ray = on an oblique ray
s1-case-facing-the-light-10-away = facing the light 10 away
s1-case-tilted-by-45-degrees = tilted by 45 degrees
s1-case-facing-the-light-20-away = facing the light 20 away
s1-case-facing-away = facing away
s2-case-out = out
s2-case-in = in
s2-case-30-degrees-air-into-glass = 30 degrees, air into glass
s2-case-straight-in = straight in
s2-case-45-degrees-glass-into-air = 45 degrees, glass into air
s2-case-40-degrees-glass-into-air = 40 degrees, glass into air
s5-case-straight-down-through-0-25-0 = straight down through (0.25, 0.5)
s5-case-straight-up-from-below-through-0 = straight up from below through (0.2, 0.2)
s5-case-down-through-0-6-0-6 = down through (0.6, 0.6), past the long edge
s5-case-down-through-0-25-0-5 = down through (0.25, 0.5) with t_max = 0.5
s5-case-parallel-to-the-triangle-s-plane = parallel to the triangle's plane
s5-case-pointing-away-up-from-above = pointing away, up from above
s5-case-from-0-0-5-along-z = from (0, 0, 5) along -z
s5-case-from-5-0-5-0-along = from (-5, 0.5, 0) along +x
s5-case-from-5-0-0-along-x = from (5, 0, 0) along -x
s5-case-from-inside-at-0-5-0 = from inside, at (0.5, 0, 0), along -z
s5-case-from-3-0-5-along-z = from (3, 0, 5) along -z, beside the box
s5-case-from-0-0-5-along-z-2 = from (0, 0, 5) along +z, away from the box
s5-case-from-0-0-5-along-z-3 = from (0, 0, 5) along -z with t_max = 3 (entered at t = 4, beyond t_max: missed, for the interval starts as [0, t_max])
s5-case-from-4-4-0-along-1 = from (4, 4, 0) along (-1, -1, 0) / sqrt 2
s5-case-lying-in-the-face-x-1 = lying in the face x = -1, from (-1, 0, 5) along (-0, 0, -1) (the chapter's box on NaN: 1 / -0 is -infinity, and 0 x infinity is NaN)
s6-case-at-a-weights-1-0-0 = at A, weights (1, 0, 0)
s6-case-halfway-along-bc-weights-0-0 = halfway along BC, weights (0, 0.5, 0.5)
s6-case-at-the-centre-weights-1-3 = at the centre, weights (1/3, 1/3, 1/3)
s6-case-at-the-centre-seen-from-below = at the centre, seen from below (the shading normal is turned to the side the geometric normal faces)
s7-case-the-top-left-texel-s-centre = the top-left texel's centre
s7-case-the-bottom-right-texel-s-centre = the bottom-right texel's centre
s7-case-near-the-top-right-corner = near the top-right corner
s7-case-one-texture-to-the-right-of = one texture to the right of the top-left centre
s7-case-a-quarter-of-a-texture-left = a quarter of a texture left of its edge, which wraps to the top-right texel (the chapter's Euclidean remainder: -1 wraps to 1, where % gives -1)
s7-case-the-top-left-texel-s-centre-2 = the top-left texel's centre
s7-case-the-texture-s-centre = the texture's centre
s7-case-between-the-two-top-texels = between the two top texels

## A texture's filter, as a lookup's failure names it.
checklist-filter-nearest = nearest
checklist-filter-bilinear = bilinear

## rules

# The rule each of the checklist's mistakes breaks, in words its failure must hold
# (tests/exercises/mistakes/): the same words as the generated check's message.
rule-s1-1-an-integer-division-drops-the = an integer division drops the half
rule-s1-1-rows-count-from-the-top = rows count from the top of the image
rule-s1-1-h-2-tan-alpha = H / (2 tan alpha)
rule-s1-2-yours-is-where-it-leaves = yours is where it leaves
rule-s1-2-only-t-0-is-a = only t > 0 is a hit
rule-s1-2-t-0-is-its-own = t = 0 is its own start
rule-s1-2-but-the-far-root-s = but the far root -s.d + sqrt(Delta) is a hit
rule-s1-2-loses-r-2-in-the = loses R^2 in the rounding of |s|^2
rule-s1-3-the-first-of-the-list = the first of the list wins
rule-s1-3-the-smallest-t-of-all = the smallest t of all the spheres met
rule-s1-4-the-1-pi-is-missing = the 1/pi is missing
rule-s1-4-it-gets-no-light-max = it gets no light, max(0, <N, l>)
rule-s1-4-not-p-light-p-light = not P_light / |P_light|
rule-s1-4-l-is-the-unit-vector = l is the unit vector to the light
rule-s2-1-rounded-to-the-nearest-not = rounded to the nearest, not down
rule-s2-1-use-the-gamma-given = use the gamma given
rule-s2-1-an-infinite-radiance-is-the = an infinite radiance is the brightest there is
rule-s2-2-not-a-fixed-epsilon = not a fixed epsilon
rule-s2-2-here-inwards-n = here inwards (-N)
rule-s2-2-not-against-n = not against N
rule-s2-3-not-from-the-hit-point = not from the hit point
rule-s2-3-divide-the-vector-to-the = divide the vector to the light by its length
rule-s2-4-subtracted-twice-it-turns-around = subtracted twice, it turns around
rule-s2-4-even-a-grazing-one = even a grazing one
rule-s2-5-eta-is-n1-n2 = eta is n1 / n2
rule-s2-5-total-internal-reflection-eta-2 = total internal reflection: eta^2
rule-s2-5-1-the-ray-refracts = <= 1: the ray refracts
rule-s3-1-0-included = 0 included
rule-s3-2-the-frame-is-left-handed = the frame is left-handed
rule-s3-2-near-n-z-1-n = near N = -z, 1 + n_z
rule-s3-3-hit-spawn-direction = hit.spawn(direction)
rule-s3-4-with-the-sigma-given = with the sigma given
rule-s4-1-sin-2-theta-1-cos = sin^2(theta) = (1 - cos)(1 + cos)
rule-s4-2-use-the-cone-s-one = use the cone's one_minus_cos_max
rule-s4-3-not-spread-as-the-density = not spread as the density says
rule-s4-4-starts-at-the-eye-start = starts at the eye, start
rule-s4-4-starts-in-the-eye-s = starts in the eye's plane
rule-s5-1-only-det-0-means-parallel = only det = 0 means parallel
rule-s5-1-only-t-0-decides = only t > 0 decides
rule-s5-1-edges-belong-to-the-triangle = edges belong to the triangle
rule-s5-2-miss-only-when-near-far = miss only when near > far
rule-s6-1-whatever-the-box-s-size = whatever the box's size
rule-s6-1-the-box-is-cut-across = the box is cut across its longest side
rule-s6-2-closer-than-t-max = closer than t_max
rule-s6-2-goes-on-with-the-rest = goes on with the rest of the stack
rule-s6-3-weight-k-goes-with-corner = weight k goes with corner k
rule-s6-3-the-vertex-the-triangle-names = the vertex the triangle names
rule-s6-3-falls-back-to-the-geometric = falls back to the geometric normal
rule-s6-3-normalise-it = normalise it
rule-s6-3-turned-to-the-geometric-normal = turned to the geometric normal's side
rule-s7-1-y-1-v-h-not = y = (1 - v) H, not v H
rule-s7-1-yours-swaps-u-and-v = yours swaps u and v, or W and H
rule-s7-1-towards-minus-infinity = towards minus infinity
rule-s7-1-by-half-a-texel = by half a texel
rule-s7-2-not-at-the-origin = not at the origin
rule-s7-2-which-mirrors-the-image = which mirrors the image
rule-s7-2-back-forward = back = -forward
rule-s7-2-the-plunge-is-in-degrees = the plunge is in degrees
rule-s7-2-keeps-its-distance-to-it = keeps its distance to it
rule-s7-2-right-normalize-forward-x-up = right = normalize(forward x up)
rule-s7-2-only-a-camera-looking-exactly = only a camera looking exactly along up
