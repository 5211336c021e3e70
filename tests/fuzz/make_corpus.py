#!/usr/bin/env python3
"""Regenerates the hostile-input corpus: python3 tests/fuzz/make_corpus.py

Seeded mutations of our own fixtures and samples (tests/fixtures, samples), written to
tests/fuzz/corpus/. The same script always writes the same files: every random choice comes from a
generator seeded with the source's name and the mutant's number. Each file is named
SOURCE.MUTATION.N.gltf (or .glb), the mutation saying what was done, e.g.
cornell_box.type_swap.3.gltf, and its asset.extras.mutation (where the mutant still has an asset)
says where.

Two kinds of mutants:
- targeted: a catalogue of hostile edits (out-of-range indices, bad URIs, strides, nested nodes,
  truncated buffers, extensions...) applied where the source has what they edit;
- random: type swaps, deletions, numbers pushed to extremes and duplications at random JSON paths.

Files the fuzzer found live in tests/fuzz/findings/ and are never touched here.

The targeted kinds (vertex_values, material_range, morph_targets, image_bytes, skin_use,
texture_webp) hold what radbake accepts but used to write invalid glTF from: bad vertex data, extension
values out of range, morph targets, images that are no PNG or JPEG, skins on unskinned meshes and
EXT_texture_webp naming other images. Their new data goes in data URIs, and their image files
(texture.tga, texture.webp) beside the mutants.
"""
import base64
import copy
import json
import os
import random
import struct
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(HERE, "corpus")
# The other fuzz targets' seeds, beside these and left alone (./dev fuzz: checkpoint_fuzzer, weather_fuzzer).
OTHER_TARGETS_SEEDS = ("checkpoint.", "weather.")
SEED = 11  # any fixed seed: the corpus is the same on every machine

SOURCES = [
    "samples/cornell_box/cornell_box.gltf",
    "samples/ferren/ferren.gltf",
    "tests/fixtures/external_buffer.gltf",
    "tests/fixtures/instanced_mesh.gltf",
    "tests/fixtures/lit_room.glb",
    "tests/fixtures/own_lightmap_uvs.gltf",
    "tests/fixtures/primitive_kinds.gltf",
    "tests/fixtures/red_textured_floor.gltf",
    "tests/fixtures/uv/non_manifold_edges.gltf",
]
RANDOM_PER_SOURCE = 8

# Values of every JSON type, and numbers at the edges of what parsers and float arithmetic take.
SWAPS = ["text", "", 1.5, -1, 0, 2147483648, {}, [], [1, 2], {"a": 1}, True, False, None]
EXTREMES = [1e308, -1e308, 1e39, -1e39, 1e-320, -0.0, 3.5, -1, 0, 4294967296, 9007199254740993,
            18446744073709551616, -2147483649, 1e20]
INDEX_NAMES = {"mesh", "material", "indices", "bufferView", "buffer", "source", "sampler", "index",
               "node", "skin", "camera", "scene", "light", "input", "output", "inverseBindMatrices"}
BAD_URIS = ["../../../../etc/passwd", "/etc/passwd", "file:///etc/passwd", "missing.bin", "",
            "http://example.com/buffer.bin", "data:application/octet-stream;base64,!!!not base64!!!",
            "data:application/octet-stream;base64,AAAA", "data:;base64,", "%2e%2e/%2e%2e/etc/passwd",
            "a" * 5000 + ".bin", "truncated.bin", "nul\u0000byte.bin", ".", "corpus"]


# --- reading and writing sources -----------------------------------------------------------------

def read_source(relative):
    """The source's JSON document, and the .glb's BIN chunk (None for .gltf)."""
    data = open(os.path.join(ROOT, relative), "rb").read()
    if relative.endswith(".glb"):
        length, _ = struct.unpack_from("<II", data, 12)
        doc = json.loads(data[20:20 + length])
        bin_at = 20 + ((length + 3) & ~3)
        bin_length, _ = struct.unpack_from("<II", data, bin_at)
        return doc, data[bin_at + 8:bin_at + 8 + bin_length]
    return json.loads(data), None


def glb_bytes(doc_text, bin_chunk):
    doc_bytes = doc_text.encode()
    doc_bytes += b" " * (-len(doc_bytes) % 4)
    chunks = struct.pack("<II", len(doc_bytes), 0x4E4F534A) + doc_bytes
    if bin_chunk is not None:
        padded = bin_chunk + b"\0" * (-len(bin_chunk) % 4)
        chunks += struct.pack("<II", len(padded), 0x004E4942) + padded
    return struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks


def dump(doc):
    return json.dumps(doc, separators=(",", ":"), allow_nan=True)


# --- JSON paths --------------------------------------------------------------------------------

def paths(value, prefix=()):
    """Every (path, value) under `value`, data URIs' insides excluded."""
    out = []
    items = value.items() if isinstance(value, dict) else enumerate(value) if isinstance(value, list) else []
    for key, child in items:
        out.append((prefix + (key,), child))
        out.extend(paths(child, prefix + (key,)))
    return out


def get(doc, path):
    for key in path:
        doc = doc[key]
    return doc


