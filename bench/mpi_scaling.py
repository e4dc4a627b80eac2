#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""MPI rendering on this machine, and a model of it on many.

The photon-mapped Cornell box (cornell_caustics' scene, --method gather) rendered, in
interleaved rounds, by
  one    cornell_caustics in one process, 1 thread
  one2   cornell_caustics in one process, 2 threads
  mpi1   mpi_render on 1 rank, 1 thread (MPI's own cost)
  mpi2   mpi_render on 2 ranks, 1 thread each
each time from the start of photon tracing to the finished image (the programs' own
"total"). Speed-up at 2 ranks = one / mpi2 (min and median over the rounds).

The model: from the 1-rank run's stages (trace, trees, irradiance, render) and the
2-rank run's traffic (photon bytes all-gathered, film bytes gathered),
    T(P) = (trace + irradiance + render) / P + trees
           + (photons + film) (P - 1) / P / bandwidth + latency log2(P)
(every rank builds every tree: that part does not shrink), on a network of `bandwidth`
(10 Gbit/s Ethernet, 1.25 GB/s, and 100 Gbit/s InfiniBand, 12.5 GB/s) with 50 us per
message step. Memory per rank: the whole photon maps, whatever P. Writes
mpi_scaling.csv (measured runs), mpi_scaling_model.csv and mpi_scaling.png.

    bench/mpi_scaling.py [--build build/release] [--out bench/results] [--repeats 3]
"""
import argparse
import csv
import math
import os
import pathlib
import re
import statistics
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
SCENE = ["--width", "192", "--height", "192", "--spp", "4", "--method", "gather", "--gather", "32",
         "--photons", "500000", "--caustic-photons", "500000"]
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1", "OMPI_MCA_btl": "self,vader,tcp",
           "OMPI_MCA_btl_tcp_if_include": "lo", "OMPI_MCA_oob_tcp_if_include": "lo",
           "OMPI_MCA_btl_vader_single_copy_mechanism": "none"}
NETWORKS = {"10 Gbit/s Ethernet": 1.25e9, "100 Gbit/s InfiniBand": 12.5e9}
LATENCY = 50e-6


def run(command, folder):
    env = dict(os.environ, **MPI_ENV)
    return subprocess.run(command + ["--out", folder], check=True, capture_output=True, text=True, env=env).stdout


def total(text):
    return float(re.search(r"total ([0-9.]+) s", text).group(1))


def rank_lines(text):
    """Per rank: bytes and stage seconds, as mpi_render prints them."""
    ranks = []
    for line in text.splitlines():
        m = re.search(r"rank (\d+): photons sent (\d+) B, received (\d+) B; film (\d+) B; (\d+) tiles; trace ([0-9.]+) s, photon gather ([0-9.]+) s, "
                      r"trees ([0-9.]+) s, irradiance ([0-9.]+) s, render ([0-9.]+) s, film gather ([0-9.]+) s", line)
        if m:
            keys = ["rank", "sent", "received", "film", "tiles", "trace", "photon_gather", "trees", "irradiance", "render", "film_gather"]
            ranks.append(dict(zip(keys, map(float, m.groups()))))
    return ranks


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build/release"))
    parser.add_argument("--out", default=str(ROOT / "bench/results"))
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    examples = pathlib.Path(args.build) / "examples"
    single, mpi = str(examples / "cornell_caustics"), str(examples / "mpi_render")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    commands = {
        "one": [single] + SCENE + ["--threads", "1"],
        "one2": [single] + SCENE + ["--threads", "2"],
        "mpi1": ["mpirun", "--oversubscribe", "-np", "1", mpi] + SCENE + ["--threads", "1"],
        "mpi2": ["mpirun", "--oversubscribe", "-np", "2", mpi] + SCENE + ["--threads", "1"],
    }
    times = {k: [] for k in commands}
    texts = {}
    with tempfile.TemporaryDirectory() as folder:
        for _ in range(args.repeats):
            for name, command in commands.items():
                texts[name] = run(command, folder)
                times[name].append(total(texts[name]))
                print(f"{name:5s} {times[name][-1]:.3f} s", flush=True)
    with open(out / "mpi_scaling.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["run", "round", "seconds"])
        for name, ts in times.items():
            for i, t in enumerate(ts):
                w.writerow([name, i, f"{t:.4f}"])
    best = {k: min(v) for k, v in times.items()}
    med = {k: statistics.median(v) for k, v in times.items()}
    print(f"speed-up at 2 ranks (one process, 1 thread / 2 ranks): min {best['one'] / best['mpi2']:.2f}, median {med['one'] / med['mpi2']:.2f}")
    print(f"2 threads in one process:                            min {best['one'] / best['one2']:.2f}, median {med['one'] / med['one2']:.2f}")
    print(f"MPI's cost on 1 rank (mpi1 / one):                   min {best['mpi1'] / best['one']:.3f}, median {med['mpi1'] / med['one']:.3f}")

    one_rank, two_ranks = rank_lines(texts["mpi1"])[0], rank_lines(texts["mpi2"])
    photons = sum(r["sent"] for r in two_ranks)  # each rank's share, sent to the other: the whole maps and irradiance
    tiles = sum(r["tiles"] for r in two_ranks)
    film = two_ranks[1]["film"] / two_ranks[1]["tiles"] * tiles  # every tile's sums (rank 1 sent its own)
    parallel = one_rank["trace"] + one_rank["irradiance"] + one_rank["render"]
    print(f"1 rank's stages: trace {one_rank['trace']:.3f} s, trees {one_rank['trees']:.3f} s (every rank), irradiance {one_rank['irradiance']:.3f} s, "
          f"render {one_rank['render']:.3f} s ({one_rank['render'] / tiles * 1e3:.2f} ms a tile of {int(tiles)})")
    print(f"traffic: photon maps and irradiance {photons / 1e6:.1f} MB all-gathered (each rank holds them all), film {film / 1e6:.2f} MB to rank 0")
    model_rows = []
    for network, bandwidth in NETWORKS.items():
        base = None
        for p in [1, 2, 4, 8, 16, 32, 64, 128, 256]:
            t = parallel / p + one_rank["trees"] + photons * (p - 1) / p / bandwidth + film * (p - 1) / p / bandwidth + LATENCY * math.log2(p)
            base = base or t
            model_rows.append([network, p, t, base / t, base / t / p])
        half = next((row[1] for row in model_rows if row[0] == network and row[4] < 0.5), None)
        ceiling = (parallel + one_rank["trees"]) / (one_rank["trees"] + photons / bandwidth + film / bandwidth)
        print(f"model, {network}: speed-up at 64 ranks {next(r[3] for r in model_rows if r[0] == network and r[1] == 64):.1f}, "
              f"efficiency below 50 % from {half} ranks, ceiling {ceiling:.1f} (trees and traffic)")
    with open(out / "mpi_scaling_model.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["network", "ranks", "seconds", "speedup", "efficiency"])
        w.writerows(model_rows)

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib (Debian: python3-matplotlib): no chart")
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ps = [1, 2, 4, 8, 16, 32, 64, 128, 256]
    ax.plot(ps, ps, ":", color="grey", label="ideal")
    for network in NETWORKS:
        rows = [r for r in model_rows if r[0] == network]
        ax.plot([r[1] for r in rows], [r[3] for r in rows], "-o", markersize=3, label=f"model, {network}")
    ax.plot([1, 2], [best["one"] / best["mpi1"], best["one"] / best["mpi2"]], "ks", label="measured here (min of runs)")
    ax.plot([2], [med["one"] / med["mpi2"]], "kx", label="measured here (median)")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log", base=2)
    ax.set_xlabel("MPI ranks (one core each)")
    ax.set_ylabel("speed-up over one process, one thread")
    ax.set_title("Photon-mapped Cornell box, 192², 10⁶ photons: MPI scaling")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "mpi_scaling.png", dpi=110)
    print(f"wrote {out / 'mpi_scaling.png'}")


if __name__ == "__main__":
    main()
