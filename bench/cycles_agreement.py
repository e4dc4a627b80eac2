#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Does prism's path tracer agree with Blender's Cycles on the diffuse Cornell box
# (shared/scenes/cornell_diffuse.md) within the two renderers' own noise? Two renders of
# each from different seeds: each pair's difference measures its noise, and the RMSE
# between the two means is compared with what that noise alone explains. Writes
# bench/results/cycles_agreement.csv and cycles_vs_prism.png (prism | Cycles | 8x difference).
#
# usage: bench/cycles_agreement.py BUILD_DIR [--spp-prism 4096] [--spp-cycles 1024] [--size 256] [--area]
# --area: the box under its ceiling light (an area light) instead of the point light;
# writes cycles_agreement_area.csv and cycles_vs_prism_area.png.
import argparse
import csv
import math
import os
import subprocess

from methods_vs_time import cycles, read_pfm, run

here = os.path.dirname(os.path.abspath(__file__))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--spp-prism", type=int, default=4096)
    ap.add_argument("--spp-cycles", type=int, default=1024)
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--area", action="store_true", help="the box under its ceiling light (an area light)")
    args = ap.parse_args()
    suffix = "_area" if args.area else ""
    work = os.path.join(args.build, "cycles_agreement" + suffix)
    os.makedirs(work, exist_ok=True)
    prism, blender, seconds = [], [], {}
    for seed in (1, 2):
        out = os.path.join(work, "prism_%d.pfm" % seed)
        seconds["prism"] = run(args.build, "area" if args.area else "diffuse", "reference", args.spp_prism, out, args.size, seed)
        prism.append(read_pfm(out)[2])
        out = os.path.join(work, "cycles_%d.pfm" % seed)
        seconds["cycles"] = cycles(args.spp_cycles, out, seed, args.size, args.area)
        blender.append(read_pfm(out)[2])
    n = len(prism[0])
    mean = lambda a, b: [(x + y) / 2 for x, y in zip(a, b)]
    rmse = lambda a, b: math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)) / n)
    noise_prism, noise_cycles = rmse(*prism) / 2, rmse(*blender) / 2  # of each pair's mean
    p, c = mean(*prism), mean(*blender)
    measured, expected = rmse(p, c), math.hypot(noise_prism, noise_cycles)
    ratio = sum(p) / sum(c)
    print("prism %d spp x2 (%.1f s each), Cycles %d spp x2 (%.1f s each)" % (args.spp_prism, seconds["prism"], args.spp_cycles, seconds["cycles"]))
    print("noise of the means: prism %.5f, Cycles %.5f; RMSE prism vs Cycles %.5f, noise alone explains %.5f (ratio %.3f)" %
          (noise_prism, noise_cycles, measured, expected, measured / expected))
    print("mean radiance prism / Cycles: %.5f" % ratio)
    with open(os.path.join(here, "results", "cycles_agreement" + suffix + ".csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["prism_spp", "cycles_spp", "prism_seconds", "cycles_seconds", "noise_prism", "noise_cycles", "rmse_between", "rmse_from_noise", "mean_ratio"])
        w.writerow([args.spp_prism, args.spp_cycles, "%.2f" % seconds["prism"], "%.2f" % seconds["cycles"], "%.6f" % noise_prism,
                    "%.6f" % noise_cycles, "%.6f" % measured, "%.6f" % expected, "%.6f" % ratio])
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
