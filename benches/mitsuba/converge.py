#!/usr/bin/env python3
"""Mitsuba 3's error against raycourse's reference at a ladder of sample counts, with
its time: the rungs of `raycourse converge` for Mitsuba's two variants, as a CSV file
that `raycourse plot` reads beside the crate's own.

    python3 benches/mitsuba/converge.py --reference out/reference/bb19f8224fecc9e7.ref

The reference is the file that `raycourse converge antialiasing --width 64 --height 64
--reference-spp 8192` names on its first line. The stage is rendered by Mitsuba as
`compare.py` describes it, at the same size, with the sample counts 1, 2, 4, ... up to
`--max-spp`; each count is rendered twice and the second render timed, so that it
finds its kernels compiled. The error is raycourse's: the root mean square
error and the relative mean square error over every pixel and channel of linear
radiance (`studies::convergence::image_error`). A stage whose camera rays pass through
the pixels' centres (no `camera.antialiasing`) is another image than Mitsuba's, which
spreads them over the pixel, so the default stage is `antialiasing`, whose Gaussian
jitter both renderers share.
"""

import argparse
import os
import struct
import sys
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from compare import ROOT, STAGES, has_llvm, in_venv, mitsuba_scene, timed_render  # noqa: E402

# The first line of a raycourse reference file (`render::cache`).
MAGIC = b"raycourse reference 1\n"


def read_reference(path):
    """A raycourse reference file as an array of shape (height, width, 3), the top
    row first, in double precision."""
    import numpy as np
    try:
        data = Path(path).read_bytes()
    except OSError as error:
        sys.exit(f"{path}: cannot read the reference: {error.strerror}")
    if not data.startswith(MAGIC):
        sys.exit(f"{path}: not a raycourse reference file (no `{MAGIC.decode().strip()}` line)")
    width, height = struct.unpack_from("<II", data, len(MAGIC))
    values = np.frombuffer(data, dtype="<f8", offset=len(MAGIC) + 8)
    if values.size != width * height * 3:
        sys.exit(f"{path}: {values.size} numbers for a {width} x {height} image")
    return values.reshape(height, width, 3)


def image_error(image, reference):
    """raycourse's `image_error`: the RMSE, and the relative MSE
    `mean((x - r)^2 / (r^2 + 0.01))`."""
    import numpy as np
    squared = (image - reference) ** 2
    return float(np.sqrt(squared.mean())), float((squared / (reference ** 2 + 0.01)).mean())


def rungs(mi, variant, scene, args, reference):
    """The variant's CSV rows, one per sample count."""
    import drjit as dr
    mi.set_variant(variant)
    dr.set_thread_count(args.threads)
    rows = []
    samples = 1
    while samples <= args.max_spp:
        loaded = mi.load_dict(mitsuba_scene(mi, scene, args.size, samples, 1))
        timed_render(mi, loaded, samples)
        image, seconds = timed_render(mi, loaded, samples)
        rmse, rel_mse = image_error(image, reference)
        efficiency = 1.0 / (rmse * rmse * seconds)
        rows.append(f"Mitsuba {variant},{samples},{seconds},{rmse},{rel_mse},{efficiency}")
        samples *= 2
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("stage", nargs="?", default="antialiasing", choices=sorted(STAGES))
    parser.add_argument("--reference", required=True,
                        help="raycourse's reference file (.ref) for the stage at this size")
    parser.add_argument("--size", type=int, default=64, help="width and height in pixels")
    parser.add_argument("--max-spp", type=int, default=256,
                        help="the largest sample count of the ladder 1, 2, 4, ...")
    parser.add_argument("--threads", type=int, default=os.cpu_count())
    parser.add_argument("--out", default=str(ROOT / "target" / "mitsuba-converge.csv"),
                        help="the CSV file of rungs")
    args = parser.parse_args()
    in_venv()
    import mitsuba as mi
    reference = read_reference(args.reference)
    if reference.shape[:2] != (args.size, args.size):
        sys.exit(f"{args.reference}: {reference.shape[1]} x {reference.shape[0]} pixels, "
                 f"not {args.size} x {args.size}")
    scene = tomllib.loads((ROOT / "sessions" / STAGES[args.stage] / f"{args.stage}.toml")
                          .read_text())
    variants = ["scalar_rgb"] + (["llvm_ad_rgb"] if has_llvm() else [])
    lines = ["variant,samples,seconds,rmse,rel_mse,efficiency"]
    for variant in variants:
        lines += rungs(mi, variant, scene, args, reference)
        print(lines[-1])
    Path(args.out).write_text("\n".join(lines) + "\n")
    print(f"-> {args.out}")


if __name__ == "__main__":
    main()
