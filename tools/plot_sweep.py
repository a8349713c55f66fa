"""Plots of an mpmcut sweep (speed x feed grid) from its sweep.csv.

usage: /usr/bin/python3 plot_sweep.py SWEEP_DIR

Writes into SWEEP_DIR (docs/results.md):
  forces_vs_speed.png  mean cutting (solid) and thrust (dashed) force per unit width vs cutting speed, one colour per feed
                       (and per value of the key a `sweep --vary` varied: sweep.csv column series, as below);
  chip_vs_speed.png    segment pitch (µm) and segmentation degree vs cutting speed, one colour per feed
                       (panels say so when the chip analysis gave no values);
  chip_map.png         speed x feed map of the chip type, coloured cells with labels;
  chip_gallery_damage.png, chip_gallery_temperature.png
                       the final chip of every case (rows: feeds, columns: speeds) coloured by damage and by
                       temperature on one colour scale, the tool drawn (needs meshio; skipped without it).
Cases that did not complete are drawn as crosses at the bottom of the force plot and as grey cells.
"""
import os
import sys

import numpy as np

import plot_style as ps
from plot_style import plt

from matplotlib.patches import Patch

CHIP_COLORS = {
    "continuous": "#4c9be8",
    "serrated": "#f0a830",
    "segmented": "#f0a830",
    "discontinuous": "#d9534f",
}


def chip_color(label):
    low = (label or "").lower()
    # Longest key first: "discontinuous" contains "continuous".
    for key in sorted(CHIP_COLORS, key=len, reverse=True):
        if key in low:
            return CHIP_COLORS[key]
    return "#d0d0d0" if not low else "#9b8ec4"


def series_of(row):
    """A case's series: its feed and, in a sweep with --vary, the varied key's value (sweep.csv column series)."""
    return row.get("series") or f"h = {ps.to_float(row['feed_mm']):g} mm"


def group_by_series(rows):
    """The series in the order of increasing feed, then of sweep.csv (the order of the --vary values)."""
    order = {}
    for r in rows:
        order.setdefault(series_of(r), (ps.to_float(r["feed_mm"]) or 0.0, len(order)))
    series = sorted(order, key=lambda s: order[s])
    return series, {s: sorted([r for r in rows if series_of(r) == s], key=lambda r: ps.to_float(r["speed_m_per_s"]))
                    for s in series}


def speed_axis(ax, speeds):
    if len(speeds) and max(speeds) / max(min(speeds), 1e-12) > 8:
        ax.set_xscale("log")
        ax.set_xticks(speeds)
        ax.set_xticklabels([f"{s:g}" for s in speeds])
        ax.minorticks_off()
    ax.set_xlabel("Cutting speed V (m/s)")
    # A second axis in the machinist's m/min.
    sec = ax.secondary_xaxis("top", functions=(lambda v: v * 60.0, lambda v: v / 60.0))
    sec.set_xlabel("V (m/min)", fontsize=8)
    sec.tick_params(labelsize=7)


def plot_forces(d, rows, feeds, by_feed, speeds):
    """feeds: the series labels (feed, and the varied key's value); by_feed: their rows."""
    fig, ax = plt.subplots(figsize=(5.6, 3.8))
    any_point = False
    for k, f in enumerate(feeds):
        color = ps.FEED_COLORS[k % len(ps.FEED_COLORS)]
        ok = [r for r in by_feed[f] if r["status"] == "complete" and ps.to_float(r["mean_cutting_force_N_per_mm"]) is not None]
        v = [ps.to_float(r["speed_m_per_s"]) for r in ok]
        fc = [ps.to_float(r["mean_cutting_force_N_per_mm"]) for r in ok]
        ft = [ps.to_float(r["mean_thrust_force_N_per_mm"]) for r in ok]
        if v:
            any_point = True
            ax.plot(v, fc, "-o", color=color, lw=1.6, ms=4.5, label=f"$F_c$, {f}")
            ax.plot(v, ft, "--s", color=color, lw=1.2, ms=4, mfc="white", label=f"$F_t$, {f}")
        bad = [ps.to_float(r["speed_m_per_s"]) for r in by_feed[f] if r["status"] != "complete"]
        if bad:
            ax.plot(bad, [0] * len(bad), "x", color=color, ms=7, mew=1.5, label=f"not complete, {f}")
    fallback = any("last half" in (r.get("force_window") or "") for r in rows)
    speed_axis(ax, speeds)
    ax.set_ylabel("Mean force per unit width (N/mm)")
    ax.set_ylim(bottom=0)
    ax.set_title("Cutting (solid) and thrust (dashed) force vs cutting speed", pad=24)
    if any_point:
        ax.legend(frameon=False, fontsize=7, ncol=1 if max(len(f) for f in feeds) > 16 else 2, loc="best")
    else:
        ax.text(0.5, 0.5, "no complete case with forces", transform=ax.transAxes, ha="center", color="0.4")
    if fallback:
        fig.text(0.01, -0.03, "Some means are over the last half of the cut: the run ended before its steady window "
                 "(column force_window of sweep.csv).", fontsize=6.5, color="0.35", va="top")
    ps.save(fig, os.path.join(d, "forces_vs_speed.png"))


