### The plots of `raycourse plot`: the error of a render against its samples per
### pixel and its time, for the book's chapter on speed against accuracy.

plot-samples = samples per pixel
plot-seconds = seconds
plot-error = RMSE (linear radiance)
plot-slope = slope -1/2

## A number on an axis or in a label (plots are narrow: no digit grouping).
plot-number = { NUMBER($value, useGrouping: "false") }

## The words of the studies' variants, as their labels write them ("8 bounces",
## "sobol + adaptive 0.05"): each is replaced by its translation where it appears,
## the longer first where one holds another.
plot-word-bounces = bounces
plot-word-bounce = bounce
plot-word-brute-force = brute force
plot-word-bounding-box = bounding box
plot-word-fast-bvh = fast BVH
plot-word-light-sampling = light sampling
plot-word-naive = naive
plot-word-limit = limit
plot-word-leaf = leaf
plot-word-bilinear = bilinear
plot-word-nearest = nearest
plot-word-single-fast = single-fast
plot-word-double-fast = double-fast
plot-word-single = single
plot-word-independent = independent
plot-word-stratified = stratified
plot-word-sobol = sobol
plot-word-adaptive = adaptive
