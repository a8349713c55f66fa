"""examples/speed_sweep.py runs (with a tiny setting, so that it cannot rot): one run per speed and the plot."""
import subprocess
import sys

from conftest import SOURCE_DIR


def test_speed_sweep_example_runs_and_plots(tmp_path):
    out = tmp_path / "sweep"
    result = subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "speed_sweep.py"), "--speeds", "10", "30",
                             "--max-steps", "40", "--threads", "1", "--out", str(out)],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "v = 10 m/s: Fc =" in result.stdout and "v = 30 m/s: Fc =" in result.stdout
    assert (out / "v10" / "summary.json").exists() and (out / "v30" / "forces.csv").exists()
    assert (out / "fc_vs_speed.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
