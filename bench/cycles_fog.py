# SPDX-License-Identifier: MIT
# Blender's Cycles renders bench/fog.cpp's scene (issue 36's volumetric caustic): a spot
# light shines down through haze onto a rough glass ball, over a floor, before a wall.
# Headless:
#
#   blender -b --factory-startup --python bench/cycles_fog.py -- OUT.pfm SAMPLES [SEED] [WIDTH]
#
# (the height is 3/4 of WIDTH). prism's pieces as Cycles 3.4 expresses them:
#   FilledAir<Fog> in a box       a box mesh with no surface shader (the boundary passes
#                                 light unchanged) and a homogeneous volume: Volume Scatter
#                                 (white, density sigma_s, anisotropy g, Henyey-Greenstein)
#                                 plus Volume Absorption (black, density sigma_a); the box is
#                                 1 cm larger where it meets the floor and the wall, so no
#                                 two surfaces coincide (nothing reaches past them)
#   SpotLight (bench's CyclesSpot) a spot of radius 0, power 4 pi I, spot size twice the
#                                 outer angle, blend (cos inner - cos outer) / (1 - cos outer):
#                                 Cycles' smoothstep over [cos outer, cos inner], times
#                                 Cycles' own cos(angle) factor, which CyclesSpot copies
#   Plane                         a quad 200 m across
#   RoughDielectric               Glass BSDF, GGX, the same index and roughness
# Volume bounces 64 (the factory default is 0: single scattering only) and volume sampling
# by multiple importance (distance and equiangular), the default. The settings that keep
# Cycles radiometric and unbiased are bench/cycles_common.py's.
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_common import arguments, blender, camera, empty_scene, material, quad, render_to_pfm, sphere  # noqa: E402

out_path, samples, seed, width, rest = arguments()

scene = empty_scene(samples, seed, width)
scene.render.resolution_y = width * 3 // 4
scene.cycles.volume_bounces = 64

world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (0, 0, 0, 1)
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world

quad("floor", [(-100, 0, 100), (100, 0, 100), (100, 0, -100), (-100, 0, -100)], material("floor", "diffuse", (0.7, 0.7, 0.7)))
quad("wall", [(-100, 0, -3), (100, 0, -3), (100, 100, -3), (-100, 100, -3)], material("wall", "diffuse", (0.5, 0.5, 0.5)))
sphere("ball", (0, 1.6, 0), 0.6, material("glass", "glass", (1.0, 1.0, 1.0), 0.1, 1.5))


def haze(absorption, scattering, g):
    m = bpy.data.materials.new("haze")
    m.use_nodes = True
    m.cycles.homogeneous_volume = True
    m.cycles.volume_sampling = "MULTIPLE_IMPORTANCE"
    nodes, links = m.node_tree.nodes, m.node_tree.links
    nodes.clear()
    scatter = nodes.new("ShaderNodeVolumeScatter")
    scatter.inputs["Color"].default_value = (1, 1, 1, 1)
    scatter.inputs["Density"].default_value = scattering
    scatter.inputs["Anisotropy"].default_value = g
    absorb = nodes.new("ShaderNodeVolumeAbsorption")
    absorb.inputs["Color"].default_value = (0, 0, 0, 1)
    absorb.inputs["Density"].default_value = absorption
    both = nodes.new("ShaderNodeAddShader")
    links.new(scatter.outputs["Volume"], both.inputs[0])
    links.new(absorb.outputs["Volume"], both.inputs[1])
    out = nodes.new("ShaderNodeOutputMaterial")
    links.new(both.outputs["Shader"], out.inputs["Volume"])
    return m


# prism's region {-5, 0, -3} to {5, 6, 6}, reaching 1 cm under the floor and behind the wall.
lo, hi = (-5, -0.01, -3.01), (5, 6, 6)
corners = [(x, y, z) for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
mesh = bpy.data.meshes.new("haze")
mesh.from_pydata([blender(c) for c in corners], [], faces)
box = bpy.data.objects.new("haze", mesh)
box.data.materials.append(haze(0.01, 0.12, 0.3))
scene.collection.objects.link(box)

outer, inner = 12.0, 9.0
light = bpy.data.lights.new("spot", type="SPOT")
light.energy = 4 * math.pi * 60.0
light.shadow_soft_size = 0.0
light.color = (1, 1, 1)
light.spot_size = math.radians(2 * outer)
light.spot_blend = (math.cos(math.radians(inner)) - math.cos(math.radians(outer))) / (1 - math.cos(math.radians(outer)))
lamp = bpy.data.objects.new("spot", light)
lamp.location = blender((0, 4.5, 0))  # Blender's spot shines along its -z, prism's -y: no rotation
scene.collection.objects.link(lamp)

camera((0, 2.0, 6.5), (0, 1.3, 0), 45.0)

render_to_pfm(scene, out_path, samples)
