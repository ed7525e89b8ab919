#!/usr/bin/env bash
# Times the sphere stages against an earlier commit of the crate, side by side in one
# run, and checks that both give the same PNG bytes.
#
#   benches/against.sh d14e0f3          # indirect and light-sampling, 192 x 192
#   benches/against.sh d14e0f3 512      # at the course's size
#
# The earlier commit is built in a git worktree (in $TMPDIR) with its own release
# profile; this one with `--profile fastest`. The two binaries take turns, twice per
# stage, so that a change in the machine's load touches both alike; the faster of
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
printf '| stage | %s | this commit | speed-up | same bytes |\n|---|---|---|---|---|\n' "$commit"
for stage in s3/indirect s4/light-sampling; do
  name=${stage#*/}
  args=(render "sessions/$stage.toml" --width "$size" --height "$size" --quiet)
  a=() b=()
  for _ in 1 2; do
    a+=("$(seconds "$old" "${args[@]}" --out "$out/old-$name.png")")
    b+=("$(seconds "$new" "${args[@]}" --out "$out/new-$name.png")")
  done
  same=$(cmp -s "$out/old-$name.png" "$out/new-$name.png" && echo yes || echo NO)
  python3 - "$name" "$same" "${a[@]}" "${b[@]}" <<'EOF'
import sys
name, same, a1, a2, b1, b2 = sys.argv[1:]
old, new = min(float(a1), float(a2)), min(float(b1), float(b2))
print(f"| {name} | {old:.2f} s | {new:.2f} s | {old / new:.2f}x | {same} |")
EOF
done
