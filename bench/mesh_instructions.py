#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Instructions a ray takes through a mesh, counted by valgrind's cachegrind: for each mesh,
kind of ray and query of bench_mesh_rays, the instructions of 2 passes of the rays less
those of 1 (the build and set-up cancel), over the rays. Deterministic where a time on a
shared machine wanders by 10 %; blind to cache misses, so it tells a leaner kernel, not a
faster one (bench_bvh_vs_embree tells that). With --vs OTHER, the same for another build of
bench_mesh_rays (a checkout before a change), and the ratio.

  bench/mesh_instructions.py BENCH_MESH_RAYS BUNNY_OBJ [--vs OTHER] [--out CSV]
"""
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
    parser.add_argument("--out", default="bench/results/mesh_instructions.csv")
    args = parser.parse_args()
    rows = []
    for mesh in ("bunny", "sphere", "terrain"):
        for kind in ("primary", "bounce", "shadow"):
            for query in ("scene", "mesh"):
                a = per_ray(args.program, args.bunny, mesh, kind, query)
                b = per_ray(args.vs, args.bunny, mesh, kind, query) if args.vs else float("nan")
                rows.append((mesh, kind, query, a, b))
                line = f"{mesh:8} {kind:8} {query:6} {a:8.1f} instructions a ray"
                if args.vs:
                    line += f", other {b:8.1f}, ratio {a / b:.3f}"
                print(line, flush=True)
    with open(args.out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["mesh", "rays", "query", "instructions_per_ray", "other_instructions_per_ray"])
        for r in rows:
            w.writerow([r[0], r[1], r[2], f"{r[3]:.1f}", "" if r[4] != r[4] else f"{r[4]:.1f}"])
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
