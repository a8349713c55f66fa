#!/usr/bin/env python3
"""A small cutting-speed sweep from Python: coarse, short cuts of Ti-6Al-4V, the cutting force Fc of each, and a
plot of Fc against speed (docs/python.md).

    PYTHONPATH=build/python /usr/bin/python3 examples/speed_sweep.py --out results/speed_sweep

Each run is a result directory like `mpmcut run` writes (results/speed_sweep/v<speed>/). Fc is the mean over the
steady window when the cut reached it (summary.json), else the mean over the last half of the cut (forces.csv).
The defaults take seconds per speed; they are far too coarse for numbers to quote (see docs/results/convergence/convergence.md).
"""
import argparse
import os
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import mpmcut  # noqa: E402

CASE = pathlib.Path(__file__).resolve().parents[1] / "cases" / "ti64_quick.toml"


def cutting_force(run):
    """Mean Fc in N/mm: the steady window's, else the last half of the tool travel's."""
    mean = run.summary().get("mean_cutting_force_N_per_mm")
    if mean is not None:
        return mean, "steady window"
    forces = run.forces()
    t, fc = forces["time_s"], forces["cutting_force_N_per_mm"]
    return float(np.mean(fc[t >= 0.5 * t[-1]])), "last half of the cut"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--speeds", type=float, nargs="+", default=[10.0, 20.0, 40.0], help="cutting speeds, m/s")
    parser.add_argument("--cut-length", type=float, default=0.1e-3, help="tool travel, m (default 0.1 mm)")
    parser.add_argument("--cell-size", type=float, default=20e-6, help="grid cell, m (default 20 um: coarse)")
    parser.add_argument("--max-steps", type=int, default=0, help="stop each run after this many steps (0: no limit)")
    parser.add_argument("--threads", type=int, default=0, help="OpenMP threads per run (0: all cores)")
    parser.add_argument("--out", default="results/speed_sweep", help="result folder")
    args = parser.parse_args(argv)

    out = pathlib.Path(args.out)
    speeds, fcs = [], []
    for v in args.speeds:
        overrides = {"cutting.cutting_speed": v, "cutting.cut_length": args.cut_length,
                     "cutting.cell_size": args.cell_size}
        if args.max_steps > 0:
            overrides["solver.max_steps"] = args.max_steps
        case = mpmcut.load_case(CASE, overrides)
        run = mpmcut.run_case(case, out / f"v{v:g}", force=True, threads=args.threads)
        if run.status != "complete":
            print(f"v = {v:g} m/s: {run.status}: {run.summary().get('message', '')}", file=sys.stderr)
            continue
        fc, basis = cutting_force(run)
        print(f"v = {v:g} m/s: Fc = {fc:.1f} N/mm ({basis}, {run.step_count} steps)")
        speeds.append(v)
        fcs.append(fc)

    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(speeds, fcs, "o-")
    ax.set_xlabel("cutting speed (m/s)")
    ax.set_ylabel("cutting force Fc (N/mm)")
    ax.set_title("Ti-6Al-4V, coarse short cuts")
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    os.makedirs(out, exist_ok=True)
    fig.savefig(out / "fc_vs_speed.png", dpi=120)
    print(f"wrote {out / 'fc_vs_speed.png'}")
    return 0 if len(speeds) == len(args.speeds) else 1


if __name__ == "__main__":
    sys.exit(main())
