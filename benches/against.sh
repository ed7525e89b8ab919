#!/usr/bin/env bash
# Times the sphere stages against an earlier commit of the crate, side by side in one
# run: this commit's default render (the course's code) and its fast engine
# (`--fast`), and checks that all three give the same PNG bytes.
#
#   benches/against.sh e11a4c8          # indirect and light-sampling, 192 x 192
#   benches/against.sh e11a4c8 512      # at the course's size
#
# The earlier commit is built in a git worktree (in $TMPDIR) with its own release
# profile; this one with `--profile fastest`. The binaries take turns, twice per
# stage, so that a change in the machine's load touches them alike; the faster of
# each pair is reported.
set -euo pipefail
cd "$(dirname "$0")/.."
commit=${1:?usage: benches/against.sh COMMIT [SIZE]}
size=${2:-192}
base=${TMPDIR:-/tmp}/raycourse-$commit
if [ ! -x "$base/target/release/raycourse" ]; then
  rm -rf "$base"
  git worktree add --force --detach "$base" "$commit" >/dev/null
  (cd "$base" && cargo build --quiet --release)
fi
cargo build --quiet --profile fastest
old=$base/target/release/raycourse
new=target/fastest/raycourse
out=target/against/images
mkdir -p "$out"
seconds() { local TIMEFORMAT=%R; { time "$@" >/dev/null; } 2>&1; }
printf '| stage | %s | this commit | this commit, `--fast` | fast against %s | same bytes |\n' "$commit" "$commit"
printf '|---|---|---|---|---|---|\n'
for stage in s3/indirect s4/light-sampling; do
  name=${stage#*/}
  args=(render "sessions/$stage.toml" --width "$size" --height "$size" --quiet)
  a=() b=() c=()
  for _ in 1 2; do
    a+=("$(seconds "$old" "${args[@]}" --out "$out/old-$name.png")")
    b+=("$(seconds "$new" "${args[@]}" --out "$out/course-$name.png")")
    c+=("$(seconds "$new" "${args[@]}" --fast --out "$out/fast-$name.png")")
  done
  same=no
  if cmp -s "$out/old-$name.png" "$out/course-$name.png" &&
    cmp -s "$out/old-$name.png" "$out/fast-$name.png"; then
    same=yes
  fi
  python3 - "$name" "$same" "${a[@]}" "${b[@]}" "${c[@]}" <<'PY'
import sys
name, same, a1, a2, b1, b2, c1, c2 = sys.argv[1:]
old, course, fast = (min(float(x), float(y)) for x, y in ((a1, a2), (b1, b2), (c1, c2)))
print(f"| {name} | {old:.2f} s | {course:.2f} s | {fast:.2f} s | {old / fast:.2f}x | {same} |")
PY
done
