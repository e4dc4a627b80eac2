#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes assets/still_life/: a textured, multi-material OBJ model with its .mtl and its
# pictures, all made here (MIT, as the rest of prism), for examples/still_life.cpp:
#   a plank floor (map_Kd), a brick pedestal (map_Kd and a bump map of its mortar),
#   a painted ball (map_Kd and a tangent-space normal map of dimples, glossy Ks),
#   and a glass cube (d 0.1, Ni 1.5).
#   tools/make_still_life.py [OUT_DIR]
# Only the Python standard library: PNGs written with zlib (tools/png_writer.py).
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png_writer  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "assets", "still_life")
os.makedirs(out, exist_ok=True)


def png(name, width, height, channels, pixel):
    """Writes out/name (tools/png_writer.py)."""
    png_writer.png(os.path.join(out, name), width, height, channels, pixel)


def hash01(i, j, k=0):
    h = (i * 73856093) ^ (j * 19349663) ^ (k * 83492791)
    h = (h ^ (h >> 13)) * 1274126177 & 0xFFFFFFFF
    return (h & 0xFFFF) / 65535.0


# Planks: 4 boards across, each its own shade, with grain lines along v.
def planks(x, y):
    board = x * 4 // 256
    shade = 0.75 + 0.25 * hash01(board, 1)
    grain = 0.9 + 0.1 * math.sin(0.35 * y + 6 * hash01(board, 2) + 3 * math.sin(0.05 * y + board))
    seam = 0.55 if x % 64 in (0, 63) else 1.0
    s = shade * grain * seam
    return (0.62 * s, 0.42 * s, 0.25 * s)


png("planks.png", 256, 256, 3, planks)


