"""End to end: a grid-convergence sweep (`mpmcut sweep --cells-per-feed`) on a tiny cut, run in two parts.

usage: /usr/bin/python3 test_convergence_sweep.py MPMCUT_BINARY SCRATCH_DIR
Checks: a sweep over two resolutions names its cases by resolution, runs each at cell = h/N (summary.json
cell_size_m), writes sweep.csv with the cell size, resolution, mass scaling and energy-partition columns,
convergence.csv and convergence.png; a second run of the same sweep keeps the complete cases (their logs
say "kept" and their results are untouched) and runs only what is new (a third resolution).
"""
import csv
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_checks import check_png, fail  # noqa: E402

# Three cells of tool travel at h = 0.1 mm, 1 particle per cell: about a second per case.
CASE = """\
title = "convergence test: tiny Ti-6Al-4V cut"
[cutting]
material = "ti64-johnson-1985"
cutting_speed = 20.0
uncut_chip_thickness = 0.1e-3
cut_length = 75e-6
particles_per_cell = 1
snapshots = 2
"""


def sweep(binary, case, out, resolutions):
    p = subprocess.run([binary, "sweep", case, "--speeds", "20", "--cells-per-feed", resolutions, "--jobs", "2",
                        "--out", out], capture_output=True, text=True, timeout=300)
    print(p.stdout, p.stderr, sep="\n")
    if p.returncode != 0:
        fail(f"sweep exit status {p.returncode}")
    with open(os.path.join(out, "sweep.csv"), newline="") as f:
        return {r["case"]: r for r in csv.DictReader(f)}


def main(binary, scratch):
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    case = os.path.join(scratch, "tiny.toml")
    with open(case, "w") as f:
        f.write(CASE)
    out = os.path.join(scratch, "conv")
    rows = sweep(binary, case, out, "3,4")
    if sorted(rows) != ["v20mps_h0.1mm_n3", "v20mps_h0.1mm_n4"]:
        fail(f"cases: {sorted(rows)}")
    for n in (3, 4):
        r = rows[f"v20mps_h0.1mm_n{n}"]
        if r["status"] != "complete":
            fail(f"n{n}: {r['status']} {r['message']}")
        with open(os.path.join(out, f"v20mps_h0.1mm_n{n}", "summary.json")) as f:
            summary = json.load(f)
        cell = summary["cell_size_m"]
        # The run's warning on its window (75 um of cut: the entry transient) is in the table's message too.
        warning = summary.get("steady_window", {}).get("warning")
        if not warning or f"warning: {warning}" not in r["message"]:
            fail(f"n{n}: the run's steady-window warning is not in sweep.csv's message: {warning!r} / {r['message']!r}")
        if abs(cell - 0.1e-3 / n) > 1e-12:
            fail(f"n{n}: cell {cell} m, expected {0.1e-3 / n}")
        if abs(float(r["cells_per_feed"]) - n) > 1e-6 or abs(float(r["cell_size_um"]) - 100.0 / n) > 0.1:
            fail(f"n{n}: resolution columns {r['cells_per_feed']}, {r['cell_size_um']}")
        parts = [float(r[k]) for k in ("plastic_work_fraction", "damage_fraction", "friction_fraction",
                                       "kinetic_elastic_fraction", "numerical_fraction")]
        if abs(sum(parts) - 1.0) > 0.02 or not 0.0 < parts[0] <= 1.0:
            fail(f"n{n}: energy partition {parts} does not add up to the tool's work")
        if float(r["mass_scaling_factor"]) != 1.0:  # 20 m/s: above the automatic scaling's speed
            fail(f"n{n}: mass scaling {r['mass_scaling_factor']} at 20 m/s")
    with open(os.path.join(out, "convergence.csv"), newline="") as f:
        conv = list(csv.DictReader(f))
    # Numbers for scripts: the two resolutions and the changes in per cent.
    try:
        ok = (len(conv) == 1 and conv[0]["cells_per_feed_second_finest"] == "3" and conv[0]["cells_per_feed_finest"] == "4"
              and abs(float(conv[0]["cutting_force_change_percent"])) < 100.0)
    except (KeyError, ValueError):
        ok = False
    if not ok:
        fail(f"convergence.csv: {conv}")
    with open(os.path.join(out, "sweep.md")) as f:
        if "## Grid convergence" not in f.read():
            fail("sweep.md has no convergence section")
    check_png(os.path.join(out, "convergence.png"))

    # The same sweep again with one more resolution: n3 and n4 are kept, only n5 runs.
    kept_summary = os.path.join(out, "v20mps_h0.1mm_n3", "summary.json")
    before = os.stat(kept_summary).st_mtime_ns
    rows = sweep(binary, case, out, "3,4,5")
    if os.stat(kept_summary).st_mtime_ns != before:
        fail("the complete case n3 was rerun")
    for n, expect_kept in ((3, True), (4, True), (5, False)):
        with open(os.path.join(out, "logs", f"v20mps_h0.1mm_n{n}.log")) as f:
            kept = "kept:" in f.read()
        if kept != expect_kept:
            fail(f"n{n}: kept = {kept}, expected {expect_kept}")
        if rows[f"v20mps_h0.1mm_n{n}"]["status"] != "complete":
            fail(f"n{n} not complete after the second sweep")
    # Three resolutions: the Richardson table (mpmcut convergence) is in sweep.md and grid_convergence.csv.
    with open(os.path.join(out, "grid_convergence.csv"), newline="") as f:
        rich = {r["quantity"]: r for r in csv.DictReader(f)}
    if rich.get("Fc", {}).get("cells_per_feed") != "3, 4, 5" or not rich["Fc"]["behaviour"]:
        fail(f"grid_convergence.csv: {rich}")
    with open(os.path.join(out, "sweep.md")) as f:
        if "## Richardson extrapolation" not in f.read():
            fail("sweep.md has no Richardson section with three resolutions")
    # A merged table with one resolution twice: exit 2 naming the lines (it stopped with exit 4, "0 < h1 < h2 < h3").
    merged = os.path.join(scratch, "merged")
    os.makedirs(merged)
    with open(os.path.join(out, "sweep.csv")) as f:
        lines = f.readlines()
    with open(os.path.join(merged, "sweep.csv"), "w") as f:
        f.writelines(lines + [lines[1]])
    p = subprocess.run([binary, "convergence", merged], capture_output=True, text=True, timeout=60)
    if p.returncode != 2 or "one run per resolution" not in p.stderr or f"sweep.csv:{len(lines) + 1}" not in p.stderr:
        fail(f"a resolution given twice: exit {p.returncode}, {p.stderr}")
    # A finer run that failed is left out, and the report says so (it used the three finest complete ones silently).
    failed = os.path.join(scratch, "failed")
    os.makedirs(failed)
    with open(os.path.join(out, "sweep.csv"), newline="") as f:
        table = list(csv.DictReader(f))
    extra = dict(table[0], status="failed", cells_per_feed="6")
    with open(os.path.join(failed, "sweep.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0]))
        w.writeheader()
        w.writerows(table + [extra])
    p = subprocess.run([binary, "convergence", failed], capture_output=True, text=True, timeout=60)
    with open(os.path.join(failed, "grid_convergence.md")) as f:
        md = f.read()
    if p.returncode != 0 or "Left out, not complete: V = 20 m/s, h = 0.1 mm at 6 cells across h (failed)" not in md:
        fail(f"a failed finer run: exit {p.returncode}, {p.stderr}, {md[-400:]}")
    print("convergence sweep: OK")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
