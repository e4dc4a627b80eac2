#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""prism's examples against POV-Ray 3.7 on the scenes in shared/scenes they mirror.

  cornell            shared/scenes/cornell_caustics.pov with Declare=PHOTONS=0
  csg_quadrics       shared/scenes/csg_quadrics.pov
  csg_quadrics_area  the same with `area_light <1.5, 0, 0>, <0, 0, 1.5>, 5, 5 adaptive 1` on
                     both lights (written here into a copy of the file): prism's PointGridLight

512 x 512, one sample per pixel (POV-Ray -A), 1 and 2 threads. The two are run
alternately, `--repeats` times each, and compared by render time without process
start: prism prints its render time (camera rays to finished film), POV-Ray its own
Trace Time. The minimum of the runs is kept (least disturbed by other load on a shared
machine). Also writes prism | POV-Ray | difference for each scene and reports how far
apart the pictures are. Output: vs_povray.csv.

With --baseline BUILD, an earlier build of prism (e.g. a worktree of the commit before a
change) runs in the same loop, and its time and ratio are reported beside the current
one's: a before/after comparison under the same load.

    bench/vs_povray.py [--build build/release] [--baseline BUILD] [--out bench/results] [--repeats 7] [--scenes A,B]
"""
import argparse
import csv
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


AREA_LIGHT = "area_light <1.5, 0, 0>, <0, 0, 1.5>, 5, 5 adaptive 1"


def with_area_lights(text):
    """The .pov text with AREA_LIGHT added to every one-line light_source { <p> color rgb c }."""
    out, count = re.subn(r"(light_source \{ *<[^>]*> *color rgb [0-9.]+) *\}", r"\1 " + AREA_LIGHT + " }", text)
    assert count == 2, "expected the two lights of csg_quadrics.pov"
    return out


SCENES = {  # example -> (POV-Ray scene file, extra POV-Ray arguments, rewrite of its text or None)
    "cornell": ("cornell_caustics.pov", ["Declare=PHOTONS=0"], None),
    "csg_quadrics": ("csg_quadrics.pov", [], None),
    "csg_quadrics_area": ("csg_quadrics.pov", [], with_area_lights),
}


def prism_time(binary, threads, folder):
    out = subprocess.run([binary, "--width", "512", "--height", "512", "--spp", "1", "--threads", str(threads),
                          "--out", folder], check=True, capture_output=True, text=True).stdout
    return float(re.search(r"render time ([0-9.]+) s", out).group(1))


def povray_time(scene, extra, threads, folder):
    run = subprocess.run(["povray", "-D", "+W512", "+H512", "-A", f"+WT{threads}", f"-I{scene}",
                          f"+O{folder}/povray.png", *extra], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("povray failed:\n" + run.stderr[-2000:])
    return float(re.search(r"Trace Time:.*\(([0-9.]+) seconds\)", run.stderr).group(1))


def find_scene(name):
    for folder in (ROOT.parent / "shared" / "scenes", ROOT / "bench" / "scenes"):
        if (folder / name).exists():
            return folder / name
    sys.exit(f"cannot find {name} (expected in ../shared/scenes)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build" / "release"))
    parser.add_argument("--out", default=str(ROOT / "bench" / "results"))
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--baseline", help="another prism build to time in the same runs (before/after a change)")
    parser.add_argument("--scenes", help="comma-separated: only these of " + ", ".join(SCENES))
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    rows = []
    for example, (pov_file, extra, rewrite) in SCENES.items():
        if args.scenes and example not in args.scenes.split(","):
            continue
        binary = pathlib.Path(args.build) / "examples" / example
        scene = find_scene(pov_file)
        with tempfile.TemporaryDirectory() as folder:
            if rewrite:
                rewritten = pathlib.Path(folder) / ("rewritten_" + pov_file)
                rewritten.write_text(rewrite(scene.read_text()))
                scene = rewritten
            for threads in (1, 2):
                prism_runs, pov_runs, base_runs = [], [], []
                for _ in range(args.repeats):
                    prism_runs.append(prism_time(binary, threads, folder))
                    pov_runs.append(povray_time(scene, extra, threads, folder))
                    if args.baseline:
                        with tempfile.TemporaryDirectory() as base_folder:
                            base_runs.append(prism_time(pathlib.Path(args.baseline) / "examples" / example, threads, base_folder))
                p, v = min(prism_runs), min(pov_runs)
                median = lambda runs: sorted(runs)[len(runs) // 2]
                rows.append({"scene": example, "threads": threads, "prism_seconds": p, "povray_trace_seconds": v, "ratio": p / v,
                             "prism_median": median(prism_runs), "povray_median": median(pov_runs)})
                print(f"{example} threads {threads}: prism {p:.4f} s, POV-Ray trace {v:.4f} s, prism/POV-Ray = {p / v:.2f}"
                      f" (medians {rows[-1]['prism_median']:.4f} / {rows[-1]['povray_median']:.4f})")
                if base_runs:
                    b = min(base_runs)
                    rows[-1].update({"baseline_seconds": b, "baseline_ratio": b / v, "baseline_median": median(base_runs)})
                    print(f"{example} threads {threads}: baseline {b:.4f} s, baseline/POV-Ray = {b / v:.2f}; current/baseline = "
                          f"{p / b:.3f} (min), {median(prism_runs) / median(base_runs):.3f} (median)")
            difference = compare(pathlib.Path(folder) / f"{example}.png", pathlib.Path(folder) / "povray.png",
                                 out / f"{example}_vs_povray_images.png")
            print(f"{example}: {difference}")

    if args.scenes and (out / "vs_povray.csv").exists():  # keep the scenes not run
        with open(out / "vs_povray.csv") as f:
            kept = [r for r in csv.DictReader(f) if r["scene"] not in args.scenes.split(",")]
        rows = kept + rows
    with open(out / "vs_povray.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(dict.fromkeys(k for r in rows for k in r)), restval="")
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {out / 'vs_povray.csv'}")


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
