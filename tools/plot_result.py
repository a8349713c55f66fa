"""Pictures of one mpmcut result directory: the chip coloured by temperature, equivalent plastic strain
and damage, with the tool drawn where it was, and the force history.

usage: /usr/bin/python3 plot_result.py RESULT_DIR [--snapshots last|all|N,M,...]

Writes into RESULT_DIR (docs/results.md):
  chip_<field>_NNNNNN.png   one picture per chosen snapshot and field (temperature, plastic_strain, damage),
  chip_NNNNNN.png           the three fields side by side for the same snapshot,
  forces.png                cutting and thrust force per unit width against tool travel,
  chip_profile.png          the chip analysis's thickness profile with its peaks, valleys and left-out entry chip.
The last snapshot is always drawn. Reads summary.json, scene.toml, forces.csv, particles.pvd and the VTU
snapshots (meshio); needs numpy, matplotlib and meshio (Debian: python3-matplotlib, python3-meshio).
"""
import argparse
import math
import os
import re
import sys
import textwrap
import tomllib
import xml.etree.ElementTree as ET

import numpy as np

import plot_style as ps
from plot_style import plt

from matplotlib.collections import PolyCollection
from matplotlib.patches import Polygon as PolygonPatch
from mpl_toolkits.axes_grid1.anchored_artists import AnchoredSizeBar

FIELDS = {
    # key: (point-data array, colour-bar label, colour map)
    "temperature": ("temperature_K", "Temperature (K)", "turbo"),
    "plastic_strain": ("plastic_strain", "Equivalent plastic strain (–)", "viridis"),
    "damage": ("damage", "Damage D (–)", "RdYlBu_r"),
}


# ---------------------------------------------------------------- the scene: tool and process

class Tool:
    """The first [[rigid_body]] of scene.toml: a polygon grown by rounding_radius, moving at velocity."""

    def __init__(self, table):
        pts = np.asarray(table["polygon"], dtype=float)
        # Counter-clockwise, so that edge normals (dy, -dx) point outwards.
        x, y = pts[:, 0], pts[:, 1]
        if 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y) < 0:
            pts = pts[::-1]
        self.polygon = pts
        self.radius = float(table.get("rounding_radius", 0.0))
        self.velocity = np.asarray(table.get("velocity", [0.0, 0.0]), dtype=float)

    def outline(self, time_s, arc_points=24):
        """The rounded outline at a time: every edge pushed out by r, every corner an arc of radius r."""
        p = self.polygon + self.velocity * time_s
        r = self.radius
        if r <= 0:
            return p
        n = len(p)
        out = []
        for i in range(n):
            prev_edge = p[i] - p[i - 1]
            next_edge = p[(i + 1) % n] - p[i]
            a0 = math.atan2(-prev_edge[0], prev_edge[1])  # outward normal of the incoming edge
            a1 = math.atan2(-next_edge[0], next_edge[1])  # ... of the outgoing edge
            while a1 < a0:
                a1 += 2 * math.pi
            for a in np.linspace(a0, a1, arc_points):
                out.append(p[i] + r * np.array([math.cos(a), math.sin(a)]))
        return np.asarray(out)

    def cutting_edge(self, time_s):
        """Centre of the cutting-edge arc: the lowest polygon corner (leftmost among equals)."""
        p = self.polygon + self.velocity * time_s
        i = min(range(len(p)), key=lambda k: (round(p[k][1], 12), p[k][0]))
        return p[i]


def read_scene(result_dir):
    with open(os.path.join(result_dir, "scene.toml"), "rb") as f:
        scene = tomllib.load(f)
    bodies = scene.get("rigid_body", [])
    tool = Tool(bodies[0]) if bodies else None
    process = scene.get("cutting_process", {})
    return scene, tool, process


def read_pvd(result_dir):
    """[(index, time_s, path)] of the snapshots listed in particles.pvd, in file order."""
    pvd = os.path.join(result_dir, "particles.pvd")
    if not os.path.exists(pvd):
        return []
    entries = []
    for k, d in enumerate(ET.parse(pvd).getroot().iter("DataSet")):
        path = os.path.join(result_dir, d.get("file"))
        stem = os.path.splitext(os.path.basename(path))[0]
        digits = stem.rsplit("_", 1)[-1]
        index = int(digits) if digits.isdigit() else k
        entries.append((index, float(d.get("timestep")), path))
    return entries


