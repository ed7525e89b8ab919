#!/usr/bin/env python3
"""The course's sphere stages in Mitsuba 3 and in raycourse, at the same size,
samples and depth: checks that the images agree (region means within a few percent)
and times both; raycourse renders with its fast engine (`--fast`), in double
precision and, with `--single`, also as built with `--features f32`.

    python3 benches/mitsuba/compare.py                       # indirect, light-sampling
    python3 benches/mitsuba/compare.py depth-of-field --size 128 --spp 200 --threads 2
    python3 benches/mitsuba/compare.py --single              # both precisions

Installs what it needs into target/mitsuba-venv (PyPI `mitsuba`, `numpy`). Mitsuba
renders with `scalar_rgb` (one path at a time, like the course's code) and, where LLVM is
found (Debian's `libllvm19`, or `DRJIT_LIBLLVM_PATH`), with `llvm_ad_rgb` (eight or
sixteen paths per instruction). Both use its path tracer with `max_depth` =
bounces + 2 (Mitsuba counts the camera ray and the light's emission as depths) and
no Russian roulette, as the stages have none. Region means compare the two images as
displayed: `min(255, L^(1/gamma))` per channel, on a 4 x 4 grid of regions.
"""

import argparse
import glob
import os
import re
import subprocess
import sys
import time
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
VENV = ROOT / "target" / "mitsuba-venv"
STAGES = {"indirect": "s3", "antialiasing": "s3", "soft-shadows": "s4",
          "light-sampling": "s4", "depth-of-field": "s4"}


def in_venv():
    """Re-runs this script inside the virtual environment, made if missing."""
    if Path(sys.prefix) == VENV:
        return
    python = VENV / "bin" / "python3"
    if not python.exists():
        subprocess.run([sys.executable, "-m", "venv", str(VENV)], check=True)
        subprocess.run([str(python), "-m", "pip", "install", "--quiet", "mitsuba", "numpy"],
                       check=True)
    os.execv(str(python), [str(python), *sys.argv])


def mitsuba_scene(mi, scene, size, spp, seed):
    """A Mitsuba scene dictionary for a raycourse scene file (parsed TOML)."""
    render, camera = scene["render"], scene["camera"]
    eye = camera["position"]
    sensor = {
        "type": "perspective",
        "fov": camera["fov"],
        "fov_axis": "y",
        "to_world": mi.ScalarTransform4f().look_at(
            origin=eye, target=[eye[0], eye[1], eye[2] - 1], up=[0, 1, 0]),
        "film": {"type": "hdrfilm", "width": size, "height": size,
                 "rfilter": {"type": "box"}, "pixel_format": "rgb"},
        "sampler": {"type": "independent", "sample_count": spp, "seed": seed},
    }
    if "antialiasing" in camera:
        sensor["film"]["rfilter"] = {"type": "gaussian", "stddev": camera["antialiasing"]}
    if "lens" in camera:
        sensor["type"] = "thinlens"
        sensor["aperture_radius"] = camera["lens"]["aperture"]
        sensor["focus_distance"] = camera["lens"]["focus"]
    result = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": render.get("bounces", 5) + 2,
                       "rr_depth": 1000},
        "sensor": sensor,
    }
    for i, sphere in enumerate(scene.get("spheres", [])):
        shape = {"type": "sphere", "center": sphere["centre"], "radius": sphere["radius"],
                 "bsdf": bsdf(sphere["material"])}
        if any(sphere.get("emission", [0, 0, 0])):
            shape["emitter"] = {"type": "area", "radiance": rgb(sphere["emission"])}
        result[f"sphere{i}"] = shape
    light = scene.get("light")
    if light and "radius" in light:
        radiance = light["intensity"] / (4 * 3.141592653589793 ** 2 * light["radius"] ** 2)
        result["light"] = {"type": "sphere", "center": light["position"],
                           "radius": light["radius"],
                           "emitter": {"type": "area", "radiance": rgb([radiance] * 3)},
                           "bsdf": {"type": "diffuse", "reflectance": rgb([0, 0, 0])}}
    elif light:
        intensity = light["intensity"] / (4 * 3.141592653589793)
        result["light"] = {"type": "point", "position": light["position"],
                           "intensity": rgb([intensity] * 3)}
    return result


def rgb(value):
    return {"type": "rgb", "value": value}


def bsdf(material):
    if "diffuse" in material:
        return {"type": "diffuse", "reflectance": rgb(material["diffuse"])}
    if material == "mirror":
        return {"type": "conductor", "material": "none"}
    index = material.get("glass") or material.get("fresnel-glass")
    return {"type": "dielectric", "int_ior": index, "ext_ior": 1.0}


def display(image, gamma):
    """Linear radiance as raycourse displays it: min(255, L^(1/gamma))."""
    import numpy as np
    return np.minimum(255.0, np.maximum(image, 0.0) ** (1.0 / gamma))


def region_means(image, grid=4):
    size = image.shape[0] // grid
    return [image[r * size:(r + 1) * size, c * size:(c + 1) * size].mean()
            for r in range(grid) for c in range(grid)]


