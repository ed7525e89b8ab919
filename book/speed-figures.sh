#!/usr/bin/env bash
# Regenerates the figures of the chapter "Speed against accuracy"
# (book/src/figures/speed/): convergence studies of the course's stages, with the
# CSV files behind every plot. Prints each study's slopes and efficiencies.
# Takes a few minutes; times depend on the machine, so the plots' time axes do too.
# The last study also renders with Mitsuba 3, which benches/mitsuba/converge.py
# installs from PyPI into target/mitsuba-venv on its first run.
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

# Precision, engine and renderer: the same study from both builds, with the course's
# code and with the fast engine (four paths at once in double precision, eight in
# single), and Mitsuba 3's two variants (benches/mitsuba/converge.py, which installs
# Mitsuba into target/mitsuba-venv), against the same (cached) reference. The stage
# is `antialiasing`, whose Gaussian jitter of camera rays Mitsuba shares.
single() { cargo run --release --quiet --features f32 -- converge "$@" "${small[@]}"; }
printed=$(converge antialiasing --label double --max-spp 256 --reference-spp 8192 \
  --out "$out/double")
echo "$printed"
reference=$(grep -o 'out/reference/[0-9a-f]*\.ref' <<< "$printed")
converge antialiasing --label double-fast --fast --max-spp 256 --reference-spp 8192 \
  --out "$out/double-fast"
single antialiasing --label single --max-spp 256 --reference-spp 8192 --out "$out/single"
single antialiasing --label single-fast --fast --max-spp 256 --reference-spp 8192 \
  --out "$out/single-fast"
python3 benches/mitsuba/converge.py antialiasing --reference "$reference" --size 64 \
  --max-spp 256 --out "$out/mitsuba.csv"
cargo run --release --quiet -- plot "$out"/{double,double-fast,single,single-fast,mitsuba}.csv \
  --out "$out/precision.png" \
  --title "antialiasing: both precisions, both engines, and Mitsuba 3"
rm -f "$out"/{double,double-fast,single,single-fast}.png

# The French edition's plots, from the same CSV files.
book/french-plots.sh
