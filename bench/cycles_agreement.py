#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Does prism's path tracer agree with Blender's Cycles on the diffuse Cornell box
# (shared/scenes/cornell_diffuse.md) within the two renderers' own noise? Two renders of
# each from different seeds: each pair's difference measures its noise, and the RMSE
# between the two means is compared with what that noise alone explains. Writes
# bench/results/cycles_agreement.csv and cycles_vs_prism.png (prism | Cycles | 8x difference).
#
# usage: bench/cycles_agreement.py BUILD_DIR [--spp-prism 4096] [--spp-cycles 1024] [--size 256] [--area | --sky | --sky-glossy | --sky-frosted]
# --area: the box under its ceiling light (an area light) instead of the point light;
# writes cycles_agreement_area.csv and cycles_vs_prism_area.png.
# --sky: bench/sky.cpp's spheres under the photographed sky (an EnvironmentMap), Cycles'
# copy built by bench/cycles_sky.py; writes cycles_agreement_sky.csv and cycles_vs_prism_sky.png.
# --sky-glossy: the same with rough metal spheres (GGX, roughness 0.4 and 0.15: RoughConductor
# against Cycles' Glossy BSDF); writes cycles_agreement_sky_glossy.csv and cycles_vs_prism_sky_glossy.png.
# --sky-frosted: the left sphere frosted glass (RoughDielectric against Cycles' Glass BSDF, GGX);
# writes cycles_agreement_sky_frosted.csv and cycles_vs_prism_sky_frosted.png.
import argparse
import csv
import math
import os
import subprocess

from methods_vs_time import cycles, read_pfm, run

here = os.path.dirname(os.path.abspath(__file__))


def run_sky(build, spp, out, size, seed, variant=""):
    """bench_sky's path-traced picture; its seconds."""
    result = subprocess.run([os.path.join(build, "bench", "bench_sky"), out, str(spp), str(size), str(seed)] + ([variant] if variant else []),
                            capture_output=True, text=True, check=True)
    return float(result.stdout.split()[1])


def cycles_sky(spp, out, seed, size, variant=""):
    """Cycles' picture of the same scene (bench/cycles_sky.py); its render seconds."""
    subprocess.run(["blender", "-b", "--factory-startup", "--python", os.path.join(here, "cycles_sky.py"), "--", out, str(spp), str(seed), str(size)] +
                   ([variant] if variant else []), capture_output=True, text=True, check=True)
    with open(out + ".txt") as f:
        return float(f.read().splitlines()[1].split(",")[1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--spp-prism", type=int, default=4096)
    ap.add_argument("--spp-cycles", type=int, default=1024)
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--area", action="store_true", help="the box under its ceiling light (an area light)")
    ap.add_argument("--sky", action="store_true", help="spheres under a photographed sky (an environment map)")
    ap.add_argument("--sky-glossy", action="store_true", help="rough metal spheres under the photographed sky (GGX)")
    ap.add_argument("--sky-frosted", action="store_true", help="a frosted glass and a rough metal sphere under the photographed sky (GGX)")
    args = ap.parse_args()
    variant = "glossy" if args.sky_glossy else "frosted" if args.sky_frosted else ""
    args.sky = args.sky or bool(variant)
    suffix = "_area" if args.area else "_sky_" + variant if variant else "_sky" if args.sky else ""
    work = os.path.join(args.build, "cycles_agreement" + suffix)
    os.makedirs(work, exist_ok=True)
    prism, blender, seconds = [], [], {}
    for seed in (1, 2):
        out = os.path.join(work, "prism_%d.pfm" % seed)
        if args.sky:
            seconds["prism"] = run_sky(args.build, args.spp_prism, out, args.size, seed, variant)
        else:
            seconds["prism"] = run(args.build, "area" if args.area else "diffuse", "reference", args.spp_prism, out, args.size, seed)
        prism.append(read_pfm(out)[2])
        out = os.path.join(work, "cycles_%d.pfm" % seed)
        seconds["cycles"] = cycles_sky(args.spp_cycles, out, seed, args.size, variant) if args.sky else cycles(args.spp_cycles, out, seed, args.size, args.area)
        blender.append(read_pfm(out)[2])
    n = len(prism[0])
    mean = lambda a, b: [(x + y) / 2 for x, y in zip(a, b)]
    rmse = lambda a, b: math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)) / n)
    print("prism %d spp x2 (%.1f s each), Cycles %d spp x2 (%.1f s each)" % (args.spp_prism, seconds["prism"], args.spp_cycles, seconds["cycles"]))
    # In linear radiance, and in the display range (clamped to 1, where the picture
    # saturates): there a sun's image and its caustics' fireflies, a few values that hold
    # most of the linear noise, count as what a viewer sees.
    stats = []
    for name, view in (("linear", lambda a: a), ("display range", lambda a: [min(v, 1.0) for v in a])):
        pv, cv = [view(x) for x in prism], [view(x) for x in blender]
        noise_prism, noise_cycles = rmse(*pv) / 2, rmse(*cv) / 2  # of each pair's mean
        p, c = mean(*pv), mean(*cv)
        measured, expected = rmse(p, c), math.hypot(noise_prism, noise_cycles)
        ratio = sum(p) / sum(c)
        print("%s: noise of the means: prism %.5f, Cycles %.5f; RMSE prism vs Cycles %.5f, noise alone explains %.5f (ratio %.3f); "
              "mean radiance prism / Cycles: %.5f" % (name, noise_prism, noise_cycles, measured, expected, measured / expected, ratio))
        stats += ["%.6f" % noise_prism, "%.6f" % noise_cycles, "%.6f" % measured, "%.6f" % expected, "%.6f" % ratio]
    p, c = mean(*prism), mean(*blender)
    with open(os.path.join(here, "results", "cycles_agreement" + suffix + ".csv"), "w", newline="") as f:
        w = csv.writer(f)
        columns = ["noise_prism", "noise_cycles", "rmse_between", "rmse_from_noise", "mean_ratio"]
        w.writerow(["prism_spp", "cycles_spp", "prism_seconds", "cycles_seconds"] + columns + [k + "_display" for k in columns])
        w.writerow([args.spp_prism, args.spp_cycles, "%.2f" % seconds["prism"], "%.2f" % seconds["cycles"]] + stats)
    # prism | Cycles | 8x difference, sRGB-encoded, for the README.
    try:
        from PIL import Image
    except ImportError:
        return
    size = args.size
    srgb = lambda v: int(255 * max(0.0, min(1.0, (12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055))) + 0.5)
    img = Image.new("RGB", (3 * size, size))
    for y in range(size):
        row = size - 1 - y  # PFM rows run bottom to top
        for x in range(size):
            i = 3 * (row * size + x)
            img.putpixel((x, y), tuple(srgb(p[i + k]) for k in range(3)))
            img.putpixel((size + x, y), tuple(srgb(c[i + k]) for k in range(3)))
            img.putpixel((2 * size + x, y), tuple(srgb(0.5 + 8 * (p[i + k] - c[i + k])) for k in range(3)))
    img.save(os.path.join(here, "results", "cycles_vs_prism" + suffix + ".png"))


if __name__ == "__main__":
    main()
