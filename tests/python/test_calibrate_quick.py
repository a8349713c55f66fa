"""End to end: `mpmcut calibrate` on quick (coarse, short) runs, its outputs, resume and determinism.

usage: /usr/bin/python3 test_calibrate_quick.py MPMCUT_BINARY SCRATCH_DIR
Checks, with tests/python/data/calibration_quick.toml (jc_A and friction free, 1 training and 1 held-back
condition, a budget of 3 evaluations: 2 of CRS2, then BOBYQA from the best point, which is cached):
  - exit 0; evaluations.csv has 3 rows; its objective column equals the weighted RMS relative error
    recomputed here from the per-condition forces and the measured means of the data file (b = 1 mm);
  - the local stage's point is the best global one (replayed from the cache, not run again);
  - best_material.toml is a [[material]] with library, the free material key, the [fixed] one (crack_friction), and
    its provenance with the [runs] conducting tool;
  - calibration.md has the training and the held-back errors; convergence.png and parity.png exist;
  - resume after a kill -9 (cache.jsonl cut to its first evaluation plus half a line): one evaluation
    is evaluated again, its complete runs kept (not rerun), the other replays, and evaluations.csv comes out
    identical (deterministic for a seed);
  - a second start over a complete directory runs nothing (neither evaluations nor held-back runs), also from a copy
    of the configuration with a comment added and a number respelt; a changed bound is refused naming its key, and
    so are measured rows that differ from those the evaluations were made with;
  - a cached evaluation of an older model version of its runs (solver/model_version.hpp) is evaluated again, its
    runs (current) kept.
"""
import csv
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tomllib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_checks import check_png, fail  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
CONFIG = os.path.join(HERE, "data", "calibration_quick.toml")
DATA = os.path.join(HERE, "..", "..", "data", "experiments", "ti64_klippel2024_orthogonal_forces.csv")


def calibrate(binary, out, *extra, config=CONFIG):
    p = subprocess.run([binary, "calibrate", config, "--out", out, "--jobs", "2", *extra],
                       capture_output=True, text=True, timeout=300)
    print(p.stdout, p.stderr, sep="\n")
    if p.returncode != 0:
        fail(f"calibrate exit status {p.returncode}")
    return p.stdout


def read(path):
    with open(path) as f:
        return f.read()


