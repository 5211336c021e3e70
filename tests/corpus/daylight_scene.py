#!/usr/bin/env python3
"""A corpus building's daylight run (`--sky cie-overcast --daylight-factor
--work-plane`, nothing else): a map and a statistics block per storey, a row per room in
work_plane_rooms.csv and report.json, and no point outdoors. Outdoors is checked against the
building's own walls (corpus.json's walls_bounds_m, the box of the nodes named as walls): every
work-plane point lies inside it; under an overcast sky a point outside would read a daylight
factor near 100%, one under the eaves 40% or more.

usage: daylight_scene.py RADBAKE CORPUS_DIR SCENE OUT_DIR STOREYS
"""
import csv
import json
import os
import subprocess
import sys


def main():
    radbake, corpus, name, out, storeys = sys.argv[1:6]
    scene = next(s for s in json.load(open(os.path.join(corpus, "corpus.json")))["scenes"] if s["name"] == name)
    folder = os.path.join(out, name + "_daylight")
    run = subprocess.run([radbake, "bake", os.path.join(corpus, scene["file"]), "-o", folder, "--sky", "cie-overcast",
                          "--daylight-factor", "--work-plane"], capture_output=True, text=True)
    print(run.stderr[-3000:])
    if run.returncode != 0:
        sys.exit(f"{name}: radbake bake exited {run.returncode}")
    failures = []
    plane = json.load(open(os.path.join(folder, "report.json")))["work_plane"]
    if len(plane["storeys"]) != int(storeys):
        failures.append(f"{len(plane['storeys'])} storeys, not {storeys}")
    rooms = [r for s in plane["storeys"] for r in s["rooms"]]
    for s in plane["storeys"]:
        for m in s["maps"]:
            if not os.path.getsize(os.path.join(folder, m)) > 0:
                failures.append(f"storey {s['storey']}: no {m}")
        if not s["rooms"]:
            failures.append(f"storey {s['storey']} has no room")
        # The storey's points are its rooms' points.
        if sum(r["points"] for r in s["rooms"]) != s["points"]:
            failures.append(f"storey {s['storey']}: rooms hold {sum(r['points'] for r in s['rooms'])} of {s['points']} points")
    with open(os.path.join(folder, "work_plane_rooms.csv")) as f:
        table = list(csv.DictReader(f))
    if len(table) != len(rooms):
        failures.append(f"work_plane_rooms.csv has {len(table)} rows for {len(rooms)} rooms")
    for row, room in zip(table, rooms):
        if int(row["points"]) != room["points"] or abs(float(row["daylight_factor_mean_percent"]) -
                                                       room["daylight_factor_percent"]["mean"]) > 1e-3 * room["daylight_factor_percent"]["mean"] + 1e-3:
            failures.append(f"work_plane_rooms.csv row {row} disagrees with report.json {room}")
    lo, hi = scene["walls_bounds_m"]["min"], scene["walls_bounds_m"]["max"]
    with open(os.path.join(folder, "sensors.csv")) as f:
        points = list(csv.DictReader(f))
    outside = [p for p in points if not (lo[0] < float(p["x"]) < hi[0] and lo[2] < float(p["z"]) < hi[2])]
    print(f"{name}: {len(plane['storeys'])} storeys, {len(rooms)} rooms, {len(points)} points, {len(outside)} outside "
          f"the walls; daylight factor mean {plane['daylight_factor_percent']['mean']:.2f}%, "
          f"max {plane['daylight_factor_percent']['max']:.1f}%; {plane['outdoor_points_left_out']} left out as outdoors")
    if outside:
        failures.append(f"{len(outside)} work-plane points outside the walls, e.g. {outside[:3]}")
    if failures:
        sys.exit(f"{name}: " + "\n  ".join(failures))


if __name__ == "__main__":
    main()
