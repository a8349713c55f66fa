"""Plots of an mpmcut validation directory: simulated vs measured Ti-6Al-4V cutting forces.

usage: /usr/bin/python3 plot_validation.py VALIDATION_DIR [--quick]

Reads VALIDATION_DIR/validation_runs.csv (the simulated runs) and VALIDATION_DIR/validation_measured.csv (the
measurements as `mpmcut validate` read them: the built-in Klippel et al. 2024 data or a --measurements file; runs
and measurements are paired by condition id). Writes into VALIDATION_DIR:
  validation_forces.png  Fc and Ft vs cutting speed at h = 0.1 mm (or, without measurements there, at the h with
                         the most): every measured condition mean with its min-max
                         range as error bars (tests marked "short" as open symbols), simulated runs as large symbols;
                         the measured forces are drawn per mm of the file's width of cut, or as N/mm under the
                         ASSUMPTION b = 1 mm where it gives none (stated on the plot);
  validation_ratio.png   Ft/Fc vs cutting speed at h = 0.1 mm (independent of b), same symbols;
  validation_parity.png  simulated vs measured Fc, Ft, Ft/Fc and chip thickness t_c of every complete force
                         condition: 45-degree line, +-15 % band, measured min-max as horizontal bars;
  validation_speed.png   Fc and Ft vs cutting speed (log axis) at each h (and tool) with two or more measured speeds;
  validation_thickness.png  Fc and Ft vs h at each speed (and tool) with two or more measured thicknesses.
Where the measurements give several tools at one h, the first two figures show the tool with the most conditions.
In the last two, measured means with min-max bars for every condition of the data file, simulated as markers.
"""
import os
import sys

import plot_style as ps
from plot_style import plt
from matplotlib.ticker import FuncFormatter, NullFormatter

def width_note(measured):
    """How the measured forces became N/mm (validation_measured.csv: width_mm blank = 1 mm assumed)."""
    given = sum(1 for m in measured if m["width_mm"])
    if given == 0:
        return "Measured N as N/mm with ASSUMED width of cut b = 1 mm"
    if given == len(measured):
        return "Measured N divided by the data file's width of cut"
    return "Measured N divided by the data file's width of cut, or by an ASSUMED 1 mm where it gives none"


def pick_series(measured):
    """The (h, tool) of the speed figures: h = 0.1 mm if measured, else the h with the most conditions; the tool
    with the most conditions there."""
    f = ps.to_float
    hs = [f(m["h_mm"]) for m in measured]
    h = 0.1 if 0.1 in hs else max(sorted(set(hs)), key=hs.count)
    tools = [m["tool"] for m in measured if f(m["h_mm"]) == h]
    return h, max(sorted(set(tools)), key=tools.count)


