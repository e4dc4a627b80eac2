#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Where each sampler puts its error in the image: the path tracer on the area-lit Cornell
# box (bench_methods' "area" scene) at a few sample counts, under independent numbers,
# Halton's and Owen-scrambled Sobol points per pixel, and zsobol (Sobol laid over the
# image in Morton order, whose error should be blue noise, prism's default), several seeds
# each, against prism's own reference (two halves, its noise taken out in quadrature as
# methods_vs_time.py does).
#
# For each render, in the display range: the RMSE per pixel; the RMSE of the image and the reference both
# blurred by a Gaussian of 1 and 2 pixels (what a viewer a little further away, a
# downsampled picture or a denoiser keeps: blue noise's error is at the high frequencies
# the blur removes); and the error's power spectrum, averaged over rings of equal
# frequency and over seeds, as a share of its total (white noise is flat at 1).
# Writes bench/results/blue_noise.csv and blue_noise_spectrum.csv; bench/plot.py draws
# blue_noise.png.
#
# usage: bench/blue_noise.py BUILD_DIR [--size 256] [--spp 2,4,16,64] [--seeds 4] [--reference-spp 4096]
import argparse
import csv
import os

import numpy as np

from methods_vs_time import read_pfm, run

here = os.path.dirname(os.path.abspath(__file__))
SAMPLERS = ["independent", "halton", "sobol", "zsobol"]


def image(path):
    """A PFM as an array of rows (top first) by columns by RGB, in the display range
    (radiance clamped to 1, where the sRGB picture saturates: the light's own pixels, tens
    of times brighter than the walls, would otherwise hold most of the error)."""
    w, h, data = read_pfm(path)
    return np.minimum(np.asarray(data, dtype=np.float64).reshape(h, w, 3)[::-1], 1.0)


def blur(a, sigma):
    """A Gaussian blur of sigma pixels, separable, the image's edges mirrored."""
    radius = int(np.ceil(3 * sigma))
    x = np.arange(-radius, radius + 1)
    k = np.exp(-0.5 * (x / sigma) ** 2)
    k /= k.sum()
    for axis in (0, 1):
        pad = [(0, 0)] * a.ndim
        pad[axis] = (radius, radius)
        p = np.pad(a, pad, mode="reflect")
        a = sum(k[i] * np.take(p, np.arange(i, i + a.shape[axis]), axis=axis) for i in range(len(k)))
    return a


def spectrum(error, rings):
    """The error's power spectrum (its luminance, the mean taken out), averaged over rings
    of radial frequency from 0 to 1/2 cycle a pixel, as a share of the mean power."""
    lum = error @ np.array([0.2126, 0.7152, 0.0722])
    lum = lum - lum.mean()
    power = np.abs(np.fft.fft2(lum)) ** 2
    fy = np.fft.fftfreq(lum.shape[0])[:, None]
    fx = np.fft.fftfreq(lum.shape[1])[None, :]
    f = np.sqrt(fx * fx + fy * fy)
    edges = np.linspace(0, 0.5, rings + 1)
    mean = power[f > 0].mean()
    return [float(power[(f > lo) & (f <= hi)].mean() / mean) for lo, hi in zip(edges[:-1], edges[1:])]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--spp", default="2,4,16,64", help="(1 spp samples each pixel's centre)")
    ap.add_argument("--seeds", type=int, default=4)
    ap.add_argument("--reference-spp", type=int, default=4096)
    ap.add_argument("--rings", type=int, default=16)
    args = ap.parse_args()
    work = os.path.join(args.build, "blue_noise")
    os.makedirs(work, exist_ok=True)
    halves = []
    for seed in (101, 102):
        half = os.path.join(work, "reference_%d_%d.pfm" % (args.size, seed))
        if not os.path.exists(half):
            run(args.build, "area", "reference", args.reference_spp // 2, half, args.size, seed)
        halves.append(image(half))
    reference = (halves[0] + halves[1]) / 2

    def noise(sigma):  # the reference's own noise, after the same blur
        d = halves[0] - halves[1] if sigma == 0 else blur(halves[0] - halves[1], sigma)
        return np.sqrt(np.mean(d * d)) / 2

    sigmas = [0, 1, 2]
    noises = {s: noise(s) for s in sigmas}
    print("reference: %d spp, its own noise %s" % (args.reference_spp, ", ".join("%.5f (blur %g)" % (noises[s], s) for s in sigmas)), flush=True)
    rows, spectra = [], []
    for spp in [int(s) for s in args.spp.split(",")]:
        for sampler in SAMPLERS:
            errors = {s: [] for s in sigmas}
            seconds, rings = [], np.zeros(args.rings)
            for seed in range(args.seeds):
                out = os.path.join(work, "%s_%d_%d.pfm" % (sampler, spp, seed))
                seconds.append(run(args.build, "area", "path:" + sampler if sampler != "sobol" else "path", spp, out, args.size, seed))
                error = image(out) - reference
                for s in sigmas:
                    e = error if s == 0 else blur(error, s)
                    errors[s].append(np.sqrt(max(np.mean(e * e) - noises[s] ** 2, 0.0)))
                rings += np.array(spectrum(error, args.rings)) / args.seeds
            row = [sampler, spp, args.seeds, float(np.median(seconds))] + [float(np.sqrt(np.mean(np.square(errors[s])))) for s in sigmas]
            rows.append(row)
            spectra += [[sampler, spp, (i + 0.5) * 0.5 / args.rings, float(r)] for i, r in enumerate(rings)]
            print("%s %d spp: %.2f s, RMSE %.5f, blurred by 1 px %.5f, by 2 px %.5f; spectrum, lowest ring %.3f, highest %.3f" %
                  (sampler, spp, row[3], row[4], row[5], row[6], rings[0], rings[-1]), flush=True)
    os.makedirs(os.path.join(here, "results"), exist_ok=True)
    with open(os.path.join(here, "results", "blue_noise.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["sampler", "spp", "seeds", "seconds", "rmse", "rmse_blur1", "rmse_blur2"])
        w.writerows(rows)
    with open(os.path.join(here, "results", "blue_noise_spectrum.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["sampler", "spp", "frequency", "power"])
        w.writerows(spectra)
    print("wrote bench/results/blue_noise.csv, blue_noise_spectrum.csv")


if __name__ == "__main__":
    main()
