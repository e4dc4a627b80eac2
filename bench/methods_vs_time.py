#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Error against time for every global illumination method prism has, against prism's
# unbiased reference (path tracing + light tracing at high effort), Blender's Cycles on
# the diffuse box and POV-Ray 3.7 on its own caustics scene, all in one run on 2 threads:
#   diffuse  shared/scenes/cornell_diffuse.md (Cycles renders it too)
#   area     the same box under its ceiling light, an area light (Cycles renders it too);
#            also the path tracer alone, with multiple importance sampling and without
#            light samples (path, path_bounces), with 2 x 2 light samples a vertex (path_grid2),
#            and with independent samples, Sobol laid over the image in Morton order or Halton
#            instead of Owen-scrambled Sobol points per pixel (path:independent, :zsobol, :halton)
#   glass    the Cornell box with the glass and mirror balls, physical light
#   povray   shared/scenes/cornell_caustics.pov in POV-Ray's model: its no-falloff light,
#            direct light and caustics only (no radiosity); prism's reference takes no
#            diffuse bounce. POV-Ray writes linear Radiance HDR; its time is the Photon
#            and Trace Times it reports. Errors are over the pixels that see only walls
#            (86 %): a caustic seen in the mirror ball (E S D S L) is a path no unbiased
#            method samples, and POV-Ray adds Phong highlights to the balls.
# Errors are against the converged image: the reference's own noise, measured from its
# two halves, is taken out in quadrature (the raw RMSE is in the CSV too). Writes bench/results/methods_vs_time.csv; bench/plot.py draws methods_vs_time.png.
#
# usage: bench/methods_vs_time.py BUILD_DIR [--size 256] [--reference-spp 4096] [--reference-method reference|vcm] [--quick]
import argparse
import csv
import functools
import math
import os
import re
import shutil
import statistics
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


def read_hdr(path):
    """A Radiance RGBE picture (new-style run-length scanlines, as POV-Ray writes), as
    read_pfm's (width, height, values), bottom row first."""
    with open(path, "rb") as f:
        data = f.read()
    start = data.index(b"\n\n") + 2
    end = data.index(b"\n", start)
    fields = data[start:end].split()
    assert fields[0] == b"-Y" and fields[2] == b"+X", fields
    h, w = int(fields[1]), int(fields[3])
    pos, rows = end + 1, []
    for _ in range(h):
        assert data[pos] == 2 and data[pos + 1] == 2 and (data[pos + 2] << 8 | data[pos + 3]) == w, "not a run-length scanline"
        pos += 4
        channels = []
        for _ in range(4):
            line = bytearray()
            while len(line) < w:
                n = data[pos]
                if n > 128:
                    line += bytes([data[pos + 1]]) * (n - 128)
                    pos += 2
                else:
                    line += data[pos + 1:pos + 1 + n]
                    pos += 1 + n
            channels.append(line)
        row = []
        for r, g, b, e in zip(*channels):
            scale = math.ldexp(1.0, e - 136) if e else 0.0
            row += [(r + 0.5) * scale if e else 0.0, (g + 0.5) * scale if e else 0.0, (b + 0.5) * scale if e else 0.0]
        rows.append(row)
    return w, h, [v for row in reversed(rows) for v in row]


def rmse(a, b, mask=None):
    assert a[0] == b[0] and a[1] == b[1]
    if mask is None:
        return math.sqrt(sum((x - y) ** 2 for x, y in zip(a[2], b[2])) / len(a[2]))
    pairs = [(x, y) for x, y, m in zip(a[2], b[2], mask) if m]
    return math.sqrt(sum((x - y) ** 2 for x, y in pairs) / len(pairs))


COLUMNS = ["rmse", "rmse_raw", "reference_noise", "rmse_display", "rmse_display_raw", "reference_noise_display"]


