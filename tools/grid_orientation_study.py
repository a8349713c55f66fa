"""Does a cut depend on how the grid is oriented? The same cut, rotated against the grid.

usage: /usr/bin/python3 tools/grid_orientation_study.py MPMCUT CASE OUT [--angles 0,15,30,45] [--cells 12e-6,8e-6]
                                                        [--threads 1] [--set KEY=VALUE ...] [--lattice grid]
                                                        [--phase 0]

For each cell size the cutting case is expanded by the program itself (a one-step run writes its complete
scene.toml), and that scene is rotated by each angle about the workpiece's lower-left corner: the workpiece, the
tool (its polygon, its edge rounding and its velocity) and the grid's extent. The grid's fixed sides cannot hold a
rotated workpiece's sides, so in every variant, the unrotated one too, a base of the same material fills the wedge
between the workpiece's bottom and left sides and the grid's fixed bottom and left sides (at 0 deg a strip three
cells thick); the thermal sides are the preset's. The tool force (rigid_forces.csv)
is turned back into the tool's frame: Fc along the cutting direction, Ft normal to it, per mm of width. Each variant
is its own run directory, run with --keep-complete: a rerun keeps what is complete (the study is resumable).

--lattice says where the rotated workpiece and base put their particles: `grid` (the default) on the grid's own
sub-grid, so that a rotated side is a staircase of particle rows; `turned` on the sub-grid turned with them
(`lattice_angle_deg` = the angle, `lattice_origin` = the workpiece's corner; docs/input.md, [[body]]), so that their
sides run along particle rows as the unrotated workpiece's do: the same cut, only the grid turned.

--phase φ (0 <= φ < 1) moves the grid down by φ cells under the same particles (their lattice stays on the
workpiece's corner, `lattice_origin`): the tool's tip, on a node row in the preset, then sits φ of a cell above one
(docs/cutting.md, "Grid phase of the tool tip"). A turned cut sweeps every phase as it travels (the tip crosses a
node row every cell / sin angle); at 0 deg this gives the phases one at a time, to compare a turned cut with the
aligned cut's average over them.

Writes OUT/grid_orientation.csv and OUT/grid_orientation.md: per cell size and angle, the mean Fc and Ft over the
second half of the cut, the tool's work and its partition (plastic, damage, friction), the damage dissipation
(J/m), the chip (type, thickness, pitch, segmentation degree: `mpmcut analyze` of the last snapshot turned back into
the tool's frame, in RUN_DIR_tool_frame; tools/snapshot_transform.py), the tool's travel between two crossings of a
grid row (cell / sin angle), the wavelength in travel and amplitude of Fc's strongest oscillation over the second half
of the cut (are the bands paced by the grid rows?) and the run's status. The preset's own run with fixed grid
sides (angle "preset") is listed beside them. OUT/grid_orientation.png shows every run's last snapshot turned back
into the tool's frame, coloured by damage (with matplotlib and meshio).
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tomllib
import xml.etree.ElementTree as ET

from snapshot_transform import turn_snapshot

HOLD_CELLS = 3  # the base's thickness at 0 deg, in cells


def parse_args(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    args = {"binary": argv[1], "case": argv[2], "out": argv[3], "angles": [0.0, 15.0, 30.0, 45.0],
            "cells": [12e-6, 8e-6], "threads": 1, "sets": [], "lattice": "grid", "phase": 0.0}
    i = 4
    while i < len(argv):
        key = argv[i]
        if i + 1 >= len(argv):
            sys.exit(f"error: {key} needs a value\n{__doc__}")
        value = argv[i + 1]
        try:
            if key == "--angles":
                args["angles"] = [float(v) for v in value.split(",")]
            elif key == "--cells":
                args["cells"] = [float(v) for v in value.split(",")]
            elif key == "--threads":
                args["threads"] = int(value)
            elif key == "--set":
                args["sets"].append(value)
            elif key == "--phase":
                args["phase"] = float(value)
                if not 0 <= args["phase"] < 1:
                    sys.exit(f"error: --phase {value}: must be in [0, 1) cells")
            elif key == "--lattice":
                if value not in ("grid", "turned"):
                    sys.exit(f"error: --lattice {value}: must be grid or turned")
                args["lattice"] = value
            else:
                sys.exit(f"error: unknown option {key}\n{__doc__}")
        except ValueError:
            sys.exit(f"error: {key} {value}: not a number (list)")
        i += 2
    if any(not (c > 0) for c in args["cells"]):
        sys.exit("error: --cells: every cell size must be positive (m)")
    return args


def run(cmd, log):
    with open(log, "w") as f:
        return subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT).returncode


def toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, (int, float)):
        return repr(float(v)) if isinstance(v, float) else str(v)
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    raise ValueError(f"cannot write {v!r}")


def table(name, d, array=False):
    lines = [f"[[{name}]]" if array else f"[{name}]"]
    lines += [f"{k} = {toml_value(v)}" for k, v in d.items() if not isinstance(v, dict)]
    return "\n".join(lines) + "\n"


def rotate(p, c, s):
    return [c * p[0] - s * p[1], s * p[0] + c * p[1]]


def workpiece_of(scene):
    """The preset scene's workpiece body (a rectangle; the turned scenes' corner is its lower-left one)."""
    return next(b for b in scene["body"] if b["name"] == "workpiece")


def rotated_scene(scene, angle_deg, turned_lattice=False, phase=0.0):
    """The preset's scene rotated by angle_deg; a base of the same material fills the wedge between the workpiece's
    bottom and left sides and the grid's fixed bottom and left sides (a strip HOLD_CELLS cells thick at 0 deg). With
    turned_lattice, both are seeded on the particle lattice turned with them about the workpiece's corner; phase
    moves the grid down by that fraction of a cell under the same particles."""
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    h = scene["grid"]["cell_size"]
    work = workpiece_of(scene)
    (x0, y0), (x1, y1) = work["rectangle"]["min"], work["rectangle"]["max"]
    a = HOLD_CELLS * h
    place = lambda p: rotate([p[0] - x0, p[1] - y0], c, s)  # noqa: E731  (about the workpiece's corner)
    p0, p1, p5 = place([x0, y0]), place([x1, y0]), place([x0, y1])
    # The grid's lower-left corner: whole cells below and left of the base (its fixed sides hold the base).
    left = math.floor((min(p0[0], p5[0]) - a) / h) * h
    bottom = math.floor((min(p0[1], p1[1]) - a) / h) * h - phase * h
    base = [p0, p1, [p1[0], bottom], [left, bottom], [left, p5[1]], p5]
    (g0x, g0y), (g1x, g1y) = scene["grid"]["min"], scene["grid"]["max"]
    pts = [place(p) for p in ([g0x, g0y], [g1x, g0y], [g1x, g1y], [g0x, g1y])]
    top_right = [max(p[0] for p in pts) + 2 * h, max(p[1] for p in pts) + 2 * h]
    tool = scene["rigid_body"][0]

    out = ["# Generated by tools/grid_orientation_study.py: the cut of the preset scene below, rotated by "
           f"{angle_deg:g} deg against the grid."]
    out.append(f"title = {toml_value(scene.get('title', 'cut') + f' rotated {angle_deg:g} deg')}")
    out.append(table("grid", {"cell_size": h, "min": [left, bottom], "max": top_right}))
    out.append(table("boundaries", {"left": "fixed", "right": "free", "bottom": "fixed", "top": "free"}))
    out.append(table("solver", scene["solver"]))
    output = dict(scene["output"])
    output["snapshot_interval"] = scene["solver"]["end_time"] / 4
    out.append(table("output", output))
    out.append(table("thermal", scene["thermal"]))
    for m in scene["material"]:
        out.append(table("material", m, array=True))
    body = {k: v for k, v in work.items() if k != "rectangle"}
    turned = turned_lattice and angle_deg != 0
    if turned:
        body["lattice_angle_deg"] = float(angle_deg)
    if turned or phase != 0:
        body["lattice_origin"] = [0.0, 0.0]  # the workpiece's corner, which the rotation keeps at the origin
    body["polygon"] = [p0, p1, place([x1, y1]), p5]
    out.append(table("body", body, array=True))
    base_body = dict(body)
    base_body["name"] = "base"
    base_body["polygon"] = base
    out.append(table("body", base_body, array=True))
    rigid = dict(tool)
    rigid["polygon"] = [place(p) for p in tool["polygon"]]
    rigid["velocity"] = rotate(tool["velocity"], c, s)
    out.append(table("rigid_body", rigid, array=True))
    return "\n".join(out)


def tool_frame_record(run_dir, angle_deg):
    """The rows of rigid_forces.csv in the tool's frame of a cut turned by angle_deg: (time s, tool travel m,
    Fc N/m along the cutting direction, Ft N/m normal to it)."""
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    with open(os.path.join(run_dir, "rigid_forces.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    record = []
    for r in rows:
        fx, fy = float(r["tool_force_x_N_per_m"]), float(r["tool_force_y_N_per_m"])
        record.append((float(r["time_s"]),
                       math.hypot(float(r["tool_displacement_x_m"]), float(r["tool_displacement_y_m"])),
                       c * fx + s * fy, -s * fx + c * fy))
    return record


def mean_tool_forces(run_dir, angle_deg):
    """Mean Fc, Ft (N/mm) over the second half of the tool travel, in the tool's frame."""
    record = tool_frame_record(run_dir, angle_deg)
    end = record[-1][0]
    fc = ft = 0.0
    n = 0
    for time, _, f_c, f_t in record:
        if time < 0.5 * end:
            continue
        fc += f_c / 1000.0
        ft += f_t / 1000.0
        n += 1
    return (fc / n, ft / n) if n else (float("nan"), float("nan"))


