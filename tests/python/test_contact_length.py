"""End to end: the tool-chip contact outputs of a cutting run (summary.json and forces.csv).

usage: /usr/bin/python3 test_contact_length.py MPMCUT_BINARY SCRATCH_DIR
The tiny coarse cut of tests/support/cases/tiny_cut.toml (25 um cells, 1 particle per cell, 0.1 mm of travel) at
mu = 0.35 and at mu = 0. Checks:
- summary.json has tool_chip_contact_length_m and _mm (the same length in two units), a contact length of at
  least one cell and at most 4 t0 (the chip, 2-3 t0 thick, cannot touch the rake face higher up this early);
- the rake-face friction/normal ratio is positive and at most mu: the nodal Coulomb law never gives a
  friction impulse above mu times the normal one (sticking nodes give less), so a ratio above mu means the
  law or the bookkeeping is wrong; its normal force is a large part of the cutting force (rake 0: the rake
  face normal is the cutting direction);
- at mu = 0 the rake-face friction force is zero (to round-off);
- forces.csv has the contact length and rake-force columns, and their time mean over the steady window
  agrees with summary.json (rows are time means between rows, the steady window starts on a row here);
- edge_and_flank (the tool force less the rake face's): at mu = 0 it pushes the tool up, and back by no less than
  -tan(clearance) of its thrust (the edge and flank feel only the material's normal push, along normals between the
  rake face's, straight back, and the flank's, up and forward by the clearance angle); at rake 0 rake normal + its
  Fc is the whole Fc and rake friction + its Ft the whole Ft;
- steady_window.drift (second half's mean force minus the first half's, % of the mean or of half the mean resultant
  where that is larger) agrees with the same
  difference computed from the rows of forces.csv (a sign or definition error would differ by its size);
- edge_and_flank.edge_arc and .flank (where on the tool that rest acts, each split into the contacts' normal and
  friction part): together they are the whole rest (unattributed < 1e-9 of the force, penalty and node contact);
  at mu = 0 their friction parts vanish; the edge arc's normal push lies in the fan of the arc's normals; with a
  1-degree clearance and a 10 um edge (the flank rubs the machined surface) the flank's normal push is along the
  flank's normal (Fc = -tan(clearance) Ft), its friction along the flank, at most mu times the normal push, and its
  contact length is positive;
- tool_heat (the heat into the tool): exactly 0 for the preset's adiabatic tool that leaves all frictional heat to
  the workpiece; with friction_heat_share = 0.5 the steady window's heat into the tool is half the ledger's frictional
  work over the window (3 %); a heat sink (tool_heat_transfer_coefficient = 1e6 W/(m^2 K)) adds conducted heat to
  that, and the share of the tool's work is the window's heat over mean Fc x travel; a conducting tool
  (tool_conductivity = 86 W/(m K), steady) warms up and so takes less heat than the sink at 298 K, more than none;
  its field (tool_temperature.csv) is 298 K in its held cells, above it where it touches the chip, and its hottest
  cell (summary tool_heat.tool_temperature.max_K) is not hotter than the workpiece's hottest particle;
- the frictional work per unit travel on the rake face and on the edge and flank: both >= 0, their sum over the
  steady window's travel is the energy ledger's friction work over the window (history.csv; the preset's penalty
  contact and node detection), the rake face's mean slip speed is below the cutting speed (the chip, thicker than t0, flows up a
  0-degree face slower than the tool moves), and everything is zero at mu = 0.
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys

CASE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support", "cases", "tiny_cut.toml")


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def run(binary, scratch, mu, detection=None, extra=()):
    name = f"mu{mu}" + (f"_{detection}" if detection else "") + ("_" + "_".join(kv.replace("cutting.", "").replace("=", "") for kv in extra) if extra else "")
    out = os.path.join(scratch, name)
    settings = ["--set", f"cutting.friction={mu}"] + [a for kv in extra for a in ("--set", kv)]
    if detection:
        settings += ["--set", f'solver.contact_detection="{detection}"']
    p = subprocess.run([binary, "run", CASE, "--out", out, "--force", "--threads", "1", "--no-progress",
                        "--no-plots"] + settings, capture_output=True, text=True, timeout=300)
    print(p.stdout, p.stderr, sep="\n")
    if p.returncode != 0:
        fail(f"run exit status {p.returncode}")
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "forces.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(out, "history.csv"), newline="") as f:
        summary["_history"] = list(csv.DictReader(f))
    return summary, rows


def ledger_friction_work(history, start, end):
    """The ledger's friction work (J/m) between two times, linear between history rows."""
    ts = [float(r["time_s"]) for r in history]
    ws = [float(r["friction_work_J_per_m"]) for r in history]

    def at(t):
        for i in range(1, len(ts)):
            if ts[i] >= t:
                return ws[i - 1] + (ws[i] - ws[i - 1]) * (t - ts[i - 1]) / (ts[i] - ts[i - 1])
        return ws[-1]
    return at(end) - at(start)


