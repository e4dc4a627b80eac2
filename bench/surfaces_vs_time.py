#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Issue 35's surfaces scene (bench/surfaces.cpp: rough gold and frosted glass spheres on a
# varnished tile floor with an image texture and a normal map, a thin lens, a point light
# and a dim sky; Cycles' copy is bench/cycles_surfaces.py), in one run on 2 threads:
#
# 1. Agreement: prism's path tracer (two halves of --reference-spp, different seeds)
#    against Cycles (two renders of --cycles-spp): the RMSE between the two means against
#    what their own noise explains, sqrt(sigma_prism^2 + sigma_cycles^2), each sigma from
#    its pair (RMSE(a, b) / 2). A ratio near 1 is agreement within the references' noise.
# 2. Error against time: every method of prism (path tracer; photon map read directly;
#    final gather; progressive photon mapping) and Cycles, against the path tracer's
#    reference with its own noise taken out in quadrature, over the whole picture and over
#    the frosted ball's caustic on the tiles (a rectangle of the picture). Each timed render
#    is run --repeats times, interleaved (min and median kept).
#
# Writes bench/results/surfaces_vs_time.csv, surfaces_agreement.csv and surfaces_strip.png
# (prism | Cycles | 8x difference, and each method at about the same time); bench/plot.py
# draws surfaces_vs_time.png.
#
# The path tracer runs twice: with Owen-scrambled Sobol points (path, prism's default) and
# with independent samples (path:independent).
#
# usage: bench/surfaces_vs_time.py BUILD_DIR [--size 256] [--reference-spp 4096] [--cycles-spp 1024] [--repeats 2] [--quick]
#                                  [--methods path,path:independent,...] [--cycles-levels 16,64,256,1024]
#                                  [--agreement-only]
import argparse
import csv
import functools
import math
import os
import statistics
import subprocess
import sys

from methods_vs_time import Scorer, bench_render, cycles_script_render, read_pfm, rectangle_mask, rmse, time_to_reach, write_csv, write_pfm

here = os.path.dirname(os.path.abspath(__file__))


def tagged(name, tag):
    """NAME.EXT as NAME_TAG.EXT (unchanged for no tag)."""
    stem, ext = os.path.splitext(name)
    return stem + ("_" + tag if tag else "") + ext

# The caustic's rectangle, as fractions of the picture (x from the left, y from the top).
CAUSTIC = (0.23, 0.47, 0.58, 0.78)


def caustic_mask(w, h):
    """Per value: True inside the caustic's rectangle."""
    return rectangle_mask(w, h, CAUSTIC)


prism_render = functools.partial(bench_render, "bench_surfaces")
cycles_render = functools.partial(cycles_script_render, "cycles_surfaces.py")


