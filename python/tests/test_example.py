"""The worked example in python/examples runs and prints its results."""

import os
import pathlib
import subprocess
import sys

EXAMPLE = pathlib.Path(__file__).resolve().parents[1] / "examples" / "scene01_study.py"


def test_worked_example_runs(tmp_path):
    env = dict(os.environ, MPLBACKEND="Agg", KINREPRO_EXAMPLE_OUT=str(tmp_path))
    out = subprocess.run([sys.executable, str(EXAMPLE)], cwd=EXAMPLE.parents[2], env=env,
                         check=True, capture_output=True, text=True).stdout
    assert "sigma_x" in out and "preload.force" in out
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return
    assert (tmp_path / "scene01_scatter.png").stat().st_size > 1000
