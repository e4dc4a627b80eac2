#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""What compiling costs, and what a scene pays for its materials.

    bench/compile_cost.py --translation-units [--units A,B] [--include DIR] [--label NAME]
        CPU seconds and peak memory of the compiler (g++ and clang++-19, -O2) for each
        example, the newcomer's two scenes (bench/newcomer_box.cpp: an area-lit Cornell box
        with a GGX and a glass sphere, path-traced; bench/newcomer_fog.cpp: the same in fog
        by progressive photon mapping) and each test file: results/compile_cost_units.csv
        (rows appended, labelled, so that a run on another checkout's include/ sits beside
        this one).

What a scene pays for its materials: the Cornell box with glass and mirror spheres
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


def compile_units(args):
    """Each example and test file compiled alone (no precompiled header), g++ and clang."""
    include = pathlib.Path(args.include or ROOT / "include")
    units = (sorted((ROOT / "examples").glob("*.cpp")) + sorted((ROOT / "bench").glob("newcomer_*.cpp")) +
             sorted(p for p in (ROOT / "tests").glob("*/*.cpp") if p.parent.name not in ("fuzz",)))
    units = [u for u in units if u.name not in ("mpi_render.cpp",) and u.relative_to(ROOT).as_posix() not in ("tests/io/exr.cpp", "tests/io/mesh.cpp")]
    if args.units:
        units = [u for u in units if u.relative_to(ROOT).as_posix() in args.units.split(",")]
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    path = out / "compile_cost_units.csv"
    new_file = not path.exists()
    with open(path, "a", newline="") as f:
        writer = csv.writer(f)
        if new_file:
            writer.writerow(["label", "compiler", "unit", "cpu_seconds", "peak_mb"])
        for compiler in ("g++", "clang++-19"):
            for unit in units:
                command = ["/usr/bin/time", "-f", "%U %S %M", compiler, "-std=c++20", "-O2", "-DNDEBUG", "-DGLM_FORCE_PURE",
                           f"-I{include}", f"-I{ROOT / 'examples'}", f"-DPRISM_TEST_ASSETS=\"{ROOT / 'assets'}\"",
                           f"-DPRISM_ASSET_DIR=\"{ROOT / 'assets'}\"", "-c", str(unit), "-o", "/dev/null"]
                run = subprocess.run(command, capture_output=True, text=True)
                user, system, peak = run.stderr.strip().splitlines()[-1].split()
                if run.returncode != 0:
                    print(f"{compiler} {unit.relative_to(ROOT)}: does not compile")
                    continue
                row = [args.label, compiler, unit.relative_to(ROOT).as_posix(), f"{float(user) + float(system):.2f}", f"{int(peak) / 1024:.0f}"]
                writer.writerow(row)
                f.flush()
                print(" ".join(row))
    print(f"wrote {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "bench" / "results"))
    parser.add_argument("--cxx", default="g++")
    parser.add_argument("--translation-units", action="store_true")
    parser.add_argument("--include", help="the include/ folder to compile against (default: this checkout's)")
    parser.add_argument("--label", default="this checkout")
    parser.add_argument("--units", help="only these, comma-separated (e.g. examples/whitted.cpp)")
    args = parser.parse_args()
    if args.translation_units:
        return compile_units(args)
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
