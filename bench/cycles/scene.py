# bench/cycles/scene.py: bench/cycles/SCENE.pov rebuilt in Blender and rendered by Cycles.
#   blender -b --factory-startup --python scene.py -- OBJ OUT.exr SPP SEED METHOD [W H THREADS [SCENE]]
# METHOD: BURLEY (Christensen-Burley, a profile like circe's circle tracing) or RANDOM_WALK.
# SCENE: head (default), textured (the colour and normal maps, the studio environment and the
# light of scenes/default.pov) or lights (three sphere lights): head.pov, textured.pov, lights.pov.
# circe's scene is POV-Ray's left-handed y-up space; Blender's is right-handed z-up: a point
# (x, y, z) of circe's is (x, z, y) of Blender's (a mirror, so the images are the same way round).
# No denoiser, no adaptive sampling, no light tree (3.4 has none), a fixed seed: each render is
# compared only with Cycles' own reference, so the two renderers' brightness need not match to the
# last percent (the light's power is matched by the radiometric definition, below).
import math
import os
import sys
import time

import bpy
from mathutils import Matrix, Vector

argv = sys.argv[sys.argv.index("--") + 1:]
obj_path, out_path, spp, seed, method = argv[0], argv[1], int(argv[2]), int(argv[3]), argv[4]
width, height, threads = (int(a) for a in (argv[5:8] + ["320", "240", "2"][len(argv[5:8]):]))
which = argv[8] if len(argv) > 8 else "head"
assets = os.path.dirname(os.path.dirname(os.path.abspath(obj_path)))  # scenes/assets


def pov(x, y, z):
    return Vector((x, z, y))


bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.engine = "CYCLES"
cy = scene.cycles
cy.device = "CPU"
cy.samples = spp
cy.seed = seed
cy.use_adaptive_sampling = False
cy.use_denoising = False
cy.max_bounces = 6  # max_trace_level 6
cy.diffuse_bounces = cy.glossy_bounces = cy.transmission_bounces = 6
cy.sample_clamp_direct = cy.sample_clamp_indirect = 0.0
cy.pixel_filter_type = "BOX"
cy.filter_width = 1.0
scene.render.threads_mode = "FIXED"
scene.render.threads = threads
scene.render.resolution_x, scene.render.resolution_y = width, height
scene.render.resolution_percentage = 100
scene.render.film_transparent = False
scene.view_settings.view_transform = "Standard"
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.image_settings.color_mode = "RGB"
scene.render.image_settings.exr_codec = "ZIP"

world = bpy.data.worlds.new("world")
scene.world = world
world.use_nodes = True
bg = world.node_tree.nodes["Background"]
if which == "textured":
    # sky_sphere { image "studio.exr" intensity 0.5 }: circe's lat-long map has u = 0.5 at its +z
    # (Blender's +y), u = 0.75 at +x; Cycles' equirectangular has u = 0.5 at +x, u = 0.75 at -y:
    # the same orientation (no mirror) turned a quarter, so the lookup vector is turned by -90
    # degrees about z. v = 0 is the image's top row (straight up) in both.
    nt = world.node_tree
    env = nt.nodes.new("ShaderNodeTexEnvironment")
    env.image = bpy.data.images.load(os.path.join(assets, "studio", "studio.exr"))
    env.interpolation = "Linear"
    tc = nt.nodes.new("ShaderNodeTexCoord")
    mp = nt.nodes.new("ShaderNodeMapping")
    mp.vector_type = "VECTOR"
    mp.inputs["Rotation"].default_value = (0, 0, -math.pi / 2)
    nt.links.new(tc.outputs["Generated"], mp.inputs["Vector"])
    nt.links.new(mp.outputs["Vector"], env.inputs["Vector"])
    nt.links.new(env.outputs["Color"], bg.inputs["Color"])
    bg.inputs["Strength"].default_value = 0.5
    world.cycles.sampling_method = "MANUAL"  # importance-sampled as circe's sky image
    world.cycles.sample_map_resolution = 1024
else:
    bg.inputs["Color"].default_value = (0.05, 0.05, 0.05, 1)
    bg.inputs["Strength"].default_value = 1.0

# The mesh as the OBJ gives it (forward y, up z: the importer keeps the file's coordinates), then
# swapped into Blender's space by the same mapping as every other point.
bpy.ops.wm.obj_import(filepath=obj_path, forward_axis="Y", up_axis="Z")
head = bpy.context.selected_objects[0]
head.matrix_world = Matrix(((1, 0, 0, 0), (0, 0, 1, 0), (0, 1, 0, 0), (0, 0, 0, 1)))
for poly in head.data.polygons:
    poly.use_smooth = True