def force_wavelength(run_dir, angle_deg, cell):
    """The strongest oscillation of Fc (tool frame) over the second half of the tool's travel: its wavelength in tool
    travel (m) and amplitude over the mean Fc, among wavelengths from 3 cells to a third of that window (a Hann-weighted
    Fourier amplitude on the rows of rigid_forces.csv); NaN where the window is shorter than 9 cells. A cut whose bands
    are paced by the grid oscillates at the travel between two grid-row crossings, cell / sin(angle); one paced by the
    chip, at its segment spacing in travel, whatever the angle."""
    record = tool_frame_record(run_dir, angle_deg)
    travel = [u for _, u, _, _ in record]
    fc = [f_c for _, _, f_c, _ in record]
    half = 0.5 * travel[-1]
    pairs = [(u, f) for u, f in zip(travel, fc) if u >= half]
    if len(pairs) < 8 or travel[-1] - half < 9 * cell:
        return float("nan"), float("nan")
    u0, span = pairs[0][0], pairs[-1][0] - pairs[0][0]
    mean = sum(f for _, f in pairs) / len(pairs)
    hann = [math.sin(math.pi * (u - u0) / span) ** 2 for u, _ in pairs]
    best = (float("nan"), 0.0)
    steps = 200
    for k in range(steps + 1):
        wavelength = 3 * cell + (span / 3 - 3 * cell) * k / steps
        a = sum(w * (f - mean) * math.cos(2 * math.pi * u / wavelength) for w, (u, f) in zip(hann, pairs))
        b = sum(w * (f - mean) * math.sin(2 * math.pi * u / wavelength) for w, (u, f) in zip(hann, pairs))
        amplitude = 2 * math.hypot(a, b) / sum(hann)
        if amplitude > best[1]:
            best = (wavelength, amplitude)
    return (best[0], best[1] / abs(mean)) if mean else (float("nan"), float("nan"))


