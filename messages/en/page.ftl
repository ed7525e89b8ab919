### The live book's pages (book/src/live/): the session demos' controls, what their
### images say to a screen reader, their status lines, and the check page.

## The demos' controls, session by session.
page-field-of-view = field of view (degrees)
page-light-axis = light { $axis }
page-albedo = albedo of the sphere
page-gamma = gamma correction ({ NUMBER(2.2) })
page-shadow-offset = shadow ray's offset
page-offset-robust = past the point's rounding error (the crate's)
# $epsilon: a number, or a power of ten as text ("10⁻⁹").
page-offset = ε = { $epsilon }
page-offset-none = ε = 0: shadow acne
page-centre-sphere = the centre sphere
page-diffuse = diffuse
page-mirror = mirror
page-glass = glass
page-refractive-index = refractive index
page-samples = samples per pixel
page-bounces = bounces
page-antialiasing = antialiasing
page-light-radius = light radius
page-light-sampling = light sampling
page-aperture = aperture
page-focus = focus distance
page-search = search of the mesh
page-brute-force = brute force
page-bounding-box = bounding box
page-bvh = BVH
page-smooth-normals = smooth normals
page-plunge = plunge (degrees); drag the image or use the arrow keys to orbit
page-texture = texture
page-fast = the fast engine (beyond the course: the same image)
## A number beside a slider, or read from one.
page-number = { $value }
page-stage = stage
# A stage in the demo's list: its name and its title (from its scene file, in English).
page-stage-option = { $stage }: { $title }

## The image's text alternative, which follows the render.
page-on = on
page-off = off
page-setting = { $control }: { $value }
page-turned = turned by { $degrees } degrees
page-samples-done =
    { $samples ->
        [one] { $samples } sample per pixel
       *[other] { $samples } samples per pixel
    }
page-not-done = rendering…
# $settings: the page-setting lines joined by page-separator; $done: page-samples-done or page-not-done.
page-image = session { $session }, stage { $stage }; { $settings }; { $done }
page-image-orbit = { page-image }. Arrow keys turn the camera, as dragging does.
page-separator = {"; "}

## The status line.
page-loading = loading the renderer…
page-error = error: { $message }
page-rendering = rendering { $stage }…
# $time: page-milliseconds or page-seconds.
page-pass = { $stage }, { $size } × { $size }: { page-samples-done } in { $time }
page-pass-done = { page-pass } ({ $workers } workers)
page-pass-refining = { page-pass }; refining…
page-pass-look = { $stage }, { $size } × { $size }: a first look, one sample for each block of { $scale } × { $scale } pixels, in { $time }; refining…
page-milliseconds = { NUMBER($ms, maximumFractionDigits: 0) } ms
page-seconds = { NUMBER($seconds, minimumFractionDigits: 1, maximumFractionDigits: 1) } s

## The mesh sessions' cost image and times.
page-cost-caption = cost: tests per camera ray
page-cost-image = the cost image, { $caption }
page-cost-fast = cost: counted for the course's searches only
page-cost-mean = cost: { NUMBER($mean, minimumFractionDigits: 1, maximumFractionDigits: 1) } tests per camera ray on average
page-functions-course = the course functions this image ran
page-functions-fast = the fast engine's function that made this image (beyond the course)
page-times-fast = { $search }, fast engine
page-times-time = { $time } ({ $samples } samples, { $size } × { $size })
page-times-cost = { NUMBER($cost, minimumFractionDigits: 1, maximumFractionDigits: 1) } tests per camera ray
page-times-search = search
page-times-duration = time
page-times-cost-head = cost

## The check page.
page-check-stage = session { $session }: { $stage }
page-check-image = your image
page-check = check
page-check-differences = the differences: differing pixels or blocks in red
page-check-choose = choose your image first (a PNG, JPEG or PPM file)
page-check-rendering = rendering the reference…
page-check-rows = rendering the reference: { $rows } rows
page-check-matches = matches
page-check-differs = differs
page-grade-legend = A class, as check --all grades it
page-grade-folder = the class's folder (a folder per student)
page-grade-images = or one student's images, named after their stages
page-grade = grade
page-grade-sheet = the grading sheet, grades.csv
page-grade-choose = choose a class's folder or a student's images first
page-grading = grading…
page-graded = folders graded: { $done } / { $count }
page-grade-matching = every image matches
page-grade-differing = some images differ
