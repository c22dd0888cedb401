"""The Python examples run, on small grids."""

import subprocess
import sys

import pandas as pd


def test_the_notebook_example_runs(root, tmp_path):
    run = subprocess.run([sys.executable, str(root / "examples" / "python" / "notebook.py"),
                          "--resolution", "13", "--out", str(tmp_path)],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    assert "step by step gives the same form as membra.run: True" in run.stdout
    assert (tmp_path / "compare.png").stat().st_size > 20_000


def test_the_sweep_example_runs(root, tmp_path):
    run = subprocess.run([sys.executable, str(root / "examples" / "python" / "sweep_ellipse.py"),
                          "--resolution", "9", "--image-size", "160", "120", "--values", "3",
                          "--out",
                          str(tmp_path)],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    table = pd.read_csv(tmp_path / "results.csv")
    assert len(table) == 9
    assert "deepest bowls" in run.stdout
