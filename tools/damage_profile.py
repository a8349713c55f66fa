#!/usr/bin/env python3
"""Damage across the chip: dissipation density and mean damage against depth below the chip's free surface.

usage: /usr/bin/python3 tools/damage_profile.py RESULT_DIR [--snapshot N] [--from-um A] [--to-um B]
                                                  [--bin-um W] [--csv FILE]

Takes the chip where it runs along the rake face (docs/analysis.md, "Where the damage sits"): workpiece particles
in front of the rake face, from where the face stands A µm above the workpiece's uncut surface to where it stands
B µm above it (clear of the chip root; default 20 to 120 µm). In strips of half a cell along the face, the particle farthest from the face marks the free
surface there; each particle's depth is its distance below it. In bins of W µm of depth (default 5) it prints the
damage dissipation per unit initial volume (MJ/m^3: the particles' damage_dissipation_J_per_m over their number
times the initial particle area (h/n)^2, n particles per cell and direction), the mean damage D and the particle
count. A dissipation that stands for cracks grows as 1/h in the bins a crack crosses; one smeared over a physical
layer keeps its density as the cell shrinks.

Needs a cutting run (scene.toml with [cutting_process]; the tool is the first rigid body, its polygon's first
vertex the edge centre) and its snapshots (particles.pvd); reads them with meshio.
"""
import argparse
import csv
import math
import pathlib
import sys
import tomllib
import xml.etree.ElementTree as ET

import numpy as np


def snapshot_files(result_dir):
    """(time, path) of every snapshot in particles.pvd, in time order."""
    root = ET.parse(result_dir / "particles.pvd").getroot()
    items = [(float(d.get("timestep")), result_dir / d.get("file")) for d in root.iter("DataSet")]
    return sorted(items)


def profile(result_dir, snapshot=-1, from_um=20.0, to_um=120.0, bin_um=5.0):
    """Rows (depth_from_um, depth_to_um, dissipation_MJ_per_m3, mean_damage, particles) and the snapshot's time."""
    import meshio

    result_dir = pathlib.Path(result_dir)
    scene = tomllib.loads((result_dir / "scene.toml").read_text())
    if "cutting_process" not in scene:
        raise SystemExit(f"error: {result_dir}/scene.toml has no [cutting_process]: not a cutting run")
    h = scene["grid"]["cell_size"]
    body = scene["body"][0]
    uncut_surface_y = body["rectangle"]["max"][1]
    n_per_cell = body.get("particles_per_cell", 2)
    tool = scene["rigid_body"][0]
    r = tool.get("rounding_radius", 0.0)
    alpha = math.radians(scene["cutting_process"]["rake_angle_deg"])
    up = np.array([math.sin(alpha), math.cos(alpha)])       # along the rake face, away from the edge
    out = np.array([-math.cos(alpha), math.sin(alpha)])     # the face's normal into the chip
    snaps = snapshot_files(result_dir)
    if not snaps:
        raise SystemExit(f"error: {result_dir}/particles.pvd lists no snapshot")
    time, path = snaps[snapshot]
    # The tool moves at its constant velocity: where it is at the snapshot's time.
    face_start = np.array(tool["polygon"][0]) + r * out + time * np.array(tool["velocity"])
    m = meshio.read(path)
    xy = m.points[:, :2]
    body_id = m.point_data["body_id"]
    dissipation = m.point_data["damage_dissipation_J_per_m"]
    damage = m.point_data["damage"]
    rel = xy - face_start
    s = rel @ up
    d = rel @ out
    # Whole strips along the face: from where the face is A above the uncut surface to where it is B above it.
    s_from, s_to = ((uncut_surface_y + z * 1e-6 - face_start[1]) / up[1] for z in (from_um, to_um))
    sel = (body_id == 0) & (s >= s_from) & (s <= s_to) & (d > -0.5 * h)
    if not sel.any():
        raise SystemExit(f"error: no workpiece particle {from_um}-{to_um} µm above the uncut surface in {path}")
    s, d, dissipation, damage = s[sel], d[sel], dissipation[sel], damage[sel]
    strip = np.floor(s / (0.5 * h)).astype(int)
    depth = np.empty_like(d)
    for k in np.unique(strip):
        i = strip == k
        depth[i] = d[i].max() - d[i]
    area = (h / n_per_cell) ** 2
    rows = []
    edges = np.arange(0.0, depth.max() + bin_um * 1e-6, bin_um * 1e-6)
    for a, b in zip(edges[:-1], edges[1:]):
        i = (depth >= a) & (depth < b)
        if i.any():
            rows.append((a * 1e6, b * 1e6, dissipation[i].sum() / (i.sum() * area) / 1e6, damage[i].mean(), int(i.sum())))
    return rows, time


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("result_dir", type=pathlib.Path)
    p.add_argument("--snapshot", type=int, default=-1, help="snapshot index in particles.pvd (default: the last)")
    p.add_argument("--from-um", type=float, default=20.0)
    p.add_argument("--to-um", type=float, default=120.0)
    p.add_argument("--bin-um", type=float, default=5.0)
    p.add_argument("--csv", type=pathlib.Path, help="also write the rows to this CSV file")
    a = p.parse_args(argv)
    if not (a.bin_um > 0 and a.to_um > a.from_um):
        p.error("need --bin-um > 0 and --to-um > --from-um")
    rows, time = profile(a.result_dir, a.snapshot, a.from_um, a.to_um, a.bin_um)
    print(f"# {a.result_dir}: snapshot at t = {time * 1e6:.2f} µs, chip {a.from_um:g}-{a.to_um:g} µm above the uncut surface")
    print("depth_from_um,depth_to_um,damage_dissipation_MJ_per_m3,mean_damage,particles")
    for row in rows:
        print(f"{row[0]:g},{row[1]:g},{row[2]:.4g},{row[3]:.4g},{row[4]}")
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["depth_from_um", "depth_to_um", "damage_dissipation_MJ_per_m3", "mean_damage", "particles"])
            w.writerows(rows)


if __name__ == "__main__":
    main(sys.argv[1:])
