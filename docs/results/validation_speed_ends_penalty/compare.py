"""Node detection against penalty contact over the conditions both reports have.

Reads ../validation_speed_ends/validation.csv (node detection) and validation.csv here (penalty contact), both
written by `mpmcut validate`, and the records' summary.json for the energy residual; prints a Markdown table
of mean and worst absolute errors over the common force conditions, and the h = 0.1 mm speed slopes.
Run: /usr/bin/python3 docs/results/validation_speed_ends_penalty/compare.py
"""
import csv
import json
import math
import pathlib

HERE = pathlib.Path(__file__).resolve().parent
NODE = HERE.parent / "validation_speed_ends"


def errors(report):
    out = {}
    with open(report / "validation.csv", newline="") as f:
        for row in csv.DictReader(f):
            if row["error_percent"] in ("", "nan"):
                continue
            out.setdefault(row["condition"].split(", r_n")[0], {})[row["quantity"]] = (
                float(row["measured_mean"]), float(row["simulated"]), float(row["error_percent"]))
    return out


def residuals(report):
    res = []
    for s in sorted((report / "records").glob("forces_*/summary.json")):
        balance = json.loads(s.read_text()).get("energy_balance", {})
        value = balance.get("relative_residual")
        if value is not None:
            res.append(100.0 * value)
    return res


def slope(points):
    """Least-squares dFc/d ln v in % of the mean Fc."""
    xs = [math.log(v) for v, _ in points]
    ys = [f for _, f in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    return 100.0 * b / my


def main():
    node, pen = errors(NODE), errors(HERE)
    common = sorted(c for c in pen if c in node and c.startswith("h = ") and "Fc" in pen[c])
    print(f"| over the same {len(common)} force conditions | node detection (validation_speed_ends) | penalty contact |")
    print("|---|---|---|")
    for q, label in (("Fc", "\\|ΔFc\\|"), ("Ft", "\\|ΔFt\\|"), ("Ft/Fc", "\\|Δ(Ft/Fc)\\|"), ("t_c", "\\|Δt_c\\|")):
        cells = []
        for rep in (node, pen):
            e = [abs(rep[c][q][2]) for c in common if q in rep[c]]
            cells.append(f"{sum(e) / len(e):.1f} / {max(e):.1f} %")
        print(f"| mean / worst {label} | {cells[0]} | {cells[1]} |")
    within = [sum(abs(rep[c]["Ft/Fc"][2]) <= 15.0 for c in common) for rep in (node, pen)]
    print(f"| Ft/Fc within ±15 % | {within[0]} of {len(common)} | {within[1]} of {len(common)} |")
    h01 = [c for c in common if c.startswith("h = 0.1 mm")]
    speeds = lambda c: float(c.split("vc = ")[1].split(" m/min")[0])
    meas = slope([(speeds(c), node[c]["Fc"][0]) for c in h01])
    sims = [slope([(speeds(c), rep[c]["Fc"][1]) for c in h01]) for rep in (node, pen)]
    print(f"| Fc per e-fold of speed, h = 0.1 mm ({len(h01)} speeds; measured {meas:+.1f} %) | {sims[0]:+.1f} % | {sims[1]:+.1f} % |")
    r = residuals(HERE)
    print(f"\nEnergy residual of the penalty runs: {min(r):+.1f} … {max(r):+.1f} % (summary.json energy_balance.relative_residual; {len(r)} runs).")


if __name__ == "__main__":
    main()