# Bricks: 8 rows of 4 bricks, offset every other row, with mortar between.
def brick_at(x, y):
    row = y // 32
    shifted = x + (16 if row % 2 else 0)
    col = (shifted // 64) % 4
    mortar = y % 32 < 3 or shifted % 64 < 3
    return row, col, mortar


def bricks(x, y):
    row, col, mortar = brick_at(x, y)
    if mortar:
        return (0.7, 0.68, 0.62)
    t = 0.8 + 0.2 * hash01(row, col)
    return (0.62 * t, 0.25 * t, 0.18 * t)


png("bricks.png", 256, 256, 3, bricks)
png("bricks_height.png", 256, 256, 1, lambda x, y: (0.0 if brick_at(x, y)[2] else 1.0,))


# The ball: six painted segments round its equator, white caps.
def ball(x, y):
    v = 1 - (y + 0.5) / 256
    if v < 0.12 or v > 0.88:
        return (0.9, 0.9, 0.88)
    seg = int((x + 0.5) / 256 * 6)
    return [(0.85, 0.12, 0.1), (0.95, 0.75, 0.1), (0.1, 0.45, 0.8), (0.9, 0.9, 0.88), (0.15, 0.6, 0.25), (0.95, 0.5, 0.1)][seg]


png("ball.png", 256, 128, 3, lambda x, y: ball(x, y * 2))


# Dimples: a grid of round hollows, as tangent-space normals (OpenGL: green along +v).
def dimples(x, y):
    cx, cy = (x % 16) - 7.5, (y % 16) - 7.5
    r = math.hypot(cx, cy)
    if r >= 6:
        return (0.5, 0.5, 1.0)
    slope = 0.6 * math.sin(math.pi * r / 6)
    # Into a hollow: the normal leans toward its centre; image y runs down, v up.
    nx, ny = -slope * cx / max(r, 1e-6), slope * cy / max(r, 1e-6)
    nz = 1.0
    n = math.sqrt(nx * nx + ny * ny + nz * nz)
    return (0.5 + 0.5 * nx / n, 0.5 + 0.5 * ny / n, 0.5 + 0.5 * nz / n)


png("dimples.png", 256, 128, 3, lambda x, y: dimples(x, y))

with open(os.path.join(out, "still_life.mtl"), "w") as f:
    f.write("""# prism still life (tools/make_still_life.py)
newmtl planks
Kd 1 1 1
Ks 0.04 0.04 0.04
Ns 60
map_Kd planks.png

newmtl bricks
Kd 1 1 1
Ks 0 0 0
map_Kd bricks.png
bump -bm 1 bricks_height.png

newmtl ball
Kd 0.75 0.75 0.75
Ks 0.2 0.2 0.2
Ns 300
map_Kd ball.png
norm dimples.png

newmtl glass
Kd 1 1 1
d 0.1
Ni 1.5
illum 7
""")

v, vt, vn, faces = [], [], [], []


def vertex(p, uv=None, n=None):
    v.append(p)
    if uv is not None:
        vt.append(uv)
    if n is not None:
        vn.append(n)
    return len(v), len(vt) if uv is not None else None, len(vn) if n is not None else None


def corner(i):
    p, t, n = i
    return f"{p}/{t or ''}/{n}" if n else (f"{p}/{t}" if t else f"{p}")


def quad(a, b, c, d, material):
    faces.append((material, [a, b, c, d]))


# The floor: 8 x 8 at y = 0, its planks repeated 4 times each way.
fl = [vertex((x, 0, z), (u, w)) for (x, z, u, w) in [(-4, 4, 0, 0), (4, 4, 4, 0), (4, -4, 4, 4), (-4, -4, 0, 4)]]
quad(*fl, "planks")

# The pedestal: a box 1.2 wide, 0.9 tall, 1.2 deep, at the origin; its sides each one
# picture across (u right, v up, seen from outside), counter-clockwise from outside.
w, h = 0.6, 0.9
sides = [
    ((-w, 0, w), (w, 0, w), (w, h, w), (-w, h, w)),    # +z
    ((w, 0, w), (w, 0, -w), (w, h, -w), (w, h, w)),    # +x
    ((w, 0, -w), (-w, 0, -w), (-w, h, -w), (w, h, -w)),  # -z
    ((-w, 0, -w), (-w, 0, w), (-w, h, w), (-w, h, -w)),  # -x
    ((-w, h, w), (w, h, w), (w, h, -w), (-w, h, -w)),  # top
]
for s in sides:
    quad(*[vertex(p, uv) for p, uv in zip(s, [(0, 0), (1.2, 0), (1.2, 0.9), (0, 0.9)])], "bricks")

# The ball: radius 0.45 on the pedestal, 48 x 24, uv as Sphere's (u round +y from +z
# through +x, -z, -x; v from the bottom), smooth normals.
r, cy = 0.45, h + 0.45
grid = {}
for j in range(25):
    theta = math.pi * j / 24  # from the top
    for i in range(49):
        phi = 2 * math.pi * i / 48
        # u = 1/2 + atan2(-x, -z) / 2 pi: x = -sin(2 pi (u - 1/2)) sin(theta), z = -cos(...) sin(theta)
        a = 2 * math.pi * (i / 48 - 0.5)
        n = (-math.sin(a) * math.sin(theta), math.cos(theta), -math.cos(a) * math.sin(theta))
        grid[i, j] = vertex((r * n[0], cy + r * n[1], r * n[2]), (i / 48, 1 - j / 24), n)
for j in range(24):
    for i in range(48):
        a, b, c, d = grid[i, j + 1], grid[i + 1, j + 1], grid[i + 1, j], grid[i, j]
        if j == 0:
            faces.append(("ball", [a, b, c]))
        elif j == 23:
            faces.append(("ball", [a, b, d]))
        else:
            quad(a, b, c, d, "ball")

# The glass cube: 0.7 on a side, turned, beside the pedestal.
e = 0.35
cx, cz, turn = 1.45, 0.55, math.radians(25)


def place(x, y, z):
    return (cx + x * math.cos(turn) + z * math.sin(turn), y, cz - x * math.sin(turn) + z * math.cos(turn))


cube = [place(x, y, z) for (x, y, z) in [(-e, 0, -e), (e, 0, -e), (e, 0, e), (-e, 0, e), (-e, 2 * e, -e), (e, 2 * e, -e), (e, 2 * e, e), (-e, 2 * e, e)]]
ci = [vertex(p) for p in cube]
for f in [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)]:
    quad(*[ci[k] for k in f], "glass")

with open(os.path.join(out, "still_life.obj"), "w") as f:
    f.write("# prism still life (tools/make_still_life.py): planks, a brick pedestal, a dimpled ball, a glass cube\n")
    f.write("mtllib still_life.mtl\n")
    for p in v:
        f.write("v %.6f %.6f %.6f\n" % p)
    for t in vt:
        f.write("vt %.6f %.6f\n" % t)
    for n in vn:
        f.write("vn %.6f %.6f %.6f\n" % n)
    current = None
    for material, corners in faces:
        if material != current:
            f.write(f"usemtl {material}\n")
            current = material
        f.write("f " + " ".join(corner(c) for c in corners) + "\n")
print(f"make_still_life: {len(v)} vertices, {len(faces)} faces, 5 pictures in {out}")
