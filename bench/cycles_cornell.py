# SPDX-License-Identifier: MIT
# Blender's Cycles renders shared/scenes/cornell_diffuse.md, the outside reference for
# prism's diffuse Cornell box. Run headless:
#
#   blender -b --factory-startup --python bench/cycles_cornell.py -- OUT.pfm SAMPLES [SEED] [SIZE] [--area]
#
# --area lights the box by its ceiling light instead of the point light: a rectangle of
# 1.30 x 1.05 at y = 5.549 facing down, an Emission shader of strength 37 on its front and
# none on its back (Cycles' mesh emission is two-sided), which is radiance 37 W/(m^2 sr):
# Blender's manual, "a strength of 1.0 ... the object will have exactly the color in the
# image" (examples/scenes/cornell.hpp's cornell_ceiling_light).
#   blender -b --factory-startup --python bench/cycles_cornell.py -- --calibrate OUT.txt
#
# The scene's coordinates are the .pov files' (y up, camera along +z); Blender is z up
# and right-handed, so (x, y, z) -> (x, z, y): a reflection, which turns the left-handed
# POV frame into Blender's right-handed one and keeps the picture.
#
# The settings that keep Cycles radiometric and unbiased are bench/cycles_common.py's; the
# world is black (the factory world emits grey).
#
# --calibrate measures Blender's point-light power per unit of radiant intensity: a
# diffuse plane of albedo 0.5 two metres below a light of 100 W, seen by a small
# orthographic camera looking straight down, reads L = (0.5 / pi) I / h^2; the script
# writes P / I (4 pi = 12.566 when the light is an isotropic point of radiant intensity
# P / (4 pi)).
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_common import empty_scene, material, render_to_pfm, render_to_pixels  # noqa: E402

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
area = "--area" in argv
argv = [a for a in argv if a != "--area"]
calibrate = bool(argv) and argv[0] == "--calibrate"
if calibrate:
    argv = argv[1:]
out_path = argv[0]
samples = int(argv[1]) if len(argv) > 1 and not calibrate else 64
seed = int(argv[2]) if len(argv) > 2 else 0
size = int(argv[3]) if len(argv) > 3 else 256

W = 5.55
INTENSITY = 20.0  # W/sr, each channel (cornell_diffuse.md)


def blender(p):
    """POV-style (x, y, z) -> Blender (x, z, y)."""
    return (p[0], p[2], p[1])


scene = empty_scene(samples, seed, size)
cycles = scene.cycles

world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (0, 0, 0, 1)
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world


def diffuse(name, rgb):
    return material(name, "diffuse", rgb)


def quad(name, corners, surface):
    """A one-sided-looking (Cycles shades both sides) quad from four POV-style corners."""
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([blender(c) for c in corners], [], [(0, 1, 2, 3)])
    obj = bpy.data.objects.new(name, mesh)
    obj.data.materials.append(surface)
    scene.collection.objects.link(obj)


def point_light(position, power):
    light = bpy.data.lights.new("light", type="POINT")
    light.energy = power
    light.shadow_soft_size = 0.0  # radius 0: an ideal point
    light.color = (1, 1, 1)
    obj = bpy.data.objects.new("light", light)
    obj.location = blender(position)
    scene.collection.objects.link(obj)


def camera(position, look_at, fov_deg, ortho_scale=None):
    cam = bpy.data.cameras.new("camera")
    if ortho_scale:
        cam.type = "ORTHO"
        cam.ortho_scale = ortho_scale
    else:
        cam.sensor_fit = "HORIZONTAL"
        cam.angle = math.radians(fov_deg)
    obj = bpy.data.objects.new("camera", cam)
    obj.location = blender(position)
    d = [look_at[i] - position[i] for i in range(3)]
    # Point the camera's -Z at the target, its +Y toward Blender's +z (POV's +y).
    from mathutils import Vector
    obj.rotation_euler = Vector(blender(d)).to_track_quat("-Z", "Y").to_euler()
    scene.collection.objects.link(obj)
    scene.camera = obj


if calibrate:
    h = 2.0
    power = 100.0
    quad("plane", [(-5, 0, -5), (5, 0, -5), (5, 0, 5), (-5, 0, 5)], diffuse("grey", (0.5, 0.5, 0.5)))
    point_light((0, h, 0), power)
    camera((0, 1.0, 0), (0, 0, 0.0001), 0, ortho_scale=0.02)
    scene.render.resolution_x = scene.render.resolution_y = 16
    cycles.samples = 256
    w, hgt, px, seconds = render_to_pixels(scene)
    radiance = sum(px[i] for i in range(0, len(px), 4)) / (w * hgt)
    intensity = radiance * math.pi / 0.5 * h * h
    with open(out_path, "w") as f:
        f.write("power_W,radiance,intensity_W_per_sr,power_over_intensity\n")
        f.write("%g,%.6g,%.6g,%.6g\n" % (power, radiance, intensity, power / intensity))
    print("cycles calibration: L = %.6g, I = %.6g W/sr, P / I = %.5f (4 pi = %.5f)" % (radiance, intensity, power / intensity, 4 * math.pi))
    sys.exit(0)

white = diffuse("white", (0.6, 0.6, 0.6))
red = diffuse("red", (0.6, 0.08, 0.08))
green = diffuse("green", (0.08, 0.6, 0.08))
quad("floor", [(0, 0, 0), (W, 0, 0), (W, 0, W), (0, 0, W)], white)
quad("ceiling", [(0, W, 0), (0, W, W), (W, W, W), (W, W, 0)], white)
quad("back", [(0, 0, W), (W, 0, W), (W, W, W), (0, W, W)], white)
quad("left", [(0, 0, 0), (0, 0, W), (0, W, W), (0, W, 0)], red)
quad("right", [(W, 0, 0), (W, W, 0), (W, W, W), (W, 0, W)], green)
if area:
    lamp = bpy.data.materials.new("lamp")
    lamp.use_nodes = True
    nodes = lamp.node_tree.nodes
    nodes.clear()
    front = nodes.new("ShaderNodeEmission")
    front.inputs["Color"].default_value = (1, 1, 1, 1)
    front.inputs["Strength"].default_value = 37.0
    back = nodes.new("ShaderNodeEmission")
    back.inputs["Strength"].default_value = 0.0
    geometry = nodes.new("ShaderNodeNewGeometry")
    mix = nodes.new("ShaderNodeMixShader")
    out = nodes.new("ShaderNodeOutputMaterial")
    links = lamp.node_tree.links
    links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
    links.new(front.outputs["Emission"], mix.inputs[1])
    links.new(back.outputs["Emission"], mix.inputs[2])
    links.new(mix.outputs["Shader"], out.inputs["Surface"])
    # Wound so that its normal points down (-y, Blender's -z).
    quad("lamp", [(2.13, 5.549, 2.27), (2.13, 5.549, 3.32), (3.43, 5.549, 3.32), (3.43, 5.549, 2.27)], lamp)
else:
    point_light((2.78, 5.35, 2.60), 4 * math.pi * INTENSITY)
camera((2.78, 2.73, -8.0), (2.78, 2.73, 0.0), 40.0)

render_to_pfm(scene, out_path, samples)
