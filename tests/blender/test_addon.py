"""The Blender add-on in real, headless Blender, installed from its zip as a user would.

  blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_addon.py -- \
      ADDON.zip RADBAKE_BINARY SOURCE_DIR CASE

CASE is one of the test functions below (ctest runs each as its own test). Any failed assertion
ends Blender with exit status 1.
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile
import warnings

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pixels import footprint_mean, page_texel, pixel_ray, render_png, surface_uv  # noqa: E402

ADDON_ZIP, RADBAKE, SOURCE, CASE = sys.argv[sys.argv.index("--") + 1:]
ALIASES_SCRIPT = os.path.join(SOURCE, "blender_addon/radbake/numpy_aliases.py")
# What numpy 1.24 removed; Debian 12's numpy is 1.24.2.
REMOVED_ALIASES = ("bool", "int", "float", "complex", "object", "str")


def install_addon():
    bpy.ops.preferences.addon_install(filepath=ADDON_ZIP, overwrite=True)
    bpy.ops.preferences.addon_enable(module="radbake")
    bpy.context.preferences.addons["radbake"].preferences.executable = RADBAKE


def cornell_box():
    """The Cornell box, built in Blender from the sample through Blender's own glTF importer."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    install_addon()
    bpy.ops.import_scene.gltf(filepath=os.path.join(SOURCE, "samples/cornell_box/cornell_box.gltf"))
    scene = bpy.context.scene
    scene.radbake.max_page_size = 256
    scene.radbake.quality = 'DRAFT'
    return scene


def snapshot():
    """What a bake may change, so a test can tell whether the scene is as it was."""
    objects = {}
    for o in bpy.data.objects:
        if o.type != 'MESH':
            continue
        objects[o.name] = (o.data.name, tuple(s.material.name if s.material else "" for s in o.material_slots),
                           tuple(l.name for l in o.data.uv_layers), tuple(a.name for a in o.data.color_attributes))
    view = bpy.context.scene.view_settings
    return objects, sorted(m.name for m in bpy.data.materials), sorted(i.name for i in bpy.data.images), \
        sorted(m.name for m in bpy.data.meshes), (view.view_transform, view.look)


def bake():
    """The operator's result; in background mode an error report comes back as a RuntimeError."""
    try:
        return bpy.ops.radbake.bake()
    except RuntimeError as e:
        print("reported:", e)
        return {'CANCELLED'}


def corner_colours(obj, facing):
    """Mean baked colour of the object's face corners whose face normal points along `facing`."""
    attr = obj.data.color_attributes["radbake_lux"]
    total, count = [0.0, 0.0, 0.0], 0
    for poly in obj.data.polygons:
        n = poly.normal
        if n.x * facing[0] + n.y * facing[1] + n.z * facing[2] < 0.7:
            continue
        for i in poly.loop_indices:
            c = attr.data[i].color
            total = [total[k] + c[k] for k in range(3)]
            count += 1
    assert count > 0, "no faces of %s face %s" % (obj.name, facing)
    return [t / count for t in total]


