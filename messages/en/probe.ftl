### What `raycourse probe` prints: one sample of one pixel, ray by ray, in the book's
### notation. The columns line up in English; the symbols (O, d, t, P, N, Le, L)
### are the book's in every language. The material is written as the code's value,
### as `--json` gives it.

probe-pixel = pixel (x { NUMBER($x, useGrouping: "false") }, y { NUMBER($y, useGrouping: "false") }), sample { NUMBER($sample, useGrouping: "false") } of { NUMBER($samples, useGrouping: "false") } (from 0)
probe-camera-ray = level { NUMBER($level, useGrouping: "false") }: the camera ray
probe-bounce = level { NUMBER($level, useGrouping: "false") }: bounce { NUMBER($level, useGrouping: "false") }
probe-sample-radiance = sample radiance  L = { $radiance }
probe-pixel-mean = pixel            mean of { NUMBER($samples, useGrouping: "false") } { $samples ->
        [one] sample
       *[other] samples
    } { $pixel } -> gamma { $gamma } -> ({ NUMBER($red, useGrouping: "false") }, { NUMBER($green, useGrouping: "false") }, { NUMBER($blue, useGrouping: "false") })
probe-ray = {"  "}ray      O = { $origin }  d = { $direction }
probe-hit = {"  "}hit      t = { $t }  P = { $point }  N = { $normal }
probe-object = {"           "}{ $shape } (object { NUMBER($object, useGrouping: "false") }), { $material }, { $face }
probe-front-face = front face
probe-back-face = back face (from inside)
probe-emitted = {"  "}emitted  Le = { $emitted }{ $glow }
probe-glow-not-counted = {" "}(not counted: light sampling counted it at the last hit)
probe-end = {"  "}end      { $end }
probe-arriving = {"  "}arriving L = { $arriving }   adds { $throughput } x (Le + direct) = { $adds }
probe-shadow-ray = {"  "}{ $light }  shadow ray O = { $origin }  d = { $direction }
probe-shadow-distance = {"           "}distance { $distance }, { $blocked }
probe-no-distance = -
probe-blocked = blocked by object { NUMBER($object, useGrouping: "false") } at t = { $t }
probe-not-blocked = not blocked
probe-no-shadow-ray = {"  "}{ $light }  no shadow ray traced
probe-direct = {"  "}direct   { $brings }
probe-next = {"  "}next     { $kind }: d' = { $direction }
probe-cos-pdf = {"           "}cos(theta) = { $cos }, pdf = cos(theta) / pi = { $pdf }
probe-fresnel = {"           "}F = { $fresnel }
probe-roulette = {"           "}past the bounce limit: Russian roulette let it go on (probability { $survival }), weight x 1/{ $survival }
probe-bounces-left = {"           "}bounces still allowed: { NUMBER($left, useGrouping: "false") }
probe-weight = {"           "}weight { $weight }
probe-triple = ({ $x }, { $y }, { $z })

## How the path goes on from a hit (`--json` keeps these words in English).
probe-next-diffuse = diffuse bounce, drawn with density cos(theta) / pi
probe-next-mirror = mirror reflection
probe-next-total-internal-reflection = total internal reflection: past the critical angle
probe-next-reflection = reflection
probe-next-refraction = refraction, eta = n1 / n2 = { NUMBER($eta, minimumFractionDigits: 4, maximumFractionDigits: 4) }
probe-next-fresnel-reflection = reflection, Fresnel's choice, with probability F
probe-next-fresnel-refraction = refraction, eta = n1 / n2 = { NUMBER($eta, minimumFractionDigits: 4, maximumFractionDigits: 4) }, Fresnel's choice, with probability 1 - F

## Why the path ends where it does (`--json` keeps these words in English).
probe-end-leaves = the ray leaves the scene: it brings black
probe-end-no-indirect = no indirect light in this scene: the path ends at its diffuse hit
probe-end-roulette = past the bounce limit, Russian roulette ended the path (it goes on with probability { $survival })
probe-end-bounce-limit = the bounce limit ({ NUMBER($bounces, useGrouping: "false") }) is reached
probe-end-here = the path ends here

## A number in scientific notation, its mantissa as the language writes it.
probe-number = { $value }

## The names the renderer gives a light and a shape (`--json` keeps them).
probe-light-no-light = no light
probe-light-point-light = point light
probe-light-sphere-light = sphere light
probe-shape-sphere = sphere
probe-shape-mesh = mesh

## Why the probe cannot follow a pixel, and what the command refuses.
probe-outside = pixel ({ NUMBER($x, useGrouping: "false") }, { NUMBER($y, useGrouping: "false") }) is outside the image, which is { NUMBER($width, useGrouping: "false") }x{ NUMBER($height, useGrouping: "false") }
probe-no-such-sample = sample { NUMBER($sample, useGrouping: "false") } does not exist: the pixel takes { NUMBER($samples, useGrouping: "false") } (from 0)
probe-no-stage = no stage `{ $name }` in this build: one of { $names }
probe-scene-and-stage = with --scene, give only X Y
probe-give-stage = give STAGE X Y (or --scene FILE X Y)
probe-beyond-the-course = the probe follows the course's code; this scene asks for { $what }
probe-not-a-coordinate = `{ $text }` is not a pixel coordinate (0, 1, 2, ...)
probe-cannot-write-json = cannot write the probe as JSON: { $why }
probe-cannot-write-output = cannot write to the standard output: { $why }
