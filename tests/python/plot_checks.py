"""Shared checks of the plot tests: a PNG exists and is not blank (many distinct colours, not one flat field)."""
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402


def fail(message):
    print("FAIL:", message, file=sys.stderr)
    sys.exit(1)


def check_png(path, min_colours=20, min_bytes=8000):
    if not os.path.exists(path):
        fail(f"{path} was not written")
    size = os.path.getsize(path)
    if size < min_bytes:
        fail(f"{path}: only {size} bytes")
    img = mpimg.imread(path)
    if img.ndim != 3 or img.shape[0] < 200 or img.shape[1] < 200:
        fail(f"{path}: unexpected image shape {img.shape}")
    rgb = np.round(img[:, :, :3] * 255).astype(np.int32)
    colours = len(np.unique(rgb[:, :, 0] * 65536 + rgb[:, :, 1] * 256 + rgb[:, :, 2]))
    if colours < min_colours:
        fail(f"{path}: only {colours} distinct colours: blank or nearly so")
    print(f"ok {os.path.basename(path)}: {img.shape[1]}x{img.shape[0]}, {colours} colours, {size} bytes")
