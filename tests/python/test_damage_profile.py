"""tools/damage_profile.py on a chip of known damage (no simulation).

usage: /usr/bin/python3 test_damage_profile.py MPMCUT_BINARY SCRATCH_DIR   (the binary is not used)
A straight chip 60 µm thick lies against the rake face of a tool with a 10 degree rake angle and a 20 µm edge radius
that has moved for 3 µs at 2 m/s. Its particles (a lattice of 2 x 2 per 8 µm cell, aligned with the face) carry a
damage dissipation of 300 MJ/m^3 in the 8 µm below the free surface, 900 MJ/m^3 in the 8 µm next to the rake face
and none in between, and D = 0.2 / 0.6 / 0. The profile must give these densities in its 4 µm depth bins (a rake
face frame, a tool position or a particle area off by a few per cent would show), nothing in the middle, and no
particle from beyond the chip's height window or behind the face.
"""
import math
import os
import shutil
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import damage_profile  # noqa: E402

H = 8e-6           # cell
N = 2              # particles per cell and direction
ALPHA = math.radians(10.0)
R = 20e-6          # edge radius
CORE0 = np.array([1.0e-3, 0.3e-3])  # edge centre at t = 0
VELOCITY = np.array([-2.0, 0.0])
TIME = 3e-6
TOP = 0.4e-3       # uncut surface
THICKNESS = 60e-6


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def write_case(d):
    up = np.array([math.sin(ALPHA), math.cos(ALPHA)])
    out = np.array([-math.cos(ALPHA), math.sin(ALPHA)])
    face_start = CORE0 + R * out + TIME * VELOCITY
    step = H / N
    points, dissipation, damage = [], [], []
    area = step * step
    for i in range(int(round(THICKNESS / step))):
        dist = (i + 0.5) * step              # from the face
        depth = THICKNESS - dist             # below the free surface (the outermost particle's is step / 2)
        for j in range(-20, 80):
            p = face_start + (j + 0.5) * step * up + dist * out
            points.append([p[0], p[1], 0.0])
            if dist < 8e-6:
                rho, dmg = 900e6, 0.6
            elif depth < 8e-6 + step / 2:
                rho, dmg = 300e6, 0.2
            else:
                rho, dmg = 0.0, 0.0
            dissipation.append(rho * area)
            damage.append(dmg)
    # A decoy behind the rake face (inside the tool), which must be left out.
    points.append([*(face_start + 40e-6 * up - 30e-6 * out), 0.0])
    dissipation.append(1.0)
    damage.append(1.0)
    import meshio

    pts = np.array(points)
    n = len(pts)
    os.makedirs(os.path.join(d, "snapshots"))
    meshio.write(os.path.join(d, "snapshots", "particles_000001.vtu"),
                 meshio.Mesh(pts, [("vertex", np.arange(n).reshape(-1, 1))],
                             point_data={"body_id": np.zeros(n, dtype=np.int32),
                                         "damage_dissipation_J_per_m": np.array(dissipation),
                                         "damage": np.array(damage)}))
    with open(os.path.join(d, "particles.pvd"), "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n'
                '<DataSet timestep="0" file="snapshots/particles_000000.vtu"/>\n'
                f'<DataSet timestep="{TIME!r}" file="snapshots/particles_000001.vtu"/>\n</Collection>\n</VTKFile>\n')
    poly = [CORE0.tolist(), [1.2e-3, 0.33e-3], [1.2e-3, 0.6e-3], [float(CORE0[0] + 0.3e-3 * math.tan(ALPHA)), 0.6e-3]]
    with open(os.path.join(d, "scene.toml"), "w") as f:
        f.write(f"[grid]\ncell_size = {H!r}\n[[body]]\nname = \"workpiece\"\nrectangle = {{ min = [0.0, 0.0], max = "
                f"[1.0e-3, {TOP!r}] }}\nparticles_per_cell = {N}\n[[rigid_body]]\nname = \"tool\"\npolygon = {poly}\n"
                f"rounding_radius = {R!r}\nvelocity = [{VELOCITY[0]!r}, 0.0]\n[cutting_process]\nrake_angle_deg = 10\n")


def main(scratch):
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    write_case(scratch)
    # 2.9 µm bins: the lattice's depths (multiples of 4 µm, up to 56 µm) stay clear of every bin edge but 0.
    rows, time = damage_profile.profile(scratch, -1, 10.0, 150.0, 2.9)
    if abs(time - TIME) > 1e-15:
        fail(f"snapshot time {time} s, expected the last one, {TIME} s")
    step = H / N
    layers = int(round(THICKNESS / step))
    depths = [k * step for k in range(layers)]  # below the outermost particle
    # The writer's layers: the two outermost at 300 MJ/m^3, D 0.2; the two next to the face at 900, D 0.6.
    value = {0: (300.0, 0.2), 1: (300.0, 0.2), layers - 2: (900.0, 0.6), layers - 1: (900.0, 0.6)}
    seen = 0
    for a, b, rho, dmg, count in rows:
        print(f"{a:5.1f}-{b:5.1f} µm: {rho:7.1f} MJ/m^3, D {dmg:.3f}, {count} particles")
        ks = [k for k, z in enumerate(depths) if a * 1e-6 - 1e-12 <= z < b * 1e-6]
        if len(ks) != 1:
            fail(f"bin {a:g}-{b:g} µm holds the lattice depths {ks}: the free surface or the face frame is off")
        rho_x, dmg_x = value.get(ks[0], (0.0, 0.0))
        if abs(rho - rho_x) > 1e-6 * max(rho_x, 1.0) or abs(dmg - dmg_x) > 1e-9:
            fail(f"bin {a:g}-{b:g} µm: {rho:.3f} MJ/m^3 and D {dmg:.3f}, expected {rho_x:g} and {dmg_x:g}")
        seen += 1
    if seen != layers:
        fail(f"{seen} bins with particles, expected one per layer of the chip ({layers}): the decoy behind the face "
             "was counted or a layer was lost")
    print("OK")


if __name__ == "__main__":
    main(sys.argv[2])
