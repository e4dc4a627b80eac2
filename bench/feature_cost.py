#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""What new features cost the scenes that do not use them: each gallery example of a
baseline tree (an earlier commit, e.g. a git worktree of the commit before an issue)
against the current tree. Compile time (g++ -O2, minimum of 2), size of the code
(.text), and render time at its default settings on one thread (runs interleaved,
baseline then current, 5 each; minimum and median ratio). The images must be identical.

    bench/feature_cost.py --baseline WORKTREE [--examples whitted,cornell,...] [--out bench/results]
"""
import argparse
import csv
import filecmp
import pathlib
import re
import statistics
import subprocess
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXAMPLES = ["whitted", "cornell", "csg_quadrics", "csg_figures", "cornell_caustics", "caustic_sphere"]


def build(tree, example, binary):
    """Compile time of the example's own file (the minimum of 2), then the program linked with
    the tree's shared example code (examples/cli.cpp and compare.cpp, where the tree has them:
    compiled here, not timed)."""
    flags = ["g++", "-std=c++20", "-O2", "-DNDEBUG", f"-I{tree / 'include'}", f"-I{tree / 'examples'}"]
    obj = binary.with_suffix(".o")
    seconds = []
    for _ in range(2):
        start = time.perf_counter()
        subprocess.run(flags + ["-c", str(tree / "examples" / f"{example}.cpp"), "-o", str(obj)], check=True)
        seconds.append(time.perf_counter() - start)
    support = [str(tree / "examples" / f) for f in ("cli.cpp", "compare.cpp") if (tree / "examples" / f).exists()]
    subprocess.run(flags + [str(obj)] + support + ["-o", str(binary), "-pthread"], check=True)
    size = subprocess.run(["size", "-A", str(binary)], check=True, capture_output=True, text=True).stdout
    return min(seconds), int(re.search(r"^\.text\s+(\d+)", size, re.M).group(1))


def render(binary, out):
    start = time.perf_counter()
    subprocess.run([str(binary), "--threads", "1", "--out", str(out)], check=True, capture_output=True)
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", required=True, help="the earlier source tree")
    parser.add_argument("--examples", default=",".join(EXAMPLES))
    parser.add_argument("--out", default=str(ROOT / "bench" / "results"))
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    baseline = pathlib.Path(args.baseline).resolve()
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        folder = pathlib.Path(folder)
        for example in args.examples.split(","):
            binaries, results = {}, {}
            for name, tree in (("baseline", baseline), ("current", ROOT)):
                binaries[name] = folder / f"{example}_{name}"
                results[name] = build(tree, example, binaries[name])
                (folder / name).mkdir(exist_ok=True)
            times = {"baseline": [], "current": []}
            for _ in range(args.repeats):
                for name in ("baseline", "current"):
                    times[name].append(render(binaries[name], folder / name))
            same = all(filecmp.cmp(p, folder / "current" / p.name, shallow=False) for p in (folder / "baseline").glob("*.png"))
            ratios = [c / b for b, c in zip(times["baseline"], times["current"])]
            row = {"example": example,
                   "compile_baseline_s": f"{results['baseline'][0]:.2f}", "compile_current_s": f"{results['current'][0]:.2f}",
                   "text_baseline": results["baseline"][1], "text_current": results["current"][1],
                   "render_min_ratio": f"{min(times['current']) / min(times['baseline']):.3f}",
                   "render_median_ratio": f"{statistics.median(ratios):.3f}", "images_identical": same}
            rows.append(row)
            print(f"{example}: compile {row['compile_baseline_s']} -> {row['compile_current_s']} s, .text {row['text_baseline']} -> "
                  f"{row['text_current']} bytes, render time current/baseline min {row['render_min_ratio']} median "
                  f"{row['render_median_ratio']}, images identical: {same}", flush=True)
            for p in (folder / "baseline").glob("*"):
                p.unlink()
            for p in (folder / "current").glob("*"):
                p.unlink()
    out = pathlib.Path(args.out) / "feature_cost.csv"
    out.parent.mkdir(parents=True, exist_ok=True)
    with open(out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
