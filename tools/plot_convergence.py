"""Grid-convergence plots of an mpmcut sweep run at several resolutions (sweep --cells-per-feed 8,12,16,24).

usage: /usr/bin/python3 plot_convergence.py SWEEP_DIR

Reads SWEEP_DIR/sweep.csv and writes SWEEP_DIR/convergence.png: one column per condition (speed, feed), rows
(a) mean cutting and thrust force per unit width, (b) chip thickness ratio t0/tc and segmentation degree,
(c) segment pitch, (d) the energy partition of the tool's work (plastic, damage, friction, kinetic + elastic,
numerical: FLIP/PIC transfer, removed particles, safeguard, residual), each against the number of cells across the uncut chip thickness. Cases that did not complete
are left out; a panel without data says so.
"""
import os
import sys

import plot_style as ps
from plot_style import plt

PARTS = [("plastic_work_fraction", "plastic", "#1f4e9c"), ("damage_fraction", "damage", "#c0392b"),
         ("friction_fraction", "friction", "#2e8b57"), ("kinetic_elastic_fraction", "kinetic+elastic", "#8e44ad"),
         ("numerical_fraction", "numerical", "#7f7f7f")]


def series(rows, key):
    pts = [(ps.to_float(r["cells_per_feed"]), ps.to_float(r.get(key))) for r in rows]
    pts = [(n, y) for n, y in pts if n is not None and y is not None]
    return [p[0] for p in pts], [p[1] for p in pts]


def no_data(ax):
    ax.text(0.5, 0.5, "no data", ha="center", va="center", transform=ax.transAxes, color="0.5")


def main(folder):
    ps.apply_style()
    rows = [r for r in ps.read_csv_rows(os.path.join(folder, "sweep.csv")) if r.get("status") == "complete"]
    if not rows:
        print("plot_convergence: no complete case in sweep.csv", file=sys.stderr)
        return 1
    conditions = sorted({(ps.to_float(r["speed_m_per_s"]), ps.to_float(r["feed_mm"])) for r in rows})
    fig, axes = plt.subplots(4, len(conditions), figsize=(3.4 * len(conditions), 9.0), squeeze=False)
    for col, (v, h) in enumerate(conditions):
        sub = sorted([r for r in rows if (ps.to_float(r["speed_m_per_s"]), ps.to_float(r["feed_mm"])) == (v, h)],
                     key=lambda r: ps.to_float(r["cells_per_feed"]) or 0)
        ax = axes[0][col]
        for key, label, color, style in [("mean_cutting_force_N_per_mm", "Fc", ps.COLOR_FC, "-"),
                                         ("mean_thrust_force_N_per_mm", "Ft", ps.COLOR_FT, "--")]:
            x, y = series(sub, key)
            ax.plot(x, y, style, marker="o", color=color, label=label)
        ax.set_ylabel("force (N/mm)")
        ax.set_ylim(bottom=0)
        ax.set_title(f"V = {v:g} m/s ({v * 60:g} m/min), h = {h:g} mm")
        ax.legend()
        ax = axes[1][col]
        x, y = series(sub, "chip_thickness_ratio")
        ax.plot(x, y, marker="o", color="k", label="t0/tc")
        x, y = series(sub, "segmentation_degree")
        ax.plot(x, y, marker="s", color="#d35400", label="segmentation degree")
        ax.set_ylabel("ratio (-)")
        ax.set_ylim(0, 1.2)
        ax.legend()
        ax = axes[2][col]
        x, y = series(sub, "pitch_um")
        if x:
            ax.plot(x, y, marker="o", color="k")
        else:
            no_data(ax)
        ax.set_ylabel("segment pitch (µm)")
        ax.set_ylim(bottom=0)
        ax = axes[3][col]
        for key, label, color in PARTS:
            x, y = series(sub, key)
            ax.plot(x, y, marker="o", color=color, label=label)
        ax.set_ylabel("fraction of the tool's work (-)")
        ax.set_xlabel("cells across the uncut chip thickness")
        ax.legend(fontsize=7)
        for a in axes[:, col]:
            ns = sorted({ps.to_float(r["cells_per_feed"]) for r in sub})
            if ns:
                a.set_xticks(ns)
                a.set_xticklabels([f"{n:g}" for n in ns])
    ps.save(fig, os.path.join(folder, "convergence.png"))
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1]))
