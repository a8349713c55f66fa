"""End to end: `mpmcut sweep` over two cutting speeds on a tiny, coarse cut, then `mpmcut plot` on one case.

usage: /usr/bin/python3 test_plots_sweep.py MPMCUT_BINARY SCRATCH_DIR
Checks: the sweep exits 0 and prints the running cases' progress at --progress-every; a bad --progress-every exits 2
before anything is made; sweep.csv has one row per case, each complete with finite forces; sweep.md exists;
the chip galleries are drawn; every run drew its own pictures and analysed its chip over the steady window
(summary.json chip_over_time, its Gs statistics in sweep.csv);
forces_vs_speed.png, chip_vs_speed.png and chip_map.png are non-trivial PNGs; `mpmcut plot` writes forces.png and
the chip pictures (temperature, plastic strain, damage, combined) of the last snapshot and the chip profile, all
non-trivial; the chip map gives continuous, serrated and discontinuous chips three different colours.
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_checks import check_png, fail  # noqa: E402

# Three 25 um cells of tool travel at h = 0.1 mm (cell = t0/4, 1 particle per cell): about a second per case.
CASE = """\
title = "sweep test: tiny Ti-6Al-4V cut"
[cutting]
material = "ti64-johnson-1985"
cutting_speed = 20.0
uncut_chip_thickness = 0.1e-3
cut_length = 75e-6
cell_size = 25e-6
particles_per_cell = 1
snapshots = 2
"""


def main(binary, scratch):
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    case = os.path.join(scratch, "tiny.toml")
    with open(case, "w") as f:
        f.write(CASE)
    out = os.path.join(scratch, "sweep")
    t0 = time.time()
    # No --feeds: the case's own uncut chip thickness (0.1 mm) is the feed.
    # --progress-every 0.2s: the one-second cases get the progress line of the running cases (default: 10 min).
    p = subprocess.run([binary, "sweep", case, "--speeds", "20,50", "--jobs", "2", "--out", out,
                        "--progress-every", "0.2s"], capture_output=True, text=True, timeout=300)
    print(p.stdout, p.stderr, sep="\n")
    if p.returncode != 0:
        fail(f"sweep exit status {p.returncode}")
    if "running: v" not in p.stdout:
        fail("--progress-every 0.2s: no progress line of the running cases")
    bad = subprocess.run([binary, "sweep", case, "--speeds", "20", "--out", os.path.join(scratch, "bad"),
                          "--progress-every", "5x"], capture_output=True, text=True, timeout=60)
    if bad.returncode != 2 or "--progress-every: '5x': unknown unit 'x'" not in bad.stderr:
        fail(f"--progress-every 5x: exit {bad.returncode}, {bad.stderr}")
    if os.path.exists(os.path.join(scratch, "bad")):
        fail("--progress-every 5x made its result directory")
    print(f"sweep took {time.time() - t0:.1f} s")
    with open(os.path.join(out, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    if sorted(r["case"] for r in rows) != ["v20mps_h0.1mm", "v50mps_h0.1mm"]:
        fail(f"sweep.csv cases: {[r['case'] for r in rows]}")
    for r in rows:
        if r["status"] != "complete":
            fail(f"{r['case']}: status {r['status']} ({r['message']})")
        for key in ("mean_cutting_force_N_per_mm", "mean_thrust_force_N_per_mm", "max_temperature_K"):
            try:
                float(r[key])
            except ValueError:
                fail(f"{r['case']}: {key} = '{r[key]}' is not a number")
        if float(r["speed_m_per_min"]) != 60 * float(r["speed_m_per_s"]):
            fail(f"{r['case']}: m/min column inconsistent")
        check_chip_over_time(os.path.join(out, r["case"]), r)
    if not os.path.exists(os.path.join(out, "sweep.md")):
        fail("sweep.md missing")
    for name in ("forces_vs_speed.png", "chip_vs_speed.png", "chip_map.png"):
        check_png(os.path.join(out, name))
    for name in ("chip_gallery_damage.png", "chip_gallery_temperature.png"):
        check_png(os.path.join(out, name), min_colours=40)

    # Every complete cutting run draws its pictures at the end (run --no-plots would skip them).
    case_dir = os.path.join(out, "v20mps_h0.1mm")
    pictures = sorted(n for n in os.listdir(case_dir) if n.endswith(".png"))
    if "forces.png" not in pictures or not any(n.startswith("chip_") for n in pictures):
        fail(f"the run drew no pictures: {pictures}")
    for n in pictures:
        os.remove(os.path.join(case_dir, n))

    # Pictures of one case, again, by the plot command.
    t0 = time.time()
    p = subprocess.run([binary, "plot", case_dir], capture_output=True, text=True, timeout=300)
    print(p.stdout, p.stderr, sep="\n")
    if p.returncode != 0:
        fail(f"plot exit status {p.returncode}")
    print(f"plot took {time.time() - t0:.1f} s")
    last = sorted(n for n in os.listdir(os.path.join(case_dir, "snapshots")) if n.endswith(".vtu"))[-1]
    index = last.split("_")[-1].split(".")[0]
    check_png(os.path.join(case_dir, "forces.png"))
    for field in ("temperature", "plastic_strain", "damage"):
        check_png(os.path.join(case_dir, f"chip_{field}_{index}.png"), min_colours=40)
    check_png(os.path.join(case_dir, f"chip_{index}.png"), min_colours=40)
    check_png(os.path.join(case_dir, "chip_profile.png"), min_colours=10)
    # A missing directory is a clear error, not a crash.
    p = subprocess.run([binary, "plot", os.path.join(scratch, "no_such_dir")], capture_output=True, text=True)
    if p.returncode == 0:
        fail("plot of a missing directory exited 0")
    # A snapshot the run does not have is an error (it was a warning, and the last snapshot was drawn).
    for bad, words in (("999", "no such snapshot"), ("-1", "expected last, all"), ("1,x", "got 'x'")):
        p = subprocess.run([binary, "plot", case_dir, "--snapshots", bad], capture_output=True, text=True, timeout=60)
        if p.returncode != 2 or words not in p.stderr:
            fail(f"plot --snapshots {bad}: exit {p.returncode}, expected 2 naming '{words}': {p.stderr}")
    # A snapshot file gone from the directory: an error naming it (it was a Python traceback).
    gone = os.path.join(scratch, "snapshot_gone")
    shutil.copytree(case_dir, gone)
    os.remove(os.path.join(gone, "snapshots", last))
    p = subprocess.run([binary, "plot", gone], capture_output=True, text=True, timeout=60)
    if p.returncode != 2 or "is missing" not in p.stderr or last not in p.stderr or "Traceback" in p.stderr:
        fail(f"plot with a deleted snapshot: exit {p.returncode}: {p.stderr}")
    # A damaged snapshot or summary: exit 2 naming it (exit 1 after meshio's message; a broken summary was drawn
    # around with a warning, exit 0).
    damaged = os.path.join(scratch, "snapshot_damaged")
    shutil.copytree(case_dir, damaged)
    with open(os.path.join(damaged, "snapshots", last), "w") as f:
        f.write("garbage\n")
    p = subprocess.run([binary, "plot", damaged], capture_output=True, text=True, timeout=120)
    if p.returncode != 2 or "cannot read" not in p.stderr or last not in p.stderr or "Traceback" in p.stderr:
        fail(f"plot with a damaged snapshot: exit {p.returncode}: {p.stderr}")
    with open(os.path.join(damaged, "summary.json"), "w") as f:
        f.write("{\n")
    p = subprocess.run([binary, "plot", damaged], capture_output=True, text=True, timeout=60)
    if p.returncode != 2 or "summary.json cannot be read" not in p.stderr:
        fail(f"plot with a damaged summary.json: exit {p.returncode}: {p.stderr}")
    # An earlier snapshot's chip analysis is printed, not merged into the summary of the final state.
    with open(os.path.join(case_dir, "summary.json")) as f:
        before = f.read()
    p = subprocess.run([binary, "analyze", case_dir, "--snapshot", "1"], capture_output=True, text=True, timeout=120)
    with open(os.path.join(case_dir, "summary.json")) as f:
        after = f.read()
    if p.returncode != 0 or "not merged" not in p.stdout or after != before:
        fail(f"analyze --snapshot 1 changed the final state's summary or did not say so: exit {p.returncode}, "
             f"{p.stdout}{p.stderr}")
    # A snapshot without particles (meshio cannot read one: plot ended in a traceback) is skipped with a note.
    empty_dir = os.path.join(scratch, "empty_snapshot")
    shutil.copytree(case_dir, empty_dir)
    with open(os.path.join(empty_dir, "snapshots", last), "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian">\n'
                '  <UnstructuredGrid>\n    <Piece NumberOfPoints="0" NumberOfCells="0">\n    </Piece>\n'
                '  </UnstructuredGrid>\n</VTKFile>\n')
    p = subprocess.run([binary, "plot", empty_dir], capture_output=True, text=True, timeout=300)
    if p.returncode != 0 or "holds no particles" not in p.stderr or "Traceback" in p.stderr:
        fail(f"plot of a run whose last snapshot is empty: exit {p.returncode}: {p.stderr}")
    check_chip_colours()
    check_vary(binary, case, scratch)
    print("PASS")


def check_vary(binary, case, scratch):
    """sweep --vary: one more grid dimension over any key --set takes; each value reaches its runs (a larger rake
    angle cuts with a smaller force), sweep.csv names the key and the series; a bad value exits 2 before any run."""
    out = os.path.join(scratch, "vary")
    # Two keys: every combination is a case (friction with one value: two cases, named and tabled by both keys).
    p = subprocess.run([binary, "sweep", case, "--speeds", "20", "--vary", "cutting.rake_angle_deg=-5,15", "--vary",
                        "cutting.friction=0.35", "--jobs", "2", "--out", out, "--no-plots"], capture_output=True,
                       text=True, timeout=300)
    print(p.stdout, p.stderr, sep="\n")
    if p.returncode != 0:
        fail(f"sweep --vary exit status {p.returncode}")
    with open(os.path.join(out, "sweep.csv"), newline="") as f:
        rows = {r["case"]: r for r in csv.DictReader(f)}
    want = {"v20mps_h0.1mm_rake_angle_deg-5_friction0.35": "-5", "v20mps_h0.1mm_rake_angle_deg15_friction0.35": "15"}
    if {k: r["cutting.rake_angle_deg"] for k, r in rows.items()} != want:
        fail(f"sweep --vary cases: {list(rows)}")
    if {r["cutting.friction"] for r in rows.values()} != {"0.35"}:
        fail("sweep --vary: the second key's column")
    if len({r["series"] for r in rows.values()}) != 2:
        fail("sweep --vary: the two values are not two series")
    with open(os.path.join(out, "v20mps_h0.1mm_rake_angle_deg15_friction0.35", "summary.json")) as f:
        if json.load(f)["cutting"]["rake_angle_deg"] != 15:
            fail("the varied rake angle did not reach the run")
    fc = {v: float(rows[k]["mean_cutting_force_N_per_mm"]) for k, v in want.items()}
    if not fc["-5"] > fc["15"]:
        fail(f"Fc at rake -5 deg ({fc['-5']}) should exceed Fc at rake 15 deg ({fc['15']})")
    for args, words in ((["--vary", "cutting.rake_angle_deg=0,50"], ["--vary cutting.rake_angle_deg", "50", "(-45, 45)"]),
                        (["--vary", "cutting.rake_angle_deg"], ["KEY=V1,V2"]),
                        (["--vary", "cutting.friction=0.2,0.2"], ["given twice"]),
                        (["--vary", "cutting.cutting_speed=10,20"], ["--speeds"]),
                        (["--vary", "cutting.friction=0.2", "--vary", "cutting.friction=0.3"], ["varied twice"]),
                        # each value reads alone, one combination leaves no tool wedge
                        (["--vary", "cutting.rake_angle_deg=0,40", "--vary", "cutting.clearance_angle_deg=10,41"],
                         ["--vary: the combination cutting.rake_angle_deg=40, cutting.clearance_angle_deg=41",
                          "rake + clearance < 80"]),
                        # each reads alone with the case's own feed; together the edge is beyond 10 feeds (the case
                        # failed after the sweep had made its directory, and the sweep exited 0)
                        (["--feeds", "5e-6", "--set", "cutting.cell_size=0", "--vary", "cutting.edge_radius=60e-6"],
                         ["the sweep's case v20mps_h0.005mm_edge_radius60e-6", "below 10 uncut chip thicknesses"])):
        p = subprocess.run([binary, "sweep", case, "--speeds", "20", "--out", out + "_bad", *args], capture_output=True,
                           text=True, timeout=60)
        if p.returncode != 2 or not all(w in p.stderr for w in words) or os.path.exists(out + "_bad"):
            fail(f"sweep {args}: exit {p.returncode}, expected 2 naming {words} before any run: {p.stderr}")
    # The grid's own values too (a repeated one made two cases share a directory and broke the convergence table;
    # NaN and a feed in mm ran and failed case by case).
    for args, words in ((["--speeds", "20,20"], ["--speeds 20", "given twice"]),
                        (["--speeds", "nan"], ["--speeds", "nan", "finite"]),
                        (["--speeds", "-1"], ["--speeds", "-1", "positive"]),
                        (["--speeds", "20", "--feeds", "0"], ["--feeds", "0", "positive"]),
                        (["--speeds", "20", "--feeds", "0.2"], ["--feeds 0.2", "(0, 0.1) m"]),
                        (["--speeds", "20", "--cells-per-feed", "4,8,8"], ["--cells-per-feed 8", "given twice"]),
                        (["--speeds", "20", "--feeds", "0.1e-3,0.1e-3"], ["--feeds 0.0001:", "given twice"]),
                        # Values that differ beyond the names' 6 digits ran into one directory, one result lost.
                        (["--speeds", "20,20.0000001"], ["share the directory v20mps_h0.1mm", "6 significant"])):
        p = subprocess.run([binary, "sweep", case, "--out", out + "_bad", *args], capture_output=True, text=True,
                           timeout=60)
        if p.returncode != 2 or not all(w in p.stderr for w in words) or os.path.exists(out + "_bad"):
            fail(f"sweep {args}: exit {p.returncode}, expected 2 naming {words} before any run: {p.stderr}")
        if len(p.stderr) > 300:  # CLI11's bound of a positive number was the largest double in 309 digits
            fail(f"sweep {args}: a message of {len(p.stderr)} characters: {p.stderr}")


def check_chip_over_time(case_dir, row):
    """The run analysed its chip over the steady window: samples from its start on, Gs statistics consistent with
    them and in sweep.csv."""
    import json
    with open(os.path.join(case_dir, "summary.json")) as f:
        over = json.load(f).get("chip_over_time")
    if not over or not over.get("samples"):
        fail(f"{case_dir}: no chip_over_time samples in summary.json: {over}")
    travels = [s["tool_travel_m"] for s in over["samples"]]
    if travels[0] < over["first_tool_travel_m"] or travels != sorted(travels):
        fail(f"{case_dir}: samples before the steady window or out of order: {travels}")
    degrees = [s["segmentation_degree"] for s in over["samples"]
               if s["steady"] and s["segmentation_degree"] is not None]
    if over["steady_samples"] == 0 and not over["note"]:
        fail(f"{case_dir}: no steady state and no note: {over}")
    stats = over["segmentation_degree"]
    if degrees and (abs(stats["mean"] - sum(degrees) / len(degrees)) > 1e-12 or stats["min"] != min(degrees)):
        fail(f"{case_dir}: Gs statistics {stats} do not match the samples {degrees}")
    if degrees and abs(float(row["segmentation_degree_mean"]) - stats["mean"]) > 1e-3:
        fail(f"sweep.csv segmentation_degree_mean {row['segmentation_degree_mean']} != {stats['mean']}")


def check_chip_colours():
    """The chip map colours each chip type by its own colour ("discontinuous" contains "continuous")."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
    import plot_sweep  # noqa: E402
    colours = {t: plot_sweep.chip_color(t) for t in ("continuous", "serrated", "discontinuous")}
    if len(set(colours.values())) != 3 or colours["discontinuous"] != plot_sweep.CHIP_COLORS["discontinuous"]:
        fail(f"chip colours: {colours}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    main(sys.argv[1], sys.argv[2])
