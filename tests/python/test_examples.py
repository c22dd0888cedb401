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


def _notebook_writer(root):
    import importlib.machinery
    import importlib.util

    path = str(root / "scripts" / "notebook-from-script")
    loader = importlib.machinery.SourceFileLoader("notebook_from_script", path)
    spec = importlib.util.spec_from_loader("notebook_from_script", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def test_the_notebook_holds_the_scripts_cells(root):
    import nbformat

    here = root / "examples" / "python"
    made = _notebook_writer(root).notebook((here / "notebook.py").read_text(encoding="utf-8"))
    committed = nbformat.read(here / "notebook.ipynb", as_version=4)
    assert [c.source for c in committed.cells] == [c.source for c in made.cells], \
        "rerun scripts/notebook-from-script examples/python/notebook.py"


def test_the_notebook_runs_headless_in_jupyter(root, tmp_path, monkeypatch):
    """The .ipynb under a real kernel (nbclient): its figure and the result's inline view."""
    import nbformat
    from nbclient import NotebookClient

    here = root / "examples" / "python"
    monkeypatch.setenv("MEMBRA_NOTEBOOK_RESOLUTION", "13")
    monkeypatch.setenv("MEMBRA_NOTEBOOK_OUT", str(tmp_path))
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # the kernel's debugger notice
    nb = nbformat.read(here / "notebook.ipynb", as_version=4)
    NotebookClient(nb, timeout=300, kernel_name="python3",
                   resources={"metadata": {"path": str(here)}}).execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    assert any("image/png" in o.get("data", {}) for o in outputs)  # the comparison figure
    inline = nb.cells[-1].outputs[0]["data"]["text/html"]
    assert "<canvas" in inline and "global form" in inline
    assert (tmp_path / "compare.png").stat().st_size > 20_000
