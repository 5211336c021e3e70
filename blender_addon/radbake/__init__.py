"""radbake for Blender: bake radiosity lightmaps without leaving Blender.

Render Properties > radbake: press Bake. The scene goes out through Blender's own glTF exporter,
radbake bakes it in the background (progress in the status bar, Esc cancels), and the result
comes back onto your own objects: a UV map "radbake_lightmap", a colour attribute "radbake_lux"
(illuminance in lux), the lightmap pages as images, and a copy of each material wired to show the baked light; the
scene's view becomes Standard, as Filmic would tone-map the baked light again. Remove takes all of
it away again and gives the objects their materials (and the scene its view) back.

For scripts and pipelines: bpy.ops.radbake.bake() run from Python (not from the UI) bakes
synchronously, e.g. blender -b scene.blend --python-expr "import bpy; bpy.ops.radbake.bake()".
"""

bl_info = {
    "name": "radbake",
    "author": "radbake developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "Properties > Render > radbake",
    "description": "Bake radiosity lightmaps with radbake and bring them back onto your objects",
    "category": "Render",
}

import bpy  # noqa: E402
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, PointerProperty, StringProperty  # noqa: E402


class RadbakePreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    executable: StringProperty(
        name="radbake executable",
        description="Path to the radbake program; empty finds it on PATH",
        subtype='FILE_PATH',
        default="",
    )

    def draw(self, context):
        self.layout.prop(self, "executable")


class RadbakeSettings(bpy.types.PropertyGroup):
    scope: EnumProperty(
        name="Bake",
        description="Which objects receive the baked light (the whole scene always lights and shadows them)",
        items=[('SCENE', "Whole scene", "Every mesh object in the scene"),
               ('SELECTION', "Selection", "Only the selected mesh objects")],
        default='SCENE',
    )
    texel_density: FloatProperty(
        name="Texel density",
        description="Lightmap texels per metre; 0 is automatic: about 50,000 texels over the scene, fewer if they do not fit one page",
        min=0.0, max=10000.0, soft_max=1000.0, default=0.0, unit='NONE',
    )
    max_page_size: IntProperty(
        name="Page size",
        description="Largest lightmap page side, in texels",
        min=16, max=16384, default=1024,
    )
    quality: EnumProperty(
        name="Quality",
        description="How many rays radbake spends: more is smoother and slower",
        items=[('DRAFT', "Draft", "Few rays: a quick look (about 4% from the reference, docs/accuracy.md)"),
               ('PREVIEW', "Preview", "radbake's defaults (2-3% from the reference)"),
               ('PRODUCTION', "Production", "More rays and smaller patches (under 1% from the reference, 4-5x the time)")],
        default='PREVIEW',
    )
    solver: EnumProperty(
        name="Solver",
        description="How radbake solves the radiosity equation; all stop on the same unshot-light tolerance",
        items=[('shooting', "Progressive shooting", "Shoot the patch with the most unshot light first"),
               ('gauss-seidel', "Gauss-Seidel", "Gathering sweeps, each using the newest values"),
               ('jacobi', "Jacobi", "Gathering sweeps from the previous sweep's values")],
        default='shooting',
    )
    bring_back: EnumProperty(
        name="Bring back",
        description="What the bake adds to your objects",
        items=[('BOTH', "Lightmaps and colours", "Lightmap images on the materials and a colour attribute"),
               ('IMAGES', "Lightmaps", "Lightmap images wired into copies of the materials"),
               ('COLORS', "Vertex colours", "Only the 'radbake' colour attribute")],
        default='BOTH',
    )
    standard_view: BoolProperty(
        name="Standard view",
        description="Switch the scene to the Standard view transform with no look, so the bake shows as the lightmap holds it: "
                    "Filmic would tone-map light that is already baked (Remove bake switches back)",
        default=True,
    )


from .operators import RADBAKE_OT_bake, RADBAKE_OT_remove  # noqa: E402
from .panel import RADBAKE_PT_panel  # noqa: E402

classes = (RadbakePreferences, RadbakeSettings, RADBAKE_OT_bake, RADBAKE_OT_remove, RADBAKE_PT_panel)


def register():
    # Blender 3.4's own glTF importer fails on Debian's numpy 1.24 without these aliases: with the
    # add-on enabled, File > Import > glTF works for the rest of the session (numpy_aliases.py).
    from . import numpy_aliases
    numpy_aliases.restore()
    for cls in classes:
        bpy.utils.register_class(cls)
    bpy.types.Scene.radbake = PointerProperty(type=RadbakeSettings)


def unregister():
    del bpy.types.Scene.radbake
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
