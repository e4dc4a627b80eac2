# SPDX-License-Identifier: MIT
# Blender's Cycles renders bench/surfaces.cpp's scene (issue 35's surfaces): a rough gold
# and a rough glass sphere on a varnished tile floor with an image texture and a normal
# map, through a thin lens, under a point light and a dim uniform sky. Headless:
#
#   blender -b --factory-startup --python bench/cycles_surfaces.py -- OUT.pfm SAMPLES [SEED] [SIZE]
#
# Each of prism's materials as Cycles 3.4 expresses it exactly:
#   RoughConductor with ConstantKr    Glossy BSDF, GGX (no Fresnel), the same colour
#   RoughDielectric                   Glass BSDF, GGX, the same index
#   Mix(Diffuse, RoughConductor with ComplexIor n = 1.5, k = 0), weight w
#                                     Mix Shader of factor w: a Diffuse BSDF and a Principled
#                                     BSDF with a black base, specular 0.5 and no tint, whose
#                                     Fresnel, F0 + (1 - F0) (F(n, cos) - F0) / (1 - F0) with
#                                     F0 = 0.08 specular = 0.04 and n = 1.5, is the dielectric's
#   NormalMapped(tangent space)       a Normal Map node on the UV map (MikkTSpace tangents,
#                                     which on a flat quad are dp/du and dp/dv, prism's)
#   nearest texel                     Image Texture, "Closest"
#   thin lens, radius r, focus d      depth of field with f-stop = focal length / (2 r)
#   PointLight of intensity I         a point light of radius 0 and power 4 pi I
#   EnvironmentLight of radiance L    the world's background colour L, strength 1
# prism is right-handed with y up, Blender right-handed with z up: (x, y, z) -> (x, -z, y).
# The settings that keep Cycles radiometric and unbiased are bench/cycles_common.py's.
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_common import arguments, blender, camera, empty_scene, material, quad, render_to_pfm, sphere  # noqa: E402

out_path, samples, seed, size, rest = arguments()
here = os.path.dirname(os.path.abspath(__file__))
ASSETS = os.path.join(here, "..", "assets", "surfaces")


scene = empty_scene(samples, seed, size)

world = bpy.data.worlds.new("sky")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.1, 0.12, 0.16, 1)
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
scene.world = world


def image(nodes, name, colorspace):
    texture = nodes.new("ShaderNodeTexImage")
    texture.image = bpy.data.images.load(os.path.join(ASSETS, name))
    texture.image.colorspace_settings.name = colorspace
    texture.interpolation = "Closest"
    texture.extension = "REPEAT"
    uv = nodes.new("ShaderNodeUVMap")
    uv.uv_map = "UVMap"
    nodes.id_data.links.new(uv.outputs["UV"], texture.inputs["Vector"])
    return texture


def glazed_tiles():
    m = bpy.data.materials.new("tiles")
    m.use_nodes = True
    nodes, links = m.node_tree.nodes, m.node_tree.links
    nodes.clear()
    albedo = image(nodes, "tiles.png", "sRGB")
    normals = image(nodes, "tiles_normal.png", "Non-Color")
    normal_map = nodes.new("ShaderNodeNormalMap")
    normal_map.space = "TANGENT"
    normal_map.uv_map = "UVMap"
    normal_map.inputs["Strength"].default_value = 1.0
    links.new(normals.outputs["Color"], normal_map.inputs["Color"])
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Roughness"].default_value = 0.0
    links.new(albedo.outputs["Color"], diffuse.inputs["Color"])
    links.new(normal_map.outputs["Normal"], diffuse.inputs["Normal"])
    varnish = nodes.new("ShaderNodeBsdfPrincipled")
    varnish.distribution = "GGX"
    varnish.inputs["Base Color"].default_value = (0, 0, 0, 1)
    varnish.inputs["Metallic"].default_value = 0.0
    varnish.inputs["Specular"].default_value = 0.5
    varnish.inputs["Specular Tint"].default_value = 0.0
    varnish.inputs["Roughness"].default_value = 0.2
    varnish.inputs["Anisotropic"].default_value = 0.0
    varnish.inputs["Sheen"].default_value = 0.0
    varnish.inputs["Clearcoat"].default_value = 0.0
    varnish.inputs["Subsurface"].default_value = 0.0
    varnish.inputs["Transmission"].default_value = 0.0
    varnish.inputs["Emission Strength"].default_value = 0.0
    links.new(normal_map.outputs["Normal"], varnish.inputs["Normal"])
    mix = nodes.new("ShaderNodeMixShader")
    mix.inputs["Fac"].default_value = 0.3
    links.new(diffuse.outputs["BSDF"], mix.inputs[1])
    links.new(varnish.outputs["BSDF"], mix.inputs[2])
    out = nodes.new("ShaderNodeOutputMaterial")
    links.new(mix.outputs["Shader"], out.inputs["Surface"])
    return m


# prism's Quad({-2, 0, 2}, {4, 0, 0}, {0, 0, -4}): uv (s, t) along its two edges.
quad("floor", [(-2, 0, 2), (2, 0, 2), (2, 0, -2), (-2, 0, -2)], glazed_tiles(), [(0, 0), (1, 0), (1, 1), (0, 1)])
sphere("gold", (0.7, 0.45, 0.2), 0.45, material("gold", "glossy", (0.95, 0.75, 0.33), 0.3))
sphere("glass", (-0.6, 0.5, 0.0), 0.5, material("glass", "glass", (1.0, 1.0, 1.0), 0.15, 1.5))

light = bpy.data.lights.new("light", type="POINT")
light.energy = 4 * math.pi * 25.0
light.shadow_soft_size = 0.0
light.color = (1, 1, 1)
lamp = bpy.data.objects.new("light", light)
lamp.location = blender((-1.3, 2.8, -1.4))
scene.collection.objects.link(lamp)

cam = camera((0, 2.0, 3.6), (0, 0.35, 0), 40.0)
cam.dof.use_dof = True
cam.dof.focus_distance = 3.74
cam.dof.aperture_blades = 0
cam.dof.aperture_ratio = 1.0
cam.dof.aperture_fstop = cam.lens * 1e-3 / (2 * 0.04)  # Cycles' lens radius: focal length / (2 f-stop)

render_to_pfm(scene, out_path, samples)
