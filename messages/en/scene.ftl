### What the renderer says of a scene file it cannot use (`raycourse render`, the
### `sN` commands, `probe`): one line that names the file, the line and column where
### TOML knows them, and the key. The file's place is written as compilers write
### it (`room.toml:16:1:`), which editors read, in every language.

scene-cannot-read = { $file }: cannot read the scene file: { $why }
scene-invalid = { $file }:{ $line }:{ $column }: { $message }
scene-invalid-key = { $file }:{ $line }:{ $column }: key `{ $key }`: { $message }
scene-inconsistent = { $file }: key `{ $key }`: { $message }
scene-asset = { $file }: { $message } (referred to by { $scene })
scene-needs-feature = { $file }: key `{ $key }`: { $what } { $remedy }

## What the TOML reader (serde) says of a key, in the words the catalogue knows.
scene-unknown-field = unknown field `{ $field }`, expected one of { $expected }
scene-missing-field = missing field `{ $field }`

## The scene file's own rules for a value (src/maths/values.rs).
scene-not-finite = expected a finite number, found { $value }
scene-not-positive = expected a number greater than 0, found { $value }
scene-negative = expected a number 0 or greater, found { $value }
scene-not-probability = expected a probability above 0 and at most 1, found { $value }
scene-not-angle = expected an angle between 0 and 180 degrees, found { $value }
scene-not-albedo = expected an albedo between 0 and 1, found { $value }

## Values that are acceptable on their own but not together.
scene-too-many-pixels = { $width } x { $height } is { NUMBER($pixels, useGrouping: "false") } pixels; at most { NUMBER($most, useGrouping: "false") } are allowed
scene-aim-needs-look-at = `up` and `plunge` aim the camera: give it a `look_at` point
scene-shadows-need-point-light = shadow rays are for a point light; a sphere light's shadows come from light_sampling or indirect rays
scene-light-sampling-needs-sphere = light sampling needs a sphere light: give [light] a radius
scene-camera-cannot-aim = the camera must not look along `up` or at its own position
scene-leaf-size-needs-fast = only the fast engine's hierarchy has a leaf size: `fast = true` with `acceleration = "bvh"`

## A mesh or a texture the scene names.
scene-cannot-load-mesh = cannot load the mesh: { $why }
scene-cannot-read-texture = cannot read the texture: { $why }

## What a scene asked for that a later session brings, and how to get it.
scene-needs-feature-s = needs feature s{ $later }: cargo run --features s{ $later } -- ...
scene-comes-with-view = comes with session { $later }: this crate stops at session { $session } (`cargo xtask view s{ $later } DIR` in the course's crate writes session { $later }'s)
scene-comes-with-exercises = comes with session { $later }: you write it then; this crate holds session { $session }'s exercises
scene-part-mirror = a mirror material
scene-part-glass = a glass material
scene-part-fresnel-glass = a Fresnel glass material
scene-part-gamma = gamma correction
scene-part-shadows = shadow rays
scene-part-shadow-offset = a fixed shadow-ray offset
scene-part-indirect = indirect lighting
scene-part-antialiasing = antialiasing
scene-part-light-sampling = light sampling
scene-part-russian-roulette = Russian roulette
scene-part-lens = a thin lens
scene-part-sphere-light = a sphere light
scene-part-meshes = triangle meshes
scene-part-acceleration = an acceleration structure
scene-part-bvh = a bounding volume hierarchy
scene-part-aimed-camera = an aimed camera
scene-part-smooth-normals = smooth normals
scene-part-textures = textures
