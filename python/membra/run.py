"""Running a scene in one go, as `membra run` does."""

import warnings

from . import _membra
from .result import Result
from .scene import as_scene


class MembraWarning(UserWarning):
    """Advice from a run before trusting its form (Result.warnings), e.g. a coarse grid."""


def run(scene, out=None, set=None, progress=None):
    """Runs a scene to the end and returns a membra.Result.

    scene: a membra.Scene, a dict, JSON text or a scene file path.
    out: if given, the folder to write the outputs to (Result.write).
    set: overrides, as for membra.Scene.
    progress: None or a callable taking a dict {"stage", "iteration", "max_iterations",
        "residual_relative", "wall_seconds", "step_done", "run_done"}, called every so often
        (run_done: the share of the whole run done, its steps weighted by their increments, or
        -1 when unknown; step_done: of the current step's path).

    The solve runs without the GIL (other Python threads go on); Ctrl-C raises
    KeyboardInterrupt within a progress interval. A run that diverges returns a Result with
    .diverged True (write() then writes report.json only). Each of Result.warnings (e.g. a
    grid too coarse for the pattern) is also issued as a membra.MembraWarning.
    """
    s = as_scene(scene, set)
    result = Result(_membra.run(s._native, progress), s)
    for text in result.warnings:
        warnings.warn(f"{s.name}: {text}", MembraWarning, stacklevel=2)
    if out is not None:
        result.write(out)
    return result