def choose_snapshots(entries, spec):
    if not entries:
        return []
    last = entries[-1]
    if spec == "all":
        return entries
    if spec in ("last", ""):
        return [last]
    wanted = set()
    for item in spec.split(","):
        item = item.strip()
        if item:
            wanted.add(int(item))
    chosen = [e for e in entries if e[0] in wanted]
    missing = wanted - {e[0] for e in chosen}
    if missing:
        print(f"warning: no snapshot numbered {sorted(missing)}; have {entries[0][0]}..{last[0]}", file=sys.stderr)
    if last not in chosen:
        chosen.append(last)
    return chosen


# ---------------------------------------------------------------- chip pictures

def view_window(tool_tip, t0, points, surface_y):
    """The cutting zone: the tool tip and a few t0 around it, grown to hold the chip (capped)."""
    tx, ty = tool_tip
    x0, x1 = tx - 4.0 * t0, tx + 2.0 * t0
    y0, y1 = ty - 2.0 * t0, ty + 4.0 * t0
    # The chip: material well above the uncut surface, near the tool.
    near = (points[:, 0] > tx - 10 * t0) & (points[:, 0] < tx + 3 * t0)
    chip = points[near & (points[:, 1] > surface_y + 0.3 * t0)]
    if len(chip):
        x0 = max(min(x0, chip[:, 0].min() - 0.3 * t0), tx - 9 * t0)
        x1 = min(max(x1, chip[:, 0].max() + 0.3 * t0), tx + 4 * t0)
        y1 = min(max(y1, chip[:, 1].max() + 0.3 * t0), ty + 9 * t0)
    return x0, x1, y0, y1


def particle_squares(points, volume, in_view):
    """One square per particle, side sqrt(area) (2D: volume per unit depth) drawn 30 % larger: particles in the
    chip are sheared into long thin shapes that squares of equal area would not cover, leaving false seams."""
    xy = points[in_view, :2]
    half = 0.65 * np.sqrt(np.abs(volume[in_view]))
    offs = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=float)
    return xy[:, None, :] + half[:, None, None] * offs[None, :, :]


def field_limits(key, values, process, material):
    if key == "temperature":
        # The top 0.2 % (single overheated particles on the rake face) would squeeze the colour scale;
        # they get the "max" arrow of the colour bar and the maximum is printed under it.
        t_init = float(process.get("initial_temperature", 298.0))
        hi = float(np.percentile(values, 99.8)) if len(values) else t_init + 1.0
        return t_init, max(hi, t_init + 1.0)
    if key == "damage":
        return 0.0, 1.0
    hi = float(np.percentile(values, 99.5)) if len(values) else 1.0
    return 0.0, max(hi, 1e-3)


def draw_field(ax, fig, key, mesh, tool, time_s, window, process, material, um, colorbar=True):
    name, label, cmap = FIELDS[key]
    x0, x1, y0, y1 = window
    pts = mesh.points
    margin = 0.05 * (x1 - x0)
    in_view = ((pts[:, 0] > x0 - margin) & (pts[:, 0] < x1 + margin) &
               (pts[:, 1] > y0 - margin) & (pts[:, 1] < y1 + margin))
    values = np.asarray(mesh.point_data[name], dtype=float).reshape(len(pts), -1)[:, 0][in_view]
    volume = np.asarray(mesh.point_data["volume_m3_per_m"], dtype=float)
    vmin, vmax = field_limits(key, values, process, material)
    squares = particle_squares(pts, volume, in_view) * um
    coll = PolyCollection(squares, array=values, cmap=cmap, edgecolors="none", antialiaseds=False, rasterized=True)
    coll.set_clim(vmin, vmax)
    ax.add_collection(coll)
    if tool is not None:
        outline = tool.outline(time_s) * um
        ax.add_patch(PolygonPatch(outline, closed=True, facecolor="#b8bcc2", edgecolor="#2b2b2b", lw=0.9, zorder=5))
        ax.text(*(tool.cutting_edge(time_s) * um + np.array([0.9, 1.6]) * float(process.get("uncut_chip_thickness", 0)) * um),
                "tool", fontsize=8, color="#2b2b2b", zorder=6)
    ax.set_xlim(x0 * um, x1 * um)
    ax.set_ylim(y0 * um, y1 * um)
    ax.set_aspect("equal")
    ax.set_facecolor("white")
    ax.set_xticks([])
    ax.set_yticks([])
    # Scale bar: a round length near a fifth of the window width.
    width_um = (x1 - x0) * um
    bar = nice_length(width_um / 5.0)
    ax.add_artist(AnchoredSizeBar(ax.transData, bar, f"{bar:g} µm", "lower left", pad=0.4, borderpad=0.5,
                                  sep=3, frameon=True, size_vertical=width_um / 150.0, color="black",
                                  fontproperties={"size": 8}))
    if colorbar:
        extend = "neither"
        if key != "damage" and len(values) and np.max(values) > vmax * 1.0001:
            extend = "max"
        cb = fig.colorbar(coll, ax=ax, fraction=0.046, pad=0.03, extend=extend)
        cb.set_label(label)
        if extend == "max":
            cb.ax.set_title(f"max\n{np.max(values):.4g}", fontsize=6.5, pad=4)
        tm = material.get("melting_temperature")
        if key == "temperature" and tm and vmin < tm < vmax:
            cb.ax.axhline(tm, color="cyan", lw=1.2)
            cb.ax.text(1.05, (tm - vmin) / (vmax - vmin), " $T_m$", transform=cb.ax.transAxes, va="center",
                       fontsize=7, color="black")
    return coll, values


