"""The penalty matrix's records with the grid slip (records/, model version 1) against the particle slip's
(records_particle_slip/), condition by condition, with their errors against the measured means.

The measured means come from particle_slip_report/validation.csv (the report over the particle slip's records, written by
`mpmcut validate`; b = 1 mm assumed for N/mm). Only conditions whose record in records/ has model_version >= 1 are
compared. Prints Markdown: a table per condition and the mean absolute errors and the h = 0.1 mm speed slope of Fc.
Run: /usr/bin/python3 docs/results/validation_speed_ends_penalty/compare_slip.py
"""
import csv
import json
import pathlib
import re

from compare import slope  # least-squares dFc/d ln v in % of the mean, as compare.py reports it

HERE = pathlib.Path(__file__).resolve().parent


def measured_means():
    """(h_mm, vc_m_per_min) -> {"Fc": N/mm, "Ft": N/mm} from the report's validation.csv."""
    out = {}
    with open(HERE / "particle_slip_report" / "validation.csv", newline="") as f:
        for row in csv.DictReader(f):
            m = re.match(r"h = ([\d.]+) mm, vc = ([\d.]+) m/min", row["condition"])
            if m and row["quantity"] in ("Fc", "Ft") and row["measured_mean"]:
                out.setdefault((float(m.group(1)), float(m.group(2))), {})[row["quantity"]] = float(row["measured_mean"])
    return out


def record(path):
    s = json.loads((path / "summary.json").read_text())
    return s.get("model_version", 0), s.get("mean_cutting_force_N_per_mm"), s.get("mean_thrust_force_N_per_mm")


def main():
    measured = measured_means()
    rows = []
    for new_dir in sorted((HERE / "records").glob("forces_*")):
        m = re.match(r"forces_h([\d.]+)mm_vc([\d.]+)mpmin", new_dir.name)
        old_dir = HERE / "records_particle_slip" / new_dir.name
        version, fc, ft = record(new_dir)
        if not m or version < 1 or not old_dir.is_dir() or fc is None:
            continue
        key = (float(m.group(1)), float(m.group(2)))
        _, fc0, ft0 = record(old_dir)
        rows.append((key, fc0, ft0, fc, ft, measured.get(key, {})))
    rows.sort()
    print("| h (mm) | vc (m/min) | Fc particle → grid slip (N/mm) | ΔFc | Ft particle → grid slip (N/mm) | ΔFt "
          "| Fc error vs measured | Ft error | Ft/Fc sim. / meas. |")
    print("|---|---|---|---|---|---|---|---|---|")
    err = {"Fc0": [], "Fc": [], "Ft0": [], "Ft": [], "r0": [], "r": []}
    for (h, v), fc0, ft0, fc, ft, meas in rows:
        e = lambda sim, q: 100.0 * (sim / meas[q] - 1.0) if q in meas else float("nan")
        ratio_meas = meas["Ft"] / meas["Fc"] if "Fc" in meas and "Ft" in meas else float("nan")
        print(f"| {h:g} | {v:g} | {fc0:.1f} → {fc:.1f} | {100 * (fc / fc0 - 1):+.1f} % | {ft0:.1f} → {ft:.1f} | "
              f"{100 * (ft / ft0 - 1):+.1f} % | {e(fc0, 'Fc'):+.1f} → {e(fc, 'Fc'):+.1f} % | {e(ft0, 'Ft'):+.1f} → "
              f"{e(ft, 'Ft'):+.1f} % | {ft0 / fc0:.3f} → {ft / fc:.3f} / {ratio_meas:.3f} |")
        if "Fc" in meas and "Ft" in meas:
            err["Fc0"].append(abs(e(fc0, "Fc")))
            err["Fc"].append(abs(e(fc, "Fc")))
            err["Ft0"].append(abs(e(ft0, "Ft")))
            err["Ft"].append(abs(e(ft, "Ft")))
            err["r0"].append(abs(100.0 * ((ft0 / fc0) / ratio_meas - 1.0)))
            err["r"].append(abs(100.0 * ((ft / fc) / ratio_meas - 1.0)))
    n = len(err["Fc"])
    if not n:
        print("\nno condition with both records yet")
        return
    mean = lambda k: sum(err[k]) / n
    print(f"\nOver {n} conditions: mean |ΔFc| {mean('Fc0'):.1f} → {mean('Fc'):.1f} %, mean |ΔFt| {mean('Ft0'):.1f} → "
          f"{mean('Ft'):.1f} %, mean |Δ(Ft/Fc)| {mean('r0'):.1f} → {mean('r'):.1f} %; Ft/Fc within ±15 %: "
          f"{sum(x <= 15 for x in err['r0'])} → {sum(x <= 15 for x in err['r'])} of {n}.")
    h01 = [(v, fc0, fc, meas) for (h, v), fc0, _, fc, _, meas in rows if h == 0.1]
    if len(h01) >= 3:
        print(f"Fc per e-fold of speed at h = 0.1 mm ({len(h01)} speeds): particle slip {slope([(v, a) for v, a, _, _ in h01]):+.1f} %, "
              f"grid slip {slope([(v, b) for v, _, b, _ in h01]):+.1f} %, measured "
              f"{slope([(v, m['Fc']) for v, _, _, m in h01 if 'Fc' in m]):+.1f} %.")


if __name__ == "__main__":
    main()
