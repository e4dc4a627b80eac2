#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Issue 36's foggy scene (bench/fog.cpp: a spot light through haze onto a rough glass
# ball, which focuses it into a volumetric caustic; Cycles' copy is bench/cycles_fog.py),
# in one run on 2 threads:
#
# 1. Two references, each of two renders with different seeds (the RMSE between them
#    measures its own noise, which is taken out of every error in quadrature): Cycles at
#    --reference-spp, and prism's progressive photon mapping at --reference-passes. Cycles
#    cannot converge the volumetric caustic (its paths through the glass find the spot
#    light only by light samples refracted out of a rough ball; at 4096 samples a pixel
#    the caustic's noise is ten times its radiance), so the errors below the reference's
#    noise are measured against prism's; both are written.
# 2. Agreement, of each pair of means (prism's path tracer, prism's progressive photon
#    mapping, Cycles): the RMSE between them against what their noise explains (a ratio
#    near 1 is agreement within the noise), and the ratio of their mean radiances, over
#    the picture and over the volumetric caustic.
# 3. Error against time: prism's path tracer, its photon mapper read directly (photons),
#    progressive photon mapping (passes), and Cycles (samples per pixel), over the whole
#    picture and over the volumetric caustic (a rectangle of the air below the ball). Each
#    timed render is run --repeats times, interleaved (min and median kept).
#
# Writes bench/results/fog_vs_time.csv, fog_agreement.csv and fog_strip.png; bench/plot.py
# draws fog_vs_time.png.
#
# The path tracer runs twice: with Owen-scrambled Sobol points (path, prism's default) and
# with independent samples (path:independent).
#
# usage: bench/fog_vs_time.py BUILD_DIR [--width 160] [--reference-spp 4096] [--reference-passes 1024] [--agreement-spp 4096]
#                             [--methods path,path:independent,...] [--cycles-levels 16,64,256,1024]
#                             [--repeats 2] [--quick] [--reuse-cycles-reference]
import argparse
import csv
import functools
import os
import statistics
import subprocess
import sys

from methods_vs_time import Scorer, bench_render, cycles_script_render, read_pfm, rectangle_mask, write_csv, write_pfm
from surfaces_vs_time import agreement, strip, summary, tagged

here = os.path.dirname(os.path.abspath(__file__))

# The volumetric caustic's rectangle, as fractions of the picture (x from the left, y from the top).
CAUSTIC = (0.44, 0.56, 0.58, 0.76)


def caustic_mask(w, h):
    """Per value: True inside the caustic's rectangle."""
    return rectangle_mask(w, h, CAUSTIC)


