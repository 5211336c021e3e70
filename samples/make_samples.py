#!/usr/bin/env python3
"""Regenerates the sample scenes: python3 samples/make_samples.py

cornell_box/  The Cornell box from the published Cornell geometry (graphics.cornell.edu
              "Cornell Box Data", millimetres converted to metres) with the usual RGB
              reflectances and its ceiling light.
ferren/       After the Goral et al. (1984) demonstration: vertical boards, white on the side
              facing the viewer and brightly coloured on the back, lit from behind by a window.
classroom/    A daylit classroom: 9 x 7 x 3 m, three windows in the south wall
              (+Z; north is -Z) glazed with a visible transmittance of 0.7, a 1 m overhang over
              them, twelve desks and a blackboard; no lamp: the sky and the sun light it.
              classroom_no_overhang.gltf: the same without the overhang (a design variant for the year's metrics).
study_room/   The accuracy study's interior (docs/accuracy.md): a 4 x 3 x 2.6 m room lit by a
              window and a ceiling lamp, a table casting a shadow, and a bookcase standing 2 cm
              from a wall (a narrow gap light must not leak through).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gltf_builder import Gltf, box_faces, facing  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))

WHITE = (0.725, 0.71, 0.68)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)


def mm(points):
    return [[c / 1000.0 for c in p] for p in points]


def cornell_box():
    g = Gltf("radbake samples/make_samples.py")
    inside = [0.278, 0.274, 0.280]
    white = g.material("white", WHITE)
    red = g.material("red", RED)
    green = g.material("green", GREEN)
    # Luminance 20000 cd/m2 (emissive x strength): about 860 lm from the 130 x 105 mm panel.
    light = g.material("light", (0.78, 0.78, 0.78), emissive=(1.0, 0.85, 0.6), strength=20000.0)

    walls = {
        "floor": (white, [[552.8, 0, 0], [0, 0, 0], [0, 0, 559.2], [549.6, 0, 559.2]]),
        "ceiling": (white, [[556.0, 548.8, 0], [556.0, 548.8, 559.2], [0, 548.8, 559.2], [0, 548.8, 0]]),
        "back_wall": (white, [[549.6, 0, 559.2], [0, 0, 559.2], [0, 548.8, 559.2], [556.0, 548.8, 559.2]]),
        "right_wall_green": (green, [[0, 0, 559.2], [0, 0, 0], [0, 548.8, 0], [0, 548.8, 559.2]]),
        "left_wall_red": (red, [[552.8, 0, 0], [549.6, 0, 559.2], [556.0, 548.8, 559.2], [556.0, 548.8, 0]]),
    }
    for name, (material, poly) in walls.items():
        g.node(name, g.mesh(name, [facing(mm(poly), inside)], material))

    # The light sits 0.1 mm under the ceiling, facing down.
    lamp = mm([[343.0, 548.7, 227.0], [343.0, 548.7, 332.0], [213.0, 548.7, 332.0], [213.0, 548.7, 227.0]])
    g.node("light", g.mesh("light", [facing(lamp, [0.278, 0.0, 0.280])], light))

    short_block = [
        [[130.0, 165.0, 65.0], [82.0, 165.0, 225.0], [240.0, 165.0, 272.0], [290.0, 165.0, 114.0]],
        [[290.0, 0.0, 114.0], [290.0, 165.0, 114.0], [240.0, 165.0, 272.0], [240.0, 0.0, 272.0]],
        [[130.0, 0.0, 65.0], [130.0, 165.0, 65.0], [290.0, 165.0, 114.0], [290.0, 0.0, 114.0]],
        [[82.0, 0.0, 225.0], [82.0, 165.0, 225.0], [130.0, 165.0, 65.0], [130.0, 0.0, 65.0]],
        [[240.0, 0.0, 272.0], [240.0, 165.0, 272.0], [82.0, 165.0, 225.0], [82.0, 0.0, 225.0]],
    ]
    tall_block = [
        [[423.0, 330.0, 247.0], [265.0, 330.0, 296.0], [314.0, 330.0, 456.0], [472.0, 330.0, 406.0]],
        [[423.0, 0.0, 247.0], [423.0, 330.0, 247.0], [472.0, 330.0, 406.0], [472.0, 0.0, 406.0]],
        [[472.0, 0.0, 406.0], [472.0, 330.0, 406.0], [314.0, 330.0, 456.0], [314.0, 0.0, 456.0]],
        [[314.0, 0.0, 456.0], [314.0, 330.0, 456.0], [265.0, 330.0, 296.0], [265.0, 0.0, 296.0]],
        [[265.0, 0.0, 296.0], [265.0, 330.0, 296.0], [423.0, 330.0, 247.0], [423.0, 0.0, 247.0]],
    ]
    for name, faces, centre in (("short_block", short_block, [186.0, 82.5, 168.5]),
                                ("tall_block", tall_block, [368.5, 165.0, 351.25])):
        c = [x / 1000.0 for x in centre]
        polys = []
        for f in faces:
            poly = mm(f)
            mirrored = [2 * sum(p[k] for p in poly) / 4 - c[k] for k in range(3)]
            polys.append(facing(poly, mirrored))  # outward
        g.node(name, g.mesh(name, polys, white))

    # The published camera: at (278, 273, -800) mm looking down +Z (glTF cameras look down -Z).
    cam = g.camera("camera", yfov=2 * math.atan(0.0125 / 0.035), aspect=1.0)
    g.node("camera", camera=cam, translation=[0.278, 0.273, -0.8], rotation=[0, 1, 0, 0])
    out = os.path.join(HERE, "cornell_box")
    os.makedirs(out, exist_ok=True)
    g.save(os.path.join(out, "cornell_box.gltf"), bin_name="cornell_box.bin")


def ferren():
    g = Gltf("radbake samples/make_samples.py")
    white = g.material("white", (0.8, 0.8, 0.8))
    floor = g.material("floor", (0.5, 0.5, 0.5))
    colours = [("red", (0.85, 0.08, 0.06)), ("yellow", (0.85, 0.7, 0.05)), ("green", (0.08, 0.7, 0.12)),
               ("blue", (0.08, 0.15, 0.85)), ("magenta", (0.75, 0.08, 0.65))]
    # A window behind the boards, facing them: luminance 4000 cd/m2, daylight-white.
    window = g.material("window", (0.0, 0.0, 0.0), emissive=(0.95, 0.97, 1.0), strength=4000.0)

    g.node("floor", g.mesh("floor", [[[-2, 0, -2], [-2, 0, 2.5], [2, 0, 2.5], [2, 0, -2]]], floor))
    # Boards turned 45 degrees like vertical louvres: the white front of each (toward the viewer at
    # -Z and toward +X) faces the coloured back of its neighbour, which the window lights.
    for i, (name, colour) in enumerate(colours):
        x = -0.6 + 0.3 * i
        # Thin along local X: after the turn, the +X face looks toward -Z and +X (the viewer and the
        # next board), the -X face toward +Z and -X (the window and the previous board).
        faces = box_faces([x, 0.5, 0.0], [0.02, 1.0, 0.4], rotation_y=math.radians(45))
        coloured = g.material(name, colour)
        g.node("board_%d_white" % i, g.mesh("board_%d_white" % i, [faces["+x"], faces["+z"], faces["-z"],
                                                                   faces["+y"], faces["-y"]], white))
        g.node("board_%d_%s" % (i, name), g.mesh("board_%d_%s" % (i, name), [faces["-x"]], coloured))
    win = [[-1.2, 0.1, 1.4], [-1.2, 1.5, 1.4], [1.2, 1.5, 1.4], [1.2, 0.1, 1.4]]
    g.node("window", g.mesh("window", [facing(win, [0, 0.7, 0])], window))
    cam = g.camera("camera", yfov=math.radians(40), aspect=1.5)
    g.node("camera", camera=cam, translation=[0.0, 0.9, -2.6], rotation=[0, 1, 0, 0])
    out = os.path.join(HERE, "ferren")
    os.makedirs(out, exist_ok=True)
    g.save(os.path.join(out, "ferren.gltf"), bin_name="ferren.bin")


def study_room():
    g = Gltf("radbake samples/make_samples.py")
    plaster = g.material("plaster", (0.75, 0.73, 0.7))
    floor = g.material("oak", (0.45, 0.3, 0.18))
    wood = g.material("walnut", (0.3, 0.2, 0.12))
    blue = g.material("blue_paint", (0.15, 0.25, 0.6))
    # An overcast window: luminance 2500 cd/m2 over 1.6 x 1.2 m.
    sky = g.material("window", (0.0, 0.0, 0.0), emissive=(0.9, 0.95, 1.0), strength=2500.0)
    inside = [2.0, 1.3, 1.5]
    room = {
        "floor": (floor, [[0, 0, 0], [4, 0, 0], [4, 0, 3], [0, 0, 3]]),
        "ceiling": (plaster, [[0, 2.6, 0], [4, 2.6, 0], [4, 2.6, 3], [0, 2.6, 3]]),
        "wall_south": (plaster, [[0, 0, 0], [4, 0, 0], [4, 2.6, 0], [0, 2.6, 0]]),
        "wall_north": (blue, [[0, 0, 3], [4, 0, 3], [4, 2.6, 3], [0, 2.6, 3]]),
        "wall_west": (plaster, [[0, 0, 0], [0, 0, 3], [0, 2.6, 3], [0, 2.6, 0]]),
        "wall_east": (plaster, [[4, 0, 0], [4, 0, 3], [4, 2.6, 3], [4, 2.6, 0]]),
    }
    for name, (material, poly) in room.items():
        g.node(name, g.mesh(name, [facing(poly, inside)], material))
    win = [[3.999, 0.9, 0.7], [3.999, 2.1, 0.7], [3.999, 2.1, 2.3], [3.999, 0.9, 2.3]]
    g.node("window", g.mesh("window", [facing(win, inside)], sky))
    table = box_faces([2.2, 0.72, 1.4], [1.4, 0.06, 0.8])
    g.node("table_top", g.mesh("table_top", list(table.values()), wood))
    for i, (x, z) in enumerate([(1.55, 1.05), (2.85, 1.05), (1.55, 1.75), (2.85, 1.75)]):
        leg = box_faces([x, 0.345, z], [0.06, 0.69, 0.06])
        g.node("table_leg_%d" % i, g.mesh("table_leg_%d" % i, [leg[k] for k in ("+x", "-x", "+z", "-z")], wood))
    # The bookcase's back stands 2 cm off the west wall: the gap behind it is dark.
    case = box_faces([0.22, 1.0, 1.2], [0.4, 2.0, 1.2])
    g.node("bookcase", g.mesh("bookcase", [case[k] for k in ("+x", "-x", "+y", "+z", "-z")], wood))
    g.node("lamp", extensions=g.light("lamp", "point", 150.0, color=(1.0, 0.9, 0.75)), translation=[1.2, 2.3, 2.2])
    out = os.path.join(HERE, "study_room")
    os.makedirs(out, exist_ok=True)
    g.save(os.path.join(out, "study_room.gltf"), bin_name="study_room.bin")


def classroom(overhang=True):
    """The classroom; overhang=False: the design variant without the 1 m slab over the windows."""
    g = Gltf("radbake samples/make_samples.py")
    plaster = g.material("plaster", (0.7, 0.68, 0.64))
    ceiling = g.material("ceiling_tiles", (0.8, 0.8, 0.78))
    floor = g.material("linoleum", (0.35, 0.3, 0.25))
    board = g.material("blackboard", (0.06, 0.12, 0.08))
    wood = g.material("desk_laminate", (0.55, 0.42, 0.28))
    concrete = g.material("concrete", (0.45, 0.45, 0.43), double_sided=True)
    # Clear double glazing: the pane lets 70% of the light through (extras.visible_transmittance).
    glass = g.material("glazing", (0.9, 0.9, 0.9), transmission=1.0, extras={"visible_transmittance": 0.7},
                       double_sided=True)
    width, depth, height = 9.0, 7.0, 3.0
    sill, head = 0.9, 2.5
    windows = [(0.75, 2.75), (3.5, 5.5), (6.25, 8.25)]  # x ranges, 2 m wide each
    inside = [width / 2, height / 2, depth / 2]
    room = {
        "floor": (floor, [[0, 0, 0], [width, 0, 0], [width, 0, depth], [0, 0, depth]]),
        "ceiling": (ceiling, [[0, height, 0], [width, height, 0], [width, height, depth], [0, height, depth]]),
        "wall_north": (plaster, [[0, 0, 0], [width, 0, 0], [width, height, 0], [0, height, 0]]),
        "wall_west": (plaster, [[0, 0, 0], [0, 0, depth], [0, height, depth], [0, height, 0]]),
        "wall_east": (plaster, [[width, 0, 0], [width, 0, depth], [width, height, depth], [width, height, 0]]),
    }
    for name, (material, poly) in room.items():
        g.node(name, g.mesh(name, [facing(poly, inside)], material))
    # The south wall around its openings: the band under the sills, the band over the heads and
    # the piers between the windows.
    z = depth
    south = [[[0, 0, z], [width, 0, z], [width, sill, z], [0, sill, z]],
             [[0, head, z], [width, head, z], [width, height, z], [0, height, z]]]
    edges = [0.0] + [x for pair in windows for x in pair] + [width]
    for a, b in zip(edges[0::2], edges[1::2]):
        south.append([[a, sill, z], [b, sill, z], [b, head, z], [a, head, z]])
    g.node("wall_south", g.mesh("wall_south", [facing(p, inside) for p in south], plaster))
    for i, (a, b) in enumerate(windows):
        pane = [[a, sill, z], [b, sill, z], [b, head, z], [a, head, z]]
        g.node("window_%d" % i, g.mesh("window_%d" % i, [facing(pane, inside)], glass))
    # The overhang: a 1 m concrete slab outside, level with the ceiling, the whole wall long.
    slab = [[0, height, z], [width, height, z], [width, height, z + 1.0], [0, height, z + 1.0]]
    if overhang:
        g.node("overhang", g.mesh("overhang", [facing(slab, [width / 2, 0, z + 0.5])], concrete))
    g.node("blackboard", g.mesh("blackboard", [facing([[2.5, 0.9, 0.01], [6.5, 0.9, 0.01], [6.5, 2.1, 0.01],
                                                        [2.5, 2.1, 0.01]], inside)], board))
    # Twelve desks in four rows facing the blackboard, 1.2 x 0.6 m tops at 0.72 m on four legs.
    for row in range(4):
        for col in range(3):
            x, zc = 1.8 + 2.7 * col, 2.0 + 1.3 * row
            name = "desk_%d_%d" % (row, col)
            top = box_faces([x, 0.71, zc], [1.2, 0.04, 0.6])
            g.node(name, g.mesh(name, list(top.values()), wood))
            legs = []
            for dx in (-0.55, 0.55):
                for dz in (-0.25, 0.25):
                    leg = box_faces([x + dx, 0.345, zc + dz], [0.04, 0.69, 0.04])
                    legs += [leg[k] for k in ("+x", "-x", "+z", "-z")]
            g.node(name + "_legs", g.mesh(name + "_legs", legs, wood))
    out = os.path.join(HERE, "classroom")
    os.makedirs(out, exist_ok=True)
    name = "classroom" if overhang else "classroom_no_overhang"
    g.save(os.path.join(out, name + ".gltf"), bin_name=name + ".bin")


if __name__ == "__main__":
    classroom()
    classroom(overhang=False)
    cornell_box()
    ferren()
    study_room()
