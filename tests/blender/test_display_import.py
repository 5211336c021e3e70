"""The display file in plain Blender: File > Import glTF, no add-on, a short render.

  blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_display_import.py -- \
      RADBAKE_BINARY SOURCE_DIR

Bakes the Cornell box sample, imports <name>_display.glb with Blender's own glTF importer, renders it
from the engine file's camera with Cycles and checks that the walls show their baked light: each
checked pixel of the back wall, the red wall and the floor is the pre-lit page as seen through that
pixel (rays cast through the pixel into the scene give the page UVs it covers). Any failed
assertion ends Blender with exit status 1.
"""
import json
import os
import subprocess
import sys
import tempfile
import time

import bpy
import mathutils

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pixels import footprint_mean, page_texel, pixel_ray, render_png, srgb_to_linear, surface_uv  # noqa: E402

RADBAKE, SOURCE = sys.argv[sys.argv.index("--") + 1:]
SIZE = 96  # render width and height in pixels
WALLS = ("back_wall", "left_wall_red", "floor")


def bake(out):
    sample = os.path.join(SOURCE, "samples/cornell_box/cornell_box.gltf")
    subprocess.run([RADBAKE, "bake", sample, "-o", out, "--max-page-size", "256", "--quiet"], check=True)
    return os.path.join(out, "cornell_box_display.glb"), os.path.join(out, "cornell_box.gltf")


def engine_camera(engine_gltf):
    """The engine file's camera node as a Blender camera object.

    A glTF camera and a Blender camera share their local frame (looking down -Z, +Y up), so the
    Blender matrix is the glTF node's matrix followed by the importer's Y-up to Z-up change of world
    axes, (x, y, z) -> (x, -z, y).
    """
    with open(engine_gltf) as f:
        doc = json.load(f)
    node = next(n for n in doc["nodes"] if "camera" in n)
    perspective = doc["cameras"][node["camera"]]["perspective"]
    t = mathutils.Vector(node.get("translation", (0, 0, 0)))
    x, y, z, w = node.get("rotation", (0, 0, 0, 1))
    gltf_matrix = mathutils.Matrix.Translation(t) @ mathutils.Quaternion((w, x, y, z)).to_matrix().to_4x4()
    y_up_to_z_up = mathutils.Matrix(((1, 0, 0, 0), (0, 0, -1, 0), (0, 1, 0, 0), (0, 0, 0, 1)))
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = 'VERTICAL'
    data.angle_y = perspective["yfov"]
    data.clip_start = perspective.get("znear", 0.01)
    camera = bpy.data.objects.new("camera", data)
    camera.matrix_world = y_up_to_z_up @ gltf_matrix
    bpy.context.scene.collection.objects.link(camera)
    return camera


def render(scene, path):
    """A small Cycles render; Standard view so the PNG holds the emitted colour sRGB-encoded as is."""
    scene.view_settings.view_transform = 'Standard'
    scene.view_settings.look = 'None'
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.display_settings.display_device = 'sRGB'
    return render_png(scene, path, SIZE, samples=64)


