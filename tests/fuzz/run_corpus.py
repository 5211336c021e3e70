#!/usr/bin/env python3
"""Bakes every file of the hostile-input corpus and holds radbake to its promise on bad input:
each file either exits 0 with outputs the Khronos glTF-Validator finds no error in, or exits 2
with one line on stderr and writes nothing. Exit 1, a crash (a signal, a sanitizer report) or a
run past the timeout is a failure, listed by file with its exit status and stderr's first line.
Both files radbake writes are validated (NAME.gltf and NAME_display.glb), and the validator's warnings
(WATCHED_WARNINGS: what radbake repairs or drops) fail a file as errors do. The summary counts the
files whose every output validates clean: no error and no warning of any code.

usage: run_corpus.py RADBAKE VALIDATOR_SCRIPT FOLDER... [--jobs N] [--timeout SECONDS] [--prefix NAME.]
Run by ctest (tests/CMakeLists.txt), one case per source of the corpus (tests/fuzz/corpus, by file
name prefix) and one for the fuzzer's findings (tests/fuzz/findings).
"""
import argparse
import concurrent.futures
import json
import os
import shutil
import subprocess
import sys
import tempfile

# Small bakes: the corpus tests what radbake accepts and writes, not the light.
BAKE_OPTIONS = ["--max-page-size", "64", "--quality", "draft", "--gather-rays", "16", "--patch-rays", "64",
                "--threads", "1"]
SANITIZER_MARKS = ("ERROR: AddressSanitizer", "ERROR: LeakSanitizer", "runtime error:")
# Validator warnings about what radbake copies from its input and must repair or drop
# (docs/hostile_input.md); its errors all fail a file.
WATCHED_WARNINGS = ("IMAGE_UNRECOGNIZED_FORMAT", "NODE_SKINNED_MESH_WITHOUT_SKIN", "MULTIPLE_EXTENSIONS",
                    "IMAGE_FEATURES_UNSUPPORTED")


def corpus_files(folders, prefix):
    files = []
    for folder in folders:
        files += [os.path.join(folder, f) for f in sorted(os.listdir(folder))
                  if f.endswith((".gltf", ".glb")) and f.startswith(prefix)]
    return files


def bake(radbake, file, scratch, timeout):
    """(file, status, stderr, output folder); status is the exit code, 'signal N' or 'timeout'."""
    out = os.path.join(scratch, os.path.basename(file) + ".out")
    try:
        r = subprocess.run([radbake, "bake", file, "-o", out] + BAKE_OPTIONS, stdin=subprocess.DEVNULL,
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=timeout)
        status = r.returncode if r.returncode >= 0 else f"signal {-r.returncode}"
        return file, status, r.stderr.decode(errors="replace"), out
    except subprocess.TimeoutExpired as e:
        return file, "timeout", (e.stderr or b"").decode(errors="replace"), out


def first_lines(stderr):
    """stderr's first line, and a sanitizer's verdict when there is one further down."""
    lines = stderr.splitlines()
    shown = lines[0] if lines else "(no output on stderr)"
    for line in lines[1:]:
        if any(mark in line for mark in SANITIZER_MARKS):
            return f"{shown} | {line.strip()}"
    return shown


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("radbake")
    parser.add_argument("validator")
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--prefix", default="", help="only files whose name starts with this")
    args = parser.parse_args()

    files = corpus_files(args.folders, args.prefix)
    if not files:
        print("run_corpus: no corpus files found", file=sys.stderr)
        return 1
    if not os.path.isdir(os.path.join(os.path.dirname(args.validator), "node_modules", "gltf-validator")):
        print("run_corpus: the validator is not installed: run ./dev test (npm ci in tests/tools)", file=sys.stderr)
        return 1
    failures, validated, refused = [], [], 0
    scratch = tempfile.mkdtemp(prefix="radbake_corpus_")
    try:
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            runs = pool.map(lambda f: bake(args.radbake, f, scratch, args.timeout), files)
            for file, status, stderr, out in runs:
                name = os.path.basename(file)
                if status == 0:
                    stem = os.path.join(out, os.path.splitext(name)[0])
                    if os.path.isfile(stem + ".gltf"):
                        validated.append((name, [stem + ".gltf"] + [stem + "_display.glb"] * os.path.isfile(stem + "_display.glb")))
                    else:
                        failures.append(f"{name}: exit 0 but no {os.path.basename(stem)}.gltf written")
                elif status == 2:
                    lines = stderr.splitlines()
                    if len(lines) != 1 or not lines[0].startswith("radbake: error: "):
                        failures.append(f"{name}: exit 2 with {len(lines)} lines on stderr: {first_lines(stderr)}")
                    elif "tinygltf" in lines[0]:  # a refusal is in radbake's words, at a JSON pointer
                        failures.append(f"{name}: refused in tinygltf's words: {first_lines(stderr)}")
                    elif os.path.exists(out):
                        failures.append(f"{name}: exit 2 but the output folder was written")
                    else:
                        refused += 1
                else:
                    failures.append(f"{name}: exit {status}: {first_lines(stderr)}")

        outputs = [(name, g) for name, gs in validated for g in gs]
        clean = set(name for name, _ in validated)
        if outputs:
            v = subprocess.run(["node", args.validator] + [g for _, g in outputs], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, timeout=60 + 10 * len(outputs))
            reports = [json.loads(line) for line in v.stdout.decode().splitlines() if line.startswith("{")]
            if len(reports) != len(outputs):
                failures.append(f"the validator reported on {len(reports)} of {len(outputs)} outputs: "
                                f"{v.stderr.decode(errors='replace').strip()[:500]}")
            for (name, gltf), report in zip(outputs, reports):
                if report["errors"] > 0 or report["warnings"] > 0:
                    clean.discard(name)
                watched = [m for m in report["messages"] if m.split(" ")[0] in WATCHED_WARNINGS]
                if report["errors"] > 0 or watched:
                    failures.append(f"{name}: exit 0 but the validator finds {report['errors']} error(s) and "
                                    f"{len(watched)} watched warning(s) in {os.path.basename(gltf)}: " +
                                    "; ".join(report["messages"][:3]))
    finally:
        shutil.rmtree(scratch, ignore_errors=True)

    print(f"run_corpus: {len(files)} files: {len(validated)} baked and validated ({len(clean)} of them clean: no "
          f"validator error or warning in any output), {refused} refused with one line, {len(failures)} failures")
    for failure in failures:
        print("  FAIL " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