def test_cornell_box_bakes_onto_the_original_objects():
    scene = cornell_box()
    before = snapshot()
    assert bake() == {'FINISHED'}
    objects, materials, images, meshes, view = snapshot()
    assert set(objects) == set(before[0]), "objects added or lost"
    assert meshes == before[3], "meshes were duplicated"
    assert before[4] == ('Filmic', 'None') and view == ('Standard', 'None'), (before[4], view)
    pages = [i for i in bpy.data.images if i.get("radbake")]
    assert pages, "no lightmap images"
    for image in pages:
        pixels = list(image.pixels)
        assert all(math.isfinite(p) for p in pixels), "non-finite lightmap texels"
        assert max(pixels) > 0, "black lightmap"
    for name, (_, slots, uv_layers, colours) in objects.items():
        assert "radbake_lightmap" in uv_layers and "radbake_lux" in colours, name
        assert all(bpy.data.materials[s].get("radbake") for s in slots), (name, slots)
    # Colour bleeding: the short block's face toward the red wall (+x) is redder than the one
    # toward the green wall (-x).
    block = bpy.data.objects["short_block"]
    red_side, green_side = corner_colours(block, (1, 0, 0)), corner_colours(block, (-1, 0, 0))
    print("red side", red_side, "green side", green_side)
    assert red_side[0] / red_side[1] > 1.2 * green_side[0] / green_side[1], (red_side, green_side)

    # The materials show the lightmap: a tiny Cycles render from the sample's camera is lit and
    # redder on the left (the red wall) than on the right.
    scene.camera = bpy.data.objects["camera"]
    scene.render.engine = 'CYCLES'
    scene.cycles.device = 'CPU'
    scene.cycles.samples = 4
    scene.cycles.use_denoising = False  # Debian's Blender has no OpenImageDenoise
    scene.render.resolution_x = scene.render.resolution_y = 32
    scene.render.filepath = os.path.join(tempfile.mkdtemp(), "render.png")
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(scene.render.filepath)
    px = list(image.pixels)
    w = image.size[0]

    def mean(x0, x1):
        values = [px[4 * (y * w + x) + c] for y in range(8, 24) for x in range(x0, x1) for c in range(3)]
        r = [px[4 * (y * w + x)] for y in range(8, 24) for x in range(x0, x1)]
        g = [px[4 * (y * w + x) + 1] for y in range(8, 24) for x in range(x0, x1)]
        return sum(values) / len(values), sum(r) / len(r), sum(g) / len(g)

    left, right = mean(0, 4), mean(28, 32)
    print("render left", left, "right", right)
    assert left[0] > 0.02 and right[0] > 0.02, "the render is black"
    assert left[1] / max(left[2], 1e-6) > right[1] / max(right[2], 1e-6), "the red wall is not on the left"


def test_baking_twice_replaces_and_remove_restores():
    cornell_box()
    before = snapshot()
    assert bake() == {'FINISHED'}
    once = snapshot()
    block = bpy.data.objects["short_block"]
    light_once = corner_colours(block, (1, 0, 0))
    assert bake() == {'FINISHED'}
    twice = snapshot()
    assert once == twice, "a second bake piled things up"
    # The first bake's light (lux on the meshes) must not reach the second as a base-colour
    # multiplier: the same scene bakes to the same light (same seed, so within float noise).
    light_twice = corner_colours(block, (1, 0, 0))
    assert all(abs(a - b) <= 1e-3 * max(a, 1.0) for a, b in zip(light_once, light_twice)), (light_once, light_twice)
    assert bpy.ops.radbake.remove() == {'FINISHED'}
    assert snapshot() == before, "remove did not restore the scene"


def test_selection_scope_bakes_only_the_selected_objects():
    """The whole scene still lights the selection, but only the selection receives the bake."""
    scene = cornell_box()
    scene.radbake.scope = 'SELECTION'
    bpy.ops.object.select_all(action='DESELECT')
    bpy.data.objects["short_block"].select_set(True)
    objects_before = snapshot()[0]
    assert bake() == {'FINISHED'}
    objects_after = snapshot()[0]
    for name, state in objects_after.items():
        if name == "short_block":
            assert "radbake_lightmap" in state[2] and "radbake_lux" in state[3], state
        else:
            assert state == objects_before[name], (name, state)
    # Lit by the rest of the scene: the face toward the red wall sees red light.
    red_side = corner_colours(bpy.data.objects["short_block"], (1, 0, 0))
    assert red_side[0] > red_side[1] > 0, red_side


def test_a_failing_bake_changes_nothing():
    cornell_box()
    before = snapshot()
    prefs = bpy.context.preferences.addons["radbake"].preferences
    prefs.executable = "/nonexistent/radbake"
    assert bake() == {'CANCELLED'}
    assert snapshot() == before
    from radbake.runner import BakeError, find_executable
    try:
        find_executable(bpy.context)
        raise AssertionError("a missing executable was accepted")
    except BakeError as e:
        assert "not found" in str(e), str(e)
    prefs.executable = RADBAKE

    # Nothing emits light: radbake's own reason comes back, the scene stays as it was.
    bpy.ops.wm.read_factory_settings(use_empty=True)
    install_addon()
    bpy.ops.mesh.primitive_cube_add()
    before = snapshot()
    from radbake import runner
    bake_job = runner.Bake(bpy.context)
    bake_job.export(bpy.context)
    bake_job.start(bpy.context.scene.radbake)
    bake_job.wait()
    try:
        bake_job.check()
        raise AssertionError("a bake without light succeeded")
    except BakeError as e:
        assert "nothing in the scene emits light" in str(e), str(e)
    finally:
        bake_job.cleanup()
    assert bake() == {'CANCELLED'}
    assert snapshot() == before

    # Selection scope with nothing selected.
    bpy.context.scene.radbake.scope = 'SELECTION'
    bpy.ops.object.select_all(action='DESELECT')
    bpy.ops.object.light_add(type='POINT', location=(0, 0, 3))
    bpy.ops.object.select_all(action='DESELECT')
    before = snapshot()
    assert bake() == {'CANCELLED'}
    assert snapshot() == before