def agreement(prism_halves, cycles_pair, mask=None, display=False):
    """(noise of prism's mean, noise of Cycles' mean, RMSE between the means, what the noise
    explains, ratio of the mean radiances), over the values where mask is True (all: None);
    with `display`, of the radiances clamped to 1 (the display range)."""
    if display:
        clamp = lambda img: (img[0], img[1], [min(v, 1.0) for v in img[2]])
        prism_halves, cycles_pair = [clamp(x) for x in prism_halves], [clamp(x) for x in cycles_pair]
    mean = lambda a, b: [(x + y) / 2 for x, y in zip(a[2], b[2])]
    w, h = prism_halves[0][0], prism_halves[0][1]
    p, c = (w, h, mean(*prism_halves)), (w, h, mean(*cycles_pair))
    noise_p, noise_c = rmse(*prism_halves, mask) / 2, rmse(*cycles_pair, mask) / 2
    kept = lambda img: [v for v, m in zip(img[2], mask or [True] * len(img[2])) if m]
    return noise_p, noise_c, rmse(p, c, mask), math.hypot(noise_p, noise_c), sum(kept(p)) / sum(kept(c))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--reference-spp", type=int, default=4096, help="samples per pixel (or passes) of each of the reference's two halves")
    ap.add_argument("--reference-method", default="path", help="the reference's method: path (the path tracer), or vcm, whose error at a given time is a "
                    "small fraction of the path tracer's here (the caustic of a point light through frosted glass)")
    ap.add_argument("--cycles-spp", type=int, default=1024, help="of each of Cycles' two renders for the agreement")
    ap.add_argument("--repeats", type=int, default=2)
    ap.add_argument("--quick", action="store_true", help="small efforts (a smoke test of this script)")
    ap.add_argument("--methods", help="a comma-separated subset of prism's methods (path, path:independent (independent samples), direct, ...)")
    ap.add_argument("--cycles-levels", help="Cycles' samples per pixel, comma-separated (16,64,256,1024), or none")
    ap.add_argument("--tag", default="", help="written to bench/results/NAME_TAG.csv and .png instead of NAME.csv, so that a run of a few methods keeps the full run's files")
    ap.add_argument("--agreement-only", action="store_true",
                    help="only score the reference and Cycles' pair already rendered in BUILD_DIR/surfaces_vs_time against each other")
    args = ap.parse_args()
    work = os.path.join(args.build, "surfaces_vs_time")
    os.makedirs(work, exist_ok=True)
    efforts = {"path": [16, 64, 256, 1024], "path:independent": [16, 64, 256, 1024], "direct": [100000, 300000, 1000000, 3000000], "gather": [16, 64, 256],
               "progressive": [16, 64, 256], "bdpt": [16, 64, 256], "vcm": [16, 64, 256]}
    cycles_spp = [16, 64, 256, 1024]
    if args.methods:
        efforts = {m: e for m, e in efforts.items() if m in args.methods.split(",")}
    if args.cycles_levels:
        cycles_spp = [] if args.cycles_levels == "none" else [int(x) for x in args.cycles_levels.split(",")]
    if args.quick:
        efforts = {m: e[:2] for m, e in efforts.items()}
        cycles_spp = cycles_spp[:2]
    # The reference: the path tracer in two halves; their difference measures its noise.
    halves, reference_seconds = [], 0.0
    if args.agreement_only:  # the times of the run that rendered them
        with open(os.path.join(here, "results", tagged("surfaces_agreement.csv", args.tag))) as f:
            first = next(csv.DictReader(f))
        reference_seconds, cycles_seconds = float(first["prism_seconds"]), float(first["cycles_seconds"]) / 2
    for seed in (101, 102):
        out = os.path.join(work, "reference_%d.pfm" % seed)
        if not args.agreement_only:
            reference_seconds += prism_render(args.build, args.reference_method, args.reference_spp, out, args.size, seed)
        halves.append(read_pfm(out))
    w, h = halves[0][0], halves[0][1]
    write_pfm(os.path.join(work, "reference.pfm"), (w, h, [(a + b) / 2 for a, b in zip(halves[0][2], halves[1][2])]))
    scorers = {"all": Scorer(halves), "caustic": Scorer(halves, caustic_mask(w, h))}
    print("reference: %s, 2 x %d spp, %.1f s; its own noise %.5f (caustic %.5f)" % (args.reference_method, args.reference_spp, reference_seconds, scorers["all"].noise,
                                                                                          scorers["caustic"].noise), flush=True)
    # Agreement with Cycles.
    pair = []
    for seed in (1, 2):
        out = os.path.join(work, "cycles_agreement_%d.pfm" % seed)
        if not args.agreement_only:
            cycles_seconds = cycles_render(args.cycles_spp, out, args.size, seed)
        pair.append(read_pfm(out))
    found = {}
    for region, mask in (("all", None), ("caustic", caustic_mask(w, h))):
        for display in (False, True):
            stats = agreement(halves, pair, mask, display)
            found[(region, display)] = stats
            print("agreement, %s, %s: noise of the means prism %.5f, Cycles %.5f; RMSE between %.5f, noise explains %.5f (ratio %.3f); "
                  "mean prism / Cycles %.5f" % (region, "display range" if display else "linear", stats[0], stats[1], stats[2], stats[3], stats[2] / stats[3],
                                                stats[4]), flush=True)
    with open(os.path.join(here, "results", tagged("surfaces_agreement.csv", args.tag)), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["region", "range", "prism_spp", "cycles_spp", "prism_seconds", "cycles_seconds", "noise_prism", "noise_cycles", "rmse_between",
                      "rmse_from_noise", "mean_ratio"])
        for (region, display), s in found.items():
            out.writerow([region, "display" if display else "linear", 2 * args.reference_spp, 2 * args.cycles_spp, "%.2f" % reference_seconds,
                          "%.2f" % (2 * cycles_seconds)] + ["%.6f" % v for v in s])
    if args.agreement_only:
        return 0
    # Every method's renders, timed in interleaved rounds.
    jobs = []
    for method, levels in efforts.items():
        for effort in levels:
            out = os.path.join(work, "%s_%d.pfm" % (method, effort))
            jobs.append(("prism " + method, effort, out, functools.partial(prism_render, args.build, method, effort, out, args.size)))
    for spp in cycles_spp:
        out = os.path.join(work, "cycles_%d.pfm" % spp)
        jobs.append(("Cycles", spp, out, functools.partial(cycles_render, spp, out, args.size)))
    times = [[] for _ in jobs]
    for _ in range(args.repeats):
        for job, seconds in zip(jobs, times):
            seconds.append(job[3]())
    rows = []
    for (method, effort, out, _), seconds in zip(jobs, times):
        image = read_pfm(out)
        for region_name, scorer in scorers.items():
            rows.append((region_name, method, effort, min(seconds), statistics.median(seconds)) + scorer(image))
            print("%-8s %-18s %8s: %.3f s (median %.3f), RMSE %.5f, display range %.5f" % (region_name, method, effort, rows[-1][3], rows[-1][4], rows[-1][5],
                                                                                         rows[-1][8]), flush=True)
    path = os.path.join(here, "results", tagged("surfaces_vs_time.csv", args.tag))
    write_csv(path, rows, "region")
    print("wrote", path)
    summary(rows)
    if len(cycles_spp) >= 2:
        strip(work, halves, pair, efforts, cycles_spp, name=tagged("surfaces_strip.png", args.tag))


