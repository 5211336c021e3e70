"""Unwraps a glTF scene with one of Blender's own lightmap unwrappers and exports the result.

Run by bench/uv_compare as:
  blender -b --factory-startup --python bench/blender_unwrap.py -- IN.gltf smart|lightmap OUT.gltf PAGE PADDING

All meshes are made single-user, their transforms applied and joined into one object, so the
unwrapper lays out the whole scene in one UV square, as radbake's atlas does. The margin is set
to the same number of texels as radbake's padding at the same page size. Prints the operator's
own time as "UNWRAP_SECONDS <s>".
"""
import math
import os
import sys
import time

# Debian's Blender 3.4 glTF importer on numpy 1.24 needs the aliases numpy removed (docs/blender.md).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "blender_addon", "radbake"))
import numpy_aliases  # noqa: E402

numpy_aliases.restore()

import bpy  # noqa: E402

source, method, target, page, padding = sys.argv[sys.argv.index("--") + 1:]
page, padding = int(page), int(padding)

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=source)
meshes = [o for o in bpy.context.scene.objects if o.type == 'MESH']
bpy.ops.object.select_all(action='DESELECT')
for o in meshes:
    o.select_set(True)
bpy.context.view_layer.objects.active = meshes[0]
bpy.ops.object.make_single_user(object=True, obdata=True)
bpy.ops.object.transform_apply(location=True, rotation=True, scale=True)
if len(meshes) > 1:
    bpy.ops.object.join()
obj = bpy.context.view_layer.objects.active
while obj.data.uv_layers:
    obj.data.uv_layers.remove(obj.data.uv_layers[0])
obj.data.uv_layers.new(name="lightmap")

bpy.ops.object.mode_set(mode='EDIT')
bpy.ops.mesh.select_all(action='SELECT')
start = time.perf_counter()
if method == "smart":
    bpy.ops.uv.smart_project(angle_limit=math.radians(66), margin_method='FRACTION', island_margin=padding / page)
else:
    # Lightmap Pack shrinks each face's box by 1 / (100 / margin) of the UV square on every side,
    # so two neighbours are 2 * margin / 100 apart: `padding` texels at `page`.
    bpy.ops.uv.lightmap_pack(PREF_CONTEXT='ALL_FACES', PREF_PACK_IN_ONE=True, PREF_IMG_PX_SIZE=page,
                             PREF_MARGIN_DIV=50.0 * padding / page)
seconds = time.perf_counter() - start
bpy.ops.object.mode_set(mode='OBJECT')
bpy.ops.export_scene.gltf(filepath=target, export_format='GLTF_SEPARATE', export_texcoords=True,
                          export_normals=False, export_materials='NONE', export_lights=False,
                          export_cameras=False)
print("UNWRAP_SECONDS", seconds)
