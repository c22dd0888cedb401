"""The Python module's tests (docs/python.md). ctest runs them with PYTHONPATH=build/python and
MEMBRA_CLI set to the membra binary; by hand:

    PYTHONPATH=build/python MEMBRA_CLI=build/bin/membra python3 -m pytest tests/python
"""

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def cli():
    return os.environ.get("MEMBRA_CLI", str(ROOT / "build" / "bin" / "membra"))


@pytest.fixture
def small_ellipse():
    """The headline example on a small grid: a bowl in about a second."""
    import membra

    return membra.Scene(ROOT / "examples" / "synclastic_ellipse.json",
                        set={"sheet.resolution": [13, 13], "simulation.solver": "newton"})


@pytest.fixture(scope="session")
def cli_env():
    """The environment for a CLI run whose bytes are compared with this process's: the same
    BLAS settings (OPENBLAS_CORETYPE selects kernels that round differently), one OpenMP thread."""
    return dict(os.environ, OMP_NUM_THREADS="1")
