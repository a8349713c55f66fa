"""End to end: tools/grid_orientation_study.py, the cut rotated against the grid.

usage: /usr/bin/python3 test_grid_orientation.py MPMCUT_BINARY SCRATCH_DIR
The tiny coarse cut of tests/support/cases/tiny_cut.toml (25 um cells, about a second a run) as the preset builds it,
and the same scene on the study's base at 0 and 30 deg. Checks:
- every run completes and grid_orientation.csv / .md list the preset and both angles;
- at 0 deg the base (a strip three cells thick held by the grid's fixed sides) stands in for the preset's fixed
  sides: Fc within 3 % and Ft within 6 % of the preset's (measured 190.2 / 67.6 against 193.0 / 69.2 N/mm);
- at 30 deg the forces, turned back into the tool's frame, are those of the same cut: Fc within 10 % and Ft within
  15 % of 0 deg's (measured +3.7 % and +0.4 %); turning them the wrong way would move Fc by about Ft (35 %);
- every run's chip is analysed (the turned ones in the tool's frame): a chip type in every row;
- the turn back into the tool's frame is exact: the preset's last snapshot turned by +30 deg about the workpiece's
  corner, as rotated_scene places a turned cut, and analysed as a turned run gives the preset's own chip (type,
  thickness, pitch, segmentation degree to 1e-6); turned back the wrong way it finds 249 particles and 433 um
  instead of 30 and 108 um;
- Fc's strongest oscillation is found: on a made-up force record of a cut turned by 30 deg whose Fc oscillates by
  5 % with a wavelength of 80 um of travel (and Ft by 20 % at 50 um), the wavelength within 3 % and the amplitude
  within 10 % of 5 %;
- a rerun keeps the complete runs (their summary.json untouched) and writes the same table;
- with --lattice turned the 30 deg workpiece is the preset's turned: its particles at the start, turned back about
  the corner, sit on the preset's own sub-grid squares, every one of them and no other (on the grid's lattice the
  same check finds particles off those squares), and its forces are again within 10 % / 15 % of 0 deg's;
- with --phase 0.25 the 0 deg cut's grid lies a quarter cell lower (its node rows a quarter cell off the tool's
  tip) under the same workpiece particles (a quarter cell is half a particle spacing: particles seeded on the grid's
  own lattice would have moved onto the squares' sides).
"""
import csv
import math
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_checks import fail  # noqa: E402

sys.path.insert(0, os.path.join(ROOT, "tools"))
import grid_orientation_study as study  # noqa: E402
from snapshot_transform import turn_snapshot  # noqa: E402


def rows_of(out):
    with open(os.path.join(out, "grid_orientation.csv"), newline="") as f:
        return {r["angle_deg"]: r for r in csv.DictReader(f)}


def check_force_wavelength(scratch):
    d = os.path.join(scratch, "made_up_forces")
    os.makedirs(d)
    angle, speed, wavelength = 30.0, 20.0, 80e-6
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    with open(os.path.join(d, "rigid_forces.csv"), "w") as f:
        f.write("time_s,tool_force_x_N_per_m,tool_force_y_N_per_m,tool_displacement_x_m,tool_displacement_y_m\n")
        for k in range(401):
            t = k * 0.15e-6
            u = speed * t
            fc = 150e3 * (1 + 0.05 * math.sin(2 * math.pi * u / wavelength))
            ft = 50e3 * (1 + 0.2 * math.sin(2 * math.pi * u / 50e-6))
            # the tool moves along -(c, s); Fc along (c, s), Ft along (-s, c) (study.mean_tool_forces)
            f.write(f"{t!r},{c * fc - s * ft!r},{s * fc + c * ft!r},{-c * u!r},{-s * u!r}\n")
    found, amplitude = study.force_wavelength(d, angle, 8e-6)
    print(f"made-up Fc oscillation: {found * 1e6:.1f} um, {100 * amplitude:.2f} %")
    if abs(found / wavelength - 1) > 0.03 or abs(amplitude / 0.05 - 1) > 0.1:
        fail(f"Fc oscillation found at {found * 1e6:.1f} um with {100 * amplitude:.2f} % (made: 80 um, 5 %)")