def restore_numpy_aliases():
    """Debian 12's Blender 3.4 runs its bundled glTF importer on Debian's numpy 1.24, which removed
    the numpy.bool alias the importer's default shading guess still uses (any glTF with normals
    fails, not only ours). A user without the add-on runs the script the add-on ships for this
    (docs/blender.md); here it runs as Blender runs a startup script, and changes nothing else: the
    import below is the importer's own, with its default options."""
    import importlib.util
    path = os.path.join(SOURCE, "blender_addon/radbake/numpy_aliases.py")
    spec = importlib.util.spec_from_file_location("numpy_aliases", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.register()


def test_display_file_plain_import():
    start = time.time()
    out = tempfile.mkdtemp(prefix="radbake_display_")
    display_glb, engine_gltf = bake(out)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    assert "radbake" not in bpy.context.preferences.addons and not hasattr(bpy.types.Scene, "radbake"), \
        "the radbake add-on is enabled: this test is about Blender without it"
    restore_numpy_aliases()
    bpy.ops.import_scene.gltf(filepath=display_glb)
    scene = bpy.context.scene
    meshes = [o for o in scene.objects if o.type == 'MESH']
    by_wall = {o.name.split(" / ")[0]: o for o in meshes}
    assert set(WALLS) <= set(by_wall), sorted(by_wall)
    # What the importer built for KHR_materials_unlit: emission seen by camera rays.
    material = by_wall["back_wall"].active_material
    assert any(n.type == 'EMISSION' for n in material.node_tree.nodes), [n.type for n in material.node_tree.nodes]
    textures = [n for n in material.node_tree.nodes if n.type == 'TEX_IMAGE']
    assert len(textures) == 1 and textures[0].image, "the unlit material has no page texture"
    page = textures[0].image
    assert page.colorspace_settings.name == 'sRGB' and not page.is_float, (page.colorspace_settings.name, page.is_float)
    page_pixels = list(page.pixels)  # a byte image: the PNG's sRGB code values / 255, bottom row first
    page_w, page_h = page.size

    camera = engine_camera(engine_gltf)
    scene.camera = camera
    image = render(scene, os.path.join(out, "render.png"))
    rendered = list(image.pixels)

    depsgraph = bpy.context.evaluated_depsgraph_get()
    frame = camera.data.view_frame(scene=scene)

    def look(x, y):
        """(wall, page colour) where the ray through image point (x, y) lands, or None."""
        seen = surface_uv(scene, depsgraph, pixel_ray(camera, frame, SIZE, x, y))
        if seen is None:
            return None
        return seen[0].name.split(" / ")[0], page_texel(page_pixels, page_w, page_h, seen[1])

    # What each pixel's centre sees; then, for the pixels of the checked walls away from their
    # edges, the page averaged over the pixel. The render's one-pixel box filter averages the page
    # over the pixel's footprint, which on the floor seen at a grazing angle spans about five
    # texels in depth, across contact shadows and colour bleeding that change faster than that:
    # an 8x8 grid of rays per pixel stands for the footprint (with a 4x4 grid the floor's worst
    # pixel used 63% of the tolerance, with 8x8 30%).
    centre = {}
    for y in range(SIZE):
        for x in range(SIZE):
            seen = look(x + 0.5, y + 0.5)
            if seen:
                centre[x, y] = seen[0]
    grid = [(i + 0.5) / 8 for i in range(8)]
    expected_at = {}
    for (x, y), name in centre.items():
        # Only pixels whose neighbours all see the same wall: an edge pixel mixes two surfaces.
        if name not in WALLS or any(centre.get((x + dx, y + dy)) != name for dx in (-1, 0, 1) for dy in (-1, 0, 1)):
            continue
        looks = [look(x + gx, y + gy) for gx in grid for gy in grid]
        assert all(l and l[0] == name for l in looks), (name, x, y)
        # The render averages light, so the page's sRGB code values are averaged as linear values
        # (averaging the codes themselves reads up to 4 codes dark across the floor's shadows).
        expected_at[x, y] = name, footprint_mean([l[1] for l in looks])

    # Tolerance, per channel, in linear values: 5% of the expected value plus what 2/255 in sRGB
    # code values is worth there. The 2/255 is 8-bit rounding: the render is written to an 8-bit
    # PNG (half a code), and the expected value decodes each 8-bit texel to linear before the
    # bilinear filter, which the renderer may do the other way round (a fraction of a code where
    # neighbouring texels differ). The 5% is for the rest: the 64-sample render and the 8x8 grid
    # each estimate the footprint average, and on the shadowed, grazing floor they differ by a
    # few percent. A tenth of a stop too bright or too dark (7%), a Filmic view or a page read as
    # Non-Color each fail on the first wall checked.
    def tolerance(expected):
        le = srgb_to_linear(expected)
        return 0.05 * le + srgb_to_linear(min(expected + 2 / 255, 1.0)) - le

    results = {}
    for wall in WALLS:
        checked, worst, means = 0, None, [[0.0] * 3, [0.0] * 3]
        for (x, y), (name, expected) in expected_at.items():
            if name != wall:
                continue
            measured = rendered[4 * (y * SIZE + x):4 * (y * SIZE + x) + 3]
            for c in range(3):
                means[0][c] += measured[c]
                means[1][c] += expected[c]
            # The error as a fraction of the tolerance, the worst channel.
            ratio = max(abs(srgb_to_linear(measured[c]) - srgb_to_linear(expected[c])) / tolerance(expected[c])
                        for c in range(3))
            if worst is None or ratio > worst[0]:
                worst = (ratio, (x, y), measured, expected)
            assert ratio <= 1, "%s pixel %s: rendered %s, page %s (sRGB codes)" % (
                wall, (x, y), [round(v * 255) for v in measured], [round(v * 255, 1) for v in expected])
            checked += 1
        assert checked >= 20, "%s: only %d pixels of it in view" % (wall, checked)
        mean_measured = [m / checked for m in means[0]]
        mean_expected = [e / checked for e in means[1]]
        results[wall] = mean_measured
        print("%s: %d pixels; mean rendered sRGB %s, mean page sRGB %s; worst pixel %s rendered %s, page %s: "
              "%.0f%% of the tolerance" % (
                  wall, checked, [round(v * 255, 1) for v in mean_measured],
                  [round(v * 255, 1) for v in mean_expected], worst[1], [round(v * 255) for v in worst[2]],
                  [round(v * 255, 1) for v in worst[3]], 100 * worst[0]))

    for wall, colour in results.items():
        assert max(colour) > 0.1, "%s is black in the render: %s" % (wall, colour)
    red = results["left_wall_red"]
    assert red[0] > 1.5 * red[1] and red[0] > 1.5 * red[2], "the red wall is not red: %s" % red
    print("display file plain import: %.1f s" % (time.time() - start))


if __name__ == "__main__":
    test_display_file_plain_import()
    print("PASSED test_display_file_plain_import")
