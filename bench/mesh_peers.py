#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""What each lever is worth to Embree itself: bench_mesh_rays' queries on the same rays,
interleaved round by round and pinned to one core with taskset, for every mesh and kind of
ray. The queries are prism's mesh alone (`mesh`), Embree as it comes (`embree`), Embree with
its high-quality build (spatial splits, `embree-hq`), with its watertight and conservative
mode (`embree-robust`) and with eight rays a packet (`embree8`). Each row gives a query's
best and median rays/s and the median of its run-by-run ratios to `embree` in the same round.

  bench/mesh_peers.py BENCH_MESH_RAYS BUNNY_OBJ ROUNDS [--out CSV] [--queries Q,Q,...]
  bench/mesh_peers.py --plot CSV PNG     (the chart of a run's ratios, with matplotlib)
"""
import argparse
import csv
import statistics
import sys

from mesh_ab import rate, write_csv


def plot(csv_path, png_path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    cells = list(dict.fromkeys((r["mesh"], r["rays"]) for r in rows))
    queries = list(dict.fromkeys(r["query"] for r in rows))
    ratio = {(r["mesh"], r["rays"], r["query"]): float(r["median_ratio_to_embree"]) for r in rows}
    labels = {"mesh": "prism (TriangleMesh alone)", "embree": "Embree as it comes", "embree-hq": "Embree, high-quality build (spatial splits)",
              "embree-robust": "Embree, robust (watertight, conservative)", "embree8": "Embree, 8-ray packets"}
    fig, ax = plt.subplots(figsize=(11, 4.2))
    width = 0.8 / len(queries)
    for j, q in enumerate(queries):
        ax.bar([i + (j - (len(queries) - 1) / 2) * width for i in range(len(cells))], [ratio[(m, k, q)] for m, k in cells], width, label=labels.get(q, q))
    ax.axhline(1.0, color="black", linewidth=0.8)
    ax.set_xticks(range(len(cells)), [f"{m}\n{k}" for m, k in cells])
    ax.set_ylabel("rays/s ÷ Embree's (median of pairs)")
    ax.set_title("What each lever is worth to Embree itself, and where prism stands (1 thread, pinned)")
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "--plot":
        return plot(sys.argv[2], sys.argv[3])
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("program")
    parser.add_argument("bunny")
    parser.add_argument("rounds", type=int)
    parser.add_argument("--out")
    parser.add_argument("--queries", default="mesh,embree,embree-hq,embree-robust,embree8")
    parser.add_argument("--meshes", default="bunny,sphere,terrain")
    args = parser.parse_args()
    if args.rounds < 1:
        sys.exit(f"mesh_peers: rounds must be >= 1, got {args.rounds}")
    queries = args.queries.split(",")
    if "embree" not in queries:
        sys.exit("mesh_peers: --queries must include embree (the ratios' denominator)")
    rows = []
    for mesh in args.meshes.split(","):
        for kind in ("primary", "bounce", "shadow"):
            rates = {q: [] for q in queries}
            for _ in range(args.rounds):
                for q in queries:
                    rates[q].append(rate(args.program, args.bunny, mesh, kind, q))
            line = [f"{mesh:8s} {kind:8s}"]
            for q in queries:
                ratio = statistics.median(x / e for x, e in zip(rates[q], rates["embree"]))
                rows.append({"mesh": mesh, "rays": kind, "query": q, "best_mrays": max(rates[q]), "median_mrays": statistics.median(rates[q]),
                             "median_ratio_to_embree": ratio})
                line.append(f"{q} {statistics.median(rates[q]):6.2f} ({ratio:.2f})")
            print("  ".join(line), flush=True)
    if args.out:
        write_csv(args.out, rows)


if __name__ == "__main__":
    main()