class Scorer:
    """Errors against the mean of two half references, with the reference's own noise
    (sigma^2 = RMSE(h1, h2)^2 / 4) taken out in quadrature: E[(x - ref)^2] = MSE(x) +
    sigma^2. Also in the display range (radiance clamped to 1, where the sRGB picture
    saturates): there a light's hot spot and a caustic's peak, a few hundred pixels that
    hold most of the linear error, count as what a viewer sees."""

    def __init__(self, halves, mask=None):
        w, h = halves[0][0], halves[0][1]
        self.mask = mask  # per value: True where it counts (None: everywhere)
        self.ref = (w, h, [(a + b) / 2 for a, b in zip(halves[0][2], halves[1][2])])
        clamp = lambda img: (img[0], img[1], [min(v, 1.0) for v in img[2]])
        clamped = [clamp(x) for x in halves]
        self.ref_display = (w, h, [(a + b) / 2 for a, b in zip(clamped[0][2], clamped[1][2])])
        self.noise = rmse(*halves, mask) / 2
        self.display_noise = rmse(*clamped, mask) / 2
        self.clamp = clamp

    def __call__(self, image):
        raw = rmse(image, self.ref, self.mask)
        display = rmse(self.clamp(image), self.ref_display, self.mask)
        fix = lambda e, n: math.sqrt(max(e * e - n * n, 0.0))
        return (fix(raw, self.noise), raw, self.noise, fix(display, self.display_noise), display, self.display_noise)


def rectangle_mask(w, h, rectangle):
    """Per value (3 a pixel, PFM rows bottom first): True inside `rectangle`, (x0, x1, y0, y1)
    as fractions of the picture, x from the left and y from the top."""
    x0, x1, y0, y1 = rectangle
    return [x0 <= (col + 0.5) / w < x1 and y0 <= (h - 1 - row + 0.5) / h < y1 for row in range(h) for col in range(w) for _ in range(3)]


def bench_render(program, build, method, effort, out, size, seed=0):
    """One render by the bench program `program` (bench_surfaces, bench_fog: method, effort,
    output, size, seed); returns the seconds it printed."""
    result = subprocess.run([os.path.join(build, "bench", program), method, str(effort), out, str(size), str(seed)],
                            capture_output=True, text=True, check=True)
    return float([line for line in result.stdout.splitlines() if line.startswith("seconds ")][0].split()[1])


def cycles_script_render(script, spp, out, size, seed=1):
    """One Cycles render by the Blender script `script` (in bench/: output, spp, seed, size);
    returns the render time it wrote beside the picture."""
    subprocess.run(["blender", "-b", "--factory-startup", "--python", os.path.join(here, script), "--", out, str(spp), str(seed), str(size)],
                   capture_output=True, text=True, check=True)
    with open(out + ".txt") as f:
        return float(f.read().splitlines()[1].split(",")[1])


def run(build, scene, method, effort, out, size, seed=0):
    """One bench_methods render; a method "direct, 1 spp" samples each pixel's centre once."""
    spp = [str(seed), "1"] if method.endswith("1 spp") else [str(seed)]
    result = subprocess.run([os.path.join(build, "bench", "bench_methods"), scene, method.split(",")[0], str(effort), out, str(size)] + spp,
                            capture_output=True, text=True, check=True)
    for line in result.stdout.splitlines():
        if line.startswith("seconds "):
            return float(line.split()[1])
    raise RuntimeError(result.stdout)


POVRAY_SCENE = os.path.join(root, "..", "shared", "scenes", "cornell_caustics.pov")
# POV-Ray's anti-aliasing for a pixel's mean, as prism's references: every pixel (threshold
# 0) on a jittered 2 x 2 grid, about prism's 4 samples per pixel. Without it POV-Ray
# samples each pixel's centre, and edges and shadow boundaries differ from a pixel's mean.
POVRAY_AA = ["+A0.0", "+AM1", "+R2", "+J"]


def povray(count, out, size, antialias):
    """POV-Ray's picture with `count` photons (its default gather); returns its Photon
    plus Trace Time."""
    folder = os.path.dirname(out)
    with open(POVRAY_SCENE) as f:
        text = f.read().replace("count 200000 ", "count %d " % count)
    pov = os.path.join(folder, "cornell_caustics_%d.pov" % count)
    with open(pov, "w") as f:
        f.write(text)
    result = subprocess.run(["povray", "-D", "+W%d" % size, "+H%d" % size, "+WT2", "-I" + pov, "+O" + out, "+FH", "Declare=PHOTONS=1"]
                            + (POVRAY_AA if antialias else ["-A"]), capture_output=True, text=True, check=True)
    seconds = lambda name: float(re.search(name + r" Time:.*\(([0-9.]+) seconds\)", result.stderr).group(1))  # noqa: E731
    return seconds("Photon") + seconds("Trace")


