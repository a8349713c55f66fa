"""The repository cites the literature, not design notes that live outside it.

usage: /usr/bin/python3 test_references.py [MPMCUT_BINARY SCRATCH_DIR]   (both ignored: no binary is run)
Checks, over the tracked files under src/, tests/, tools/, docs/, materials/, cases/, data/ and README.md
(this file excepted):
  1. no file cites the project's outside notes (algorithms.md, ti64_data.md, anchors.md,
     ti64_forces_klippel2024.md) or a path into a shared/ directory: a reader of the repository cannot
     follow them; cite the work itself and its entry in docs/references.md;
  2. every reference key such as [Sulsky1994] used in src/, docs/ and README.md is defined in
     docs/references.md, and no key is defined twice.
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SELF = os.path.relpath(os.path.abspath(__file__), ROOT).replace(os.sep, "/")
SCANNED = ("src/", "tests/", "tools/", "docs/", "materials/", "cases/", "data/", "README.md")
KEY_SCOPE = ("src/", "docs/", "README.md")
REFERENCES = "docs/references.md"

FORBIDDEN = re.compile(r"algorithms\.md|ti64_data|anchors\.md|ti64_forces_klippel2024\.md|(?<![A-Za-z0-9_])shared/")
# A key: starts with a capital, has at least one lower-case letter, letters and digits only ([Sulsky1994],
# [NLopt]); the tags [V], [A], [M], [M-lo] and all-capital words such as [TOML] are not keys; neither is a
# Markdown link text followed by "(".
KEY_USE = re.compile(r"\[([A-Z][A-Za-z0-9]*[a-z][A-Za-z0-9]*)\](?!\()")
KEY_DEF = re.compile(r"^- \*\*\[([A-Za-z0-9]+)\]\*\*", re.MULTILINE)


def tracked_files():
    try:
        out = subprocess.run(["git", "-C", ROOT, "ls-files", "-z"], capture_output=True, check=True).stdout
        files = [f for f in out.decode("utf-8").split("\0") if f]
    except (OSError, subprocess.CalledProcessError):
        files = []  # not a git checkout (e.g. a copied tree): walk the directories instead
        for top in SCANNED:
            path = os.path.join(ROOT, top)
            if os.path.isfile(path):
                files.append(top)
            for d, _, names in os.walk(path):
                files += [os.path.relpath(os.path.join(d, n), ROOT).replace(os.sep, "/") for n in names]
    return sorted(f for f in files if f.startswith(SCANNED) and f != SELF)


def read_text(rel):
    try:
        with open(os.path.join(ROOT, rel), "rb") as f:
            data = f.read()
    except OSError:
        return None  # listed by git but deleted in the work tree
    if b"\0" in data:
        return None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return None  # binary (images)


def main():
    errors = []
    files = tracked_files()
    if not any(f.startswith("src/") for f in files):
        errors.append(f"no source files found under {ROOT}")

    with open(os.path.join(ROOT, REFERENCES), encoding="utf-8") as f:
        defined_list = KEY_DEF.findall(f.read())
    defined = set(defined_list)
    if len(defined) < 20:
        errors.append(f"{REFERENCES}: only {len(defined)} keys found; the entry format is '- **[Key]** ...'")
    for key in sorted(defined):
        if defined_list.count(key) > 1:
            errors.append(f"{REFERENCES}: [{key}] is defined {defined_list.count(key)} times")

    scanned = 0
    for rel in files:
        text = read_text(rel)
        if text is None:
            continue
        scanned += 1
        for lineno, line in enumerate(text.splitlines(), 1):
            for m in FORBIDDEN.finditer(line):
                errors.append(f"{rel}:{lineno}: cites '{m.group(0)}', which is outside the repository: "
                              f"cite the work itself (docs/references.md)")
            if rel.startswith(KEY_SCOPE):
                for key in KEY_USE.findall(line):
                    if key not in defined:
                        errors.append(f"{rel}:{lineno}: [{key}] is not defined in {REFERENCES}")

    for e in errors:
        print(e)
    print(f"{scanned} files scanned, {len(defined)} keys in {REFERENCES}, {len(errors)} problem(s)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
