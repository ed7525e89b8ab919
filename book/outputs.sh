#!/usr/bin/env bash
# What `raycourse check` prints, as the Running chapter shows it in each edition's
# language: a render of the glass stage without its gamma correction, checked in
# English and in French, into book/src/outputs/{en,fr}/check-glass.txt (the chapter's
# `{{#output check-glass}}`). The checklist's outputs are written by .ci/exercises,
# which runs the exercise crates they come from. CI runs both and fails if a file
# changed: a message changed in the catalogue shows in the chapter.
#
#   book/outputs.sh     # from anywhere; seconds
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cargo build --release --quiet
raycourse="$root/target/release/raycourse"
sed '/^gamma = /d' sessions/s2/glass.toml >"$work/glass.toml"
"$raycourse" render "$work/glass.toml" --out "$work/my-glass.png" >/dev/null
for lang in en fr; do
  mkdir -p "book/src/outputs/$lang"
  # check exits with 1 on an image that differs, as this one does.
  (cd "$work" && "$raycourse" check glass my-glass.png --diff diff.png --lang "$lang") \
    >"book/src/outputs/$lang/check-glass.txt" && exit 1
  grep -q "hint (\|indice (" "book/src/outputs/$lang/check-glass.txt"
done
