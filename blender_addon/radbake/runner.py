"""Running radbake: export the scene, start the bake as a subprocess, follow its progress."""
import os
import queue
import re
import shutil
import subprocess
import tempfile
import threading

import bpy

from . import compat

# radbake's stages in order, for one overall fraction from its per-stage progress lines.
STAGES = ["lightmap uvs", "elements", "sample placement", "direct light", "form factors",
          "radiosity", "final gather"]
PROGRESS = re.compile(r"^radbake: (.+) (\d+)%$")
# Blender's exporter turns lights into candela with 683 lm/W but leaves emission strength as it
# is: scaling emission by the same 683 keeps emitting surfaces as bright next to lamps as Cycles
# shows them.
LUMENS_PER_WATT = 683.0
EMISSION_SCALE = "%g" % LUMENS_PER_WATT


class BakeError(Exception):
    """A bake that did not happen, with radbake's own one-line reason."""


def find_executable(context):
    prefs = context.preferences.addons[__package__].preferences
    path = bpy.path.abspath(prefs.executable) if prefs.executable else shutil.which("radbake")
    if not path or not os.path.isfile(path) or not os.access(path, os.X_OK):
        raise BakeError("radbake executable not found: set its path in the add-on preferences or put it on PATH"
                        if not prefs.executable else "radbake executable not found at " + path)
    return path


class Bake:
    """One bake: a temporary folder, the exported scene, the radbake process and its output."""

    def __init__(self, context):
        self.executable = find_executable(context)
        self.folder = tempfile.mkdtemp(prefix="radbake-blender-")
        self.scene_file = os.path.join(self.folder, "scene.glb")
        self.output = os.path.join(self.folder, "baked")
        self.process = None
        self.reader = None
        self.lines = queue.Queue()
        self.last_error = ""
        self.fraction = 0.0
        self.stage = "exporting"

    def export(self, context):
        options = compat.gltf_export_options()
        # The whole scene goes out: unselected objects still cast shadows and bounce light.
        result = bpy.ops.export_scene.gltf(filepath=self.scene_file, use_selection=False, **options)
        if 'FINISHED' not in result or not os.path.exists(self.scene_file):
            raise BakeError("Blender's glTF exporter did not write the scene")

    def command(self, settings):
        args = [self.executable, "bake", self.scene_file, "-o", self.output, "--solver", settings.solver,
                "--max-page-size", str(settings.max_page_size), "--emission-scale", EMISSION_SCALE]
        if settings.texel_density > 0:
            args += ["--density", "%g" % settings.texel_density]
        return args + ["--quality", settings.quality.lower()]

    def start(self, settings):
        self.process = subprocess.Popen(self.command(settings), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                        text=True, bufsize=1)
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        for line in self.process.stderr:
            self.lines.put(line.rstrip("\n"))
        self.lines.put(None)

    def poll(self):
        """Takes in the progress lines so far; True once radbake has finished (either way)."""
        done = False
        while True:
            try:
                line = self.lines.get_nowait()
            except queue.Empty:
                break
            if line is None:
                done = True
                continue
            match = PROGRESS.match(line)
            if match:
                stage, percent = match.group(1), int(match.group(2))
                index = STAGES.index(stage) if stage in STAGES else 0
                self.stage = stage
                self.fraction = (index + percent / 100.0) / len(STAGES)
            elif line.startswith("radbake: error: "):
                self.last_error = line[len("radbake: error: "):]
        return done and self.process.poll() is not None

    def wait(self):
        self.process.wait()
        self.reader.join()
        self.poll()

    def check(self):
        code = self.process.wait()
        if code != 0:
            raise BakeError(self.last_error or "radbake failed (exit status %d)" % code)

    def cancel(self):
        if self.process and self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()

    def cleanup(self):
        self.cancel()
        shutil.rmtree(self.folder, ignore_errors=True)
