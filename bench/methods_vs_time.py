#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Error against time for every global illumination method prism has, against prism's
# unbiased reference (path tracing + light tracing at high effort), and Blender's
# Cycles on the diffuse box, all in one run on 2 threads:
#   diffuse  shared/scenes/cornell_diffuse.md (Cycles renders it too)
#   glass    the Cornell box with the glass and mirror balls, physical light
# Errors are against the converged image: the reference's own noise, measured from its
# two halves, is taken out in quadrature (the raw RMSE is in the CSV too). Writes bench/results/methods_vs_time.csv; bench/plot.py draws methods_vs_time.png.
#
# usage: bench/methods_vs_time.py BUILD_DIR [--size 256] [--reference-spp 4096] [--quick]
import argparse
import csv
import math
import os
import struct
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)


def read_pfm(path):
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF"
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = struct.unpack(("<" if scale < 0 else ">") + "%df" % (w * h * 3), f.read(w * h * 12))
    return w, h, data


def write_pfm(path, image):
    w, h, data = image
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        f.write(struct.pack("<%df" % len(data), *data))


def rmse(a, b):
    assert a[0] == b[0] and a[1] == b[1]
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a[2], b[2])) / len(a[2]))


COLUMNS = ["rmse", "rmse_raw", "reference_noise", "rmse_display", "rmse_display_raw", "reference_noise_display"]


class Scorer:
    """Errors against the mean of two half references, with the reference's own noise
    (sigma^2 = RMSE(h1, h2)^2 / 4) taken out in quadrature: E[(x - ref)^2] = MSE(x) +
    sigma^2. Also in the display range (radiance clamped to 1, where the sRGB picture
    saturates): there a light's hot spot and a caustic's peak, a few hundred pixels that
    hold most of the linear error, count as what a viewer sees."""

    def __init__(self, halves):
        w, h = halves[0][0], halves[0][1]
        self.ref = (w, h, [(a + b) / 2 for a, b in zip(halves[0][2], halves[1][2])])
        clamp = lambda img: (img[0], img[1], [min(v, 1.0) for v in img[2]])
        clamped = [clamp(x) for x in halves]
        self.ref_display = (w, h, [(a + b) / 2 for a, b in zip(clamped[0][2], clamped[1][2])])
        self.noise = rmse(*halves) / 2
        self.display_noise = rmse(*clamped) / 2
        self.clamp = clamp

    def __call__(self, image):
        raw = rmse(image, self.ref)
        display = rmse(self.clamp(image), self.ref_display)
        fix = lambda e, n: math.sqrt(max(e * e - n * n, 0.0))
        return (fix(raw, self.noise), raw, self.noise, fix(display, self.display_noise), display, self.display_noise)


def run(build, scene, method, effort, out, size, seed=0):
    result = subprocess.run([os.path.join(build, "bench", "bench_methods"), scene, method, str(effort), out, str(size), str(seed)],
                            capture_output=True, text=True, check=True)
    for line in result.stdout.splitlines():
        if line.startswith("seconds "):
            return float(line.split()[1])
    raise RuntimeError(result.stdout)


