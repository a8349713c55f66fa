"""Cell-crossing noise of the tool force: the amplitude of the cutting and thrust force at one cycle
per cell of tool travel, relative to the mean, next to the amplitudes at longer wavelengths (the chip's
segment pitch).

usage: /usr/bin/python3 force_spectrum.py RESULT_DIR [RESULT_DIR ...] [--from TRAVEL_M] [--to TRAVEL_M] [--json]

For each result directory it reads forces.csv (the filtered force rows, every quarter cell of tool travel)
and summary.json (cell size, steady window). Over the steady window (or --from/--to, tool travel in m), trimmed to a whole number of cells,
it fits a*cos + b*sin at the wavelength of one cell of travel (the Fourier coefficient, exact for an
integer number of periods) and reports the amplitude sqrt(a^2 + b^2) over the mean force, in %. The rows
are box means over a quarter cell, which attenuate the one-cell component by sinc(1/4) = 0.90; the
amplitude is corrected for that. It also prints the largest amplitude at wavelengths of 3 cells or more
(the chip segmentation lies there: the default cut's pitch is about 77 um, 6-10 cells) and the mean
Fc, Ft, frictional work and, when present, contact length and rake-face friction/normal ratio.
"""
import csv
import json
import math
import os
import sys

import numpy as np


def read_forces(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    cols = {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
    return cols


def amplitude(travel, force, wavelength):
    """Fourier amplitude of force(travel) at the given wavelength, over the samples given (uniform)."""
    phase = 2.0 * math.pi * travel / wavelength
    a = 2.0 * np.mean(force * np.cos(phase))
    b = 2.0 * np.mean(force * np.sin(phase))
    return math.hypot(a, b)


def analyse(result_dir, travel_from=None, travel_to=None):
    summary = json.load(open(os.path.join(result_dir, "summary.json")))
    h = summary["cutting"]["cell_size_m"]
    f = read_forces(os.path.join(result_dir, "forces.csv"))
    travel = f["tool_displacement_m"]
    # Row i holds the mean force over (travel[i-1], travel[i]]: its centre is the midpoint.
    centre = np.concatenate([[travel[0]], 0.5 * (travel[1:] + travel[:-1])])
    start = travel_from if travel_from is not None else summary.get("steady_window", {}).get("start_tool_travel_m", 0.0)
    end = travel[-1] if travel_to is None else min(travel_to, travel[-1])
    ncell = math.floor((end - start) / h + 1e-9)
    if ncell < 2:
        raise SystemExit(f"{result_dir}: window of {(end - start) / h:.1f} cells is too short")
    lo = end - ncell * h
    sel = (centre > lo + 1e-12) & (centre <= end + 1e-12)
    x = centre[sel]
    out = {"dir": result_dir, "cell_size_m": h, "window_travel_m": [lo, end], "window_cells": ncell}
    box = math.sin(math.pi / 4) / (math.pi / 4)  # quarter-cell box mean at one cycle per cell
    for key, name in (("cutting_force_N_per_mm", "Fc"), ("thrust_force_N_per_mm", "Ft")):
        y = f[key][sel]
        mean = float(np.mean(y))
        a_cell = amplitude(x, y - mean, h) / box
        # Longest-wavelength content: harmonics of the window with wavelength >= 3 cells.
        long_amps = [amplitude(x, y - mean, ncell * h / k) for k in range(1, int(ncell // 3) + 1)]
        out[name] = {"mean_N_per_mm": mean, "cell_amplitude_N_per_mm": a_cell,
                     "cell_amplitude_percent": 100.0 * a_cell / abs(mean) if mean else float("nan"),
                     "max_long_wave_amplitude_N_per_mm": max(long_amps) if long_amps else float("nan"),
                     "rms_percent": 100.0 * float(np.std(y)) / abs(mean) if mean else float("nan")}
    out["friction_work_J_per_m"] = summary.get("energy_J_per_m", {}).get("friction_work")
    # Frictional work done over the window (history.csv), J per m of thickness, and per unit tool travel
    # (a mean friction power over V: N/mm), comparable between runs of different lengths.
    hist_path = os.path.join(result_dir, "history.csv")
    if os.path.exists(hist_path):
        hist = read_forces(hist_path)
        v = summary["cutting"]["cutting_speed_m_per_s"]
        wf = np.interp([lo / v, end / v], hist["time_s"], hist["friction_work_J_per_m"])
        out["window_friction_work_J_per_m"] = float(wf[1] - wf[0])
        out["window_friction_work_per_travel_N_per_mm"] = float(wf[1] - wf[0]) / (end - lo) * 1e-3
    for key in ("tool_chip_contact_length_m", "rake_face"):
        if key in summary:
            out[key] = summary[key]
    return out


def main(argv):
    dirs, travel_from, travel_to, as_json = [], None, None, False
    it = iter(argv)
    for a in it:
        if a == "--from":
            travel_from = float(next(it))
        elif a == "--to":
            travel_to = float(next(it))
        elif a == "--json":
            as_json = True
        else:
            dirs.append(a)
    if not dirs:
        print(__doc__)
        return 2
    results = [analyse(d, travel_from, travel_to) for d in dirs]
    if as_json:
        print(json.dumps(results, indent=1))
        return 0
    print("dir | h (um) | cells | Fc (N/mm) | Fc at 1/h (%) | Ft (N/mm) | Ft at 1/h (%) | Fc long-wave max (N/mm) | "
          "friction work in window (J/m) [per travel, N/mm] | contact length (um) | rake friction/normal")
    for r in results:
        rake = r.get("rake_face", {})
        cl = r.get("tool_chip_contact_length_m")
        print(f"{r['dir']} | {r['cell_size_m'] * 1e6:.1f} | {r['window_cells']} | {r['Fc']['mean_N_per_mm']:.1f} | "
              f"{r['Fc']['cell_amplitude_percent']:.2f} | {r['Ft']['mean_N_per_mm']:.1f} | "
              f"{r['Ft']['cell_amplitude_percent']:.2f} | {r['Fc']['max_long_wave_amplitude_N_per_mm']:.2f} | "
              f"{r.get('window_friction_work_J_per_m', float('nan')):.3f} "
              f"[{r.get('window_friction_work_per_travel_N_per_mm', float('nan')):.2f}] | "
              f"{(cl * 1e6 if cl else float('nan')):.1f} | {rake.get('friction_to_normal_ratio', float('nan')):.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
