"""Scenes: a dict, JSON text or a scene file, validated by the same reader as `membra run`."""

import copy
import json
import os
from pathlib import Path

from . import _membra


def _set_args(set):
    """`set` as `--set` assignments: a dict {"sheet.resolution": [21, 21]} or a list of
    "path=value" strings."""
    if set is None:
        return []
    if isinstance(set, dict):
        return [f"{k}={json.dumps(v)}" for k, v in set.items()]
    if isinstance(set, str):
        return [set]
    return [str(s) for s in set]


class Scene:
    """A validated scene (docs/scene.md).

    Scene(source, set=None, base_dir=None)

    source: a dict, JSON text, or the path of a scene file (str or Path).
    set: overrides applied before validation, as `membra run --set` takes them: a dict
        {"simulation.solver": "newton", "sheet.resolution": [21, 21]} or a list of
        "path=value" strings.
    base_dir: where files the scene names (images) are found; default the scene file's folder,
        or the working directory for a dict or text.

    Raises membra.SceneError (with .pointer, the JSON pointer of the field at fault, and
    .detail) for an invalid scene; the message names the file when there is one.
    """

    def __init__(self, source, set=None, base_dir=None):
        sets = _set_args(set)
        if isinstance(source, Scene):
            base_dir = base_dir or source.base_dir
            source = copy.deepcopy(source.data)
        if isinstance(source, dict):
            self.file = None
            self.base_dir = Path(base_dir or os.getcwd())
            text = _membra.apply_overrides(json.dumps(source), sets)
            self._native = _membra.parse_scene(text, str(self.base_dir))
            self.data = json.loads(text)
        elif isinstance(source, str) and source.lstrip().startswith("{"):
            self.file = None
            self.base_dir = Path(base_dir or os.getcwd())
            text = _membra.apply_overrides(source, sets)
            self._native = _membra.parse_scene(text, str(self.base_dir))
            self.data = json.loads(text)
        else:
            self.file = Path(source)
            self.base_dir = Path(base_dir) if base_dir else self.file.parent
            self._native = _membra.load_scene(str(self.file), sets)
            with open(self.file, encoding="utf-8") as f:
                text = _membra.apply_overrides(f.read(), sets)
            self.data = json.loads(text)
            if base_dir is not None:  # files named relative to another folder
                self._native = _membra.parse_scene(text, str(self.base_dir))

    @property
    def name(self):
        """The scene's name (report.json "scene"; `membra run`'s default output folder)."""
        return self._native.name

    def with_set(self, set):
        """A copy with more overrides applied (same forms as the constructor's `set`)."""
        return Scene(copy.deepcopy(self.data), set=set, base_dir=self.base_dir)

    def validate(self):
        """Builds the sheet as a run would and returns its counts: {"particles", "springs",
        "pinned"}. Raises SceneError when the scene cannot be prepared (e.g. too large)."""
        return _membra.validate(self._native)

    def __repr__(self):
        where = f" from {self.file}" if self.file else ""
        return f"<membra.Scene {self.name!r}{where}>"


def as_scene(scene, set=None):
    """A Scene from anything Scene() takes (a Scene is kept as it is unless `set` is given)."""
    if isinstance(scene, Scene):
        return scene.with_set(set) if set else scene
    return Scene(scene, set=set)


def validate(scene, set=None):
    """Validates a scene (anything Scene() takes) and returns its counts, as `membra validate`:
    {"particles", "springs", "pinned"}. Raises SceneError naming the field at fault."""
    return as_scene(scene, set).validate()