def put(doc, path, value):
    get(doc, path[:-1])[path[-1]] = value


def pointer(path):
    return "/" + "/".join(str(k) for k in path)


# --- targeted mutations: each returns a description, or None when the source lacks what it edits --

def first(doc, collection):
    return doc.get(collection) or []


def mutate_index(rng, doc):
    found = [(p, v) for p, v in paths(doc) if isinstance(v, int) and not isinstance(v, bool) and
             (p[-1] in INDEX_NAMES or (len(p) > 1 and p[-2] in ("children", "nodes", "attributes", "joints")))]
    if not found:
        return None
    path, value = rng.choice(found)
    bad = rng.choice([-1, -2147483648, 2147483647, 4294967295, value + 1000, 65536, 1.5])
    put(doc, path, bad)
    return f"{pointer(path)}: {value} -> {bad}"


def truncate_buffer(rng, doc, bin_chunk):
    buffers = first(doc, "buffers")
    if not buffers:
        return None, bin_chunk
    b = rng.randrange(len(buffers))
    buffer = buffers[b]
    uri = buffer.get("uri", "")
    how = rng.choice(["shorter", "longer", "zero", "uri"])
    if how == "uri" or (how == "shorter" and not uri.startswith("data:") and bin_chunk is None):
        buffer["uri"] = "truncated.bin"
        return f"/buffers/{b}/uri -> truncated.bin", bin_chunk
    if how == "longer":
        buffer["byteLength"] = buffer.get("byteLength", 0) * 2 + 4
        return f"/buffers/{b}/byteLength doubled", bin_chunk
    if how == "zero":
        buffer["byteLength"] = 0
        return f"/buffers/{b}/byteLength -> 0", bin_chunk
    if uri.startswith("data:"):
        head, data = uri.split(",", 1)
        raw = base64.b64decode(data)
        buffer["uri"] = head + "," + base64.b64encode(raw[:len(raw) // 2]).decode()
        return f"/buffers/{b}/uri: data cut to half", bin_chunk
    return f"BIN chunk cut to half", bin_chunk[:len(bin_chunk) // 2]


def bad_uri(rng, doc):
    owners = [(c, i) for c in ("buffers", "images") for i, o in enumerate(first(doc, c)) if "uri" in o]
    if not owners:
        return None
    collection, i = rng.choice(owners)
    uri = rng.choice(BAD_URIS)
    doc[collection][i]["uri"] = uri
    return f"/{collection}/{i}/uri -> {uri[:40]!r}"


def bad_accessor(rng, doc):
    accessors = first(doc, "accessors")
    if not accessors:
        return None
    a = rng.randrange(len(accessors))
    acc = accessors[a]
    key, value = rng.choice([
        ("componentType", 5124), ("componentType", 0), ("componentType", 5130), ("type", "VEC5"), ("type", "MAT4"),
        ("type", "SCALAR"), ("count", 0), ("count", 2 ** 31), ("count", 2 ** 53), ("count", acc.get("count", 1) + 1),
        ("byteOffset", 1), ("byteOffset", 2 ** 40), ("byteOffset", 3), ("normalized", True), ("bufferView", None),
        ("min", [0]), ("max", ["x", 1, 2]), ("min", [1e39, 1e39, 1e39]),
        ("sparse", {"count": 2, "indices": {"bufferView": 0, "componentType": 5123},
                    "values": {"bufferView": 0}}),
        ("sparse", {"count": 2 ** 30, "indices": {"bufferView": 0, "componentType": 5125},
                    "values": {"bufferView": 0, "byteOffset": 2 ** 31}}),
        ("sparse", {"count": 1})])
    if value is None:
        acc.pop(key, None)
    else:
        acc[key] = value
    return f"/accessors/{a}/{key} -> {json.dumps(value)[:40]}"


def bad_buffer_view(rng, doc):
    views = first(doc, "bufferViews")
    if not views:
        return None
    v = rng.randrange(len(views))
    key, value = rng.choice([
        ("byteStride", 0), ("byteStride", 3), ("byteStride", 1), ("byteStride", 256), ("byteStride", 2 ** 31),
        ("byteStride", 4), ("byteLength", 0), ("byteLength", 2 ** 32), ("byteLength", 1), ("byteOffset", 2 ** 32),
        ("byteOffset", 1), ("target", 1234), ("target", 34963), ("buffer", 7)])
    views[v][key] = value
    return f"/bufferViews/{v}/{key} -> {value}"


def nested_nodes(rng, doc):
    nodes = doc.setdefault("nodes", [])
    if not nodes:
        return None
    n = len(nodes)
    how = rng.choice(["self", "cycle", "two_parents", "deep", "bomb", "scene_twice", "child_and_root"])
    mesh = next((i for i, node in enumerate(nodes) if "mesh" in node), 0)
    if how == "self":
        nodes[0].setdefault("children", []).append(0)
    elif how == "cycle":
        nodes.append({"children": [n + 1]})
        nodes.append({"children": [n]})
        doc["scenes"][0]["nodes"].append(n)
    elif how == "two_parents":
        nodes.append({"children": [mesh]})
        nodes.append({"children": [mesh]})
        doc["scenes"][0]["nodes"] += [n, n + 1]
    elif how == "deep":
        depth = 3000
        for k in range(depth):
            nodes.append({"children": [n + k + 1]} if k + 1 < depth else {"mesh": nodes[mesh].get("mesh", 0)})
        doc["scenes"][0]["nodes"].append(n)
    elif how == "bomb":  # a DAG whose every level doubles the instances: 2^40 copies of a mesh
        for k in range(40):
            nodes.append({"children": [n + k + 1, n + k + 1]})
        nodes.append({"mesh": nodes[mesh].get("mesh", 0)})
        doc["scenes"][0]["nodes"].append(n)
    elif how == "scene_twice":
        doc["scenes"][0]["nodes"].append(doc["scenes"][0]["nodes"][0])
    else:
        nodes.append({"children": [doc["scenes"][0]["nodes"][0]]})
        doc["scenes"][0]["nodes"].append(n)
    return f"nodes: {how}"


def bad_extension(rng, doc):
    how = rng.choice(["required_unknown", "used_not_array", "value_not_object", "undeclared", "light_type",
                      "light_negative", "spot_reversed", "light_missing", "transform_junk", "strength_string",
                      "extensions_array", "unknown_kept", "khr_on_wrong_object", "used_duplicate",
                      "required_not_used", "clearcoat_junk"])
    materials = first(doc, "materials")
    lights = doc.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    if how == "required_unknown":
        doc["extensionsRequired"] = ["EXT_made_up"]
        doc.setdefault("extensionsUsed", []).append("EXT_made_up")
    elif how == "used_not_array":
        doc["extensionsUsed"] = "KHR_lights_punctual"
    elif how == "value_not_object" and materials:
        materials[0].setdefault("extensions", {})["EXT_vendor_thing"] = 5
        doc.setdefault("extensionsUsed", []).append("EXT_vendor_thing")
    elif how == "undeclared" and materials:
        materials[0].setdefault("extensions", {})["EXT_vendor_thing"] = {"level": 3}
    elif how == "light_type" and lights:
        lights[0]["type"] = "laser"
    elif how == "light_negative" and lights:
        lights[0]["intensity"] = -5
    elif how == "spot_reversed" and lights:
        lights[0].update({"type": "spot", "spot": {"innerConeAngle": 1.2, "outerConeAngle": 0.3}})
    elif how == "light_missing":
        doc.get("extensions", {}).pop("KHR_lights_punctual", None)
    elif how == "transform_junk" and materials:
        pbr = materials[0].setdefault("pbrMetallicRoughness", {})
        pbr["baseColorTexture"] = {"index": 0, "extensions": {"KHR_texture_transform": {"offset": "far", "scale": [1]}}}
        doc.setdefault("extensionsUsed", []).append("KHR_texture_transform")
    elif how == "strength_string" and materials:
        materials[-1].setdefault("extensions", {})["KHR_materials_emissive_strength"] = {"emissiveStrength": "bright"}
    elif how == "extensions_array" and materials:
        materials[0]["extensions"] = ["KHR_materials_emissive_strength"]
    elif how == "unknown_kept" and materials:
        materials[0].setdefault("extensions", {})["EXT_vendor_thing"] = {"level": 3, "deep": {"a": [1, {"b": None}]}}
        doc.setdefault("extensionsUsed", []).append("EXT_vendor_thing")
    elif how == "khr_on_wrong_object" and materials:
        materials[0].setdefault("extensions", {})["KHR_lights_punctual"] = {"light": 0}
    elif how == "used_duplicate":
        doc["extensionsUsed"] = doc.get("extensionsUsed", []) * 2 + ["KHR_materials_emissive_strength"]
    elif how == "required_not_used":
        doc["extensionsRequired"] = ["KHR_texture_transform"]
    elif how == "clearcoat_junk" and materials:
        materials[0].setdefault("extensions", {})["KHR_materials_clearcoat"] = {"clearcoatFactor": "max",
                                                                             "clearcoatTexture": {}}
        doc.setdefault("extensionsUsed", []).append("KHR_materials_clearcoat")
    else:
        return None
    return f"extensions: {how}"


def bad_material(rng, doc):
    materials = first(doc, "materials")
    if not materials:
        return None
    m = rng.randrange(len(materials))
    mat = materials[m]
    key, value = rng.choice([
        ("normalTexture", {"scale": 1}), ("occlusionTexture", {"index": 0, "strength": 2}), ("normalTexture", 3),
        ("emissiveTexture", {"index": 0, "texCoord": 7}), ("emissiveTexture", {"texCoord": 1}),
        ("alphaMode", "SOMETIMES"), ("alphaMode", "MASK"), ("alphaCutoff", -1), ("alphaCutoff", "half"),
        ("doubleSided", "yes"), ("emissiveFactor", [1e30, 1e30, 1e30]), ("emissiveFactor", [1, 1]),
        ("pbrMetallicRoughness", {"baseColorFactor": [1, 1, 1]}), ("pbrMetallicRoughness", "red"),
        ("pbrMetallicRoughness", {"metallicFactor": 2, "roughnessFactor": -1}),
        ("pbrMetallicRoughness", {"baseColorTexture": {"index": 0}}), ("name", 12), ("extras", [1, 2, 3])])
    mat[key] = value
    return f"/materials/{m}/{key} -> {json.dumps(value)[:40]}"


def bad_mesh(rng, doc):
    meshes = first(doc, "meshes")
    if not meshes:
        return None
    m = rng.randrange(len(meshes))
    prim = meshes[m]["primitives"][0]
    attributes = prim.setdefault("attributes", {})
    position = attributes.get("POSITION", 0)
    key, value = rng.choice([
        ("mode", 7), ("mode", 0), ("mode", 1), ("mode", -1), ("attributes", {}), ("attributes", []),
        ("POSITION", None), ("TEXCOORD_1", position), ("TEXCOORD_5", position), ("NORMAL", position),
        ("TANGENT", position), ("COLOR_0", position), ("JOINTS_0", position), ("_CUSTOM", position),
        ("targets", [{"POSITION": position}]), ("targets", [{"POSITION": "x"}]), ("targets", {}),
        ("primitives", []), ("indices", position), ("weights", [0.5])])
    if key in ("mode", "attributes", "targets", "indices"):
        prim[key] = value
    elif key in ("primitives", "weights"):
        meshes[m][key] = value
    elif value is None:
        attributes.pop(key, None)
    else:
        attributes[key] = value
    return f"/meshes/{m}: {key} -> {json.dumps(value)[:40]}"


def bad_texture(rng, doc):
    if not first(doc, "textures"):
        return None
    how = rng.choice(["source_missing", "sampler_junk", "image_both", "image_neither", "image_garbage",
                      "mime", "wrap"])
    tex, image = doc["textures"][0], doc["images"][0] if first(doc, "images") else {}
    if how == "source_missing":
        tex["source"] = 9
    elif how == "sampler_junk":
        doc.setdefault("samplers", []).append({"magFilter": 1, "minFilter": "linear", "wrapS": 0})
        tex["sampler"] = len(doc["samplers"]) - 1
    elif how == "image_both":
        image["bufferView"] = 0
    elif how == "image_neither":
        image.pop("uri", None)
    elif how == "image_garbage":
        image["uri"] = "data:image/png;base64," + base64.b64encode(b"\x89PNG\r\n\x1a\n" + bytes(64)).decode()
    elif how == "mime":
        image["mimeType"] = "image/gif"
    else:
        doc.setdefault("samplers", []).append({"wrapS": 12345, "wrapT": -1})
        tex["sampler"] = len(doc["samplers"]) - 1
    return f"textures: {how}"


def bad_structure(rng, doc):
    how = rng.choice(["asset_missing", "version_3", "version_number", "collection_object", "empty_arrays",
                      "scene_missing", "cameras", "skin", "animation", "long_name"])
    if how == "asset_missing":
        doc.pop("asset", None)
    elif how == "version_3":
        doc["asset"]["version"] = "3.0"
    elif how == "version_number":
        doc["asset"]["version"] = 2.0
    elif how == "collection_object":
        key = rng.choice(["nodes", "meshes", "accessors", "materials", "scenes", "buffers", "bufferViews"])
        doc[key] = {"0": doc.get(key, [{}])[0]}
        how += " " + key
    elif how == "empty_arrays":
        for key in ("cameras", "skins", "animations", "samplers"):
            doc[key] = []
    elif how == "scene_missing":
        doc["scene"] = 3
    elif how == "cameras":
        doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": -1, "znear": "near"}},
                          {"type": "fisheye"}, {"type": "orthographic"}]
        doc["nodes"][0]["camera"] = rng.choice([0, 1, 2, 5])
    elif how == "skin":
        doc["skins"] = [{"joints": [999]}, {"joints": "all"}]
        doc["nodes"][0]["skin"] = rng.choice([0, 1, 4])
    elif how == "animation":
        doc["animations"] = [{"channels": [{"sampler": 3, "target": {"node": 0, "path": "colour"}}],
                              "samplers": [{"input": 999, "output": 0, "interpolation": "CUBIC"}]},
                             {"channels": "none"}]
    else:
        doc["nodes"][0]["name"] = "n" * 20000
    return f"structure: {how}"


# --- what radbake accepts and once wrote invalid glTF from ---------------------------------------

def png_bytes(width, height, rgb):
    """A PNG of 8-bit RGB pixels, rows top to bottom."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    rows = b"".join(b"\0" + bytes(rgb[y * width * 3:(y + 1) * width * 3]) for y in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def tga_bytes(width, height, rgb):
    """An uncompressed true-colour TGA (what assimp's Collada duck names)."""
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, width, height, 24, 0)
    return header + bytes(c for p in range(width * height) for c in reversed(rgb[3 * p:3 * p + 3]))


PNG_2X2 = png_bytes(2, 2, [200, 40, 40] * 4)
TGA_2X2 = tga_bytes(2, 2, [200, 40, 40] * 4)
# Image files the image kinds name by URI, written beside the mutants: a TGA, PNG bytes named .webp,
# and PNGs with chunks the validator flags (png_chunks, below).
IMAGE_FILES = {"texture.tga": TGA_2X2, "texture.webp": PNG_2X2}


def data_uri(mime, data):
    return f"data:{mime};base64," + base64.b64encode(data).decode()


def add_accessor(doc, values, count, kind, component_type=5126):
    """An accessor over `values` (floats, or unsigned bytes) in a buffer of its own; returns its index.
    No min/max: NaN has no JSON spelling, and radbake measures the bounds it writes."""
    data = struct.pack(f"<{len(values)}{'f' if component_type == 5126 else 'B'}", *values)
    data += b"\0" * (-len(data) % 4)
    doc.setdefault("buffers", []).append({"byteLength": len(data), "uri": data_uri("application/octet-stream", data)})
    doc.setdefault("bufferViews", []).append({"buffer": len(doc["buffers"]) - 1, "byteLength": len(data)})
    doc.setdefault("accessors", []).append({"bufferView": len(doc["bufferViews"]) - 1, "componentType": component_type,
                                            "count": count, "type": kind})
    return len(doc["accessors"]) - 1


def vertex_count(doc, prim):
    return doc["accessors"][prim["attributes"]["POSITION"]]["count"]


def triangle_primitives(doc):
    """(mesh, primitive) of every primitive drawn as triangles."""
    return [(m, k) for m, mesh in enumerate(first(doc, "meshes")) for k, prim in enumerate(mesh.get("primitives", []))
            if prim.get("mode", 4) >= 4 and "POSITION" in prim.get("attributes", {})]


def declare(doc, extension):
    if extension not in doc.setdefault("extensionsUsed", []):
        doc["extensionsUsed"].append(extension)


def vertex_values(rng, doc):
    """NaN, infinite, zero-length or huge normals and tangents, tangents' w not +-1, NaN texcoords."""
    found = triangle_primitives(doc)
    if not found:
        return None
    m, k = rng.choice(found)
    prim = doc["meshes"][m]["primitives"][k]
    n = vertex_count(doc, prim)
    attribute = rng.choice(["NORMAL", "TANGENT", "TEXCOORD_0"] if "NORMAL" in prim["attributes"] else
                           ["NORMAL", "TEXCOORD_0"])
    bad = rng.choice({"NORMAL": ["nan", "inf", "zero", "huge", "short"],
                      "TANGENT": ["nan", "zero", "huge", "sign", "nan_sign"],
                      "TEXCOORD_0": ["nan", "inf", "-inf"]}[attribute])
    good = {"NORMAL": [0.0, 1.0, 0.0], "TANGENT": [1.0, 0.0, 0.0, 1.0], "TEXCOORD_0": [0.5, 0.5]}[attribute]
    wrong = {"nan": float("nan"), "inf": float("inf"), "-inf": float("-inf"), "zero": 0.0, "huge": 1e30,
             "short": 0.1, "sign": 0.5, "nan_sign": float("nan")}[bad]
    values = []
    for v in range(n):
        element = list(good)
        if v % 3 == 0:  # a third of the vertices
            if bad in ("sign", "nan_sign"):
                element[3] = wrong
            elif bad in ("zero", "huge", "short"):
                element = [wrong * e if bad != "zero" else 0.0 for e in element[:3]] + element[3:]
            else:
                element[v % len(element)] = wrong
        values += element
    prim["attributes"][attribute] = add_accessor(doc, values, n, {2: "VEC2", 3: "VEC3", 4: "VEC4"}[len(good)])
    return f"/meshes/{m}/primitives/{k}/attributes/{attribute}: {bad} at every third vertex"


def material_range(rng, doc):
    """KHR_materials_ior and KHR_materials_transmission values out of range or of the wrong type."""
    materials = first(doc, "materials")
    if not materials:
        return None
    m = rng.randrange(len(materials))
    extension, key, value = rng.choice([
        ("KHR_materials_ior", "ior", -1), ("KHR_materials_ior", "ior", 0.5), ("KHR_materials_ior", "ior", "1.5"),
        ("KHR_materials_ior", "ior", None), ("KHR_materials_transmission", "transmissionFactor", 2),
        ("KHR_materials_transmission", "transmissionFactor", -0.5), ("KHR_materials_specular", "specularFactor", 3),
        ("KHR_materials_clearcoat", "clearcoatRoughnessFactor", 1.5)])
    materials[m].setdefault("extensions", {})[extension] = {key: value}
    declare(doc, extension)
    return f"/materials/{m}/extensions/{extension}/{key} -> {json.dumps(value)}"


def morph_targets(rng, doc):
    """A NaN or infinite displacement, or 5,000 empty morph targets, on every primitive of a mesh."""
    found = triangle_primitives(doc)
    if not found:
        return None
    m = rng.choice(found)[0]
    mesh = doc["meshes"][m]
    how = rng.choice(["nan_displacement", "inf_displacement", "empty_targets"])
    for prim in mesh["primitives"]:
        if how == "empty_targets":
            prim["targets"] = [{} for _ in range(5000)]
            continue
        n = vertex_count(doc, prim)
        wrong = float("nan") if how == "nan_displacement" else float("inf")
        values = [wrong if v == 0 and c == 1 else 0.01 * c for v in range(n) for c in range(3)]
        prim["targets"] = [{"POSITION": add_accessor(doc, values, n, "VEC3")}]
    mesh["weights"] = [0.0] * len(mesh["primitives"][0]["targets"])
    return f"/meshes/{m}: {how}"


def textured_material(doc):
    """A material every primitive using it gives TEXCOORD_0, so a texture on it is read; or None."""
    users = {}
    for mesh in first(doc, "meshes"):
        for prim in mesh.get("primitives", []):
            if "material" in prim:
                users.setdefault(prim["material"], []).append("TEXCOORD_0" in prim.get("attributes", {}))
    ok = sorted(m for m, has in users.items() if all(has) and isinstance(m, int) and 0 <= m < len(first(doc, "materials")))
    return ok[0] if ok else None


def add_texture(doc, image, material):
    """`image` as a new image, its texture the material's base colour texture; returns the texture."""
    doc.setdefault("images", []).append(image)
    doc.setdefault("textures", []).append({"source": len(doc["images"]) - 1})
    doc["materials"][material].setdefault("pbrMetallicRoughness", {})["baseColorTexture"] = {
        "index": len(doc["textures"]) - 1}
    return len(doc["textures"]) - 1


def image_bytes(rng, doc):
    """Images that are no PNG or JPEG, or not the one their mimeType says."""
    material = textured_material(doc)
    if material is None:
        return None
    how = rng.choice(["garbage_png", "tga_file", "truncated_jpeg", "png_said_jpeg"])
    image = {"garbage_png": {"uri": data_uri("image/png", b"\x89PNG\r\n\x1a\n" + bytes(40))},
             "tga_file": {"uri": "texture.tga"},
             "truncated_jpeg": {"uri": data_uri("image/jpeg", b"\xff\xd8\xff\xe0\x00\x10JFIF")},
             "png_said_jpeg": {"uri": data_uri("image/jpeg", PNG_2X2), "mimeType": "image/jpeg"}}[how]
    add_texture(doc, image, material)
    return f"images: {how} on /materials/{material}"


def skin_use(rng, doc):
    """A skin on a node whose mesh has no joints, or joints on a mesh whose node has no skin."""
    nodes = first(doc, "nodes")
    with_mesh = [i for i, node in enumerate(nodes) if isinstance(node.get("mesh"), int)]
    if not with_mesh or not first(doc, "scenes"):
        return None
    n = rng.choice(with_mesh)
    how = rng.choice(["skin_without_joints", "joints_without_skin"])
    if how == "skin_without_joints":
        nodes.append({"name": "joint"})
        doc["scenes"][0].setdefault("nodes", []).append(len(nodes) - 1)
        doc.setdefault("skins", []).append({"joints": [len(nodes) - 1]})
        nodes[n]["skin"] = len(doc["skins"]) - 1
    else:
        for prim in doc["meshes"][nodes[n]["mesh"]]["primitives"]:
            count = vertex_count(doc, prim)
            prim["attributes"]["JOINTS_0"] = add_accessor(doc, [0] * 4 * count, count, "VEC4", 5121)
            prim["attributes"]["WEIGHTS_0"] = add_accessor(doc, [1.0, 0.0, 0.0, 0.0] * count, count, "VEC4")
    return f"/nodes/{n}: {how}"


def texture_webp(rng, doc):
    """EXT_texture_webp naming a PNG, or a file whose bytes are not WebP."""
    material = textured_material(doc)
    if material is None:
        return None
    how = rng.choice(["names_png", "names_png_as_only_source", "png_bytes_named_webp"])
    image = {"uri": "texture.webp"} if how == "png_bytes_named_webp" else {"uri": data_uri("image/png", PNG_2X2)}
    t = add_texture(doc, image, material)
    texture = doc["textures"][t]
    texture["extensions"] = {"EXT_texture_webp": {"source": texture["source"]}}
    if how != "names_png":
        del texture["source"]
    declare(doc, "EXT_texture_webp")
    return f"/textures/{t}: {how}"


def specular_glossiness(rng, doc):
    """KHR_materials_pbrSpecularGlossiness on a material: archived, and beside MOZ_lightmap the
    validator warns MULTIPLE_EXTENSIONS (as assimp's converted files carry it)."""
    materials = first(doc, "materials")
    if not materials:
        return None
    m = rng.randrange(len(materials))
    how = rng.choice(["beside_metallic_roughness", "alone", "required"])
    if not isinstance(materials[m], dict):
        return None
    spec = {"diffuseFactor": [round(rng.random(), 3) for _ in range(3)] + [1.0], "specularFactor": [0.5, 0.5, 0.5],
            "glossinessFactor": round(rng.random(), 3)}
    if how == "alone":
        materials[m].pop("pbrMetallicRoughness", None)
    materials[m].setdefault("extensions", {})["KHR_materials_pbrSpecularGlossiness"] = spec
    declare(doc, "KHR_materials_pbrSpecularGlossiness")
    if how == "required":
        doc.setdefault("extensionsRequired", []).append("KHR_materials_pbrSpecularGlossiness")
    return f"/materials/{m}: specular-glossiness {how}"


def png_with(chunks_after_header, before_data=()):
    """PNG_2X2 with chunks added after IHDR, and before IDAT."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    ihdr_end = 8 + 25
    idat = PNG_2X2.index(b"IDAT") - 4
    return (PNG_2X2[:ihdr_end] + b"".join(chunk(k, d) for k, d in chunks_after_header) + PNG_2X2[ihdr_end:idat] +
            b"".join(chunk(k, d) for k, d in before_data) + PNG_2X2[idat:])


ADOBE_RGB = struct.pack(">8I", 31270, 32900, 64000, 33000, 21000, 71000, 15000, 6000)
# PNGs with chunks the validator flags (IMAGE_FEATURES_UNSUPPORTED), by what they carry.
FLAGGED_PNGS = {"chrm": png_with([(b"cHRM", ADOBE_RGB)]),
                "gama": png_with([(b"gAMA", struct.pack(">I", 55556))]),
                "iccp": png_with([(b"iCCP", b"icc\0\0" + zlib.compress(b"profile"))]),
                "phys": png_with([(b"pHYs", struct.pack(">IIB", 2835, 5670, 1))]),
                "apng": png_with([(b"acTL", struct.pack(">II", 1, 0))],
                                 [(b"fcTL", struct.pack(">IIIIIHHBB", 0, 2, 2, 0, 0, 1, 10, 0, 0))])}


def png_chunks(rng, doc):
    """A PNG texture with what glTF viewers ignore and the validator flags as unsupported features:
    a colour space other than sRGB's, non-square pixels, animation."""
    material = textured_material(doc)
    if material is None:
        return None
    how = rng.choice(sorted(FLAGGED_PNGS))
    png = FLAGGED_PNGS[how]
    image = {"uri": data_uri("image/png", png)} if rng.random() < 0.5 else {"uri": f"texture_{how}.png"}
    add_texture(doc, image, material)
    return f"images: PNG with {how} on /materials/{material}"


TARGETED = {
    "index": mutate_index, "uri": bad_uri, "accessor": bad_accessor, "buffer_view": bad_buffer_view,
    "nodes": nested_nodes, "extension": bad_extension, "material": bad_material, "mesh": bad_mesh,
    "texture": bad_texture, "structure": bad_structure,
    "vertex_values": vertex_values, "material_range": material_range, "morph_targets": morph_targets,
    "image_bytes": image_bytes, "skin_use": skin_use, "texture_webp": texture_webp,
    "specular_glossiness": specular_glossiness, "png_chunks": png_chunks,
}
TARGETED_PER_SOURCE = 2  # of each kind, but for the targeted kinds, which have more variants each
PER_SOURCE = {"vertex_values": 4, "material_range": 3, "morph_targets": 3, "image_bytes": 3, "skin_use": 2,
              "texture_webp": 3, "specular_glossiness": 3, "png_chunks": 3}


# --- random mutations ----------------------------------------------------------------------------

def random_edit(rng, doc):
    found = [(p, v) for p, v in paths(doc) if not (isinstance(v, str) and v.startswith("data:"))]
    path, value = rng.choice(found)
    op = rng.choice(["type_swap", "type_swap", "delete", "extreme", "extreme", "duplicate"])
    if op == "extreme":
        numeric = [(p, v) for p, v in found if isinstance(v, (int, float)) and not isinstance(v, bool)]
        if numeric:
            path, value = rng.choice(numeric)
        new = rng.choice(EXTREMES)
        put(doc, path, new)
        return op, f"{pointer(path)}: {json.dumps(value)[:30]} -> {new}"
    if op == "delete":
        parent = get(doc, path[:-1])
        del parent[path[-1]]
        return op, f"{pointer(path)} deleted"
    if op == "duplicate":
        parent = get(doc, path[:-1])
        if isinstance(parent, list):
            parent.append(copy.deepcopy(value))
            return op, f"{pointer(path)} appended again"
        put(doc, path, [copy.deepcopy(value), copy.deepcopy(value)])
        return op, f"{pointer(path)} doubled into an array"
    new = rng.choice([s for s in SWAPS if type(s) is not type(value)])
    put(doc, path, copy.deepcopy(new))
    return op, f"{pointer(path)}: {type(value).__name__} -> {json.dumps(new)}"


# --- byte-level mutations (what JSON cannot say) ----------------------------------------------------

def text_mutants(rng, name, doc_text, bin_chunk, write):
    """NaN and Infinity tokens, deep nesting, truncated files, a broken .glb header."""
    number_at = [i for i, c in enumerate(doc_text) if c.isdigit() and doc_text[i - 1] in ":[,"]
    for k, token in enumerate(rng.sample(["NaN", "Infinity", "-Infinity", "1e999"], 2)):
        at = rng.choice(number_at)
        write(f"{name}.nan_token.{k}", doc_text[:at] + token + doc_text[at + 1:], bin_chunk, f"{token} at byte {at}")
    # Deeper than a recursive parser's or walker's stack; in a material, which the writer walks.
    depth = 100000 if name in ("cornell_box", "lit_room") else 3000
    at = doc_text.find('"materials":[{') + len('"materials":[{')
    write(f"{name}.deep_json.0", doc_text[:at] + '"extras":' + "[" * depth + "]" * depth + "," + doc_text[at:],
          bin_chunk, f"material extras nested {depth} deep")
    cut = rng.randrange(len(doc_text) // 4, len(doc_text))
    write(f"{name}.truncated_json.0", doc_text[:cut], bin_chunk, f"cut at byte {cut}")
    if bin_chunk is not None:  # the container itself
        whole = glb_bytes(doc_text, bin_chunk)
        for k, (what, data) in enumerate([
                ("declared length too long", whole[:8] + struct.pack("<I", len(whole) * 4) + whole[12:]),
                ("JSON chunk length too long", whole[:12] + struct.pack("<I", 2 ** 31) + whole[16:]),
                ("version 1", whole[:4] + struct.pack("<I", 1) + whole[8:]),
                ("file cut in the BIN chunk", whole[:len(whole) - len(bin_chunk) // 2]),
                ("header only", whole[:12]),
                ("BIN chunk first", whole[:12] + whole[20 + len(doc_text) + (-len(doc_text) % 4):] +
                 whole[12:20 + len(doc_text) + (-len(doc_text) % 4)])]):
            write(f"{name}.glb_container.{k}", None, None, what, raw=data)


def main():
    os.makedirs(OUT, exist_ok=True)
    for old in os.listdir(OUT):
        if not old.startswith(OTHER_TARGETS_SEEDS):
            os.remove(os.path.join(OUT, old))
    # External buffers the sources name, beside the mutants, and a short one for truncation.
    for relative in ("samples/cornell_box/cornell_box.bin", "samples/ferren/ferren.bin",
                     "samples/study_room/study_room.bin", "tests/fixtures/external_buffer.bin"):
        data = open(os.path.join(ROOT, relative), "rb").read()
        open(os.path.join(OUT, os.path.basename(relative)), "wb").write(data)
    open(os.path.join(OUT, "truncated.bin"), "wb").write(bytes(10))
    for file, data in IMAGE_FILES.items():
        open(os.path.join(OUT, file), "wb").write(data)
    for how, data in FLAGGED_PNGS.items():
        open(os.path.join(OUT, f"texture_{how}.png"), "wb").write(data)
    written = 0

    def write(stem, doc_text, bin_chunk, what, raw=None, glb=None):
        nonlocal written
        glb = glb if glb is not None else (bin_chunk is not None or raw is not None)
        path = os.path.join(OUT, stem + (".glb" if glb else ".gltf"))
        data = raw if raw is not None else glb_bytes(doc_text, bin_chunk) if glb else doc_text.encode()
        open(path, "wb").write(data)
        written += 1

    def write_doc(stem, doc, bin_chunk, what):
        # Where the mutation was, kept in the file for whoever reads a failure (asset survives most).
        if isinstance(doc.get("asset"), dict):
            doc["asset"]["extras"] = {"mutation": what}
        write(stem, dump(doc), bin_chunk, what, glb=bin_chunk is not None)

    for relative in SOURCES:
        source, bin_chunk = read_source(relative)
        name = os.path.splitext(os.path.basename(relative))[0]
        for kind, mutate in TARGETED.items():
            made = 0
            for attempt in range(12):
                if made == PER_SOURCE.get(kind, TARGETED_PER_SOURCE):
                    break
                rng = random.Random(f"{SEED}:{name}:{kind}:{attempt}")
                doc = copy.deepcopy(source)
                if kind == "uri" and bin_chunk is not None:
                    doc["buffers"].append({"byteLength": 4, "uri": "x.bin"})
                what = mutate(rng, doc)
                if what is None:
                    continue
                write_doc(f"{name}.{kind}.{made}", doc, bin_chunk, what)
                made += 1
        for k in range(1):
            rng = random.Random(f"{SEED}:{name}:truncate:{k}")
            doc = copy.deepcopy(source)
            what, chunk = truncate_buffer(rng, doc, bin_chunk)
            if what:
                write_doc(f"{name}.truncated_buffer.{k}", doc, chunk, what)
        for k in range(RANDOM_PER_SOURCE):
            rng = random.Random(f"{SEED}:{name}:random:{k}")
            doc = copy.deepcopy(source)
            edits = [random_edit(rng, doc) for _ in range(1 + k % 3)]
            write_doc(f"{name}.{edits[0][0]}.{k}", doc, bin_chunk, "; ".join(e[1] for e in edits))
        text_mutants(random.Random(f"{SEED}:{name}:text"), name, dump(source), bin_chunk, write)
    print(f"make_corpus: wrote {written} files to {os.path.relpath(OUT, ROOT)}", file=sys.stderr)


if __name__ == "__main__":
    main()
