#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""What a scene of many *different* types costs: bench/many_types.cpp compiled for S = 1
to 1024 distinct slot types (g++ -O2: CPU seconds and peak memory of the compiler), and
run for N = S to 10^5 spheres spread over those types, against the same N spheres in one
ObjectArray (ns per closest-hit and per shadow query). CSV and a chart.

    bench/many_types.py [--types 1,4,16,64,256,1024] [--objects 10,100,1000,10000,100000] [--out bench/results]
                        [--render]

--render compiles each program with a Whitted render of both scenes in it (what a user's
scene program instantiates), and adds the render times: many_types_render_*.csv.
"""
import argparse
import csv
import pathlib
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def compile_one(cxx, types, binary, render):
    """(CPU seconds, peak MB) of compiling for `types`, or None where it fails."""
    command = ["/usr/bin/time", "-f", "%U %S %M", cxx, "-std=c++20", "-O2", "-DNDEBUG", "-DGLM_FORCE_PURE", f"-I{ROOT / 'include'}",
               f"-DPRISM_BENCH_TYPES={types}", f"-DPRISM_BENCH_RENDER={int(render)}", str(ROOT / "bench" / "many_types.cpp"), "-o", str(binary)]
    run = subprocess.run(command, capture_output=True, text=True)
    user, system, peak_kb = run.stderr.strip().splitlines()[-1].split()
    if run.returncode != 0:
        print(f"S = {types}: does not compile ({run.stderr.strip().splitlines()[0][:200]})")
        return None
    return float(user) + float(system), int(peak_kb) / 1024


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--types", default="1,4,16,64,256,1024")
    parser.add_argument("--objects", default="10,100,1000,10000,100000")
    parser.add_argument("--cxx", default="g++")
    parser.add_argument("--out", default=str(ROOT / "bench" / "results"))
    parser.add_argument("--render", action="store_true", help="compile and time a Whitted render of both scenes too")
    args = parser.parse_args()
    prefix = "many_types_render" if args.render else "many_types"
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    compiled, rays, renders = [], [], []
    with tempfile.TemporaryDirectory() as folder:
        for types in (int(s) for s in args.types.split(",")):
            binary = pathlib.Path(folder) / f"many_types_{types}"
            cost = compile_one(args.cxx, types, binary, args.render)
            compiled.append({"types": types, "compile_cpu_seconds": cost[0] if cost else "", "peak_mb": round(cost[1]) if cost else ""})
            if not cost:
                continue
            print(f"S = {types:5d}: compile {cost[0]:6.1f} s CPU, {cost[1]:6.0f} MB")
            objects = [n for n in (int(s) for s in args.objects.split(",")) if n >= types]
            lines = subprocess.run([str(binary)] + [str(n) for n in objects], check=True, capture_output=True, text=True).stdout
            for line in lines.strip().splitlines():
                if line.startswith("render,"):
                    _, s, n, ms_types, ms_one, same = line.split(",")
                    assert same == "1", f"S = {s}, N = {n}: the two renders differ"
                    renders.append({"types": int(s), "objects": int(n), "render_ms_types": float(ms_types), "render_ms_one": float(ms_one)})
                    print(f"  N = {int(n):6d}: Whitted 128 x 128 {float(ms_types):8.1f} ms against {float(ms_one):8.1f} in one array "
                          f"({float(ms_types) / float(ms_one):.2f}), the same bits")
                    continue
                s, n, closest_types, closest_one, shadow_types, shadow_one, hits_types, hits_one = line.split(",")
                assert hits_types == hits_one, f"S = {s}, N = {n}: {hits_types} hits against {hits_one}"
                rays.append({"types": int(s), "objects": int(n), "closest_ns_types": float(closest_types), "closest_ns_one": float(closest_one),
                             "shadow_ns_types": float(shadow_types), "shadow_ns_one": float(shadow_one)})
                print(f"  N = {int(n):6d}: closest {float(closest_types):7.1f} ns against {float(closest_one):7.1f} in one array "
                      f"({float(closest_types) / float(closest_one):.2f}), shadow {float(shadow_types):7.1f} against {float(shadow_one):7.1f} "
                      f"({float(shadow_types) / float(shadow_one):.2f})")
    for name, rows in ((f"{prefix}_compile.csv", compiled), (f"{prefix}_rays.csv", rays), (f"{prefix}_times.csv", renders)):
        if not rows:
            continue
        with open(out / name, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)
        print(f"wrote {out / name}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib (Debian: python3-matplotlib): no chart")
        return
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
    done = [r for r in compiled if r["compile_cpu_seconds"] != ""]
    left.plot([r["types"] for r in done], [r["compile_cpu_seconds"] for r in done], "o-", label="compile, CPU s")
    left.plot([r["types"] for r in done], [r["peak_mb"] / 100 for r in done], "s--", label="peak memory, 100 MB")
    left.set_xscale("log", base=2)
    left.set_xlabel("distinct slot types S")
    left.set_title(f"{args.cxx} -O2, bench/many_types.cpp" + (" with a render" if args.render else ""))
    left.legend()
    for types in sorted({r["types"] for r in rays}):
        mine = [r for r in rays if r["types"] == types]
        right.plot([r["objects"] for r in mine], [r["closest_ns_types"] for r in mine], "o-", label=f"S = {types}")
    one = {r["objects"]: r["closest_ns_one"] for r in rays}
    right.plot(sorted(one), [one[n] for n in sorted(one)], "k--", label="one ObjectArray")
    right.set_xscale("log")
    right.set_xlabel("objects N")
    right.set_ylabel("ns per closest-hit query")
    right.set_title("N spheres over S types, one thread")
    right.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(out / f"{prefix}.png", dpi=90)
    print(f"wrote {out / f'{prefix}.png'}")


if __name__ == "__main__":
    main()