def plot_chip_metrics(d, rows, feeds, by_feed, speeds):
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.6), layout="constrained")
    for ax, key, label in ((axes[0], "pitch_um", "Segment pitch (µm)"),
                           (axes[1], "segmentation_degree", "Segmentation degree (–)")):
        n = 0
        for k, f in enumerate(feeds):
            color = ps.FEED_COLORS[k % len(ps.FEED_COLORS)]
            pts = [(ps.to_float(r["speed_m_per_s"]), ps.to_float(r.get(key))) for r in by_feed[f]]
            pts = [(v, y) for v, y in pts if y is not None]
            if pts:
                n += len(pts)
                ax.plot(*zip(*pts), "-o", color=color, lw=1.5, ms=4.5, label=f)
        if len(speeds) == 1 or not n:
            ax.set_xlim(min(speeds) * 0.8, max(speeds) * 1.2)
        speed_axis(ax, speeds)
        ax.set_ylabel(label)
        if n:
            ax.legend(frameon=False)
            ax.set_ylim(bottom=0)
        else:
            analysed = any(r.get("chip_classification") for r in rows)
            text = ("no values: no segments found\n(pitch is undefined for continuous chips)" if analysed else
                    "not available:\nno chip analysis in the summaries\n(mpmcut analyze)")
            ax.text(0.5, 0.5, text, transform=ax.transAxes, ha="center", va="center", color="0.4", fontsize=8)
    fig.suptitle("Chip segmentation vs cutting speed")
    ps.save(fig, os.path.join(d, "chip_vs_speed.png"))


def plot_chip_map(d, rows, feeds, speeds):
    fig, ax = plt.subplots(figsize=(max(4.0, 1.05 * len(speeds) + 1.6), max(2.2, 0.75 * len(feeds) + 1.3)))
    used = {}
    for r in rows:
        v, f = ps.to_float(r["speed_m_per_s"]), series_of(r)
        if v not in speeds or f not in feeds:
            continue
        i, j = speeds.index(v), feeds.index(f)
        if r["status"] != "complete":
            label, color = r["status"] or "failed", "#7f7f7f"
        else:
            label = r.get("chip_classification") or "n/a"
            color = chip_color(r.get("chip_classification"))
        used[label] = color
        ax.add_patch(plt.Rectangle((i, j), 1, 1, facecolor=color, edgecolor="white", lw=2))
        ax.text(i + 0.5, j + 0.5, label, ha="center", va="center", fontsize=7.5,
                color="white" if color == "#7f7f7f" else "black", wrap=True)
    ax.set_xlim(0, len(speeds))
    ax.set_ylim(0, len(feeds))
    ax.set_xticks(np.arange(len(speeds)) + 0.5)
    ax.set_xticklabels([f"{v:g}\n({v * 60:g})" for v in speeds], fontsize=7.5)
    ax.set_yticks(np.arange(len(feeds)) + 0.5)
    varied = any(r.get("series") and r["series"] != f"h = {ps.to_float(r['feed_mm']):g} mm" for r in rows)
    ax.set_yticklabels(feeds if varied else [f.removeprefix("h = ").removesuffix(" mm") for f in feeds],
                       fontsize=7 if varied else None)
    ax.set_xlabel("Cutting speed V, m/s (m/min)")
    ax.set_ylabel("" if varied else "Uncut chip thickness h (mm)")
    ax.tick_params(length=0, top=False, right=False)
    ax.set_title("Chip type")
    if "n/a" in used:
        ax.text(0.0, -0.02, "n/a: no chip classification in summary.json (mpmcut analyze)", transform=fig.transFigure,
                fontsize=6.5, color="0.35")
    handles = [Patch(facecolor=c, label=l) for l, c in used.items()]
    ax.legend(handles=handles, frameon=False, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7.5)
    ps.save(fig, os.path.join(d, "chip_map.png"))


