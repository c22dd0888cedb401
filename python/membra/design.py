"""Inverse design: which resin pattern gives a form asked for (docs/inverse_design.md)."""

import json
import os
from pathlib import Path

from . import _membra


class DesignResult:
    """The best stencil found: rms_error and max_error (% of the target's diameter),
    flat_error (what a flat sheet scores), verdict and verdict_note (meets_goal,
    closer_than_flat or no_closer_than_flat and the same in words, as report.json's
    design.verdict and design.verdict_note), prestretch (the frame's stretch the stencil was
    simulated at: the file's, or the one "search_stretch" found), pieces_bottom (the stencil's
    pieces on the bottom face), reachable and message, the best form's positions
    (n, 3, mm) and triangles, scene (the scene.json dict that reproduces the form through
    membra.run), report (as the design's report.json), write(dir)."""

    def __init__(self, native):
        self._native = native

    rms_error = property(lambda self: self._native.rms_error)
    max_error = property(lambda self: self._native.max_error)
    flat_error = property(lambda self: self._native.flat_error)
    reachable = property(lambda self: self._native.reachable)
    message = property(lambda self: self._native.message)
    positions = property(lambda self: self._native.positions)
    triangles = property(lambda self: self._native.triangles)
    scene = property(lambda self: self._native.scene)
    report = property(lambda self: self._native.report)
    verdict = property(lambda self: self._design_report["verdict"])
    verdict_note = property(lambda self: self._design_report["verdict_note"])
    prestretch = property(lambda self: tuple(self._design_report["lambda"]))
    pieces_bottom = property(lambda self: self._design_report["stencil"]["pieces_bottom"])
    _design_report = property(lambda self: self.report["design"])

    def write(self, dir):
        """Writes what `membra design target FILE --out DIR` writes, all or nothing."""
        self.render_note = self._native.write(str(dir))
        return Path(dir)

    def __repr__(self):
        return f"<membra.DesignResult rms {self.rms_error:.2f} % (flat {self.flat_error:.2f} %)>"


def design(target, out=None, progress=None, base_dir=None, cache=True):
    """Searches the stencil whose released form is closest to a target (membra design target).

    target: a design file path, or its content as a dict (docs/inverse_design.md).
    out: if given, the folder to write the outputs to.
    progress: None or a callable taking a dict per forward simulation {"index", "stage",
        "rms_error", "max_error", "resin_share", "pieces", "density_scale", "seconds", "best",
        "note", "objective", "gradient_norm"}; with "method": "adjoint" the density iterates have
        stage "density" (rms_error: to the particles' own target points), the stencil trials
        "stencil" (density_scale: the multiple of the designed densities laid out), the piece
        sizes' iterates "pieces" (as "density") and the sized stencil "stencil" again.
    cache: keep the adjoint method's stencil calibration in $MEMBRA_CACHE_DIR (else
        ~/.cache/membra) and read it back for later designs on the same sheet, as
        `membra design` does; False measures it every time.
    Raises membra.SceneError naming the field at fault in the design file.
    """
    if isinstance(target, dict):
        spec = _membra.parse_design(json.dumps(target), str(base_dir or os.getcwd()))
    else:
        spec = _membra.load_design(str(target))
    result = DesignResult(_membra.design(spec, progress, cache))
    if out is not None:
        result.write(out)
    return result
