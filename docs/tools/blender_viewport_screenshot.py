"""The README's Blender screenshot: the Cornell box baked through the add-on, seen in Blender's
3D viewport (Rendered shading with Cycles, through the scene camera). Run by ./dev blender-screenshot in two
steps: headless Blender bakes and saves a .blend with the viewport set up; Blender under Xvfb opens
it (no splash screen over a file given on the command line), switches the viewport to Rendered
and saves it as a PNG.

  blender -b --factory-startup --python THIS -- bake ADDON.zip RADBAKE SOURCE_DIR SCENE.blend
  xvfb-run blender --factory-startup SCENE.blend --python THIS -- shoot OUT.png
"""
import os
import sys

import bpy

STEP, *ARGS = sys.argv[sys.argv.index("--") + 1:]


def bake(addon_zip, radbake, source, blend):
    bpy.ops.preferences.addon_install(filepath=addon_zip, overwrite=True)
    bpy.ops.preferences.addon_enable(module="radbake")
    bpy.context.preferences.addons["radbake"].preferences.executable = radbake
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    bpy.ops.import_scene.gltf(filepath=os.path.join(source, "samples/cornell_box/cornell_box.gltf"))
    scene = bpy.context.scene
    scene.camera = bpy.data.objects["camera"]
    scene.radbake.max_page_size = 512
    assert bpy.ops.radbake.bake() == {'FINISHED'}
    for screen in bpy.data.screens:
        for area in screen.areas:
            if area.type == 'VIEW_3D':
                space = area.spaces.active
                space.overlay.show_overlays = False
                space.show_gizmo = False
                space.show_region_toolbar = False
                space.show_region_header = False
                space.show_region_tool_header = False
                space.region_3d.view_perspective = 'CAMERA'
    # The lightmap materials emit the baked light scaled to about 1 for the brightest surfaces:
    # the Standard view shows that as the PNG pages look, Filmic would grey it down.
    scene.view_settings.view_transform = 'Standard'
    # Rendered shading with Cycles on the CPU: EEVEE's Material Preview needs a GPU that Xvfb's
    # software OpenGL does not stand in for faithfully.
    scene.render.engine = 'CYCLES'
    scene.cycles.device = 'CPU'
    scene.cycles.preview_samples = 64
    scene.cycles.use_preview_denoising = False
    bpy.ops.wm.save_as_mainfile(filepath=blend)


def start_rendering(out):
    """Rendered shading can only be switched on with a window; Cycles then needs a while."""
    window = bpy.context.window_manager.windows[0]
    for area in window.screen.areas:
        if area.type == 'VIEW_3D':
            area.spaces.active.shading.type = 'RENDERED'
    bpy.app.timers.register(lambda: shoot(out), first_interval=30.0)


def shoot(out):
    window = bpy.context.window_manager.windows[0]
    area = max((a for a in window.screen.areas if a.type == 'VIEW_3D'), key=lambda a: a.width * a.height)
    region = next(r for r in area.regions if r.type == 'WINDOW')
    with bpy.context.temp_override(window=window, area=area, region=region):
        bpy.ops.view3d.view_center_camera()
        bpy.ops.wm.redraw_timer(type='DRAW_WIN_SWAP', iterations=10)
        bpy.ops.screen.screenshot(filepath=out)
    crop(out, region)
    print("wrote", out)
    bpy.ops.wm.quit_blender()


def crop(path, region):
    """Keeps the viewport's drawing region of the whole-window screenshot."""
    import numpy
    shot = bpy.data.images.load(path)
    w, h = shot.size
    pixels = numpy.array(shot.pixels[:], dtype=numpy.float32).reshape(h, w, 4)
    part = pixels[region.y:region.y + region.height, region.x:region.x + region.width]
    out = bpy.data.images.new("viewport", part.shape[1], part.shape[0])
    out.pixels = part.ravel()
    out.filepath_raw = path
    out.file_format = 'PNG'
    out.save()


if STEP == "bake":
    bake(*ARGS)
else:
    bpy.app.timers.register(lambda: start_rendering(*ARGS), first_interval=1.0)