def plot_chip_gallery(d, rows, feeds, speeds, key):
    """The last snapshot of every complete case side by side, one colour scale for all panels."""
    import plot_result as pr
    by_cell = {(ps.to_float(r["speed_m_per_s"]), series_of(r)): r for r in rows}
    fig, axes = plt.subplots(len(feeds), len(speeds), figsize=(2.5 * len(speeds) + 0.8, 2.3 * len(feeds) + 0.5),
                             squeeze=False, layout="constrained")
    drawn = []  # (collection, values, material)
    for j, f in enumerate(reversed(feeds)):  # the thickest feed on top, as in chip_map.png
        for i, v in enumerate(speeds):
            ax = axes[j][i]
            r = by_cell.get((v, f))
            entries = pr.read_pvd(os.path.join(d, r["case"])) if r and r["status"] == "complete" else []
            if not entries:
                ax.axis("off")
                ax.text(0.5, 0.5, f"{v:g} m/s, {f}\n{r['status'] if r else 'not run'}", ha="center",
                        va="center", transform=ax.transAxes, fontsize=8)
                continue
            case_dir = os.path.join(d, r["case"])
            scene, tool, process = pr.read_scene(case_dir)
            material = (scene.get("material") or [{}])[0]
            _, time_s, path = entries[-1]
            mesh, time_s, window = pr.load_snapshot(path, tool, process, time_s)
            coll, values = pr.draw_field(ax, fig, key, mesh, tool, time_s, window, process, material, 1e6,
                                         colorbar=False)
            drawn.append((coll, values, material))
            ax.set_title(f"{v:g} m/s ({v * 60:g} m/min), {f}\n{r.get('chip_classification') or 'n/a'}",
                         fontsize=7.5)
    if not drawn:
        plt.close(fig)
        return
    if key == "temperature":  # one scale: from the initial temperature to the highest 99.8th percentile
        lo = min(c.get_clim()[0] for c, _, _ in drawn)
        hi = max(c.get_clim()[1] for c, _, _ in drawn)
        for c, _, _ in drawn:
            c.set_clim(lo, hi)
    _, label, _ = pr.FIELDS[key]
    fig.colorbar(drawn[-1][0], ax=axes, fraction=0.025, pad=0.01, label=label)
    what = {"damage": "damage D", "temperature": "temperature", "plastic_strain": "equivalent plastic strain"}[key]
    fig.suptitle(f"Final chips of the sweep coloured by {what}", fontsize=9.5)
    ps.save(fig, os.path.join(d, f"chip_gallery_{key}.png"))


def main(argv):
    if len(argv) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    d = argv[0]
    rows = ps.read_csv_rows(os.path.join(d, "sweep.csv"))
    if not rows:
        print("error: sweep.csv has no rows", file=sys.stderr)
        return 1
    ps.apply_style()
    feeds, by_feed = group_by_series(rows)
    speeds = sorted({ps.to_float(r["speed_m_per_s"]) for r in rows})
    plot_forces(d, rows, feeds, by_feed, speeds)
    plot_chip_metrics(d, rows, feeds, by_feed, speeds)
    plot_chip_map(d, rows, feeds, speeds)
    try:
        import meshio  # noqa: F401  (the gallery reads the VTU snapshots)
    except ImportError:
        print("note: no meshio: no chip galleries", file=sys.stderr)
        return 0
    for key in ("damage", "temperature"):
        plot_chip_gallery(d, rows, feeds, speeds, key)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
