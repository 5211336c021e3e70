"""What the Blender tests share: a small Cycles render to an 8-bit PNG, the ray through a pixel, the
UV it lands on and the lightmap page sampled there, and the sRGB transfer function."""
import bpy
import mathutils
from mathutils.interpolate import poly_3d_calc


def srgb_to_linear(s):
    return s / 12.92 if s <= 0.04045 else ((s + 0.055) / 1.055) ** 2.4


def linear_to_srgb(v):
    return v * 12.92 if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055


def render_png(scene, path, size, samples):
    """A size x size Cycles render on a black world, written as an 8-bit PNG and loaded back. The
    view transform is left as the scene has it: what it does to the colours is what the callers
    test."""
    world = bpy.data.worlds.new("black")
    world.color = (0, 0, 0)
    world.use_nodes = False
    scene.world = world
    scene.render.engine = 'CYCLES'
    scene.cycles.device = 'CPU'
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False  # Debian's Blender has no OpenImageDenoise
    # A box filter one pixel wide averages only what the pixel covers, so a pixel is the page
    # over its own footprint (the default Blackman-Harris reaches into the neighbours).
    scene.cycles.pixel_filter_type = 'BOX'
    scene.cycles.filter_width = 1.0
    scene.render.dither_intensity = 0.0
    scene.render.resolution_x = scene.render.resolution_y = size
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = 'PNG'
    scene.render.image_settings.color_mode = 'RGB'
    scene.render.image_settings.color_depth = '8'
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(path, check_existing=False)
    assert tuple(image.size) == (size, size), tuple(image.size)
    return image


def pixel_ray(camera, frame, size, x, y):
    """The world-space ray through a point of a size x size image, (x, y) in pixels from its bottom
    left; frame is camera.data.view_frame(scene=scene)."""
    top_right, bottom_right, bottom_left, top_left = frame
    local = bottom_left + (bottom_right - bottom_left) * (x / size) + (top_left - bottom_left) * (y / size)
    if camera.data.type == 'ORTHO':
        # Parallel rays along the view axis, from the camera's plane.
        direction = camera.matrix_world.to_3x3() @ mathutils.Vector((0, 0, -1))
        return camera.matrix_world @ mathutils.Vector((local.x, local.y, 0)), direction.normalized()
    origin = camera.matrix_world.translation
    return origin, ((camera.matrix_world @ local) - origin).normalized()


def surface_uv(scene, depsgraph, ray, uv_map=None):
    """(object, UV) where the ray lands, the UV interpolated in the named UV map (the active one
    if None), or None when the ray misses."""
    hit, location, _, face, obj, matrix = scene.ray_cast(depsgraph, *ray)
    if not hit:
        return None
    mesh = obj.data
    poly = mesh.polygons[face]
    local = matrix.inverted() @ location
    corners = [mesh.vertices[mesh.loops[i].vertex_index].co for i in poly.loop_indices]
    weights = poly_3d_calc(corners, local)
    uvs = (mesh.uv_layers[uv_map] if uv_map else mesh.uv_layers.active).data
    return obj, sum((uvs[i].uv * w for i, w in zip(poly.loop_indices, weights)), mathutils.Vector((0, 0)))


def page_texel(pixels, width, height, uv):
    """The page bilinearly sampled at a Blender UV (as a Linear, clamped image texture does)."""
    fx = min(max(uv.x * width - 0.5, 0.0), width - 1.0)
    fy = min(max(uv.y * height - 0.5, 0.0), height - 1.0)
    x0, y0 = int(fx), int(fy)
    x1, y1 = min(x0 + 1, width - 1), min(y0 + 1, height - 1)
    ax, ay = fx - x0, fy - y0

    def at(x, y, c):
        return pixels[4 * (y * width + x) + c]

    return [(at(x0, y0, c) * (1 - ax) + at(x1, y0, c) * ax) * (1 - ay) +
            (at(x0, y1, c) * (1 - ax) + at(x1, y1, c) * ax) * ay for c in range(3)]


def footprint_mean(samples):
    """The sRGB colour of a pixel whose footprint holds these sRGB samples: a render averages light,
    so they are averaged as linear values."""
    return [linear_to_srgb(sum(srgb_to_linear(s[c]) for s in samples) / len(samples)) for c in range(3)]