def check_friction_work(summary, speed, label):
    rake, rest = summary["rake_face"], summary["edge_and_flank"]
    w = summary["steady_window"]
    travel = w["end_tool_travel_m"] - w["start_tool_travel_m"]
    per_travel = rake["friction_work_per_travel_N_per_mm"] + rest["friction_work_per_travel_N_per_mm"]
    ledger = ledger_friction_work(summary["_history"], w["start_time_s"], w["end_time_s"]) / travel * 1e-3
    print(f"{label}: friction work per travel: rake face {rake['friction_work_per_travel_N_per_mm']:.3f}, edge and "
          f"flank {rest['friction_work_per_travel_N_per_mm']:.3f}, ledger {ledger:.3f} N/mm; rake mean slip speed "
          f"{rake['mean_slip_speed_m_per_s']:.3f} m/s")
    if rake["friction_work_per_travel_N_per_mm"] < 0 or rest["friction_work_per_travel_N_per_mm"] < 0:
        fail(f"{label}: negative frictional work {rake}, {rest}")
    # The history rows bracket the window's ends, where the work rate is nearly constant: a few per cent.
    if abs(per_travel - ledger) > 0.03 * ledger:
        fail(f"{label}: rake + edge and flank friction work {per_travel:.4f} N/mm vs the ledger's {ledger:.4f} N/mm")
    if not 0.0 < rake["mean_slip_speed_m_per_s"] < speed:
        fail(f"{label}: rake mean slip speed {rake['mean_slip_speed_m_per_s']} m/s not in (0, {speed}) m/s")


def check_tool_heat(binary, scratch, adiabatic):
    heat = adiabatic["tool_heat"]
    if heat["heat_into_tool_J_per_m"] != 0.0 or heat["steady_window_share_of_tool_work"] != 0.0:
        fail(f"adiabatic tool, all frictional heat to the workpiece, but tool_heat {heat}")
    halves = run(binary, scratch, 0.35, extra=("cutting.friction_heat_share=0.5",))[0]
    sink = run(binary, scratch, 0.35, extra=("cutting.friction_heat_share=0.5",
                                             "cutting.tool_heat_transfer_coefficient=1e6"))[0]
    w = halves["steady_window"]
    ledger = ledger_friction_work(halves["_history"], w["start_time_s"], w["end_time_s"])
    got = halves["tool_heat"]["steady_window_heat_into_tool_J_per_m"]
    print(f"tool heat: half the frictional heat {got:.5f} J/m (ledger friction work over the window {ledger:.5f} "
          f"J/m); with the sink {sink['tool_heat']}")
    if abs(got - 0.5 * ledger) > 0.03 * 0.5 * ledger:
        fail(f"friction_heat_share 0.5: heat into the tool {got} J/m is not half the window's friction work {ledger} J/m")
    if not halves["tool_heat"]["heat_into_tool_J_per_m"] >= got > 0:
        fail(f"the run's heat into the tool {halves['tool_heat']} is below its steady window's")
    t = sink["tool_heat"]
    friction_part = 0.5 * ledger_friction_work(sink["_history"], sink["steady_window"]["start_time_s"],
                                               sink["steady_window"]["end_time_s"])
    if not t["steady_window_heat_into_tool_J_per_m"] > 1.05 * friction_part:
        fail(f"a 1e6 W/(m^2 K) sink adds no conducted heat: {t} vs friction part {friction_part} J/m")
    sw = sink["steady_window"]
    work = sink["mean_cutting_force_N_per_mm"] * 1e3 * (sw["end_tool_travel_m"] - sw["start_tool_travel_m"])
    if abs(t["steady_window_share_of_tool_work"] - t["steady_window_heat_into_tool_J_per_m"] / work) > 1e-3 * \
            t["steady_window_share_of_tool_work"]:
        fail(f"tool heat share {t['steady_window_share_of_tool_work']} != heat / (Fc x travel) = "
             f"{t['steady_window_heat_into_tool_J_per_m'] / work}")
    check_conducting_tool(binary, scratch)