def summary(rows):
    """For each Cycles picture, each prism method's time to its error, as a ratio of Cycles'
    time: in linear radiance and in the display range (clamped to 1, where the fireflies of
    a caustic found by paths count as what a viewer sees rather than as their energy)."""
    for column, name in ((5, "linear"), (8, "display range")):
        for region in ("all", "caustic"):
            print("%s, %s RMSE: time to reach Cycles' error, as a ratio of Cycles' time:" % (region, name))
            methods = list(dict.fromkeys(r[1] for r in rows if r[0] == region and r[1].startswith("prism")))
            for r in rows:
                if r[0] != region or r[1] != "Cycles":
                    continue
                parts = []
                for method in methods:
                    t = time_to_reach([(x[3], x[column]) for x in rows if x[0] == region and x[1] == method], r[column])
                    parts.append("%s %s" % (method.replace("prism ", ""), "not reached" if t is None else "%.2f" % (t / r[3])))
                print("  Cycles %5s spp: %.5f in %.2f s; %s" % (r[2], r[column], r[3], ", ".join(parts)))


def strip(work, halves, pair, efforts, cycles_spp, rect=CAUSTIC, name="surfaces_strip.png", labels=("prism path tracer, reference", "Cycles")):
    """bench/results/NAME: prism's reference | Cycles | 8x difference, then each method's
    picture at its second effort, with the rectangle `rect` (the caustic's) outlined."""
    try:
        from PIL import Image, ImageDraw
    except ImportError:
        return
    srgb = lambda v: int(255 * max(0.0, min(1.0, (12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055))) + 0.5)
    w, h = halves[0][0], halves[0][1]
    mean = lambda a, b: [(x + y) / 2 for x, y in zip(a[2], b[2])]
    p, c = mean(*halves), mean(*pair)

    def picture(values):
        img = Image.new("RGB", (w, h))
        img.putdata([tuple(srgb(values[3 * ((h - 1 - i // w) * w + i % w) + k]) for k in range(3)) for i in range(w * h)])
        return img

    cells = [(labels[0], picture(p)), (labels[1], picture(c)),
             ("8 x (prism - Cycles) + 0.5", picture([0.5 + 8 * (a - b) for a, b in zip(p, c)]))]
    for method, levels in efforts.items():
        effort = levels[min(1, len(levels) - 1)]
        cells.append(("%s %d" % (method, effort), picture(read_pfm(os.path.join(work, "%s_%d.pfm" % (method, effort)))[2])))
    cells.append(("Cycles %d spp" % cycles_spp[1], picture(read_pfm(os.path.join(work, "cycles_%d.pfm" % cycles_spp[1]))[2])))
    columns = 4
    rows = (len(cells) + columns - 1) // columns
    out = Image.new("RGB", (columns * w, rows * (h + 18)), (255, 255, 255))
    draw = ImageDraw.Draw(out)
    x0, x1, y0, y1 = rect
    for i, (label, img) in enumerate(cells):
        left, top = (i % columns) * w, (i // columns) * (h + 18)
        out.paste(img, (left, top + 18))
        draw.text((left + 4, top + 3), label, fill=(0, 0, 0))
        draw.rectangle([left + x0 * w, top + 18 + y0 * h, left + x1 * w, top + 18 + y1 * h], outline=(255, 255, 0))
    out.save(os.path.join(here, "results", name))


if __name__ == "__main__":
    sys.exit(main())
