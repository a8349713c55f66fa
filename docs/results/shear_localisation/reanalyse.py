#!/usr/bin/python3
"""Chip metrics of this study's runs re-analysed with the current `mpmcut analyze` (issue 11, item 2).

The runs' own summaries (records/) hold the chip analysis of the binary that ran them; this analyses
each run's last snapshot again in a scratch directory (the result directories are not touched) and
writes chip_reanalysis.md/.csv beside this script: the segmentation degree, teeth, pitch and mean
thickness before and after, and the part of the chip profile measured (the entry chip is left out).

usage: /usr/bin/python3 docs/results/shear_localisation/reanalyse.py MPMCUT
  (needs the result directories of run.sh and of the penalty matrix's crack-gap runs, results/crack_gap)
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
SPEEDS = ["12.6", "100", "381.3"]


def runs():
    """(variant, speed, result directory) of every run that has one."""
    out = []
    for v in SPEEDS:
        cond = f"forces_h0.1mm_vc{v}mpmin"
        out.append(("matrix", v, os.path.join(ROOT, "results", "crack_gap", cond, cond)))
        for n in (16, 24, 32):
            out.append((f"t0_{n}", v, os.path.join(ROOT, "results", "shear_localisation", f"t0_{n}_{cond}", cond)))
    return [r for r in out if os.path.exists(os.path.join(r[2], "particles.pvd"))
            and os.path.exists(os.path.join(r[2], "summary.json"))
            and json.load(open(os.path.join(r[2], "summary.json"))).get("status") == "complete"]


def reanalyse(mpmcut, result_dir):
    with tempfile.TemporaryDirectory() as tmp:
        for f in ("summary.json", "scene.toml", "particles.pvd"):
            shutil.copy(os.path.join(result_dir, f), tmp)
        os.symlink(os.path.join(result_dir, "snapshots"), os.path.join(tmp, "snapshots"))
        subprocess.run([mpmcut, "analyze", tmp], check=True, stdout=subprocess.DEVNULL)
        return json.load(open(os.path.join(tmp, "summary.json")))["chip"]


def um(v):
    return "-" if v is None else f"{v * 1e6:.0f}"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    mpmcut = os.path.abspath(sys.argv[1])
    rows = []
    for variant, speed, d in runs():
        before = json.load(open(os.path.join(d, "summary.json")))["chip"]
        after = reanalyse(mpmcut, d)
        p = after["profile"]
        end_all = p["start_m"] + p["spacing_m"] * (p["samples"] - 1)
        gs = lambda c: "-" if c.get("segmentation_degree") is None else f"{c['segmentation_degree']:.2f}"
        rows.append({
            "h_mm": 0.1, "speed_m_per_min": speed, "variant": variant,
            "cells_across_t0": f"{after['cells_across_uncut_chip']:.1f}",
            "Gs_before": gs(before), "Gs_after": gs(after),
            "teeth_before": before.get("segments"), "teeth_after": after.get("segments"),
            "pitch_after_um": um(after.get("pitch_m")),
            "mean_thickness_before_um": um(before.get("mean_thickness_m")),
            "mean_thickness_after_um": um(after.get("mean_thickness_m")),
            "profile_measured_um": f"{p['start_m'] * 1e6:.0f}-{um(p.get('steady_end_m'))} of {end_all * 1e6:.0f}",
            "classification_after": after["classification"] + (
                " (marginal)" if after.get("classification_confidence") == "marginal" else ""),
        })
        print(rows[-1], flush=True)
    keys = list(rows[0].keys())
    with open(os.path.join(HERE, "chip_reanalysis.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(HERE, "chip_reanalysis.md"), "w") as f:
        f.write("| " + " | ".join(keys) + " |\n|" + "---|" * len(keys) + "\n")
        for r in rows:
            f.write("| " + " | ".join(str(r[k]) for k in keys) + " |\n")


if __name__ == "__main__":
    main()