def check_conducting_tool(binary, scratch):
    sink = run(binary, scratch, 0.35, extra=("cutting.tool_heat_transfer_coefficient=1e6",))[0]
    extra = ("cutting.tool_heat_transfer_coefficient=1e6", "cutting.tool_conductivity=86")
    warm = run(binary, scratch, 0.35, extra=extra)[0]
    q_sink = sink["tool_heat"]["steady_window_heat_into_tool_J_per_m"]
    q_warm = warm["tool_heat"]["steady_window_heat_into_tool_J_per_m"]
    field = warm["tool_heat"].get("tool_temperature")
    print(f"conducting tool: {q_warm:.5f} J/m into it over the window (sink at 298 K: {q_sink:.5f} J/m); {field}")
    if not 0.0 < q_warm < q_sink:
        fail(f"a conducting tool should take less heat than a 298 K sink and more than none: {q_warm} vs {q_sink} J/m")
    if field is None or field["mode"] != "steady" or field["conductivity_W_per_mK"] != 86:
        fail(f"summary tool_heat.tool_temperature missing or wrong: {field}")
    if not 298.0 + 1.0 < field["max_K"] <= warm["max_temperature_K"]:
        fail(f"the tool's hottest cell {field['max_K']} K should be above 298 K and not above the workpiece's "
             f"{warm['max_temperature_K']} K")
    name = "mu0.35_" + "_".join(kv.replace("cutting.", "").replace("=", "") for kv in extra)
    with open(os.path.join(scratch, name, "tool_temperature.csv"), newline="") as f:
        cells = list(csv.DictReader(f))
    held = [float(c["temperature_K"]) for c in cells if c["held"] == "1"]
    if not held or any(T != 298.0 for T in held) or len(held) * 5 > len(cells):
        fail(f"held cells: {len(held)} of {len(cells)}, temperatures {sorted(set(held))[:5]}")
    if abs(max(float(c["temperature_K"]) for c in cells) - field["max_K"]) > 1e-9 * field["max_K"]:
        fail("tool_temperature.csv's hottest cell differs from summary.json's")


def check_regions(summary, label, mu):
    """edge_and_flank's split into the edge arc and the flank, each into its normal and friction part."""
    rest = summary["edge_and_flank"]
    edge, flank, left = rest["edge_arc"], rest["flank"], rest["unattributed"]
    scale = math.hypot(summary["mean_cutting_force_N_per_mm"], summary["mean_thrust_force_N_per_mm"])
    clearance = math.radians(summary["cutting"]["clearance_angle_deg"])
    print(f"{label}: edge arc Fc {edge['cutting_force_N_per_mm']:.3f} Ft {edge['thrust_force_N_per_mm']:.3f}, flank Fc "
          f"{flank['cutting_force_N_per_mm']:.3f} Ft {flank['thrust_force_N_per_mm']:.3f} N/mm (normal part "
          f"{flank['normal_part']}), flank contact {flank['contact_length_mm'] * 1e3:.2f} um, unattributed {left}")
    for part in (edge, flank):
        for key in ("cutting_force_N_per_mm", "thrust_force_N_per_mm"):
            if abs(part["normal_part"][key] + part["friction_part"][key] - part[key]) > 1e-9 * scale:
                fail(f"{label}: normal + friction part != the region's {key}: {part}")
    if max(abs(left["cutting_force_N_per_mm"]), abs(left["thrust_force_N_per_mm"])) > 1e-9 * scale:
        fail(f"{label}: the edge arc and flank do not add up to edge_and_flank: unattributed {left}")
    if mu == 0.0:
        for part in (edge, flank):
            if math.hypot(*part["friction_part"].values()) > 1e-9 * scale:
                fail(f"{label}: mu = 0 but friction part {part['friction_part']}")
    # The arc's normals fan from the rake face's (push straight back) to the flank's (up, forward by the clearance).
    n = edge["normal_part"]
    if n["thrust_force_N_per_mm"] < 0 or \
            n["cutting_force_N_per_mm"] < -math.tan(clearance) * n["thrust_force_N_per_mm"] - 1e-9 * scale:
        fail(f"{label}: edge arc's normal push {n} outside the fan of its normals")
    return flank, clearance


