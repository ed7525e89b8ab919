### What a render says when it is done (`raycourse render`, the `sN` commands,
### `animate`): its closing line, with the scene's settings in a few words; and the
### line of a command that fails. The README quotes the English closing line: keep
### it as it is.

command-error = error: { $why }

## Why a render command could not go on: its threads, the file it writes.
command-too-many-threads = --threads { NUMBER($threads, useGrouping: "false") }: at most { NUMBER($most, useGrouping: "false") } (one per core is the fastest)
command-cannot-start-threads = cannot start { NUMBER($threads, useGrouping: "false") } worker threads: { $why }
command-cannot-write = { $file }: cannot write the file: { $why }
command-not-a-file = { $file }: not a regular file (a folder, a device or a pipe): give the path of a file to write
command-link-loop = { $file }: a loop of symbolic links
command-fast-differs = { $stage }: the fast engine's image differs from the course's code's

## The closing line: `camera: 512x512, 50 spp, ... -> out/camera.png`.
render-done = { $label }: { $summary }, { NUMBER($seconds, minimumFractionDigits: 3, maximumFractionDigits: 3, useGrouping: "false") } s, { NUMBER($rays, useGrouping: "false") } rays, { NUMBER($speed, minimumFractionDigits: 2, maximumFractionDigits: 2, useGrouping: "false") } Mrays/s, { NUMBER($threads, useGrouping: "false") } threads{ $adaptive }{ $dropped } -> { $out }
render-adaptive = , { NUMBER($average, minimumFractionDigits: 1, maximumFractionDigits: 1, useGrouping: "false") } spp on average
render-dropped = , { NUMBER($dropped, useGrouping: "false") } non-finite samples dropped

## The scene's settings in a few words.
summary-settings = { NUMBER($width, useGrouping: "false") }x{ NUMBER($height, useGrouping: "false") }, { NUMBER($samples, useGrouping: "false") } spp, { NUMBER($bounces, useGrouping: "false") } bounces
summary-gamma = , gamma { $gamma }
summary-shadows = , shadows
summary-indirect = , indirect
summary-light-sampling = , light sampling
summary-russian-roulette = , Russian roulette

## The closing line of `--aov`: `glass: normal image, from 0 (purple) to 1 (yellow) -> out`.
render-aov-done = { $label }: { $aov } image{ $range }{ $mean } -> { $out }
render-aov-range = , from { $low } (purple) to { $high } (yellow)
render-aov-mean = , mean cost { $mean } tests a ray
render-cost-not-fast = { $label }: `--aov cost` counts the tests of the course's searches, which the fast engine does not run: leave out `--fast` (or `fast = true` in the scene file)
render-noise-map = { $label }: samples per pixel from { NUMBER($fewest, useGrouping: "false") } (black) to { NUMBER($most, useGrouping: "false") } (white) -> { $out }

## `raycourse animate`: each frame's label and time, and the closing line.
animate-frame-label = { $name } frame { NUMBER($frame, useGrouping: "false") }/{ NUMBER($frames, useGrouping: "false") }
animate-frame = { $label }: { NUMBER($seconds, minimumFractionDigits: 2, maximumFractionDigits: 2, useGrouping: "false") } s
animate-cannot-encode = cannot encode the animation: { $why }
animate-done = { $name }: { NUMBER($frames, useGrouping: "false") } frames, plunge { $from } to { $to } degrees, { NUMBER($seconds, minimumFractionDigits: 1, maximumFractionDigits: 1, useGrouping: "false") } s -> { $out }
