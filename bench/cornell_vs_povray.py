#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""prism's `cornell` example against POV-Ray 3.7 on shared/scenes/cornell_caustics.pov.

Same picture (Declare=PHOTONS=0), 512 x 512, one sample per pixel (POV-Ray -A), 1 and 2
threads. The two are run alternately, `--repeats` times each, and compared by render
time without process start: prism prints its render time (camera rays to finished
film), POV-Ray its own Trace Time. The minimum of the runs is kept (least disturbed by
other load on a shared machine). Also reports how far apart the two pictures are.

    bench/cornell_vs_povray.py [--build build/release] [--out bench/results] [--repeats 7]
"""
import argparse
import csv
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def prism_time(binary, threads, folder):
    out = subprocess.run([binary, "--width", "512", "--height", "512", "--spp", "1", "--threads", str(threads),
                          "--out", folder], check=True, capture_output=True, text=True).stdout
    return float(re.search(r"render time ([0-9.]+) s", out).group(1))


def povray_time(scene, threads, folder):
    run = subprocess.run(["povray", "-D", "+W512", "+H512", "-A", f"+WT{threads}", f"-I{scene}",
                          f"+O{folder}/povray.png", "Declare=PHOTONS=0"], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("povray failed:\n" + run.stderr[-2000:])
    return float(re.search(r"Trace Time:.*\(([0-9.]+) seconds\)", run.stderr).group(1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build" / "release"))
    parser.add_argument("--out", default=str(ROOT / "bench" / "results"))
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    binary = pathlib.Path(args.build) / "examples" / "cornell"
    scene = ROOT.parent / "shared" / "scenes" / "cornell_caustics.pov"
    if not scene.exists():
        scene = ROOT / "bench" / "scenes" / "cornell_caustics.pov"
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for threads in (1, 2):
            prism_runs, pov_runs = [], []
            for _ in range(args.repeats):
                prism_runs.append(prism_time(binary, threads, folder))
                pov_runs.append(povray_time(scene, threads, folder))
            p, v = min(prism_runs), min(pov_runs)
            rows.append({"threads": threads, "prism_seconds": p, "povray_trace_seconds": v, "ratio": p / v,
                         "prism_median": sorted(prism_runs)[len(prism_runs) // 2],
                         "povray_median": sorted(pov_runs)[len(pov_runs) // 2]})
            print(f"threads {threads}: prism {p:.4f} s, POV-Ray trace {v:.4f} s, prism/POV-Ray = {p / v:.2f}"
                  f" (medians {rows[-1]['prism_median']:.4f} / {rows[-1]['povray_median']:.4f})")
        difference = compare(pathlib.Path(folder) / "cornell.png", pathlib.Path(folder) / "povray.png",
                             out / "cornell_vs_povray_images.png")

    with open(out / "cornell_vs_povray.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {out / 'cornell_vs_povray.csv'}")
    if difference:
        print(difference)


def compare(prism_png, povray_png, side_by_side):
    """Mean absolute difference of the two 8-bit pictures, and a prism | POV-Ray | |diff| x4 picture."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.image as mpimg
        import numpy as np
    except ImportError:
        return "images not compared: matplotlib is missing (tools/setup.sh --bench)"
    a = mpimg.imread(prism_png)[..., :3]
    b = mpimg.imread(povray_png)[..., :3]
    diff = np.abs(a - b)
    mean = 255 * diff.mean()
    far = (255 * diff.max(axis=2) > 16).mean()
    mpimg.imsave(side_by_side, np.concatenate([a, b, np.clip(4 * diff, 0, 1)], axis=1))
    return (f"picture difference: mean |prism - POV-Ray| = {mean:.2f} of 255, "
            f"{100 * far:.2f}% of pixels differ by more than 16; wrote {side_by_side}")


if __name__ == "__main__":
    main()