def cycles(spp, out, seed, size):
    subprocess.run(["blender", "-b", "--factory-startup", "--python", os.path.join(here, "cycles_cornell.py"), "--", out, str(spp), str(seed), str(size)],
                   capture_output=True, text=True, check=True)
    with open(out + ".txt") as f:
        return float(f.read().splitlines()[1].split(",")[1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--reference-spp", type=int, default=4096)
    ap.add_argument("--quick", action="store_true", help="fewer and smaller runs (a smoke test)")
    ap.add_argument("--rescore", action="store_true", help="score the renders already in BUILD_DIR/methods_vs_time again (no rendering)")
    ap.add_argument("--methods", help="comma-separated: re-run only these (direct, gather, cache, progressive, reference, cycles), "
                    "keeping the CSV's other rows and the references already rendered")
    args = ap.parse_args()
    only = set(args.methods.split(",")) if args.methods else None
    if args.rescore:
        return rescore(os.path.join(args.build, "methods_vs_time"))
    work = os.path.join(args.build, "methods_vs_time")
    os.makedirs(work, exist_ok=True)
    efforts = {
        "direct": [10000, 30000, 100000, 300000, 1000000, 3000000],
        "gather": [16, 64, 256],
        "cache": [256, 1024, 4096],
        "progressive": [4, 16, 64, 256],
        "reference": [4, 16, 64, 256],
    }
    cycles_spp = [16, 64, 256, 1024]
    if args.quick:
        efforts = {m: e[:2] for m, e in efforts.items()}
        cycles_spp = cycles_spp[:2]
    rows = []
    for scene in ["diffuse", "glass"]:
        # The reference: two halves from different seeds, averaged. Their difference
        # measures its own noise, sigma^2 = RMSE(h1, h2)^2 / 4, which every error
        # against it contains: E[(x - ref)^2] = MSE(x) + sigma^2. The charts show
        # sqrt(max(MSE - sigma^2, 0)), the error against the converged image.
        halves = []
        ref_seconds = 0
        for seed in (101, 102):
            half = os.path.join(work, "%s_reference_%d.pfm" % (scene, seed))
            if not (only and os.path.exists(half)):
                ref_seconds += run(args.build, scene, "reference", args.reference_spp // 2, half, args.size, seed)
            halves.append(read_pfm(half))
        w, h = halves[0][0], halves[0][1]
        ref = (w, h, [(a + b) / 2 for a, b in zip(halves[0][2], halves[1][2])])
        write_pfm(os.path.join(work, "%s_reference.pfm" % scene), ref)
        score = Scorer(halves)
        print("%s: reference, %d spp in two halves, %.1f s, its own noise %.5f (display range %.5f)" %
              (scene, args.reference_spp, ref_seconds, score.noise, score.display_noise), flush=True)
        for method, levels in efforts.items():
            if only and method not in only:
                continue
            for effort in levels:
                out = os.path.join(work, "%s_%s_%s.pfm" % (scene, method, effort))
                seconds = run(args.build, scene, method, effort, out, args.size)
                rows.append((scene, "prism " + method, effort, seconds) + score(read_pfm(out)))
                print("%s: %s %s: %.2f s, RMSE %.5f, in the display range %.5f" % (scene, method, effort, seconds, rows[-1][4], rows[-1][7]), flush=True)
        if scene == "diffuse" and (not only or "cycles" in only):
            try:
                for spp in cycles_spp:
                    out = os.path.join(work, "cycles_%d.pfm" % spp)
                    seconds = cycles(spp, out, 1, args.size)
                    rows.append((scene, "Cycles", spp, seconds) + score(read_pfm(out)))
                    print("%s: Cycles %d spp: %.2f s, RMSE %.5f, in the display range %.5f" % (scene, spp, seconds, rows[-1][4], rows[-1][7]), flush=True)
            except (FileNotFoundError, subprocess.CalledProcessError) as e:
                print("Cycles not run (%s): install blender (tools/setup.sh --bench)" % e, file=sys.stderr)
    path = os.path.join(here, "results", "methods_vs_time.csv")
    if only and os.path.exists(path):  # keep the rows of the methods not re-run
        with open(path) as f:
            kept = [r for r in csv.DictReader(f)
                    if r["method"].replace("prism ", "").lower() not in only and not (r["method"] == "Cycles" and "cycles" in only)]
        rows = [(r["scene"], r["method"], r["effort"], float(r["seconds"])) + tuple(float(r[k]) for k in COLUMNS) for r in kept] + rows
    write_csv(path, rows)
    print("wrote", path)
    strip(work, efforts, cycles_spp)


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scene", "method", "effort", "seconds"] + COLUMNS)
        for r in rows:
            w.writerow([r[0], r[1], r[2], "%.4f" % r[3]] + ["%.6f" % x for x in r[4:]])


def rescore(work):
    path = os.path.join(here, "results", "methods_vs_time.csv")
    with open(path) as f:
        old = list(csv.DictReader(f))
    scorers = {scene: Scorer([read_pfm(os.path.join(work, "%s_reference_%d.pfm" % (scene, seed))) for seed in (101, 102)]) for scene in ("diffuse", "glass")}
    rows = []
    for r in old:
        method = r["method"].replace("prism ", "")
        name = "cycles_%s.pfm" % r["effort"] if method == "Cycles" else "%s_%s_%s.pfm" % (r["scene"], method, r["effort"])
        rows.append((r["scene"], r["method"], r["effort"], float(r["seconds"])) + scorers[r["scene"]](read_pfm(os.path.join(work, name))))
    write_csv(path, rows)
    print("rescored", path)


def strip(work, efforts, cycles_spp):
    """bench/results/methods_strip.png: each method's picture at about 2 s, and the references."""
    try:
        from PIL import Image, ImageDraw
    except ImportError:
        return
    srgb = lambda v: int(255 * max(0.0, min(1.0, (12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055))) + 0.5)

    def picture(path):
        w, h, d = read_pfm(path)
        img = Image.new("RGB", (w, h))
        img.putdata([tuple(srgb(d[3 * ((h - 1 - i // w) * w + i % w) + k]) for k in range(3)) for i in range(w * h)])
        return img

    rows = []
    for scene in ["glass", "diffuse"]:
        cells = [("direct map, 1e6", "%s_direct_1000000.pfm" % scene), ("final gather, 64", "%s_gather_64.pfm" % scene),
                 ("cached gather", "%s_cache_4096.pfm" % scene), ("progressive, 64", "%s_progressive_64.pfm" % scene),
                 ("reference", "%s_reference.pfm" % scene)]
        if scene == "diffuse":
            cells.append(("Cycles %d spp" % cycles_spp[-1], "cycles_%d.pfm" % cycles_spp[-1]))
        rows.append([(label, os.path.join(work, name)) for label, name in cells if os.path.exists(os.path.join(work, name))])
    if not rows or not rows[0]:
        return
    size = read_pfm(rows[0][0][1])[0]
    columns = max(len(r) for r in rows)
    out = Image.new("RGB", (columns * size, len(rows) * (size + 18)), (255, 255, 255))
    draw = ImageDraw.Draw(out)
    for j, row in enumerate(rows):
        for i, (label, path) in enumerate(row):
            out.paste(picture(path), (i * size, j * (size + 18) + 18))
            draw.text((i * size + 4, j * (size + 18) + 3), label, fill=(0, 0, 0))
    out.save(os.path.join(here, "results", "methods_strip.png"))


if __name__ == "__main__":
    main()
