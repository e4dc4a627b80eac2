#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes assets/surfaces/: the pictures of the floor that prism and Blender's Cycles both
# render in bench/surfaces.cpp and bench/cycles_surfaces.py, all made here (MIT):
#   tiles.png         sRGB albedo: 8 x 8 glazed tiles of 16 x 16 texels, each its own
#                     shade of terracotta, slate or cream, with grout between
#   tiles_normal.png  a tangent-space normal map (OpenGL and Blender's: red along +u,
#                     green along +v): each tile's edges bevelled down into the grout,
#                     at most about 8 degrees, and a faint ripple in its glaze
#   tools/make_surfaces.py [OUT_DIR]
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_writer import png  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets", "surfaces")
SIZE, TILE = 128, 16


def hash01(i, j, k=0):
    h = (i * 73856093) ^ (j * 19349663) ^ (k * 83492791)
    h = (h ^ (h >> 13)) * 1274126177 & 0xFFFFFFFF
    return (h & 0xFFFF) / 65535.0


def grout(x, y):
    return x % TILE == 0 or y % TILE == 0


def tiles(x, y):
    if grout(x, y):
        return (0.55, 0.53, 0.5)
    i, j = x // TILE, y // TILE
    palette = [(0.78, 0.36, 0.2), (0.3, 0.34, 0.4), (0.86, 0.8, 0.66)]
    base = palette[int(3 * hash01(i, j)) % 3]
    t = 0.8 + 0.2 * hash01(i, j, 1)
    return tuple(c * t for c in base)


def tiles_normal(x, y):
    """The slope (du, dv) of the surface's height at texel (x, y), as a unit normal in
    [0, 1]^3; image y runs down, v up."""
    if grout(x, y):
        return (0.5, 0.5, 1.0)
    a, b = x % TILE, y % TILE  # 1 .. 15 inside a tile
    slope_u = slope_v = 0.0
    bevel = 0.14  # tan(8 degrees)
    if a <= 2:
        slope_u = bevel  # rising from the grout on the left
    elif a >= 14:
        slope_u = -bevel
    if b <= 2:
        slope_v = -bevel  # rising from the grout above: the surface falls toward +v
    elif b >= 14:
        slope_v = bevel
    slope_u += 0.03 * math.sin(2 * math.pi * (x + 0.5 * y) / 9)
    # The normal of a height field h(u, v): (-dh/du, -dh/dv, 1), normalised.
    nx, ny, nz = -slope_u, -slope_v, 1.0
    n = math.sqrt(nx * nx + ny * ny + nz * nz)
    return (0.5 + 0.5 * nx / n, 0.5 + 0.5 * ny / n, 0.5 + 0.5 * nz / n)


png(os.path.join(out, "tiles.png"), SIZE, SIZE, 3, tiles)
png(os.path.join(out, "tiles_normal.png"), SIZE, SIZE, 3, tiles_normal)
print("make_surfaces: 2 pictures of %d x %d in %s" % (SIZE, SIZE, out))
