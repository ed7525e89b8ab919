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

# Precision: the same study from both builds, against the same (cached) reference.
converge indirect --label double --max-spp 256 --reference-spp 8192 --out "$out/double"
cargo run --release --quiet --features f32 -- converge indirect --label single \
  --max-spp 256 --reference-spp 8192 "${small[@]}" --out "$out/single"
cargo run --release --quiet -- plot "$out/double.csv" "$out/single.csv" \
  --out "$out/precision.png" --title "indirect: double against single precision"
rm -f "$out/double.png" "$out/single.png"
