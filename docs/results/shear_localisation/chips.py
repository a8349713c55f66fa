#!/usr/bin/python3
"""chips.png: the plastic strain pictures of the two ends at the four resolutions, side by side.

Reads the chip_plastic_strain_*.png that each run drew (run.sh writes results/shear_localisation/<variant>_<condition>;
the matrix-resolution runs are those of docs/results/crack_gap/run.sh, the same physics and scenes as the penalty
matrix's records).
usage: /usr/bin/python3 docs/results/shear_localisation/chips.py [--matrix-runs PATTERN]
"""
import argparse
import glob
import pathlib

import matplotlib
matplotlib.use("Agg")
import matplotlib.image as mpimg
import matplotlib.pyplot as plt

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[2]


def picture(run_dir):
    found = sorted(glob.glob(str(run_dir / "chip_plastic_strain_*.png")))
    if not found:
        raise SystemExit(f"chips.py: no chip_plastic_strain_*.png in {run_dir} (run it, or `mpmcut plot` it, first)")
    return mpimg.imread(found[-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--matrix-runs", default="results/crack_gap/gap_{c}/{c}",
                    help="run directory of the matrix-resolution runs, {c} = condition (default: %(default)s)")
    a = ap.parse_args()
    study = "results/shear_localisation/{n}_{c}/{c}"
    columns = [("t0/12–13 (matrix: 7.9 / 8.25 µm)", a.matrix_runs),
               ("t0/16 (6.25 µm)", study.replace("{n}", "t0_16")),
               ("t0/24 (4.17 µm)", study.replace("{n}", "t0_24")),
               ("t0/32 (3.13 µm)", study.replace("{n}", "t0_32"))]
    fig, ax = plt.subplots(2, len(columns), figsize=(5 * len(columns), 8.4))
    for j, (label, pattern) in enumerate(columns):
        for i, v in enumerate(["12.6", "381.3"]):
            c = f"forces_h0.1mm_vc{v}mpmin"
            ax[i, j].imshow(picture(ROOT / pattern.format(c=c)))
            ax[i, j].set_title(f"{v} m/min, {label}", fontsize=11)
            ax[i, j].axis("off")
    fig.suptitle("Equivalent plastic strain at 0.6 mm of cut, h = 0.1 mm (penalty contact, speed-ends material)")
    fig.tight_layout()
    fig.savefig(HERE / "chips.png", dpi=110)


if __name__ == "__main__":
    main()
