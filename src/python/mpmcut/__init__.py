"""mpmcut: material point method simulation of orthogonal metal cutting, from Python.

    import mpmcut
    case = mpmcut.load_case("cases/ti64_quick.toml", {"cutting.cutting_speed": 30.0})
    run = mpmcut.Run(case, "results/quick", force=True, threads=1)
    run.run()
    print(run.summary()["mean_cutting_force_N_per_mm"], run.forces()["cutting_force_N_per_mm"])

See docs/python.md. A run writes the same result directory as `mpmcut run`, through the same library code.
"""
import os

from ._mpmcut import Case, InputError, Run, __version__, grid_convergence, particle_field_units, particle_fields

__all__ = ["Case", "InputError", "Run", "load_case", "case_from_toml", "default_case", "overrides_from", "run_case",
           "particle_fields", "particle_field_units", "grid_convergence", "__version__"]


# Case.__new__(Case) and Run.__new__(Run) gave objects whose C++ part was never made, and using them crashed the
# interpreter (pybind11 does not check). Cases come from the functions below (made in C++, which does not call
# __new__); a Run from Run(case, out, ...), which calls __new__ with its arguments and then __init__.
def _case_new(cls, *args, **kwargs):
    raise TypeError("mpmcut.Case is made by mpmcut.load_case(), case_from_toml() or default_case()")


_run_new_of_pybind11 = Run.__new__


def _run_new(cls, *args, **kwargs):
    if not args and not kwargs:
        raise TypeError("mpmcut.Run is made by Run(case, out, ...), run_case() or Run.resume(out)")
    return _run_new_of_pybind11(cls, *args, **kwargs)


Case.__new__ = _case_new
Run.__new__ = _run_new


def _toml_value(value):
    """A Python value as the TOML text a --set override takes."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int) and not -2**63 <= value < 2**63:
        # TOML's integers are 64-bit: the text would not parse as a number and be taken for a bare string.
        raise ValueError(f"{value} is outside the 64-bit integer range of a case value (±9.2e18)")
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    if hasattr(value, "tolist"):  # NumPy scalars and arrays
        return _toml_value(value.tolist())
    raise TypeError(f"cannot write {value!r} ({type(value).__name__}) as a case value")


def overrides_from(overrides):
    """`--set`-style override strings from a dict {"solver.cfl": 0.3, "body[0].velocity": [1, 0]} (or a list of
    "key=value" strings, taken as they are)."""
    if overrides is None:
        return []
    if isinstance(overrides, dict):
        texts = []
        for key, value in overrides.items():
            try:
                texts.append(f"{key}={_toml_value(value)}")
            except (ValueError, TypeError) as e:  # name the key, as every other override error does
                raise type(e)(f"key '{key}': {e}") from None
        return texts
    if isinstance(overrides, (str, bytes)):  # would be taken apart into characters
        raise TypeError(f"overrides: a dict {{key: value}} or a list of 'key=value' strings, not one string "
                        f"({overrides!r}: write [{overrides!r}])")
    return [str(o) for o in overrides]


def load_case(path, overrides=None):
    """A case from a TOML file, with overrides applied before validation (InputError names file:line)."""
    return Case._from_file(os.fspath(path), overrides_from(overrides))


def case_from_toml(text, overrides=None, name="<string>"):
    """A case from TOML text."""
    return Case._from_toml(text, name, overrides_from(overrides))


def default_case(overrides=None):
    """The built-in default cut (cases/ti64_default.toml), as `mpmcut run` without a case file."""
    return Case._default_cut(overrides_from(overrides))


def run_case(case, out, callback=None, every=1, **options):
    """Runs `case` into `out` to its end and returns the finished Run (options as for Run)."""
    if every < 1:  # before the result directory is made
        raise ValueError(f"run_case: every must be 1 or more steps, got {every}")
    run = Run(case, os.fspath(out), **options)
    run.run(callback, every)
    return run