def workpiece_squares(run_dir, angle_deg, corner, spacing):
    """The workpiece's particles in the first snapshot, turned back by angle_deg about the origin onto `corner`, as
    sub-grid squares (k, l) counted from the corner; and the largest distance of a particle from its square's centre,
    in spacings."""
    import meshio
    import numpy as np
    with open(os.path.join(run_dir, "scene.toml"), "rb") as f:
        names = [b["name"] for b in study.tomllib.load(f)["body"]]
    m = meshio.read(os.path.join(run_dir, "snapshots", "particles_000000.vtu"))
    p = m.points[m.point_data["body_id"].ravel() == names.index("workpiece"), :2]
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    if angle_deg != 0:
        p = np.column_stack([c * p[:, 0] + s * p[:, 1], -s * p[:, 0] + c * p[:, 1]]) + np.asarray(corner)
    u = (p - np.asarray(corner)) / spacing - 0.5
    squares = np.rint(u)
    return {(int(a), int(b)) for a, b in squares}, float(np.abs(u - squares).max()), len(p)


def study_command(binary, out, *options):
    return ["/usr/bin/python3", os.path.join(ROOT, "tools", "grid_orientation_study.py"), binary,
            os.path.join(ROOT, "tests", "support", "cases", "tiny_cut.toml"), out, "--cells", "25e-6", "--angles", "0,30",
            *options]


def run_study(cmd, names=("0", "30", "preset")):
    """Runs the study; its rows, every one complete, named `names` (the preset and the angles)."""
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    print(p.stdout, p.stderr, sep="\n")
    if p.returncode != 0:
        fail(f"{' '.join(cmd[2:])}: exit status {p.returncode}")
    rows = rows_of(cmd[4])
    if sorted(rows) != sorted(names):
        fail(f"grid_orientation.csv rows: {sorted(rows)}")
    for name, r in rows.items():
        if r["status"] != "complete":
            fail(f"{name}: status {r['status']}")
    return rows


def check_turned_forces(rows, what):
    """Fc and Ft of the 30 deg cut within 10 % and 15 % of 0 deg's; the forces by row."""
    fc = {k: float(r["Fc_N_per_mm"]) for k, r in rows.items()}
    ft = {k: float(r["Ft_N_per_mm"]) for k, r in rows.items()}
    print(f"{what} Fc: {fc}\nFt: {ft}")
    if abs(fc["30"] / fc["0"] - 1) > 0.10 or abs(ft["30"] / ft["0"] - 1) > 0.15:
        fail(f"{what}, 30 deg against 0 deg: Fc {fc['30']:.1f} / {fc['0']:.1f}, Ft {ft['30']:.1f} / {ft['0']:.1f}")
    return fc, ft


def check_turned_lattice(binary, scratch, grid_lattice_out):
    out = os.path.join(scratch, "study_turned")
    rows = run_study(study_command(binary, out, "--lattice", "turned"))
    with open(os.path.join(out, "preset_25um", "scene.toml"), "rb") as f:
        work = study.workpiece_of(study.tomllib.load(f))
    corner = work["rectangle"]["min"]
    spacing = 25e-6 / work["particles_per_cell"]
    preset, off, n = workpiece_squares(os.path.join(out, "preset_25um"), 0.0, corner, spacing)
    turned, off_turned, n_turned = workpiece_squares(os.path.join(out, "rotated_30deg_25um"), 30.0, corner, spacing)
    print(f"turned lattice: {n_turned} workpiece particles, {off_turned:.2e} spacings off their squares "
          f"(preset {n}, {off:.2e})")
    if n_turned != n or turned != preset or off_turned > 1e-6:
        fail(f"turned lattice: {n_turned} particles ({n} in the preset), {len(turned ^ preset)} squares differ, "
             f"{off_turned:.2e} spacings off")
    _, off_grid, _ = workpiece_squares(os.path.join(grid_lattice_out, "rotated_30deg_25um"), 30.0, corner, spacing)
    if off_grid < 0.1:
        fail(f"the grid's lattice turned back sits on the squares too ({off_grid:.2e} spacings off): no check")
    check_turned_forces(rows, "turned lattice")