def test_cancel_ends_radbake_and_leaves_nothing_behind():
    """What Esc does in the modal bake: progress has arrived, then the process ends, its temporary
    folder goes and the scene is as it was."""
    import time
    scene = cornell_box()  # installs the add-on this case's own scripts folder starts without
    from radbake import runner
    scene.radbake.quality = 'PRODUCTION'
    scene.radbake.max_page_size = 1024
    before = snapshot()
    job = runner.Bake(bpy.context)
    job.export(bpy.context)
    job.start(scene.radbake)
    deadline = time.monotonic() + 120
    while job.fraction == 0 and time.monotonic() < deadline:
        assert not job.poll(), "radbake finished before it could be cancelled"
        time.sleep(0.05)
    print("cancelled at", job.stage, job.fraction)
    assert job.fraction > 0, "no progress from radbake"
    job.cleanup()
    assert job.process.poll() is not None, "radbake still running"
    assert not os.path.exists(job.folder), "temporary files left"
    assert snapshot() == before


def test_point_light_power_gives_the_documented_illuminance():
    """README: Blender's exporter turns a point light of P watts into P * 683 / (4 pi) candela, so a
    surface d metres below it, facing it, reads P * 683 / (4 pi d^2) lux."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    install_addon()
    bpy.ops.mesh.primitive_grid_add(x_subdivisions=10, y_subdivisions=10, size=2)
    plane = bpy.context.active_object
    black = bpy.data.materials.new("black")
    black.use_nodes = True
    black.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0, 0, 0, 1)
    plane.data.materials.append(black)
    bpy.ops.object.light_add(type='POINT', location=(0, 0, 1))
    light = bpy.context.active_object
    light.data.energy = 100.0
    light.data.shadow_soft_size = 0
    scene = bpy.context.scene
    scene.radbake.texel_density = 64
    scene.radbake.bring_back = 'COLORS'
    assert bake() == {'FINISHED'}
    attr = plane.data.color_attributes["radbake_lux"]
    # The vertex nearest the centre, at distance r from the foot of the light: E = I cos(theta) / d^2.
    vertices = plane.data.vertices
    nearest = min(range(len(vertices)), key=lambda v: vertices[v].co.length)
    corners = [i for i, loop in enumerate(plane.data.loops) if loop.vertex_index == nearest]
    measured = sum(attr.data[i].color[0] for i in corners) / len(corners)
    r = vertices[nearest].co.length
    assert r < 0.15, r
    expected = 100.0 * 683 / (4 * math.pi) / (1.0 + r * r) ** 1.5
    print("centre illuminance", measured, "lux, expected", expected)
    assert abs(measured / expected - 1) < 0.02, (measured, expected)  # 2%: the vertex fit over 1/64 m texels


def numpy_lacks_the_aliases():
    import numpy
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FutureWarning)  # numpy 1.24 warns on the lookup itself
        return not hasattr(numpy, "bool")


def display_file():
    """A radbake output file: the Cornell box sample baked by the command line."""
    out = tempfile.mkdtemp(prefix="radbake_numpy_")
    sample = os.path.join(SOURCE, "samples/cornell_box/cornell_box.gltf")
    subprocess.run([RADBAKE, "bake", sample, "-o", out, "--max-page-size", "256", "--quality", "draft", "--quiet"],
                   check=True)
    return os.path.join(out, "cornell_box_display.glb")


def import_gltf(path):
    """Blender's own importer, File > Import > glTF 2.0 with its defaults: the meshes it made, or the
    importer's error."""
    before = set(bpy.data.objects)
    try:
        bpy.ops.import_scene.gltf(filepath=path)
    except RuntimeError as e:
        return str(e)
    return [o for o in bpy.data.objects if o not in before and o.type == 'MESH']


