#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# The scene where only merging converges: examples/sun_caustic (the sun's caustic through a
# glass ball on a floor, seen directly and in a mirror beside the ball). Seen in the mirror
# the caustic is the path E S D S S L, every segment with a delta end: no connection joins
# it. Each estimator renders the scene at 256 x 160 on 2 threads, and its mean radiance over
# the caustic's mirror image and over the caustic seen directly is compared with a long VCM
# render (1024 passes, of a seed of its own, so that it shares no pass with the others); progressive photon mapping, consistent too, is the independent check.
# Writes bench/results/sun_caustic.csv.
#
# usage: bench/sun_caustic.py BUILD_DIR   (BUILD_DIR/examples/sun_caustic; numpy)
import csv
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

RUNS = [  # name, flags, what the effort counts
    ("vcm", ["--spp", "1024", "--seed", "101"], "reference: 1024 passes, another seed"),
    ("vcm", ["--spp", "64"], "64 passes"),
    ("vcm", ["--spp", "256"], "256 passes"),
    ("bdpt", ["--spp", "256"], "256 passes"),
    ("reference", ["--spp", "256"], "256 spp and as many light paths"),
    ("progressive", ["--passes", "256", "--spp", "1"], "256 passes of 200 000 + 200 000 photons"),
]
# Pixel boxes (rows y0:y1, columns x0:x1 of the 256 x 160 image, top row 0).
BOXES = {"mirrored caustic": (66, 80, 50, 72), "direct caustic": (94, 110, 150, 180)}


def read_pfm(path):
    with open(path, "rb") as f:
        f.readline()
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4").reshape(height, width, 3)
    return data[::-1].astype(np.float64)


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build/gallery"
    program = os.path.join(build, "examples", "sun_caustic")
    rows = []
    reference = None
    with tempfile.TemporaryDirectory() as tmp:
        for k, (method, flags, effort) in enumerate(RUNS):
            out = os.path.join(tmp, str(k))
            log = subprocess.run([program, "--width", "256", "--height", "160", "--threads", "2", "--method", method, "--out", out] + flags,
                                 check=True, capture_output=True, text=True).stdout
            seconds = float(re.findall(r"([0-9.]+) s$", log.strip().splitlines()[-1])[0])
            image = read_pfm(os.path.join(out, "sun_caustic.pfm"))
            if reference is None:
                reference = image
            means = {name: image[y0:y1, x0:x1].mean() for name, (y0, y1, x0, x1) in BOXES.items()}
            ref_means = {name: reference[y0:y1, x0:x1].mean() for name, (y0, y1, x0, x1) in BOXES.items()}
            rmse = float(np.sqrt(((image - reference) ** 2).mean()))
            row = {"method": method, "effort": effort, "seconds": seconds, "rmse": rmse}
            for name in BOXES:
                row[name] = means[name]
                row[name + " vs reference"] = means[name] / ref_means[name] - 1
            rows.append(row)
            print(f"{method:12s} {effort:40s} {seconds:7.2f} s  " + "  ".join(f"{name} {means[name]:.4f} ({100 * row[name + ' vs reference']:+.1f} %)" for name in BOXES) +
                  f"  RMSE {rmse:.4f}", flush=True)
    os.makedirs("bench/results", exist_ok=True)
    with open("bench/results/sun_caustic.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
