### What `raycourse check` says of a student's image of a stage, line by line; the
### book's check page shows the same lines. English, the catalogue's source.

## The verdict. $stage: the stage's name; $share: the percentage of the image that
## differs; $cell: 1 when pixels are compared one by one, otherwise the side of the
## square blocks compared (Monte Carlo stages).

check-unit =
    { $cell ->
        [1] pixels
       *[other] blocks of { $cell } x { $cell } pixels
    }
check-matches = { $stage }: matches ({ NUMBER($share, minimumFractionDigits: 1, maximumFractionDigits: 1) }% of { check-unit } differ, within what is allowed)
check-differs = { $stage }: differs ({ NUMBER($share, minimumFractionDigits: 1, maximumFractionDigits: 1) }% of { check-unit } differ)

## The brightness of each channel against the reference's, as a ratio.
check-brightness = {"  "}brightness against the reference: red x{ NUMBER($red, minimumFractionDigits: 2, maximumFractionDigits: 2) }, green x{ NUMBER($green, minimumFractionDigits: 2, maximumFractionDigits: 2) }, blue x{ NUMBER($blue, minimumFractionDigits: 2, maximumFractionDigits: 2) }

## Where the image differs: a list of places, each with the percentage of it that
## differs. $places: the places, already joined by the separator below.
check-where = {"  "}where: { $places }
check-place = { $place } ({ NUMBER($share, maximumFractionDigits: 0) }%)
check-place-separator = {", "}

## The places of an image.
place-background = the background
place-light = the light
place-mesh = the mesh
place-sphere = the sphere
place-floor = the floor
place-ceiling = the ceiling
place-left-wall = the left wall
place-right-wall = the right wall
place-back-wall = the back wall
place-wall-behind-camera = the wall behind the camera
place-wall = a wall
place-top-half = the top half
place-bottom-half = the bottom half

## The noise of a matching Monte Carlo image. $ratio: its variance over that of a
## render at the course's $samples samples per pixel; $equivalent: the samples per
## pixel it seems to have.
check-noise = {"  "}noise: { NUMBER($ratio, minimumFractionDigits: 2, maximumFractionDigits: 2) } times the variance of a render at the course's { $samples } samples per pixel (as from about { NUMBER($equivalent, maximumFractionDigits: 0, useGrouping: "false") } samples)

## The hint: the classic mistake that explains the difference ($name, $hint below),
## or the command that renders the reference to compare with.
check-hint = {"  "}hint ({ $name }): { $hint }
check-no-hint = {"  "}hint: no classic mistake explains the difference; compare with `{ $command }`

## An image that cannot be read. $error: what the image library says.
check-unreadable = not a PNG, JPEG or PPM image that can be read: { $error }

## What check says of the files it is given, after the file's name. $error: what
## the system says.
check-cannot-read = cannot read the image: { $error }
check-not-a-folder = not a folder
## A folder (check --all, or the check page's class) with no image named after a
## stage, neither in it nor in a student's folder inside it.
check-no-stage = no image of a stage here, nor in a student's folder: name each image after its stage, such as glass.png
check-no-stage-command = { check-no-stage } (`raycourse list` gives the stages)
## Where check --all wrote the grading sheet.
check-sheet-written = grading sheet -> { $path }

## The classic mistakes: a short name, and the hint (what to look for in one's code).

mistake-no-gamma = no gamma
    .hint = the image looks displayed without gamma correction: write min(255, L^(1/{ NUMBER(2.2) })), not min(255, L)
mistake-gamma-twice = gamma twice
    .hint = the image looks gamma-corrected twice: apply L^(1/{ NUMBER(2.2) }) once, when writing the pixel
mistake-one-over-pi-missing = 1/pi missing
    .hint = the image is about pi times too bright: the diffuse BRDF is albedo / pi; check the 1/pi, and that the light's intensity is used as given
mistake-one-over-pi-twice = 1/pi twice
    .hint = the image is about pi times too dark: the diffuse BRDF's 1/pi is counted twice
mistake-no-falloff = no falloff
    .hint = the light does not fall off with distance: a point light gives I / (4 pi d^2), d the distance to the light
mistake-upside-down = upside down
    .hint = the image is upside down: image rows go from the top, so row i counts from the bottom as H - 1 - row
mistake-mirrored = mirrored
    .hint = the image is mirrored left to right: the camera's x axis points right (check the sign of x in the pixel's direction)
mistake-half-a-turn = half a turn
    .hint = the image is turned half a turn: both the rows and the columns run the wrong way (row i counts from the bottom as H - 1 - row, and x grows with the column j)
mistake-rows-and-columns-swapped = rows and columns swapped
    .hint = rows and columns are swapped: the pixel of column j and row i is written at column i and row j (a pixel's index in the image is row * W + column)
mistake-shifted-a-pixel = shifted a pixel
    .hint = the image is the stage's moved by one pixel: row i counts from the bottom as H - 1 - row (not H - row), and a pixel's centre is half a pixel in, x = j - W/2 + { NUMBER(0.5) }
mistake-shadow-acne = shadow acne
    .hint = lit surfaces are speckled with dark dots (shadow acne): start shadow rays a little off the surface, P + epsilon N, not at P
mistake-inverted-index = inverted index
    .hint = the glass bends rays the wrong way: going into glass, eta = n1 / n2 = 1 / { NUMBER(1.5) }; coming out, { NUMBER(1.5) }
mistake-light-counted-twice = light counted twice
    .hint = the light is counted twice: with light sampling, a bounced ray that meets the light must not add its emission again
mistake-bounce-limit = bounce limit
    .hint = the paths stop too early: a path follows up to `bounces` bounces (the stage's setting), and only then stops; check where your bounce counter is tested and decremented
mistake-bounce-weight = bounce weight
    .hint = the indirect light is off while the direct light is right: the weight of a bounce must match how its direction was drawn (cosine-weighted directions: albedo; uniform ones: 2 albedo cos(theta))
mistake-texture-gamma = texture gamma
    .hint = the texture looks washed out: texel values are gamma-encoded; use (v / 255)^{ NUMBER(2.2) } as the albedo
mistake-texture-v-flipped = texture v flipped
    .hint = the texture is upside down on the mesh: v runs from the bottom of the picture, so the texel row is (1 - v) H
