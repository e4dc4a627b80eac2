# SPDX-License-Identifier: MIT
# Blender's Cycles renders bench/sky.cpp's scene: a white and a mirror sphere on a grey
# floor under the photographed sky assets/sky/sunrise.exr, the outside reference for
# prism's EnvironmentMap (its layout on the sphere, its radiance, its sampling). Headless:
#
#   blender -b --factory-startup --python bench/cycles_sky.py -- OUT.pfm SAMPLES [SEED] [SIZE] [glossy]
#
# `glossy`: the spheres rough instead (bench_sky's glossy scene): Glossy BSDFs, GGX, of colour
# 0.9 and roughness 0.4 (left) and 0.15 (right). `frosted`: the left one frosted glass
# instead (a Glass BSDF, GGX, index 1.5, roughness 0.3).
#
# prism is right-handed with y up, Blender right-handed with z up: (x, y, z) -> (x, -z, y),
# a rotation. prism's image looks toward -z at its middle column (u = 1/2) and turns
# counterclockwise from above by its rotation; Cycles' equirectangular lookup looks toward
# +x there (u = 1/2 - atan2(y, x) / 2 pi). So the world's direction is turned about
# Blender's z by -(90 + rotation) degrees before the lookup (a Mapping node of type Vector).
# The settings that keep Cycles radiometric and unbiased are bench/cycles_common.py's; the
# image is read as linear ("Linear" colour space, what the EXR holds), strength 1.
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_common import arguments, camera, empty_scene, material, quad, render_to_pfm, sphere  # noqa: E402

out_path, samples, seed, size, rest = arguments()
variant = rest[0] if rest else ""
here = os.path.dirname(os.path.abspath(__file__))
SKY = os.path.join(here, "..", "assets", "sky", "sunrise.exr")
ROTATION = 150.0  # bench/sky.cpp's, degrees about prism's +y


scene = empty_scene(samples, seed, size)

world = bpy.data.worlds.new("sky")
world.use_nodes = True
nodes, links = world.node_tree.nodes, world.node_tree.links
background = nodes["Background"]
background.inputs["Strength"].default_value = 1.0
texture = nodes.new("ShaderNodeTexEnvironment")
texture.image = bpy.data.images.load(SKY)
texture.image.colorspace_settings.name = "Linear"
texture.interpolation = "Linear"
texture.projection = "EQUIRECTANGULAR"
coordinates = nodes.new("ShaderNodeTexCoord")
mapping = nodes.new("ShaderNodeMapping")
mapping.vector_type = "VECTOR"
mapping.inputs["Rotation"].default_value = (0.0, 0.0, math.radians(-(90.0 + ROTATION)))
links.new(coordinates.outputs["Generated"], mapping.inputs["Vector"])
links.new(mapping.outputs["Vector"], texture.inputs["Vector"])
links.new(texture.outputs["Color"], background.inputs["Color"])
scene.world = world


quad("floor", [(-5, 0, 5), (5, 0, 5), (5, 0, -5), (-5, 0, -5)], material("grey", "diffuse", (0.5, 0.5, 0.5)))
if variant == "frosted":
    sphere("frosted", (-0.8, 0.6, 0), 0.6, material("frosted", "glass", (1.0, 1.0, 1.0), 0.3, 1.5))
    sphere("satin", (0.8, 0.6, 0), 0.6, material("satin", "glossy", (0.9, 0.9, 0.9), 0.15))
elif variant == "glossy":
    sphere("rough", (-0.8, 0.6, 0), 0.6, material("rough", "glossy", (0.9, 0.9, 0.9), 0.4))
    sphere("satin", (0.8, 0.6, 0), 0.6, material("satin", "glossy", (0.9, 0.9, 0.9), 0.15))
else:
    sphere("white", (-0.8, 0.6, 0), 0.6, material("white", "diffuse", (0.8, 0.8, 0.8)))
    sphere("mirror", (0.8, 0.6, 0), 0.6, material("mirror", "glossy", (0.9, 0.9, 0.9)))

camera((0, 1.5, 5), (0, 0.5, 0), 50.0)

render_to_pfm(scene, out_path, samples)