def main(argv):
    quick = "--quick" in argv
    argv = [a for a in argv if a != "--quick"]
    if len(argv) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    d = argv[0]
    ps.apply_style()
    runs = [r for r in ps.read_csv_rows(os.path.join(d, "validation_runs.csv")) if r["kind"] == "forces"]
    all_measured = ps.read_csv_rows(os.path.join(d, "validation_measured.csv"))
    if not all_measured:
        print("no measured force condition: nothing to plot", file=sys.stderr)
        return 0
    f = ps.to_float
    source = all_measured[0]["source"]
    h_shown, tool_shown = pick_series(all_measured)
    measured = [m for m in all_measured if f(m["h_mm"]) == h_shown and m["tool"] == tool_shown]
    ids = {m["condition"] for m in measured}
    shown = f"h = {h_shown:g} mm" + (f", {tool_shown}" if tool_shown else "")
    pts = [(f(r["speed_m_per_min"]), f(r["cutting_force_N_per_mm"]), f(r["thrust_force_N_per_mm"]), r)
           for r in runs if r["condition"] in ids and r["status"] == "complete"]
    sim = [p for p in pts if p[1] is not None and p[2] is not None]
    fallback = any("last half" in p[3]["force_window"] for p in sim)

    # Forces.
    fig, ax = plt.subplots(figsize=(6.2, 4.0))
    for key, color, name in (("Fc", ps.COLOR_FC, "$F_c$"), ("Ff", ps.COLOR_FT, "$F_t$")):
        for status, mfc in (("ok", color), ("short", "white")):
            rows = [m for m in measured if (m["status"] == "short") == (status == "short")]
            if not rows:
                continue
            v = [f(m["vc_m_per_min"]) for m in rows]
            y = [f(m[f"{key}_mean_N_per_mm"]) for m in rows]
            lo = [yy - f(m[f"{key}_min_N_per_mm"]) for yy, m in zip(y, rows)]
            hi = [f(m[f"{key}_max_N_per_mm"]) - yy for yy, m in zip(y, rows)]
            ax.errorbar(v, y, yerr=[lo, hi], fmt="o", ms=3.5, color=color, mfc=mfc, capsize=2, lw=0.8,
                        label=f"{name} measured{' (status short)' if status == 'short' else ''}")
        if sim:
            idx = 1 if key == "Fc" else 2
            ax.plot([p[0] for p in sim], [p[idx] for p in sim], "D", ms=8, color=color, mec="black", mew=0.8,
                    label=f"{name} simulated", zorder=5)
    ax.set_xlabel("Cutting speed $v_c$ (m/min)")
    ax.set_ylabel("Force per unit width (N/mm)")
    ax.set_ylim(bottom=0)
    ax.set_title(f"{shown}: measured ({source}) vs simulated", fontsize=9)
    ax.legend(frameon=False, fontsize=7, ncol=2, loc="lower left")
    notes = [width_note(all_measured) + "; bars: min–max of the repeated tests."]
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
        r = [f(m["Ff_mean_N_per_mm"]) / f(m["Fc_mean_N_per_mm"]) for m in rows]
        lo = [rr - f(m["Ff_min_N_per_mm"]) / f(m["Fc_max_N_per_mm"]) for rr, m in zip(r, rows)]
        hi = [f(m["Ff_max_N_per_mm"]) / f(m["Fc_min_N_per_mm"]) - rr for rr, m in zip(r, rows)]
        ax.errorbar(v, r, yerr=[lo, hi], fmt="o", ms=3.5, color="#444444", mfc=mfc, capsize=2, lw=0.8,
                    label=f"measured{' (status short)' if status == 'short' else ''}")
    if sim:
        ax.plot([p[0] for p in sim], [p[2] / p[1] for p in sim], "D", ms=8, color="#2e8b57", mec="black", mew=0.8,
                label="simulated", zorder=5)
    ax.set_xlabel("Cutting speed $v_c$ (m/min)")
    ax.set_ylabel("$F_t / F_c$ (–)")
    ax.set_ylim(0, 1.2)
    ax.set_title(f"Thrust-to-cutting force ratio, {shown} (independent of the width of cut)", fontsize=9)
    ax.legend(frameon=False, fontsize=7.5, loc="lower left")
    fig.text(0.01, -0.02, "Bars: extreme combinations of the min–max ranges of Ft and Fc. "
             + ("Tool rake/clearance of the experiments not in the data file; simulation: 0°/11° assumed."
                if not tool_shown else f"Tool: {tool_shown}."), fontsize=6.5, color="0.3", va="top")
    ps.save(fig, os.path.join(d, "validation_ratio.png"))

    note = width_note(all_measured) + "." + (" --quick: not converged." if quick else "")
    parity(d, runs, all_measured, note, source)
    trend_panels(d, runs, all_measured, "vc_m_per_min", "h_mm", note, source)
    trend_panels(d, runs, all_measured, "h_mm", "vc_m_per_min", note, source)
    return 0


def same(a, b):
    return a is not None and b is not None and abs(a - b) <= 1e-6 * max(1.0, abs(b))


def measured_of(run, measured):
    for m in measured:
        if m["condition"] == run["condition"]:
            return m
    return None


def complete_runs(runs):
    f = ps.to_float
    return [r for r in runs if r["status"] == "complete" and f(r["cutting_force_N_per_mm"]) is not None
            and f(r["thrust_force_N_per_mm"]) is not None]


def parity(d, runs, measured, note, source):
    """Simulated vs measured Fc, Ft, Ft/Fc, t_c with the 45-degree line and a +-15 % band."""
    f = ps.to_float
    fig, axes = plt.subplots(2, 2, figsize=(7.6, 7.0))
    panels = (("Fc", "$F_c$ (N/mm)"), ("Ft", "$F_t$ (N/mm)"), ("ratio", "$F_t/F_c$ (–)"), ("tc", "chip thickness $t_c$ (µm)"))
    for ax, (q, label) in zip(axes.flat, panels):
        xs, ys, lo, hi = [], [], [], []
        for r in complete_runs(runs):
            m = measured_of(r, measured)
            if m is None:
                continue
            fc_s, ft_s = f(r["cutting_force_N_per_mm"]), f(r["thrust_force_N_per_mm"])
            if q == "Fc":
                x, y, a, b = f(m["Fc_mean_N_per_mm"]), fc_s, f(m["Fc_min_N_per_mm"]), f(m["Fc_max_N_per_mm"])
            elif q == "Ft":
                x, y, a, b = f(m["Ff_mean_N_per_mm"]), ft_s, f(m["Ff_min_N_per_mm"]), f(m["Ff_max_N_per_mm"])
            elif q == "ratio":
                x, y = f(m["Ff_mean_N_per_mm"]) / f(m["Fc_mean_N_per_mm"]), ft_s / fc_s
                a, b = f(m["Ff_min_N_per_mm"]) / f(m["Fc_max_N_per_mm"]), f(m["Ff_max_N_per_mm"]) / f(m["Fc_min_N_per_mm"])
            else:
                x, y = f(m.get("chip_thickness_um", "")), f(r.get("chip_thickness_um", ""))
                a = b = x
            if x is None or y is None:
                continue
            xs.append(x), ys.append(y), lo.append(x - a), hi.append(b - x)
        if xs:
            top = 1.15 * max(xs + ys)
            ax.fill_between([0, top], [0, 0.85 * top], [0, 1.15 * top], color="0.9", label="±15 %")
            ax.plot([0, top], [0, top], color="0.4", lw=0.8, label="simulated = measured")
            ax.errorbar(xs, ys, xerr=[lo, hi], fmt="D", ms=5, color="#2e8b57", mec="black", mew=0.6, capsize=2,
                        lw=0.8, label="condition (bars: measured min–max)")
            ax.set_xlim(0, top)
            ax.set_ylim(0, top)
        else:
            ax.text(0.5, 0.5, "no complete condition with a value", ha="center", va="center", transform=ax.transAxes,
                    fontsize=8, color="0.4")
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel(f"measured {label}")
        ax.set_ylabel(f"simulated {label}")
    axes.flat[0].legend(frameon=False, fontsize=6.5, loc="upper left")
    fig.suptitle(f"{source}: simulated vs measured, every complete force condition", fontsize=10)
    fig.text(0.01, 0.0, note + " t_c: simulated t0 / chip thickness ratio vs measured h_avg.", fontsize=6.5,
             color="0.3", va="top")
    ps.save(fig, os.path.join(d, "validation_parity.png"))


