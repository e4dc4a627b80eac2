# SPDX-License-Identifier: MIT
# What bench/cycles_cornell.py and bench/cycles_sky.py share inside Blender: the settings
# that keep Cycles radiometric and unbiased, and a render written as PFM.
#
# CPU, 2 threads, view transform Standard with no look, exposure 0, gamma 1 (the EXR holds
# scene-linear radiance anyway), point lights of radius 0, no clamping, light threshold 0,
# adaptive sampling and denoising off, Filter Glossy off (it blurs a mirror after a diffuse
# bounce), 64 bounces of everything, a 1-pixel box filter. The render is saved as float EXR,
# read back inside Blender (Debian has no python3-openexr) and written as PFM. And the
# pieces of a prism scene in Blender's terms: prism is right-handed with y up, Blender
# right-handed with z up, so a point (x, y, z) is (x, -z, y), a rotation.
import math
import os
import struct
import sys
import tempfile
import time

import bpy
from mathutils import Vector


def arguments():
    """The script's arguments after Blender's `--`: OUT.pfm [SAMPLES] [SEED] [SIZE] [more...],
    as (out_path, samples (64), seed (0), size (256), the rest)."""
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    return (argv[0], int(argv[1]) if len(argv) > 1 else 64, int(argv[2]) if len(argv) > 2 else 0, int(argv[3]) if len(argv) > 3 else 256,
            argv[4:])


def blender(p):
    """prism (x, y, z) -> Blender (x, -z, y)."""
    return (p[0], -p[2], p[1])


def quad(name, corners, m, uvs=None):
    """A quad of four prism corners with material m, and a UV map "UVMap" of `uvs` (one per corner) if given."""
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([blender(c) for c in corners], [], [(0, 1, 2, 3)])
    if uvs:
        layer = mesh.uv_layers.new(name="UVMap")
        for loop in mesh.loops:
            layer.data[loop.index].uv = uvs[loop.vertex_index]
    obj = bpy.data.objects.new(name, mesh)
    obj.data.materials.append(m)
    bpy.context.scene.collection.objects.link(obj)


def sphere(name, centre, radius, m):
    """A smooth-shaded UV sphere of 256 x 128 segments: Cycles' stand-in for prism's true sphere."""
    bpy.ops.mesh.primitive_uv_sphere_add(segments=256, ring_count=128, radius=radius, location=blender(centre))
    obj = bpy.context.active_object
    bpy.ops.object.shade_smooth()
    obj.data.materials.append(m)


def camera(position, look_at, fov_deg):
    """A camera at prism's `position` looking at `look_at`, fov_deg across (prism's Camera::fov), made the scene's; returns its data."""
    cam = bpy.data.cameras.new("camera")
    cam.sensor_fit = "HORIZONTAL"
    cam.angle = math.radians(fov_deg)
    obj = bpy.data.objects.new("camera", cam)
    obj.location = blender(position)
    obj.rotation_euler = Vector(blender([look_at[i] - position[i] for i in range(3)])).to_track_quat("-Z", "Y").to_euler()
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj
    return cam


def empty_scene(samples, seed, size):
    """The factory scene emptied of objects, set up as above; returns it."""
    scene = bpy.context.scene
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = samples
    cycles.seed = seed
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.light_sampling_threshold = 0.0
    for bounces in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces", "transparent_max_bounces"):
        setattr(cycles, bounces, 64)
    cycles.caustics_reflective = True
    cycles.caustics_refractive = True
    cycles.blur_glossy = 0.0
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    scene.render.threads_mode = "FIXED"
    scene.render.threads = 2
    scene.render.resolution_x = scene.render.resolution_y = size
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.display_settings.display_device = "sRGB"
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.exr_codec = "NONE"
    return scene


def material(name, kind, rgb, roughness=0.0, ior=1.5):
    """A material of one BSDF: "diffuse" (Lambertian), "glossy" (a mirror of colour rgb,
    or at a roughness above 0 single-scattering GGX with alpha = roughness^2 and no Fresnel:
    prism's RoughConductor with ConstantKr) or "glass" (Cycles' Glass BSDF, GGX, of index
    ior: prism's RoughDielectric)."""
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes = m.node_tree.nodes
    nodes.clear()
    kinds = {"diffuse": "ShaderNodeBsdfDiffuse", "glossy": "ShaderNodeBsdfGlossy", "glass": "ShaderNodeBsdfGlass"}
    bsdf = nodes.new(kinds[kind])
    bsdf.inputs["Color"].default_value = (rgb[0], rgb[1], rgb[2], 1)
    bsdf.inputs["Roughness"].default_value = roughness
    if kind != "diffuse":
        bsdf.distribution = "GGX"
    if kind == "glass":
        bsdf.inputs["IOR"].default_value = ior
    out = nodes.new("ShaderNodeOutputMaterial")
    m.node_tree.links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    return m


def render_to_pixels(scene):
    """Render, save float EXR, read it back: (width, height, RGBA floats bottom row first, seconds)."""
    exr = os.path.join(tempfile.mkdtemp(), "render.exr")
    scene.render.filepath = exr
    start = time.time()
    bpy.ops.render.render(write_still=True)
    seconds = time.time() - start
    image = bpy.data.images.load(exr)
    w, h = image.size
    return w, h, list(image.pixels), seconds


def render_to_pfm(scene, out_path, samples):
    """Render and write OUT.pfm (rows bottom to top, as Blender's) and OUT.pfm.txt (samples, seconds)."""
    w, h, px, seconds = render_to_pixels(scene)
    with open(out_path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        data = []
        for i in range(0, len(px), 4):
            data.extend(px[i:i + 3])
        f.write(struct.pack("<%df" % len(data), *data))
    with open(out_path + ".txt", "w") as f:
        f.write("samples,seconds\n%d,%.3f\n" % (samples, seconds))
    print("cycles: %d spp at %dx%d in %.2f s -> %s" % (samples, w, h, seconds, out_path))
