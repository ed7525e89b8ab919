#!/usr/bin/env python3
"""The medians of a run of book/speed-tables.sh, as the rows of the speed appendix.

Reads book/src/figures/speed/tables.txt (or the file given) and prints, as Markdown
table rows, what the appendix "Speed against accuracy" states from it: the hierarchy's
table and the peers' (Mrays/s, one thread, the median of each figure's rounds), the
threads' table (median times and the median of the pairs' ratios) and Mitsuba's
(median times, and each renderer's speed against the double-precision crate from
those medians). With --check BOOK, it also checks that every one of those rows is a
line of BOOK (book/src/speed.md by default) and names those that are not, with exit
code 1: the appendix's tables are then not the run's.

Usage: python3 book/speed-medians.py [TABLES] [--check [BOOK]]
"""

import argparse
import re
import statistics
import sys
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SETS = ["primary", "diffuse", "shadow"]
HIERARCHIES = ["midpoint", "sah", "fast-portable", "fast"]
THREAD_LABELS = {
    "indirect": "`indirect`, course's code",
    "indirect-fast": "`indirect`, `--fast`",
    "bvh-fast": "`bvh`, `--fast`",
}
RENDERERS = [
    "raycourse",
    "raycourse, single precision",
    "Mitsuba scalar_rgb",
    "Mitsuba llvm_ad_rgb",
]


def median(values, what):
    """The median of `values`, or a clear error naming what is missing."""
    if not values:
        sys.exit(f"speed-medians.py: no measurement of {what} in the tables")
    return statistics.median(values)


def hierarchy_rows(lines):
    """The hierarchy table: each hierarchy's and Embree's one-thread medians."""
    speeds = defaultdict(list)
    for line in lines:
        own = re.match(r"rays \d+ (\S+) raycourse (\S+) threads=1 Mrays/s=([\d.]+)", line)
        embree = re.match(r"rays \d+ embree1 (\S+) threads=1 Mrays/s=([\d.]+)", line)
        if own:
            speeds[(own[1], own[2])].append(float(own[3]))
        elif embree:
            speeds[("embree", embree[1])].append(float(embree[2]))
    rows, embree_medians = [], {}
    for rays in SETS:
        cells = [f"{median(speeds[(h, rays)], f'{h} {rays}'):.2f}" for h in HIERARCHIES]
        embree_medians[rays] = f"{median(speeds[('embree', rays)], f'Embree {rays}'):.2f}"
        share = 100 * float(cells[-1]) / float(embree_medians[rays])
        rows.append(f"| {rays} | {' | '.join(cells)} | {embree_medians[rays]} | {share:.2f}% |")
    return rows, embree_medians


def peers_rows(lines, embree_medians):
    """The peers table: Embree's median beside the peers benchmark's medians."""
    columns = defaultdict(list)
    for line in lines:
        row = re.match(r"peers \d+ \| (\w+) \(\d+\) \| (.*)\|$", line)
        if row:
            cells = [cell.split()[0] for cell in row[2].split("|")[:-1]]
            columns[row[1]].append([float(cell) for cell in cells])
    rows = []
    for rays in SETS:
        runs = columns[rays] or median([], f"the peers benchmark's {rays} rays")
        cells = [f"{statistics.median(column):.2f}" for column in zip(*runs)]
        rows.append(f"| {rays} | {embree_medians[rays]} | {' | '.join(cells)} |")
    return rows


def threads_rows(lines):
    """The threads table: median times on one and two threads, the pairs' ratio."""
    times = defaultdict(list)
    for line in lines:
        pair = re.match(r"threads (\S+) ([12]) ([\d.]+)$", line)
        if pair:
            times[(pair[1], pair[2])].append(float(pair[3]))
    rows = []
    for label, title in THREAD_LABELS.items():
        one, two = times[(label, "1")], times[(label, "2")]
        ratio = median([a / b for a, b in zip(one, two)], f"{label} on two threads")
        cells = f"{median(one, label):.2f} s | {median(two, label):.2f} s | {ratio:.2f}x"
        rows.append(f"| {title} | {cells} |")
    return rows


def mitsuba_rows(lines):
    """Mitsuba's table: median times, speeds against the double-precision crate,
    and the first run's region means of the single-precision crate and JIT."""
    times, regions, stages = defaultdict(list), {}, []
    for line in lines:
        row = re.match(r"mitsuba (\d+) \| (\S+) \| ([^|]+) \| ([\d.]+) \|.*\| ([^|]+) \|$", line)
        if row:
            stage, renderer = row[2], row[3].strip()
            times[(stage, renderer)].append(float(row[4]))
            if stage not in stages:
                stages.append(stage)
            if row[1] == "1":
                regions[(stage, renderer)] = row[5].strip().replace(", ", " / ")
    rows = []
    for stage in stages or median([], "Mitsuba's comparison"):
        medians = [median(times[(stage, r)], f"{r} on {stage}") for r in RENDERERS]
        cells = [f"{medians[0]:.2f} s"]
        cells += [f"{m:.2f} s ({medians[0] / m:.2f}x)" for m in medians[1:]]
        means = f"{regions[(stage, RENDERERS[1])]}; {regions[(stage, RENDERERS[3])]}"
        rows.append(f"| `{stage}` | {' | '.join(cells)} | {means} |")
    return rows


def read(path):
    """The text of `path`, or a clear error naming it."""
    try:
        return path.read_text()
    except OSError as error:
        sys.exit(f"speed-medians.py: cannot read {path}: {error.strerror}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "tables", nargs="?", type=Path, default=ROOT / "book/src/figures/speed/tables.txt"
    )
    parser.add_argument(
        "--check", nargs="?", type=Path, const=ROOT / "book/src/speed.md", metavar="BOOK"
    )
    args = parser.parse_args()
    lines = read(args.tables).splitlines()
    rows, embree_medians = hierarchy_rows(lines)
    rows += peers_rows(lines, embree_medians) + threads_rows(lines) + mitsuba_rows(lines)
    if not args.check:
        print("\n".join(rows))
        return
    book_lines = set(read(args.check).splitlines())
    missing = [row for row in rows if row not in book_lines]
    for row in missing:
        print(f"{args.check}: no line reads\n  {row}\nwhich is what {args.tables} gives", file=sys.stderr)
    if missing:
        sys.exit(1)
    print(f"{args.check}: its {len(rows)} rows of medians are those of {args.tables}")


if __name__ == "__main__":
    main()
