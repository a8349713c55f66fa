"""The MPI task farm: `mpirun -n 3` gives the same tables as the local run, for sweep and calibrate.

usage: /usr/bin/python3 test_mpi_farm.py MPMCUT_BINARY SCRATCH_DIR
Runs a two-speed sweep of a coarse, short cut and the two-evaluation quick calibration
(tests/python/data/calibration_quick.toml with a budget of 2) once locally (--jobs 2) and once under
`mpirun --oversubscribe -n 3` (rank 0 hands out, ranks 1-2 run). Checks: both exit 0; the MPI runs
say they ran on the farm (ranks 1 and 2 both ran cases); sweep.csv is identical but for the wall-time
column; evaluations.csv and calibration_best.csv are identical. A case that fails on a rank is reported
in the table, not fatal: the sweep includes a speed the input rejects (exit 1, the other case complete).
"""
import csv
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_checks import fail  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "..", "..", "cases", "ti64_quick.toml")


def mpirun():
    cmd = ["mpirun", "--oversubscribe", "--bind-to", "none", "-n", "3"]
    if os.geteuid() == 0:
        cmd.insert(1, "--allow-run-as-root")
    return cmd


def run(cmd, expect):
    print(" ".join(cmd))
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=400)
    print(p.stdout, p.stderr, sep="\n")
    if p.returncode != expect:
        fail(f"exit status {p.returncode}, expected {expect}: {' '.join(cmd)}")
    return p.stdout


def rows(path, drop=()):
    with open(path, newline="") as f:
        return [{k: v for k, v in r.items() if k not in drop} for r in csv.DictReader(f)]


def main(binary, scratch):
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    # 20 and 40 m/s run; 1e-9 m/s reads (the sweep checks every value before it starts) but would need 1.9e9 steps,
    # which the run refuses when it opens: that case fails on its rank.
    sweep = ["sweep", CASE, "--speeds", "20,40,1e-9", "--set", "cutting.cut_length=40e-6", "--set",
             "cutting.cell_size=25e-6", "--no-plots"]
    run([binary, *sweep, "--jobs", "2", "--out", os.path.join(scratch, "sweep_local")], 1)
    log = run([*mpirun(), binary, *sweep, "--out", os.path.join(scratch, "sweep_mpi")], 1)
    if "MPI task farm" not in log or "rank 1)" not in log or "rank 2)" not in log:
        fail("the MPI sweep did not hand its cases to ranks 1 and 2")
    local = rows(os.path.join(scratch, "sweep_local", "sweep.csv"), drop=("wall_time_s", "message"))
    farm = rows(os.path.join(scratch, "sweep_mpi", "sweep.csv"), drop=("wall_time_s", "message"))
    if local != farm:
        fail(f"sweep tables differ:\nlocal {local}\nMPI   {farm}")
    if [r["status"] for r in farm] != ["complete", "complete", "failed"]:
        fail(f"statuses {[r['status'] for r in farm]}")

    config = os.path.join(scratch, "calibration.toml")
    with open(os.path.join(HERE, "data", "calibration_quick.toml")) as f:
        text = f.read()
    with open(config, "w") as f:
        f.write(text.replace("evaluations = 3", "evaluations = 2").replace('local = "LN_BOBYQA"', 'local = "none"'))
    cal = ["calibrate", config, "--no-plots"]
    run([binary, *cal, "--jobs", "2", "--out", os.path.join(scratch, "cal_local")], 0)
    log = run([*mpirun(), binary, *cal, "--out", os.path.join(scratch, "cal_mpi")], 0)
    if "MPI task farm" not in log:
        fail("the MPI calibration did not run on the farm")
    for name in ("evaluations.csv", "calibration_best.csv"):
        a = rows(os.path.join(scratch, "cal_local", name))
        b = rows(os.path.join(scratch, "cal_mpi", name))
        if a != b or not a:
            fail(f"{name} differs:\nlocal {a}\nMPI   {b}")
    if len(rows(os.path.join(scratch, "cal_mpi", "evaluations.csv"))) != 2:
        fail("not two evaluations")
    print("PASS")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    main(sys.argv[1], sys.argv[2])
