#!/usr/bin/python3
"""Where Fc's (missing) fall with speed at h = 0.1 mm sits: the records' force components, chip and
temperatures at each speed, and their least-squares slope per e-fold of speed. And where the thrust's miss sits
along h at 100 m/min: the same components at each h, and straight lines Fc(h), Ft(h) fitted over h >= 0.04 mm to
the runs and to the measured means; the line's value at h = 0 is the edge's force (ploughing, independent of h),
its slope the chip formation's force per mm of h.

Writes trend_components.md and thickness_components.md next to this file from records/forces_h*_vc*/summary.json
and the measured means in validation.csv.
Run: /usr/bin/python3 docs/results/validation_speed_ends_penalty/trend_components.py
"""
import csv
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


def records(pattern, value):
    """(value read from the directory name, summary) of the records matching pattern, sorted by the value."""
    runs = []
    for d in glob.glob(os.path.join(HERE, "records", pattern)):
        with open(os.path.join(d, "summary.json")) as f:
            runs.append((value(d), json.load(f)))
    return sorted(runs, key=lambda r: r[0])


def component_table(runs, label):
    table = [[get(s) for _, _, get in COLUMNS] for _, s in runs]
    lines = [f"| {label} | " + " | ".join(f"{h} ({u})" for h, u, _ in COLUMNS) + " |",
             "|---" * (len(COLUMNS) + 1) + "|"]
    for (v, _), row in zip(runs, table):
        lines.append(f"| {v:g} | " + " | ".join(f"{x:.3g}" if abs(x) < 10 else f"{x:.1f}" for x in row) + " |")
    return table, lines


def line_fit(xs, ys):
    """Least-squares line y = a + b x: (a, b)."""
    b = slope(xs, ys)
    return sum(ys) / len(ys) - b * sum(xs) / len(xs), b


def measured_at_100_m_per_min():
    """Measured mean Fc and Ft (N/mm, b = 1 mm assumed) by h at 100 m/min, from validation.csv."""
    out = {}
    for r in csv.DictReader(open(os.path.join(HERE, "validation.csv"), newline="")):
        m = re.match(r"h = ([\d.]+) mm, vc = 100 m/min", r["condition"])
        if m and r["quantity"] in ("Fc", "Ft"):
            out.setdefault(float(m.group(1)), {})[r["quantity"]] = float(r["measured_mean"])
    return out


def speed_series():
    runs = records("forces_h0.1mm_vc*mpmin", lambda d: float(re.search(r"vc([\d.]+)mpmin", d).group(1)))
    table, lines = component_table(runs, "vc (m/min)")
    lnv = [math.log(v) for v, _ in runs]
    slopes = [slope(lnv, [row[i] for row in table]) for i in range(len(COLUMNS))]
    lines.append("| slope per e-fold of speed | " + " | ".join(f"{x:+.3g}" for x in slopes) + " |")
    with open(os.path.join(HERE, "trend_components.md"), "w") as f:
        f.write("\n".join(["<!-- written by trend_components.py from records/; do not edit -->"] + lines) + "\n")
    print("\n".join(lines[-2:]))


def thickness_series():
    runs = records("forces_h*mm_vc100mpmin", lambda d: float(re.search(r"_h([\d.]+)mm", d).group(1)))
    _, lines = component_table(runs, "h (mm)")
    meas = measured_at_100_m_per_min()
    fitted = [(h, s) for h, s in runs if h >= 0.04 and h in meas]
    hs = [h for h, _ in fitted]
    lines += ["", f"Straight lines over h = {min(hs):g}-{max(hs):g} mm ({len(hs)} conditions): the force at h = 0 (the "
              "edge's) and per mm of h (the chip formation's), N/mm.", "",
              "| force | measured: at h = 0 | measured: per mm of h | simulated: at h = 0 | simulated: per mm of h |",
              "|---|---|---|---|---|"]
    for q, key in (("Fc", "mean_cutting_force_N_per_mm"), ("Ft", "mean_thrust_force_N_per_mm")):
        am, bm = line_fit(hs, [meas[h][q] for h in hs])
        a, b = line_fit(hs, [s[key] for _, s in fitted])
        lines.append(f"| {q} | {am:.1f} | {bm:.0f} | {a:.1f} | {b:.0f} |")
    with open(os.path.join(HERE, "thickness_components.md"), "w") as f:
        f.write("\n".join(["<!-- written by trend_components.py from records/ and validation.csv; do not edit -->"]
                          + lines) + "\n")
    print("\n".join(lines[-4:]))


def main():
    speed_series()
    thickness_series()


if __name__ == "__main__":
    main()
