#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Instructions a ray takes through a mesh, counted by valgrind's cachegrind: for each mesh,
kind of ray and query of bench_mesh_rays, the instructions of 2 passes of the rays less
those of 1 (the build and set-up cancel), over the rays. Deterministic where a time on a
shared machine wanders by 10 %; blind to cache misses, so it tells a leaner kernel, not a
faster one (bench_bvh_vs_embree tells that). With --vs OTHER, the same for another build of
bench_mesh_rays (a checkout before a change), and the ratio. With --embree, Embree's own
single-ray queries on the same rays too (bench_mesh_rays built with Embree; under valgrind
Embree runs its AVX2 kernels, since valgrind offers no AVX-512). Two counts run at a time.

  bench/mesh_instructions.py BENCH_MESH_RAYS BUNNY_OBJ [--vs OTHER] [--embree] [--out CSV]
"""
from concurrent.futures import ThreadPoolExecutor
import argparse
import csv
import re
import subprocess
import sys


def instructions(program, bunny, mesh, kind, query, passes):
    run = subprocess.run(["valgrind", "--tool=cachegrind", "--cache-sim=no", "--cachegrind-out-file=/dev/null", program, bunny, mesh, kind, query, str(passes)],
                         capture_output=True, text=True, check=True)
    refs = re.search(r"I\s+refs:\s+([\d,]+)", run.stderr)
    rays = re.search(r": (\d+) rays", run.stdout)
    if not refs or not rays:
        sys.exit(f"mesh_instructions: no count from {program} {mesh} {kind} {query}:\n{run.stdout}{run.stderr}")
    return int(refs.group(1).replace(",", "")), int(rays.group(1))


def per_ray(program, bunny, mesh, kind, query):
    one, rays = instructions(program, bunny, mesh, kind, query, 1)
    two, _ = instructions(program, bunny, mesh, kind, query, 2)
    return (two - one) / rays


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("program")
    parser.add_argument("bunny")
    parser.add_argument("--vs", help="another build of bench_mesh_rays, to compare with")
    parser.add_argument("--embree", action="store_true", help="count Embree's queries too (bench_mesh_rays built with Embree)")
    parser.add_argument("--out", default="bench/results/mesh_instructions.csv")
    args = parser.parse_args()
    combos = [(mesh, kind) for mesh in ("bunny", "sphere", "terrain") for kind in ("primary", "bounce", "shadow")]
    jobs = [(args.program, m, k, q) for m, k in combos for q in ("scene", "mesh")]
    if args.vs:
        jobs += [(args.vs, m, k, q) for m, k in combos for q in ("scene", "mesh")]
    if args.embree:
        jobs += [(args.program, m, k, "embree") for m, k in combos]
    with ThreadPoolExecutor(2) as pool:
        counts = dict(zip(jobs, pool.map(lambda j: per_ray(j[0], args.bunny, j[1], j[2], j[3]), jobs)))
    rows = []
    for mesh, kind in combos:
        e = counts.get((args.program, mesh, kind, "embree"), float("nan"))
        for query in ("scene", "mesh"):
            a = counts[(args.program, mesh, kind, query)]
            b = counts.get((args.vs, mesh, kind, query), float("nan"))
            rows.append((mesh, kind, query, a, b, e))
            line = f"{mesh:8} {kind:8} {query:6} {a:8.1f} instructions a ray"
            if args.vs:
                line += f", other {b:8.1f}, ratio {a / b:.3f}"
            if args.embree:
                line += f", Embree {e:8.1f}, prism/Embree {a / e:.3f}"
            print(line, flush=True)
    with open(args.out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["mesh", "rays", "query", "instructions_per_ray", "other_instructions_per_ray", "embree_instructions_per_ray"])
        for r in rows:
            w.writerow([r[0], r[1], r[2], f"{r[3]:.1f}"] + ["" if v != v else f"{v:.1f}" for v in r[4:]])
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
