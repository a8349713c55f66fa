#!/usr/bin/env python3
"""Penalty contact against node detection on the measured condition h = 0.1 mm, 100 m/min (issue 11, item 5).

Reads every run record in records/ (scene.toml, summary.json, forces.csv, history.csv of a complete run) and
writes penalty_contact.csv (every column), penalty_contact.md (the table) and penalty_contact.png (Ft and Fc
against the grid phase of the tool tip, and against the cells across t0) beside this script.
The phase is frac((H - t0) / h), H the workpiece's top (its rectangle in the scene), t0 the uncut chip
thickness, h the cell: where the tool's lowest point sits within its cell (docs/cutting.md, "Grid phase").
The cell-period amplitude and the window's frictional work come from tools/force_spectrum.py, over each run's
own steady window. Node detection's earlier runs of the same condition are drawn beside them as references:
docs/results/grid_phase/phase_experiment.csv (t0/10, four phases) and docs/results/convergence/klippel_100m_min/
sweep.csv (t0/8 to t0/24, phase 0).
Run: /usr/bin/python3 docs/results/penalty_contact/tables.py [RECORDS STEM]
RECORDS (default records) is the folder of runs beside this script, STEM (default penalty_contact) the name of the
three files written. With records_grid_slip / penalty_contact_grid_slip (the penalty friction taking its slip from
the grid's velocity, since 2026-12-07) the plot also draws the runs of records/ (the particle's slip) in grey.
"""
import csv
import json
import math
import pathlib
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).resolve().parent
root = here.parents[2]
sys.path.insert(0, str(root / "tools"))
import force_spectrum  # noqa: E402


def row(run_dir):
    s = json.loads((run_dir / "summary.json").read_text())
    if s.get("status") != "complete":
        return None
    scene = tomllib.loads((run_dir / "scene.toml").read_text())
    h = scene["grid"]["cell_size"]
    t0 = scene["cutting_process"]["uncut_chip_thickness"]
    top = scene["body"][0]["rectangle"]["max"][1]
    rows_below = (top - t0) / h
    phase = rows_below - math.floor(rows_below + 1e-6)
    spec = force_spectrum.analyse(str(run_dir))
    fc, ft = s["mean_cutting_force_N_per_mm"], s["mean_thrust_force_N_per_mm"]
    part = s["fracture"]["energy_partition"]
    chip = s.get("chip", {})
    tc = chip.get("mean_thickness_m")
    return {
        "run": run_dir.name,
        "contact_detection": scene["solver"]["contact_detection"],
        "penalty_stiffness": scene["solver"].get("penalty_stiffness", ""),
        "cells_across_t0": round(t0 / h, 2),
        "cell_um": round(h * 1e6, 3),
        "phase": round(phase, 3),
        "Fc_N_per_mm": round(fc, 1),
        "Fc_cell_amplitude_percent": round(spec["Fc"]["cell_amplitude_percent"], 2),
        "Ft_N_per_mm": round(ft, 1),
        "Ft_cell_amplitude_percent": round(spec["Ft"]["cell_amplitude_percent"], 2),
        "Ft_over_Fc": round(ft / fc, 3),
        "rake_normal_N_per_mm": round(s["rake_face"]["normal_force_N_per_mm"], 1),
        "rake_friction_N_per_mm": round(s["rake_face"]["friction_force_N_per_mm"], 1),
        "rake_sliding_share": round(s["rake_face"]["sliding_share_of_normal_force"], 2),
        "edge_flank_Ft_N_per_mm": round(s["edge_and_flank"]["thrust_force_N_per_mm"], 1),
        "friction_work_per_travel_N_per_mm": round(spec["window_friction_work_per_travel_N_per_mm"], 2),
        "friction_share": round(part["friction"], 3),
        "damage_share": round(part["damage"], 3),
        "energy_relative_residual": round(s["energy_balance"]["relative_residual"], 4),
        "contact_length_um": round(s["tool_chip_contact_length_m"] * 1e6, 0),
        "t0_over_tc": round(t0 / tc, 3) if tc else "",
        "chip": chip.get("classification", ""),
        "wall_time_s_1_thread": round(s["wall_time_s"]),
        "source_revision": s.get("source_revision", ""),
    }


def node_references():
    """(phase rows at t0/10, convergence rows at phase 0) of node detection from the two earlier studies."""
    with open(root / "docs/results/grid_phase/phase_experiment.csv") as f:
        phase = [(float(r["phase"]), float(r["Fc_N_per_mm"]), float(r["Ft_N_per_mm"])) for r in csv.DictReader(f)
                 if r["contact_detection"] == "node" and r["cells_across_t0"] == "10"]
    with open(root / "docs/results/convergence/klippel_100m_min/sweep.csv") as f:
        conv = [(float(r["cells_per_feed"]), float(r["mean_cutting_force_N_per_mm"]),
                 float(r["mean_thrust_force_N_per_mm"])) for r in csv.DictReader(f) if r["status"] == "complete"]
    return sorted(phase), sorted(conv)


