#!/usr/bin/env python3
"""Grid phase of the tool tip in the validation runs made before the preset aligned it (issue 11).

For each complete force condition of the validation matrix as it was run before the alignment (the report's
validation_runs.csv, kept here as unaligned_validation_runs.csv, and the run records, kept in unaligned_runs/),
the phase phi = frac((H - t0) / cell) of the machined surface within its cell
(H = t0 + max(3 t0, 2 r_n), the grid starting at y = 0), and the simulated against measured Ft/Fc.
Writes validation_phase.csv and validation_phase.png beside this script.
Run: /usr/bin/python3 docs/results/grid_phase/phase_of_validation_runs.py
"""
import csv
import json
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).resolve().parent
root = here.parents[2]

measured = {}
with open(root / "data/experiments/ti64_klippel2024_orthogonal_forces.csv") as f:
    for r in csv.DictReader(line for line in f if not line.startswith("#")):
        measured[(float(r["h_mm"]), float(r["vc_m_per_min"]))] = r

runs = {}  # condition -> (h mm, v m/min, r_n um, cell um, Fc, Ft)
with open(here / "unaligned_validation_runs.csv") as f:
    for r in csv.DictReader(f):
        if r["kind"] == "forces" and r["status"] == "complete":
            runs[r["condition"]] = (float(r["h_mm"]), float(r["speed_m_per_min"]), float(r["edge_radius_um"]),
                                    float(r["cell_size_um"]), float(r["cutting_force_N_per_mm"]),
                                    float(r["thrust_force_N_per_mm"]))
for summary in sorted((here / "unaligned_runs").glob("forces_*/summary.json")):
    s = json.loads(summary.read_text())
    if s.get("status") != "complete":
        continue
    name = summary.parent.name
    h = float(name.split("_h")[1].split("mm")[0])
    v = float(name.split("vc")[1].split("mpmin")[0])
    runs[name] = (h, v, float(measured[(h, v)]["edge_radius_um"]), s["cell_size_m"] * 1e6,
                  s["mean_cutting_force_N_per_mm"], s["mean_thrust_force_N_per_mm"])

rows = []
for name, (h, v, rn, cell, fc, ft) in sorted(runs.items(), key=lambda kv: kv[1][:2]):
    t0 = h * 1e3  # um
    depth = max(3 * t0, 2 * rn)  # H - t0, um
    q = depth / cell
    phase = max(0.0, q - math.floor(q + 1e-6))
    m = measured[(h, v)]
    ratio_sim, ratio_meas = ft / fc, float(m["Ff_mean_N"]) / float(m["Fc_mean_N"])
    rows.append({"condition": name, "h_mm": h, "vc_m_per_min": v, "edge_radius_um": rn, "cell_um": round(cell, 4),
                 "phase": round(phase, 3), "Fc_N_per_mm": round(fc, 1), "Ft_N_per_mm": round(ft, 1),
                 "Ft_over_Fc_sim": round(ratio_sim, 4), "Ft_over_Fc_measured": round(ratio_meas, 4),
                 "Ft_over_Fc_error_percent": round(100 * (ratio_sim / ratio_meas - 1), 1),
                 "Ft_error_percent": round(100 * (ft / float(m["Ff_mean_N"]) - 1), 1)})

with open(here / "validation_phase.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
    w.writeheader()
    w.writerows(rows)

fig, ax = plt.subplots(figsize=(6.4, 4.0))
thin = [r for r in rows if r["h_mm"] < 0.06]
thick = [r for r in rows if r["h_mm"] >= 0.06]
ax.scatter([r["phase"] for r in thick], [r["Ft_over_Fc_error_percent"] for r in thick], label="h ≥ 0.06 mm")
ax.scatter([r["phase"] for r in thin], [r["Ft_over_Fc_error_percent"] for r in thin], marker="s",
           label="h ≤ 0.04 mm (ploughing, Ft > Fc)")
ax.axhspan(-15, 15, color="0.9", zorder=0, label="goal ±15 %")
ax.set_xlabel("phase of the machined surface within its cell, (H − t0)/h − whole cells (–)")
ax.set_ylabel("Ft/Fc error against Klippel 2024 (%)")
ax.set_title("Validation runs before the alignment: thrust against grid phase", fontsize=10)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(here / "validation_phase.png", dpi=120)
print(f"{len(rows)} conditions -> {here / 'validation_phase.csv'}, validation_phase.png")