def test_plain_import_fails_on_this_numpy_without_the_aliases():
    """The control: on Debian's numpy 1.24 Blender 3.4 imports no glTF at all, not only radbake's."""
    path = display_file()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    assert "radbake" not in bpy.context.preferences.addons
    import numpy
    if not numpy_lacks_the_aliases():
        print("numpy %s has numpy.bool: nothing to mend here; the import must simply work" % numpy.__version__)
        assert isinstance(import_gltf(path), list)
        return
    for sample in (path, os.path.join(SOURCE, "samples/cornell_box/cornell_box.gltf")):
        result = import_gltf(sample)
        print("numpy", numpy.__version__, os.path.basename(sample), "->", str(result)[-200:])
        assert isinstance(result, str) and "has no attribute 'bool'" in result, result


def test_enabling_the_addon_mends_plain_import():
    """With the add-on enabled, File > Import > glTF works in the same session, on the file radbake
    wrote and on any other."""
    path = display_file()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    lacked = numpy_lacks_the_aliases()
    install_addon()
    import builtins
    import numpy
    if lacked:
        for name in REMOVED_ALIASES:
            assert getattr(numpy, name) is getattr(builtins, name), name
    meshes = import_gltf(path)
    assert isinstance(meshes, list), meshes
    walls = {o.name.split(" / ")[0] for o in meshes}
    assert {"back_wall", "left_wall_red", "floor", "short_block"} <= walls, sorted(walls)
    # File > New keeps the session's Python, and with it the aliases.
    bpy.ops.wm.read_homefile(use_empty=True)
    meshes = import_gltf(os.path.join(SOURCE, "samples/cornell_box/cornell_box.gltf"))
    assert isinstance(meshes, list) and meshes, meshes


def test_the_startup_script_mends_plain_import_without_the_addon():
    """A user without the add-on: numpy_aliases.py in the startup scripts folder, or run once with
    --python. Each is a Blender of its own, started as the user starts it (without
    --factory-startup, which skips the startup folder) on an empty configuration."""
    path = display_file()
    expr = ("import bpy, sys; bpy.ops.wm.read_factory_settings(use_empty=True); "
            "bpy.ops.import_scene.gltf(filepath=%r); "
            "n = sum(o.type == 'MESH' for o in bpy.data.objects); print('imported meshes:', n); "
            "sys.exit(0 if n else 1)" % path)

    def blender(startup_scripts, *args):
        home = tempfile.mkdtemp(prefix="radbake_blender_home_")
        scripts = os.path.join(home, "scripts")
        os.makedirs(os.path.join(scripts, "startup"))
        for script in startup_scripts:
            shutil.copy(script, os.path.join(scripts, "startup"))
        env = dict(os.environ, BLENDER_USER_SCRIPTS=scripts, BLENDER_USER_CONFIG=os.path.join(home, "config"))
        run = subprocess.run([bpy.app.binary_path, "-b", *args, "--python-exit-code", "1", "--python-expr", expr],
                             env=env, capture_output=True, text=True, timeout=300)
        output = run.stdout + run.stderr
        print(args or startup_scripts, "exit", run.returncode, [l for l in output.splitlines() if "imported" in l])
        return run.returncode, output

    if numpy_lacks_the_aliases():
        code, output = blender([])
        assert code != 0 and "has no attribute 'bool'" in output, output[-2000:]
    code, output = blender([ALIASES_SCRIPT])
    assert code == 0, output[-2000:]
    code, output = blender([], "--factory-startup", "--python", ALIASES_SCRIPT)
    assert code == 0, output[-2000:]
    assert "numpy aliases restored:" in output, output[-2000:]