def main(binary, scratch):
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    out = os.path.join(scratch, "cal")
    calibrate(binary, out)
    # A directory that is not a calibration's is neither written into nor deleted with --force (it was deleted).
    precious = os.path.join(scratch, "precious")
    os.makedirs(precious)
    with open(os.path.join(precious, "thesis.tex"), "w") as f:
        f.write("x")
    for extra in ([], ["--force"]):
        p = subprocess.run([binary, "calibrate", CONFIG, "--out", precious, *extra], capture_output=True, text=True,
                           timeout=60)
        if p.returncode != 2 or "holds no calibration.toml" not in p.stderr or os.listdir(precious) != ["thesis.tex"]:
            fail(f"calibrate {extra} into a foreign directory: exit {p.returncode}, {p.stderr}, {os.listdir(precious)}")
    with open(os.path.join(out, "evaluations.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    if [r["stage"] for r in rows] != ["global", "global", "local"]:
        fail(f"stages: {[r['stage'] for r in rows]}")
    with open(DATA) as f:
        measured = [m for m in csv.DictReader(line for line in f if not line.startswith("#"))
                    if float(m["h_mm"]) == 0.1 and float(m["vc_m_per_min"]) == 381.3][0]
    fc_m, ft_m = float(measured["Fc_mean_N"]), float(measured["Ff_mean_N"])  # N/mm with b = 1 mm
    for r in rows:
        fc = float(r["h0.1mm_vc381.3mpmin_Fc_N_per_mm"])
        ft = float(r["h0.1mm_vc381.3mpmin_Ft_N_per_mm"])
        j = math.sqrt((1.0 * ((fc - fc_m) / fc_m) ** 2 + 0.5 * ((ft - ft_m) / ft_m) ** 2) / 1.5)
        # The forces in the CSV are rounded to 6 digits.
        if abs(j - float(r["objective"])) > 1e-4 * j:
            fail(f"evaluation {r['evaluation']}: objective {r['objective']} != recomputed {j}")
        if not (700e6 <= float(r["jc_A_Pa"]) <= 1000e6 and 0.1 <= float(r["friction"]) <= 0.6):
            fail(f"evaluation {r['evaluation']} outside the bounds: {r}")
    if float(rows[0]["jc_A_Pa"]) != 862e6 or float(rows[0]["friction"]) != 0.35:
        fail(f"the first point is not the start (ti64-cutting's jc_A, friction 0.35): {rows[0]}")
    best = min(rows[:2], key=lambda r: float(r["objective"]))
    if (rows[2]["jc_A_Pa"], rows[2]["friction"]) != (best["jc_A_Pa"], best["friction"]):
        fail("the local stage did not start from the best global point")
    with open(os.path.join(out, "best_material.toml"), "rb") as f:
        toml = tomllib.load(f)
    m = toml["material"][0]
    if (m["name"] != "ti64-test-fit" or m["library"] != "ti64-cutting" or m["jc_A"] != float(best["jc_A_Pa"])
            or m.get("crack_friction") != 0.5):
        fail(f"best_material.toml: {m}")
    text = read(os.path.join(out, "best_material.toml"))
    for word in ("Data:", "Objective:", "Budget:", "Process:", "friction = ", "seed 7", "conducting tool 86 W/(m K)"):
        if word not in text:
            fail(f"best_material.toml has no '{word}'")
    md = read(os.path.join(out, "calibration.md"))
    for word in ("| training | h0.1mm_vc381.3mpmin", "| held back | h0.1mm_vc150mpmin", "b = 1 mm ASSUMED", "quick"):
        if word not in md:
            fail(f"calibration.md has no '{word}'")
    for name in ("convergence.png", "parity.png"):
        check_png(os.path.join(out, name))
    table = read(os.path.join(out, "evaluations.csv"))

    # kill -9 during the second evaluation: the cache holds the first and half a line.
    cache = os.path.join(out, "cache.jsonl")
    lines = read(cache).splitlines(keepends=True)
    if len(lines) != 3:
        fail(f"cache.jsonl has {len(lines)} lines, expected 3 (2 evaluations, the third point is a replay; the "
             "held-back runs)")
    with open(cache, "w") as f:
        f.write(lines[0] + lines[1][: len(lines[1]) // 2])
    os.remove(os.path.join(out, "evaluations.csv"))
    log = calibrate(binary, out, "--no-plots")
    if "3 evaluations (1 run now, 2 from the cache)" not in log:
        fail("the resumed calibration did not run exactly the lost evaluation")
    if read(os.path.join(out, "evaluations.csv")) != table:
        fail("evaluations.csv differs after the resume: not deterministic")
    # The lost evaluation's runs were complete in its folder: kept, not run again (calibrate runs them with
    # --keep-complete, so an evaluation cut short resumes from its checkpoints).
    logs = os.path.join(out, "evaluations", "e0002", "logs")
    for name in sorted(os.listdir(logs)):
        if not name.endswith(".analyze.log") and "already holds the complete run" not in read(os.path.join(logs, name)):
            fail(f"the resumed evaluation ran {name[:-4]} again instead of keeping its complete run")
    # The same configuration with a comment and a number respelt is the same problem: its cache holds (it was
    # refused as "a different configuration"); a changed bound is another problem: refused.
    same = os.path.join(scratch, "same.toml")
    with open(same, "w") as f:
        f.write("# the quick configuration, commented\n" + read(CONFIG).replace("min = 700e6", "min = 7.0e8"))
    log = calibrate(binary, out, "--no-plots", config=same)
    if "(0 run now, 3 from the cache)" not in log or "held-back conditions at the best set" in log:
        fail("a complete calibration ran evaluations or the held-back runs again")
    changed = os.path.join(scratch, "changed.toml")
    with open(changed, "w") as f:
        f.write(read(CONFIG).replace("max = 1000e6", "max = 1100e6"))
    p = subprocess.run([binary, "calibrate", changed, "--out", out, "--no-plots"], capture_output=True, text=True,
                       timeout=60)
    if p.returncode != 2 or "different configuration" not in p.stderr or "changed: parameter" not in p.stderr:
        fail(f"a changed bound was not refused naming its key: exit {p.returncode}, {p.stderr}")
    # Measured rows that differ from those the evaluations were made with (an edited measurement file; here the
    # record of the rows is edited instead): refused, naming the row (the cached objectives were of the old data).
    rows_file = os.path.join(out, "measurements_used.txt")
    rows_text = read(rows_file)
    if "training line" not in rows_text or "held_back line" not in rows_text:
        fail(f"measurements_used.txt: {rows_text}")
    # Rows that only moved in the file (a comment added above them) are the same rows: resumed, not refused.
    with open(rows_file, "w") as f:
        f.write(re.sub(r" line (\d+):", lambda m: f" line {int(m.group(1)) + 3}:", rows_text))
    log = calibrate(binary, out, "--no-plots")
    if "(0 run now, 3 from the cache)" not in log:
        fail("rows that only moved in the measurement file were not resumed")
    # A cached evaluation made by an older model of its runs: evaluated again, not replayed. The quick runs are the
    # preset's penalty contact with friction (model version 1), so -1 stands for a version before a change; their
    # run directories are current and kept.
    lines = read(cache).splitlines(keepends=True)
    first = json.loads(lines[0])
    first["evaluation"]["model_version"] = -1
    with open(cache, "w") as f:
        f.write(json.dumps(first) + "\n" + "".join(lines[1:]))
    log = calibrate(binary, out, "--no-plots")
    if "evaluation 1: the cached result is of model version -1" not in log or "(1 run now, 2 from the cache)" not in log:
        fail("a cached evaluation of an older model version was replayed instead of evaluated again")
    logs = os.path.join(out, "evaluations", "e0001", "logs")
    for name in sorted(os.listdir(logs)):
        if not name.endswith(".analyze.log") and "already holds the complete run" not in read(os.path.join(logs, name)):
            fail(f"the evaluation of an older model version ran {name[:-4]} again, though its run is current")
    if read(os.path.join(out, "evaluations.csv")) != table:
        fail("evaluations.csv differs after evaluating the outdated evaluation again")
    with open(rows_file, "w") as f:
        f.write(rows_text.replace(", Fc ", ", Fc 1", 1))
    p = subprocess.run([binary, "calibrate", CONFIG, "--out", out, "--no-plots"], capture_output=True, text=True,
                       timeout=60)
    if p.returncode != 2 or "measured rows of this calibration changed" not in p.stderr:
        fail(f"changed measured rows were not refused: exit {p.returncode}, {p.stderr}")
    print("PASS")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    main(sys.argv[1], sys.argv[2])
