# Renders a scene written by `skinsim truth` (scene.json + meshes.bin + textures/) with Blender
# Cycles: random-walk subsurface scattering, path-traced shadows, no denoising, to a linear
# OpenEXR. Run by skinsim as
#   blender -b --factory-startup -P cycles_render.py -- SCENE_JSON OUT_EXR SEED THREADS
# The mapping of each skinsim parameter to Cycles is documented in docs/validation.md; this
# script only builds what scene.json states (units, light strengths and radii are converted
# by skinsim, driver/truth/truth_scene.cpp).
import json
import math
import os
import sys

from array import array

import bpy
from mathutils import Matrix, Vector


def fail(message):
    print(f"cycles_render.py: error: {message}", file=sys.stderr)
    sys.exit(2)


def build_mesh(m, raw):
    n, t = m["vertex_count"], m["triangle_count"]

    def values(typecode, key, count):
        a = array(typecode)
        a.frombytes(raw[m[key]:m[key] + count * a.itemsize])
        if sys.byteorder != "little":  # meshes.bin is little-endian
            a.byteswap()
        return a

    positions, normals = values("f", "positions", n * 3), values("f", "normals", n * 3)
    uvs, indices = values("f", "uvs", n * 2), values("I", "indices", t * 3)
    me = bpy.data.meshes.new(m["name"])
    me.vertices.add(n)
    me.vertices.foreach_set("co", positions)
    me.loops.add(t * 3)
    me.loops.foreach_set("vertex_index", indices)
    me.polygons.add(t)
    me.polygons.foreach_set("loop_start", range(0, t * 3, 3))
    me.polygons.foreach_set("loop_total", [3] * t)
    me.polygons.foreach_set("use_smooth", [True] * t)
    me.update(calc_edges=True)
    # skinsim's UV origin is the image's top-left (glTF), Blender's its bottom-left.
    loop_uvs = array("f", bytes(8 * t * 3))
    for k, i in enumerate(indices):
        loop_uvs[2 * k] = uvs[2 * i]
        loop_uvs[2 * k + 1] = 1.0 - uvs[2 * i + 1]
    me.uv_layers.new(name="UVMap").data.foreach_set("uv", loop_uvs)
    # The vertex normals skinsim interpolates, not Blender's own.
    me.use_auto_smooth = True
    me.normals_split_custom_set_from_vertices([normals[3 * i:3 * i + 3] for i in range(n)])
    obj = bpy.data.objects.new(m["name"], me)
    obj.visible_shadow = m["casts_shadow"]
    bpy.context.scene.collection.objects.link(obj)
    return obj


class Nodes:
    def __init__(self, material):
        material.use_nodes = True
        self.tree = material.node_tree
        self.tree.nodes.clear()

    def add(self, kind, **inputs):
        node = self.tree.nodes.new(kind)
        for name, value in inputs.items():
            self.set(node.inputs[name], value)
        return node

    def set(self, socket, value):
        if hasattr(value, "bl_idname"):  # a node: its first output
            self.tree.links.new(value.outputs[0], socket)
        elif isinstance(value, tuple) and hasattr(value[0], "bl_idname"):  # (node, output)
            self.tree.links.new(value[0].outputs[value[1]], socket)
        else:
            socket.default_value = value

    def math(self, op, a, b):
        node = self.add("ShaderNodeMath")
        node.operation = op
        self.set(node.inputs[0], a)
        self.set(node.inputs[1], b)
        return node


def albedo_nodes(nodes, mat, base):
    """Albedo (linear) and reflectivity (the texture's alpha times the factor) sockets."""
    factor = tuple(mat["base_color_factor"][:3]) + (1.0,)
    if mat["base_color_texture"] is None:
        return factor, mat["reflectivity"]
    tex = nodes.add("ShaderNodeTexImage")
    image = bpy.data.images.load(os.path.join(base, mat["base_color_texture"]))
    image.colorspace_settings.name = "sRGB" if mat["base_color_srgb"] else "Non-Color"
    image.alpha_mode = "CHANNEL_PACKED"  # alpha is the reflectivity map, not coverage
    tex.image = image
    tex.interpolation = "Linear"
    mix = nodes.add("ShaderNodeMixRGB", Fac=1.0, Color2=factor)
    mix.blend_type = "MULTIPLY"
    nodes.set(mix.inputs["Color1"], (tex, 0))
    return (mix, 0), nodes.math("MULTIPLY", (tex, 1), mat["reflectivity"])


def glossy_lobe(nodes, lobe, reflectivity, ior):
    """One specular lobe: Beckmann, colour = weight x reflectivity x Fresnel(ior)."""
    fresnel = nodes.add("ShaderNodeFresnel", IOR=ior)
    scale = nodes.math("MULTIPLY", reflectivity, lobe["scale"])
    glossy = nodes.add("ShaderNodeBsdfGlossy", Roughness=lobe["blender_roughness"])
    glossy.distribution = "BECKMANN"
    colour = nodes.math("MULTIPLY", (fresnel, 0), (scale, 0))
    nodes.set(glossy.inputs["Color"], (colour, 0))
    return glossy