def test_the_bake_shows_as_the_lightmap_png():
    """After Bake, the scene's view is Standard and a render of a baked surface shows the lightmap
    PNG's texels. A white floor under a point light, seen from straight above: every pixel is base
    colour 1 x the page, so it should read the PNG's own sRGB codes. Under Filmic, Blender's
    default, the same render is off by far more."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    install_addon()
    scene = bpy.context.scene
    assert scene.view_settings.view_transform == 'Filmic', scene.view_settings.view_transform
    bpy.ops.mesh.primitive_plane_add(size=2)
    floor = bpy.context.active_object
    white = bpy.data.materials.new("white")
    white.use_nodes = True
    white.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (1, 1, 1, 1)
    floor.data.materials.append(white)
    bpy.ops.object.light_add(type='POINT', location=(0.3, 0.2, 0.8))
    bpy.context.active_object.data.energy = 100.0
    bpy.context.active_object.data.shadow_soft_size = 0
    scene.radbake.texel_density = 32
    scene.radbake.bring_back = 'IMAGES'

    # The bake's own output folder, kept past the add-on's cleanup for its PNG page.
    from radbake import runner
    kept = os.path.join(tempfile.mkdtemp(prefix="radbake_view_"), "baked")
    cleanup = runner.Bake.cleanup

    def keep_output(bake):
        if os.path.isdir(bake.output):
            shutil.copytree(bake.output, kept)
        cleanup(bake)
    runner.Bake.cleanup = keep_output
    try:
        assert bake() == {'FINISHED'}
    finally:
        runner.Bake.cleanup = cleanup
    assert (scene.view_settings.view_transform, scene.view_settings.look) == ('Standard', 'None'), \
        (scene.view_settings.view_transform, scene.view_settings.look)

    pngs = sorted(f for f in os.listdir(kept) if "_lightmap_" in f and f.endswith(".png"))
    assert len(pngs) == 1, pngs
    page = bpy.data.images.load(os.path.join(kept, pngs[0]))
    page_pixels = list(page.pixels)  # a byte image: the PNG's sRGB codes / 255, bottom row first
    page_w, page_h = page.size

    camera_data = bpy.data.cameras.new("above")
    camera_data.type = 'ORTHO'
    camera_data.ortho_scale = 2.0
    camera = bpy.data.objects.new("above", camera_data)
    camera.location = (0, 0, 3)
    scene.collection.objects.link(camera)
    scene.camera = camera
    size = 24
    # The frame follows the render's aspect: square before it is taken.
    scene.render.resolution_x = scene.render.resolution_y = size
    depsgraph = bpy.context.evaluated_depsgraph_get()
    frame = camera.data.view_frame(scene=scene)
    grid = [(i + 0.5) / 4 for i in range(4)]
    expected = {}
    # The page over each pixel's footprint (4x4 rays), one pixel in from the floor's edges, where
    # the box filter would mix in the black beyond.
    for y in range(1, size - 1):
        for x in range(1, size - 1):
            texels = []
            for gx in grid:
                for gy in grid:
                    seen = surface_uv(scene, depsgraph, pixel_ray(camera, frame, size, x + gx, y + gy), "radbake_lightmap")
                    assert seen and seen[0] == floor, (x, y)
                    texels.append(page_texel(page_pixels, page_w, page_h, seen[1]))
            expected[x, y] = footprint_mean(texels)

    def worst_error(view_transform):
        """The largest and the mean difference, in 8-bit codes, between a rendered pixel and the PNG."""
        scene.view_settings.view_transform = view_transform
        image = render_png(scene, os.path.join(kept, view_transform + ".png"), size, samples=16)
        rendered = list(image.pixels)
        errors = [abs(rendered[4 * (y * size + x) + c] - e[c]) * 255 for (x, y), e in expected.items() for c in range(3)]
        return max(errors), sum(errors) / len(errors)

    lit = [e[0] * 255 for e in expected.values()]
    print("PNG codes over the floor: %.0f to %.0f" % (min(lit), max(lit)))
    assert min(lit) < 128 < max(lit), "the floor should span dark to bright"
    standard, standard_mean = worst_error('Standard')
    filmic, filmic_mean = worst_error('Filmic')
    print("render against the PNG: Standard worst %.2f, mean %.2f codes; Filmic worst %.1f, mean %.1f codes"
          % (standard, standard_mean, filmic, filmic_mean))
    # 1.5 codes: the PNG page and the rendered PNG are each rounded to 8 bits (half a code each),
    # and the render's 16 samples and the 4x4 rays estimate each pixel's footprint average a little
    # differently (measured worst 0.92, mean 0.28). A tenth of a stop too bright or dark is about
    # 4 codes at mid-grey; Filmic misses by up to 49.
    assert standard <= 1.5, "Standard view: a pixel %.2f codes off the lightmap PNG" % standard
    assert filmic > 10.0, "Filmic no longer shifts the baked colours (%.1f codes): is the test blind?" % filmic


if __name__ == "__main__":
    globals()[CASE]()
    print("PASSED", CASE)