mat = bpy.data.materials.new("skin")
mat.use_nodes = True
p = mat.node_tree.nodes["Principled BSDF"]
p.subsurface_method = method
col = (0.8, 0.55, 0.45, 1)
p.inputs["Base Color"].default_value = col
p.inputs["Subsurface Color"].default_value = col
p.inputs["Subsurface"].default_value = 1.0  # also the radius' scale: radius in scene units
p.inputs["Subsurface Radius"].default_value = tuple(r / 22.0 for r in (1.35, 1.14, 0.99))
p.inputs["Subsurface IOR"].default_value = 1.4
# circe's coat takes its roughness as the GGX alpha (src/render/bsdf.h, bsdf_coat); Cycles'
# Principled squares its roughness into alpha: sqrt(0.35) is the same lobe.
p.inputs["Roughness"].default_value = math.sqrt(0.35)
p.inputs["Specular"].default_value = ((1.4 - 1) / (1.4 + 1)) ** 2 / 0.08  # F0 of ior 1.4
if which == "textured":
    # skin { image "Map-COL.jpg" normal_map "..._Tangent_SmoothUV.jpg" strength 1 }: the colour
    # map (sRGB) is the albedo (Cycles' base and subsurface colour), the tangent-space normal map
    # (raw numbers) through a Normal Map node of strength 1, both on the OBJ's uv.
    nt = mat.node_tree
    col_tex = nt.nodes.new("ShaderNodeTexImage")
    col_tex.image = bpy.data.images.load(os.path.join(assets, "lee_perry_smith_head", "Map-COL.jpg"))
    col_tex.interpolation = "Linear"
    nt.links.new(col_tex.outputs["Color"], p.inputs["Base Color"])
    nt.links.new(col_tex.outputs["Color"], p.inputs["Subsurface Color"])
    nrm_tex = nt.nodes.new("ShaderNodeTexImage")
    nrm_tex.image = bpy.data.images.load(
        os.path.join(assets, "lee_perry_smith_head", "Infinite-Level_02_Tangent_SmoothUV.jpg"))
    nrm_tex.image.colorspace_settings.name = "Non-Color"
    nrm_tex.interpolation = "Linear"
    nm = nt.nodes.new("ShaderNodeNormalMap")
    nm.space = "TANGENT"
    nm.inputs["Strength"].default_value = 1.0
    nt.links.new(nrm_tex.outputs["Color"], nm.inputs["Color"])
    nt.links.new(nm.outputs["Normal"], p.inputs["Normal"])
head.data.materials.clear()
head.data.materials.append(mat)

# The sphere light: circe's intensity I (W/sr, radiant intensity of the whole sphere) is Cycles'
# point-light power P = 4 pi I watts.
# (position, colour, intensity, radius) of each light_source of the scene's .pov.
lights = {
    "head": [((8, 8, 14), (1, 1, 1), 300, 1.0)],
    "textured": [((-10, 12, 16), (1, 0.94, 0.86), 450, 1.5)],
    "lights": [((8, 8, 14), (1, 0.9, 0.8), 200, 1.0), ((-14, 2, 8), (0.6, 0.75, 1), 150, 3.0),
               ((-4, 10, -12), (1, 0.6, 0.3), 300, 0.3)],
}[which]
for i, (at, rgb, intensity, radius) in enumerate(lights):
    light = bpy.data.lights.new("light%d" % i, "POINT")
    light.energy = 4 * math.pi * intensity
    light.shadow_soft_size = radius
    light.color = rgb
    lo = bpy.data.objects.new("light%d" % i, light)
    lo.location = pov(*at)
    scene.collection.objects.link(lo)

# The camera: POV-Ray's angle is the horizontal field of view.
cam = bpy.data.cameras.new("cam")
cam.sensor_fit = "HORIZONTAL"
cam.angle = math.radians(34)
co = bpy.data.objects.new("cam", cam)
co.location = pov(4.5, 1.5, 17)
co.rotation_euler = (pov(0, 0.6, 0) - co.location).to_track_quat("-Z", "Y").to_euler()
scene.collection.objects.link(co)
scene.camera = co

scene.render.filepath = out_path
t, c = time.time(), time.process_time()
bpy.ops.render.render(write_still=True)
# Wall seconds, then CPU seconds of the whole process (every thread's) during the render.
print("cycles-render-seconds %.3f" % (time.time() - t))
print("cycles-render-cpu %.3f" % (time.process_time() - c))
