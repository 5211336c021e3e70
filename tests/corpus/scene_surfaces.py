#!/usr/bin/env python3
"""One corpus scene's surfaces against its stored path-traced reference.

The reference (tests/fixtures/SCENE_surfaces_reference.csv, made by `./dev surfaces-reference
SCENE` on the same atlas at seed 1, as these bakes are) holds each surface's area-weighted mean
illuminance and its standard error. Every surface of at least 1 m2 that the path tracer finds lit
(its mean at least LIT_SHARE of the whole scene's, area-weighted: fainter, its light is a few rare
paths and no user reads it) must come within its preset's bound of the reference's mean, plus
twice the reference's standard error (what its own noise may put between them at 95%); and the
area-weighted mean of those surfaces' |bias| within the preset's bound on it, plus the same
allowance area-weighted. Bounds: at --quality production 3% on each surface and 1% on the mean
|bias|; at the defaults 5% and 2%. The defaults' bake is corpus.bake.SCENE's, read from OUT_DIR.

usage: scene_surfaces.py RADBAKE CORPUS_DIR OUT_DIR SCENE REFERENCE_CSV
"""
import json
import os
import subprocess
import sys

from bake_scene import corpus_scene
from interior_surfaces import keyed, read_reference

# (label, bake options or None for corpus.bake's, bound on each surface, bound on the mean |bias|)
PRESETS = [("production", ["--quality", "production"], 0.03, 0.01), ("the defaults", None, 0.05, 0.02)]
SMALLEST_M2 = 1.0
LIT_SHARE = 0.01


def held(label, report, reference, surface_bound, mean_bound):
    """What fails of one bake against the reference (a list of lines)."""
    baked = keyed(report)
    missing = [k[0] for k in reference if k not in baked]
    if missing:
        return [f"{label}: {len(missing)} surfaces of the reference are not in the bake, e.g. {missing[0]} "
                "(the atlas or the texels changed: make the reference again, ./dev surfaces-reference SCENE)"]
    area = lambda k: float(reference[k]["area_m2"])
    lux = lambda k: float(reference[k]["mean_lx"])
    scene_mean = sum(area(k) * lux(k) for k in reference) / sum(area(k) for k in reference)
    checked = [k for k in reference if area(k) >= SMALLEST_M2 and lux(k) >= LIT_SHARE * scene_mean]
    failures, weighted_bias, weighted_noise, total_area = [], 0.0, 0.0, 0.0
    for k in sorted(checked, key=lambda k: -area(k)):
        noise = 2 * float(reference[k]["standard_error_lx"]) / lux(k)
        bias = baked[k]["mean_lx"] / lux(k) - 1
        weighted_bias += area(k) * abs(bias)
        weighted_noise += area(k) * noise
        total_area += area(k)
        print(f"  {k[0][:60]:60s} {area(k):8.1f} m2 {lux(k):9.2f} lx {bias:+.2%} (bound {surface_bound + noise:.2%})")
        if abs(bias) > surface_bound + noise:
            failures.append(f"{label}: {k[0]} ({area(k):.1f} m2, {lux(k):.1f} lx) reads {bias:+.2%} of the reference, "
                            f"past {surface_bound:.0%} + {noise:.2%}")
    if not checked:
        return [f"{label}: no surface of at least {SMALLEST_M2:g} m2 is lit in the reference"]
    mean_bias, allowance = weighted_bias / total_area, weighted_noise / total_area
    print(f"{label}: {len(checked)} surfaces, area-weighted mean |bias| {mean_bias:.2%} (bound {mean_bound:.0%} + {allowance:.2%})")
    if mean_bias > mean_bound + allowance:
        failures.append(f"{label}: the area-weighted mean |bias| is {mean_bias:.2%}, past {mean_bound:.0%} + {allowance:.2%}")
    return failures


def main():
    radbake, corpus, out, name, reference_csv = sys.argv[1:6]
    scene = corpus_scene(corpus, name)
    reference = read_reference(reference_csv)
    failures = []
    for label, options, surface_bound, mean_bound in PRESETS:
        folder = os.path.join(out, name if options is None else f"{name}_surfaces_{label}")
        if options is not None:
            run = subprocess.run([radbake, "bake", os.path.join(corpus, scene["file"]), "-o", folder, "--quiet", *options],
                                 capture_output=True, text=True)
            if run.returncode != 0:
                sys.exit(f"radbake bake ({label}) exited {run.returncode}: {run.stderr[-2000:]}")
        failures += held(label, json.load(open(os.path.join(folder, "report.json"))), reference, surface_bound, mean_bound)
    if failures:
        sys.exit("\n".join(failures))


if __name__ == "__main__":
    main()
