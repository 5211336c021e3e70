"""Where to hang lamps in a game level that keeps no player starts: points over its floors, spread
as far apart as they go (samples/corpus/make_corpus.py; the standard library only).

A floor is an upward-facing triangle (its normal within 25 degrees of up) of at least a square
metre with nothing over its centre for HEADROOM metres: room to stand. The first point is the
floor nearest the middle of them all; each next one the floor farthest from every point already
taken (farthest-point sampling), so the lamps spread over the whole level, upper floors included,
the same way every time.
"""
import math

UP = math.cos(math.radians(25))
SMALLEST_FLOOR_M2 = 1.0
HEADROOM = 2.0
CELL = 4.0  # metres: the grid the vertical rays look triangles up in


def floor_points(triangles, count):
    """`count` points on floors of `triangles` (world-space corner triples, metres, Y up)."""
    grid = {}
    for k, corners in enumerate(triangles):
        xs, zs = [p[0] for p in corners], [p[2] for p in corners]
        for gx in range(math.floor(min(xs) / CELL), math.floor(max(xs) / CELL) + 1):
            for gz in range(math.floor(min(zs) / CELL), math.floor(max(zs) / CELL) + 1):
                grid.setdefault((gx, gz), []).append(k)

    def covered(x, y, z):
        """Whether a surface lies over (x, z) between y and y + HEADROOM."""
        for k in grid.get((math.floor(x / CELL), math.floor(z / CELL)), ()):
            a, b, c = triangles[k]
            d = (b[2] - c[2]) * (a[0] - c[0]) + (c[0] - b[0]) * (a[2] - c[2])
            if d == 0:
                continue
            u = ((b[2] - c[2]) * (x - c[0]) + (c[0] - b[0]) * (z - c[2])) / d
            v = ((c[2] - a[2]) * (x - c[0]) + (a[0] - c[0]) * (z - c[2])) / d
            if u >= 0 and v >= 0 and u + v <= 1 and y < u * a[1] + v * b[1] + (1 - u - v) * c[1] < y + HEADROOM:
                return True
        return False

    floors = []
    for a, b, c in triangles:
        e1, e2 = [b[i] - a[i] for i in range(3)], [c[i] - a[i] for i in range(3)]
        n = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
        twice_area = math.sqrt(sum(x * x for x in n))
        centre = [(a[i] + b[i] + c[i]) / 3 for i in range(3)]
        if twice_area >= 2 * SMALLEST_FLOOR_M2 and n[1] >= UP * twice_area and not covered(centre[0], centre[1] + 0.01, centre[2]):
            floors.append(centre)
    if not floors:
        return []
    middle = [(min(p[i] for p in floors) + max(p[i] for p in floors)) / 2 for i in range(3)]
    chosen = [min(floors, key=lambda p: math.dist(p, middle))]
    nearest = [math.dist(p, chosen[0]) for p in floors]
    while len(chosen) < min(count, len(floors)):
        k = max(range(len(floors)), key=nearest.__getitem__)
        chosen.append(floors[k])
        nearest = [min(d, math.dist(p, floors[k])) for d, p in zip(nearest, floors)]
    return chosen
