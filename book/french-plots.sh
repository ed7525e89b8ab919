#!/usr/bin/env bash
# The French edition's plots of the chapter "Speed against accuracy": the same CSV
# files as the English plots (written by speed-figures.sh and sampler-figures.sh),
# drawn by `raycourse plot --lang fr` with French titles, axes and legends into the
# fr/ folder beside each English plot; the titles are the catalogue's
# (`plot-title-*` in messages/fr/book.ftl). Draws only, measures nothing: seconds.
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
# The French catalogue's message ID (a line of messages/fr/book.ftl); none fails.
message() { sed -n "s/^$1 = //p" messages/fr/book.ftl | grep .; }
study_title=$(message plot-title-study)
precision_title=$(message plot-title-precision)
# TITLE with its `{ $study }` made STUDY.
titled() { printf '%s' "${1//'{ $study }'/$2}"; }

plot "$speed/indirect.csv" --title "$(titled "$study_title" indirect)" --out "$figures/speed/fr/indirect.png"
plot "$speed/light-sampling.csv" --title "$(titled "$study_title" "light-sampling (light-sampling)")" \
  --out "$figures/speed/fr/light-sampling.png"
for study in bounces roulette; do
  plot "$speed/$study.csv" --title "$(titled "$study_title" "indirect ($study)")" \
    --out "$figures/speed/fr/$study.png"
done
plot "$speed/acceleration.csv" --title "$(titled "$study_title" "bvh (acceleration)")" \
  --out "$figures/speed/fr/acceleration.png"
plot "$speed"/{double,double-fast,single,single-fast,mitsuba}.csv \
  --title "$(titled "$precision_title" antialiasing)" \
  --out "$figures/speed/fr/precision.png"

for stage in antialiasing soft-shadows light-sampling depth-of-field textures; do
  for comparison in sampler adaptive; do
    plot "$samplers/$stage-$comparison.csv" --title "$(titled "$study_title" "$stage ($comparison)")" \
      --out "$figures/samplers/fr/$stage-$comparison.png"
  done
done
