#!/usr/bin/python3
"""Where Fc's (missing) fall with speed at h = 0.1 mm sits: the records' force components, chip and
temperatures at each speed, and their least-squares slope per e-fold of speed.

Writes trend_components.md next to this file from records/forces_h0.1mm_vc*/summary.json.
Run: /usr/bin/python3 docs/results/validation_speed_ends_penalty/trend_components.py
"""
import glob
import json
import math
import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))

COLUMNS = [  # (header, unit, getter)
    ("Fc", "N/mm", lambda s: s["mean_cutting_force_N_per_mm"]),
    ("Ft", "N/mm", lambda s: s["mean_thrust_force_N_per_mm"]),
    ("rake normal", "N/mm", lambda s: s["rake_face"]["normal_force_N_per_mm"]),
    ("rake friction", "N/mm", lambda s: s["rake_face"]["friction_force_N_per_mm"]),
    ("rake friction / normal", "-", lambda s: s["rake_face"]["friction_to_normal_ratio"]),
    ("edge + flank, cutting", "N/mm", lambda s: s["edge_and_flank"]["cutting_force_N_per_mm"]),
    ("edge + flank, thrust", "N/mm", lambda s: s["edge_and_flank"]["thrust_force_N_per_mm"]),
    ("t0/tc", "-", lambda s: s["chip"]["chip_thickness_ratio"]),
    ("contact length", "µm", lambda s: 1e3 * s["tool_chip_contact_length_mm"]),
    ("hottest, tool-chip interface", "K", lambda s: s["temperature"]["tool_chip_interface"]["max_K"]),
    ("hottest, primary shear zone", "K", lambda s: s["temperature"]["primary_shear_zone"]["max_K"]),
    ("plastic / tool work", "-", lambda s: s["energy_J_per_m"]["plastic_work"] / s["energy_J_per_m"]["external_work"]),
    ("damage / tool work", "-", lambda s: s["energy_J_per_m"]["damage_dissipation"] / s["energy_J_per_m"]["external_work"]),
    ("friction / tool work", "-", lambda s: s["energy_J_per_m"]["friction_work"] / s["energy_J_per_m"]["external_work"]),
]


def slope(xs, ys):
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main():
    runs = []
    for d in glob.glob(os.path.join(HERE, "records", "forces_h0.1mm_vc*mpmin")):
        speed = float(re.search(r"vc([\d.]+)mpmin", d).group(1))
        with open(os.path.join(d, "summary.json")) as f:
            runs.append((speed, json.load(f)))
    runs.sort(key=lambda r: r[0])
    table = [[get(s) for _, _, get in COLUMNS] for _, s in runs]
    lnv = [math.log(v) for v, _ in runs]
    lines = ["<!-- written by trend_components.py from records/; do not edit -->",
             "| vc (m/min) | " + " | ".join(f"{h} ({u})" for h, u, _ in COLUMNS) + " |",
             "|---" * (len(COLUMNS) + 1) + "|"]
    for (v, _), row in zip(runs, table):
        lines.append(f"| {v:g} | " + " | ".join(f"{x:.3g}" if abs(x) < 10 else f"{x:.1f}" for x in row) + " |")
    slopes = [slope(lnv, [row[i] for row in table]) for i in range(len(COLUMNS))]
    lines.append("| slope per e-fold of speed | " + " | ".join(f"{x:+.3g}" for x in slopes) + " |")
    with open(os.path.join(HERE, "trend_components.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines[-2:]))


if __name__ == "__main__":
    main()
