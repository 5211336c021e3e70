"""Bringing a bake back onto the user's own objects, and taking it away again.

What the add-on adds carries the name "radbake": the UV map "radbake_lightmap" and colour
attribute "radbake_lux" on each mesh, the lightmap images, and per material slot a copy of the material ("<name> (radbake)") wired to
show the baked light; the object remembers its original materials so Remove can put them back.
"""
import contextlib
import json
import math
import os
import struct

import bpy
import numpy

from . import compat
from .runner import LUMENS_PER_WATT

NAME = "radbake"                       # the custom property marking what the add-on made
UV_MAP = "radbake_lightmap"            # UV maps and colour attributes share one namespace
COLORS = "radbake_lux"                 # illuminance in lux (or radiosity in lm/m2) per corner
ORIGINAL_MATERIALS = "radbake_original_materials"  # per slot, "" for an empty slot
ADDED_SLOT = "radbake_added_slot"                  # the object had no material slot
ORIGINAL_MESH = "radbake_original_mesh"            # the mesh it shared with other objects
ORIGINAL_VIEW = "radbake_original_view"            # on the scene: [view transform, look] before the bake
EMITTED_PER_STRENGTH = LUMENS_PER_WATT * math.pi  # lm/m2 leaving per unit of Blender emission strength
COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}
DTYPES = {5126: numpy.float32, 5125: numpy.uint32, 5123: numpy.uint16, 5121: numpy.uint8}


class BakedScene:
    """The baked glTF as arrays: per node name, per primitive, corner positions, lightmap UVs,
    colours and page."""

    def __init__(self, folder):
        gltf = next(f for f in os.listdir(folder) if f.endswith(".gltf"))
        with open(os.path.join(folder, gltf)) as f:
            self.doc = json.load(f)
        self.folder = folder
        self.buffers = {}
        info = self.doc["extras"]["radbake"]
        self.exr_pages = [os.path.join(folder, p["exr"]) for p in info["pages"]]
        self.page_of_texture = {p["texture"]: i for i, p in enumerate(info["pages"])}
        self.png_intensity = float(info["png_intensity"])

    def _buffer(self, index):
        if index not in self.buffers:
            with open(os.path.join(self.folder, self.doc["buffers"][index]["uri"]), "rb") as f:
                self.buffers[index] = f.read()
        return self.buffers[index]

    def accessor(self, index):
        a = self.doc["accessors"][index]
        view = self.doc["bufferViews"][a["bufferView"]]
        dtype = numpy.dtype(DTYPES[a["componentType"]])
        n = COMPONENTS[a["type"]]
        stride = view.get("byteStride", 0) or dtype.itemsize * n
        data = self._buffer(view["buffer"])
        start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
        rows = numpy.ndarray((a["count"], n), dtype=dtype, buffer=data, offset=start, strides=(stride, dtype.itemsize))
        return numpy.array(rows)

    def primitives(self, node_name):
        """(positions per corner, lightmap UV per corner, colour per corner, page) per primitive."""
        node = next((n for n in self.doc["nodes"] if n.get("name") == node_name and "mesh" in n), None)
        if node is None:
            return []
        out = []
        for prim in self.doc["meshes"][node["mesh"]]["primitives"]:
            if prim.get("mode", 4) != 4 or "_BAKED_LIGHT" not in prim["attributes"]:
                continue
            # A double-sided face's back, baked apart: a Blender face has one UV and colour per
            # corner, so the add-on brings back the fronts' light.
            if "back_faces_of_primitive" in prim.get("extras", {}).get("radbake", {}):
                continue
            material = self.doc["materials"][prim["material"]]
            lightmap = material["extensions"]["MOZ_lightmap"]
            uv_set = "TEXCOORD_%d" % lightmap["texCoord"]
            corners = self.accessor(prim["indices"]).reshape(-1) if "indices" in prim else None
            positions = self.accessor(prim["attributes"]["POSITION"])
            uvs = self.accessor(prim["attributes"][uv_set])
            colors = self.accessor(prim["attributes"]["_BAKED_LIGHT"])  # lux, linear
            if corners is not None:
                positions, uvs, colors = positions[corners], uvs[corners], colors[corners]
            out.append((positions, uvs, colors, self.page_of_texture[lightmap["index"]]))
        return out


