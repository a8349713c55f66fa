"""End to end: a cut whose material has a value in a wrong unit says so, where a user looks.

usage: /usr/bin/python3 test_input_plausibility.py MPMCUT_BINARY SCRATCH_DIR
Checks: `mpmcut run` of a tiny cut with the density in g/cm^3 still completes, but the console names the key and
the likely unit at the start, summary.json's `input_warnings` holds the same line, and a sweep's sweep.csv message
carries it, and so does `mpmcut run --check`; the same cut with the density in kg/m^3 has an empty `input_warnings` and no such line.
"""
import csv
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_checks import fail  # noqa: E402

# Two cells of tool travel at h = 0.1 mm, 1 particle per cell: under a second.
CASE = """\
title = "a tiny Ti-6Al-4V cut"
[cutting]
material = "ti"
cutting_speed = 20.0
uncut_chip_thickness = 0.1e-3
cut_length = 50e-6
cell_size = 25e-6
particles_per_cell = 1
snapshots = 1
[[material]]
name = "ti"
library = "ti64-cutting"
density = {density}
"""


def run(binary, case, out):
    p = subprocess.run([binary, "run", case, "--out", out, "--no-plots", "--threads", "1"], capture_output=True,
                       text=True, timeout=120)
    if p.returncode != 0:
        fail(f"run {case}: exit {p.returncode}\n{p.stderr}")
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f), p.stderr


def main(binary, scratch):
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    cases = {}
    for label, density in (("good", "4430.0"), ("g_per_cm3", "4.43")):
        cases[label] = os.path.join(scratch, f"{label}.toml")
        with open(cases[label], "w") as f:
            f.write(CASE.format(density=density))

    summary, console = run(binary, cases["good"], os.path.join(scratch, "good"))
    if summary.get("input_warnings") != []:
        fail(f"a plausible material warns: {summary.get('input_warnings')!r}")
    if "density" in console:
        fail(f"the console names the density of a plausible material:\n{console}")

    summary, console = run(binary, cases["g_per_cm3"], os.path.join(scratch, "g_per_cm3"))
    if summary["status"] != "complete":
        fail(f"the warning stopped the run: {summary['status']}")
    warnings = summary.get("input_warnings", [])
    if len(warnings) != 1 or "density = 4.43 kg/m^3" not in warnings[0] or "g/cm^3" not in warnings[0]:
        fail(f"input_warnings: {warnings!r}")
    if f"warning: {warnings[0]}" not in console:
        fail(f"the console does not carry the warning:\n{console}")
    # At the start: before the first progress line.
    if console.index(warnings[0]) > console.find("progress:") >= 0:
        fail("the warning comes after the run started")

    # run --check, the pre-flight, says the same without running.
    p = subprocess.run([binary, "run", cases["g_per_cm3"], "--check"], capture_output=True, text=True, timeout=60)
    if p.returncode != 0 or f"warning: {warnings[0]}" not in p.stderr or "valid;" not in p.stdout:
        fail(f"run --check: exit {p.returncode}, does not carry the warning:\n{p.stdout}{p.stderr}")

    out = os.path.join(scratch, "sweep")
    p = subprocess.run([binary, "sweep", cases["g_per_cm3"], "--speeds", "20", "--jobs", "1", "--out", out,
                        "--no-plots"], capture_output=True, text=True, timeout=300)
    if p.returncode != 0:
        fail(f"sweep: exit {p.returncode}\n{p.stderr}")
    with open(os.path.join(out, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    if len(rows) != 1 or "density = 4.43 kg/m^3" not in rows[0]["message"]:
        fail(f"sweep.csv's message does not carry the warning: {rows!r}")
    print("input plausibility: OK")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