def trend_panels(d, runs, measured, x_key, group_key, note, source):
    """Fc and Ft vs x_key (speed or h), one panel per value of group_key and tool with two or more measured x."""
    f = ps.to_float
    run_key = {"vc_m_per_min": "speed_m_per_min", "h_mm": "h_mm"}
    groups = {}
    for m in measured:
        groups.setdefault((f(m[group_key]), m["tool"]), []).append(m)
    groups = {g: ms for g, ms in sorted(groups.items()) if len({f(m[x_key]) for m in ms}) >= 2}
    by_speed = x_key == "vc_m_per_min"
    name = "validation_speed.png" if by_speed else "validation_thickness.png"
    n = max(1, len(groups))
    cols = min(n, 2)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.4 * cols, 3.8 * rows), squeeze=False)
    done = complete_runs(runs)
    for ax, ((g, tool), ms) in zip(axes.flat, groups.items()):
        ms = sorted(ms, key=lambda m: f(m[x_key]))
        for key, color, label in (("Fc", ps.COLOR_FC, "$F_c$"), ("Ff", ps.COLOR_FT, "$F_t$")):
            x = [f(m[x_key]) for m in ms]
            y = [f(m[f"{key}_mean_N_per_mm"]) for m in ms]
            lo = [yy - f(m[f"{key}_min_N_per_mm"]) for yy, m in zip(y, ms)]
            hi = [f(m[f"{key}_max_N_per_mm"]) - yy for yy, m in zip(y, ms)]
            ax.errorbar(x, y, yerr=[lo, hi], fmt="o-", ms=3.5, color=color, mfc="white", capsize=2, lw=0.7,
                        label=f"{label} measured")
            col = "cutting_force_N_per_mm" if key == "Fc" else "thrust_force_N_per_mm"
            ids = {m["condition"] for m in ms}
            sim = sorted((f(r[run_key[x_key]]), f(r[col])) for r in done if r["condition"] in ids)
            if sim:
                ax.plot([p[0] for p in sim], [p[1] for p in sim], "D", ms=7, color=color, mec="black", mew=0.7,
                        label=f"{label} simulated", zorder=5)
        if by_speed:
            ax.set_xscale("log")
            xs = [f(m[x_key]) for m in ms]
            ax.set_xticks([t for t in (10, 20, 50, 100, 200, 500) if min(xs) / 1.2 <= t <= max(xs) * 1.2])
            ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
            ax.xaxis.set_minor_formatter(NullFormatter())
            ax.set_xlabel("cutting speed $v_c$ (m/min)")
            ax.set_title(f"h = {g:g} mm" + (f", {tool}" if tool else ""), fontsize=9)
        else:
            ax.set_xlabel("uncut chip thickness h (mm)")
            ax.set_xlim(left=0)
            ax.set_title(f"$v_c$ = {g:g} m/min" + (f", {tool}" if tool else ""), fontsize=9)
        ax.set_ylabel("force (N/mm)")
        ax.set_ylim(bottom=0)
    for ax in list(axes.flat)[len(groups):]:
        ax.axis("off")
    labels = {}
    for ax in axes.flat:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            labels.setdefault(label, handle)
    if labels:
        axes.flat[0].legend(labels.values(), labels.keys(), frameon=False, fontsize=6.5, loc="best")
    fig.suptitle("Fc and Ft against " + ("speed at each h" if by_speed else "h at each speed")
                 + f" (measured: {source}, mean and min–max)", fontsize=9)
    fig.tight_layout(rect=(0, 0.01, 1, 0.96))
    fig.text(0.01, 0.0, note, fontsize=6.5, color="0.3", va="top")
    ps.save(fig, os.path.join(d, name))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
