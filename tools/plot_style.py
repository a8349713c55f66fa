"""Shared look of the mpmcut figures (journal-like: serif-free, small, 200 dpi) and small helpers.

Imported by plot_result.py, plot_sweep.py and plot_validation.py. The mpmcut binary writes all of
tools/*.py into one temporary folder before it runs one of them, so this import works there too.
"""
import csv
import json
import math
import os

import matplotlib

matplotlib.use("Agg")  # files only; never a window
import matplotlib.pyplot as plt  # noqa: E402

DPI = 200
COLOR_FC = "#1f4e9c"   # cutting force: dark blue
COLOR_FT = "#c0392b"   # thrust force: dark red
FEED_COLORS = ["#1f4e9c", "#c0392b", "#2e8b57", "#8e44ad", "#d35400", "#2c3e50"]


def apply_style():
    plt.rcParams.update({
        "font.size": 9,
        "axes.titlesize": 9.5,
        "axes.labelsize": 9,
        "legend.fontsize": 8,
        "xtick.direction": "in",
        "ytick.direction": "in",
        "xtick.top": True,
        "ytick.right": True,
        "axes.linewidth": 0.8,
        "savefig.dpi": DPI,
        "savefig.bbox": "tight",
        "savefig.pad_inches": 0.04,
    })


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def read_csv_rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def to_float(text):
    """A CSV cell as a float; None for blanks and non-numbers."""
    if text is None:
        return None
    try:
        x = float(text)
    except ValueError:
        return None
    return x if math.isfinite(x) else None


def save(fig, path):
    fig.savefig(path)
    plt.close(fig)
    print("wrote", os.path.abspath(path))