def summary_of(run_dir):
    with open(os.path.join(run_dir, "summary.json")) as f:
        return json.load(f)


def last_snapshot(run_dir):
    """The last snapshot particles.pvd lists: its file (relative to run_dir) and time (s)."""
    last = list(ET.parse(os.path.join(run_dir, "particles.pvd")).getroot().iter("DataSet"))[-1]
    return last.get("file"), float(last.get("timestep"))


def chip_in_tool_frame(binary, preset, run_dir, angle_deg, corner):
    """The chip analysis (`mpmcut analyze`, docs/analysis.md) of a turned run's last snapshot in the preset's frame.

    RUN_DIR_tool_frame gets the preset's scene.toml (the cut's parameters), the run's summary.json and the snapshot
    turned back by -angle_deg about the turned workpiece's corner (the origin, rotated_scene) onto the preset's corner;
    the analysis merges its "chip" section there. A rerun reuses a complete one."""
    d = run_dir + "_tool_frame"
    if os.path.exists(os.path.join(d, "summary.json")):
        chip = summary_of(d).get("chip")
        if chip:
            return chip
    file, time = last_snapshot(run_dir)
    os.makedirs(os.path.dirname(os.path.join(d, file)), exist_ok=True)
    turn_snapshot(os.path.join(run_dir, file), os.path.join(d, file), -angle_deg, (0.0, 0.0), corner)
    with open(os.path.join(d, "particles.pvd"), "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">\n'
                f'  <Collection>\n    <DataSet timestep="{time!r}" group="" part="0" file="{file}"/>\n'
                "  </Collection>\n</VTKFile>\n")
    shutil.copy(os.path.join(preset, "scene.toml"), d)
    shutil.copy(os.path.join(run_dir, "summary.json"), d)
    if run([binary, "analyze", d], d + ".log") != 0:
        print(f"note: no chip analysis of {run_dir} (see {d}.log)")
        return None
    return summary_of(d).get("chip")


