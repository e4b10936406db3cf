# Renders one frame of a Throng glTF/GLB export with Blender, headless (Cycles on the CPU),
# on a grey ground under a sun, from a camera at a given place looking at a given point:
# a quick look at what an artist will get, without opening Blender.
#
#   blender -b -P scripts/render-gltf.py -- IN.glb OUT.(png|jpg) FRAME \
#       TARGET_X TARGET_Y TARGET_Z CAMERA_X CAMERA_Y CAMERA_Z [LENS_MM=50] [SAMPLES=48]
#
# Coordinates are Blender's (Z up; the glTF importer turns Throng's y-up, so Throng's
# (x, y, z) is Blender's (x, -z, y)). FRAME is Blender's frame number after the import.
# Example (docs/images/export-actions.jpg, from tests/data/scenes/actions.yaml):
#   build/app/cli/throng-cli run tests/data/scenes/actions.yaml --frames 60 --export /tmp/actions.glb
#   blender -b -P scripts/render-gltf.py -- /tmp/actions.glb docs/images/export-actions.jpg 41 \
#       0 0 0.9  6 -9 1.6  30
import math
import sys

import bpy
import mathutils
import numpy as np

# Debian 12's Blender 3.4 importer still uses np.bool, which NumPy 1.24 removed.
if not hasattr(np, "bool"):
    np.bool = bool

args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
if len(args) < 9:
    sys.exit("usage: blender -b -P render-gltf.py -- IN.glb OUT.png FRAME TX TY TZ CX CY CZ [LENS_MM] [SAMPLES]")
source, out, frame = args[0], args[1], int(args[2])
target = mathutils.Vector([float(v) for v in args[3:6]])
camera_at = mathutils.Vector([float(v) for v in args[6:9]])
lens = float(args[9]) if len(args) > 9 else 50.0
samples = int(args[10]) if len(args) > 10 else 48

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=source)
scene = bpy.context.scene
scene.frame_set(frame)

bpy.ops.mesh.primitive_plane_add(size=400, location=(0, 0, 0))
ground = bpy.data.materials.new("ground")
ground.use_nodes = True
ground.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.55, 0.55, 0.52, 1)
bpy.context.active_object.data.materials.append(ground)

camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
camera.data.lens = lens
camera.location = camera_at
camera.rotation_euler = (target - camera_at).to_track_quat("-Z", "Y").to_euler()
scene.collection.objects.link(camera)
scene.camera = camera

sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
sun.data.energy = 3.5
sun.rotation_euler = (math.radians(50), math.radians(10), math.radians(30))
scene.collection.objects.link(sun)
scene.world = bpy.data.worlds.new("sky")
scene.world.use_nodes = True
scene.world.node_tree.nodes["Background"].inputs[0].default_value = (0.75, 0.8, 0.9, 1)
scene.world.node_tree.nodes["Background"].inputs[1].default_value = 0.8

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = samples
scene.cycles.use_denoising = False  # Debian's build has no OpenImageDenoise
scene.render.resolution_x, scene.render.resolution_y = 960, 540
if out.lower().endswith((".jpg", ".jpeg")):
    scene.render.image_settings.file_format = "JPEG"
    scene.render.image_settings.quality = 88
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