def nice_length(x):
    if x <= 0:
        return 1.0
    e = 10 ** math.floor(math.log10(x))
    for m in (1, 2, 5, 10):
        if m * e >= x * 0.75:
            return m * e
    return 10 * e


def case_caption(process, time_s, tool):
    parts = []
    v = process.get("cutting_speed")
    h = process.get("uncut_chip_thickness")
    if v:
        parts.append(f"V = {v:g} m/s ({v * 60:g} m/min)")
    if h:
        parts.append(f"h = {h * 1e3:g} mm")
    if process.get("rake_angle_deg") is not None:
        parts.append(f"γ = {process['rake_angle_deg']:g}°")
    travel = abs(tool.velocity[0]) * time_s * 1e6 if tool is not None else None
    t = f"t = {time_s * 1e6:.3g} µs"
    if travel is not None:
        t += f", tool travel {travel:.0f} µm"
    return ", ".join(parts), t


def snapshot_is_empty(path):
    """Whether a VTU snapshot has no points (read from its Piece header, as meshio fails on it)."""
    try:
        with open(path, "rb") as f:
            head = f.read(4096).decode("latin-1")
    except OSError:
        return False
    m = re.search(r'NumberOfPoints="(\d+)"', head)
    return m is not None and int(m.group(1)) == 0


def load_snapshot(path, tool, process, time_s):
    """The mesh of one VTU snapshot, its time (from the file where it has one) and the view window of the
    cutting zone around the tool tip."""
    import meshio  # here, so that forces.png does not need meshio
    mesh = meshio.read(path)
    field_time = mesh.field_data.get("TimeValue") if hasattr(mesh, "field_data") else None
    if field_time is not None and len(np.ravel(field_time)):
        time_s = float(np.ravel(field_time)[0])
    pts = np.asarray(mesh.points, dtype=float)
    body = np.asarray(mesh.point_data.get("body_id", np.zeros(len(pts)))).ravel()
    t0 = float(process.get("uncut_chip_thickness", 0.0)) or 0.1 * float(np.ptp(pts[:, 1]) or 1e-3)
    if tool is not None:
        tip = tool.cutting_edge(time_s) - np.array([0.0, tool.radius])
    else:
        tip = np.array([pts[:, 0].max(), pts[:, 1].max() - t0])
    surface_y = tip[1] + t0
    return mesh, time_s, view_window(tip, t0, pts[body >= 0], surface_y)


def plot_snapshot(result_dir, index, time_s, path, tool, process, material):
    mesh, time_s, window = load_snapshot(path, tool, process, time_s)
    um = 1e6
    process_line, time_line = case_caption(process, time_s, tool)
    aspect = (window[3] - window[2]) / (window[1] - window[0])
    written = []
    for key in FIELDS:
        fig, ax = plt.subplots(figsize=(4.6, 3.6 * aspect + 0.6), layout="constrained")
        draw_field(ax, fig, key, mesh, tool, time_s, window, process, material, um)
        ax.set_title(f"{process_line}\n{time_line}", fontsize=8.5)
        out = os.path.join(result_dir, f"chip_{key}_{index:06d}.png")
        ps.save(fig, out)
        written.append(out)
    # The three fields side by side: the figure a paper would print.
    fig, axes = plt.subplots(1, 3, figsize=(12.0, 3.0 * aspect + 0.7), layout="constrained")
    for ax, key in zip(axes, FIELDS):
        draw_field(ax, fig, key, mesh, tool, time_s, window, process, material, um)
    fig.suptitle(f"{process_line};  {time_line}", fontsize=9.5)
    out = os.path.join(result_dir, f"chip_{index:06d}.png")
    ps.save(fig, out)
    written.append(out)
    return written


# ---------------------------------------------------------------- force history