def plot_final_chips(out, cell_tags, variants_of):
    """grid_orientation.png: the last snapshot of every variant, turned back into the tool's frame, coloured by damage
    (one row per cell size). Needs matplotlib and meshio; skipped with a note without them."""
    try:
        import glob
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import meshio
        import numpy as np
    except ImportError as e:
        print(f"note: no grid_orientation.png ({e})")
        return
    columns = max(len(v) for v in variants_of.values())
    fig, axes = plt.subplots(len(cell_tags), columns, figsize=(3.0 * columns, 3.0 * len(cell_tags)), squeeze=False)
    sc = None  # the last scatter drawn: the colour bar's source (none when no run wrote a snapshot)
    for i, tag in enumerate(cell_tags):
        for j in range(columns):
            ax = axes[i][j]
            ax.set_axis_off()
            if j >= len(variants_of[tag]):
                continue
            name, run_dir, angle = variants_of[tag][j]
            files = sorted(glob.glob(os.path.join(run_dir, "snapshots", "*.vtu")))
            if not files:
                continue
            m = meshio.read(files[-1])
            c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
            x, y = m.points[:, 0], m.points[:, 1]
            # Back into the tool's frame (about the grid's origin: the shift is the same for every particle).
            u, v = c * x + s * y, -s * x + c * y
            keep = m.point_data["body_id"] == 0  # the workpiece, not the base
            sc = ax.scatter(u[keep] * 1e3, v[keep] * 1e3, c=m.point_data["damage"][keep], s=1.0, cmap="inferno",
                            vmin=0.0, vmax=1.0, rasterized=True)
            ax.set_aspect("equal")
            # Around the chip: its highest particle, the tool (moving to -x) to its right.
            k = int(np.argmax(np.where(keep, v, -np.inf)))
            ax.set_xlim(u[k] * 1e3 - 0.3, u[k] * 1e3 + 0.2)
            ax.set_ylim(v[k] * 1e3 - 0.4, v[k] * 1e3 + 0.05)
            ax.set_title(f"{tag}, {name}" + (" deg" if name != "preset" else ""), fontsize=9)
    if sc is None:
        print("note: no grid_orientation.png (no run wrote a snapshot)")
        plt.close(fig)
        return
    fig.colorbar(sc, ax=axes, shrink=0.6, label="damage D")
    fig.savefig(os.path.join(out, "grid_orientation.png"), dpi=150)
    plt.close(fig)


