#!/usr/bin/env bash
# Measures the speed tables of the appendix "Speed against accuracy" in one run and
# writes them to book/src/figures/speed/tables.txt, headed by the date, the processor
# and the compiler: every stage at the course's settings (`bench`), one thread against
# two, the hierarchies on the Embree benchmark's ray sets beside Embree, tinybvh and
# obvhs, the sphere stages beside Mitsuba 3 in both precisions, and the live book in
# headless Chromium, then the medians the appendix gives (book/speed-medians.py). Each
# figure is a time, so run it on an otherwise idle machine; it takes about 20 minutes
# on two cores once Mitsuba 3 is installed.
#
# Needs a C++ compiler (tinybvh), Python 3 (Mitsuba 3 is installed into
# target/mitsuba-venv on the first run), the Embree tool (EMBREE_BENCH, by default
# ../shared/tools/embree-bench, whose build installs Embree), and node with
# web/node_modules and Chromium for the browser's table. ROUNDS (3 by default) sets
# how many times the ray sets, the thread pairs and Mitsuba's renders are measured;
# the appendix gives the median of each figure.
set -euo pipefail
cd "$(dirname "$0")/.."
out=book/src/figures/speed/tables.txt
rounds=${ROUNDS:-3}
embree=${EMBREE_BENCH:-../shared/tools/embree-bench}
mesh=assets/ogre/ogre.obj
sets=/tmp/raysets/ogre
images=target/speed-tables

# Everything the run needs, checked before its first measurement.
missing() { echo "speed-tables.sh: $1" >&2; exit 1; }
[ -x "$embree/run.sh" ] || missing "no Embree tool at $embree (set EMBREE_BENCH to its folder)"
command -v c++ >/dev/null || missing "no C++ compiler (c++), which the peers benchmark's tinybvh needs"
command -v python3 >/dev/null || missing "no python3, which Mitsuba's comparison needs"
command -v node >/dev/null || missing "no node, which the browser's table needs"
[ -d web/node_modules/puppeteer-core ] || missing "no puppeteer-core in web/node_modules (run: cd web && npm ci)"
[ -x "${CHROMIUM:-/usr/bin/chromium}" ] || missing "no Chromium at ${CHROMIUM:-/usr/bin/chromium} (set CHROMIUM)"
mkdir -p "$images"
exec > >(tee "$out")

processor=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')
echo "# $(date -u '+%-d %B %Y'), $processor, $(nproc) cores; $(rustc --version)"
cargo build --quiet --profile fastest
fastest=target/fastest/raycourse

echo "## Every stage at the course's settings, course's code and --fast"
"$fastest" bench 1 2 3 4
"$fastest" bench 5 6 7

echo "## One thread against two: 128 x 128, 200 samples, $rounds alternating pairs"
seconds() { local TIMEFORMAT=%R; { time "$@" >/dev/null; } 2>&1; }
one_and_two() {
  local label=$1 scene=$2
  shift 2
  for _ in $(seq "$rounds"); do
    for n in 1 2; do
      echo "threads $label $n $(seconds "$fastest" render "sessions/$scene.toml" --width 128 \
        --height 128 --spp 200 --threads "$n" --quiet --out "$images/$n.png" "$@")"
    done
    cmp "$images/1.png" "$images/2.png" && echo "threads $label same bytes"
  done
}
one_and_two indirect s3/indirect
one_and_two indirect-fast s3/indirect --fast
one_and_two bvh-fast s6/bvh --fast

echo "## The hierarchies on the ray sets, one thread (and two for the fast BVH), $rounds rounds"
"$embree/run.sh" "$mesh" --threads 1 --reps 1 --no-packets >/dev/null
for round in $(seq "$rounds"); do
  for bvh in midpoint sah fast-portable fast; do
    threads=1
    [ "$bvh" = fast ] && threads=1,2
    "$fastest" rays "$mesh" "$sets"/{primary,diffuse,shadow}.rays --bvh "$bvh" \
      --threads "$threads" | grep 'threads=' | sed "s/^/rays $round $bvh /"
  done
  "$embree/run.sh" "$mesh" --threads 1,2 --quality high --no-packets | grep '^embree1' |
    sed "s/^/rays $round /"
  RAYSETS=$sets cargo bench --quiet -p raycourse-benches --bench peers | grep '^| [pds]' |
    sed "s/^/peers $round /"
done

echo "## Beside Mitsuba 3: 128 x 128, 200 samples, two threads, $rounds runs"
for round in $(seq "$rounds"); do
  python3 benches/mitsuba/compare.py indirect antialiasing light-sampling depth-of-field \
    --single | sed "s/^/mitsuba $round /"
done

echo "## In the browser: the live book's demos and check page in headless Chromium"
cargo xtask book >/dev/null
RAYCOURSE=$fastest node web/tests/browser.mjs --speed

echo "## The medians the appendix gives, by book/speed-medians.py"
python3 book/speed-medians.py "$out"