def read_rows(records):
    rows = [r for r in (row(d) for d in sorted((here / records).iterdir()) if (d / "summary.json").exists()) if r]
    rows.sort(key=lambda r: (r["contact_detection"], r["cells_across_t0"], r["phase"]))
    return rows


def penalty_series(rows):
    """(phase rows at t0/10, resolution rows at phase 0) of the default-stiffness penalty runs."""
    by_phase = [r for r in rows if r["contact_detection"] == "penalty" and r["cells_across_t0"] == 10
                and r["penalty_stiffness"] in (1.0, "")]
    by_cells = sorted((r for r in rows if r["contact_detection"] == "penalty" and r["phase"] < 0.01
                       and r["penalty_stiffness"] in (1.0, "")), key=lambda r: r["cells_across_t0"])
    return by_phase, by_cells


def main(records="records", stem="penalty_contact"):
    rows = read_rows(records)
    with open(here / f"{stem}.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    cols = [("contact_detection", "contact"), ("penalty_stiffness", "stiffness (m/dt²)"), ("cells_across_t0", "cells across t0"), ("phase", "phase φ"),
            ("Fc_N_per_mm", "Fc (N/mm)"), ("Fc_cell_amplitude_percent", "Fc at 1/h (%)"),
            ("Ft_N_per_mm", "Ft (N/mm)"), ("Ft_cell_amplitude_percent", "Ft at 1/h (%)"), ("Ft_over_Fc", "Ft/Fc"),
            ("rake_normal_N_per_mm", "rake N (N/mm)"), ("rake_friction_N_per_mm", "rake friction (N/mm)"),
            ("edge_flank_Ft_N_per_mm", "edge+flank Ft (N/mm)"),
            ("friction_work_per_travel_N_per_mm", "friction work per travel (N/mm)"),
            ("friction_share", "friction / W"), ("damage_share", "damage / W"),
            ("energy_relative_residual", "energy residual"), ("contact_length_um", "contact length (µm)"),
            ("t0_over_tc", "t0/tc"), ("chip", "chip")]
    lines = ["| " + " | ".join(c[1] for c in cols) + " |", "|" + "---|" * len(cols)]
    for r in rows:
        lines.append("| " + " | ".join(str(r[c[0]]) for c in cols) + " |")
    (here / f"{stem}.md").write_text(
        f"<!-- written by tables.py from {records}/; do not edit -->\n" + "\n".join(lines) + "\n")

    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    phase, conv = node_references()
    for (x, fc, ft), ax, what in ((zip(*phase), a, "grid_phase study"), (zip(*conv), b, "convergence study")):
        x, fc, ft = list(x), list(fc), list(ft)
        ax.plot(x, ft, "s-", color="tab:blue", label=f"Ft, node ({what})")
        ax.plot(x, fc, "s--", color="tab:blue", label=f"Fc, node ({what})")
    series = [(penalty_series(rows), "tab:red", "penalty" if records == "records" else "penalty, grid slip")]
    if records != "records":
        series.insert(0, (penalty_series(read_rows("records")), "tab:grey", "penalty, particle slip"))
    for (by_phase, by_cells), colour, name in series:
        a.plot([r["phase"] for r in by_phase], [r["Ft_N_per_mm"] for r in by_phase], "o-", color=colour, label=f"Ft, {name}")
        a.plot([r["phase"] for r in by_phase], [r["Fc_N_per_mm"] for r in by_phase], "o--", color=colour, label=f"Fc, {name}")
        b.plot([r["cells_across_t0"] for r in by_cells], [r["Ft_N_per_mm"] for r in by_cells], "o-", color=colour,
               label=f"Ft, {name}")
        b.plot([r["cells_across_t0"] for r in by_cells], [r["Fc_N_per_mm"] for r in by_cells], "o--", color=colour,
               label=f"Fc, {name}")
    for ax in (a, b):
        ax.axhline(201, color="grey", lw=0.8, ls=":")
        ax.axhline(129, color="grey", lw=0.8, ls=":")
        ax.set_ylabel("force (N/mm, b = 1 mm)")
        ax.legend(fontsize=8)
    a.set_xlabel("grid phase φ of the tool tip (t0/10)")
    b.set_xlabel("cells across t0 (φ = 0)")
    fig.suptitle("h = 0.1 mm, 100 m/min, r_n = 34.4 µm; dotted: measured Fc 201, Ft 129 N/mm")
    fig.tight_layout()
    fig.savefig(here / f"{stem}.png", dpi=110)
    print(f"{len(rows)} runs -> {stem}.csv, .md, .png")


if __name__ == "__main__":
    main(*sys.argv[1:3])
