#!/usr/bin/python3
"""The tool's share of the heat: validation conditions run with the tool's thermal options
(`validate --friction-heat-share S`, `--tool-heat-transfer-coefficient H`) beside the same conditions of
the validation matrix (adiabatic tool, all frictional heat into the workpiece).

Reads records/<variant>/<condition>/{scene.toml,summary.json} (copied from the validate result
directories) and ../validation_matrix/records/<condition>/ (the matrix: the reference); the tool's
thermal settings are read from each scene's [[rigid_body]] table. Writes tool_heat.csv and tool_heat.md
here. Run: /usr/bin/python3 docs/results/tool_heat/compare_tool_heat.py
"""
import csv
import json
import math
import pathlib
import re
import tomllib

HERE = pathlib.Path(__file__).resolve().parent
MATRIX = HERE.parent / "validation_matrix" / "records"


def measured():
    """Measured means by (h mm, speed m/min) from the matrix report: Fc and Ft (N/mm, b = 1 mm assumed), t_c (um)."""
    out = {}
    for r in csv.DictReader(open(HERE.parent / "validation_matrix" / "validation.csv")):
        m = re.match(r"h = ([0-9.]+) mm, vc = ([0-9.]+) m/min", r["condition"])
        if m and r["quantity"] in ("Fc", "Ft", "t_c") and r["measured_mean"]:
            out.setdefault((float(m[1]), float(m[2])), {})[r["quantity"]] = float(r["measured_mean"])
    return out


MEASURED = measured()


def row(variant, run_dir):
    tool = tomllib.loads((run_dir / "scene.toml").read_text())["rigid_body"][0]
    d = json.loads((run_dir / "summary.json").read_text())
    e, t, rf = d["energy_J_per_m"], d["temperature"], d["rake_face"]
    fc, ft = d["mean_cutting_force_N_per_mm"], d["mean_thrust_force_N_per_mm"]
    key = (round(d["cutting"]["uncut_chip_thickness_m"] * 1e3, 4), round(d["cutting"]["cutting_speed_m_per_min"], 1))
    meas = MEASURED.get(key, {})
    return {
        "condition": run_dir.name,
        "variant": variant,
        "speed_m_per_min": round(d["cutting"]["cutting_speed_m_per_min"], 1),
        "friction_heat_share": tool.get("friction_heat_share", 1.0),
        "tool_heat_transfer_coefficient_W_per_m2K": tool.get("heat_transfer_coefficient", 0.0),
        "tool_temperature_K": tool.get("temperature", 298.0) if tool.get("heat_transfer_coefficient", 0.0) > 0 else "",
        "Fc_N_per_mm": round(fc, 1),
        "Fc_error_percent": round(100 * (fc / meas["Fc"] - 1), 1) if "Fc" in meas else "",
        "Ft_N_per_mm": round(ft, 1),
        "Ft_error_percent": round(100 * (ft / meas["Ft"] - 1), 1) if "Ft" in meas else "",
        "Ft_over_Fc": round(ft / fc, 3),
        "chip_thickness_um": round(d["chip"]["mean_thickness_m"] * 1e6, 1),
        "measured_Fc_Ft_tc": "{:g} / {:g} / {:g}".format(meas["Fc"], meas["Ft"], meas["t_c"]) if len(meas) == 3 else "",
        "tool_chip_interface_max_K": round(t["tool_chip_interface"]["max_K"]),
        "primary_shear_zone_max_K": round(t["primary_shear_zone"]["max_K"]),
        "rake_friction_to_normal": round(rf["friction_to_normal_ratio"], 3),
        "rake_sliding_share_of_normal": round(rf["sliding_share_of_normal_force"], 2),
        "contact_length_um": round(d["tool_chip_contact_length_mm"] * 1e3),
        "friction_work_J_per_m": round(e["friction_work"], 1),
        "energy_residual_percent": round(100 * d["energy_balance"]["relative_residual"], 2),
    }


def main():
    rows = []
    for variant_dir in sorted((HERE / "records").iterdir()):
        for run_dir in sorted(variant_dir.iterdir()):
            if not any(r["condition"] == run_dir.name and r["variant"] == "matrix" for r in rows):
                rows.append(row("matrix", MATRIX / run_dir.name))
            rows.append(row(variant_dir.name, run_dir))
    rows.sort(key=lambda r: (r["speed_m_per_min"], r["variant"] != "matrix", r["variant"]))
    with open(HERE / "tool_heat.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    cols = ["speed_m_per_min", "friction_heat_share", "tool_heat_transfer_coefficient_W_per_m2K", "tool_temperature_K",
            "Fc_N_per_mm", "Fc_error_percent", "Ft_N_per_mm", "Ft_error_percent", "Ft_over_Fc", "chip_thickness_um",
            "measured_Fc_Ft_tc", "tool_chip_interface_max_K",
            "primary_shear_zone_max_K", "rake_friction_to_normal", "rake_sliding_share_of_normal", "contact_length_um",
            "energy_residual_percent"]
    with open(HERE / "tool_heat.md", "w") as f:
        f.write("| " + " | ".join(cols) + " |\n|" + "---|" * len(cols) + "\n")
        for r in rows:
            f.write("| " + " | ".join(str(r[c]) for c in cols) + " |\n")
        # Speed trend of Fc at h = 0.1 mm: least-squares slope over ln(v), N/mm per e-fold of speed, for each
        # variant over its speeds, with the matrix (adiabatic tool) and the measurement over the same speeds.
        f.write("\n| variant | speeds (m/min) | Fc slope, variant | Fc slope, matrix | Fc slope, measured |\n|---|---|---|---|---|\n")
        for variant in sorted({r["variant"] for r in rows} - {"matrix"}):
            speeds = sorted({r["speed_m_per_min"] for r in rows if r["variant"] == variant})
            if len(speeds) < 3:
                continue
            pick = lambda v, key: [r[key] for s_ in speeds for r in rows if r["variant"] == v and r["speed_m_per_min"] == s_]
            meas = [r["Fc_N_per_mm"] / (1 + r["Fc_error_percent"] / 100) for s_ in speeds for r in rows
                    if r["variant"] == "matrix" and r["speed_m_per_min"] == s_]
            f.write(f"| {variant} | {', '.join(f'{s_:g}' for s_ in speeds)} | {slope(speeds, pick(variant, 'Fc_N_per_mm')):+.1f} | "
                    f"{slope(speeds, pick('matrix', 'Fc_N_per_mm')):+.1f} | {slope(speeds, meas):+.1f} |\n")
    print((HERE / "tool_heat.md").read_text())


def slope(speeds, values):
    x = [math.log(v) for v in speeds]
    mx, my = sum(x) / len(x), sum(values) / len(values)
    return sum((a - mx) * (b - my) for a, b in zip(x, values)) / sum((a - mx) ** 2 for a in x)


if __name__ == "__main__":
    main()
