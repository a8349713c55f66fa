"""docs/input.md lists the [[material]] keys exactly as the physics parameter tables declare them.

usage: /usr/bin/python3 test_input_keys_doc.py MPMCUT_BINARY [SCRATCH_DIR] [--fix]
The table between the markers "<!-- begin: mpmcut keys --markdown -->" and "<!-- end: mpmcut keys
--markdown -->" in docs/input.md must be the output of `mpmcut keys --markdown`, which is made from the
tables in src/physics/*_parameters.hpp (the one source of truth). When a parameter is added or changed
there, this test fails until the document is regenerated: run it with --fix (or paste the output).
"""
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DOC = os.path.join(ROOT, "docs", "input.md")
BEGIN = "<!-- begin: mpmcut keys --markdown -->\n"
END = "<!-- end: mpmcut keys --markdown -->\n"


def main():
    binary = sys.argv[1]
    generated = subprocess.run([binary, "keys", "--markdown"], check=True, capture_output=True, text=True).stdout
    with open(DOC, encoding="utf-8") as f:
        text = f.read()
    if BEGIN not in text or END not in text:
        print(f"FAIL: docs/input.md has no '{BEGIN.strip()}' ... '{END.strip()}' section")
        return 1
    head, rest = text.split(BEGIN, 1)
    documented, tail = rest.split(END, 1)
    if documented == generated:
        print(f"input keys doc: {generated.count(chr(10)) - 2} [[material]] keys, as the parameter tables declare them")
        return 0
    if "--fix" in sys.argv:
        with open(DOC, "w", encoding="utf-8") as f:
            f.write(head + BEGIN + generated + END + tail)
        print("docs/input.md: the [[material]] key table regenerated")
        return 0
    doc_lines, gen_lines = documented.splitlines(), generated.splitlines()
    for i in range(max(len(doc_lines), len(gen_lines))):
        d = doc_lines[i] if i < len(doc_lines) else "(nothing)"
        g = gen_lines[i] if i < len(gen_lines) else "(nothing)"
        if d != g:
            print(f"FAIL: docs/input.md differs from `mpmcut keys --markdown` at table line {i + 1}:\n"
                  f"  documented: {d}\n  generated:  {g}")
            break
    print(f"regenerate it: /usr/bin/python3 {os.path.relpath(__file__, ROOT)} {binary} --fix")
    return 1


if __name__ == "__main__":
    sys.exit(main())
