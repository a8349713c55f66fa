"""Plots of an mpmcut calibration directory (`mpmcut calibrate`).

usage: /usr/bin/python3 plot_calibration.py CALIBRATION_DIR

Reads CALIBRATION_DIR/evaluations.csv (every evaluation) and calibration_best.csv (measured vs simulated at
the best set). Writes into CALIBRATION_DIR:
  convergence.png  the objective (weighted RMS relative error, -) of each evaluation and the best so far,
                   global and local stage in their own colours;
  parity.png       simulated vs measured Fc and Ft (N/mm) at the best set, training conditions filled,
                   held-back ones open, with the line of equality and +-10 % bands. Measured forces in N are
                   drawn as N/mm with the ASSUMED width of cut stated in calibration.md.
"""
import os
import sys

import plot_style as ps
from plot_style import plt


def main(argv):
    if len(argv) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    d = argv[0]
    ps.apply_style()
    f = ps.to_float
    evals = ps.read_csv_rows(os.path.join(d, "evaluations.csv"))

    fig, ax = plt.subplots(figsize=(6.0, 3.6))
    for stage, color in (("global", "#1f4e9c"), ("local", "#d35400")):
        pts = [(int(r["evaluation"]), f(r["objective"])) for r in evals if r["stage"] == stage]
        if pts:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", ms=4, color=color, label=f"{stage} stage")
    if evals:
        ax.step([int(r["evaluation"]) for r in evals], [f(r["best_objective"]) for r in evals], where="post",
                color="black", lw=1.2, label="best so far")
    ax.set_yscale("log")
    ax.set_xlabel("Evaluation (–)")
    ax.set_ylabel("Objective: weighted RMS relative error (–)")
    ax.set_title("Calibration convergence")
    ax.legend(frameon=False, fontsize=8)
    ps.save(fig, os.path.join(d, "convergence.png"))

    best = ps.read_csv_rows(os.path.join(d, "calibration_best.csv"))
    fig, ax = plt.subplots(figsize=(4.8, 4.6))
    values = []
    for q, color, name in (("Fc", ps.COLOR_FC, "$F_c$"), ("Ft", ps.COLOR_FT, "$F_t$")):
        for subset, mfc in (("training", color), ("held back", "white")):
            pts = [(f(r[f"measured_{q}_N_per_mm"]), f(r[f"simulated_{q}_N_per_mm"])) for r in best
                   if r["set"] == subset]
            pts = [p for p in pts if p[0] is not None and p[1] is not None]
            if pts:
                ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", ms=7, color=color, mfc=mfc, mew=1.2,
                        label=f"{name}, {subset}")
                values += [v for p in pts for v in p]
    hi = 1.1 * max(values) if values else 1.0
    ax.plot([0, hi], [0, hi], color="0.3", lw=0.8)
    ax.fill_between([0, hi], [0, 0.9 * hi], [0, 1.1 * hi], color="0.85", zorder=0, label="±10 %")
    ax.set_xlim(0, hi)
    ax.set_ylim(0, hi)
    ax.set_aspect("equal")
    ax.set_xlabel("Measured force (N/mm, width of cut assumed)")
    ax.set_ylabel("Simulated force (N/mm)")
    ax.set_title("Parity at the best set")
    ax.legend(frameon=False, fontsize=7.5, loc="upper left")
    ps.save(fig, os.path.join(d, "parity.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
