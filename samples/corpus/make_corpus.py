#!/usr/bin/env python3
"""Makes the real-scene corpus: models nobody here wrote, as users bring them.

usage: make_corpus.py OUTPUT_FOLDER

Every scene comes from a Debian package that ./dev installs (assimp-testmodels, converted to glTF
2.0 by assimp-utils' `assimp export`), but zdm2, which no package holds: it is copied from the
shared corpus beside the project (../shared/corpus, found as SHARED_CORPUS says). Where a model
has no light, one is added, always the same way (add_light below), and said so in
OUTPUT_FOLDER/corpus.json, which the tests and ./dev bench-real read. Nothing of the models is
kept in this repository: the script rebuilds the corpus from the packages and the shared corpus.
samples/corpus/README.md says where each came from and its licence.
"""
import json
import math
import os
import shutil
import struct
import subprocess
import sys

import floor_lamps
import quake3_map

MODELS = "/usr/share/assimp/models"
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# name: (what it stands for, source file, the light added)
SCENES = {
    "fzk_haus": ("architecture: KIT's two-storey sample house, IFC", "IFC/AC14-FZK-Haus.ifc", "sun"),
    "cylinder_engine": ("CAD: a two-cylinder engine, 82 parts", "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
                        "lamp"),
    "teapots": ("kit-bashed props: one teapot instanced by COLLADA instance nodes", "Collada/teapot_instancenodes.DAE", "lamp"),
    "milk_truck": ("a vehicle: Cesium's milk truck, glTF 1.0, textured", "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", "sun"),
    "duck": ("a textured game asset: the COLLADA duck", "Collada/duck.dae", "lamp"),
    "arena": ("a game level: OpenArena's am_underworks2, an underground industrial arena, Quake 3 BSP",
              "openarena:am_underworks2", "player_lamps"),
    "zdm2": ("a game level that is a benchmark elsewhere: Cube 2: Sauerbraten's zdm2, indoor and outdoor, the map of "
             "Godot's global-illumination demo", "shared:zdm2/zdm2.gltf", "floor_lamps"),
}
# Scenes of the shared corpus, with the metres in one of their units: Cube 2's is about 0.125 m (a
# player stands about 15 units tall), as ../shared/corpus/README.md says.
SHARED_UNIT_M = {"zdm2": 0.125}
# A level with no player starts gets as many lamps as the arena has (its floors are as large:
# 9,300 m2 against the arena's 10,600), at floor_lamps' points, standing where a start would.
FLOOR_LAMPS = 15
PLAYER_START_HEIGHT = 0.75  # metres over the floor, Quake 3's
# OpenArena's archives (Debian's openarena-088-data, openarena-081-textures), later ones winning.
OPENARENA = "/usr/share/games/openarena/baseoa"
OPENARENA_PK3S = ["pak4-textures.pk3", "pak6-patch088.pk3"]

# The walls of a building: its outside is their box (tests check work-plane points lie inside it).
WALLS = {"fzk_haus": "IfcWall"}
# A building's exterior surfaces, by name (a regular expression): its outer walls, roof slabs and
# site. The per-surface comparisons (bench/surfaces, tests/corpus/interior_surfaces.py) take the
# rest as its interior.
EXTERIOR = {"fzk_haus": "Wand-Ext|Dach|Gelände"}

# Added lights. The sun: 60,000 lx (a clear day's direct normal illuminance in the CIE 171 range)
# from 35 degrees up in the south-west, so it enters a building's windows. The lamp: a point light
# above and in front of the model at 1.5 bounding-box diagonals from its centre, giving 300 lx there.
SUN_LUX = 60000.0
SUN_ELEVATION, SUN_AZIMUTH = math.radians(35), math.radians(225)  # azimuth from north (-Z) through east (+X)
LAMP_LUX_AT_CENTRE = 300.0
# A game level keeps no light of its own (q3map2 bakes its lights and drops them): a lamp of
# PLAYER_LAMP_CD at head height, PLAYER_LAMP_HEIGHT above each player start (which stands
# PLAYER_START_HEIGHT above the floor), lights the places the level is played in.
PLAYER_LAMP_CD, PLAYER_LAMP_HEIGHT = 200.0, 1.0