def check_phase(binary, scratch, phase_0_out):
    out = os.path.join(scratch, "study_phase")
    run_study(study_command(binary, out, "--angles", "0", "--phase", "0.25"), ("0", "preset"))
    grid_min = {}
    for name, d in (("phase 0", phase_0_out), ("phase 0.25", out)):
        with open(os.path.join(d, "rotated_0deg_25um", "scene.toml"), "rb") as f:
            grid_min[name] = study.tomllib.load(f)["grid"]["min"]
    shift = [(a - b) / 25e-6 for a, b in zip(grid_min["phase 0"], grid_min["phase 0.25"])]
    print(f"--phase 0.25 moved the grid by {shift} cells")
    if abs(shift[0]) > 1e-9 or abs(shift[1] - 0.25) > 1e-9:
        fail(f"--phase 0.25 moved the grid by {shift} cells, not [0, 0.25]")
    with open(os.path.join(out, "preset_25um", "scene.toml"), "rb") as f:
        work = study.workpiece_of(study.tomllib.load(f))
    corner, spacing = work["rectangle"]["min"], 25e-6 / work["particles_per_cell"]
    squares = {name: workpiece_squares(os.path.join(d, "rotated_0deg_25um"), 0.0, corner, spacing)
               for name, d in (("phase 0", phase_0_out), ("phase 0.25", out))}
    if squares["phase 0.25"][0] != squares["phase 0"][0] or squares["phase 0.25"][1] > 1e-6:
        fail(f"--phase 0.25 moved the workpiece's particles: {squares['phase 0.25'][2]} particles, "
             f"{squares['phase 0.25'][1]:.2e} spacings off their squares")


def main(binary, scratch):
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    check_force_wavelength(scratch)
    out = os.path.join(scratch, "study")
    cmd = study_command(binary, out)
    rows = run_study(cmd)
    if not os.path.isfile(os.path.join(out, "grid_orientation.md")):
        fail("grid_orientation.md missing")
    fc, ft = check_turned_forces(rows, "grid lattice")
    if abs(fc["0"] / fc["preset"] - 1) > 0.03 or abs(ft["0"] / ft["preset"] - 1) > 0.06:
        fail(f"0 deg on the base against the preset: Fc {fc['0']:.1f} / {fc['preset']:.1f}, Ft {ft['0']:.1f} / "
             f"{ft['preset']:.1f}")

    for name, r in rows.items():
        if not r["chip_type"]:
            fail(f"{name}: no chip analysis")
    print("chips:", {k: (r["chip_type"], r["chip_thickness_um"], r["pitch_um"]) for k, r in rows.items()})

    # The turn back, checked on the preset's own last snapshot turned as a 30 deg run would hold it.
    preset = os.path.join(out, "preset_25um")
    with open(os.path.join(preset, "scene.toml"), "rb") as f:
        corner = study.workpiece_of(study.tomllib.load(f))["rectangle"]["min"]
    reference = study.chip_in_tool_frame(binary, preset, preset, 0.0, (0.0, 0.0))
    turned = os.path.join(scratch, "turned_30deg")
    file, time = study.last_snapshot(preset)
    os.makedirs(os.path.dirname(os.path.join(turned, file)))
    turn_snapshot(os.path.join(preset, file), os.path.join(turned, file), 30.0, corner, (0.0, 0.0))
    shutil.copy(os.path.join(preset, "particles.pvd"), turned)  # lists earlier snapshots too: only the last is read
    shutil.copy(os.path.join(preset, "summary.json"), turned)
    back = study.chip_in_tool_frame(binary, preset, turned, 30.0, corner)
    if not reference or not back:
        fail(f"no chip analysis: {reference!r} / {back!r}")
    for key in ("mean_thickness_m", "pitch_m", "segmentation_degree", "peak_height_m"):
        a, b = reference.get(key), back.get(key)
        if (a is None) != (b is None) or (a is not None and abs(a - b) > 1e-6 * abs(a)):
            fail(f"turned back, {key}: {b} against {a}")
    if reference["classification"] != back["classification"]:
        fail(f"turned back: {back['classification']} against {reference['classification']}")

    summary = os.path.join(out, "rotated_30deg_25um", "summary.json")
    before = os.stat(summary).st_mtime_ns
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        fail(f"rerun exit status {p.returncode}: {p.stderr}")
    if os.stat(summary).st_mtime_ns != before:
        fail("the rerun ran the complete 30 deg run again")
    if rows_of(out) != rows:
        fail("the rerun's table differs")
    check_turned_lattice(binary, scratch, out)
    check_phase(binary, scratch, out)
    print("OK")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