def check_flank(summary, mu):
    """A flank that rubs: its normal push along its normal, its friction along it and within Coulomb's bound."""
    flank, clearance = check_regions(summary, "1-degree clearance, 10 um edge", mu)
    n, t = flank["normal_part"], flank["friction_part"]
    normal, friction = math.hypot(*n.values()), math.hypot(*t.values())
    if not normal > 1e-3 * summary["mean_thrust_force_N_per_mm"] or flank["contact_length_m"] <= 0:
        fail(f"1-degree clearance: the flank carries no load ({flank})")
    # On the flat flank a contact's normal is the flank's; one on the arc within the 2.6-degree band deviates less.
    if abs(n["cutting_force_N_per_mm"] / n["thrust_force_N_per_mm"] + math.tan(clearance)) > 0.25 * math.tan(clearance):
        fail(f"flank normal push {n} is not along the flank's normal (Fc/Ft = -tan(clearance) = {-math.tan(clearance):.4f})")
    if friction > 0 and abs(t["thrust_force_N_per_mm"] / t["cutting_force_N_per_mm"] - math.tan(clearance)) > \
            0.25 * math.tan(clearance):
        fail(f"flank friction {t} is not along the flank (Ft/Fc = tan(clearance) = {math.tan(clearance):.4f})")
    if friction > mu * normal * (1 + 1e-6):
        fail(f"flank friction {friction:.4f} N/mm above mu = {mu} times its normal push {normal:.4f} N/mm")


def main(binary, scratch):
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    h, t0 = 25e-6, 0.1e-3

    summary, rows = run(binary, scratch, 0.35)
    length = summary.get("tool_chip_contact_length_m")
    if length is None or abs(summary["tool_chip_contact_length_mm"] - 1e3 * length) > 1e-12:
        fail(f"contact length keys: {length}, {summary.get('tool_chip_contact_length_mm')}")
    if not h <= length <= 4 * t0:
        fail(f"contact length {length * 1e6:.1f} um outside [{h * 1e6:.0f}, {4 * t0 * 1e6:.0f}] um")
    rake = summary["rake_face"]
    ratio = rake["friction_to_normal_ratio"]
    print(f"contact length {length * 1e6:.1f} um, rake friction/normal {ratio:.4f} (mu 0.35), normal "
          f"{rake['normal_force_N_per_mm']:.1f} N/mm of Fc {summary['mean_cutting_force_N_per_mm']:.1f} N/mm, "
          f"sliding share {rake['sliding_share_of_normal_force']:.2f}")
    if not 0.0 < ratio <= 0.35 + 1e-9:
        fail(f"rake-face friction/normal {ratio} not in (0, mu = 0.35]")
    if not rake["normal_force_N_per_mm"] > 0.3 * summary["mean_cutting_force_N_per_mm"]:
        fail("rake-face normal force is not a large part of the cutting force")
    for key in ("tool_chip_contact_length_m", "rake_normal_force_N_per_mm", "rake_friction_force_N_per_mm"):
        if key not in rows[0]:
            fail(f"forces.csv lacks {key}")
    # Time mean of the rows over the steady window = the summary's mean (rows are exact time means).
    start = summary["steady_window"]["start_time_s"]
    prev_t, acc, total = None, 0.0, 0.0
    for r in rows:
        t = float(r["time_s"])
        if prev_t is not None and prev_t >= start - 1e-15:
            acc += float(r["tool_chip_contact_length_m"]) * (t - prev_t)
            total += t - prev_t
        prev_t = t
    if total <= 0 or abs(acc / total - length) > 0.05 * length:
        fail(f"forces.csv contact length mean {acc / max(total, 1e-30) * 1e6:.2f} um vs summary {length * 1e6:.2f} um")

    check_drift(summary, rows)
    check_friction_work(summary, 20.0, "penalty contact (the preset's)")
    summary_node = run(binary, scratch, 0.35, "node")[0]
    check_friction_work(summary_node, 20.0, "node contact")
    check_regions(summary, "penalty contact", 0.35)
    check_tool_heat(binary, scratch, summary)
    check_regions(summary_node, "node contact", 0.35)
    check_flank(run(binary, scratch, 0.35, extra=("cutting.clearance_angle_deg=1", "cutting.edge_radius=10e-6"))[0], 0.35)

    summary0, _ = run(binary, scratch, 0.0)
    for part in ("rake_face", "edge_and_flank"):
        if summary0[part]["friction_work_per_travel_N_per_mm"] != 0.0:
            fail(f"mu = 0 but {part} friction work {summary0[part]['friction_work_per_travel_N_per_mm']} N/mm")
    # Zero up to round-off of the impulse's component along the face (1e-9 of the normal force).
    if abs(summary0["rake_face"]["friction_force_N_per_mm"]) > 1e-9 * summary0["rake_face"]["normal_force_N_per_mm"]:
        fail(f"mu = 0 but rake friction {summary0['rake_face']['friction_force_N_per_mm']} N/mm")
    # The edge arc and the flank carry the rest of the tool force. Without friction the tool there only feels
    # the material's normal push, along the outline's normals between the rake face's (straight back: Fc > 0,
    # Ft = 0) and the flank's (up, and forward by the clearance angle c: Fc = -tan(c) Ft), so Ft > 0 and
    # Fc >= -tan(c) Ft (penalty contact on this coarse grid: the springback under the flank gives a small negative
    # Fc); and the rake face (rake 0: its normal force is along the cutting direction, no friction) plus the rest is
    # the whole force.
    check_regions(summary0, "mu = 0", 0.0)
    rest = summary0["edge_and_flank"]
    clearance = math.radians(summary0["cutting"]["clearance_angle_deg"])
    print(f"mu = 0: edge and flank carry Fc {rest['cutting_force_N_per_mm']:.2f}, Ft {rest['thrust_force_N_per_mm']:.2f} "
          f"N/mm of {summary0['mean_cutting_force_N_per_mm']:.2f}, {summary0['mean_thrust_force_N_per_mm']:.2f}")
    if rest["thrust_force_N_per_mm"] <= 0 or \
            rest["cutting_force_N_per_mm"] < -math.tan(clearance) * rest["thrust_force_N_per_mm"] - 1e-9:
        fail(f"mu = 0: edge and flank forces {rest} must push the tool up, and forward by no more than "
             f"tan(clearance) of their thrust")
    total = rest["cutting_force_N_per_mm"] + summary0["rake_face"]["normal_force_N_per_mm"]
    if abs(total - summary0["mean_cutting_force_N_per_mm"]) > 1e-9 * abs(total):
        fail(f"mu = 0, rake 0: rake normal + edge and flank {total} != Fc {summary0['mean_cutting_force_N_per_mm']}")
    # With friction at rake 0 the rake face's friction is a thrust: Ft = F + the rest's thrust.
    rest = summary["edge_and_flank"]
    total = rest["thrust_force_N_per_mm"] + summary["rake_face"]["friction_force_N_per_mm"]
    if abs(total - summary["mean_thrust_force_N_per_mm"]) > 1e-9 * abs(total):
        fail(f"rake 0: rake friction + edge and flank thrust {total} != Ft {summary['mean_thrust_force_N_per_mm']}")
    print("OK")


