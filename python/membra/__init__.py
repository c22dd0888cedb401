"""membra: the form a pre-stretched, resin-impregnated membrane takes when released.

Units, as in the scene files and the outputs: lengths in millimetres, Gaussian curvature in
1/mm^2, stress in MPa, time in seconds. Quick start (docs/python.md)::

    import membra
    scene = membra.Scene("examples/synclastic_ellipse.json", set={"sheet.resolution": [21, 21]})
    result = membra.run(scene)
    result.positions          # (n, 3) numpy array, mm
    result.report["shape"]    # the same dict as report.json
    result.write("out/ellipse")

Long solves release the GIL; Ctrl-C stops them with KeyboardInterrupt.
"""

from ._membra import OutputError, SceneError
from .design import DesignResult, design
from .membrane import Membrane
from .result import Result
from .scene import Scene, validate
from .run import MembraWarning, run
from . import sweep_spec

__all__ = [
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