def timed_render(mi, loaded, spp):
    """The image of the loaded scene at `spp` samples, as a double-precision array,
    and the seconds its render took, waiting for every kernel to finish."""
    import drjit as dr
    import numpy as np
    start = time.perf_counter()
    image = mi.render(loaded, spp=spp)
    dr.eval(image)
    dr.sync_thread()
    seconds = time.perf_counter() - start
    return np.array(image, dtype=np.float64), seconds


def render_mitsuba(mi, variant, scene, args):
    """The image (linear) and the seconds of a render, after a warm-up render that
    compiles the variant's kernels."""
    import drjit as dr
    mi.set_variant(variant)
    dr.set_thread_count(args.threads)
    loaded = mi.load_dict(mitsuba_scene(mi, scene, args.size, args.spp, 1))
    mi.render(loaded, spp=1)
    return timed_render(mi, loaded, args.spp)


# Where each precision's build of raycourse goes.
BUILDS = {"double": ROOT / "target", "single": ROOT / "target" / "f32"}


def build(precision):
    """Builds raycourse with `--profile fastest` in `precision`, each into its own
    target folder so that neither rebuild undoes the other."""
    features = ["--features", "f32"] if precision == "single" else []
    environment = {**os.environ, "CARGO_TARGET_DIR": str(BUILDS[precision])}
    subprocess.run(["cargo", "build", "--quiet", "--profile", "fastest", *features],
                   cwd=ROOT, env=environment, check=True)


def raycourse_image(stage, args, precision):
    import numpy as np
    binary = BUILDS[precision] / "fastest" / "raycourse"
    out = ROOT / "target" / f"mitsuba-{stage}-{precision}.png"
    command = [str(binary), "render", str(ROOT / "sessions" / STAGES[stage] / f"{stage}.toml"),
               "--width", str(args.size), "--height", str(args.size), "--spp", str(args.spp),
               "--threads", str(args.threads), "--quiet", "--fast", "--out", str(out)]
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    seconds = time.perf_counter() - start
    import mitsuba as mi
    bitmap = mi.Bitmap(str(out))
    return np.array(bitmap, dtype=np.float64), seconds


def agreement(means, mine_means):
    """The largest relative difference of a region's mean from raycourse's, and that
    of the whole image's mean."""
    worst = max(abs(a - b) / max(b, 1.0) for a, b in zip(means, mine_means))
    overall = abs(sum(means) - sum(mine_means)) / sum(mine_means)
    return worst, overall


def has_llvm():
    """Whether Dr.Jit can find a recent LLVM for `llvm_ad_rgb` (the newest installed;
    LLVM 14 is too old for the kernels of Mitsuba 3.9)."""
    if os.environ.get("DRJIT_LIBLLVM_PATH"):
        return True
    found = glob.glob("/usr/lib/*/libLLVM*.so*") + glob.glob("/usr/lib/llvm-*/lib/libLLVM*.so*")
    versions = [(int(m.group(1)), path) for path in found
                if (m := re.search(r"libLLVM(?:-|\.so\.)(\d+)", path))]
    if not versions or max(versions)[0] < 15:
        print("no LLVM 15 or newer: llvm_ad_rgb skipped (Debian: apt-get install libllvm19)")
        return False
    os.environ["DRJIT_LIBLLVM_PATH"] = max(versions)[1]
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("stages", nargs="*", default=["indirect", "light-sampling"])
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--spp", type=int, default=200)
    parser.add_argument("--threads", type=int, default=os.cpu_count())
    parser.add_argument("--single", action="store_true",
                        help="also time raycourse built in single precision (--features f32)")
    args = parser.parse_args()
    in_venv()
    precisions = ["double", "single"] if args.single else ["double"]
    for precision in precisions:
        build(precision)
    import mitsuba as mi
    variants = ["scalar_rgb"] + (["llvm_ad_rgb"] if has_llvm() else [])
    print(f"{args.size} x {args.size}, {args.spp} spp, {args.threads} threads")
    print("| stage | renderer | seconds | speed against raycourse | region means: worst, overall |")
    print("|---|---|---|---|---|")
    for stage in args.stages:
        scene = tomllib.loads((ROOT / "sessions" / STAGES[stage] / f"{stage}.toml").read_text())
        gamma = scene["render"].get("gamma", 1.0)
        mine, mine_seconds = raycourse_image(stage, args, "double")
        mine_means = region_means(mine)
        print(f"| {stage} | raycourse | {mine_seconds:.2f} | 1 | - |")
        for precision in precisions[1:]:
            image, seconds = raycourse_image(stage, args, precision)
            worst, overall = agreement(region_means(image), mine_means)
            print(f"| {stage} | raycourse, {precision} precision | {seconds:.2f} | "
                  f"{mine_seconds / seconds:.2f}x | {100 * worst:.1f}%, {100 * overall:.1f}% |")
        for variant in variants:
            image, seconds = render_mitsuba(mi, variant, scene, args)
            worst, overall = agreement(region_means(display(image, gamma)), mine_means)
            print(f"| {stage} | Mitsuba {variant} | {seconds:.2f} | "
                  f"{mine_seconds / seconds:.2f}x | {100 * worst:.1f}%, {100 * overall:.1f}% |")


if __name__ == "__main__":
    main()
