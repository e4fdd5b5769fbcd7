"""The caustic scene of `scatterlab render --scene caustic` for Blender Cycles, and the noise of
renders of it (run by bench/caustic_compare.py).

    blender -b --factory-startup -noaudio -P cycles_caustic.py -- render \
        --res 128 96 --spp 64 --seeds 8 --threads 2 --out DIR
    blender -b --factory-startup -noaudio -P cycles_caustic.py -- stats --res 128 96 --files FILE.exr...

Scene (integrator/scene_presets.h): a smooth glass sphere (IOR 1.5; a smooth-shaded UV sphere
of 256 x 128 segments, as cycles_sphere.py) of radius 1 at the origin on a grey Lambertian
ground z = -1 (albedo 0.5), lit by a sphere light of radius 0.25 at (3, 0, 2.5) alone (a point
light with that radius; no world light), seen from (0, -5, 1.6) toward (0, 0, -0.3), +Z up, 40
degree field of view (sensor fit auto), box filter of one pixel, every bounce limit 12, no
clamping, no glossy filter, no denoising, no adaptive sampling, caustics on (Blender's
defaults). The light's power is not matched to scatterlab's radiance: only relative noise is
compared, and every light in the caustic region came through the glass.

`render` renders one image per seed 0 .. seeds-1 (DIR/cycles_K.exr) and prints `RESULT {json}`
with each render call's seconds. `stats` prints `STATS {json}`: over the caustic region (pixels
whose centre ray meets the ground within 0.35 of where the light's line through the sphere's
centre meets it, (-1.2, 0, -1)), the mean over pixels of each pixel's variance (the sample
variance of the files' luminance at that pixel) over the square of the region's mean luminance:
the relative variance of a typical pixel (a pixel's own mean can be 0 where a path tracer found
no light yet), and the region's mean luminance.
"""
import argparse
import json
import math
import sys
import time

import bpy
import numpy as np

EYE = np.array([0.0, -5.0, 1.6])
TARGET = np.array([0.0, 0.0, -0.3])
FOV = 40.0
LIGHT = (3.0, 0.0, 2.5)
LIGHT_RADIUS = 0.25
CAUSTIC = np.array([-1.2, 0.0, -1.0])
REGION_RADIUS = 0.35


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser(prog="cycles_caustic.py")
    ap.add_argument("mode", choices=["render", "stats"])
    ap.add_argument("--res", type=int, nargs=2, default=[128, 96])
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--seeds", type=int, default=8)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", default=".")
    ap.add_argument("--files", nargs="*", default=[])
    return ap.parse_args(argv)


