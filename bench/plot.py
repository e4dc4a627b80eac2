#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Draw the README's charts from the CSVs in bench/results (Debian: python3-matplotlib).

    bench/plot.py [results-folder]
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

RESULTS = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent / "results")


def read(name):
    path = RESULTS / name
    if not path.exists():
        return None
    with open(path) as f:
        return list(csv.DictReader(f))


def save(fig, name):
    fig.tight_layout()
    fig.savefig(RESULTS / name, dpi=110)
    plt.close(fig)
    print(f"wrote {RESULTS / name}")


def accuracy_charts(rows):
    scenes = sorted({r["scene"] for r in rows})
    # 1. float vs double and 2. Schlick vs exact: error against time, one panel per scene.
    for name, key, variants in (
        ("accuracy_float_vs_double.png", "scalar", [("float", "exact"), ("double", "exact")]),
        ("accuracy_schlick_vs_exact.png", "fresnel", [("float", "exact"), ("float", "schlick")]),
    ):
        fig, axes = plt.subplots(1, len(scenes), figsize=(5.2 * len(scenes), 4.2), squeeze=False)
        for ax, scene in zip(axes[0], scenes):
            for scalar, fresnel in variants:
                pts = [r for r in rows if r["scene"] == scene and r["scalar"] == scalar and r["fresnel"] == fresnel]
                label = f"{scalar}, {fresnel} Fresnel"
                t = [float(r["seconds"]) for r in pts]
                ax.plot(t, [float(r["rmse"]) for r in pts], "o-", label=f"{label}: vs 1024-spp reference")
                same = [max(float(r["rmse_same_samples"]), 1e-9) for r in pts]
                if any(s > 1e-9 for s in same):
                    ax.plot(t, same, "s--", label=f"{label}: vs double exact, same samples")
                for r in pts:
                    ax.annotate(f"{r['spp']} spp", (float(r["seconds"]), float(r["rmse"])), fontsize=7,
                                textcoords="offset points", xytext=(4, 4))
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("render time, 256x256, one thread (s)")
            ax.set_ylabel("RMSE of linear radiance")
            ax.set_title(f"{scene}: {key}")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7)
        save(fig, name)
    # 3. samples per pixel against error.
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    for scene in scenes:
        pts = [r for r in rows if r["scene"] == scene and r["scalar"] == "float" and r["fresnel"] == "exact"]
        spp = [int(r["spp"]) for r in pts]
        ax.plot(spp, [float(r["rmse"]) for r in pts], "o-", label=f"{scene}")
    ref = [r for r in rows if r["scalar"] == "float" and r["fresnel"] == "exact" and r["spp"] == "4"]
    if ref:
        e4 = float(ref[0]["rmse"])
        ax.plot([4, 64], [e4, e4 / 4], "k:", label="slope -1/2 (Monte Carlo)")
        ax.plot([4, 64], [e4, e4 / 16], "k--", alpha=0.5, label="slope -1 (stratified edges)")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("samples per pixel")
    ax.set_ylabel("RMSE vs 1024-spp double reference")
    ax.set_title("spp against error (float, exact Fresnel)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, "accuracy_spp.png")


def acne_chart(rows):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    for ax, scalar in zip(axes, ("float", "double")):
        for shape, marker in (("sphere", "o"), ("plane", "s"), ("box", "^")):
            for method, style in (("robust", "-"), ("epsilon_1e-4", "--"), ("none", ":")):
                pts = [r for r in rows if r["scalar"] == scalar and r["shape"] == shape and r["method"] == method
                       and r["kind"] == "reflect"]
                rate = [100 * int(r["self_hits"]) / max(1, int(r["rays"])) for r in pts]
                ax.plot([float(r["distance"]) for r in pts], [max(x, 1e-3) for x in rate], marker + style,
                        label=f"{shape}, {method}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(5e-4, 200)
        ax.set_xlabel("distance of the scene from the origin")
        ax.set_title(f"{scalar}: self-hits of reflected rays (0 drawn at 1e-3)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("self-hit rate (%)")
    axes[1].legend(fontsize=7, ncol=1, loc="center right")
    save(fig, "acne.png")


def povray_chart(rows):
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(1, len(scenes), figsize=(5.2 * len(scenes), 3.6), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        pts = [r for r in rows if r["scene"] == scene]
        x = range(len(pts))
        ax.bar([i - 0.2 for i in x], [float(r["prism_seconds"]) for r in pts], 0.4, label="prism (render time)")
        ax.bar([i + 0.2 for i in x], [float(r["povray_trace_seconds"]) for r in pts], 0.4, label="POV-Ray 3.7 (trace time)")
        if all(r.get("baseline_seconds") for r in pts):  # an earlier build, timed in the same runs
            ax.scatter([i - 0.2 for i in x], [float(r["baseline_seconds"]) for r in pts], marker="_", s=600, color="black",
                       label="prism, baseline build", zorder=3)
        for i, r in zip(x, pts):
            ax.annotate(f"{float(r['ratio']):.2f}x", (i - 0.2, 0.5 * float(r["prism_seconds"])), ha="center", va="center", fontsize=9,
                        color="white")
        ax.set_xticks(list(x), [f"{r['threads']} thread(s)" for r in pts])
        ax.set_ylabel("seconds (minimum of runs)")
        ax.set_title(f"{scene}, 512x512, 1 spp")
        ax.legend(fontsize=8)
    save(fig, "vs_povray.png")


def quadric_chart(rows):
    experiments = [("asymptotic", "ray tilted eps from a paraboloid's axis (A -> 0)", "eps (rad)", "relative error of t (a missed root: 1)"),
                   ("grazing", "chord at 1 - delta from a unit sphere's centre", "delta", "relative error of t (a missed root: 1)"),
                   ("distance", "ellipsoid placed D from the origin", "D", "worst distance of hit point from surface")]
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.6))
    for ax, (name, title, xlabel, ylabel) in zip(axes, experiments):
        pts = [r for r in rows if r["experiment"] == name]
        for method in dict.fromkeys(r["method"] for r in pts):
            for scalar, style in (("float", "-"), ("double", "--")):
                line = [r for r in pts if r["method"] == method and r["scalar"] == scalar and r["error"] != "nan"]
                ax.plot([float(r["x"]) for r in line], [max(float(r["error"]), 1e-18) for r in line], style, marker="o", markersize=3,
                        label=f"{method}, {scalar}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    axes[0].set_ylim(1e-18, 1e3)
    axes[0].invert_xaxis()
    axes[1].invert_xaxis()
    save(fig, "quadric_roots.png")


def composition_chart(rows):
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    k = [int(r["spheres"]) for r in rows]
    for key, label in (("union_ns", "one Union<...> CSG object"), ("separate_ns", "separate objects"), ("array_ns", "one ObjectArray")):
        ax.plot(k, [float(r[key]) for r in rows], "o-", label=label)
    ax.set_xlabel("spheres")
    ax.set_ylabel("ns per closest-hit query")
    ax.set_title("cost of composition (same surfaces, same rays)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, "csg_composition.png")


def kdtree_chart(rows):
    n = [int(r["points"]) for r in rows]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4))
    for ax, (ours, theirs, title, unit) in zip(axes, (
            ("build_prism_s", "build_nanoflann_s", "build", "seconds"),
            ("knn50_prism_ns", "knn50_nanoflann_ns", "k = 50 nearest", "ns per query"),
            ("radius_prism_ns", "radius_nanoflann_ns", "radius 0.05", "ns per query"))):
        ax.plot(n, [float(r[ours]) for r in rows], "o-", label="prism KdTree")
        ax.plot(n, [float(r[theirs]) for r in rows], "s--", label="nanoflann 1.4.3")
        for x, r in zip(n, rows):
            ax.annotate(f"{float(r[theirs]) / float(r[ours]):.2f}x", (x, float(r[ours])), textcoords="offset points", xytext=(4, -12), fontsize=8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("photons")
        ax.set_ylabel(unit)
        ax.set_title(f"{title} (nanoflann / prism)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    save(fig, "kdtree.png")


def embree_chart(rows, name="bvh_vs_embree.png", embree="Embree 3", prism="prism"):
    """Mrays/s of prism and Embree 3 against object count (spheres), and their ratio for
    every geometry, from the minimum times of interleaved rounds."""
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.2))
    ax = axes[0]
    for kind, style in (("primary", "-"), ("bounce", "--")):
        sel = [r for r in rows if r["geometry"] == "spheres" and r["rays"] == kind and r["threads"] == "1"]
        n = [int(r["count"]) for r in sel]
        ax.plot(n, [float(r["prism_mrays_min"]) for r in sel], "o" + style, color="C0", label=f"{prism}, {kind} rays")
        ax.plot(n, [float(r["embree_mrays_min"]) for r in sel], "s" + style, color="C1", label=f"{embree}, {kind} rays")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("spheres")
    ax.set_ylabel("million rays per second (1 thread)")
    ax.set_title("closest hit among N spheres")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax = axes[1]
    labels, ratios = [], {}
    for r in rows:
        count = int(r["count"])
        label = f"{count:.0e} spheres".replace("e+0", "e") if r["geometry"] == "spheres" else f"{r['geometry']}, {count / 1000:.0f}k triangles"
        if label not in labels:
            labels.append(label)
        key = (r["rays"], r["threads"])
        ratios.setdefault(key, {})[label] = float(r["prism_mrays_min"]) / float(r["embree_mrays_min"])
    width = 0.8 / len(ratios)
    for i, (key, values) in enumerate(sorted(ratios.items())):
        xs = [j + (i - (len(ratios) - 1) / 2) * width for j in range(len(labels))]
        ax.bar(xs, [values.get(label, 0) for label in labels], width, label=f"{key[0]} rays, {key[1]} thread{'s' if key[1] != '1' else ''}")
    ax.axhline(1.0, color="k", lw=0.8)
    ax.axhline(0.67, color="gray", lw=0.8, ls=":")
    ax.set_xticks(range(len(labels)))
    ax.set_xticklabels(labels, rotation=30, ha="right", fontsize=8)
    ax.set_ylabel(f"{prism} rays/s ÷ {embree} rays/s")
    ax.set_title("ratio (1.0: as fast as Embree; dotted: 0.67); shadow: any hit")
    ax.legend(fontsize=7)
    save(fig, name)


def bvh_quality_chart(rows):
    """Trace time against build time per Bvh setting, one panel per geometry (the trace
    axis from 0: the settings differ by a few per cent)."""
    geometries = []
    for r in rows:
        key = (r["geometry"], r["count"])
        if key not in geometries:
            geometries.append(key)
    fig, axes = plt.subplots(1, len(geometries), figsize=(3.2 * len(geometries), 3.6))
    for ax, (geometry, count) in zip(axes, geometries):
        sel = [r for r in rows if r["geometry"] == geometry and r["count"] == count]
        for i, r in enumerate(sel):
            ax.plot(float(r["build_s"]), 1e3 / float(r["mrays"]), "o", color=f"C{i}", label=f"{r['setting']} (SAH {float(r['sah_cost']):.2f})")
        ax.set_xscale("log")
        ax.set_ylim(0, 1.25e3 / min(float(r["mrays"]) for r in sel))
        ax.set_xlabel("build (s)")
        ax.set_ylabel("trace (ns per ray, 1 thread)")
        n = int(count)
        ax.set_title(f"{n:.0e} spheres".replace("e+0", "e") if geometry == "spheres" else f"{geometry}, {n / 1000:.0f}k triangles", fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=6)
    save(fig, "bvh_quality.png")


def photon_chart(rows):
    """Error against time: prism's estimators and POV-Ray, both against prism's reference
    (left) and each against its own (right)."""
    fig, axes = plt.subplots(1, 2, figsize=(15, 5.2))
    for ax, key, title in ((axes[0], "rmse_common", "against prism's 2e7-photon reference (POV-Ray's highlights masked)"),
                           (axes[1], "rmse", "each against its own reference")):
        for name in dict.fromkeys(r["estimator"] for r in rows):
            line = [r for r in rows if r["estimator"] == name]
            pov = line[0]["renderer"] == "povray"
            ax.plot([float(r["time"]) for r in line], [float(r[key]) for r in line], "s-" if pov else "o-", linewidth=2.5 if pov else 1.2,
                    color="black" if pov else None, markersize=4, label=("POV-Ray 3.7, " if pov else "prism, ") + name)
            if pov or name.startswith("k 100 (r <= 0.1) cone"):
                for r in line:
                    ax.annotate(f"{int(r['photons']):.0e}".replace("+0", ""), (float(r["time"]), float(r[key])), textcoords="offset points",
                                xytext=(3, 3), fontsize=7)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("seconds: photon tracing + rendering, 2 threads")
        ax.set_ylabel("RMSE, 8-bit sRGB (0..255)")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7, loc="upper right")
    fig.suptitle("Cornell caustics, 512x512, 1e4 ... 3e6 photons (labels: photons emitted / POV-Ray count)", fontsize=10)
    save(fig, "photon_accuracy.png")


def leak_chart(rows):
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    for name in dict.fromkeys(r["config"] for r in rows):
        line = sorted((float(r["time"]), float(r["rmse"])) for r in rows if r["config"] == name)
        style = "o--" if "," in name else "s-"  # the global map's shapes dashed, the newer estimators solid
        ax.plot([p[0] for p in line], [p[1] for p in line], style, label=name)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("render time (s, 2 threads)")
    ax.set_ylabel("RMSE, 8-bit sRGB, against path tracing\n(its noise removed)")
    ax.set_title("diffuse box: global map read directly (r = 0.25; sphere or disk, filters)\nand issue 13's estimators", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, "photon_leaks.png")


def ray_property_chart(after, before):
    """Lost hits and clear hits missed, per distance and size, before and after issue 10."""
    def cells(rows, scalar):
        out = {}
        for r in rows:
            if r["scalar"] != scalar:
                continue
            key = (float(r["distance"]), float(r["size"]))
            v = out.setdefault(key, [0, 0, 0, 0])
            v[0] += int(r["lost"])
            v[1] += int(r["hits"])
            v[2] += int(r["missed_vs_double"])
            v[3] += int(r["clear_hits"])
        return out

    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    panels = [("float", 0, 1, "float: hits the scene lost (% of the shape's own)"),
              ("double", 0, 1, "double: hits the scene lost (% of the shape's own)"),
              ("float", 2, 3, "float: clear hits missed (% of the double twin's)")]
    for ax, (scalar, num, den, title) in zip(axes, panels):
        a, b = cells(after, scalar), cells(before, scalar) if before else {}
        keys = sorted(a)
        x = range(len(keys))
        pct = lambda d, k: 100.0 * d[k][num] / d[k][den] if k in d and d[k][den] else 0.0
        if b:
            ax.bar([i - 0.2 for i in x], [pct(b, k) for k in keys], 0.4, label="before", color="#c44")
        ax.bar([i + 0.2 for i in x], [pct(a, k) for k in keys], 0.4, label="after", color="#48c")
        ax.set_xticks(list(x))
        ax.set_xticklabels([f"{d:g}\n{s:g}" for d, s in keys], fontsize=7)
        ax.set_xlabel("distance (shape from origin, rays from shape) / size")
        ax.set_title(title, fontsize=9)
        ax.legend(fontsize=8)
    save(fig, "ray_property.png")


def methods_chart(rows, labels, x_key, y_key, floor, xlabel, ylabel, title, name):
    """Error against time on log-log axes, one line per method, each point labelled by its parameter."""
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for method, label in labels.items():
        pts = [r for r in rows if r["method"] == method]
        if not pts:
            continue
        x = [float(r[x_key]) for r in pts]
        y = [max(float(r[y_key]), floor) for r in pts]
        ax.loglog(x, y, "o-", label=label)
        for xi, yi, r in zip(x, y, pts):
            ax.annotate(r["parameter"], (xi, yi), textcoords="offset points", xytext=(3, 3), fontsize=7)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, name)


