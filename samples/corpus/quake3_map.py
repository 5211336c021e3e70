#!/usr/bin/env python3
"""A Quake 3 map (IBSP version 46, as OpenArena ships them in .pk3 archives) as Wavefront OBJ + MTL,
which assimp-utils then converts to glTF. assimp 5.2 has a Q3BSP importer of its own, but it
fails on every OpenArena map ("aiMesh::mFaces[0]::mIndices[0] is out of range", assimp issue
#2862), so this reads the BSP itself; only the standard library is used.

usage: quake3_map.py MAP OUT_FOLDER PK3 [PK3 ...]   (later archives win, as in the game)

What is written: the world model (model 0): polygons, triangle meshes and curved surfaces
(biquadratic patches, tessellated TESSELLATION steps a side); sky, fog, hint, skip and nodraw
surfaces are left out, as the game does not draw them. Quake's Z is up and its unit is an inch of
the player (a player stands 56 units tall): positions become (x, z, -y) / 32 metres, Y up, so a
player is 1.75 m. Each shader becomes a material of diffuse 0.8 with its texture: JPEG copied,
TGA converted to PNG (glTF has no TGA); shaders with no image keep the plain colour.

The map's player starts (info_player_start, info_player_deathmatch) are returned, in the same
metres, for whoever lights the level: compiled maps keep no light entities (q3map2 bakes them into
its own lightmaps and drops them).
"""
import os
import re
import struct
import sys
import zipfile
import zlib

METRES_PER_UNIT = 1.0 / 32.0
TESSELLATION = 6
SURF_SKY, SURF_NODRAW, SURF_HINT, SURF_SKIP = 0x4, 0x80, 0x100, 0x200
CONTENTS_FOG = 0x40
LUMP_ENTITIES, LUMP_SHADERS, LUMP_MODELS, LUMP_VERTICES, LUMP_MESH_VERTICES, LUMP_FACES = 0, 1, 7, 10, 11, 13
POLYGON, PATCH, MESH = 1, 2, 3


def to_metres(p):
    return (p[0] * METRES_PER_UNIT, p[2] * METRES_PER_UNIT, -p[1] * METRES_PER_UNIT)


class Archives:
    """Files of several .pk3 (zip) archives by lower-case name; a later archive's copy wins."""

    def __init__(self, paths):
        self.files = {}
        for path in paths:
            archive = zipfile.ZipFile(path)
            for name in archive.namelist():
                self.files[name.lower()] = (archive, name)

    def read(self, name):
        found = self.files.get(name.lower())
        return found[0].read(found[1]) if found else None


