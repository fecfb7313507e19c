"""Renders a glTF (or OBJ) model in Blender Cycles (CPU) as rt sees it, for bench/compare_cycles.sh.

    blender -b --factory-startup --python bench/cycles_render.py -- \
        MODEL.glb SCENE.xml OUT.exr WIDTH HEIGHT SAMPLES [multiscatter] [threads=N] [time=SECONDS] [seed=N]

SCENE.xml is the rt scene the same model was converted to (rt-convert, then edited by
compare_cycles.sh); it gives the camera (origin, destination, up, horizontal fov), the constant
background (the world's radiance) and whether lights are kept. rt's world is glTF's (+y up);
Blender's importer turns it to +z up: (x, y, z) becomes (x, -z, y), and so does the camera here.

Punctual lights are imported in the importer's SPEC mode, its default: a glTF intensity I in
candela becomes a Blender power of 4 pi I / 683 watts, a radiant intensity of I / 683 W/sr, which
is rt-convert's rule too (docs/conversion.md); they are made points (radius 0, Blender's default
being 0.25 m). Cycles is set as close to rt's path tracer as it goes: the same bounce
limit for every kind of path, no clamping, no glossy filter, no light threshold, a box pixel
filter one pixel wide, emitters that shine from their front only, no denoiser, no adaptive sampling; the EXR holds linear Rec.709 values (the
"Standard" view transform is set, which only the PNGs Blender would write use). With
"multiscatter", the Principled BSDFs use Cycles' multiple-scattering GGX instead of the importer's
single-scattering GGX, as rt's metals do (Kulla and Conty's lobe). With "threads=N", Cycles renders on
N threads (else on every core). With "time=SECONDS", Cycles stops sampling after that many seconds
(its time_limit: synchronisation left out) or at SAMPLES, whichever comes first; "seed=N" seeds its
sampler (else 0). Blender's status lines on standard output ("... | Time:00:04.32 | ... | Sample 0/64",
then "... | Finished") give the time its path tracing took, after the scene's sync,
the BVH build and the kernels' loading: compare_cycles.sh reads them.
"""

import math
import sys
import xml.etree.ElementTree as ElementTree

import numpy

# Debian's Blender 3.4 importer still calls numpy.bool, which numpy 1.24 removed.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

import bpy  # noqa: E402  (after the numpy fix the importer needs)
from mathutils import Matrix, Vector  # noqa: E402


def to_blender(v):
    """rt's (glTF's) +y-up coordinates to Blender's +z-up ones, as the glTF importer turns them."""
    return Vector((v[0], -v[2], v[1]))


def xyz(element):
    return [float(element.get(axis)) for axis in ("x", "y", "z")]


def read_rt_scene(path):
    root = ElementTree.parse(path).getroot()
    camera = root.find("camera")
    background = root.find("background")
    return {
        "origin": to_blender(xyz(camera.find("origin"))),
        "destination": to_blender(xyz(camera.find("destination"))),
        "up": to_blender(xyz(camera.find("up"))),
        "fov": float(camera.get("fov")) * 100.0 / float(camera.get("zoom", "100")),
        "background": [float(background.get(c)) for c in ("r", "g", "b")] if background is not None else [0, 0, 0],
        "lights": root.find("lights") is not None and len(root.find("lights")) > 0,
    }


def place_camera(scene, rt):
    """A camera at rt's origin looking at its destination, rt's up vector up, rt's horizontal fov."""
    data = bpy.data.cameras.new("rt")
    data.sensor_fit = "HORIZONTAL"
    data.angle = math.radians(rt["fov"])
    data.clip_start = 1e-4
    data.clip_end = 1e6
    camera = bpy.data.objects.new("rt", data)
    scene.collection.objects.link(camera)
    forward = (rt["destination"] - rt["origin"]).normalized()
    right = forward.cross(rt["up"]).normalized()
    up = right.cross(forward)
    # Blender's camera looks along its local -z with +y up.
    rotation = Matrix((right, up, -forward)).transposed().to_4x4()
    camera.matrix_world = Matrix.Translation(rt["origin"]) @ rotation
    scene.camera = camera


