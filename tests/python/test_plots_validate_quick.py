"""End to end: `mpmcut validate --quick` (coarse, short runs of the measured conditions) and its report.

usage: /usr/bin/python3 test_plots_validate_quick.py MPMCUT_BINARY SCRATCH_DIR
Checks: exit 0; validation.csv has Fc, Ft and Ft/Fc rows for h = 0.1 mm at 150 and 381.3 m/min with the
measured means of data/experiments/ti64_klippel2024_orthogonal_forces.csv (197.4 N and 157.5 N), simulated
values and error %; chip-type rows for the Sutter & List speeds; validation.md states the b = 1 mm assumption
and the --quick caveat; validation_forces.png and validation_ratio.png are non-trivial PNGs.
"""
import csv
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_checks import check_png, fail  # noqa: E402


def main(binary, scratch):
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    out = os.path.join(scratch, "validation")
    t0 = time.time()
    p = subprocess.run([binary, "validate", "--quick", "--jobs", "2", "--out", out],
                       capture_output=True, text=True, timeout=300)
    print(p.stdout, p.stderr, sep="\n")
    if p.returncode != 0:
        fail(f"validate --quick exit status {p.returncode}")
    print(f"validate --quick took {time.time() - t0:.1f} s")
    with open(os.path.join(out, "validation.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    by = {(r["condition"].split(",")[1].strip(), r["quantity"]): r for r in rows if r["condition"].startswith("h = 0.1 mm, vc")}
    expected = {("vc = 150 m/min (2.5 m/s)", "Fc"): 197.4, ("vc = 381.3 m/min (6.36 m/s)", "Fc"): 157.5}
    for key, mean in expected.items():
        if key not in by:
            fail(f"no row {key}; have {sorted(by)}")
        r = by[key]
        if abs(float(r["measured_mean"]) - mean) > 1e-6:
            fail(f"{key}: measured mean {r['measured_mean']} != {mean}")
        float(r["simulated"])
        float(r["error_percent"])
    for cond in ("vc = 150 m/min (2.5 m/s)", "vc = 381.3 m/min (6.36 m/s)"):
        for q in ("Ft", "Ft/Fc"):
            if (cond, q) not in by:
                fail(f"no row {cond} {q}")
    chips = [r for r in rows if r["quantity"] == "chip type"]
    if len(chips) != 2 or {c["measured_mean"] for c in chips} != {"serrated", "discontinuous"}:
        fail(f"chip rows: {chips}")
    with open(os.path.join(out, "validation.md")) as f:
        md = f.read()
    for text in ("b = 1 mm", "--quick", "Klippel", "Sutter"):
        if text not in md:
            fail(f"validation.md does not mention '{text}'")
    for name in ("validation_forces.png", "validation_ratio.png"):
        check_png(os.path.join(out, name))
    print("PASS")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    main(sys.argv[1], sys.argv[2])