def read_gltf(path):
    """(json, bin bytes or None) of a .gltf or .glb."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != b"glTF":
        return json.loads(data), None
    length = struct.unpack_from("<I", data, 8)[0]
    offset, doc, binary = 12, None, None
    while offset < length:
        size, kind = struct.unpack_from("<II", data, offset)
        chunk = data[offset + 8:offset + 8 + size]
        if kind == 0x4E4F534A:
            doc = json.loads(chunk)
        elif kind == 0x004E4942:
            binary = chunk
        offset += 8 + size
    return doc, binary


def write_glb(path, doc, binary):
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    binary = binary + b"\0" * (-len(binary) % 4)
    total = 12 + 8 + len(text) + 8 + len(binary)
    with open(path, "wb") as f:
        f.write(struct.pack("<III", 0x46546C67, 2, total))
        f.write(struct.pack("<II", len(text), 0x4E4F534A) + text)
        f.write(struct.pack("<II", len(binary), 0x004E4942) + binary)


def mat_mul(a, b):  # column-major 4x4
    return [sum(a[k * 4 + r] * b[c * 4 + k] for k in range(4)) for c in range(4) for r in range(4)]


def node_matrix(node):
    if "matrix" in node:
        return node["matrix"]
    tx, ty, tz = node.get("translation", [0, 0, 0])
    x, y, z, w = node.get("rotation", [0, 0, 0, 1])
    sx, sy, sz = node.get("scale", [1, 1, 1])
    r = [1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w),
         2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
         2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)]
    return [r[0] * sx, r[1] * sx, r[2] * sx, 0, r[3] * sy, r[4] * sy, r[5] * sy, 0,
            r[6] * sz, r[7] * sz, r[8] * sz, 0, tx, ty, tz, 1]


def placed_primitives(doc, named=""):
    """(world matrix, primitive) of every primitive of the default scene; with `named`, of the nodes
    whose name holds it (and their children) only."""
    placed = []
    scene = doc.get("scenes", [{}])[doc.get("scene", 0)]

    def walk(index, parent, counted):
        node = doc["nodes"][index]
        m = mat_mul(parent, node_matrix(node))
        counted = counted or named in node.get("name", "")
        if "mesh" in node and counted:
            placed.extend((m, p) for p in doc["meshes"][node["mesh"]]["primitives"])
        for child in node.get("children", []):
            walk(child, m, counted)

    for root in scene.get("nodes", []):
        walk(root, [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], not named)
    return placed


def transformed(m, v):
    return [m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2] + m[12 + r] for r in range(3)]


def world_bounds(doc, named=""):
    """World-space box of the default scene (or of the nodes `named`, as placed_primitives), from
    each mesh's POSITION min/max corners."""
    lo, hi = [math.inf] * 3, [-math.inf] * 3
    for m, p in placed_primitives(doc, named):
        a = doc["accessors"][p["attributes"]["POSITION"]]
        for corner in range(8):
            w = transformed(m, [a["max"][i] if corner >> i & 1 else a["min"][i] for i in range(3)])
            for i in range(3):
                lo[i], hi[i] = min(lo[i], w[i]), max(hi[i], w[i])
    return lo, hi


def accessor_values(doc, binary, index):
    """A float or unsigned accessor's components, flat, read from the file's one buffer."""
    a = doc["accessors"][index]
    view = doc["bufferViews"][a["bufferView"]]
    width = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[a["type"]]
    code = {5126: "f", 5125: "I", 5123: "H", 5121: "B"}[a["componentType"]]
    size = struct.calcsize(code)
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    stride = view.get("byteStride", width * size)
    return [x for k in range(a["count"]) for x in struct.unpack_from("<" + code * width, binary, start + k * stride)]


def world_triangles(doc, binary):
    """Every triangle of the default scene as three world-space corners."""
    triangles = []
    for m, p in placed_primitives(doc):
        if p.get("mode", 4) != 4:
            continue
        xyz = accessor_values(doc, binary, p["attributes"]["POSITION"])
        points = [transformed(m, xyz[k:k + 3]) for k in range(0, len(xyz), 3)]
        corners = accessor_values(doc, binary, p["indices"]) if "indices" in p else range(len(points))
        triangles.extend((points[corners[k]], points[corners[k + 1]], points[corners[k + 2]])
                         for k in range(0, len(corners) - 2, 3))
    return triangles


def look_rotation(direction):
    """Quaternion turning a light's -Z onto `direction` (unit)."""
    dx, dy, dz = direction
    ax, ay, az = dy, -dx, 0.0  # (0, 0, -1) x direction
    w = 1 - dz  # 1 + cos of the angle between them
    if w < 1e-9:
        return [0, 1, 0, 0]
    n = math.sqrt(ax * ax + ay * ay + az * az + w * w)
    return [ax / n, ay / n, az / n, w / n]