def tga_to_png(tga):
    """A true-colour TGA (uncompressed or run-length, 24 or 32 bits) as PNG bytes; None otherwise."""
    id_length, colour_map, kind = tga[0], tga[1], tga[2]
    width, height, bits, descriptor = struct.unpack_from("<HHBB", tga, 12)
    if colour_map != 0 or kind not in (2, 10) or bits not in (24, 32) or width == 0 or height == 0:
        return None
    size, pixels, at = bits // 8, bytearray(), 18 + id_length
    while len(pixels) < width * height * size:
        if kind == 2:
            pixels += tga[at:at + width * height * size]
            break
        header, at = tga[at], at + 1
        count = (header & 0x7F) + 1
        if header & 0x80:
            pixels += tga[at:at + size] * count
            at += size
        else:
            pixels += tga[at:at + count * size]
            at += count * size
    if len(pixels) < width * height * size:
        return None
    rows = []
    for y in range(height):
        row = pixels[y * width * size:(y + 1) * width * size]
        rgba = bytearray(width * 4)
        rgba[0::4], rgba[1::4], rgba[2::4] = row[2::size], row[1::size], row[0::size]
        rgba[3::4] = row[3::size] if size == 4 else b"\xff" * width
        rows.append(bytes(rgba))
    if not descriptor & 0x20:  # stored bottom row first
        rows.reverse()

    def chunk(kind_name, data):
        return struct.pack(">I", len(data)) + kind_name + data + struct.pack(">I", zlib.crc32(kind_name + data))

    raw = b"".join(b"\0" + row for row in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def entities(text):
    """The entity lump as a list of dicts of its keys."""
    return [dict(re.findall(r'"([^"]*)"\s+"([^"]*)"', block)) for block in re.findall(r"\{([^}]*)\}", text)]


def patch_triangles(control, add_vertex):
    """One 3 x 3 biquadratic patch of vertex tuples, tessellated: its triangles."""
    def bezier(a, b, c, t):
        s = 1 - t
        return tuple(s * s * a[k] + 2 * s * t * b[k] + t * t * c[k] for k in range(len(a)))

    rows = []
    for j in range(TESSELLATION + 1):
        v = j / TESSELLATION
        column = [bezier(control[0][i], control[1][i], control[2][i], v) for i in range(3)]
        rows.append([add_vertex(bezier(column[0], column[1], column[2], i / TESSELLATION))
                     for i in range(TESSELLATION + 1)])
    triangles = []
    for j in range(TESSELLATION):
        for i in range(TESSELLATION):
            a, b, c, d = rows[j][i], rows[j][i + 1], rows[j + 1][i], rows[j + 1][i + 1]
            triangles += [(a, b, c), (b, d, c)]
    return triangles


def convert(map_name, out_folder, pk3s):
    """Writes OUT_FOLDER/MAP.obj, .mtl and textures; returns (obj path, player starts in metres)."""
    files = Archives(pk3s)
    data = files.read(f"maps/{map_name}.bsp")
    if data is None:
        sys.exit(f"quake3_map: maps/{map_name}.bsp is in none of {pk3s}")
    magic, version = struct.unpack_from("<4si", data, 0)
    if magic != b"IBSP" or version != 46:
        sys.exit(f"quake3_map: maps/{map_name}.bsp is not a Quake 3 map (IBSP 46)")
    lumps = [struct.unpack_from("<ii", data, 8 + 8 * i) for i in range(17)]

    def lump(index, layout):
        offset, length = lumps[index]
        size = struct.calcsize(layout)
        return [struct.unpack_from(layout, data, offset + k * size) for k in range(length // size)]

    shaders = [(s[0].split(b"\0")[0].decode("latin-1"), s[1], s[2]) for s in lump(LUMP_SHADERS, "<64sii")]
    first_face, face_count = lump(LUMP_MODELS, "<6fiiii")[0][6:8]
    vertices = lump(LUMP_VERTICES, "<3f2f2f3f4B")  # position, texture uv, lightmap uv, normal, colour
    mesh_vertices = [m[0] for m in lump(LUMP_MESH_VERTICES, "<i")]
    faces = lump(LUMP_FACES, "<12i3f3f3f3f2i")

    positions, uvs, normals, index_of = [], [], [], {}

    def add_vertex(v):  # (x, y, z, u, v, ..., nx, ny, nz) in Quake's frame
        key = (v[0:3], v[3:5], v[7:10])
        if key not in index_of:
            index_of[key] = len(positions)
            positions.append(to_metres(v[0:3]))
            uvs.append((v[3], 1.0 - v[4]))
            n = to_metres(v[7:10])
            length = (n[0] ** 2 + n[1] ** 2 + n[2] ** 2) ** 0.5 or 1.0
            normals.append(tuple(c / length for c in n))
        return index_of[key]

    triangles_of = {}  # shader -> triangles
    for face in faces[first_face:first_face + face_count]:
        shader, _, kind, first_vertex, _, first_index, index_count = face[0:7]
        _, flags, contents = shaders[shader]
        if flags & (SURF_SKY | SURF_NODRAW | SURF_HINT | SURF_SKIP) or contents & CONTENTS_FOG:
            continue
        triangles = triangles_of.setdefault(shader, [])
        if kind in (POLYGON, MESH):
            corners = [add_vertex(vertices[first_vertex + mesh_vertices[first_index + k]]) for k in range(index_count)]
            triangles += [(corners[k], corners[k + 2], corners[k + 1]) for k in range(0, len(corners) - 2, 3)]  # Quake winds clockwise
        elif kind == PATCH:
            width, height = face[-2:]
            grid = vertices[first_vertex:first_vertex + width * height]
            for y in range(0, height - 1, 2):
                for x in range(0, width - 1, 2):
                    triangles += patch_triangles([[grid[(y + j) * width + x + i] for i in range(3)] for j in range(3)],
                                                 add_vertex)

    os.makedirs(out_folder, exist_ok=True)
    materials, mtl = {}, []
    for shader in sorted(s for s, t in triangles_of.items() if t):
        name = shaders[shader][0]
        material = f"m{shader:03d}_{name.replace('/', '_')}"
        materials[shader] = material
        mtl.append(f"newmtl {material}\nKd 0.8 0.8 0.8\nKs 0 0 0\nd 1\nillum 1\n")
        for extension in (".jpg", ".png", ".tga"):
            image = files.read(name + extension)
            if image is None:
                continue
            file = name.replace("/", "_") + (".png" if extension == ".tga" else extension)
            if extension == ".tga":
                image = tga_to_png(image)
            if image:
                with open(os.path.join(out_folder, file), "wb") as f:
                    f.write(image)
                mtl[-1] += f"map_Kd {file}\n"
            break
    obj = os.path.join(out_folder, map_name + ".obj")
    with open(os.path.join(out_folder, map_name + ".mtl"), "w") as f:
        f.write("\n".join(mtl))
    with open(obj, "w") as f:
        f.write(f"mtllib {map_name}.mtl\no {map_name}\n")
        f.writelines("v %.5f %.5f %.5f\n" % p for p in positions)
        f.writelines("vt %.5f %.5f\n" % t for t in uvs)
        f.writelines("vn %.4f %.4f %.4f\n" % n for n in normals)
        for shader, material in materials.items():
            f.write(f"g {material}\nusemtl {material}\n")
            f.writelines("f %d/%d/%d %d/%d/%d %d/%d/%d\n" % ((a + 1,) * 3 + (b + 1,) * 3 + (c + 1,) * 3)
                         for a, b, c in triangles_of[shader])
    offset, length = lumps[LUMP_ENTITIES]
    starts = [to_metres([float(c) for c in e["origin"].split()])
              for e in entities(data[offset:offset + length].decode("latin-1"))
              if e.get("classname") in ("info_player_start", "info_player_deathmatch") and "origin" in e]
    return obj, starts


if __name__ == "__main__":
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    path, found = convert(sys.argv[1], sys.argv[2], sys.argv[3:])
    print(f"quake3_map: wrote {path}; {len(found)} player starts")