def plot_forces(result_dir, summary, process, tool):
    path = os.path.join(result_dir, "forces.csv")
    if not os.path.exists(path):
        print("note: no forces.csv (not a cutting run?): no force plot", file=sys.stderr)
        return None
    rows = ps.read_csv_rows(path)
    if len(rows) < 2:
        print("note: forces.csv has fewer than two rows: no force plot", file=sys.stderr)
        return None
    col = lambda name: np.array([ps.to_float(r.get(name)) or 0.0 for r in rows])
    t = col("time_s")
    travel_um = np.abs(col("tool_displacement_m")) * 1e6
    if not np.any(travel_um) and tool is not None:
        travel_um = np.abs(tool.velocity[0]) * t * 1e6
    use_mm = travel_um.max() >= 1000.0
    x = travel_um / 1e3 if use_mm else travel_um
    xlabel = "Tool travel (mm)" if use_mm else "Tool travel (µm)"

    fig, ax = plt.subplots(figsize=(6.0, 3.4))
    for name, raw, color, label in (("cutting_force_N_per_mm", "cutting_force_raw_N_per_mm", ps.COLOR_FC, "$F_c$ (cutting)"),
                                    ("thrust_force_N_per_mm", "thrust_force_raw_N_per_mm", ps.COLOR_FT, "$F_t$ (thrust)")):
        if raw in rows[0]:
            ax.plot(x, col(raw), color=color, lw=0.5, alpha=0.35)
        ax.plot(x, col(name), color=color, lw=1.8, label=label)

    window = (summary or {}).get("steady_window") or {}
    start, end = window.get("start_time_s"), window.get("end_time_s")
    note = None
    if start is not None and end is not None:
        xs = np.interp([start, end], t, x)
        ax.axvspan(xs[0], xs[1], color="0.85", alpha=0.6, lw=0, label="steady window")
        for key, color, sym, dy in (("mean_cutting_force_N_per_mm", ps.COLOR_FC, "c", 0.04),
                                    ("mean_thrust_force_N_per_mm", ps.COLOR_FT, "t", -0.04)):
            mean = (summary or {}).get(key)
            if mean is None:
                continue
            ax.hlines(mean, xs[0], xs[1], colors=color, linestyles="--", lw=1.0)
            ax.annotate(f"$\\bar F_{sym}$ = {mean:.0f} N/mm", xy=(xs[1], mean), xytext=(4, 10 if dy > 0 else -12),
                        textcoords="offset points", color=color, fontsize=8.5, ha="left",
                        bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8))
    else:
        note = window.get("definition") or "no steady window in summary.json"
    ax.set_xlabel(xlabel)
    ax.set_ylabel("Force per unit width (N/mm)")
    ax.set_xlim(x.min(), x.max() * 1.18 if start is not None else x.max())
    ax.axhline(0, color="0.3", lw=0.5)
    v = process.get("cutting_speed")
    h = process.get("uncut_chip_thickness")
    title = "Cutting forces"
    if v and h:
        title += f":  V = {v:g} m/s ({v * 60:g} m/min),  h = {h * 1e3:g} mm"
    ax.set_title(title)
    ax.legend(loc="upper left", frameon=False, ncol=3)
    if note:
        ax.text(0.99, 0.02, "steady window: " + note, transform=ax.transAxes, ha="right", va="bottom",
                fontsize=7, color="0.35", wrap=True)
    top = max(np.max(col("cutting_force_N_per_mm")), np.max(col("thrust_force_N_per_mm")), 1.0)
    ax.set_ylim(min(0.0, ax.get_ylim()[0]), top * 1.35)
    out = os.path.join(result_dir, "forces.png")
    ps.save(fig, out)
    return out


# ---------------------------------------------------------------- chip profile

