"""What a run returns: the released form as numpy arrays, the report, the files."""

from pathlib import Path


class Result:
    """The end state of a run.

    Arrays (numpy, one row per particle of the final sheet, in the outputs' units):
      positions          (n, 3) float, mm: where each particle came to rest
      paper_positions    (n, 2) float, mm: where it sits on the unstretched paper sheet
      triangles          (m, 3) int: particle indices, counter-clockwise seen from +z
      gaussian_curvature (n,) float, 1/m^2: angle defect over area (0 on the rim)
      stress             (n,) float, MPa: mean stress of the particle's springs
    report: dict, the same as report.json (docs/cli.md lists its keys and units).
    """

    def __init__(self, native, scene):
        self._native = native
        self.scene = scene
        self._report = None

    positions = property(lambda self: self._native.positions)
    paper_positions = property(lambda self: self._native.paper_positions)
    triangles = property(lambda self: self._native.triangles)
    gaussian_curvature = property(lambda self: self._native.gaussian_curvature)
    stress = property(lambda self: self._native.stress)

    @property
    def report(self):
        """report.json's content as a dict (computed once)."""
        if self._report is None:
            self._report = self._native.report
        return self._report

    @property
    def converged(self):
        """True when the last solve met its tolerance (report["converged"])."""
        return bool(self.report["converged"])

    @property
    def warnings(self):
        """Advice before trusting the form (report["warnings"]), e.g. a grid too coarse for the
        pattern; membra.run also issues each as a Python warning (MembraWarning)."""
        return list(self._native.warnings)

    @property
    def diverged(self):
        """True when the run blew up: write() then writes report.json only."""
        return bool(self._native.diverged)

    def write(self, dir, curvature_range=None, stress_range=None):
        """Writes the files `membra run --out DIR` writes (report.json, final.obj, final.ply,
        pattern.svg/.dxf, the PNG pictures), all or nothing. curvature_range: (lo, hi) in
        1/m^2, stress_range: (lo, hi) in MPa, as --curvature-range / --stress-range.
        Returns the folder as a Path. Raises membra.OutputError when it cannot be written."""
        note = self._native.write(str(dir), list(curvature_range or []), list(stress_range or []))
        self.render_note = note  # "" or why no PNG could be rendered (no OpenGL)
        return Path(dir)

    def _repr_html_(self):
        """Jupyter's inline view: the form in 3-D (drag to turn), coloured by Gaussian
        curvature, beside its key numbers."""
        from .inline_view import result_html

        r = self.report
        shape, glob = r.get("shape", {}), r.get("curvature", {}).get("global", {})
        facts = [("global form", str(glob.get("classification", "?"))),
                 ("height", f"{shape.get('height', float('nan')):.1f} mm"),
                 ("global total K", f"{glob.get('total', float('nan')):+.3f} rad"),
                 ("particles", str(len(self.positions))),
                 ("converged", "yes" if self.converged else "no")]
        quadric = shape.get("quadric")
        if quadric:
            facts.insert(1, ("best-fit quadric", str(quadric.get("classification"))))
        facts += [("warning", w) for w in self.warnings]
        return result_html(self.positions, self.triangles, self.gaussian_curvature,
                           f"membra: {self.scene.name}", facts)

    def __repr__(self):
        shape = self.report.get("shape", {})
        return (f"<membra.Result {self.scene.name!r}: {len(self.positions)} particles, "
                f"height {shape.get('height', float('nan')):.2f} mm>")
