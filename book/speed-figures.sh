#!/usr/bin/env bash
# Regenerates the figures of the chapter "Speed against accuracy"
# (book/src/figures/speed/): convergence studies of the course's stages, with the
# CSV files behind every plot. Prints each study's slopes and efficiencies.
# Takes a few minutes; times depend on the machine, so the plots' time axes do too.
set -euo pipefail
cd "$(dirname "$0")/.."
out=book/src/figures/speed
exec > >(tee "$out/summary.txt")
small=(--width 64 --height 64 --quiet)
converge() { cargo run --release --quiet -- converge "$@" "${small[@]}"; }

converge indirect --max-spp 256 --reference-spp 8192 --out "$out/indirect"
converge light-sampling --compare light-sampling --max-spp 256 --reference-spp 8192 \
  --out "$out/light-sampling"
converge indirect --compare bounces --max-spp 256 --reference-spp 8192 --out "$out/bounces"
converge indirect --compare roulette --max-spp 256 --reference-spp 8192 --out "$out/roulette"
converge bvh --compare acceleration --max-spp 4 --reference-spp 64 --out "$out/acceleration"
# The leaf size and the texture filter: table rows only, no plot.
converge bvh --compare leaf --max-spp 64 --reference-spp 8192 --out "$out/leaf"
converge textures --compare filter --max-spp 64 --reference-spp 8192 --out "$out/filter"
rm -f "$out/leaf.png" "$out/filter.png"

# Precision and engine: the same study from both builds, with the course's code and
# with the fast engine (four paths at once in double precision, eight in single),
# against the same (cached) reference.
single() { cargo run --release --quiet --features f32 -- converge "$@" "${small[@]}"; }
converge indirect --label double --max-spp 256 --reference-spp 8192 --out "$out/double"
converge indirect --label double-fast --fast --max-spp 256 --reference-spp 8192 \
  --out "$out/double-fast"
single indirect --label single --max-spp 256 --reference-spp 8192 --out "$out/single"
single indirect --label single-fast --fast --max-spp 256 --reference-spp 8192 \
  --out "$out/single-fast"
cargo run --release --quiet -- plot "$out"/{double,double-fast,single,single-fast}.csv \
  --out "$out/precision.png" --title "indirect: double against single precision, both engines"
rm -f "$out"/{double,double-fast,single,single-fast}.png