def graded_index_chart(rows):
    methods_chart(rows, {"adaptive": "Sharma RKN, step doubling (tolerance)", "fixed": "Sharma RKN, fixed steps (dt)",
                         "layers": "lecture notes: flat layers + Snell (layers)"},
                  "ns_per_ray", "error", 1e-16, "ns per ray (min of 5 runs)", "|x - exact| where the ray reaches y = 4",
                  "graded-index air n = 1 + 0.05 y: error against time", "graded_index.png")


def graded_index_image_chart(rows):
    methods_chart(rows, {"adaptive": "GradedAir: Sharma RKN, step doubling (tolerance)", "layers": "LayeredAir: the notes' flat layers (layers)"},
                  "seconds", "rmse", 1e-10, "seconds per 160x60 render, 1 thread (min of 3)", "RMSE against GradedAir at tolerance 1e-9",
                  "the mirage over a hot road, whole pictures: error against time", "graded_index_image.png")


def dispersion_chart(rows):
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    pts = [r for r in rows if int(r["bands"]) < 64]
    x = [float(r["seconds"]) for r in pts]
    y = [float(r["rmse"]) for r in pts]
    ax.loglog(x, y, "o-", label="Whitted, white light split into N bands")
    for xi, yi, r in zip(x, y, pts):
        ax.annotate(r["bands"], (xi, yi), textcoords="offset points", xytext=(3, 3), fontsize=7)
    ax.set_xlabel("seconds per 320x240 render, 1 thread (min of 3)")
    ax.set_ylabel("RMSE against 64 bands")
    ax.set_title("dispersion: an F2 prism over a checkerboard, error against time", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, "dispersion.png")


