"""End to end: `mpmcut run` on a tiny elastic case, then every snapshot read back with meshio.

usage: /usr/bin/python3 test_vtu_meshio.py MPMCUT_BINARY SCRATCH_DIR
Checks: the run completes; the .pvd lists snapshots with increasing times, each of which exists;
every snapshot has summary.json's particle count, every expected array with the right shape,
finite values. Exits 77 (CTest's conventional "skipped" code, if SKIP_RETURN_CODE is set) only
when the binary has no `run` command at all.
"""
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_roundtrip_check import check_vtu  # noqa: E402

CASE = """\
title = "meshio round trip: a steel block sliding through empty space"

[grid]
cell_size = 0.01
min = [0.0, 0.0]
max = [0.1, 0.1]

[solver]
end_time = 2.0e-4

[[material]]
name = "steel"
model = "elastic"
density = 7800.0
youngs_modulus = 2.0e11
poisson_ratio = 0.3

[[body]]
name = "block"
material = "steel"
particles_per_cell = 2
velocity = [1.0, 0.5]
rectangle = { min = [0.03, 0.03], max = [0.07, 0.07] }

[output]
snapshot_interval = 5.0e-5
"""


def fail(message):
    print("FAIL:", message, file=sys.stderr)
    sys.exit(1)


def pvd_entries(pvd_path):
    root = ET.parse(pvd_path).getroot()
    if root.get("type") != "Collection":
        fail(f"{pvd_path}: not a VTK Collection")
    base = os.path.dirname(pvd_path)
    return [(float(d.get("timestep")), os.path.join(base, d.get("file")))
            for d in root.iter("DataSet")]


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    binary, scratch = sys.argv[1], sys.argv[2]
    os.makedirs(scratch, exist_ok=True)
    case = os.path.join(scratch, "block.toml")
    out = os.path.join(scratch, "result")
    with open(case, "w") as f:
        f.write(CASE)

    help_run = subprocess.run([binary, "run", "--help"], capture_output=True, text=True)
    if help_run.returncode != 0 and "run" not in (help_run.stdout + help_run.stderr):
        print(f"SKIP: {binary} has no `run` command yet", file=sys.stderr)
        return 77

    cmd = [binary, "run", case, "--out", out, "--force"]
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if run.returncode != 0:
        fail(f"{' '.join(cmd)} exited with {run.returncode}\n{run.stdout}\n{run.stderr}")

    summary_path = os.path.join(out, "summary.json")
    if not os.path.isfile(summary_path):
        fail(f"no summary.json in {out}; the run wrote: {sorted(os.listdir(out)) if os.path.isdir(out) else 'nothing'}")
    with open(summary_path) as f:
        summary = json.load(f)
    if summary.get("status") != "complete":
        fail(f"summary.json status is {summary.get('status')!r}, expected 'complete'")
    count = summary.get("particles")
    if not isinstance(count, int) or count <= 0:
        fail(f"summary.json 'particles' is {count!r}, expected a positive integer")

    pvds = [os.path.join(d, f) for d, _, files in os.walk(out) for f in files if f.endswith(".pvd")]
    if len(pvds) != 1:
        fail(f"expected exactly one .pvd under {out}, found {pvds}")
    entries = pvd_entries(pvds[0])
    if len(entries) < 2:
        fail(f"{pvds[0]} lists {len(entries)} snapshots; the case asks for about 5")
    times = [t for t, _ in entries]
    if any(b <= a for a, b in zip(times, times[1:])):
        fail(f"{pvds[0]}: snapshot times do not increase: {times}")

    problems = []
    for time_s, path in entries:
        if not os.path.isfile(path):
            problems.append(f"{path} is listed in the .pvd but does not exist")
            continue
        file_problems, mesh = check_vtu(path, count)
        problems += file_problems
        stored = mesh.field_data.get("time_s")
        if stored is None or abs(float(stored[0]) - time_s) > 1e-12 * max(1.0, abs(time_s)):
            problems.append(f"{path}: FieldData time_s {stored} differs from the .pvd time {time_s}")
    for p in problems:
        print("FAIL:", p, file=sys.stderr)
    if problems:
        return 1
    print(f"ok: {len(entries)} snapshots of {count} particles read by meshio")
    return 0


if __name__ == "__main__":
    sys.exit(main())