def build_material(mat, base):
    material = bpy.data.materials.new(mat["name"])
    nodes = Nodes(material)
    albedo, reflectivity = albedo_nodes(nodes, mat, base)
    if mat["kind"] == "skin":
        sss = mat["subsurface"]
        surface = nodes.add("ShaderNodeBsdfPrincipled", Subsurface=1.0, Specular=0.0,
                            Roughness=0.5)
        surface.subsurface_method = "RANDOM_WALK"
        nodes.set(surface.inputs["Base Color"], albedo)
        nodes.set(surface.inputs["Subsurface Color"], albedo)
        surface.inputs["Subsurface Radius"].default_value = sss["radius"]
        surface.inputs["Subsurface IOR"].default_value = sss["ior"]
        for lobe in mat["specular_lobes"]:
            added = nodes.add("ShaderNodeAddShader")
            nodes.set(added.inputs[0], surface)
            nodes.set(added.inputs[1], glossy_lobe(nodes, lobe, reflectivity, mat["ior"]))
            surface = added
    elif mat["kind"] == "eye":
        diffuse = nodes.add("ShaderNodeBsdfDiffuse")
        nodes.set(diffuse.inputs["Color"], albedo)
        surface = nodes.add("ShaderNodeAddShader")
        nodes.set(surface.inputs[0], diffuse)
        nodes.set(surface.inputs[1], glossy_lobe(nodes, mat["cornea"], 1.0, mat["ior"]))
    else:
        surface = nodes.add("ShaderNodeBsdfDiffuse")
        nodes.set(surface.inputs["Color"], albedo)
    out = nodes.add("ShaderNodeOutputMaterial")
    nodes.set(out.inputs["Surface"], surface)
    return material


def build_camera(cam, width, height):
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"  # skinsim's field of view / ymag is vertical
    if cam["projection"] == "orthographic":
        data.type = "ORTHO"
        data.ortho_scale = 2.0 * cam["ymag"]
    else:
        data.type = "PERSP"
        data.angle_y = cam["yfov_radians"]
    data.clip_start, data.clip_end = cam["znear"], cam["zfar"]
    obj = bpy.data.objects.new("camera", data)
    # OpenGL's camera frame (looks down -Z, +Y up) is Blender's too.
    obj.matrix_world = Matrix(cam["camera_to_world"])
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj


def build_light(light, index):
    data = bpy.data.lights.new(f"light{index}", "SUN")
    radiance = light["radiance"]
    peak = max(radiance)
    if peak <= 0.0:
        return
    data.color = [c / peak for c in radiance]
    data.energy = light["sun_strength_scale"] * peak
    data.angle = light["angular_diameter_radians"]
    obj = bpy.data.objects.new(f"light{index}", data)
    # A sun shines along its local -Z: point +Z at the light.
    obj.rotation_euler = Vector(light["direction"]).to_track_quat("Z", "Y").to_euler()
    bpy.context.scene.collection.objects.link(obj)


def main():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(args) != 4:
        fail("usage: blender -b --factory-startup -P cycles_render.py -- SCENE_JSON OUT_EXR SEED THREADS")
    scene_path, out_path, seed, threads = args[0], args[1], int(args[2]), int(args[3])
    with open(scene_path) as f:
        d = json.load(f)
    base = os.path.dirname(os.path.abspath(scene_path))
    with open(os.path.join(base, d["meshes_file"]), "rb") as f:
        raw = f.read()

    bpy.ops.wm.read_factory_settings(use_empty=True)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.device = "CPU"
    r = d["render"]
    sc.cycles.samples = r["samples"]
    sc.cycles.seed = seed
    sc.cycles.use_adaptive_sampling = False  # every pixel gets the stated sample count
    sc.cycles.use_denoising = False  # Debian's Blender has no OpenImageDenoise; truth stays unbiased
    sc.cycles.pixel_filter_type = "BOX"  # each pixel the mean over its area
    sc.cycles.filter_width = 1.0
    sc.cycles.max_bounces = r["max_bounces"]
    sc.cycles.sample_clamp_direct = 0.0
    sc.cycles.sample_clamp_indirect = 0.0
    sc.render.resolution_x, sc.render.resolution_y = d["width"], d["height"]
    sc.render.resolution_percentage = 100
    sc.render.film_transparent = True  # no surface: black, as skinsim's clear colour
    if threads > 0:
        sc.render.threads_mode = "FIXED"
        sc.render.threads = threads
    sc.view_settings.view_transform = "Standard"
    settings = sc.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_mode = "RGBA"
    settings.color_depth = "32"
    settings.exr_codec = "ZIP"

    materials = [build_material(m, base) for m in d["materials"]]
    for m in d["meshes"]:
        build_mesh(m, raw).data.materials.append(materials[m["material"]])
    build_camera(d["camera"], d["width"], d["height"])
    for i, light in enumerate(d["lights"]):
        build_light(light, i)
    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = tuple(d["world"]["radiance"]) + (1.0,)
    background.inputs["Strength"].default_value = 1.0
    sc.world = world

    sc.render.filepath = out_path
    bpy.ops.render.render(write_still=True)
    if not os.path.exists(out_path):
        fail(f"Cycles wrote no image to {out_path}")


main()