def check_drift(summary, rows):
    """steady_window.drift from forces.csv: the second half's mean from its rows (the split and the end lie on
    rows, and rows are exact impulse means), the first half's from the window's mean and the second half's."""
    w = summary["steady_window"]
    drift = w.get("drift")
    if drift is None:
        fail("summary.json steady_window has no drift")
    start, split, end = w["start_time_s"], drift["split_time_s"], w["end_time_s"]
    if not start < split < end:
        fail(f"drift split {split} s not inside the window [{start}, {end}] s")
    if not any(abs(float(r["time_s"]) - split) <= 1e-12 * end for r in rows):
        fail(f"drift split {split} s is not the time of a row of forces.csv")
    for column, key, mean_key in (("cutting_force_N_per_mm", "cutting_force_percent", "mean_cutting_force_N_per_mm"),
                                  ("thrust_force_N_per_mm", "thrust_force_percent", "mean_thrust_force_N_per_mm")):
        impulse, time, prev_t = 0.0, 0.0, None
        for r in rows:
            t = float(r["time_s"])
            if prev_t is not None and prev_t >= split - 1e-12 * end:
                impulse += float(r[column]) * (t - prev_t)
                time += t - prev_t
            prev_t = t
        mean = summary[mean_key]
        second = impulse / time
        first = (mean * (end - start) - second * (end - split)) / (split - start)
        # % of the force's mean, or of half the mean resultant where that is larger (a force near zero)
        half_resultant = 0.5 * math.hypot(summary["mean_cutting_force_N_per_mm"], summary["mean_thrust_force_N_per_mm"])
        expected = 100.0 * (second - first) / max(abs(mean), half_resultant)
        print(f"{key}: summary {drift[key]:+.3f} %, from forces.csv {expected:+.3f} %")
        if abs(drift[key] - expected) > 0.01:  # a sign or definition error is the size of the drift
            fail(f"steady_window.drift {key} {drift[key]:.3f} % vs {expected:.3f} % from forces.csv")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
