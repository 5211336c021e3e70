#!/usr/bin/env python3
"""Every test that ctest lists has a name a reader can type (`ctest -R NAME` finds it again) and
one of the four labels a subset is chosen by (`ctest -L unit`: tests/CMakeLists.txt says which).

Fails on a name holding raw bytes or addresses (what Google Test prints for a parameter with no
name generator: "GetParam() = 16-byte object <52-EA ...>", "0x55d7..."), on a parameterised case
named by its index alone ("/0"), on names listed twice, and on a test with none of the labels.

usage: readable_names.py CTEST BUILD_DIR
"""
import re
import subprocess
import sys

UNREADABLE = [
    (re.compile(r"GetParam\(\)|TypeParam"), "a parameter's printed value"),
    (re.compile(r"byte object|<[0-9A-F]{2}-[0-9A-F]{2}"), "raw bytes"),
    (re.compile(r"0x[0-9a-fA-F]{4,}"), "an address"),
    (re.compile(r"[^A-Za-z0-9_./-]"), "a character -R would need quoting for"),
]


def main():
    ctest, build = sys.argv[1], sys.argv[2]
    listing = subprocess.run([ctest, "-N"], cwd=build, capture_output=True, text=True, check=True).stdout
    names = [m.group(1) for m in re.finditer(r"^\s*Test\s+#\d+: (.*)$", listing, re.M)]
    if len(names) < 100:
        sys.exit(f"ctest -N listed {len(names)} tests: expected the whole suite")
    problems = []
    for name in names:
        for pattern, what in UNREADABLE:
            if pattern.search(name):
                problems.append(f"{name}: {what}")
                break
        else:
            # A parameterised case (Prefix/Suite.Test/N) named by a bare number is named by its
            # index (its suite has no name generator); a number that is the parameter carries its unit.
            if re.match(r"^[^/]+/[^/]+\.[^/]+/\d+$", name):
                problems.append(f"{name}: named by a bare number, not its parameter")
    unlabelled = subprocess.run([ctest, "-N", "-LE", "^(unit|bake|client|slow)$"], cwd=build, capture_output=True,
                                text=True, check=True).stdout
    for m in re.finditer(r"^\s*Test\s+#\d+: (.*)$", unlabelled, re.M):
        problems.append(f"{m.group(1)}: none of the labels unit, bake, client, slow")
    seen = set()
    for name in names:
        if name in seen:
            problems.append(f"{name}: listed twice")
        seen.add(name)
    for p in problems:
        print(p)
    print(f"{len(names)} test names, {len(problems)} unreadable")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
