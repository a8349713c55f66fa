#!/usr/bin/python3
"""Variants of validation conditions beside the validation matrix: one table row per run.

A sensitivity study runs some measured conditions of the matrix with one thing changed (a tool option, a
material set) and keeps each run's record, RECORDS/<variant>/<condition>/{scene.toml,summary.json}. This
script puts every such run next to the matrix's own record of the same condition
(docs/results/validation_matrix/records/<condition>, or --matrix DIR's, variant "matrix") and the measured means
(from that matrix's validation.csv), and writes
PREFIX.csv (every column) and PREFIX.md (the --columns, then the least-squares speed trend of Fc for each
variant and uncut chip thickness run at 2 or more speeds, beside the matrix and the measurement at the same
speeds).

What each run had is read from its scene.toml: the material (the [[material]] the workpiece used, and the
library set it derives from), whether heat is conducted ([thermal] conduction), the tool's Coulomb coefficient and
its thermal settings ([[rigid_body]] friction, friction_heat_share, heat_transfer_coefficient, temperature).

usage: /usr/bin/python3 tools/compare_variants.py RECORDS PREFIX [--matrix DIR] [--columns a,b,c]
"""
import argparse
import csv
import json
import math
import pathlib
import re
import tomllib

ROOT = pathlib.Path(__file__).resolve().parent.parent
MATRIX = ROOT / "docs" / "results" / "validation_matrix"


def measured(matrix):
    """Measured means by (h mm, speed m/min) from the matrix report: Fc and Ft (N/mm, b = 1 mm assumed), t_c (um)."""
    out = {}
    for r in csv.DictReader(open(matrix / "validation.csv")):
        m = re.match(r"h = ([0-9.]+) mm, vc = ([0-9.]+) m/min", r["condition"])
        if m and r["quantity"] in ("Fc", "Ft", "t_c") and r["measured_mean"]:
            out.setdefault((float(m[1]), float(m[2])), {})[r["quantity"]] = float(r["measured_mean"])
    return out


def material_of(scene):
    """The workpiece's material name and the library set it derives from ('' if none)."""
    name = scene.get("cutting_process", {}).get("material") or scene["body"][0]["material"]
    for m in scene.get("material", []):
        if m["name"] == name:
            return name, m.get("library", "")
    return name, ""


def row(variant, run_dir, meas_by_condition):
    scene = tomllib.loads((run_dir / "scene.toml").read_text())
    tool = scene["rigid_body"][0]
    d = json.loads((run_dir / "summary.json").read_text())
    e, t, rf, ef = d["energy_J_per_m"], d["temperature"], d["rake_face"], d.get("edge_and_flank", {})
    fc, ft = d["mean_cutting_force_N_per_mm"], d["mean_thrust_force_N_per_mm"]
    key = (round(d["cutting"]["uncut_chip_thickness_m"] * 1e3, 4), round(d["cutting"]["cutting_speed_m_per_min"], 1))
    meas = meas_by_condition.get(key, {})
    material, library = material_of(scene)
    htc = tool.get("heat_transfer_coefficient", 0.0)
    return {
        "condition": run_dir.name,
        "variant": variant,
        "h_mm": round(d["cutting"]["uncut_chip_thickness_m"] * 1e3, 4),
        "speed_m_per_min": round(d["cutting"]["cutting_speed_m_per_min"], 1),
        "material": material,
        "material_library_set": library,
        "friction": tool.get("friction", 0.0),
        "conduction": scene.get("thermal", {}).get("conduction", False),
        "friction_heat_share": tool.get("friction_heat_share", 1.0),
        "tool_heat_transfer_coefficient_W_per_m2K": htc,
        "tool_temperature_K": tool.get("temperature", 298.0) if htc > 0 else "",
        "Fc_N_per_mm": round(fc, 1),
        "Fc_error_percent": round(100 * (fc / meas["Fc"] - 1), 1) if "Fc" in meas else "",
        "Ft_N_per_mm": round(ft, 1),
        "Ft_error_percent": round(100 * (ft / meas["Ft"] - 1), 1) if "Ft" in meas else "",
        "Ft_over_Fc": round(ft / fc, 3),
        "chip_thickness_um": round(d["chip"]["mean_thickness_m"] * 1e6, 1),
        "chip_type": d["chip"].get("classification", ""),
        "segmentation_degree": round(d["chip"]["segmentation_degree"], 2) if "segmentation_degree" in d["chip"] else "",
        "measured_Fc_Ft_tc": "{:g} / {:g} / {:g}".format(meas["Fc"], meas["Ft"], meas["t_c"]) if len(meas) == 3 else "",
        "tool_chip_interface_max_K": round(t["tool_chip_interface"]["max_K"]),
        "primary_shear_zone_max_K": round(t["primary_shear_zone"]["max_K"]),
        "rake_normal_N_per_mm": round(rf["normal_force_N_per_mm"], 1),
        "rake_friction_N_per_mm": round(rf["friction_force_N_per_mm"], 1),
        # Older records have no edge-and-flank split (blank).
        "edge_flank_cutting_N_per_mm": round(d["edge_and_flank"]["cutting_force_N_per_mm"], 1) if "edge_and_flank" in d else "",
        # Newer records split it further: the edge arc's normal push and the flank's thrust (blank before).
        "edge_arc_normal_thrust_N_per_mm": round(ef["edge_arc"]["normal_part"]["thrust_force_N_per_mm"], 1)
        if "edge_arc" in ef else "",
        "flank_thrust_N_per_mm": round(ef["flank"]["thrust_force_N_per_mm"], 1) if "flank" in ef else "",
        "rake_friction_to_normal": round(rf["friction_to_normal_ratio"], 3),
        "rake_sliding_share_of_normal": round(rf["sliding_share_of_normal_force"], 2),
        "contact_length_um": round(d["tool_chip_contact_length_mm"] * 1e3),
        "friction_work_J_per_m": round(e["friction_work"], 1),
        "damage_share_of_tool_work": round(d["fracture"]["energy_partition"]["damage"], 3),
        "energy_residual_percent": round(100 * d["energy_balance"]["relative_residual"], 2),
        # The tool's share of the heat over the steady window (summary.json tool_heat; blank in older records).
        "tool_heat_share_of_work": round(d["tool_heat"]["steady_window_share_of_tool_work"], 3)
        if d.get("tool_heat", {}).get("steady_window_share_of_tool_work") is not None else "",
        # A conducting tool's hottest cell at the end (summary.json tool_heat.tool_temperature; blank for the others).
        "tool_max_K": round(d["tool_heat"]["tool_temperature"]["max_K"])
        if "tool_temperature" in d.get("tool_heat", {}) else "",
    }