def add_punctual(doc, light, node):
    lights = doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {}).setdefault("lights", [])
    node["extensions"] = {"KHR_lights_punctual": {"light": len(lights)}}
    lights.append(light)
    doc.setdefault("nodes", []).append(node)
    doc["scenes"][doc.get("scene", 0)].setdefault("nodes", []).append(len(doc["nodes"]) - 1)
    used = doc.setdefault("extensionsUsed", [])
    if "KHR_lights_punctual" not in used:
        used.append("KHR_lights_punctual")


def add_player_lamps(doc, starts, where="each player start"):
    """A point lamp over each player start (PLAYER_LAMP_*); returns its description and the bounds."""
    for k, (x, y, z) in enumerate(starts):
        add_punctual(doc, {"name": f"added lamp {k}", "type": "point", "intensity": PLAYER_LAMP_CD},
                     {"name": f"added lamp {k}", "translation": [x, y + PLAYER_LAMP_HEIGHT, z]})
    lo, hi = world_bounds(doc)
    return f"{len(starts)} point lamps of {PLAYER_LAMP_CD:g} cd, {PLAYER_LAMP_HEIGHT:g} m above {where}", {"min": lo, "max": hi}


def add_floor_lamps(doc, binary):
    """Player lamps over floor_lamps' points, standing where player starts would, for a level that
    keeps none."""
    points = floor_lamps.floor_points(world_triangles(doc, binary), FLOOR_LAMPS)
    starts = [(x, y + PLAYER_START_HEIGHT, z) for x, y, z in points]
    return add_player_lamps(doc, starts, f"{len(starts)} points {PLAYER_START_HEIGHT:g} m over its floors, spread as far "
                                         "apart as they go (it keeps no player starts; floor_lamps.py)")


def shared_corpus():
    """The shared corpus's folder: $RADBAKE_SHARED_CORPUS, else ../shared/corpus beside the project,
    else beside the repository this one was cloned from (a CI or fresh clone elsewhere); None when
    none of them is there."""
    places = [os.environ.get("RADBAKE_SHARED_CORPUS", ""), os.path.join(ROOT, "..", "shared", "corpus")]
    origin = subprocess.run(["git", "-C", ROOT, "config", "--get", "remote.origin.url"], capture_output=True, text=True)
    if origin.returncode == 0 and os.path.isdir(origin.stdout.strip()):
        places.append(os.path.join(origin.stdout.strip(), "..", "shared", "corpus"))
    return next((os.path.realpath(p) for p in places if p and os.path.isdir(p)), None)


def copy_shared(name, source, out):
    """Copies a shared-corpus scene (a .gltf and the files it names) into `out`, its units scaled to
    metres by a root node; returns its path, json and buffer."""
    folder = shared_corpus()
    if folder is None or not os.path.exists(os.path.join(folder, source)):
        return None
    src = os.path.join(folder, source)
    doc, _ = read_gltf(src)
    for entry in doc.get("buffers", []) + doc.get("images", []):
        if "uri" in entry and not entry["uri"].startswith("data:"):
            # A file beside the scene, by its plain name: nothing the file names is read from elsewhere.
            if os.path.basename(entry["uri"]) != entry["uri"] or entry["uri"] in ("", ".", ".."):
                sys.exit(f"make_corpus: {src}: names {entry['uri']!r}, not a file beside it")
            shutil.copy(os.path.join(os.path.dirname(src), entry["uri"]), out)
    scene = doc["scenes"][doc.get("scene", 0)]
    unit = SHARED_UNIT_M[name]
    doc["nodes"].append({"name": f"{name} units to metres", "scale": [unit] * 3, "children": scene["nodes"]})
    scene["nodes"] = [len(doc["nodes"]) - 1]
    with open(os.path.join(out, doc["buffers"][0]["uri"]), "rb") as f:
        binary = f.read()
    return os.path.join(out, name + ".gltf"), doc, binary


def add_light(doc, kind):
    """Adds one KHR_lights_punctual light (see SUN_*, LAMP_*); returns its description."""
    lo, hi = world_bounds(doc)
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    diagonal = math.dist(lo, hi)
    if kind == "sun":
        towards_sun = [math.cos(SUN_ELEVATION) * math.sin(SUN_AZIMUTH), math.sin(SUN_ELEVATION),
                       -math.cos(SUN_ELEVATION) * math.cos(SUN_AZIMUTH)]
        light = {"name": "added sun", "type": "directional", "intensity": SUN_LUX}
        node = {"name": "added sun", "rotation": look_rotation([-c for c in towards_sun])}
        said = f"directional sun, {SUN_LUX:g} lx, 35 degrees up in the south-west"
    else:
        distance = 1.5 * diagonal
        position = [centre[0] + 0.5 * distance, centre[1] + 0.7 * distance, centre[2] + 0.5 * distance]
        distance = math.dist(position, centre)
        light = {"name": "added lamp", "type": "point", "intensity": LAMP_LUX_AT_CENTRE * distance * distance}
        node = {"name": "added lamp", "translation": position}
        said = f"point lamp, {light['intensity']:.4g} cd, {distance:.3g} m from the model's centre ({LAMP_LUX_AT_CENTRE:g} lx there)"
    add_punctual(doc, light, node)
    return said, {"min": lo, "max": hi}