def _key(p):
    return (round(float(p[0]), 5), round(float(p[1]), 5), round(float(p[2]), 5))


def _corner_values(obj, primitives):
    """Per loop of obj's mesh: (lightmap uv, colour, page), matched by position. The exporter may
    split a polygon along another diagonal than Blender did, so each polygon is matched to every
    baked triangle whose corners are all among its vertices."""
    triangles = {}
    for positions, uvs, colors, page in primitives:
        for t in range(len(positions) // 3):
            keys = [_key(positions[3 * t + k]) for k in range(3)]
            triangles.setdefault(frozenset(keys), []).append(
                {keys[k]: (uvs[3 * t + k], colors[3 * t + k], page) for k in range(3)})
    mesh = obj.data
    values = [None] * len(mesh.loops)
    for poly in mesh.polygons:
        keys = [_key(mesh.vertices[mesh.loops[i].vertex_index].co) for i in poly.loop_indices]
        corner = {}
        n = len(keys)
        for a in range(n):
            for b in range(a + 1, n):
                for c in range(b + 1, n):
                    for found in triangles.get(frozenset((keys[a], keys[b], keys[c])), []):
                        for k, v in found.items():
                            corner.setdefault(k, v)
        for i, k in zip(poly.loop_indices, keys):
            values[i] = corner.get(k)
    return values


@contextlib.contextmanager
def earlier_bake_set_aside():
    """While the scene is exported for the next bake, what the earlier bake added is taken off, so
    the next bake sees the user's scene: Blender's exporter would write the lightmap UV map as a
    TEXCOORD (which radbake keeps as given lightmap UVs), the render colour attribute as COLOR_0
    (a base-colour multiplier in glTF, and lux is not a reflectance) and the lightmap materials
    instead of the user's."""
    layers, slots = [], []
    for mesh in bpy.data.meshes:
        if UV_MAP in mesh.uv_layers:
            uvs = numpy.empty(len(mesh.uv_layers[UV_MAP].data) * 2, dtype=numpy.float32)
            mesh.uv_layers[UV_MAP].data.foreach_get("uv", uvs)
            layers.append((mesh, "uv", uvs, False))
            mesh.uv_layers.remove(mesh.uv_layers[UV_MAP])
        if COLORS in mesh.color_attributes:
            attribute = mesh.color_attributes[COLORS]
            colors = numpy.empty(len(attribute.data) * 4, dtype=numpy.float32)
            attribute.data.foreach_get("color", colors)
            is_render_color = mesh.color_attributes.find(COLORS) == mesh.color_attributes.render_color_index
            layers.append((mesh, "color", colors, is_render_color))
            mesh.color_attributes.remove(attribute)
    for obj in bpy.data.objects:
        originals = obj.get(ORIGINAL_MATERIALS) if obj.type == 'MESH' else None
        if originals is not None:
            slots.append((obj, [slot.material for slot in obj.material_slots]))
            for slot, name in zip(obj.material_slots, list(originals)):
                slot.material = bpy.data.materials.get(name) if name else None
    try:
        yield
    finally:
        for obj, materials in slots:
            for slot, material in zip(obj.material_slots, materials):
                slot.material = material
        for mesh, kind, values, is_render_color in layers:
            if kind == "uv":
                mesh.uv_layers.new(name=UV_MAP).data.foreach_set("uv", values)
            else:
                compat.new_color_attribute(mesh, COLORS).data.foreach_set("color", values)
                if is_render_color:
                    mesh.color_attributes.render_color_index = mesh.color_attributes.find(COLORS)


def _remove_named_layers(mesh):
    if UV_MAP in mesh.uv_layers:
        mesh.uv_layers.remove(mesh.uv_layers[UV_MAP])
    if COLORS in mesh.color_attributes:
        mesh.color_attributes.remove(mesh.color_attributes[COLORS])


def _lightmap_material(original, image, page, exposure):
    """A copy of `original` (or a plain white material) whose surface is its base colour times the
    lightmap: the baked light, unlit, as engines show lightmaps."""
    copy = original.copy() if original else bpy.data.materials.new("radbake default")
    copy.name = "%s (radbake%s)" % (original.name if original else "default", " page %d" % page if page else "")
    copy[NAME] = True
    copy.use_nodes = True
    nodes, links = copy.node_tree.nodes, copy.node_tree.links
    output = next((n for n in nodes if n.type == 'OUTPUT_MATERIAL' and n.is_active_output), None) or nodes.new("ShaderNodeOutputMaterial")
    uv = nodes.new("ShaderNodeUVMap")
    uv.uv_map = UV_MAP
    tex = nodes.new("ShaderNodeTexImage")
    tex.image = image
    tex.interpolation = 'Linear'
    links.new(uv.outputs["UV"], tex.inputs["Vector"])
    scaled = nodes.new("ShaderNodeVectorMath")
    scaled.operation = 'SCALE'
    scaled.inputs["Scale"].default_value = exposure
    links.new(tex.outputs["Color"], scaled.inputs[0])
    albedo = nodes.new("ShaderNodeVectorMath")
    albedo.operation = 'MULTIPLY'
    links.new(scaled.outputs["Vector"], albedo.inputs[0])
    base = compat.principled_base_color(copy)
    if base is not None and base.is_linked:
        links.new(base.links[0].from_socket, albedo.inputs[1])
    else:
        albedo.inputs[1].default_value = tuple(base.default_value[:3]) if base is not None else (0.8, 0.8, 0.8)
    shown = albedo
    emitted = _emitted_light(copy, nodes, links, exposure)
    if emitted is not None:
        shown = nodes.new("ShaderNodeVectorMath")
        shown.operation = 'ADD'
        links.new(albedo.outputs["Vector"], shown.inputs[0])
        links.new(emitted.outputs["Vector"], shown.inputs[1])
    emission = nodes.new("ShaderNodeEmission")
    links.new(shown.outputs["Vector"], emission.inputs["Color"])
    links.new(emission.outputs["Emission"], output.inputs["Surface"])
    x = output.location.x
    for i, node in enumerate((uv, tex, scaled, albedo, emission)):
        node.location = (x - 1000 + 200 * i, output.location.y - 400)
    return copy


def _emitted_light(material, nodes, links, exposure):
    """The material's own emission on the lightmap's scale, or None when it emits nothing. The
    lightmap holds illuminance E, shown as base colour x E (the light leaving, in lm/m2); radbake
    counts an emission strength S as S x 683 x pi lm/m2 leaving (runner.EMISSION_SCALE)."""
    emission = compat.principled_emission(material)
    if emission is None:
        return None
    color, strength = emission
    if not strength.is_linked and strength.default_value <= 0:
        return None
    scaled = nodes.new("ShaderNodeVectorMath")
    scaled.operation = 'SCALE'
    if color.is_linked:
        links.new(color.links[0].from_socket, scaled.inputs[0])
    else:
        scaled.inputs[0].default_value = tuple(color.default_value[:3])
    if strength.is_linked:
        factor = nodes.new("ShaderNodeMath")
        factor.operation = 'MULTIPLY'
        links.new(strength.links[0].from_socket, factor.inputs[0])
        factor.inputs[1].default_value = EMITTED_PER_STRENGTH * exposure
        links.new(factor.outputs["Value"], scaled.inputs["Scale"])
    else:
        scaled.inputs["Scale"].default_value = strength.default_value * EMITTED_PER_STRENGTH * exposure
    return scaled


def use_standard_view(scene):
    """The Standard view transform, no look: the lightmap material emits base colour x the baked
    light on the PNG's scale, and Standard shows that as the PNG's sRGB codes. Blender's default,
    Filmic, tone-maps it a second time (measured: up to 49 of 255 off the page, tests/blender). The
    first bake remembers the scene's own view for Remove."""
    view = scene.view_settings
    if ORIGINAL_VIEW not in scene:
        scene[ORIGINAL_VIEW] = [view.view_transform, view.look]
    view.view_transform = 'Standard'
    view.look = 'None'


def restore_view(scene):
    """The view the scene had before its first bake switched it to Standard."""
    original = scene.get(ORIGINAL_VIEW)
    if original is not None:
        scene.view_settings.view_transform, scene.view_settings.look = original
        del scene[ORIGINAL_VIEW]


def remove(objects):
    """Takes away everything a bake added to these objects; unused radbake images and materials go too."""
    _detach(objects)
    _purge_unused()


def _detach(objects):
    for obj in objects:
        if obj.type != 'MESH':
            continue
        _remove_named_layers(obj.data)
        originals = obj.get(ORIGINAL_MATERIALS)
        if originals is not None:
            for slot, name in zip(obj.material_slots, list(originals)):
                slot.material = bpy.data.materials.get(name) if name else None
            del obj[ORIGINAL_MATERIALS]
        if obj.get(ADDED_SLOT):
            obj.data.materials.pop(index=len(obj.data.materials) - 1)
            del obj[ADDED_SLOT]
        original_mesh = bpy.data.meshes.get(obj.get(ORIGINAL_MESH, ""))
        if original_mesh is not None:
            own = obj.data
            obj.data = original_mesh
            if own.users == 0:
                bpy.data.meshes.remove(own)
            del obj[ORIGINAL_MESH]


def _purge_unused():
    for material in [m for m in bpy.data.materials if m.get(NAME) and m.users == 0]:
        bpy.data.materials.remove(material)
    for image in [i for i in bpy.data.images if i.get(NAME) and i.users == 0]:
        bpy.data.images.remove(image)


def apply(baked, objects, bring_back):
    """Puts the bake onto the objects. Reads and matches everything first, so a failure changes
    nothing; then replaces what an earlier bake left."""
    matched = {}
    for obj in objects:
        values = _corner_values(obj, baked.primitives(obj.name))
        if any(v is None for v in values):
            missing = sum(v is None for v in values)
            raise RuntimeError("%s: %d of %d face corners have no baked value (was the mesh changed during the bake?)"
                               % (obj.name, missing, len(values)))
        matched[obj] = values
    images = []
    if bring_back in ('BOTH', 'IMAGES'):
        for path in baked.exr_pages:
            image = bpy.data.images.load(path, check_existing=False)
            image.colorspace_settings.name = 'Non-Color'
            image.pack()
            images.append(image)

    _detach(objects)
    _purge_unused()  # the earlier bake's materials and pages, before the new ones take their names
    for i, image in enumerate(images):
        image.name = "radbake lightmap %d" % i
    exposure = 1.0 / baked.png_intensity
    # Objects on one page whose slots hold one material share one lightmap material.
    lightmap_materials = {}
    for obj, values in matched.items():
        if obj.data.users > 1:
            # Linked duplicates share one mesh, but each is lit differently: this one gets a copy.
            obj[ORIGINAL_MESH] = obj.data.name
            obj.data = obj.data.copy()
        mesh = obj.data
        uv_layer = mesh.uv_layers.new(name=UV_MAP)
        uv_layer.data.foreach_set("uv", [c for v in values for c in (float(v[0][0]), 1.0 - float(v[0][1]))])
        if bring_back in ('BOTH', 'COLORS'):
            colors = compat.new_color_attribute(mesh, COLORS)
            colors.data.foreach_set("color", [c for v in values for c in (*map(float, v[1][:3]), 1.0)])
        if images:
            # The page each material slot's faces landed on.
            page_of_slot = {}
            for poly in mesh.polygons:
                page_of_slot.setdefault(poly.material_index, values[poly.loop_indices[0]][2])
            if not obj.material_slots:
                obj.data.materials.append(None)
                obj[ADDED_SLOT] = True
            obj[ORIGINAL_MATERIALS] = [slot.material.name if slot.material else "" for slot in obj.material_slots]
            for index, slot in enumerate(obj.material_slots):
                if index in page_of_slot:
                    page = page_of_slot[index]
                    key = (slot.material.name if slot.material else "", page)
                    if key not in lightmap_materials:
                        lightmap_materials[key] = _lightmap_material(slot.material, images[page], page, exposure)
                    slot.material = lightmap_materials[key]
    # Tagged only once in use, so that a later purge takes them only when a new bake replaced them.
    for image in images:
        image[NAME] = True
