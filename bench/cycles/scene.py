# bench/cycles/scene.py: bench/cycles/head.pov rebuilt in Blender and rendered by Cycles.
#   blender -b --factory-startup --python scene.py -- OBJ OUT.exr SPP SEED METHOD [W H THREADS]
# METHOD: BURLEY (Christensen-Burley, a profile like circe's circle tracing) or RANDOM_WALK.
# circe's scene is POV-Ray's left-handed y-up space; Blender's is right-handed z-up: a point
# (x, y, z) of circe's is (x, z, y) of Blender's (a mirror, so the images are the same way round).
# No denoiser, no adaptive sampling, no light tree (3.4 has none), a fixed seed: each render is
# compared only with Cycles' own reference, so the two renderers' brightness need not match to the
# last percent (the light's power is matched by the radiometric definition, below).
import math
import sys
import time

import bpy
from mathutils import Matrix, Vector

argv = sys.argv[sys.argv.index("--") + 1:]
obj_path, out_path, spp, seed, method = argv[0], argv[1], int(argv[2]), int(argv[3]), argv[4]
width, height, threads = (int(a) for a in (argv[5:8] + ["320", "240", "2"][len(argv[5:8]):]))


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
world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.05, 0.05, 0.05, 1)
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0

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
p.inputs["Roughness"].default_value = 0.35
p.inputs["Specular"].default_value = ((1.4 - 1) / (1.4 + 1)) ** 2 / 0.08  # F0 of ior 1.4
head.data.materials.clear()
head.data.materials.append(mat)

# The sphere light: circe's intensity I (W/sr, radiant intensity of the whole sphere) is Cycles'
# point-light power P = 4 pi I watts.
light = bpy.data.lights.new("key", "POINT")
light.energy = 4 * math.pi * 300
light.shadow_soft_size = 1.0
light.color = (1, 1, 1)
lo = bpy.data.objects.new("key", light)
lo.location = pov(8, 8, 14)
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
t = time.time()
bpy.ops.render.render(write_still=True)
print("cycles-render-seconds %.3f" % (time.time() - t))
