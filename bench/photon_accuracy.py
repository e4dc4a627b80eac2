#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Photon mapping, error against time: prism and POV-Ray 3.7 on the Cornell caustics scene.

Caustics (shared/scenes/cornell_caustics.pov with PHOTONS=1; prism's cornell_caustics with
POV-Ray's no-falloff light and no global map, as POV-Ray has no radiosity there):
  * prism at 1e4 ... 3e6 caustic photons, radius estimates (r = 0.05, 0.1, 0.2, box) and
    k-nearest estimates (k = 50, 100, 200 within a search limit, box, cone, Gaussian);
  * POV-Ray at photon `count` 1e4 ... 3e6, its gather settings left at their defaults.
Each image's RMSE (8-bit sRGB, all pixels and channels, on 0..255) is taken against the
same renderer's converged picture: prism at 2e7 photons with r = 0.03, POV-Ray at
count 2e7 with `gather 100, 400` (more photons per estimate than its defaults 20, 100).
The references' own uncertainty: prism's from a second reference with another seed,
POV-Ray's from a second one with its default gather.
Both are also compared with prism's reference (`rmse_common`), leaving out the pixels
where the two renderers differ without photons (POV-Ray's specular highlights).
Time: photon tracing plus rendering as each reports it (prism: photons stored + render
time; POV-Ray: Photon Time + Trace Time), both with the same threads.

Light leaks and blotches (--only leaks): the diffuse box (shared/scenes/cornell_diffuse.md,
which agrees with Blender's Cycles), against prism's unbiased path-traced reference with its
own noise taken out: the global map read directly (r = 0.25, a sphere or a disk 0.1 r
thick; box, cone, Gaussian filters) at 1e4 ... 1e6 photons, and the estimators of issue 13
(final gather, cached gather, progressive) by effort. RMSE on the 8-bit sRGB scale, over
the whole image, and a crop of one corner for each.

Output: photon_accuracy.csv, photon_leaks.csv and photon_leaks_crops.png in --out.

    bench/photon_accuracy.py [--build build/release] [--out bench/results] [--threads 2]
"""
import argparse
import csv
import pathlib
import re
import subprocess
import sys
import tempfile

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
SIZE = 512
COUNTS = [10000, 30000, 100000, 300000, 1000000, 3000000]
PRISM_ESTIMATORS = {  # name -> (extra arguments of cornell_caustics, largest photon count)
    "radius 0.05": (["--k", "0", "--radius", "0.05", "--filter", "box"], 3000000),
    "radius 0.1": (["--k", "0", "--radius", "0.1", "--filter", "box"], 3000000),
    "radius 0.2": (["--k", "0", "--radius", "0.2", "--filter", "box"], 1000000),
    "k 50 (r <= 0.15)": (["--k", "50", "--radius", "0.15", "--filter", "box"], 3000000),
    "k 50 (r <= 0.15) cone": (["--k", "50", "--radius", "0.15", "--filter", "cone"], 3000000),
    "k 100 (r <= 0.1) cone": (["--k", "100", "--radius", "0.1", "--filter", "cone"], 3000000),
    "k 100 (r <= 0.1) gaussian": (["--k", "100", "--radius", "0.1", "--filter", "gaussian"], 3000000),
    "k 200 (r <= 0.1) cone": (["--k", "200", "--radius", "0.1", "--filter", "cone"], 3000000),
}

def srgb8(path):
    image = mpimg.imread(path)[:, :, :3]
    return np.round(image * 255.0) if image.dtype != np.uint8 else image.astype(float)


def rmse(a, b, mask=None):
    d2 = (a - b) ** 2
    if mask is not None:
        d2 = d2[mask]
    return float(np.sqrt(d2.mean()))


def run_prism(binary, threads, folder, args):
    out = subprocess.run([binary, "--width", str(SIZE), "--height", str(SIZE), "--spp", "1", "--threads", str(threads),
                          "--out", folder, *args], check=True, capture_output=True, text=True).stdout
    stored = re.search(r"(\d+) global and (\d+) caustic photons stored in ([0-9.]+) s", out)
    render = float(re.search(r"render time ([0-9.]+) s", out).group(1))
    return {"stored": int(stored.group(1)) + int(stored.group(2)), "photon_time": float(stored.group(3)),
            "render_time": render, "image": srgb8(pathlib.Path(folder) / "cornell_caustics.png")}


def run_povray(scene_text, threads, folder, count, gather=None, photons=True):
    text = scene_text.replace("count 200000 ", f"count {count} ")
    if gather:
        text = text.replace("autostop 0", f"autostop 0\n    gather {gather[0]}, {gather[1]}")
    pov = pathlib.Path(folder) / "scene.pov"
    pov.write_text(text)
    png = pathlib.Path(folder) / "povray.png"
    run = subprocess.run(["povray", "-D", f"+W{SIZE}", f"+H{SIZE}", "-A", f"+WT{threads}", f"-I{pov}", f"+O{png}",
                          f"Declare=PHOTONS={1 if photons else 0}"], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("povray failed:\n" + run.stderr[-2000:])
    seconds = lambda name: float(re.search(name + r" Time:.*\(([0-9.]+) seconds\)", run.stderr).group(1))  # noqa: E731
    stored = re.search(r"Surface photons stored:\s+(\d+)", run.stderr)
    return {"stored": int(stored.group(1)) if stored else 0, "photon_time": seconds("Photon") if photons else 0.0,
            "render_time": seconds("Trace"), "image": srgb8(png)}


def caustics(args, binary, scene_text, tmp, out):
    common = ["--light", "povray", "--photons", "0", "--method", "direct"]
    print("references: prism 2e7 photons (two seeds), POV-Ray count 2e7 with gather 100, 400 and 20, 100 ...", flush=True)
    reference = common + ["--caustic-photons", "20000000", "--k", "0", "--radius", "0.03", "--filter", "box"]
    ref = run_prism(binary, args.threads, tmp, reference)
    ref2 = run_prism(binary, args.threads, tmp, reference + ["--seed", "1"])
    pov_ref = run_povray(scene_text, args.threads, tmp, 20000000, gather=(100, 400))
    pov_ref2 = run_povray(scene_text, args.threads, tmp, 20000000, gather=(20, 100))
    floor = rmse(ref["image"], ref2["image"]) / np.sqrt(2)
    print(f"  POV-Ray's references with gather 100, 400 and 20, 100 differ by {rmse(pov_ref['image'], pov_ref2['image']):.3f}")
    # Pixels where the two differ without photons: POV-Ray's highlights. prism's Whitted
    # picture is its photon mapper's without caustics (glass then casts no shadow in
    # POV-Ray, so the shadow regions are left out as well).
    pov_plain = run_povray(scene_text, args.threads, tmp, 1000, photons=False)["image"]
    subprocess.run([str(pathlib.Path(binary).parent / "cornell"), "--width", str(SIZE), "--height", str(SIZE), "--spp", "1",
                    "--out", tmp], check=True, capture_output=True)
    prism_plain = srgb8(pathlib.Path(tmp) / "cornell.png")
    mask = np.repeat((np.abs(pov_plain - prism_plain).max(axis=2) <= 8)[:, :, None], 3, axis=2)
    print(f"  reference noise (prism, two seeds / sqrt 2): {floor:.3f}; prism vs POV-Ray references: "
          f"{rmse(ref['image'], pov_ref['image'], mask):.3f} on {mask[:, :, 0].mean() * 100:.1f} % of the pixels", flush=True)
    rows = []

    def record(renderer, estimator, count, r, own):
        row = {"renderer": renderer, "estimator": estimator, "photons": count, "stored": r["stored"],
               "photon_time": r["photon_time"], "render_time": r["render_time"], "time": r["photon_time"] + r["render_time"],
               "rmse": rmse(r["image"], own), "rmse_common": rmse(r["image"], ref["image"], mask),
               "mean": float(r["image"].mean()), "reference_noise": floor}
        rows.append(row)
        print(f"  {renderer:6} {estimator:15} {count:>8}: {row['time']:6.3f} s  rmse {row['rmse']:6.3f}  "
              f"common {row['rmse_common']:6.3f}  mean {row['mean']:6.2f}", flush=True)

    for count in COUNTS:
        best = min((run_povray(scene_text, args.threads, tmp, count) for _ in range(args.repeats)), key=lambda r: r["photon_time"] + r["render_time"])
        record("povray", "default gather", count, best, pov_ref["image"])
        for name, (extra, largest) in PRISM_ESTIMATORS.items():
            if count > largest:
                continue
            best = min((run_prism(binary, args.threads, tmp, common + ["--caustic-photons", str(count)] + extra) for _ in range(args.repeats)),
                       key=lambda r: r["photon_time"] + r["render_time"])
            record("prism", name, count, best, ref["image"])
    with open(out / "photon_accuracy.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    summary(rows)


def summary(rows):
    """For each POV-Ray point, prism's fastest run with no more error, by both measures."""
    for key, title in (("rmse", "each against its own reference"), ("rmse_common", "both against prism's reference")):
        print(f"prism's time to reach POV-Ray's error, {title}:")
        for pov in (r for r in rows if r["renderer"] == "povray"):
            better = [r for r in rows if r["renderer"] == "prism" and float(r[key]) <= float(pov[key])]
            if not better:
                print(f"  POV-Ray count {int(pov['photons']):>8}: rmse {float(pov[key]):.3f}; no prism run reached it")
                continue
            fastest = min(better, key=lambda r: float(r["time"]))
            print(f"  POV-Ray count {int(pov['photons']):>8}: rmse {float(pov[key]):.3f} in {float(pov['time']):.3f} s; prism "
                  f"{fastest['estimator']} at {int(fastest['photons'])}: rmse {float(fastest[key]):.3f} in {float(fastest['time']):.3f} s, "
                  f"time ratio {float(fastest['time']) / float(pov['time']):.2f}")


LEAK_CONFIGS = {  # the global map read directly, r = 0.25: the estimate's shape and filter
    "sphere, box": ["--method", "direct", "--filter", "box", "--max-height-ratio", "1"],
    "disk, box": ["--method", "direct", "--filter", "box", "--max-height-ratio", "0.1"],
    "disk, cone": ["--method", "direct", "--filter", "cone", "--max-height-ratio", "0.1"],
    "disk, gaussian": ["--method", "direct", "--filter", "gaussian", "--max-height-ratio", "0.1"],
}
LEAK_COUNTS = [10000, 30000, 100000, 300000, 1000000]
# The estimators issue 13 added, at their defaults, by effort: (name, flag, efforts).
LEAK_METHODS = [
    ("final gather (2e5 photons)", ["--method", "gather"], "--gather", [16, 64, 256]),
    ("cached gather (2e5 photons)", ["--method", "cache"], "--gather", [64]),
    ("progressive (5e4 photons a pass)", ["--method", "progressive", "--photons", "50000", "--spp", "1"], "--passes", [4, 16, 64]),
]


def linear_to_srgb8(values):
    """Linear radiance to the 8-bit sRGB scale (0..255, unrounded), clamped as a PNG is."""
    v = np.clip(values, 0.0, 1.0)
    return 255.0 * np.where(v <= 0.0031308, 12.92 * v, 1.055 * np.power(v, 1 / 2.4) - 0.055)


def read_pfm(path):
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF"
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), "<f4" if scale < 0 else ">f4").reshape(h, w, 3)
    return data[::-1].astype(np.float64)


def leaks(args, tmp, out):
    """Light leaks and blotches on the diffuse box (shared/scenes/cornell_diffuse.md, the
    box Cycles agrees with), against prism's unbiased reference (path tracing, two halves
    from different seeds, whose own noise is taken out in quadrature)."""
    binary = str(pathlib.Path(args.build) / "examples" / "cornell_diffuse")

    def render(extra):
        stdout = subprocess.run([binary, "--width", str(SIZE), "--height", str(SIZE), "--threads", str(args.threads), "--out", tmp, *extra],
                                check=True, capture_output=True, text=True).stdout
        seconds = float(re.findall(r"([0-9.]+) s$", stdout.strip())[-1])
        return seconds, linear_to_srgb8(read_pfm(pathlib.Path(tmp) / "cornell_diffuse.pfm"))

    print(f"light leaks and blotches: the diffuse box against path tracing ({args.leak_reference_spp} spp in two halves) ...", flush=True)
    halves = [render(["--method", "reference", "--spp", str(args.leak_reference_spp // 2), "--seed", str(seed)])[1] for seed in (101, 102)]
    ref = (halves[0] + halves[1]) / 2
    noise = rmse(halves[0], halves[1]) / 2
    print(f"  reference noise {noise:.3f} (8-bit sRGB), taken out of every error", flush=True)
    rows, crops = [], []

    def record(name, effort, seconds, image):
        raw = rmse(image, ref)
        row = {"config": name, "effort": effort, "time": seconds, "rmse": float(np.sqrt(max(raw * raw - noise * noise, 0.0))),
               "rmse_raw": raw, "reference_noise": noise, "mean": float(image.mean())}
        rows.append(row)
        print(f"  {name:34} {effort:>8}: {seconds:6.3f} s  rmse {row['rmse']:6.3f}  mean {row['mean']:6.2f}", flush=True)

    corner = (slice(300, 480), slice(40, 220))  # the floor, the red wall and the back wall meet
    for name, extra in LEAK_CONFIGS.items():
        for count in LEAK_COUNTS:
            seconds, image = render(extra + ["--photons", str(count), "--global-radius", "0.25"])
            record(name, count, seconds, image)
            if count == 30000:
                crops.append(image[corner])
    for name, extra, flag, efforts in LEAK_METHODS:
        for effort in efforts:
            seconds, image = render(extra + [flag, str(effort)])
            record(name, effort, seconds, image)
        crops.append(image[corner])
    crops.append(ref[corner])
    with open(out / "photon_leaks.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    gap = np.full((crops[0].shape[0], 4, 3), 255.0)
    strip = np.concatenate(sum(([c, gap] for c in crops), [])[:-1], axis=1)
    mpimg.imsave(out / "photon_leaks_crops.png", np.repeat(np.repeat(np.round(strip), 2, axis=0), 2, axis=1).astype(np.uint8))
    labels = [f"{n} (3e4)" for n in LEAK_CONFIGS] + [f"{n} ({e[-1]})" for n, _, _, e in LEAK_METHODS] + ["reference"]
    print(f"wrote {out / 'photon_leaks_crops.png'}: " + " | ".join(labels))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build" / "release"))
    parser.add_argument("--out", default=str(ROOT / "bench" / "results"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--only", choices=["caustics", "leaks"])
    parser.add_argument("--leak-reference-spp", type=int, default=2048, help="the leak study's path-traced reference, in two halves")
    parser.add_argument("--summary", action="store_true", help="only summarise the photon_accuracy.csv in --out")
    args = parser.parse_args()
    if args.summary:
        with open(pathlib.Path(args.out) / "photon_accuracy.csv") as f:
            summary(list(csv.DictReader(f)))
        return
    binary = str(pathlib.Path(args.build) / "examples" / "cornell_caustics")
    scene = ROOT.parent / "shared" / "scenes" / "cornell_caustics.pov"
    if not scene.exists():
        sys.exit(f"cannot find {scene}")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        if args.only != "leaks":
            caustics(args, binary, scene.read_text(), tmp, out)
        if args.only != "caustics":
            leaks(args, tmp, out)


if __name__ == "__main__":
    main()