prism_render = functools.partial(bench_render, "bench_fog")
cycles_render = functools.partial(cycles_script_render, "cycles_fog.py")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--width", type=int, default=160)
    ap.add_argument("--reference-spp", type=int, default=4096, help="samples per pixel of each of Cycles' two reference renders")
    ap.add_argument("--reference-passes", type=int, default=1024, help="passes of each of prism's two progressive reference renders")
    ap.add_argument("--agreement-spp", type=int, default=4096, help="of each of prism's two path-traced renders for the agreement")
    ap.add_argument("--repeats", type=int, default=2)
    ap.add_argument("--quick", action="store_true", help="small efforts (a smoke test of this script)")
    ap.add_argument("--methods", help="a comma-separated subset of prism's methods (path, path:independent (independent samples), direct, ...)")
    ap.add_argument("--cycles-levels", help="Cycles' samples per pixel, comma-separated (16,64,256,1024)")
    ap.add_argument("--tag", default="", help="written to bench/results/NAME_TAG.csv and .png instead of NAME.csv, so that a run of a few methods keeps the full run's files")
    ap.add_argument("--reuse-cycles-reference", action="store_true", help="keep Cycles' reference renders already in BUILD_DIR/fog_vs_time")
    ap.add_argument("--reference-method", default="progressive", choices=("progressive", "vcm"),
                    help="prism's reference: progressive photon mapping (biased at the sharpest caustics until very many passes), "
                         "or vertex connection and merging (unbiased but for its merges); --reference-passes each of two renders")
    ap.add_argument("--rescore", action="store_true",
                    help="no timed renders: score those already in BUILD_DIR/fog_vs_time against the references, their times from the CSV")
    ap.add_argument("--reuse-prism-references", action="store_true",
                    help="keep prism's path-traced and progressive renders for the agreement and reference already in BUILD_DIR/fog_vs_time (with their times)")
    args = ap.parse_args()
    work = os.path.join(args.build, "fog_vs_time")
    os.makedirs(work, exist_ok=True)
    efforts = {"path": [64, 256, 1024, 4096], "path:independent": [64, 256, 1024, 4096], "direct": [100000, 300000, 1000000, 3000000],
               "progressive": [16, 64, 256], "bdpt": [16, 64, 256, 1024], "vcm": [16, 64, 256, 1024]}
    cycles_spp = [16, 64, 256, 1024]
    if args.methods:
        efforts = {m: e for m, e in efforts.items() if m in args.methods.split(",")}
    if args.cycles_levels:
        cycles_spp = [int(x) for x in args.cycles_levels.split(",")]
    if args.quick:
        efforts = {m: e[:2] for m, e in efforts.items()}
        cycles_spp = cycles_spp[:2]
        args.reference_spp, args.agreement_spp, args.reference_passes = 64, 64, 8
    pairs, seconds = {}, {}
    # Cycles' reference.
    pair, seconds["Cycles"] = [], 0.0
    for seed in (101, 102):
        out = os.path.join(work, "reference_%d.pfm" % seed)
        if args.reuse_cycles_reference and os.path.exists(out):
            with open(out + ".txt") as f:
                seconds["Cycles"] += float(f.read().splitlines()[1].split(",")[1])
        else:
            seconds["Cycles"] += cycles_render(args.reference_spp, out, args.width, seed)
        pair.append(read_pfm(out))
    pairs["Cycles"] = pair
    # prism's: the path tracer and the reference (progressive photon mapping or VCM), two seeds each.
    ref = args.reference_method
    for method, effort in (("path", args.agreement_spp), (ref, args.reference_passes)):
        pair, seconds[method] = [], 0.0
        for seed in (1, 2):
            out = os.path.join(work, "agreement_%s_%d.pfm" % (method, seed))
            if args.reuse_prism_references and os.path.exists(out) and os.path.exists(out + ".seconds"):
                with open(out + ".seconds") as f:
                    seconds[method] += float(f.read())
            else:
                took = prism_render(args.build, method, effort, out, args.width, seed)
                with open(out + ".seconds", "w") as f:
                    f.write("%.4f\n" % took)
                seconds[method] += took
            pair.append(read_pfm(out))
        pairs[method] = pair
    labels = {"Cycles": "Cycles %d spp x 2" % args.reference_spp, "path": "prism path %d spp x 2" % args.agreement_spp,
              ref: "prism %s %d passes x 2" % (ref, args.reference_passes)}
    w, h = pairs["Cycles"][0][0], pairs["Cycles"][0][1]
    masks = {"all": None, "caustic": caustic_mask(w, h)}
    with open(os.path.join(here, "results", tagged("fog_agreement.csv", args.tag)), "w", newline="") as f:
        table = csv.writer(f)
        table.writerow(["first", "second", "region", "range", "first_seconds", "second_seconds", "noise_first", "noise_second", "rmse_between",
                        "rmse_from_noise", "mean_ratio"])
        for a, b in (("path", "Cycles"), (ref, "Cycles"), (ref, "path")):
            for region, mask in masks.items():
                for display in (False, True):
                    st = agreement(pairs[a], pairs[b], mask, display)
                    print("agreement, %s (%.1f s) against %s (%.1f s), %s, %s: noise of the means %.5f and %.5f; RMSE between %.5f, noise explains %.5f "
                          "(ratio %.3f); mean ratio %.5f" % (labels[a], seconds[a], labels[b], seconds[b], region, "display range" if display else "linear",
                                                             st[0], st[1], st[2], st[3], st[2] / st[3], st[4]), flush=True)
                    table.writerow([labels[a], labels[b], region, "display" if display else "linear", "%.2f" % seconds[a], "%.2f" % seconds[b]] +
                                   ["%.6f" % v for v in st])
    for name in ("Cycles", ref):
        write_pfm(os.path.join(work, "reference_%s.pfm" % name), (w, h, [(a + b) / 2 for a, b in zip(pairs[name][0][2], pairs[name][1][2])]))
    scorers = {(reference, region): Scorer(pairs[reference], mask) for reference in (ref, "Cycles") for region, mask in masks.items()}
    for (reference, region), scorer in scorers.items():
        print("reference %s, %s: its own noise %.5f (display range %.5f)" % (labels[reference], region, scorer.noise, scorer.display_noise), flush=True)
    # Every method's renders, timed in interleaved rounds.
    jobs = []
    for method, levels in efforts.items():
        for effort in levels:
            out = os.path.join(work, "%s_%d.pfm" % (method, effort))
            jobs.append(("prism " + method, effort, out, functools.partial(prism_render, args.build, method, effort, out, args.width)))
    for spp in cycles_spp:
        out = os.path.join(work, "cycles_%d.pfm" % spp)
        jobs.append(("Cycles", spp, out, functools.partial(cycles_render, spp, out, args.width)))
    times = [[] for _ in jobs]
    if args.rescore:
        # The times of the last timed run of every method (its CSV, untagged), by method and effort.
        with open(os.path.join(here, "results", "fog_vs_time_cycles.csv")) as f:
            timed = {(r["method"], r["effort"]): (float(r["seconds"]), float(r["seconds_median"])) for r in csv.DictReader(f)}
        jobs = [job for job in jobs if (job[0], str(job[1])) in timed]
        times = [[timed[(job[0], str(job[1]))][0]] + 2 * [timed[(job[0], str(job[1]))][1]] for job in jobs]  # (min and median kept)
    else:
        for _ in range(args.repeats):
            for job, took in zip(jobs, times):
                took.append(job[3]())
    rows = {ref: [], "Cycles": []}
    for (method, effort, out, _), took in zip(jobs, times):
        image = read_pfm(out)
        for (reference, region), scorer in scorers.items():
            rows[reference].append((region, method, effort, min(took), statistics.median(took)) + scorer(image))
            r = rows[reference][-1]
            print("against %-11s %-8s %-18s %8s: %.3f s (median %.3f), RMSE %.5f, display range %.5f" % (reference, region, method, effort, r[3], r[4], r[5], r[8]),
                  flush=True)
    for reference, name in ((ref, tagged("fog_vs_time.csv", args.tag)), ("Cycles", tagged("fog_vs_time_cycles.csv", args.tag))):
        path = os.path.join(here, "results", name)
        write_csv(path, rows[reference], "region")
        print("wrote", path)
        print("against %s:" % labels[reference])
        summary(rows[reference])
    strip(work, pairs[ref], pairs["Cycles"], efforts, cycles_spp, rect=CAUSTIC, name=tagged("fog_strip.png", args.tag),
          labels=(labels[ref], labels["Cycles"]))


if __name__ == "__main__":
    sys.exit(main())
