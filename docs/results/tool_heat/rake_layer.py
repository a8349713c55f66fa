"""The material along the rake face at the end of a cutting run: damage, temperature and shear stress in the first
cells of material in front of the (0-degree) rake face, over the run's tool-chip contact length.

usage: /usr/bin/python3 docs/results/tool_heat/rake_layer.py RESULT_DIR [RESULT_DIR ...] > rake_layer.md

RESULT_DIR is a result directory of `mpmcut run` (or of a validate condition): its scene.toml (the tool's outline
and edge radius), summary.json (the tool's displacement, the contact length, the cell size) and the last snapshot
under snapshots/. Bands: particles whose x lies 0-1, 1-2 and 2-4 cells in front of the rake face, between the top
of the edge arc and the contact length above it. The tool's rake face must be vertical (rake angle 0).
"""
import glob
import json
import os
import re
import sys

import meshio
import numpy as np

MAX_DAMAGE = 0.999  # the material sets' max_damage: D at which a particle counts as failed


def bands(run_dir):
    scene = open(os.path.join(run_dir, "scene.toml")).read()
    tool = scene[scene.index("[[rigid_body]]"):]
    first = re.search(r"polygon = \[\[([0-9.eE+-]+), ([0-9.eE+-]+)\]", tool)
    r = float(re.search(r"rounding_radius = ([0-9.eE+-]+)", tool).group(1))
    rake = re.search(r"rake_angle_deg = ([0-9.eE+-]+)", scene)
    if rake and abs(float(rake.group(1))) > 1e-9:
        sys.exit(f"{run_dir}: rake angle {rake.group(1)} deg; this script reads a 0-degree rake face only")
    with open(os.path.join(run_dir, "summary.json")) as f:
        s = json.load(f)
    h = s["cell_size_m"]
    contact = s["tool_chip_contact_length_mm"] * 1e-3
    face_x = float(first.group(1)) + s["rigid_bodies"][0]["displacement_m"][0] - r  # the edge centre is vertex 0
    arc_top = float(first.group(2))  # the arc's centre: the flat face starts at its height
    m = meshio.read(sorted(glob.glob(os.path.join(run_dir, "snapshots", "*.vtu")))[-1])
    x, y, d = m.points[:, 0], m.points[:, 1], m.point_data
    rows = []
    for lo, hi in ((0, 1), (1, 2), (2, 4)):
        sel = (x < face_x - lo * h) & (x >= face_x - hi * h) & (y > arc_top) & (y < arc_top + contact)
        D, T, sxy = d["damage"][sel], d["temperature_K"][sel], d["stress_Pa"][sel][:, 3]
        failed = 100 * (D >= MAX_DAMAGE).mean()  # fully failed: no shear at all, whatever the pressure
        p = -d["stress_Pa"][sel][:, :3].mean(axis=1)
        rows.append((f"{lo}-{hi}", int(sel.sum()), D.mean(), 100 * (D > 0.5).mean(), failed, T.mean(), p.mean() / 1e6,
                     np.abs(sxy).mean() / 1e6))
    return contact, rows


def main(dirs):
    print("| run | contact (µm) | cells in front of the face | particles | mean D | D > 0.5 (%) | failed (%) | "
          "mean T (K) | mean pressure (MPa) | mean abs(σ_xy) (MPa) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for run_dir in dirs:
        contact, rows = bands(run_dir)
        name = "/".join(os.path.normpath(run_dir).split(os.sep)[-2:])
        for band, n, D, over, failed, T, p, sxy in rows:
            print(f"| {name} | {contact * 1e6:.0f} | {band} | {n} | {D:.2f} | {over:.0f} | {failed:.0f} | {T:.0f} | "
                  f"{p:.0f} | {sxy:.0f} |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
