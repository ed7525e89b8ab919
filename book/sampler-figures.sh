#!/usr/bin/env bash
# Regenerates the sampler and adaptive-sampling figures of the chapter "Speed
# against accuracy" (book/src/figures/samplers/): for five stages, the course's
# independent numbers against stratified numbers and Sobol points, then against
# adaptive sampling, up to 64 samples per pixel at 64 x 64 against a 4096-sample
# reference. Writes a CSV and a plot per study and summary.txt. A few minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
out=book/src/figures/samplers
mkdir -p "$out"
exec > >(tee "$out/summary.txt")
cargo build --quiet --profile fastest
for stage in antialiasing soft-shadows light-sampling depth-of-field textures; do
  for comparison in sampler adaptive; do
    target/fastest/raycourse converge "$stage" --compare "$comparison" --max-spp 64 \
      --reference-spp 4096 --width 64 --height 64 --quiet --out "$out/$stage-$comparison"
  done
done

# The French edition's plots, from the same CSV files.
book/french-plots.sh
