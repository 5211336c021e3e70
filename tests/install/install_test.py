#!/usr/bin/python3
"""radbake as a user installs it: `cmake --install` into a fresh prefix, and the Debian
package `cpack -G DEB` makes, unpacked into a clean folder; from each, `radbake bake` the Cornell
box and `radbake view` it in headless Chromium with no console error, its three.js served from the
install's share/radbake. A radbake copied away from its share folder refuses `view` in one line.

  install_test.py BUILD_DIR SOURCE_DIR WORK_DIR [--deb]
"""
import json
import os
import re
import shutil
import subprocess
import sys
import urllib.request

build, source, work = sys.argv[1:4]
deb = "--deb" in sys.argv[4:]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL: " + message, file=sys.stderr)


def bake_and_view(radbake, label):
    out = os.path.join(work, label + "_out")
    shutil.rmtree(out, ignore_errors=True)
    subprocess.run([radbake, "bake", os.path.join(source, "samples", "cornell_box", "cornell_box.gltf"), "-o", out,
                    "--max-page-size", "128", "--quiet"], check=True)
    check(os.path.isfile(os.path.join(out, "cornell_box.gltf")), label + ": bake wrote no glTF")
    server = subprocess.Popen([radbake, "view", out, "--no-open"], stdout=subprocess.PIPE, text=True)
    try:
        line = server.stdout.readline()
        match = re.search(r"http://\S+", line)
        check(match is not None, label + ": view printed no address: " + line)
        if not match:
            return
        url = match.group(0)
        # three.js comes from the install: the same bytes as the pinned copy it was installed from.
        served = urllib.request.urlopen(url + "three/build/three.module.js").read()
        pinned = open(os.path.join(source, "web", "node_modules", "three", "build", "three.module.js"), "rb").read()
        check(served == pinned, label + ": three.module.js served differs from web/node_modules'")
        page = subprocess.run(["node", os.path.join(source, "tests", "web", "viewer_modes.mjs"), url, "320", "240",
                               json.dumps([{"mode": "lightmap", "pixels": [[160, 120]]}])],
                              capture_output=True, text=True, timeout=240)
        check(page.returncode == 0, label + ": the page did not load: " + page.stderr[-2000:])
        if page.returncode == 0:
            result = json.loads(page.stdout.strip().splitlines()[-1])
            check(result["consoleErrors"] == [], label + ": console errors: " + json.dumps(result["consoleErrors"]))
            rgb = result["steps"][0]["pixels"][0]["rgb"]
            check(max(rgb[:3]) > 0, label + ": the view's centre is black: " + json.dumps(rgb))
    finally:
        server.terminate()
        server.wait()


def lone_copy_refuses():
    # Away from any share folder, view says where it looked and what to do, and exits non-zero.
    lone = os.path.join(work, "lone", "bin")
    os.makedirs(lone, exist_ok=True)
    shutil.copy(os.path.join(build, "radbake"), lone)
    out = os.path.join(work, "install_out")
    r = subprocess.run([os.path.join(lone, "radbake"), "view", out, "--no-open"], capture_output=True, text=True, timeout=60)
    check(r.returncode != 0, "a radbake without its share folder served the viewer")
    lines = [l for l in r.stderr.splitlines() if l.strip()]
    check(len(lines) == 1 and "share/radbake" in lines[0] and "cmake --install" in lines[0],
          "the refusal is not one line naming where it looked: " + r.stderr)


os.makedirs(work, exist_ok=True)
if deb:
    packages = os.path.join(work, "packages")
    shutil.rmtree(packages, ignore_errors=True)
    subprocess.run(["cpack", "-G", "DEB", "--config", os.path.join(build, "CPackConfig.cmake"), "-B", packages],
                   check=True, stdout=subprocess.DEVNULL)
    debs = [f for f in os.listdir(packages) if f.endswith(".deb")]
    check(len(debs) == 1, "cpack made no single .deb: " + " ".join(os.listdir(packages)))
    root = os.path.join(work, "deb_root")
    shutil.rmtree(root, ignore_errors=True)
    subprocess.run(["dpkg-deb", "-x", os.path.join(packages, debs[0]), root], check=True)
    control = subprocess.run(["dpkg-deb", "-f", os.path.join(packages, debs[0]), "Depends"], capture_output=True,
                             text=True, check=True).stdout
    check("libembree" in control and "libopenexr" in control.lower() and "libpng" in control.lower(), "the package's Depends lacks its libraries: " + control)
    for path in ["usr/bin/radbake", "usr/share/radbake/web/viewer/index.html", "usr/share/radbake/web/three/build/three.module.js",
                 "usr/share/radbake/web/radbake-lightmap.js", "usr/share/radbake/web/gltf-transform.config.mjs",
                 "usr/share/radbake/radbake_blender_addon.zip"]:
        check(os.path.isfile(os.path.join(root, path)), "the package lacks " + path)
    bake_and_view(os.path.join(root, "usr", "bin", "radbake"), "deb")
else:
    prefix = os.path.join(work, "prefix")
    shutil.rmtree(prefix, ignore_errors=True)
    subprocess.run(["cmake", "--install", build, "--prefix", prefix], check=True, stdout=subprocess.DEVNULL)
    for path in ["bin/radbake", "share/radbake/web/viewer/index.html", "share/radbake/web/three/build/three.module.js",
                 "share/radbake/radbake_blender_addon.zip"]:
        check(os.path.isfile(os.path.join(prefix, path)), "the install lacks " + path)
    bake_and_view(os.path.join(prefix, "bin", "radbake"), "install")
    lone_copy_refuses()

if failures:
    sys.exit(1)
print("ok")
