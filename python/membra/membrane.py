"""The material process step by step, for notebooks: stretch, impregnate, release, ..."""

import copy
import json

from . import _membra
from .result import Result
from .scene import as_scene


class Membrane:
    """A membrane carried through the process one step at a time (docs/process.md).

    Membrane(scene, progress=None): the scene's sheet, frame, pins and simulation settings,
    prepared flat; its protocol is not applied (run_protocol() applies it). Each step method
    takes the step's fields as keyword arguments, exactly as a scene's protocol entry
    (docs/scene.md), with `lambda_` for "lambda"; it carries out the step, follows it to
    equilibrium, and returns True unless the solve diverged::

        m = membra.Membrane(scene)
        m.stretch(lambda_=[1.5, 1.0])
        m.impregnate(material="epoxy", pattern={"circle": {"center": [150, 100], "radius": 60}})
        m.release(increments=10)
        m.positions            # (n, 3) numpy array, mm
        m.result().report      # as report.json

    A step's fields are validated by the scene reader: a bad one raises membra.SceneError
    whose .pointer is its place in the protocol ("/protocol/2/pattern").
    """

    def __init__(self, scene, progress=None):
        self.scene = as_scene(scene)
        base = copy.deepcopy(self.scene.data)
        self._own_protocol = base.pop("protocol", [])
        self._base = base
        self.steps = []  # the steps applied so far, as protocol entries
        # Prepared from the whole scene (its protocol is not applied: the steps are yours), so
        # that it is valid exactly when membra.run takes it.
        self._run = _membra.NativeRun(self.scene._native, progress)

    def step(self, entry):
        """Applies one protocol entry, a dict such as {"step": "release", "increments": 10}."""
        data = dict(self._base, protocol=self.steps + [entry])
        with_step = _membra.parse_scene(json.dumps(data), str(self.scene.base_dir))
        ok = self._run.apply_last(with_step)
        self.steps.append(copy.deepcopy(entry))
        return ok

    def _kind(kind, doc):
        def apply(self, **fields):
            entry = {"step": kind}
            for k, v in fields.items():
                entry[k.rstrip("_")] = v
            return self.step(entry)

        apply.__name__ = kind
        apply.__doc__ = doc + " Fields as in a scene's protocol (docs/scene.md)."
        return apply

    stretch = _kind("stretch", "Stretches the sheet on its frame (lambda_=[lx, ly]).")
    impregnate = _kind("impregnate", "Cures resin into the springs under `pattern`.")
    release = _kind("release", "Releases the frame gradually (increments=...).")
    grow = _kind("grow", "Changes rest lengths by a growth field.")
    cut = _kind("cut", "Cuts along a polyline or removes a hole.")
    add_springs = _kind("add_springs", "Adds springs that pull particles together.")
    curvature_map = _kind("curvature_map", "Grows the sheet towards a Gaussian-curvature map.")
    load = _kind("load", "Pins particles and applies loads.")
    del _kind

    def run_protocol(self):
        """Applies the scene's own protocol steps that have not been applied, in order. Returns
        False as soon as one diverges."""
        for entry in self._own_protocol[len(self.steps):]:
            if not self.step(entry):
                return False
        return True

    def solve(self):
        """Solves the membrane as it stands to equilibrium (the scene's solver). Returns False
        when the solve diverged."""
        return self._run.solve()

    @property
    def positions(self):
        """(n, 3) numpy array, mm: the particles as they are now."""
        return self._run.positions

    def result(self):
        """The membrane so far, measured as at the end of a run: a membra.Result (its report
        and write() as for membra.run)."""
        return Result(self._run.result(), self.scene)

    def __repr__(self):
        done = ", ".join(s["step"] for s in self.steps) or "flat"
        return f"<membra.Membrane {self.scene.name!r}: {done}>"