def main(argv):
    a = parse_args(argv)
    os.makedirs(a["out"], exist_ok=True)
    rows = []
    variants_of = {}
    for h in a["cells"]:
        tag = f"{h * 1e6:g}um"
        preset = os.path.join(a["out"], f"preset_{tag}")
        sets = [x for s in a["sets"] for x in ("--set", s)]
        base = [a["binary"], "run", a["case"], "--set", f"cutting.cell_size={h!r}", *sets, "--no-plots",
                "--no-progress", "--threads", str(a["threads"])]
        # The preset itself, whole (its scene.toml is the one rotated; its forces are the fixed-sides reference).
        code = run(base + ["--out", preset, "--keep-complete"], preset + ".log")
        if not os.path.exists(os.path.join(preset, "scene.toml")):
            sys.exit(f"error: {a['case']} at cell {h:g} m did not start (exit {code}); see {preset}.log")
        with open(os.path.join(preset, "scene.toml"), "rb") as f:
            scene = tomllib.load(f)
        variants = [("preset", preset, code, 0.0)]
        for angle in a["angles"]:
            d = os.path.join(a["out"], f"rotated_{angle:g}deg_{tag}")
            case = d + ".toml"
            with open(case, "w") as f:
                f.write(rotated_scene(scene, angle, a["lattice"] == "turned", a["phase"]))
            print(f"cell {tag}, {angle:g} deg ...", flush=True)
            code = run([a["binary"], "run", case, "--out", d, "--keep-complete", "--no-plots", "--no-progress",
                        "--threads", str(a["threads"])], d + ".log")
            variants.append((f"{angle:g}", d, code, angle))
        variants_of[tag] = [(name, d, angle) for name, d, code, angle in variants]
        corner = workpiece_of(scene)["rectangle"]["min"]
        for name, d, code, angle in variants:
            try:
                s = summary_of(d)
            except (OSError, ValueError):
                rows.append({"cell_um": h * 1e6, "angle_deg": name, "status": f"no summary (exit {code})"})
                continue
            chip = s.get("chip") if name == "preset" else None
            if name != "preset" and s.get("status") == "complete":
                chip = chip_in_tool_frame(a["binary"], preset, d, angle, corner)
            chip = chip or {}
            num = lambda v: float(v) if isinstance(v, (int, float)) else float("nan")  # noqa: E731  (None: none)
            fc, ft = mean_tool_forces(d, angle)
            wavelength, oscillation = force_wavelength(d, angle, h)
            e = s.get("energy_J_per_m", {})
            work = e.get("external_work", float("nan"))
            frac = lambda k: e.get(k, float("nan")) / work if work else float("nan")  # noqa: E731
            rows.append({"cell_um": h * 1e6, "angle_deg": name, "status": s.get("status", "?"),
                         "Fc_N_per_mm": fc, "Ft_N_per_mm": ft, "tool_work_J_per_m": work,
                         "plastic_fraction": frac("plastic_work"), "damage_fraction": frac("damage_dissipation"),
                         "friction_fraction": frac("friction_work"),
                         "damage_J_per_m": e.get("damage_dissipation", float("nan")),
                         "chip_type": chip.get("classification", ""),
                         "chip_thickness_um": num(chip.get("mean_thickness_m")) * 1e6,
                         "pitch_um": num(chip.get("pitch_m")) * 1e6,
                         "segmentation_degree": num(chip.get("segmentation_degree")),
                         "grid_row_period_um": h * 1e6 / math.sin(math.radians(angle)) if angle > 0 else float("nan"),
                         "force_wavelength_um": wavelength * 1e6, "force_oscillation_percent": 100 * oscillation,
                         "wall_time_s": s.get("wall_time_s", float("nan"))})
    keys = ["cell_um", "angle_deg", "status", "Fc_N_per_mm", "Ft_N_per_mm", "tool_work_J_per_m", "plastic_fraction",
            "damage_fraction", "friction_fraction", "damage_J_per_m", "chip_type", "chip_thickness_um", "pitch_um",
            "segmentation_degree", "grid_row_period_um", "force_wavelength_um", "force_oscillation_percent",
            "wall_time_s"]
    with open(os.path.join(a["out"], "grid_orientation.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{r[k]:.6g}" if isinstance(r.get(k), float) else r.get(k, "")) for k in keys})
    fmt = lambda v, d: (f"{v:.{d}f}" if isinstance(v, float) and math.isfinite(v) else "–")  # noqa: E731
    with open(os.path.join(a["out"], "grid_orientation.md"), "w") as f:
        f.write(f"# The cut of {a['case']} rotated against the grid\n\n"
                "Mean tool forces over the second half of the cut in the tool's frame (N/mm); the tool's work "
                "(J/m) and its partition (fractions of it); the damage dissipation (J/m). \"preset\": the "
                "case as the program builds it; the angles: the same scene rotated, on a base that fills the wedge "
                "down to the grid's fixed sides, "
                + ("seeded on the particle lattice turned with them. " if a["lattice"] == "turned" else
                   "seeded on the grid's own particle lattice (rotated sides in steps). ")
                + (f"The grid moved down by {a['phase']:g} cell under the particles (--phase). " if a["phase"] else "")
                + "The chip (docs/analysis.md) from the last snapshot turned back into the "
                "tool's frame: type, mean thickness and pitch (µm), segmentation degree; the grid-row period is the tool's "
                "travel between two crossings of a grid row, cell / sin(angle) (µm); the strongest oscillation of Fc "
                "over the second half of the travel: its wavelength in travel (µm) and amplitude (% of the mean).\n\n"
                "| cell (µm) | angle (°) | status | Fc | Ft | tool work | plastic | damage | friction | damage (J/m) | "
                "chip | thickness | pitch | Gs | grid-row period | Fc wavelength | Fc oscillation |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write(f"| {r['cell_um']:g} | {r['angle_deg']} | {r['status']} | {fmt(r.get('Fc_N_per_mm'), 1)} | "
                    f"{fmt(r.get('Ft_N_per_mm'), 1)} | {fmt(r.get('tool_work_J_per_m'), 2)} | "
                    f"{fmt(r.get('plastic_fraction'), 3)} | {fmt(r.get('damage_fraction'), 3)} | "
                    f"{fmt(r.get('friction_fraction'), 3)} | {fmt(r.get('damage_J_per_m'), 2)} | "
                    f"{r.get('chip_type') or '–'} | {fmt(r.get('chip_thickness_um'), 1)} | {fmt(r.get('pitch_um'), 1)} | "
                    f"{fmt(r.get('segmentation_degree'), 2)} | {fmt(r.get('grid_row_period_um'), 1)} | "
                    f"{fmt(r.get('force_wavelength_um'), 1)} | {fmt(r.get('force_oscillation_percent'), 1)} |\n")
    plot_final_chips(a["out"], list(variants_of), variants_of)
    print(f"wrote {os.path.join(a['out'], 'grid_orientation.csv')}, grid_orientation.md and grid_orientation.png")
    return 0 if all(r["status"] == "complete" for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