def thin_film_chart(rows):
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    soap = [r for r in rows if r["what"] == "soap"]
    for step in sorted({r["step_nm"] for r in soap}, key=float):
        pts = [r for r in soap if r["step_nm"] == step]
        x = [float(r["build_ms"]) for r in pts]
        y = [float(r["worst"]) for r in pts]
        ax.loglog(x, y, "o-", label=f"table, {step} nm thickness step (worst)")
        for xi, yi, r in zip(x, y, pts):
            ax.annotate(r["cosines"], (xi, yi), textcoords="offset points", xytext=(3, 3), fontsize=7)
    if soap:
        ax.set_title(f"soap film 20-900 nm: table error against build time (labels: cosines)\n"
                     f"a lookup {float(soap[0]['lookup_ns']):.0f} ns, the exact spectral integral {float(soap[0]['exact_ns']) / 1000:.1f} us", fontsize=9)
    ax.set_xlabel("ms to build the table")
    ax.set_ylabel("worst RGB error against the exact integral (cos >= 0.05)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, "thin_film.png")


def methods_vs_time_chart(rows):
    """Error against prism's reference vs time: a column per scene, linear radiance above,
    the display range (clamped to 1) below; a curve per method."""
    scenes = [("diffuse", "diffuse Cornell box (Cycles renders it too)"), ("area", "the diffuse box under its ceiling light\n(an area light; Cycles renders it too)"),
              ("glass", "Cornell box, glass and mirror balls\n(the reference: 2 x 1024 passes of VCM)"),
              ("povray", "glass box in POV-Ray's model (direct + caustics),\nover the pixels that see walls")]
    scenes = [(scene, title) for scene, title in scenes if any(r["scene"] == scene for r in rows)]
    metrics = [("rmse", "RMSE, linear radiance"), ("rmse_display", "RMSE, display range (radiance clamped to 1)")]
    fig, axes = plt.subplots(2, len(scenes), figsize=(6 * len(scenes), 9), squeeze=False)
    for column, (scene, title) in enumerate(scenes):
        methods = []
        for r in rows:
            if r["scene"] == scene and r["method"] not in methods:
                methods.append(r["method"])
        for row, (key, ylabel) in enumerate(metrics):
            ax = axes[row][column]
            for method in methods:
                points = sorted((float(r["seconds"]), float(r[key])) for r in rows if r["scene"] == scene and r["method"] == method)
                points = [p for p in points if p[1] > 0]
                style = {"Cycles": "k--", "POV-Ray": "k--", "POV-Ray, anti-aliased": "k:"}.get(method, "-")
                ax.loglog([p[0] for p in points], [p[1] for p in points], style, marker="o", label=method)
            ax.set_xlabel("render time (s, 2 threads)")
            ax.set_ylabel(ylabel + "\nagainst prism's reference, its noise removed")
            ax.set_title(title)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8)
    save(fig, "methods_vs_time.png")


