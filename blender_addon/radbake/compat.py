"""What differs between the Blender versions the add-on runs on."""
import bpy


def gltf_export_options():
    """Keyword arguments for bpy.ops.export_scene.gltf that mean the same on 3.4 and 4.x."""
    props = {p.identifier for p in bpy.ops.export_scene.gltf.get_rna_type().properties}
    options = dict(export_format='GLB', export_yup=False, export_apply=False, export_lights=True,
                   export_cameras=False, export_extras=False)
    # Lights in photometric units (a point light of P W becomes P * 683 / (4 pi) candela): the
    # option was renamed in Blender 3.6.
    for name in ("export_import_convert_lighting_mode", "convert_lighting_mode"):
        if name in props:
            options[name] = 'SPEC'
    return {k: v for k, v in options.items() if k in props or k == 'filepath'}


def _principled(material):
    if not material or not material.use_nodes:
        return None
    return next((n for n in material.node_tree.nodes if n.type == 'BSDF_PRINCIPLED'), None)


def principled_base_color(material):
    """The Principled BSDF's base colour input, or None (the socket name is the same in 3.x and 4.x)."""
    node = _principled(material)
    return node.inputs.get("Base Color") if node else None


def principled_emission(material):
    """(colour input, strength input) of the Principled BSDF's emission, or None: the colour
    socket is "Emission" in 3.x and "Emission Color" in 4.x."""
    node = _principled(material)
    if node is None:
        return None
    color = node.inputs.get("Emission Color") or node.inputs.get("Emission")
    strength = node.inputs.get("Emission Strength")
    return (color, strength) if color is not None and strength is not None else None


def new_color_attribute(mesh, name):
    """A float colour per face corner (mesh.color_attributes exists since 3.2)."""
    return mesh.color_attributes.new(name=name, type='FLOAT_COLOR', domain='CORNER')
