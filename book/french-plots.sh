#!/usr/bin/env bash
# The French edition's plots of the chapter "Speed against accuracy": the same CSV
# files as the English plots (written by speed-figures.sh and sampler-figures.sh),
# drawn by `raycourse plot --lang fr` with French titles, axes and legends into the
# fr/ folder beside each English plot. Draws only, measures nothing: seconds.
#
#   book/french-plots.sh [FIGURES]     # default book/src/figures
set -euo pipefail
cd "$(dirname "$0")/.."
figures=${1:-book/src/figures}
speed=book/src/figures/speed
samplers=book/src/figures/samplers
mkdir -p "$figures/speed/fr" "$figures/samplers/fr"
cargo build --release --quiet
plot() { target/release/raycourse plot --lang fr "$@" >/dev/null; }
against="erreur selon les échantillons et le temps"
colon=$'\u00a0:'  # French puts a no-break space before a colon

plot "$speed/indirect.csv" --title "indirect$colon $against" --out "$figures/speed/fr/indirect.png"
plot "$speed/light-sampling.csv" --title "light-sampling (light-sampling)$colon $against" \
  --out "$figures/speed/fr/light-sampling.png"
for study in bounces roulette; do
  plot "$speed/$study.csv" --title "indirect ($study)$colon $against" \
    --out "$figures/speed/fr/$study.png"
done
plot "$speed/acceleration.csv" --title "bvh (acceleration)$colon $against" \
  --out "$figures/speed/fr/acceleration.png"
plot "$speed"/{double,double-fast,single,single-fast,mitsuba}.csv \
  --title "antialiasing$colon les deux précisions, les deux moteurs et Mitsuba 3" \
  --out "$figures/speed/fr/precision.png"

for stage in antialiasing soft-shadows light-sampling depth-of-field textures; do
  for comparison in sampler adaptive; do
    plot "$samplers/$stage-$comparison.csv" --title "$stage ($comparison)$colon $against" \
      --out "$figures/samplers/fr/$stage-$comparison.png"
  done
done