def error_vs_time_chart(rows, regions, reference, name):
    """Error against a reference vs time (bench/surfaces_vs_time.py, bench/fog_vs_time.py),
    over the regions (csv name, title) side by side; linear radiance above, the display
    range below; a curve per method, Cycles dashed."""
    metrics = [("rmse", "RMSE, linear radiance"), ("rmse_display", "RMSE, display range (radiance clamped to 1)")]
    fig, axes = plt.subplots(2, len(regions), figsize=(6 * len(regions), 9), squeeze=False)
    for column, (region, title) in enumerate(regions):
        methods = list(dict.fromkeys(r["method"] for r in rows if r["region"] == region))
        for row, (key, ylabel) in enumerate(metrics):
            ax = axes[row][column]
            for method in methods:
                points = sorted((float(r["seconds"]), float(r[key])) for r in rows if r["region"] == region and r["method"] == method)
                points = [p for p in points if p[1] > 0]
                ax.loglog([p[0] for p in points], [p[1] for p in points], "k--" if method == "Cycles" else "-", marker="o", label=method)
            ax.set_xlabel("render time (s, 2 threads)")
            ax.set_ylabel(ylabel + "\nagainst " + reference + ", its noise removed")
            ax.set_title(title)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8)
    save(fig, name)


def blue_noise_chart(rows, spectra):
    """bench/blue_noise.py: the error's spectrum under each sampler at a few sample counts,
    and its RMSE per pixel and after a blur against the samples."""
    counts = sorted({int(r["spp"]) for r in spectra})
    fig, axes = plt.subplots(1, len(counts) + 1, figsize=(4.5 * (len(counts) + 1), 4.5), squeeze=False)
    samplers = list(dict.fromkeys(r["sampler"] for r in rows))
    for column, spp in enumerate(counts):
        ax = axes[0][column]
        for sampler in samplers:
            points = [(float(r["frequency"]), float(r["power"])) for r in spectra if r["sampler"] == sampler and int(r["spp"]) == spp]
            ax.plot([p[0] for p in points], [p[1] for p in points], marker=".", label=sampler)
        ax.axhline(1, color="k", lw=0.5)
        ax.set_xlabel("spatial frequency (cycles a pixel)")
        ax.set_ylabel("the error's power, as a share of its mean")
        ax.set_title("the error's spectrum, %d spp a pixel" % spp)
        ax.set_ylim(bottom=0)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    ax = axes[0][-1]
    for sampler in samplers:
        points = sorted((int(r["spp"]), float(r["rmse"]), float(r["rmse_blur2"])) for r in rows if r["sampler"] == sampler)
        line, = ax.loglog([p[0] for p in points], [p[2] for p in points], marker="o", label=sampler + ", blurred by 2 px")
        ax.loglog([p[0] for p in points], [p[1] for p in points], ls=":", color=line.get_color(), marker=".", label=sampler + ", per pixel")
    ax.set_xlabel("samples a pixel")
    ax.set_ylabel("RMSE, display range, against prism's reference")
    ax.set_title("the area-lit box's path tracer: error per pixel\nand after a Gaussian blur of 2 pixels")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, "blue_noise.png")