def assimp_version():
    r = subprocess.run(["assimp", "version"], capture_output=True, text=True)
    for line in r.stdout.splitlines():
        if "Version" in line:
            return line.strip()
    return "unknown"


def make(name, source, light, folder):
    """Converts (or copies) one model into folder/name/ and adds its light."""
    out = os.path.join(folder, name)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    src, starts = os.path.join(MODELS, source), []
    if source.startswith("shared:"):
        copied = copy_shared(name, source.split(":")[1], out)
        if copied is None:
            shutil.rmtree(out)
            return None
        path, doc, binary = copied
        said, bounds = add_floor_lamps(doc, binary)
        with open(path, "w") as f:
            json.dump(doc, f, indent=1)
        return path, said, bounds, f"copied from the shared corpus, {SHARED_UNIT_M[name]:g} m a unit"
    if source.startswith("openarena:"):
        src, starts = quake3_map.convert(source.split(":")[1], os.path.join(out, "map"),
                                         [os.path.join(OPENARENA, p) for p in OPENARENA_PK3S])
    if source.endswith(".glb"):
        doc, binary = read_gltf(src)
        said, bounds = add_light(doc, light)
        path = os.path.join(out, name + ".glb")
        write_glb(path, doc, binary)
        return path, said, bounds, "copied"
    converted = os.path.join(out, name + ".gltf")
    r = subprocess.run(["assimp", "export", src, converted, "-f", "gltf2"], capture_output=True, text=True)
    if r.returncode != 0 or not os.path.exists(converted):
        sys.exit(f"make_corpus: assimp could not convert {src}: {(r.stderr or r.stdout).strip().splitlines()[-1:]}")
    with open(converted) as f:
        doc = json.load(f)
    # Images the model names sit next to its source; the converted file names them relatively.
    for image in doc.get("images", []):
        uri = image.get("uri", "")
        if uri and not uri.startswith("data:") and not os.path.exists(os.path.join(out, uri)):
            found = os.path.join(os.path.dirname(src), uri)
            if os.path.exists(found):
                shutil.copy(found, os.path.join(out, os.path.basename(uri)))
                image["uri"] = os.path.basename(uri)
    if source.startswith("openarena:"):
        shutil.rmtree(os.path.dirname(src))  # the OBJ, its MTL and textures: copied into the glTF's folder
    said, bounds = add_player_lamps(doc, starts) if light == "player_lamps" else add_light(doc, light)
    with open(converted, "w") as f:
        json.dump(doc, f, indent=1)
    return converted, said, bounds, "converted by " + assimp_version()


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    folder = os.path.abspath(sys.argv[1])
    os.makedirs(folder, exist_ok=True)
    manifest, missing = [], []
    for name, (kind, source, light) in SCENES.items():
        made = make(name, source, light, folder)
        if made is None:
            missing.append(name)
            print(f"make_corpus: {name} left out: no shared corpus holds {source.split(':')[1]} "
                  "(../shared/corpus beside the project or its origin, or $RADBAKE_SHARED_CORPUS)")
            continue
        path, said, bounds, how = made
        origin = ("openarena (openarena-088-data, openarena-081-textures): maps/" + source.split(":")[1] + ".bsp"
                  if source.startswith("openarena:") else "the shared corpus: " + source.split(":")[1]
                  if source.startswith("shared:") else "assimp-testmodels: " + source)
        entry = {"name": name, "kind": kind, "file": os.path.relpath(path, folder),
                 "source": origin, "made": how, "light_added": said, "bounds_m": bounds}
        if name in EXTERIOR:
            entry["exterior_surfaces"] = EXTERIOR[name]
        if name in WALLS:
            lo, hi = world_bounds(read_gltf(path)[0], WALLS[name])
            entry["walls_bounds_m"] = {"min": lo, "max": hi}
        manifest.append(entry)
    with open(os.path.join(folder, "corpus.json"), "w") as f:
        json.dump({"scenes": manifest, "missing": missing}, f, indent=1)
    print(f"make_corpus: {len(manifest)} scenes in {folder}")


if __name__ == "__main__":
    main()
