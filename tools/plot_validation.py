"""Plots of an mpmcut validation directory: simulated vs measured Ti-6Al-4V cutting forces.

usage: /usr/bin/python3 plot_validation.py VALIDATION_DIR [--quick]

Reads VALIDATION_DIR/validation_runs.csv (the simulated runs) and the measured forces in
data/experiments/ti64_klippel2024_orthogonal_forces.csv (found next to this script's folder: ../data/experiments).
Writes into VALIDATION_DIR:
  validation_forces.png  Fc and Ft vs cutting speed at h = 0.1 mm: every measured condition mean with its min-max
                         range as error bars (tests marked "short" as open symbols), simulated runs as large symbols;
                         the measured forces in N are drawn as N/mm under the ASSUMPTION b = 1 mm (stated on the plot);
  validation_ratio.png   Ft/Fc vs cutting speed at h = 0.1 mm (independent of b), same symbols.
"""
import os
import sys

import plot_style as ps
from plot_style import plt

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data", "experiments", "ti64_klippel2024_orthogonal_forces.csv")


def read_measured(path):
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    import csv
    return list(csv.DictReader(lines))


def main(argv):
    quick = "--quick" in argv
    argv = [a for a in argv if a != "--quick"]
    if len(argv) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    d = argv[0]
    ps.apply_style()
    runs = [r for r in ps.read_csv_rows(os.path.join(d, "validation_runs.csv")) if r["kind"] == "forces"]
    measured = [m for m in read_measured(DATA) if ps.to_float(m["h_mm"]) == 0.1]
    f = ps.to_float

    def sim_at(h):
        pts = [(f(r["speed_m_per_min"]), f(r["cutting_force_N_per_mm"]), f(r["thrust_force_N_per_mm"]), r)
               for r in runs if f(r["h_mm"]) == h and r["status"] == "complete"]
        return [p for p in pts if p[1] is not None and p[2] is not None]

    sim = sim_at(0.1)
    fallback = any("last half" in p[3]["force_window"] for p in sim)

    # Forces.
    fig, ax = plt.subplots(figsize=(6.2, 4.0))
    for key, color, name in (("Fc", ps.COLOR_FC, "$F_c$"), ("Ff", ps.COLOR_FT, "$F_t$")):
        for status, mfc in (("ok", color), ("short", "white")):
            rows = [m for m in measured if (m["status"] == "short") == (status == "short")]
            if not rows:
                continue
            v = [f(m["vc_m_per_min"]) for m in rows]
            y = [f(m[f"{key}_mean_N"]) for m in rows]
            lo = [yy - f(m[f"{key}_min_N"]) for yy, m in zip(y, rows)]
            hi = [f(m[f"{key}_max_N"]) - yy for yy, m in zip(y, rows)]
            ax.errorbar(v, y, yerr=[lo, hi], fmt="o", ms=3.5, color=color, mfc=mfc, capsize=2, lw=0.8,
                        label=f"{name} measured{' (status short)' if status == 'short' else ''}")
        if sim:
            idx = 1 if key == "Fc" else 2
            ax.plot([p[0] for p in sim], [p[idx] for p in sim], "D", ms=8, color=color, mec="black", mew=0.8,
                    label=f"{name} simulated", zorder=5)
    ax.set_xlabel("Cutting speed $v_c$ (m/min)")
    ax.set_ylabel("Force per unit width (N/mm)")
    ax.set_ylim(bottom=0)
    ax.set_title("Ti-6Al-4V, h = 0.1 mm: measured (Klippel et al. 2024) vs simulated")
    ax.legend(frameon=False, fontsize=7, ncol=2, loc="lower left")
    notes = ["Measured N converted to N/mm with ASSUMED width of cut b = 1 mm (b is not in the data file); "
             "bars: min–max of the repeated tests."]
    if fallback:
        notes.append("Simulated means over the last half of the cut (runs ended before their steady window).")
    if quick:
        notes.append("--quick: coarse, short runs; simulated values are not converged.")
    fig.text(0.01, -0.02, "\n".join(notes), fontsize=6.5, color="0.3", va="top")
    ps.save(fig, os.path.join(d, "validation_forces.png"))

    # Ft/Fc.
    fig, ax = plt.subplots(figsize=(6.2, 3.4))
    for status, mfc in (("ok", "#444444"), ("short", "white")):
        rows = [m for m in measured if (m["status"] == "short") == (status == "short")]
        if not rows:
            continue
        v = [f(m["vc_m_per_min"]) for m in rows]
        r = [f(m["Ff_mean_N"]) / f(m["Fc_mean_N"]) for m in rows]
        lo = [rr - f(m["Ff_min_N"]) / f(m["Fc_max_N"]) for rr, m in zip(r, rows)]
        hi = [f(m["Ff_max_N"]) / f(m["Fc_min_N"]) - rr for rr, m in zip(r, rows)]
        ax.errorbar(v, r, yerr=[lo, hi], fmt="o", ms=3.5, color="#444444", mfc=mfc, capsize=2, lw=0.8,
                    label=f"measured{' (status short)' if status == 'short' else ''}")
    if sim:
        ax.plot([p[0] for p in sim], [p[2] / p[1] for p in sim], "D", ms=8, color="#2e8b57", mec="black", mew=0.8,
                label="simulated", zorder=5)
    ax.set_xlabel("Cutting speed $v_c$ (m/min)")
    ax.set_ylabel("$F_t / F_c$ (–)")
    ax.set_ylim(0, 1.2)
    ax.set_title("Thrust-to-cutting force ratio, h = 0.1 mm (independent of the width of cut)")
    ax.legend(frameon=False, fontsize=7.5, loc="lower left")
    fig.text(0.01, -0.02, "Bars: extreme combinations of the min–max ranges of Ft and Fc. Tool rake/clearance "
             "of the experiments not in the data file; simulation: 0°/11° assumed.", fontsize=6.5, color="0.3", va="top")
    ps.save(fig, os.path.join(d, "validation_ratio.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
