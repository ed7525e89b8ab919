### The words the book's tools write into the book: the captions of its listings
### and the header of its exercise tables (`cargo xtask book`'s preprocessor,
### xtask/src/listings.rs), the words of `bench`'s tables that the French edition
### translates (xtask/src/timings.rs), the labels of the comparison figures
### (book/figures/) and the titles of the French edition's plots
### (book/french-plots.sh).

## A listing's caption: `src/file.rs, session 3, lines marked ...`.
book-session = session
book-gained = , lines marked `// +` new in this session
book-unchanged = , unchanged since the last session
book-beyond = beyond the course
book-exercises-header = | exercise | what you write | function | file | checklist line |
book-and = {" "}and{" "}

## The words of a `bench` table, as the command prints them: the longer first where
## one holds another. A number in such a table, its digits as measured.
bench-course-s-code = course's code
bench-speed-up = speed-up
bench-settings = settings
bench-stage = stage
bench-mrays = Mrays/s
bench-rays = rays
bench-course = course
bench-about = about
bench-spp = spp
bench-bounces = bounces
bench-shadows = shadows
bench-light-sampling = light sampling
bench-russian-roulette = Russian roulette
bench-number = { $value }
bench-seconds = { $value } s
bench-size = { $width }x{ $height }
bench-speed-up-times = { $value }x

## The labels of the comparison figures (book/src/figures/compare/).
figure-without-antialiasing = without antialiasing
figure-with-antialiasing = with antialiasing
figure-with-shadow-rays = with shadow rays
figure-without-shadow-rays = without
figure-flat-normals = flat normals
figure-smooth-normals = smooth normals
figure-bounces = { $bounces } bounces
figure-bounces-and-roulette = { $bounces } bounces + roulette
figure-converted-to-linear = converted to linear
figure-used-as-it-is = used as it is
figure-cost = { $search ->
        [brute-force] brute force
        [box] box
       *[bvh] BVH
    }: { NUMBER($mean, minimumFractionDigits: 1, maximumFractionDigits: 1, useGrouping: "false") } tests a ray
figure-at-scale = { $offset ->
        [fixed] fixed epsilon
       *[bound] error bound
    }, scale { $scale }

## The titles of the plots of the chapter "Speed against accuracy": a stage (and its
## study), then what the plot shows. book/french-plots.sh reads the French.
plot-title-study = { $study }: error against samples and time
plot-title-precision = { $study }: both precisions, both engines and Mitsuba 3