def airlight_chart(rows):
    """Whitted's single scattering of a point light in fog: marching against the airlight,
    RMS relative error against time per ray (bench/airlight.cpp)."""
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for method, style, label in (("march", "o-", "marching: steps, a shadow ray at each"), ("airlight", "s-", "airlight: Gauss-Legendre nodes in the angle")):
        points = [(float(r["nanoseconds_per_ray"]), float(r["rms_relative_error"]), r["setting"]) for r in rows if r["method"] == method]
        ax.loglog([p[0] for p in points], [max(p[1], 1e-8) for p in points], style, label=label)
        for x, y, setting in points:
            ax.annotate(setting, (x, max(y, 1e-8)), textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.axhline(6e-8, color="grey", lw=0.8, ls=":")
    ax.set_xlabel("time per camera ray (ns, one thread)")
    ax.set_ylabel("RMS relative error against Simpson in double")
    ax.set_title("Whitted: a point light's single scattering in fog")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, "airlight.png")


def transmittance_chart(rows):
    """Transmittance through media of varying density: residual ratio tracking, ratio
    tracking, the track-length estimator and marching, RMS error against time per ray
    (bench/transmittance.cpp)."""
    media = [("smoke", "smoke: value noise on a 32³ grid"), ("ground", "ground fog (exponential)")]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4))
    for ax, (medium, title) in zip(axes, media):
        for method, style, label in (("residual", "o-", "residual ratio tracking (prism's)"), ("ratio", "s-", "ratio tracking"),
                                     ("track-length", "^-", "track-length (delta tracking)"), ("march", "d--", "marching (biased)")):
            points = [(float(r["nanoseconds_per_ray"]), float(r["rms_error"]), r["setting"]) for r in rows if r["medium"] == medium and r["method"] == method]
            ax.loglog([p[0] for p in points], [max(p[1], 1e-8) for p in points], style, label=label)
            for x, y, setting in points:
                ax.annotate(setting, (x, max(y, 1e-8)), textcoords="offset points", xytext=(4, 4), fontsize=7)
        ax.set_xlabel("time per ray (ns, one thread)")
        ax.set_ylabel("RMS error of the transmittance")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    save(fig, "transmittance.png")


