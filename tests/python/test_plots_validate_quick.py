"""End to end: `mpmcut validate` over the measured matrix: selection, --list, resolution rule, resumption, report.

usage: /usr/bin/python3 test_plots_validate_quick.py MPMCUT_BINARY SCRATCH_DIR
Checks:
- `--list` names all 35 force rows and the 2 chip-type rows; the case file of the thin feed with a large edge
  (h = 0.01 mm, r_n = 39.8 um) has cell = t0/10 = 1 um, that of h = 0.2 mm (r_n = 38.8 um) r_n/4 = 9.7 um;
  --h / --speeds-m-per-min select (intersected); a value outside the matrix is an error naming the option;
  without options every case runs the default set as it was fitted (ti64-klippel-crack-friction, its friction
  0.356, a conducting tool: 1e7 W/(m^2 K), 86 W/(m K)); --material another set runs with the preset's friction
  0.35 and an adiabatic tool (no tool heat keys in the case file), as does --tool-heat-transfer-coefficient 0;
  --material and --friction reach the case files, an unknown set or a friction out of range exits 2; a
  --material-file set reaches the case files with its [[material]] tables (the case reads on its own), a broken
  file is reported at its line and key, two sets need --material; --material-key changes keys of the chosen set
  (a set "trial" starting from it in every case file, which reads on its own), and a bad key or value exits 2.
- Resumption: `--quick --conditions A,B`, then `--quick` (its 5 conditions, a superset): A and B are not launched
  again (their logs unchanged, origin "earlier run"), the other 3 run; the report says 5 of 37 complete, 3 of 35
  force and 2 of 2 chip-type conditions, 3 run by this invocation; a third part of one of them runs nothing and
  reports all 5 as "earlier run".
- Run records (--records): a part writes scene.toml, forces.csv and summary.json of each complete condition to
  the records; a new --out with the same records reports them as "record" without running them (no log) and with
  the same forces; a record of another scene (another friction) is not used.
- Each run's summary.json names the git revision it was built from (a commit of this checkout); the runs table and
  validation.md show it.
- The report's arithmetic: validation_errors.csv, validation_goals.csv and validation_trends.csv recomputed here
  from validation_runs.csv and the data file (errors, worst, slope of Fc over ln v, signs, goals met).
- validation_runs.csv splits each force into the rake face's part and the edge and flank's (they add up to Fc and
  Ft; the edge and flank's thrust is positive), and that thrust into the edge arc's and the flank's normal and
  friction parts (they add up to it); its tool-chip interface temperature lies above room temperature and at or
  below the run's maximum; the default conducting tool takes a share of the work in (0, 1).
- --chip-observations: a user's chip-type file gives the chip conditions (h, angles and edge radius from its rows),
  validation.csv says whether each simulated chip is the observed one; bad files exit 2 with file, line, column.
- validation.csv has Fc/Ft/Ft/Fc/t_c rows with the measured means; chip-type rows; validation.md states b = 1 mm,
  the --quick caveat and its sources; the five plots are non-trivial PNGs.
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_checks import check_png, fail  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "data", "experiments", "ti64_klippel2024_orthogonal_forces.csv")


def validate(binary, *args, expect=0):
    p = subprocess.run([binary, "validate", *args], capture_output=True, text=True, timeout=300)
    print(" ".join(args), "->", p.returncode)
    print(p.stdout[-3000:], p.stderr[-2000:], sep="\n")
    if expect is not None and p.returncode != expect:
        fail(f"validate {' '.join(args)}: exit status {p.returncode}, expected {expect}")
    return p


def listed(p):
    return [line.split()[0] for line in p.stdout.splitlines() if re.match(r"(forces|chip)_", line)]


def case_value(path, key):
    with open(path) as f:
        for line in f:
            if line.startswith(key + " "):
                return float(line.split("=")[1].split("#")[0])
    fail(f"{path}: no {key}")


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def measured_rows():
    with open(DATA) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def slope(x, y):
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)


def rounding_slack(x, y, digits=4):
    """The most a least-squares slope over x can move when each y is rounded to `digits` significant digits (as
    validation_runs.csv writes the forces): sum |x_i - mean x| half-ulp_i / sum (x_i - mean x)^2."""
    mx = sum(x) / len(x)
    half_ulp = [0.5 * 10 ** (math.floor(math.log10(abs(b))) - digits + 1) if b else 0.0 for b in y]
    return sum(abs(a - mx) * u for a, u in zip(x, half_ulp)) / sum((a - mx) ** 2 for a in x)


def check_arithmetic(out):
    """Recompute the errors, trends and goals from validation_runs.csv and the data file."""
    runs = [r for r in read_csv(os.path.join(out, "validation_runs.csv"))
            if r["kind"] == "forces" and r["status"] == "complete" and r["cutting_force_N_per_mm"]]
    meas = {(float(m["h_mm"]), float(m["vc_m_per_min"])): m for m in measured_rows()}
    err = {"Fc": [], "Ft": [], "Ft/Fc": [], "t_c": [], "Fc, steady runs": [], "Ft, steady runs": [],
           "Ft/Fc, steady runs": []}
    sim = {}
    for r in runs:
        h, v = float(r["h_mm"]), float(r["speed_m_per_min"])
        m = meas[(h, v)]
        fc, ft = float(r["cutting_force_N_per_mm"]), float(r["thrust_force_N_per_mm"])
        sim[(h, v)] = fc
        # The tool force split (rake 0: the rake face's normal force is a cutting force, its friction a thrust;
        # the edge arc and flank carry the rest, pushing the tool forward and up).
        split = [float(r[k]) for k in ("rake_normal_force_N_per_mm", "rake_friction_force_N_per_mm",
                                       "edge_flank_cutting_force_N_per_mm", "edge_flank_thrust_force_N_per_mm")]
        if abs(split[0] + split[2] - fc) > 1e-3 * abs(fc) or abs(split[1] + split[3] - ft) > 1e-3 * abs(fc) or \
                split[3] <= 0:
            fail(f"{r['condition']}: rake {split[:2]} + edge/flank {split[2:]} != (Fc, Ft) = ({fc}, {ft})")
        # ... and the edge arc's and flank's thrust, each from the contacts' normal push and friction, add up to it.
        parts = [float(r[k]) for k in ("edge_arc_normal_thrust_N_per_mm", "edge_arc_friction_thrust_N_per_mm",
                                       "flank_normal_thrust_N_per_mm", "flank_friction_thrust_N_per_mm")]
        if abs(sum(parts) - split[3]) > 1e-3 * abs(fc):
            fail(f"{r['condition']}: edge arc + flank thrust parts {parts} != edge/flank thrust {split[3]}")
        if r["tool_heat_share_of_work"] == "" or not 0.0 < float(r["tool_heat_share_of_work"]) < 1.0:
            fail(f"{r['condition']}: the default conducting tool's heat share {r['tool_heat_share_of_work']} is "
                 "outside (0, 1)")
        if not 298.0 < float(r["tool_chip_interface_max_K"]) <= float(r["max_temperature_K"]) + 1e-6:
            fail(f"{r['condition']}: tool-chip interface max {r['tool_chip_interface_max_K']} K outside "
                 f"(298, max temperature {r['max_temperature_K']}] K")
        err["Fc"].append(abs(fc / float(m["Fc_mean_N"]) - 1))
        err["Ft"].append(abs(ft / float(m["Ff_mean_N"]) - 1))
        err["Ft/Fc"].append(abs((ft / fc) / (float(m["Ff_mean_N"]) / float(m["Fc_mean_N"])) - 1))
        drifts = [r["Fc_drift_in_window_percent"], r["Ft_drift_in_window_percent"]]
        if all(drifts) and max(abs(float(d)) for d in drifts) <= 10.0:
            for q in ("Fc", "Ft", "Ft/Fc"):
                err[q + ", steady runs"].append(err[q][-1])
        if r["chip_thickness_ratio"] and m["chip_thickness_um"]:
            tc = h * 1e3 / float(r["chip_thickness_ratio"])
            err["t_c"].append(abs(tc / float(m["chip_thickness_um"]) - 1))
    thick = []
    for (h, v), fc in sim.items():
        if h != 0.1 and (0.1, v) in sim:
            mr = float(meas[(h, v)]["Fc_mean_N"]) / float(meas[(0.1, v)]["Fc_mean_N"])
            thick.append(abs((fc / sim[(0.1, v)]) / mr - 1))
    err["Fc / Fc(h = 0.1 mm)"] = thick
    table = {r["quantity"]: r for r in read_csv(os.path.join(out, "validation_errors.csv"))}
    for q, e in err.items():
        row = table[q]
        if int(row["conditions"]) != len(e):
            fail(f"errors {q}: {row['conditions']} conditions, recomputed {len(e)}")
        if not e:
            continue
        # The report used unrounded forces, validation_runs.csv has 4 digits: 0.15 points of slack.
        for col, value in (("mean_abs_error_percent", 100 * sum(e) / len(e)), ("worst_abs_error_percent", 100 * max(e))):
            if abs(float(row[col]) - value) > 0.15:
                fail(f"errors {q} {col}: report {row[col]}, recomputed {value:.2f}")
    # Trends: slope of Fc over ln v at each h with >= 2 complete speeds, measured over the same speeds.
    # Rows "all" (the goal's) and, where a test of status "short" is among the speeds, "status ok only".
    trends = {(float(r["h_mm"]), r["tests"]): r for r in read_csv(os.path.join(out, "validation_trends.csv"))}
    right = total = 0
    for h in sorted({k[0] for k in sim}):
        all_vs = sorted(v for (hh, v) in sim if hh == h)
        ok_vs = [v for v in all_vs if meas[(h, v)]["status"] == "ok"]
        for tests, vs in (("all", all_vs), ("status ok only", ok_vs if ok_vs != all_vs else [])):
            if len(vs) < 2:
                if (h, tests) in trends:
                    fail(f"trend row h = {h} ({tests}) over fewer than two speeds")
                continue
            x = [math.log(v) for v in vs]
            fm = [float(meas[(h, v)]["Fc_mean_N"]) for v in vs]
            fs = [sim[(h, v)] for v in vs]
            sm, ss = slope(x, fm), slope(x, fs)
            row = trends.get((h, tests)) or fail(f"no trend row for h = {h} ({tests})")
            # The report used unrounded forces: the simulated slope's slack is what 4-digit rounding can move it.
            slack = rounding_slack(x, fs)
            for col, value, tol in (("measured_slope_N_per_mm", sm, 0.0), ("simulated_slope_N_per_mm", ss, slack),
                                    ("measured_slope_percent", 100 * sm / (sum(fm) / len(fm)), 0.0),
                                    ("simulated_slope_percent", 100 * ss / (sum(fs) / len(fs)),
                                     100 * slack / (sum(fs) / len(fs)))):
                if abs(float(row[col]) - value) > 0.01 * abs(value) + 0.02 + tol:
                    fail(f"trend h = {h} ({tests}) {col}: report {row[col]}, recomputed {value:.4g}")
            ok = (sm > 0) == (ss > 0)
            if row["sign_right"] != ("yes" if ok else "no"):
                fail(f"trend h = {h} ({tests}): sign_right {row['sign_right']}, recomputed {ok}")
            if tests == "all":
                right += ok
                total += 1
    if total == 0:
        fail("the quick set should give one speed trend (h = 0.04 mm at 100 and 400.1 m/min)")
    goals = read_csv(os.path.join(out, "validation_goals.csv"))
    expect_met = [max(err["Ft/Fc"]) <= 0.15, max(thick) <= 0.10, right == total,
                  sum(err["Fc"]) / len(err["Fc"]) < 0.15]
    for g, met in zip(goals, expect_met):
        if g["met"] != ("yes" if met else "no"):
            fail(f"goal '{g['goal']}': report {g['met']}, recomputed {met} ({g['value']})")
    if goals[2]["value"] != f"{right} of {total} right":
        fail(f"trend goal value {goals[2]['value']}")


def check_source_revision(out):
    """Each run records the git revision of the program that made it; the report names it."""
    revisions = {r["source_revision"] for r in read_csv(os.path.join(out, "validation_runs.csv"))}
    if len(revisions) != 1 or "" in revisions or "unrecorded" in revisions:
        fail(f"source_revision of the runs: {revisions}")
    revision = revisions.pop()
    root = os.path.join(HERE, "..", "..")
    if revision != "unknown" and subprocess.run(["git", "-C", root, "rev-parse", "HEAD"],
                                                capture_output=True).returncode == 0:
        # The build's commit is HEAD, or an ancestor when commits were made after the build.
        commit = revision.removesuffix("-dirty").rsplit("-g", 1)[-1]
        if subprocess.run(["git", "-C", root, "merge-base", "--is-ancestor", commit, "HEAD"]).returncode != 0:
            fail(f"source_revision {revision} is not a commit of this checkout's history")
    with open(os.path.join(out, "validation.md")) as f:
        if f"`{revision}`" not in f.read():
            fail("validation.md does not name the source revision of its runs")


def check_records(binary, scratch, out):
    """--records keeps complete runs in small files and brings them back into a fresh --out."""
    records = os.path.join(scratch, "records")
    one = "forces_h0.04mm_vc400.1mpmin"
    validate(binary, "--quick", "--no-plots", "--conditions", one, "--out", out, "--records", records)
    for name in ("scene.toml", "forces.csv", "summary.json"):
        if not os.path.isfile(os.path.join(records, one, name)):
            fail(f"--records: no {name} in the record of {one}")
    if len(os.listdir(records)) != 5:
        fail(f"--records: every complete condition of the report should be recorded, have {os.listdir(records)}")
    fresh = os.path.join(scratch, "validation_from_records")
    validate(binary, "--quick", "--no-plots", "--conditions", one, "--out", fresh, "--records", records)
    rows = {r["condition"]: r for r in read_csv(os.path.join(fresh, "validation_runs.csv"))}
    if set(rows) != set(os.listdir(records)) or {r["origin"] for r in rows.values()} != {"record"}:
        fail(f"--records into a fresh --out: origins {[(k, r['origin']) for k, r in rows.items()]}")
    if os.path.exists(os.path.join(fresh, "logs", one + ".log")):
        fail("a condition restored from its record was run again")
    before = {r["condition"]: r for r in read_csv(os.path.join(out, "validation_runs.csv"))}
    if rows[one]["cutting_force_N_per_mm"] != before[one]["cutting_force_N_per_mm"]:
        fail("the record does not give the run's cutting force")
    other = os.path.join(scratch, "validation_other_friction")
    p = validate(binary, "--quick", "--no-plots", "--conditions", one, "--friction", "0.2", "--out", other,
                 "--records", records)
    rows = {r["condition"]: r for r in read_csv(os.path.join(other, "validation_runs.csv"))}
    if rows.get(one, {}).get("origin") != "this run" or len(rows) != 1:
        fail(f"a record of another scene (friction 0.356) was used for friction 0.2: {rows}")
    if "kept, not replaced" not in p.stderr:
        fail("a run of another scene must warn that it does not replace the record")
    with open(os.path.join(records, one, "scene.toml")) as f:
        if "0.2" in [line.split("=")[1].strip() for line in f if line.startswith("friction")]:
            fail("the record of friction 0.356 was replaced by a run of friction 0.2")


def check_measurements(binary, scratch):
    """--measurements: a user's force file with tool angles becomes the matrix (no chip-type conditions); its angles
    reach the case files, the report names the file; bad files exit 2 naming file, line and column."""
    data = os.path.join(scratch, "my_forces.csv")
    with open(data, "w") as f:
        f.write("# my tests on 2 mm wide discs\n"
                "h_mm,vc_m_per_min,Fc_mean_N,Ff_mean_N,edge_radius_um,rake_deg,clearance_deg,width_mm\n"
                "0.05,120,220,120,20,15,7,2\n"
                "0.05,120,260,160,20,-6,7,2\n"
                "0.05,240,200,110,20,15,7,2\n"
                "0.05,240,250,150,20,-6,7,2\n")
    mine = os.path.join(scratch, "measurements")
    ids = listed(validate(binary, "--list", "--measurements", data, "--out", mine))
    want = ["forces_h0.05mm_vc120mpmin_rake15deg_clearance7deg", "forces_h0.05mm_vc120mpmin_rake-6deg_clearance7deg",
            "forces_h0.05mm_vc240mpmin_rake15deg_clearance7deg", "forces_h0.05mm_vc240mpmin_rake-6deg_clearance7deg"]
    if ids != want:
        fail(f"--measurements --list: {ids}, expected {want}")
    if case_value(os.path.join(mine, "cases", want[1] + ".toml"), "rake_angle_deg") != -6.0:
        fail("the row's rake angle did not reach its case file")
    with open(os.path.join(mine, "cases", want[1] + ".toml")) as f:
        if "divided by the tests' width b = 2 mm" not in f.read():
            fail("the case file does not say that the forces are divided by the tests' width")
    validate(binary, "--quick", "--no-plots", "--conditions", want[0], "--measurements", data, "--out", mine)
    validate(binary, "--quick", "--no-plots", "--measurements", data, "--out", mine)  # without a selection: all rows
    # One speed trend per tool, not one over both tools at h = 0.05 mm.
    trends = [r for r in read_csv(os.path.join(mine, "validation_trends.csv")) if r["tests"] == "all"]
    if sorted(r["tool"] for r in trends) != ["rake -6°, clearance 7°", "rake 15°, clearance 7°"] or \
            any(r["speeds_m_per_min"] != "120 240" for r in trends):
        fail(f"speed trends with two tools: {trends}")
    with open(os.path.join(mine, "validation.md")) as f:
        md = f.read()
    for text in ("Data: " + data, "rake 15°", "clearance 7°", "# Validation against the measurements of " + data,
                 "divided by each row's width_mm", "N/mm (b of the data file)"):
        if text not in md:
            fail(f"validation.md with --measurements does not say '{text}'")
    if "Sutter" in md or "Klippel condition means" in md:
        fail("validation.md with --measurements still carries the built-in data's notes")
    rows = [r for r in read_csv(os.path.join(mine, "validation.csv")) if r["quantity"] == "Fc"]
    # 220 N on a 2 mm wide cut: 110 N/mm.
    if len(rows) != 4 or float(rows[0]["measured_mean"]) != 110.0 or data not in rows[0]["source"]:
        fail(f"validation.csv with --measurements: {rows}")
    for text, words in (("0.05,120,110,60\n", ["my_bad.csv:1", "missing column(s) 'edge_radius_um'"]),
                        ("0.05,120,110,60,20,50\n", ["my_bad.csv:3", "rake_deg", "(-45, 45)"]),
                        ("0.05,120,110,60,20,5\n0.05,120,111,61,20,5\n", ["my_bad.csv:4", "the same cut as line 3"]),
                        # rake 0 given is the preset's: the cut of a row without angles, under another id
                        ("0.05,120,110,60,20,\n0.05,120,111,61,20,0\n", ["my_bad.csv:4", "the same cut as line 3"]),
                        ("0.05,120,110,60,20,5,120,100\n", ["my_bad.csv:3", "Fc_mean_N", "must lie in [min, max] = [120, 100]"])):
        bad_file = os.path.join(scratch, "my_bad.csv")
        with open(bad_file, "w") as f:
            if "missing" in words[1]:
                f.write("h_mm,vc_m_per_min,Fc_mean_N,Ff_mean_N\n" + text)
            else:
                f.write("# mine\nh_mm,vc_m_per_min,Fc_mean_N,Ff_mean_N,edge_radius_um,rake_deg"
                        + (",Fc_min_N,Fc_max_N" if text.count(",") == 7 else "") + "\n" + text)
        bad = validate(binary, "--list", "--measurements", bad_file, "--out", mine + "_bad", expect=2)
        if not all(w in bad.stderr for w in words):
            fail(f"bad measurement file: the error must name {words}: {bad.stderr}")
    validate(binary, "--list", "--measurements", os.path.join(scratch, "none.csv"), "--out", mine + "_bad", expect=2)
    # Two tools that differ only in their edge radius are two conditions, named by r_n.
    edges_file = os.path.join(scratch, "my_edges.csv")
    with open(edges_file, "w") as f:
        f.write("h_mm,vc_m_per_min,Fc_mean_N,Ff_mean_N,edge_radius_um\n0.05,120,110,60,20\n0.05,120,120,70,40\n")
    edges = listed(validate(binary, "--list", "--measurements", edges_file, "--out", mine + "_edges"))
    if edges != ["forces_h0.05mm_vc120mpmin_rn20um", "forces_h0.05mm_vc120mpmin_rn40um"]:
        fail(f"two edge radii at one h and speed: --list must show both, named by r_n: {edges}")
    # A sharp edge (0) is a tool like any other (it was refused as "must be positive"); a negative radius is not.
    with open(edges_file, "w") as f:
        f.write("h_mm,vc_m_per_min,Fc_mean_N,Ff_mean_N,edge_radius_um\n0.05,120,110,60,0\n")
    listed(validate(binary, "--list", "--measurements", edges_file, "--out", mine + "_sharp"))
    with open(edges_file, "w") as f:
        f.write("h_mm,vc_m_per_min,Fc_mean_N,Ff_mean_N,edge_radius_um\n0.05,120,110,60,-1\n")
    bad = validate(binary, "--list", "--measurements", edges_file, "--out", mine + "_sharp_bad", expect=2)
    if "column 'edge_radius_um': must be 0 (a sharp edge) or positive, got -1" not in bad.stderr:
        fail(f"a negative edge radius: {bad.stderr}")


def check_chip_observations(binary, scratch):
    """--chip-observations: a user's chip-type file (the built-in layout) gives the chip-type conditions beside the
    forces of --measurements; a row's h, tool angles and edge radius reach its case file; a row without a speed is
    not run; validation.csv says whether the simulated chip is the observed one; bad files exit 2 with file, line
    and column."""
    forces = os.path.join(scratch, "my_forces.csv")  # written by check_measurements
    chips = os.path.join(scratch, "my_chips.csv")
    with open(chips, "w") as f:
        f.write("# my chip observations\n"
                "id,chip_type,simulate_speed_m_per_s,h_min_mm,rake_deg,edge_radius_um,statement,source\n"
                "steel_slow,continuous,2,0.08,10,20,long ribbons,my lab\n"
                "steel_fast,serrated->discontinuous,40,0.08,,,saw-tooth then pieces,my lab\n"
                "steel_hand,discontinuous,,0.2,,,hand-held test,my lab\n")
    out = os.path.join(scratch, "chips")
    ids = listed(validate(binary, "--list", "--measurements", forces, "--chip-observations", chips, "--out", out))
    want = ["chip_steel_slow_v2mps", "chip_steel_fast_v40mps"]
    if [i for i in ids if i.startswith("chip_")] != want or len(ids) != 6:
        fail(f"--chip-observations --list: {ids}, expected the 4 force rows and {want}")
    slow = os.path.join(out, "cases", want[0] + ".toml")
    if abs(case_value(slow, "uncut_chip_thickness") - 0.08e-3) > 1e-12 or case_value(slow, "rake_angle_deg") != 10.0 \
            or abs(case_value(slow, "edge_radius") - 20e-6) > 1e-12:
        fail("the observation's h, rake and edge radius did not reach its case file")
    with open(slow) as f:
        if f.read().count("from the chip observations") != 2:
            fail("the case file does not say where its edge radius and rake come from")
    # Without a selection --quick runs every row of the user's files.
    validate(binary, "--quick", "--no-plots", "--jobs", "2", "--measurements", forces, "--chip-observations", chips,
             "--out", out)
    rows = [r for r in read_csv(os.path.join(out, "validation.csv")) if r["quantity"] == "chip type"]
    if [r["measured_mean"] for r in rows] != ["continuous", "serrated->discontinuous"]:
        fail(f"validation.csv chip rows: {rows}")
    for r in rows:
        sim = r["simulated"]
        expect = "" if sim not in ("continuous", "serrated", "discontinuous") else \
            "yes" if sim == r["measured_mean"] or (r["measured_mean"] == "serrated->discontinuous" and sim != "continuous") \
            else "no"
        if r["in_measured_range"] != expect or "my lab" not in r["source"]:
            fail(f"chip row {r}: agreement {r['in_measured_range']!r}, expected {expect!r}")
    if "h = 0.08 mm" not in rows[0]["condition"] or "rake 10°" not in rows[0]["condition"]:
        fail(f"the chip row does not name its condition: {rows[0]['condition']}")
    with open(os.path.join(out, "validation.md")) as f:
        md = f.read()
    if "chip types: " + chips + " (--chip-observations)" not in md or "Sutter" in md:
        fail("validation.md does not name the chip file, or still carries the built-in chip notes")
    for text, words in (("a,round,2,0.1\n", ["my_bad_chips.csv:3", "chip_type", "round"]),
                        ("a,serrated,2,\n", ["my_bad_chips.csv:3", "h_min_mm", "a value is needed"]),
                        ("a,serrated,2,0.1\na,continuous,3,0.1\n", ["my_bad_chips.csv:4", "on line 3 already"]),
                        ("a,serrated,-2,0.1\n", ["my_bad_chips.csv:3", "simulate_speed_m_per_s", "(0, 1000)"]),
                        ("my/chip,serrated,2,0.1\n", ["my_bad_chips.csv:3", "column 'id'", "names the condition's"]),
                        ("", ["my_bad_chips.csv:2", "no data rows"])):
        bad_file = os.path.join(scratch, "my_bad_chips.csv")
        with open(bad_file, "w") as f:
            f.write("# mine\nid,chip_type,simulate_speed_m_per_s,h_min_mm\n" + text)
        bad = validate(binary, "--list", "--chip-observations", bad_file, "--out", out + "_bad", expect=2)
        if not all(w in bad.stderr for w in words):
            fail(f"bad chip file: the error must name {words}: {bad.stderr}")
    # A misspelt optional column (edge_radus_um ran with the preset's 5 um edge) and a file with nothing to simulate.
    for text, words in (("id,chip_type,simulate_speed_m_per_s,h_min_mm,edge_radus_um\na,serrated,2,0.1,20\n",
                         ["my_bad_chips.csv:1", "'edge_radus_um'", "did you mean 'edge_radius_um'"]),
                        ("id,chip_type,simulate_speed_m_per_s,h_min_mm\na,serrated,,0.1\n",
                         ["no row gives simulate_speed_m_per_s"])):
        with open(bad_file, "w") as f:
            f.write(text)
        bad = validate(binary, "--list", "--chip-observations", bad_file, "--out", out + "_bad", expect=2)
        if not all(w in bad.stderr for w in words):
            fail(f"bad chip file: the error must name {words}: {bad.stderr}")
    # A speed as --list prints it (6 digits) selects its condition.
    odd = os.path.join(scratch, "odd_speed.csv")
    with open(odd, "w") as f:
        f.write("id,chip_type,simulate_speed_m_per_s,h_min_mm\nodd,serrated,5.123456789,0.1\n")
    ids = listed(validate(binary, "--list", "--chip-observations", odd, "--speeds-m-per-min", "307.407", "--out",
                          out + "_odd"))
    if "chip_odd_v5.12346mps" not in ids:
        fail(f"--speeds-m-per-min 307.407 does not select the 5.123456789 m/s condition: {ids}")
    with open(bad_file, "w") as f:
        f.write("id,chip_type,h_min_mm\na,serrated,0.1\n")
    bad = validate(binary, "--list", "--chip-observations", bad_file, "--out", out + "_bad", expect=2)
    if "missing column(s) 'simulate_speed_m_per_s'" not in bad.stderr:
        fail(f"a chip file without its speed column: {bad.stderr}")


def check_default_physics(binary, scratch, default_case):
    """The default physics in a case file of a plain --list; an adiabatic tool and another set on request."""
    with open(default_case) as f:
        text = f.read()
    if 'material = "ti64-klippel-crack-friction"' not in text:
        fail("the default material set is not ti64-klippel-crack-friction")
    for key, value in (("friction", 0.356), ("tool_heat_transfer_coefficient", 1e7), ("tool_conductivity", 86.0)):
        if abs(case_value(default_case, key) - value) > 1e-9 * value:
            fail(f"default {key} {case_value(default_case, key)}, expected {value}")
    for name, options, friction in (("other_set", ["--material", "ti64-cutting"], 0.35),
                                    ("adiabatic", ["--tool-heat-transfer-coefficient", "0"], 0.356)):
        out = os.path.join(scratch, "list_" + name)
        validate(binary, "--list", *options, "--conditions", "forces_h0.1mm_vc100mpmin", "--out", out)
        case = os.path.join(out, "cases", "forces_h0.1mm_vc100mpmin.toml")
        with open(case) as f:
            text = f.read()
        if "tool_heat_transfer_coefficient" in text or "tool_conductivity" in text:
            fail(f"{' '.join(options)}: the case file must have no tool heat keys (an adiabatic tool)")
        if abs(case_value(case, "friction") - friction) > 1e-12:
            fail(f"{' '.join(options)}: friction {case_value(case, 'friction')}, expected {friction}")
    # A conductivity needs a heat transfer coefficient: refused before any run, naming the option.
    bad = validate(binary, "--list", "--material", "ti64-cutting", "--tool-conductivity", "20",
                   "--out", out + "_bad", expect=2)
    if "--tool-conductivity 20" not in bad.stderr:
        fail("a conductivity with an adiabatic tool must be refused naming --tool-conductivity")


def main(binary, scratch):
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)

    # --list: the whole matrix, the resolution rule in the case files, the selection options.
    lst = os.path.join(scratch, "list")
    ids = listed(validate(binary, "--list", "--out", lst))
    if len([i for i in ids if i.startswith("forces_")]) != 35 or len([i for i in ids if i.startswith("chip_")]) != 2:
        fail(f"--list: {len(ids)} conditions: {ids}")
    thin = os.path.join(lst, "cases", "forces_h0.01mm_vc100mpmin.toml")
    if abs(case_value(thin, "cell_size") - 1e-6) > 1e-12:
        fail(f"thin feed cell {case_value(thin, 'cell_size')} m, expected t0/10 = 1e-6 m")
    thick = os.path.join(lst, "cases", "forces_h0.2mm_vc100mpmin.toml")
    if abs(case_value(thick, "cell_size") - 9.7e-6) > 1e-12:
        fail(f"h = 0.2 mm cell {case_value(thick, 'cell_size')} m, expected r_n/4 = 9.7e-6 m")
    if abs(case_value(thin, "cut_length") - 6 * 39.8e-6) > 1e-12:
        fail("thin feed cut length is not 6 r_n")
    check_default_physics(binary, scratch, thin)
    if listed(validate(binary, "--list", "--h", "0.01", "--out", lst)) != [
            "forces_h0.01mm_vc100mpmin", "forces_h0.01mm_vc400.1mpmin", "forces_h0.01mm_vc500mpmin"]:
        fail("--h 0.01 does not select the three h = 0.01 mm conditions")
    if listed(validate(binary, "--list", "--h", "0.1,0.02", "--speeds-m-per-min", "100,400.1", "--out", lst)) != [
            "forces_h0.02mm_vc100mpmin", "forces_h0.02mm_vc400.1mpmin", "forces_h0.1mm_vc100mpmin"]:
        fail("--h and --speeds-m-per-min do not intersect")
    bad = validate(binary, "--list", "--h", "0.07", "--out", lst, expect=2)
    if "--h 0.07" not in bad.stderr:
        fail("--h 0.07 (not in the matrix) must be an error naming the option")

    # Another material set and friction (e.g. a calibrated pair) reach every case file; bad ones are input errors.
    other = os.path.join(scratch, "other")
    ti = validate(binary, "--list", "--material", "ti64-lee-lin-1998", "--friction", "0.5", "--h", "0.1",
                  "--speeds-m-per-min", "100", "--out", other)
    # The built-in data are Ti-6Al-4V: another set is compared with them only under a warning.
    steel = validate(binary, "--list", "--material", "steel-4340-ambati-2012", "--h", "0.1", "--out", other + "_steel")
    if "measurements are of Ti-6Al-4V" in ti.stderr or "measurements are of Ti-6Al-4V" not in steel.stderr:
        fail(f"the Ti-6Al-4V data warning: with a Ti set '{ti.stderr[-300:]}', with a steel '{steel.stderr[-300:]}'")
    with open(os.path.join(other, "cases", "forces_h0.1mm_vc100mpmin.toml")) as f:
        text = f.read()
    if 'material = "ti64-lee-lin-1998"' not in text or abs(case_value(
            os.path.join(other, "cases", "forces_h0.1mm_vc100mpmin.toml"), "friction") - 0.5) > 1e-12:
        fail("--material / --friction did not reach the case file")
    bad = validate(binary, "--list", "--material", "ti64-nonesuch", "--out", other, expect=2)
    if "ti64-cutting" not in bad.stderr:
        fail("an unknown --material must list the library's sets")
    validate(binary, "--list", "--friction", "3", "--out", other, expect=2)

    # A material file (a calibration's best_material.toml, a user's set): its set reaches every case file, which
    # carries the file's [[material]] tables and reads on its own; a broken file stops with its file, line and key.
    sets = os.path.join(scratch, "sets.toml")
    with open(sets, "w") as f:
        f.write('[[material]]\nname = "my-ti64"\nlibrary = "ti64-seo-2005"\nfracture_energy = 15.0e3\n')
    mine = os.path.join(scratch, "mine")
    validate(binary, "--list", "--material-file", sets, "--conditions", "forces_h0.1mm_vc100mpmin", "--out", mine)
    case = os.path.join(mine, "cases", "forces_h0.1mm_vc100mpmin.toml")
    with open(case) as f:
        text = f.read()
    if 'material = "my-ti64"' not in text or 'name = "my-ti64"' not in text or 'library = "ti64-seo-2005"' not in text:
        fail("--material-file: the file's set did not reach the case file:\n" + text[:800])
    check = subprocess.run([binary, "run", case, "--check"], capture_output=True, text=True, timeout=120)
    if check.returncode != 0:
        fail(f"the case file written with --material-file does not read on its own: {check.stderr}")
    with open(sets, "a") as f:
        f.write('[[material]]\nname = "my-other"\nlibrary = "ti64-seo-2005"\njc_A = -1.0\n')
    bad = validate(binary, "--list", "--material-file", sets, "--material", "my-ti64", "--out", mine, expect=2)
    if "sets.toml:" not in bad.stderr or "jc_A" not in bad.stderr:
        fail("a broken material file must be reported at its file, line and key")
    with open(sets, "w") as f:
        f.write('[[material]]\nname = "a"\nlibrary = "ti64-seo-2005"\n[[material]]\nname = "b"\nlibrary = "ti64-seo-2005"\n')
    bad = validate(binary, "--list", "--material-file", sets, "--out", mine, expect=2)
    if "--material" not in bad.stderr or "a, b" not in bad.stderr:
        fail("a material file of two sets without --material must ask for one and name both")
    validate(binary, "--list", "--material-file", os.path.join(scratch, "no-such-file.toml"), "--out", mine, expect=2)

    # --material-key: the chosen set (here the file's) with a key changed, as a set "trial" that starts from it in
    # every case file, which reads on its own; an unknown key, a value out of range or no number exits 2.
    with open(sets, "w") as f:
        f.write('[[material]]\nname = "my-ti64"\nlibrary = "ti64-seo-2005"\nfracture_energy = 15.0e3\n')
    keyed = os.path.join(scratch, "keyed")
    validate(binary, "--list", "--material-file", sets, "--material-key", "jc_C=0.035", "--material-key", "jc_m=1.1",
             "--conditions", "forces_h0.1mm_vc100mpmin", "--out", keyed)
    case = os.path.join(keyed, "cases", "forces_h0.1mm_vc100mpmin.toml")
    with open(case) as f:
        text = f.read()
    if ('name = "trial"\nlibrary = "my-ti64"\njc_C = 0.035\njc_m = 1.1' not in text or 'material = "trial"' not in text
            or 'name = "my-ti64"' not in text):
        fail("--material-key: the trial set did not reach the case file:\n" + text[:1200])
    check = subprocess.run([binary, "run", case, "--check"], capture_output=True, text=True, timeout=120)
    if check.returncode != 0:
        fail(f"the case file written with --material-key does not read on its own: {check.stderr}")
    for key, words in (("jc_Q=1", ["jc_Q", "unknown key"]), ("jc_C=-1", ["jc_C", "must be in"]),
                       ("jc_C", ["--material-key 'jc_C'", "KEY=VALUE"]), ("jc_C=abc", ["KEY=VALUE"])):
        bad = validate(binary, "--list", "--material-key", key, "--out", keyed, expect=2)
        if not all(w in bad.stderr for w in words):
            fail(f"--material-key {key}: the error must name {words}: {bad.stderr}")
    bad = validate(binary, "--list", "--material-key", "jc_A=800e6", "--material-key", "jc_A=900e6", "--out", keyed,
                   expect=2)
    if not all(w in bad.stderr for w in ("--material-key jc_A", "given twice", "8e+08", "9e+08")):
        fail(f"a key given twice: the error must name it and both values: {bad.stderr}")

    check_measurements(binary, scratch)
    check_chip_observations(binary, scratch)

    # Resumption: part one, then the quick set (a superset) keeps part one.
    out = os.path.join(scratch, "validation")
    part = ["forces_h0.04mm_vc100mpmin", "forces_h0.1mm_vc100mpmin"]
    validate(binary, "--quick", "--jobs", "2", "--no-plots", "--conditions", ",".join(part), "--out", out)
    logs_of_part = {}
    for name in part:
        with open(os.path.join(out, "logs", name + ".log")) as f:
            logs_of_part[name] = f.read()
    validate(binary, "--quick", "--jobs", "2", "--out", out)
    # Part one's conditions are not launched again (their logs stay those of part one), the others run.
    for name in part:
        with open(os.path.join(out, "logs", name + ".log")) as f:
            if f.read() != logs_of_part[name]:
                fail(f"{name}, complete from part one, was launched again")
    origins = {r["condition"]: r["origin"] for r in read_csv(os.path.join(out, "validation_runs.csv"))}
    if {k for k, v in origins.items() if v == "earlier run"} != set(part) or \
            sum(v == "this run" for v in origins.values()) != 3:
        fail(f"origins after the superset part: {origins}")
    with open(os.path.join(out, "validation.md")) as f:
        md = f.read()
    if "5 of the 37 conditions of the matrix are complete" not in md:
        fail("validation.md does not say 5 of 37 complete")
    for text in ("3 of 35 force conditions and 2 of 2 chip-type conditions", "3 run by this invocation",
                 "2 complete from an earlier run"):
        if text not in md:
            fail(f"validation.md does not say '{text}'")
    for text in ("b = 1 mm", "--quick", "Klippel", "Sutter", "## Goals", "## Not run yet", "## By condition"):
        if text not in md:
            fail(f"validation.md does not mention '{text}'")

    # A later part that selects one condition, complete already, runs nothing and still reports all five.
    validate(binary, "--quick", "--no-plots", "--conditions", "forces_h0.04mm_vc400.1mpmin", "--out", out)
    origins = {r["condition"]: r["origin"] for r in read_csv(os.path.join(out, "validation_runs.csv"))}
    if len(origins) != 5 or set(origins.values()) != {"earlier run"}:
        fail(f"origins after a one-condition part: {origins}")
    with open(os.path.join(out, "validation.md")) as f:
        md = f.read()
    if "5 of the 37 conditions of the matrix are complete" not in md or "0 run by this invocation" not in md:
        fail("a one-condition part of a complete condition does not report the 5 complete conditions, 0 run")

    check_records(binary, scratch, out)
    check_source_revision(out)

    rows = read_csv(os.path.join(out, "validation.csv"))
    by = {(r["condition"].split(",")[0] + "," + r["condition"].split(",")[1], r["quantity"]): r for r in rows
          if r["condition"].startswith("h = ")}
    for key, mean in {(("h = 0.1 mm, vc = 100 m/min (1.67 m/s)"), "Fc"): 200.8,
                      (("h = 0.04 mm, vc = 400.1 m/min (6.67 m/s)"), "Ft"): 108.9,
                      (("h = 0.04 mm, vc = 100 m/min (1.67 m/s)"), "t_c"): 73.4}.items():
        r = by.get(key) or fail(f"no row {key}; have {sorted(by)}")
        if abs(float(r["measured_mean"]) - mean) > 1e-6:
            fail(f"{key}: measured mean {r['measured_mean']} != {mean}")
        float(r["simulated"])
    chips = [r for r in rows if r["quantity"] == "chip type"]
    if len(chips) != 2 or {c["measured_mean"] for c in chips} != {"serrated", "discontinuous"}:
        fail(f"chip rows: {chips}")
    check_arithmetic(out)
    for name in ("validation_forces.png", "validation_ratio.png", "validation_parity.png", "validation_speed.png",
                 "validation_thickness.png"):
        check_png(os.path.join(out, name))
    print("PASS")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    main(sys.argv[1], sys.argv[2])
