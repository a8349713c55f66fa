"""The committed validation records still match the conditions that today's binary would run.

usage: /usr/bin/python3 test_run_records_match.py MPMCUT_BINARY SCRATCH_DIR

`validate --records DIR` reports a condition from its record only when the record's scene.toml is,
byte for byte, the scene the binary writes for that condition (run/run_case.cpp, existing_run). A
change that writes one more key into every scene (a new solver option, say) therefore silently turns
every committed record into a condition "still to run", and the committed reports could no longer be
regenerated without hours of runs. This test lists the committed matrices with `validate --list`
(which runs nothing) and checks that every record directory is reported as complete from its record.
A new key must be written only where it is set (io/scene_writer.cpp) to keep the records valid.

A record made by an older model of its scene (solver/model_version.hpp; summary.json `model_version`) is
reported as "outdated-record" and runs again: the penalty contact's records made before the friction spring
took its slip from the grid (model version 1; their summaries have no `model_version`) must be listed so, those
made since as "record".
"""
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# (records directory, the validate options it was run with: its README's command, the model version of its
# scenes today: a record of an older one is listed "outdated-record"). The node-detection matrices name their
# contact since the preset's became penalty (2026-12-07), and their chip-type conditions' t0/10 since the default
# became t0/20 (the same day). The matrix of ti64-cutting names its set since the default set became
# ti64-klippel-crack-friction (2026-12-08; another set keeps the preset's friction and an adiabatic tool).
OLD_CHIP_CELLS = ["--chip-cells-per-feed", "10"]
SPEED_ENDS = ["--material-file", "docs/results/calibration_speed_ends/best_material.toml"]
MATRICES = [
    ("docs/results/validation_matrix/records",
     ["--material", "ti64-cutting", "--contact-detection", "node"] + OLD_CHIP_CELLS, 0),
    ("docs/results/validation_speed_ends/records", SPEED_ENDS + ["--contact-detection", "node"] + OLD_CHIP_CELLS, 0),
    ("docs/results/validation_speed_ends_penalty/records",
     SPEED_ENDS + ["--contact-detection", "penalty"] + OLD_CHIP_CELLS, 1),
    ("docs/results/validation_crack_friction/records",
     SPEED_ENDS + ["--contact-detection", "penalty", "--material-key", "crack_friction=0.5", "--tool-conductivity", "86",
                   "--tool-heat-transfer-coefficient", "1e7"] + OLD_CHIP_CELLS, 1),
    # validate's default physics, run with no option: a change of the default shows here as records that no longer
    # match (its README says what the default is).
    ("docs/results/validation_default/records", [], 1),
]


def expected_state(record_dir, model_version):
    with open(os.path.join(record_dir, "summary.json")) as f:
        recorded = json.load(f).get("model_version", 0)
    return "record" if recorded >= model_version else "outdated-record"


def listed_states(binary, records, options, out):
    cmd = [binary, "validate", "--list", "--out", out, "--records", records] + options
    res = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=300)
    if res.returncode != 0:
        raise SystemExit(f"FAIL: {' '.join(cmd)} exited {res.returncode}:\n{res.stderr}")
    states = {}
    for line in res.stdout.splitlines():
        m = re.match(r"^((?:forces|chip)_\S+)\s.*\s(\S+)$", line)
        if m:
            states[m.group(1)] = m.group(2)
    return states


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    binary, scratch = sys.argv[1], sys.argv[2]
    os.makedirs(scratch, exist_ok=True)
    failures = []
    for i, (records, options, model_version) in enumerate(MATRICES):
        recorded = sorted(d for d in os.listdir(os.path.join(ROOT, records))
                          if os.path.isfile(os.path.join(ROOT, records, d, "scene.toml")))
        if not recorded:
            failures.append(f"{records}: no records found")
            continue
        states = listed_states(binary, records, options, os.path.join(scratch, f"matrix{i}"))
        expected = {d: expected_state(os.path.join(ROOT, records, d), model_version) for d in recorded}
        stale = [d for d in recorded if states.get(d) != expected[d]]
        outdated = sum(1 for d in recorded if expected[d] == "outdated-record")
        print(f"{records}: {len(recorded) - len(stale)} of {len(recorded)} records listed as expected "
              f"({outdated} of them outdated)")
        if stale:
            failures.append(f"{records}: {len(stale)} records not listed as expected (a scene this binary writes "
                            f"differently, or another model version; first: {stale[0]}, listed as "
                            f"'{states.get(stale[0], 'absent')}', expected '{expected[stale[0]]}')")
    if failures:
        raise SystemExit("FAIL:\n  " + "\n  ".join(failures))
    print("OK")


if __name__ == "__main__":
    main()