def whitted_glossy_chart(rows):
    """Whitted's error on a rough metal ball against the roughness (bench/whitted_glossy.cpp)."""
    r = [float(x["roughness"]) for x in rows]
    fig, ax = plt.subplots(figsize=(5.6, 4.0))
    ax.plot(r, [100 * float(x["whitted_error"]) for x in rows], "o-", label="Whitted: one mirror ray with the lobe's albedo")
    ax.plot(r, [100 * float(x["reference_noise"]) for x in rows], "s--", label="the reference's own noise")
    ax.set_xlabel("roughness (alpha = roughness²)")
    ax.set_ylabel("RMS error over the ball, % of its mean")
    ax.set_title("What Whitted's mirror ray cuts from a glossy lobe")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, "whitted_glossy.png")


def prism_haze_chart(rows):
    """The namesake in haze (bench/prism_haze.cpp): display-range error against time, a panel
    per region, a curve per method."""
    regions = [("all", "the whole picture"), ("fan", "the fan of colours in the haze"), ("spot", "its spot on the floor"),
               ("beam", "the white beam"), ("prism face", "the prism's lit face")]
    fig, axes = plt.subplots(1, len(regions), figsize=(4.2 * len(regions), 4.0))
    for ax, (region, title) in zip(axes, regions):
        for method in dict.fromkeys(r["method"] for r in rows):
            points = sorted((float(r["seconds"]), float(r["rmse_" + region])) for r in rows if r["method"] == method)
            ax.loglog([p[0] for p in points], [p[1] for p in points], "-", marker="o", label=method)
        ax.set_xlabel("render time (s, 2 threads)")
        ax.set_ylabel("RMSE, display range\nagainst 1024 passes of BDPT")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    save(fig, "prism_haze.png")


