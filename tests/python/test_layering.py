"""The layers of src/ hold: a folder includes only folders below it (the layer order below, README "Layout").

usage: /usr/bin/python3 test_layering.py [MPMCUT_BINARY SCRATCH_DIR]   (both ignored: no binary is run)

Layer order, lowest first: core, physics, contact, thermal, solver, io, cutting, analysis, run, studies,
app, python. A `#include "X/..."` in src/Y/ with X above Y fails the test, except the crossings listed in
KNOWN below, which are the ones that existed when this check was written (issue 13 is to remove them). The
list may only shrink: a listed crossing that no longer exists fails the test too, so that it is taken off.
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ORDER = ["core", "physics", "contact", "thermal", "solver", "io", "cutting", "analysis", "run", "studies", "app",
         "python"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/', re.MULTILINE)

# (file, the layer it includes): crossings to remove (issue 13), not to add to.
KNOWN = set()


def crossings():
    found = set()
    src = os.path.join(ROOT, "src")
    for layer in sorted(os.listdir(src)):
        if layer not in ORDER:
            continue
        for folder, _, names in os.walk(os.path.join(src, layer)):
            for name in names:
                if not name.endswith((".hpp", ".cpp")):
                    continue
                path = os.path.join(folder, name)
                with open(path, encoding="utf-8") as f:
                    text = f.read()
                for included in set(INCLUDE.findall(text)):
                    if included in ORDER and ORDER.index(included) > ORDER.index(layer):
                        found.add((os.path.relpath(path, ROOT).replace(os.sep, "/"), included))
    return found


def main():
    found = crossings()
    new = sorted(found - KNOWN)
    gone = sorted(KNOWN - found)
    for f, layer in new:
        print(f"FAIL: {f} includes {layer}/, a layer above its own (DESIGN order: {' < '.join(ORDER)})")
    for f, layer in gone:
        print(f"FAIL: {f} no longer includes {layer}/: take it off KNOWN in {os.path.basename(__file__)}")
    print(f"layering: {len(found)} known crossings left, {len(new)} new, {len(gone)} gone")
    return 1 if new or gone else 0


if __name__ == "__main__":
    sys.exit(main())