def region_mask(width, height):
    # The pinhole of integrator/camera.h: film (x, y) looks along
    # forward + tan(fov/2) ((2x - w) / s) right + tan(fov/2) ((h - 2y) / s) up, s = max(w, h).
    forward = (TARGET - EYE) / np.linalg.norm(TARGET - EYE)
    right = np.cross(forward, [0.0, 0.0, 1.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    scale = math.tan(math.radians(FOV) / 2) / max(width, height)
    mask = np.zeros((height, width), dtype=bool)
    for y in range(height):
        for x in range(width):
            d = forward + (2 * (x + 0.5) - width) * scale * right + (height - 2 * (y + 0.5)) * scale * up
            d /= np.linalg.norm(d)
            if d[2] >= 0:
                continue
            t = (-1.0 - EYE[2]) / d[2]
            p = EYE + t * d
            # The sphere in front of the ground point hides it.
            b = np.dot(EYE, d)
            disc = b * b - (np.dot(EYE, EYE) - 1.0)
            if disc > 0 and -b - math.sqrt(disc) < t:
                continue
            mask[y, x] = np.linalg.norm(p - CAUSTIC) < REGION_RADIUS
    return mask


def node_material(name, shader, inputs, **properties):
    """A material of one shader node (type `shader`) with `inputs` set, into the output."""
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nt = material.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    node = nt.nodes.new(shader)
    for key, value in properties.items():
        setattr(node, key, value)
    for key, value in inputs.items():
        node.inputs[key].default_value = value
    nt.links.new(node.outputs[0], out.inputs["Surface"])
    return material


def build_scene(a):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    s = bpy.context.scene
    glass = node_material("glass", "ShaderNodeBsdfGlass", {"Color": (1, 1, 1, 1), "IOR": 1.5},
                          distribution="SHARP")
    bpy.ops.mesh.primitive_uv_sphere_add(segments=256, ring_count=128, radius=1.0, location=(0, 0, 0))
    bpy.ops.object.shade_smooth()
    bpy.context.active_object.data.materials.append(glass)
    grey = node_material("grey", "ShaderNodeBsdfDiffuse", {"Color": (0.5, 0.5, 0.5, 1), "Roughness": 0.0})
    bpy.ops.mesh.primitive_plane_add(size=200.0, location=(0, 0, -1))
    bpy.context.active_object.data.materials.append(grey)

    light = bpy.data.lights.new("light", type="POINT")
    light.shadow_soft_size = LIGHT_RADIUS
    light.energy = 1000.0
    obj = bpy.data.objects.new("light", light)
    obj.location = LIGHT
    s.collection.objects.link(obj)

    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    s.world = world

    cam_data = bpy.data.cameras.new("Camera")
    cam_data.lens_unit = "FOV"
    cam_data.sensor_fit = "AUTO"
    cam_data.angle = math.radians(FOV)
    cam = bpy.data.objects.new("Camera", cam_data)
    s.collection.objects.link(cam)
    cam.location = tuple(EYE)
    direction = TARGET - EYE
    # Blender's camera looks along its -Z with +Y up: pitch up from straight down, then turn.
    cam.rotation_euler = (math.atan2(math.hypot(direction[0], direction[1]), -direction[2]), 0.0,
                          math.atan2(direction[1], direction[0]) - math.pi / 2)
    s.camera = cam

    r = s.render
    r.engine = "CYCLES"
    r.resolution_x, r.resolution_y = a.res
    r.resolution_percentage = 100
    r.threads_mode = "FIXED"
    r.threads = a.threads
    c = s.cycles
    c.device = "CPU"
    c.samples = a.spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.use_animated_seed = False
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = 12
    c.transparent_max_bounces = 12
    c.min_light_bounces = 0
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    s.view_settings.view_transform = "Standard"


def render(a):
    build_scene(a)
    seconds = []
    for seed in range(a.seeds):
        bpy.context.scene.cycles.seed = seed
        t0 = time.perf_counter()
        bpy.ops.render.render(write_still=False)
        seconds.append(time.perf_counter() - t0)
        st = bpy.context.scene.render.image_settings
        st.file_format = "OPEN_EXR"
        st.color_mode = "RGB"
        st.color_depth = "32"
        bpy.data.images["Render Result"].save_render(f"{a.out}/cycles_{seed}.exr", scene=bpy.context.scene)
    print("RESULT " + json.dumps({"peer": "blender-cycles " + bpy.app.version_string, "seconds": seconds}),
          flush=True)


def luminance_of(path, width, height):
    image = bpy.data.images.load(path)
    pixels = np.array(image.pixels[:], dtype=np.float64).reshape(height, width, image.channels)
    bpy.data.images.remove(image)
    # Blender's rows run bottom to top.
    rgb = pixels[::-1, :, :3]
    return 0.2126 * rgb[..., 0] + 0.7152 * rgb[..., 1] + 0.0722 * rgb[..., 2]


def stats(a):
    width, height = a.res
    mask = region_mask(width, height)
    values = np.stack([luminance_of(f, width, height) for f in a.files])
    mean = values.mean(axis=0)
    variance = values.var(axis=0, ddof=1)
    m, v = mean[mask], variance[mask]
    print("STATS " + json.dumps({"pixels": int(mask.sum()), "region_mean": float(m.mean()),
                                 "relative_variance": float(v.mean() / m.mean() ** 2)}), flush=True)


args = parse_args()
render(args) if args.mode == "render" else stats(args)