def slope(speeds, values):
    """Least-squares dFc/d ln(v): N/mm per e-fold of speed."""
    x = [math.log(v) for v in speeds]
    mx, my = sum(x) / len(x), sum(values) / len(values)
    return sum((a - mx) * (b - my) for a, b in zip(x, values)) / sum((a - mx) ** 2 for a in x)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("records", type=pathlib.Path, help="RECORDS/<variant>/<condition>/ of the study")
    ap.add_argument("prefix", type=pathlib.Path, help="writes PREFIX.csv and PREFIX.md")
    ap.add_argument("--columns", default="speed_m_per_min,variant,Fc_N_per_mm,Fc_error_percent,Ft_N_per_mm,"
                    "Ft_error_percent,Ft_over_Fc,chip_thickness_um,measured_Fc_Ft_tc",
                    help="the columns of PREFIX.md, comma-separated")
    ap.add_argument("--matrix", type=pathlib.Path, default=MATRIX,
                    help="the validation study whose records/ and validation.csv are the reference "
                    "(default docs/results/validation_matrix)")
    ap.add_argument("--min-trend-speeds", type=int, default=2,
                    help="speeds a variant needs for its row of the trend table (default 2)")
    a = ap.parse_args()
    meas = measured(a.matrix)
    rows = []
    for variant_dir in sorted(p for p in a.records.iterdir() if p.is_dir()):
        for run_dir in sorted(p for p in variant_dir.iterdir() if (p / "summary.json").exists()):
            if not any(r["condition"] == run_dir.name and r["variant"] == "matrix" for r in rows):
                rows.append(row("matrix", a.matrix / "records" / run_dir.name, meas))
            rows.append(row(variant_dir.name, run_dir, meas))
    if not rows:
        raise SystemExit(f"compare_variants: no complete runs under {a.records}/<variant>/<condition>/")
    rows.sort(key=lambda r: (r["h_mm"], r["speed_m_per_min"], r["variant"] != "matrix", r["variant"]))
    with open(a.prefix.with_suffix(".csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    cols = a.columns.split(",")
    unknown = [c for c in cols if c not in rows[0]]
    if unknown:
        raise SystemExit(f"compare_variants: unknown column(s) {unknown}; allowed: {', '.join(rows[0])}")
    with open(a.prefix.with_suffix(".md"), "w") as f:
        f.write("| " + " | ".join(cols) + " |\n|" + "---|" * len(cols) + "\n")
        for r in rows:
            f.write("| " + " | ".join(str(r[c]) for c in cols) + " |\n")
        # The speed trend at one uncut chip thickness: a variant's runs at other thicknesses are not in it.
        f.write("\n| variant | h (mm) | speeds (m/min) | Fc slope, variant | Fc slope, matrix | Fc slope, measured |\n"
                "|---|---|---|---|---|---|\n")
        for variant, h in sorted({(r["variant"], r["h_mm"]) for r in rows if r["variant"] != "matrix"}):
            at_h = [r for r in rows if r["h_mm"] == h]
            speeds = sorted({r["speed_m_per_min"] for r in at_h if r["variant"] == variant})
            if len(speeds) < a.min_trend_speeds:
                continue
            pick = lambda v, key: [r[key] for s in speeds for r in at_h if r["variant"] == v and r["speed_m_per_min"] == s]
            measured_fc = [r["Fc_N_per_mm"] / (1 + r["Fc_error_percent"] / 100) for s in speeds for r in at_h
                           if r["variant"] == "matrix" and r["speed_m_per_min"] == s]
            f.write(f"| {variant} | {h:g} | {', '.join(f'{s:g}' for s in speeds)} | "
                    f"{slope(speeds, pick(variant, 'Fc_N_per_mm')):+.1f} | "
                    f"{slope(speeds, pick('matrix', 'Fc_N_per_mm')):+.1f} | {slope(speeds, measured_fc):+.1f} |\n")
    print(a.prefix.with_suffix(".md").read_text())


if __name__ == "__main__":
    main()
