#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Two builds of bench_mesh_rays (before and after a change), timed on the same rays in
interleaved runs (A B A B ...) pinned to one core with taskset: for each case, the best
rays/s of each and the median of the run-by-run ratios B/A. On a shared machine a single
time wanders by 10 %; pairing the runs cancels much of what moves both. Cases are
MESH:RAYS[:QUERY] (bunny|sphere|terrain, primary|bounce|shadow, mesh|scene|embree;
bench_mesh_rays' own arguments), the query the mesh alone unless given.

  bench/mesh_ab.py A B BUNNY_OBJ ROUNDS CASE... [--out CSV]
"""
import argparse
import csv
import re
import statistics
import subprocess
import sys


def rate(program, bunny, mesh, kind, query):
    """bench_mesh_rays' Mrays/s for one mesh, kind of ray and query, pinned to core 1."""
    out = subprocess.run(["taskset", "-c", "1", program, bunny, mesh, kind, query, "3"], capture_output=True, text=True, check=True).stdout
    found = re.search(r"([\d.]+) Mrays/s", out)
    if not found:
        sys.exit(f"no rate from {program} {mesh} {kind} {query}:\n{out}")
    return float(found.group(1))


def write_csv(path, rows):
    """rows (dicts with the same keys) as a CSV file at path."""
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("bunny")
    parser.add_argument("rounds", type=int)
    parser.add_argument("cases", nargs="+")
    parser.add_argument("--out")
    args = parser.parse_args()
    if args.rounds < 1:
        sys.exit(f"mesh_ab: rounds must be >= 1, got {args.rounds}")
    rows = []
    for case in args.cases:
        parts = case.split(":")
        if len(parts) not in (2, 3):
            sys.exit(f"mesh_ab: a case is MESH:RAYS[:QUERY], got '{case}'")
        mesh, kind, query = parts[0], parts[1], parts[2] if len(parts) == 3 else "mesh"
        a, b = [], []
        for _ in range(args.rounds):
            a.append(rate(args.a, args.bunny, mesh, kind, query))
            b.append(rate(args.b, args.bunny, mesh, kind, query))
        median = statistics.median(y / x for x, y in zip(a, b))
        print(f"{case:22s} A {max(a):6.2f}  B {max(b):6.2f} Mrays/s; B/A: best {max(b) / max(a):.3f}, median pair {median:.3f}", flush=True)
        rows.append({"case": case, "a_best_mrays": max(a), "b_best_mrays": max(b), "best_ratio": max(b) / max(a), "median_pair_ratio": median})
    if args.out:
        write_csv(args.out, rows)


if __name__ == "__main__":
    main()
