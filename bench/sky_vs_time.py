#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Error against time under the photographed sky (bench/sky.cpp; Cycles' copy is
# bench/cycles_sky.py), for each of its three versions: `plain` (a white and a mirror
# sphere), `glossy` (rough metals, roughness 0.4 and 0.15) and `frosted` (frosted glass
# and rough metal), in one run on 2 threads:
#
# - prism's path tracer with Owen-scrambled Sobol points (its default) and with
#   independent samples, and Cycles, at the same samples per pixel;
# - each against prism's path-traced reference (two renders of --reference-spp with
#   different seeds; its own noise, from their difference, is taken out in quadrature).
#   bench/cycles_agreement.py --sky, --sky-glossy and --sky-frosted check that reference
#   against Cycles'.
# Each timed render is run --repeats times, interleaved (min and median kept).
#
# Writes bench/results/sky_vs_time.csv (region = the version); bench/plot.py draws
# sky_vs_time.png. Prints, for each Cycles picture, the time each prism sampler needs
# for its error as a ratio of Cycles' time.
#
# usage: bench/sky_vs_time.py BUILD_DIR [--size 256] [--reference-spp 2048] [--repeats 2]
#                             [--variants plain,glossy,frosted] [--levels 16,64,256,1024] [--quick]
import argparse
import csv
import os
import statistics
import subprocess

from cycles_agreement import cycles_sky
from methods_vs_time import COLUMNS, Scorer, read_pfm, time_to_reach, write_csv

here = os.path.dirname(os.path.abspath(__file__))


def prism_sky(build, spp, out, size, seed, variant, sampler, method="path"):
    """bench_sky's picture; the seconds it printed."""
    result = subprocess.run([os.path.join(build, "bench", "bench_sky"), out, str(spp), str(size), str(seed), variant, sampler, method],
                            capture_output=True, text=True, check=True)
    return float(result.stdout.split()[1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--reference-spp", type=int, default=2048, help="samples per pixel of each of the reference's two halves")
    ap.add_argument("--repeats", type=int, default=2)
    ap.add_argument("--variants", default="plain,glossy,frosted")
    ap.add_argument("--levels", default="16,64,256,1024", help="samples per pixel of the timed renders, comma-separated")
    ap.add_argument("--quick", action="store_true", help="small efforts (a smoke test of this script)")
    ap.add_argument("--methods", default="path,independent,cycles",
                    help="comma-separated, of path, independent, bdpt, vcm, cycles: re-run only these, keeping the CSV's other rows")
    args = ap.parse_args()
    methods = args.methods.split(",")
    labels = {"path": "prism path", "independent": "prism path:independent", "bdpt": "prism bdpt", "vcm": "prism vcm", "cycles": "Cycles"}
    work = os.path.join(args.build, "sky_vs_time")
    os.makedirs(work, exist_ok=True)
    levels = [4, 16, 64] if args.quick else [int(x) for x in args.levels.split(",")]
    reference_spp = 64 if args.quick else args.reference_spp
    rows = []
    for variant in args.variants.split(","):
        halves = []
        for seed in (101, 102):
            # (Kept from an earlier run of the same size and samples: the reference is the
            # path tracer's, which the methods re-run here do not change.)
            out = os.path.join(work, "%s_reference_%d_%d_%d.pfm" % (variant, seed, args.size, reference_spp))
            if not os.path.exists(out):
                prism_sky(args.build, reference_spp, out, args.size, seed, variant, "sobol")
            halves.append(read_pfm(out))
        score = Scorer(halves)
        print("%s: reference 2 x %d spp, its own noise %.5f (display range %.5f)" % (variant, reference_spp, score.noise, score.display_noise), flush=True)
        jobs = []
        for spp in levels:
            for method in methods:
                out = os.path.join(work, "%s_%s_%d.pfm" % (variant, method, spp))
                if method == "cycles":
                    jobs.append(("Cycles", spp, out, lambda spp=spp, out=out: cycles_sky(spp, out, 1, args.size, "" if variant == "plain" else variant)))
                else:
                    sampler, estimator = ("independent", "path") if method == "independent" else ("sobol", method)
                    jobs.append((labels[method], spp, out, lambda spp=spp, out=out, sampler=sampler, estimator=estimator: prism_sky(
                        args.build, spp, out, args.size, 1, variant, sampler, estimator)))
        times = [[] for _ in jobs]
        for _ in range(args.repeats):
            for job, seconds in zip(jobs, times):
                seconds.append(job[3]())
        for (method, spp, out, _), seconds in zip(jobs, times):
            rows.append((variant, method, spp, min(seconds), statistics.median(seconds)) + score(read_pfm(out)))
            print("%-8s %-24s %5d spp: %.3f s (median %.3f), RMSE %.5f, display range %.5f" % (variant, method, spp, rows[-1][3], rows[-1][4], rows[-1][5],
                                                                                          rows[-1][8]), flush=True)
    path = os.path.join(here, "results", "sky_vs_time.csv")
    redone = {labels[m] for m in methods}
    if os.path.exists(path):
        with open(path) as f:
            kept = [r for r in csv.DictReader(f) if r["region"] not in args.variants.split(",") or r["method"] not in redone]
        rows = [(r["region"], r["method"], int(r["effort"]), float(r["seconds"]), float(r["seconds_median"])) + tuple(float(r[k]) for k in COLUMNS)
                for r in kept] + rows
    write_csv(path, rows, "region")
    print("wrote", path)
    for column, name in ((5, "linear"), (8, "display range")):
        print("time to reach Cycles' error (%s RMSE), as a ratio of Cycles' time:" % name)
        for r in rows:
            if r[1] != "Cycles":
                continue
            parts = []
            for method in [m for m in ("prism path", "prism path:independent", "prism bdpt", "prism vcm") if any(x[1] == m for x in rows)]:
                t = time_to_reach([(x[3], x[column]) for x in rows if x[0] == r[0] and x[1] == method], r[column])
                parts.append("%s %s" % (method.replace("prism ", ""), "not reached" if t is None else "%.2f" % (t / r[3])))
            print("  %-8s Cycles %5d spp: %.5f in %.2f s; %s" % (r[0], r[2], r[column], r[3], ", ".join(parts)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
