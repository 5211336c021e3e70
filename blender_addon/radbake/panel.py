"""The radbake panel in Render Properties."""
import bpy


class RADBAKE_PT_panel(bpy.types.Panel):
    bl_label = "radbake"
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    bl_context = "render"

    def draw(self, context):
        settings = context.scene.radbake
        layout = self.layout
        layout.use_property_split = True
        layout.prop(settings, "scope")
        layout.prop(settings, "texel_density")
        layout.prop(settings, "max_page_size")
        layout.prop(settings, "quality")
        layout.prop(settings, "solver")
        layout.prop(settings, "bring_back")
        layout.prop(settings, "standard_view")
        row = layout.row(align=True)
        row.operator("radbake.bake", icon='RENDER_STILL')
        row.operator("radbake.remove", icon='X')
