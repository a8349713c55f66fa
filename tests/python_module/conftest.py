"""Shared set-up of the Python module's tests: the module from the build tree (PYTHONPATH, set by ctest),
the command-line program beside it, and a short cutting case."""
import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("MPMCUT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BINARY = os.environ.get("MPMCUT_BINARY", str(SOURCE_DIR / "build" / "mpmcut"))

# The quick Ti-6Al-4V cut, cut short: a few hundred steps, forces and history on every step.
QUICK_CASE = SOURCE_DIR / "cases" / "ti64_quick.toml"
SHORT = {"solver.max_steps": 150, "output.history_interval": 0.0}


@pytest.fixture
def binary():
    return BINARY


@pytest.fixture
def quick_case():
    return QUICK_CASE


@pytest.fixture
def short():
    return dict(SHORT)
