"""Speed and edge radius, separated: least squares of Fc and Ft over the h = 0.1 mm series.

The Klippel et al. 2024 tests at h = 0.1 mm were cut with edges of 29-41 um (each condition's measured mean r_n),
so a force's change between two speeds mixes the speed's effect with the edge's. Fitting
    F = a + b ln(v / (m/min)) + c r_n / um
to the measured means and, separately, to the simulated ones (each run has its condition's r_n) gives both effects
and their standard errors. The simulated forces are split as summary.json splits them (the flat rake face's normal and
friction force, the edge arc's and flank's cutting and thrust force), to show where the edge's effect sits. Usage:

    /usr/bin/python3 docs/results/validation_default/edge_radius.py [RECORDS_DIR] [H_MM]

RECORDS_DIR defaults to this folder's records, H_MM to 0.1. Prints a Markdown table (b = 1 mm assumed: N/mm).
"""
import csv
import json
import os
import re
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
MEASURED = os.path.join(ROOT, "data", "experiments", "ti64_klippel2024_orthogonal_forces.csv")


def measured_conditions():
    with open(MEASURED) as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        return {(float(r["h_mm"]), float(r["vc_m_per_min"])): r for r in rows}


def fit(design, values):
    """Coefficients and their standard errors (ordinary least squares)."""
    values = np.asarray(values)
    coef, _, _, _ = np.linalg.lstsq(design, values, rcond=None)
    residual = values - design @ coef
    variance = residual @ residual / (len(values) - design.shape[1])
    errors = np.sqrt(np.diag(variance * np.linalg.inv(design.T @ design)))
    return coef, errors


def main():
    records = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "records")
    h = float(sys.argv[2]) if len(sys.argv) > 2 else 0.1
    measured = measured_conditions()
    design, forces = [], {"Fc measured": [], "Fc simulated": [], "Ft measured": [], "Ft simulated": []}
    split = {"rake face normal force (in Fc)": [], "rake face friction force (in Ft)": [],
             "edge arc and flank, Fc": [], "edge arc and flank, Ft": []}
    for name in sorted(os.listdir(records)):
        match = re.match(r"forces_h([\d.]+)mm_vc([\d.]+)mpmin$", name)
        if not match or float(match.group(1)) != h:
            continue
        speed = float(match.group(2))
        row = measured[(h, speed)]
        with open(os.path.join(records, name, "summary.json")) as f:
            summary = json.load(f)
        design.append([1.0, np.log(speed), float(row["edge_radius_um"])])
        forces["Fc measured"].append(float(row["Fc_mean_N"]))
        forces["Fc simulated"].append(summary["mean_cutting_force_N_per_mm"])
        forces["Ft measured"].append(float(row["Ff_mean_N"]))
        forces["Ft simulated"].append(summary["mean_thrust_force_N_per_mm"])
        rake, edge = summary["rake_face"], summary["edge_and_flank"]
        split["rake face normal force (in Fc)"].append(rake["normal_force_N_per_mm"])
        split["rake face friction force (in Ft)"].append(rake["friction_force_N_per_mm"])
        split["edge arc and flank, Fc"].append(edge["cutting_force_N_per_mm"])
        split["edge arc and flank, Ft"].append(edge["thrust_force_N_per_mm"])
    if len(design) < 4:
        raise SystemExit(f"{records}: {len(design)} conditions at h = {h} mm, at least 4 needed for the fit")
    design = np.array(design)
    print(f"{len(design)} conditions at h = {h} mm (r_n {design[:, 2].min():.1f}-{design[:, 2].max():.1f} um, "
          f"correlation of ln v and r_n {np.corrcoef(design[:, 1], design[:, 2])[0, 1]:+.2f})\n")
    print("| force | mean (N/mm) | per e-fold of speed (N/mm) | per um of edge radius (N/mm) |")
    print("|---|---|---|---|")
    for label, values in list(forces.items()) + [("simulated: " + k, v) for k, v in split.items()]:
        coef, errors = fit(design, values)
        print(f"| {label} | {np.mean(values):.1f} | {coef[1]:+.2f} ± {errors[1]:.2f} | {coef[2]:+.2f} ± {errors[2]:.2f} |")


if __name__ == "__main__":
    main()