def plot_profile(result_dir, summary):
    """The chip analysis's thickness profile (summary.json chip.profile): what the segmentation degree, the teeth
    and the mean thickness were measured on, the left-out entry chip shaded, the thickness by area beside the mean."""
    chip = (summary or {}).get("chip") or {}
    prof = chip.get("profile") or {}
    thickness = prof.get("thickness_m")
    if thickness is not None and len(thickness) == 0:
        print("note: the chip has no measurable profile (a cut too short for the chip to leave its root; "
              "`mpmcut analyze` gives the same): no chip_profile.png", file=sys.stderr)
        return None
    if not thickness:
        print("note: summary.json has no chip profile (not a cutting run, or analysed before profiles were "
              "written: mpmcut analyze DIR adds it): no chip_profile.png", file=sys.stderr)
        return None
    um = 1e6
    start, spacing = float(prof.get("start_m") or 0.0), float(prof["spacing_m"])
    s = (start + spacing * np.arange(len(thickness))) * um
    t = np.asarray(thickness, dtype=float) * um
    steady = int(prof.get("steady_samples") or len(t))
    fig, ax = plt.subplots(figsize=(6.4, 3.4))
    ax.plot(s, t, color="0.2", lw=1.2, label="thickness across the chip")
    if steady < len(t):
        ax.axvspan(s[steady - 1], s[-1], color="0.85", alpha=0.7, lw=0, label="entry chip, left out")
    for key, marker, color, label in (("peak_positions_m", "^", ps.COLOR_FT, "peaks"),
                                      ("valley_positions_m", "v", ps.COLOR_FC, "valleys")):
        pos = np.asarray(prof.get(key) or [], dtype=float) * um
        if len(pos):
            ax.plot(pos, np.interp(pos, s, t), marker, color=color, ms=7, ls="none", label=label)
    mean = chip.get("mean_thickness_m")
    if mean:
        ax.axhline(mean * um, color="0.5", ls="--", lw=0.8, label=f"mean {mean * um:.0f} µm")
    by_area = chip.get("area_mean_thickness_m")
    if by_area:  # differs from the mean where cross-sections stop at open cracks (docs/analysis.md)
        ax.axhline(by_area * um, color="0.5", ls=":", lw=1.0, label=f"by area {by_area * um:.0f} µm")
    gs, pitch = chip.get("segmentation_degree"), chip.get("pitch_m")
    facts = [f"{chip.get('classification', '?')} ({chip.get('classification_confidence', '?')})"]
    if gs is not None:
        facts.append(f"Gs = {gs:.2f}")
    facts.append(f"{chip.get('segments', 0)} teeth")
    if pitch:
        facts.append(f"pitch {pitch * um:.0f} µm")
    ax.set_title("Chip profile: " + ",  ".join(facts), fontsize=9.5)
    ax.set_xlabel("Distance along the chip from the rake face's edge (µm)")
    ax.set_ylabel("Chip thickness (µm)")
    ax.set_ylim(0, max(t.max(), 1.0) * 1.3)
    ax.legend(loc="upper left", frameon=False, ncol=3, fontsize=7.5)
    note = prof.get("note")
    if note:  # below the axes, wrapped to their width
        ax.annotate(textwrap.fill("note: " + note, 110), xy=(0.0, -0.22), xycoords="axes fraction", va="top",
                    fontsize=6.5, color="0.35")
    out = os.path.join(result_dir, "chip_profile.png")
    ps.save(fig, out)
    return out


# ---------------------------------------------------------------- main

def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("result_dir")
    parser.add_argument("--snapshots", default="last", help="last (default), all, or snapshot numbers N,M,...")
    args = parser.parse_args(argv)
    ps.apply_style()
    d = args.result_dir
    if not os.path.isdir(d):
        print(f"error: {d} is not a directory", file=sys.stderr)
        return 2
    summary = ps.read_json(os.path.join(d, "summary.json"))
    if summary is None:
        print(f"warning: {d}/summary.json missing or unreadable", file=sys.stderr)
    try:
        scene, tool, process = read_scene(d)
    except (OSError, tomllib.TOMLDecodeError) as e:
        print(f"warning: cannot read {d}/scene.toml ({e}); no tool drawn", file=sys.stderr)
        scene, tool, process = {}, None, {}
    materials = scene.get("material", [])
    material = materials[0] if materials else {}

    written = []
    try:
        chosen = choose_snapshots(read_pvd(d), args.snapshots)
    except ValueError:
        print(f"error: --snapshots takes last, all or numbers N,M,...; got '{args.snapshots}'", file=sys.stderr)
        return 2
    if not chosen:
        print(f"note: no snapshots listed in {d}/particles.pvd: no chip pictures", file=sys.stderr)
    for index, time_s, path in chosen:
        if snapshot_is_empty(path):  # meshio cannot read a VTU without points (a run that lost every particle)
            print(f"note: {os.path.basename(path)} holds no particles: no chip picture of it", file=sys.stderr)
            continue
        try:
            written += plot_snapshot(d, index, time_s, path, tool, process, material)
        except (Exception, SystemExit) as e:  # a damaged VTU (meshio prints "Error: ..." and exits for some)
            print(f"\nerror: cannot read {path} ({'see above' if isinstance(e, SystemExit) else e}): the run's results are damaged", file=sys.stderr)
            return 2
    f = plot_forces(d, summary, process, tool)
    if f:
        written.append(f)
    f = plot_profile(d, summary)
    if f:
        written.append(f)
    if not written:
        print("error: nothing to plot", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