def set_world(scene, rgb):
    world = bpy.data.worlds.new("rt") if scene.world is None else scene.world
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (*rgb, 1.0)
    background.inputs["Strength"].default_value = 1.0
    scene.world = world


def match_lights(scene, keep):
    for light in [o for o in scene.objects if o.type == "LIGHT"]:
        if keep:
            light.data.shadow_soft_size = 0.0  # a punctual light, as glTF's
            light.data.use_shadow = True
        else:
            bpy.data.objects.remove(light)


def emit_from_front_only():
    """rt's emitters shine from their front only (docs/path-tracing.md); Cycles' from both sides."""
    for material in bpy.data.materials:
        if not material.use_nodes:
            continue
        tree = material.node_tree
        for shader in [n for n in tree.nodes if n.type == "BSDF_PRINCIPLED"]:
            strength = shader.inputs["Emission Strength"]
            front = tree.nodes.new("ShaderNodeMath")
            front.operation = "SUBTRACT"
            front.inputs[0].default_value = 1.0
            tree.links.new(tree.nodes.new("ShaderNodeNewGeometry").outputs["Backfacing"], front.inputs[1])
            scaled = tree.nodes.new("ShaderNodeMath")
            scaled.operation = "MULTIPLY"
            scaled.inputs[0].default_value = strength.default_value
            tree.links.new(front.outputs["Value"], scaled.inputs[1])
            tree.links.new(scaled.outputs["Value"], strength)


def use_multiscatter_ggx():
    for material in bpy.data.materials:
        for shader in [n for n in material.node_tree.nodes if n.type == "BSDF_PRINCIPLED"] if material.use_nodes else []:
            shader.distribution = "MULTI_GGX"


def set_cycles(scene, width, height, samples):
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = samples
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.seed = 0
    bounces = 8  # rt-render's --max-bounces default
    cycles.max_bounces = bounces
    cycles.diffuse_bounces = bounces
    cycles.glossy_bounces = bounces
    cycles.transmission_bounces = bounces
    cycles.transparent_max_bounces = bounces
    cycles.volume_bounces = 0
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.blur_glossy = 0.0
    cycles.caustics_reflective = True
    cycles.caustics_refractive = True
    cycles.light_sampling_threshold = 0.0
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    scene.render.film_transparent = False
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.render.threads_mode = "AUTO"
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
    settings.color_mode = "RGB"


def import_model(path):
    if path.lower().endswith(".obj"):
        # OBJ is +y up like rt; Blender turns it as it turns glTF. Ke becomes the emission.
        bpy.ops.wm.obj_import(filepath=path, forward_axis="NEGATIVE_Z", up_axis="Y")
    else:
        bpy.ops.import_scene.gltf(filepath=path, convert_lighting_mode="SPEC")


def main(argv):
    model, rt_scene, output, width, height, samples, *options = argv
    bpy.ops.wm.read_factory_settings(use_empty=True)
    import_model(model)
    scene = bpy.context.scene
    rt = read_rt_scene(rt_scene)
    place_camera(scene, rt)
    set_world(scene, rt["background"])
    match_lights(scene, rt["lights"])
    emit_from_front_only()
    if "multiscatter" in options:
        use_multiscatter_ggx()
    set_cycles(scene, int(width), int(height), int(samples))
    for option in options:
        if option.startswith("threads="):
            scene.render.threads_mode = "FIXED"
            scene.render.threads = int(option.split("=")[1])
        if option.startswith("time="):
            scene.cycles.time_limit = float(option.split("=")[1])
        if option.startswith("seed="):
            scene.cycles.seed = int(option.split("=")[1])
    scene.render.filepath = output
    bpy.ops.render.render(write_still=True)


if __name__ == "__main__":
    main(sys.argv[sys.argv.index("--") + 1:])
