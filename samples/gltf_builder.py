"""A small glTF 2.0 writer for the samples and the test fixtures (standard library only).

Scenes are built from flat-shaded polygons; every polygon gets its own vertices and a face
normal, as a modelling tool would export hard-edged geometry.
"""
import base64
import json
import math
import struct
import zlib


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def normalize(a):
    n = math.sqrt(sum(x * x for x in a))
    return [x / n for x in a]


def polygon_normal(poly):
    n = [0.0, 0.0, 0.0]
    for i in range(1, len(poly) - 1):
        c = cross(sub(poly[i], poly[0]), sub(poly[i + 1], poly[0]))
        n = [n[k] + c[k] for k in range(3)]
    return normalize(n)


def facing(poly, toward):
    """The polygon wound so its normal points toward the point `toward`."""
    centre = [sum(p[k] for p in poly) / len(poly) for k in range(3)]
    n = polygon_normal(poly)
    d = sub(toward, centre)
    return poly if sum(n[k] * d[k] for k in range(3)) > 0 else list(reversed(poly))


def facing_away(poly, point):
    centre = [sum(p[k] for p in poly) / len(poly) for k in range(3)]
    mirrored = [2 * centre[k] - point[k] for k in range(3)]
    return facing(poly, mirrored)


def box_faces(centre, size, rotation_y=0.0):
    """The six outward-facing quads of a box, turned about +Y by rotation_y radians."""
    c, s = math.cos(rotation_y), math.sin(rotation_y)
    hx, hy, hz = size[0] / 2, size[1] / 2, size[2] / 2

    def at(x, y, z):
        return [centre[0] + c * x + s * z, centre[1] + y, centre[2] - s * x + c * z]

    corners = {(i, j, k): at(i * hx, j * hy, k * hz) for i in (-1, 1) for j in (-1, 1) for k in (-1, 1)}
    faces = {
        "+x": [corners[(1, -1, -1)], corners[(1, 1, -1)], corners[(1, 1, 1)], corners[(1, -1, 1)]],
        "-x": [corners[(-1, -1, -1)], corners[(-1, -1, 1)], corners[(-1, 1, 1)], corners[(-1, 1, -1)]],
        "+y": [corners[(-1, 1, -1)], corners[(-1, 1, 1)], corners[(1, 1, 1)], corners[(1, 1, -1)]],
        "-y": [corners[(-1, -1, -1)], corners[(1, -1, -1)], corners[(1, -1, 1)], corners[(-1, -1, 1)]],
        "+z": [corners[(-1, -1, 1)], corners[(1, -1, 1)], corners[(1, 1, 1)], corners[(-1, 1, 1)]],
        "-z": [corners[(-1, -1, -1)], corners[(-1, 1, -1)], corners[(1, 1, -1)], corners[(1, -1, -1)]],
    }
    return {k: facing_away(v, centre) for k, v in faces.items()}


def png_bytes(width, height, pixel):
    """An RGB 8-bit PNG; pixel(x, y) returns (r, g, b) in 0..255."""
    raw = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