def cycles(spp, out, seed, size, area=False):
    subprocess.run(["blender", "-b", "--factory-startup", "--python", os.path.join(here, "cycles_cornell.py"), "--", out, str(spp), str(seed), str(size)] +
                   (["--area"] if area else []), capture_output=True, text=True, check=True)
    with open(out + ".txt") as f:
        return float(f.read().splitlines()[1].split(",")[1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--reference-spp", type=int, default=4096, help="the reference's effort, in two halves: samples per pixel, or passes for bdpt and vcm")
    ap.add_argument("--reference-method", default="reference",
                    help="what renders the references: reference (path tracing + light tracing), or vcm (every path, E S ... S L under a point light too); "
                         "another than reference is always rendered anew")
    ap.add_argument("--quick", action="store_true", help="fewer and smaller runs (a smoke test)")
    ap.add_argument("--rescore", action="store_true", help="score the renders already in BUILD_DIR/methods_vs_time again (no rendering)")
    ap.add_argument("--methods", help="comma-separated: re-run only these (direct, gather, cache, progressive, reference, bdpt, vcm, cycles, povray), "
                    "keeping the CSV's other rows and the references already rendered")
    ap.add_argument("--repeats", type=int, default=3, help="interleaved rounds of every timed render (min and median kept)")
    ap.add_argument("--summary", action="store_true", help="only print the time-to-error ratios of the CSV")
    ap.add_argument("--scenes", default="diffuse,area,glass,povray", help="comma-separated: run only these scenes, keeping the CSV's other rows")
    args = ap.parse_args()
    only = set(args.methods.split(",")) if args.methods else None
    scenes = args.scenes.split(",")
    if args.summary:
        with open(os.path.join(here, "results", "methods_vs_time.csv")) as f:
            return summary([(r["scene"], r["method"], r["effort"], float(r["seconds"]), float(r.get("seconds_median") or r["seconds"])) +
                            tuple(float(r[k]) for k in COLUMNS) for r in csv.DictReader(f)])
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
        "bdpt": [4, 16, 64, 256],
        "vcm": [4, 16, 64, 256],
    }
    cycles_spp = [16, 64, 256, 1024]
    if args.quick:
        efforts = {m: e[:2] for m, e in efforts.items()}
        cycles_spp = cycles_spp[:2]
    povray_counts = [10000, 30000, 100000, 300000, 1000000, 3000000]
    paths = {"path": efforts["reference"], "path_bounces": efforts["reference"], "path_grid2": efforts["reference"],
             "path:independent": efforts["reference"], "path:zsobol": efforts["reference"], "path:halton": efforts["reference"]}
    # Independent and Halton photons and samples beside the Sobol ones, on the diffuse box;
    # and Halton or independent photons alone, the camera's samples Sobol's (:KIND-photons).
    independent = {"direct:independent": efforts["direct"], "progressive:independent": efforts["progressive"],
                   "direct:halton": efforts["direct"], "progressive:halton": efforts["progressive"],
                   "direct:halton-photons": efforts["direct"], "progressive:halton-photons": efforts["progressive"],
                   "direct:independent-photons": efforts["direct"], "progressive:independent-photons": efforts["progressive"]}
    per_scene = {"diffuse": {**efforts, **independent}, "glass": efforts, "area": {**efforts, **paths},
                 "povray": {"direct": [10000, 30000, 100000, 300000, 1000000, 3000000],
                            "direct, 1 spp": [10000, 30000, 100000, 300000, 1000000, 3000000], "progressive": efforts["progressive"],
                            "reference": [1, 2] + efforts["reference"]}}
    if args.quick:
        povray_counts = povray_counts[:2]
        per_scene["povray"] = {m: e[:2] for m, e in per_scene["povray"].items()}
    rows = []
    for scene in scenes:
        # The reference: two halves from different seeds, averaged. Their difference
        # measures its own noise, sigma^2 = RMSE(h1, h2)^2 / 4, which every error
        # against it contains: E[(x - ref)^2] = MSE(x) + sigma^2. The charts show
        # sqrt(max(MSE - sigma^2, 0)), the error against the converged image.
        halves = []
        ref_seconds = 0
        for seed in (101, 102):
            half = os.path.join(work, "%s_reference_%d.pfm" % (scene, seed))
            if not (only and os.path.exists(half)) or args.reference_method != "reference":
                ref_seconds += run(args.build, scene, args.reference_method, args.reference_spp // 2, half, args.size, seed)
            halves.append(read_pfm(half))
        w, h = halves[0][0], halves[0][1]
        ref = (w, h, [(a + b) / 2 for a, b in zip(halves[0][2], halves[1][2])])
        write_pfm(os.path.join(work, "%s_reference.pfm" % scene), ref)
        score = Scorer(halves, wall_mask(args.build, work, scene, args.size))
        print("%s: reference by %s, %d spp or passes in two halves, %.1f s, its own noise %.5f (display range %.5f)" %
              (scene, args.reference_method, args.reference_spp, ref_seconds, score.noise, score.display_noise), flush=True)
        # Every render of the scene, then each timed in --repeats interleaved rounds
        # (min and median kept; the pictures are the same bits every round).
        jobs = []  # (method, effort, output, render: () -> seconds, reader)
        for method, levels in per_scene[scene].items():
            if not only or method_key(method) in only:
                for effort in levels:
                    out = os.path.join(work, prism_render_name(scene, method, effort))
                    jobs.append(("prism " + method, effort, out, functools.partial(run, args.build, scene, method, effort, out, args.size), read_pfm))
        if scene in ("diffuse", "area") and (not only or "cycles" in only):
            if shutil.which("blender"):
                for spp in cycles_spp:
                    out = os.path.join(work, "cycles_%s%d.pfm" % ("area_" if scene == "area" else "", spp))
                    jobs.append(("Cycles", spp, out, functools.partial(cycles, spp, out, 1, args.size, scene == "area"), read_pfm))
            else:
                print("Cycles not run: install blender (tools/setup.sh --bench)", file=sys.stderr)
        if scene == "povray" and (not only or "povray" in only):
            if shutil.which("povray"):
                for antialias in (False, True):
                    for count in povray_counts:
                        out = os.path.join(work, "povray_%d%s.hdr" % (count, "_aa" if antialias else ""))
                        jobs.append(("POV-Ray, anti-aliased" if antialias else "POV-Ray", count, out,
                                     functools.partial(povray, count, out, args.size, antialias), read_hdr))
            else:
                print("POV-Ray not run: install povray (tools/setup.sh --bench)", file=sys.stderr)
        times = [[] for _ in jobs]
        for _ in range(args.repeats):
            for job, seconds in zip(jobs, times):
                seconds.append(job[3]())
        for (method, effort, out, _, reader), seconds in zip(jobs, times):
            rows.append((scene, method, effort, min(seconds), statistics.median(seconds)) + score(reader(out)))
            print("%s: %s %s: %.3f s (median %.3f), RMSE %.5f, in the display range %.5f" % (scene, method, effort, rows[-1][3], rows[-1][4], rows[-1][5],
                                                                                             rows[-1][8]), flush=True)
    path = os.path.join(here, "results", "methods_vs_time.csv")
    if (only or len(scenes) < 4) and os.path.exists(path):  # keep the rows not re-run
        with open(path) as f:
            kept = [r for r in csv.DictReader(f) if r["scene"] not in scenes or (only and method_key(r["method"]) not in only)]
        rows = [(r["scene"], r["method"], r["effort"], float(r["seconds"]), float(r.get("seconds_median") or r["seconds"])) +
                tuple(float(r[k]) for k in COLUMNS) for r in kept] + rows
    write_csv(path, rows)
    print("wrote", path)
    summary(rows)
    strip(work, efforts, cycles_spp)


def prism_render_name(scene, method, effort):
    """The file a prism render is kept in: povray_direct1spp_10000.pfm for "direct, 1 spp"."""
    return "%s_%s_%s.pfm" % (scene, method.replace(", 1 spp", "1spp"), effort)


def method_key(method):
    """A CSV row's method as --methods names it: direct ... reference, cycles, povray."""
    return method.replace("prism ", "").split(",")[0].replace("-", "").lower()


def wall_mask(build, work, scene, size):
    """The values that count in the povray scene's errors: pixels whose every sample
    (8 x 8) sees a wall first. None (all) for the other scenes."""
    if scene != "povray":
        return None
    out = os.path.join(work, "povray_mask.pfm")
    run(build, scene, "mask", 64, out, size)
    return [v == 1.0 for v in read_pfm(out)[2]]


def write_csv(path, rows, first="scene"):
    """Rows of (first, method, effort, min seconds, median seconds, COLUMNS...) as CSV; the
    first column is the scene's name here, a region of one scene in the other benches."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow([first, "method", "effort", "seconds", "seconds_median"] + COLUMNS)
        for r in rows:
            w.writerow([r[0], r[1], r[2], "%.4f" % r[3], "%.4f" % r[4]] + ["%.6f" % x for x in r[5:]])


def time_to_reach(points, error):
    """The time a method needs for `error`, on the log-log line between its two measured
    points that bracket it (its first point if that is already as good; None if none
    reaches it). points: (seconds, error), by effort."""
    points = sorted(points)
    for (t0, e0), (t1, e1) in zip([(None, None)] + points, points):
        if e1 <= error:
            if t0 is None or e0 <= error or e0 == e1:
                return t1
            return math.exp(math.log(t0) + (math.log(t1) - math.log(t0)) * (math.log(error) - math.log(e0)) / (math.log(e1) - math.log(e0)))
    return None


def summary(rows):
    """For every picture of an outside renderer, prism's fastest method to the same error,
    as a ratio of that renderer's time (min times; the target is <= 0.5)."""
    for column, name in ((5, "linear"), (8, "display range")):
        print("time to reach the outside renderer's error (%s RMSE), as a ratio of its time:" % name)
        for r in rows:
            if r[1].startswith("prism"):
                continue
            best = None
            for method in dict.fromkeys(x[1] for x in rows if x[0] == r[0] and x[1].startswith("prism")):
                t = time_to_reach([(x[3], x[column]) for x in rows if x[0] == r[0] and x[1] == method], r[column])
                if t is not None and (best is None or t < best[0]):
                    best = (t, method)
            verdict = "not reached" if best is None else "%s in %.3f s, ratio %.2f" % (best[1], best[0], best[0] / r[3])
            print("  %-8s %-22s %8s: %.4f in %.3f s; prism %s" % (r[0], r[1], r[2], r[column], r[3], verdict))


def rescore(work):
    path = os.path.join(here, "results", "methods_vs_time.csv")
    with open(path) as f:
        old = list(csv.DictReader(f))
    masks = {scene: [v == 1.0 for v in read_pfm(os.path.join(work, "povray_mask.pfm"))[2]] if scene == "povray" else None
             for scene in ("diffuse", "area", "glass", "povray")}
    scorers = {scene: Scorer([read_pfm(os.path.join(work, "%s_reference_%d.pfm" % (scene, seed))) for seed in (101, 102)], masks[scene])
               for scene in {r["scene"] for r in old}}
    rows = []
    for r in old:
        method = method_key(r["method"])
        if method == "cycles":
            image = read_pfm(os.path.join(work, "cycles_%s%s.pfm" % ("area_" if r["scene"] == "area" else "", r["effort"])))
        elif method == "povray":
            image = read_hdr(os.path.join(work, "povray_%s%s.hdr" % (r["effort"], "_aa" if "anti" in r["method"] else "")))
        else:
            image = read_pfm(os.path.join(work, prism_render_name(r["scene"], r["method"].replace("prism ", ""), r["effort"])))
        rows.append((r["scene"], r["method"], r["effort"], float(r["seconds"]), float(r.get("seconds_median") or r["seconds"])) +
                    scorers[r["scene"]](image))
    write_csv(path, rows)
    print("rescored", path)
    summary(rows)


def strip(work, efforts, cycles_spp):
    """bench/results/methods_strip.png: each method's picture at about 2 s, and the references."""
    try:
        from PIL import Image, ImageDraw
    except ImportError:
        return
    srgb = lambda v: int(255 * max(0.0, min(1.0, (12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055))) + 0.5)

    def picture(path):
        w, h, d = read_hdr(path) if path.endswith(".hdr") else read_pfm(path)
        img = Image.new("RGB", (w, h))
        img.putdata([tuple(srgb(d[3 * ((h - 1 - i // w) * w + i % w) + k]) for k in range(3)) for i in range(w * h)])
        return img

    rows = []
    for scene in ["glass", "diffuse", "area", "povray"]:
        cells = [("direct map, 1e6", "%s_direct_1000000.pfm" % scene), ("final gather, 64", "%s_gather_64.pfm" % scene),
                 ("cached gather", "%s_cache_4096.pfm" % scene), ("progressive, 64", "%s_progressive_64.pfm" % scene),
                 ("reference", "%s_reference.pfm" % scene)]
        if scene == "diffuse":
            cells.append(("Cycles %d spp" % cycles_spp[-1], "cycles_%d.pfm" % cycles_spp[-1]))
        if scene == "area":
            cells[4:4] = [("path tracer, MIS, 64", "area_path_64.pfm")]
            cells.append(("Cycles %d spp" % cycles_spp[-1], "cycles_area_%d.pfm" % cycles_spp[-1]))
        if scene == "povray":
            cells = [("POV-Ray's model: direct map, 1e6", cells[0][1]), cells[3], cells[4], ("POV-Ray, 1e6, anti-aliased", "povray_1000000_aa.hdr")]
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
