"""membra: the form a pre-stretched, resin-impregnated membrane takes when released.

Units, as in the outputs: lengths in millimetres, Gaussian curvature in 1/m^2 (principal
curvatures in 1/m), stress in MPa, time in seconds. Quick start (docs/python.md)::

    import membra
    scene = membra.Scene("examples/synclastic_ellipse.json", set={"sheet.resolution": [21, 21]})
    result = membra.run(scene)
    result.positions          # (n, 3) numpy array, mm
    result.report["shape"]    # the same dict as report.json
    result.write("out/ellipse")

Long solves release the GIL; Ctrl-C stops them with KeyboardInterrupt.
"""

from ._build import PYTHON as _BUILT_FOR
from ._build import VERSION as __version__


def _check_interpreter():
    """Fails at import, naming the interpreter to use, where the native module or numpy would
    fail later: another Python version, or an interpreter without numpy."""
    import importlib.machinery
    import sys
    from pathlib import Path

    here = Path(__file__).resolve().parent
    natives = [p.name for p in here.glob("_membra*.so")]
    # The interpreter's own tagged suffixes (".cpython-311-x86_64-linux-gnu.so"): the plain
    # ".so" and the stable ABI's would match a module built for any version.
    tagged = [s for s in importlib.machinery.EXTENSION_SUFFIXES if s not in (".so", ".abi3.so")]
    if natives and not any(n.endswith(s) for n in natives for s in tagged):
        raise ImportError(
            f"membra's native module ({natives[0]}) was built for {_BUILT_FOR}; this is "
            f"{sys.executable} (Python {sys.version_info.major}.{sys.version_info.minor}): "
            f"run it with {_BUILT_FOR}")
    try:
        import numpy  # noqa: F401  (every array membra returns is numpy's)
    except ImportError:
        raise ImportError(
            f"membra needs numpy, which {sys.executable} does not have: run it with "
            f"{_BUILT_FOR}, the interpreter membra was built for (Debian's python3-numpy)"
        ) from None


_check_interpreter()

from ._membra import OutputError, SceneError  # noqa: E402
from .design import DesignResult, design  # noqa: E402
from .membrane import Membrane  # noqa: E402
from .result import Result  # noqa: E402
from .scene import Scene, validate  # noqa: E402
from .run import MembraWarning, run  # noqa: E402
from . import sweep_spec  # noqa: E402

__all__ = [
    "__version__",
    "Scene",
    "run",
    "validate",
    "design",
    "sweep",
    "Membrane",
    "Result",
    "DesignResult",
    "SceneError",
    "OutputError",
    "MembraWarning",
]


def sweep(*args, **kwargs):
    """Runs a sweep on a Dask cluster; see membra.sweep.sweep (imported lazily: Dask is only
    needed for sweeps)."""
    from .sweeps import sweep as _sweep

    return _sweep(*args, **kwargs)
