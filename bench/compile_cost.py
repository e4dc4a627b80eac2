#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""What a scene pays for its materials: the Cornell box with glass and mirror spheres
(bench/scene_full.cpp) against the same box with diffuse spheres
(bench/scene_diffuse_only.cpp), whose Whitted integrator compiles no reflection or
refraction code. Compile time (g++ -O2, minimum of 3), size of the code (.text),
render time (512 x 512, 1 spp, one thread, minimum of 5).

    bench/compile_cost.py [--out bench/results]
"""
import argparse
import csv
import pathlib
import re
import subprocess
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "bench" / "results"))
    parser.add_argument("--cxx", default="g++")
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for variant in ("scene_diffuse_only", "scene_full"):
            binary = pathlib.Path(folder) / variant
            command = [args.cxx, "-std=c++20", "-O2", "-DNDEBUG", "-DGLM_FORCE_PURE", f"-I{ROOT / 'include'}",
                       f"-I{ROOT / 'examples'}", str(ROOT / "bench" / f"{variant}.cpp"), "-o", str(binary), "-pthread"]
            seconds = []
            for _ in range(3):
                start = time.perf_counter()
                subprocess.run(command, check=True)
                seconds.append(time.perf_counter() - start)
            size = subprocess.run(["size", "-A", str(binary)], check=True, capture_output=True, text=True).stdout
            text = int(re.search(r"^\.text\s+(\d+)", size, re.M).group(1))
            run = subprocess.run([str(binary)], check=True, capture_output=True, text=True).stdout
            render = float(re.search(r"render_seconds ([0-9.]+)", run).group(1))
            rows.append({"variant": variant, "compile_seconds": min(seconds), "text_bytes": text, "render_seconds": render})
            print(f"{variant:20s} compile {min(seconds):6.2f} s   .text {text:7d} bytes   render {render:.4f} s")
    full, diffuse = rows[1], rows[0]
    print(f"diffuse-only / full: compile {diffuse['compile_seconds'] / full['compile_seconds']:.2f}, "
          f".text {diffuse['text_bytes'] / full['text_bytes']:.2f}, render {diffuse['render_seconds'] / full['render_seconds']:.2f}")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "compile_cost.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {out / 'compile_cost.csv'}")


if __name__ == "__main__":
    main()