class Gltf:
    def __init__(self, generator="radbake samples"):
        self.doc = {"asset": {"version": "2.0", "generator": generator}, "scene": 0,
                    "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "materials": [],
                    "accessors": [], "bufferViews": [], "buffers": []}
        self.data = bytearray()
        self.extensions = set()

    def _view(self, blob, target):
        while len(self.data) % 4:
            self.data.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.data), "byteLength": len(blob),
                                        "target": target})
        self.data.extend(blob)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, values, kind, component=5126, target=34962, bounds=False):
        width = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[kind]
        fmt = {5126: "f", 5125: "I", 5123: "H", 5121: "B"}[component]
        flat = [x for v in values for x in (v if isinstance(v, (list, tuple)) else [v])]
        view = self._view(struct.pack("<%d%s" % (len(flat), fmt), *flat), target)
        acc = {"bufferView": view, "componentType": component, "count": len(flat) // width, "type": kind}
        if bounds:
            acc["min"] = [min(flat[i::width]) for i in range(width)]
            acc["max"] = [max(flat[i::width]) for i in range(width)]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def material(self, name, base_color=(0.8, 0.8, 0.8), emissive=None, strength=None, double_sided=False,
                 metallic=0.0, base_texture=None, emissive_texture=None, transmission=None, extras=None):
        m = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(base_color) + [1.0],
                                                   "metallicFactor": metallic, "roughnessFactor": 1.0}}
        if base_texture is not None:
            m["pbrMetallicRoughness"]["baseColorTexture"] = {"index": base_texture}
        if emissive is not None:
            m["emissiveFactor"] = list(emissive)
        if emissive_texture is not None:
            m["emissiveTexture"] = {"index": emissive_texture}
        if strength is not None:
            m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": strength}}
            self.extensions.add("KHR_materials_emissive_strength")
        if transmission is not None:
            m.setdefault("extensions", {})["KHR_materials_transmission"] = {"transmissionFactor": transmission}
            self.extensions.add("KHR_materials_transmission")
        if extras is not None:
            m["extras"] = extras
        if double_sided:
            m["doubleSided"] = True
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def texture_png(self, png_bytes, name):
        """An embedded PNG texture (data URI), returning the texture index."""
        self.doc.setdefault("images", []).append(
            {"name": name, "uri": "data:image/png;base64," + base64.b64encode(png_bytes).decode()})
        self.doc.setdefault("textures", []).append({"source": len(self.doc["images"]) - 1})
        return len(self.doc["textures"]) - 1

    def mesh(self, name, polygons, material, uvs=None, lightmap_uvs=None):
        """A mesh of flat polygons (each a list of 3+ points, fanned); uvs (TEXCOORD_0) and
        lightmap_uvs (TEXCOORD_1), if given, per polygon."""
        positions, normals, texcoords, lightmap, indices = [], [], [], [], []
        for p, poly in enumerate(polygons):
            n = polygon_normal(poly)
            base = len(positions)
            positions.extend(poly)
            normals.extend([n] * len(poly))
            if uvs is not None:
                texcoords.extend(uvs[p])
            if lightmap_uvs is not None:
                lightmap.extend(lightmap_uvs[p])
            for i in range(1, len(poly) - 1):
                indices.extend([base, base + i, base + i + 1])
        attributes = {"POSITION": self.accessor(positions, "VEC3", bounds=True),
                      "NORMAL": self.accessor(normals, "VEC3")}
        if uvs is not None:
            attributes["TEXCOORD_0"] = self.accessor(texcoords, "VEC2")
        if lightmap_uvs is not None:
            attributes["TEXCOORD_1"] = self.accessor(lightmap, "VEC2")
            attributes.setdefault("TEXCOORD_0", attributes["TEXCOORD_1"])
        index_type = 5123 if len(positions) < 65536 else 5125
        primitive = {"attributes": attributes, "indices": self.accessor(indices, "SCALAR", index_type, 34963),
                     "material": material}
        self.doc["meshes"].append({"name": name, "primitives": [primitive]})
        return len(self.doc["meshes"]) - 1

    def primitive_mesh(self, name, positions, material, indices=None, index_type=5123, mode=None, extra=None):
        """A one-primitive mesh from raw positions and optional indices of a given component type."""
        attributes = {"POSITION": self.accessor(positions, "VEC3", bounds=True)}
        primitive = {"attributes": attributes, "material": material}
        if indices is not None:
            primitive["indices"] = self.accessor(indices, "SCALAR", index_type, 34963)
        if mode is not None:
            primitive["mode"] = mode
        prims = [primitive] + (extra or [])
        self.doc["meshes"].append({"name": name, "primitives": prims})
        return len(self.doc["meshes"]) - 1

    def node(self, name, mesh=None, translation=None, rotation=None, scale=None, extensions=None, camera=None,
             matrix=None, children=None, root=True):
        n = {"name": name}
        if matrix is not None:
            n["matrix"] = list(matrix)
        if children:
            n["children"] = list(children)
        if mesh is not None:
            n["mesh"] = mesh
        if camera is not None:
            n["camera"] = camera
        if translation is not None:
            n["translation"] = list(translation)
        if rotation is not None:
            n["rotation"] = list(rotation)
        if scale is not None:
            n["scale"] = list(scale)
        if extensions:
            n["extensions"] = extensions
        self.doc["nodes"].append(n)
        if root:
            self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)
        return len(self.doc["nodes"]) - 1

    def light(self, name, kind, intensity, color=(1, 1, 1), range_m=None, inner=None, outer=None):
        lights = self.doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})["lights"]
        light = {"name": name, "type": kind, "intensity": intensity, "color": list(color)}
        if range_m is not None:
            light["range"] = range_m
        if kind == "spot":
            light["spot"] = {"innerConeAngle": inner or 0.0, "outerConeAngle": outer or math.pi / 4}
        lights.append(light)
        self.extensions.add("KHR_lights_punctual")
        return {"KHR_lights_punctual": {"light": len(lights) - 1}}

    def camera(self, name, yfov, aspect=1.0, znear=0.01):
        self.doc.setdefault("cameras", []).append(
            {"name": name, "type": "perspective",
             "perspective": {"yfov": yfov, "aspectRatio": aspect, "znear": znear}})
        return len(self.doc["cameras"]) - 1

    def save(self, path, bin_name=None):
        """Writes path (.gltf). With bin_name the buffer goes to that file beside it, else inline."""
        doc = dict(self.doc)
        if self.extensions:
            doc["extensionsUsed"] = sorted(self.extensions)
        if not self.data:
            doc.pop("buffers")
            for key in ("accessors", "bufferViews", "meshes", "materials"):
                if not doc[key]:
                    doc.pop(key)
        elif bin_name:
            doc["buffers"] = [{"uri": bin_name, "byteLength": len(self.data)}]
            with open(path.rsplit("/", 1)[0] + "/" + bin_name if "/" in path else bin_name, "wb") as f:
                f.write(self.data)
        else:
            doc["buffers"] = [{"byteLength": len(self.data),
                               "uri": "data:application/octet-stream;base64," + base64.b64encode(self.data).decode()}]
        with open(path, "w") as f:
            json.dump(doc, f, indent=1)
            f.write("\n")

    def save_glb(self, path):
        doc = dict(self.doc)
        if self.extensions:
            doc["extensionsUsed"] = sorted(self.extensions)
        data = bytes(self.data) + b"\0" * (-len(self.data) % 4)
        doc["buffers"] = [{"byteLength": len(self.data)}]
        text = json.dumps(doc).encode()
        text += b" " * (-len(text) % 4)
        with open(path, "wb") as f:
            f.write(struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(data)))
            f.write(struct.pack("<I4s", len(text), b"JSON") + text)
            f.write(struct.pack("<I4s", len(data), b"BIN\0") + data)