def main():
    if (rows := read("prism_haze.csv")):
        prism_haze_chart(rows)
    if (rows := read("methods_vs_time.csv")):
        methods_vs_time_chart(rows)
    if (rows := read("surfaces_vs_time.csv")):
        error_vs_time_chart(rows, [("all", "rough gold, frosted glass, textured and normal-mapped\nvarnished tiles, thin lens (Cycles renders it too)"),
                                   ("caustic", "the frosted ball's caustic on the tiles")], "prism's path-traced reference", "surfaces_vs_time.png")
    if (rows := read("airlight.csv")):
        airlight_chart(rows)
    if (rows := read("transmittance.csv")):
        transmittance_chart(rows)
    if (rows := read("fog_vs_time.csv")):
        error_vs_time_chart(rows, [("all", "a spot light through haze onto a rough glass ball\n(Cycles renders it too)"),
                                   ("caustic", "the volumetric caustic below the ball")], "prism's progressive reference", "fog_vs_time.png")
    if (rows := read("fog_vs_time_vcmref.csv")):
        error_vs_time_chart(rows, [("all", "a spot light through haze onto a rough glass ball\n(Cycles renders it too)"),
                                   ("caustic", "the volumetric caustic below the ball")], "a long VCM reference", "fog_vs_time_vcmref.png")
    if (rows := read("fog_vs_time_cycles.csv")):
        error_vs_time_chart(rows, [("all", "a spot light through haze onto a rough glass ball"), ("caustic", "the volumetric caustic below the ball")],
                            "Cycles' reference", "fog_vs_time_cycles.png")
    if (rows := read("surfaces_vs_time_samplers.csv")):
        error_vs_time_chart(rows, [("all", "rough gold, frosted glass, textured tiles, thin lens:\nthe path tracer's two samplers and Cycles"),
                                   ("caustic", "the frosted ball's caustic on the tiles")], "prism's path-traced reference", "surfaces_vs_time_samplers.png")
    if (rows := read("surfaces_vs_time_bidirectional.csv")):
        error_vs_time_chart(rows, [("all", "rough gold, frosted glass, textured tiles, thin lens:\nthe path tracer, BDPT and VCM"),
                                   ("caustic", "the frosted ball's caustic on the tiles")], "a long VCM reference", "surfaces_vs_time_bidirectional.png")
    if (rows := read("fog_vs_time_samplers.csv")):
        error_vs_time_chart(rows, [("all", "a spot light through haze onto a rough glass ball:\nthe path tracer's two samplers and Cycles"),
                                   ("caustic", "the volumetric caustic below the ball")], "prism's progressive reference", "fog_vs_time_samplers.png")
    if (rows := read("sky_vs_time.csv")):
        titles = {"plain": "a white and a mirror sphere under the photographed sky", "glossy": "rough metal spheres (roughness 0.4, 0.15) under the sky",
                  "frosted": "frosted glass and rough metal under the sky"}
        error_vs_time_chart(rows, [(v, titles[v] + "\n(Cycles renders it too)") for v in dict.fromkeys(r["region"] for r in rows)],
                            "prism's path-traced reference", "sky_vs_time.png")
    if (rows := read("blue_noise.csv")):
        blue_noise_chart(rows, read("blue_noise_spectrum.csv"))
    if (rows := read("accuracy.csv")):
        accuracy_charts(rows)
    if (rows := read("acne.csv")):
        acne_chart(rows)
    if (rows := read("vs_povray.csv")):
        povray_chart(rows)
    if (rows := read("quadric_roots.csv")):
        quadric_chart(rows)
    if (rows := read("csg_composition.csv")):
        composition_chart(rows)
    if (rows := read("kdtree.csv")):
        kdtree_chart(rows)
    if (rows := read("bvh_vs_embree.csv")):
        embree_chart(rows)
    if (rows := read("bvh_vs_embree_sse4.2.csv")):
        embree_chart(rows, "bvh_vs_embree_sse4.2.png", "Embree 3 held to SSE4.2")
    if (rows := read("bvh_vs_embree_prism-avx2.csv")):
        embree_chart(rows, "bvh_vs_embree_prism-avx2.png", "Embree 3", "prism (AVX2 + FMA, 8-wide)")
    if (rows := read("bvh_vs_embree_prism-native.csv")):
        embree_chart(rows, "bvh_vs_embree_prism-native.png", "Embree 3", "prism (-march=native: AVX-512, 8-wide)")
    if (rows := read("bvh_vs_embree_prism-avx2_avx2.csv")):
        embree_chart(rows, "bvh_vs_embree_prism-avx2_avx2.png", "Embree 3 held to AVX2", "prism (AVX2, 8-wide)")
    if (rows := read("bvh_quality.csv")):
        bvh_quality_chart(rows)
    if (rows := read("photon_accuracy.csv")):
        photon_chart(rows)
    if (rows := read("photon_leaks.csv")):
        leak_chart(rows)
    if (rows := read("graded_index.csv")):
        graded_index_chart(rows)
    if (rows := read("graded_index_image.csv")):
        graded_index_image_chart(rows)
    if (rows := read("dispersion.csv")):
        dispersion_chart(rows)
    if (rows := read("thin_film.csv")):
        thin_film_chart(rows)
    if (rows := read("ray_property.csv")):
        ray_property_chart(rows, read("ray_property_before.csv"))
    if (rows := read("whitted_glossy.csv")):
        whitted_glossy_chart(rows)


if __name__ == "__main__":
    main()
