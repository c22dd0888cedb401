"""A sweep's description (docs/sweeps.md) expanded into jobs, one per scene to run.

A sweep file (JSON), or the same as a dict::

    {
      "name": "ellipse_axes",
      "scene": "../synclastic_ellipse.json",          # the base scene (or "design": a design file)
      "set": {"sheet.resolution": [21, 21]},          # overrides of every job
      "grid": {"protocol.1.pattern.union.0.ellipse.radii.0": [100, 120],
               "protocol.1.pattern.union.0.ellipse.radii.1": [60, 80]},   # every combination
      "list": [{"simulation.solver": "newton"}, ...], # or: these parameter sets, one job each
      "scenes": ["a.json", "b.json"],                 # or: these scene files, one job each
      "labels": {"protocol.1.pattern.union.0.ellipse.radii.0": "width"}  # short column names
    }

Paths in the file are relative to the file. `grid` and `list` combine: each list entry is
crossed with the grid. Jobs are numbered in a fixed order, so that a sweep's results and
folders are the same whatever the cluster.
"""

import hashlib
import itertools
import json
import math
from pathlib import Path

from ._membra import SceneError

KNOWN_KEYS = {"name", "description", "scene", "design", "set", "grid", "list", "scenes", "labels"}


MAX_JOBS = 100_000


def _error(where, detail):
    err = SceneError(f"{where}: {detail}")
    err.pointer = where
    err.detail = detail
    return err


def load_sweep(source, base_dir=None):
    """The sweep as a dict with absolute paths, from a file path or a dict. Raises SceneError
    naming the file and field for a malformed sweep."""
    where = "sweep"
    if isinstance(source, dict):
        spec = json.loads(json.dumps(source))
        base = Path(base_dir or ".").resolve()
    else:
        where = str(source)
        try:
            with open(source, encoding="utf-8") as f:
                spec = json.load(f)
        except OSError as e:
            raise _error(where, f"cannot read the sweep file: {e.strerror}") from None
        except json.JSONDecodeError as e:
            raise _error(where, f"malformed JSON at line {e.lineno}, column {e.colno}: {e.msg}") from None
        except UnicodeDecodeError as e:
            raise _error(where, f"not UTF-8 text (byte {e.start}): save it as UTF-8") from None
        base = Path(source).resolve().parent
    _check(spec, where)
    for key in ("scene", "design"):
        if key in spec:
            spec[key] = str((base / spec[key]).resolve())
    if "scenes" in spec:
        spec["scenes"] = [str((base / s).resolve()) for s in spec["scenes"]]
    spec.setdefault("name", Path(where).stem if where != "sweep" else "sweep")
    return spec


def _check(spec, where):
    if not isinstance(spec, dict):
        raise _error(where, "a sweep is a JSON object")
    unknown = sorted(set(spec) - KNOWN_KEYS)
    if unknown:
        raise _error(f"{where}: /{unknown[0]}", f"unknown key (known: {', '.join(sorted(KNOWN_KEYS))})")
    bases = [k for k in ("scene", "design", "scenes") if k in spec]
    if len(bases) != 1:
        raise _error(where, 'give exactly one of "scene", "design" or "scenes"')
    if "scenes" in spec and ("grid" in spec or "list" in spec):
        raise _error(f"{where}: /scenes", '"scenes" cannot be combined with "grid" or "list"')
    for key, kind in (("set", dict), ("grid", dict), ("list", list), ("scenes", list),
                      ("labels", dict)):
        if key in spec and not isinstance(spec[key], kind):
            raise _error(f"{where}: /{key}", f"must be a JSON {'object' if kind is dict else 'array'}")
    for path, values in spec.get("grid", {}).items():
        if not isinstance(values, list) or not values:
            raise _error(f"{where}: /grid/{path}", "must be a non-empty array of values")
    for path, label in spec.get("labels", {}).items():
        if not (isinstance(label, str) and label.strip()):
            raise _error(f"{where}: /labels/{path}", "must be a non-empty string: the column's name")
    for i, entry in enumerate(spec.get("list", [])):
        if not isinstance(entry, dict):
            raise _error(f"{where}: /list/{i}", "must be an object of path: value")
    for key in ("scene", "design", "name", "description"):
        if key in spec and not (isinstance(spec[key], str) and spec[key]):
            raise _error(f"{where}: /{key}", "must be a non-empty string")
    for i, file in enumerate(spec.get("scenes", [])):
        if not (isinstance(file, str) and file):
            raise _error(f"{where}: /scenes/{i}", "must be a scene file's path")
    # Counted before anything is expanded: a grid of a few long axes multiplies fast.
    jobs = max(1, len(spec.get("list", []))) * math.prod(len(v) for v in spec.get("grid", {}).values())
    if jobs > MAX_JOBS:
        raise _error(f"{where}: /grid", f"the sweep has {jobs} scenes; at most {MAX_JOBS} are run in "
                     "one sweep (split it, or sample the grid with a list)")


def expand(spec):
    """The jobs of a loaded sweep, in their fixed order: dicts with "id" ("0007"), "kind"
    ("run" or "design"), "file" (the scene or design file), "params" (path: value, the varied
    ones) and "sets" (every override, as --set strings)."""
    fixed = spec.get("set", {})
    if "scenes" in spec:
        variants = [({"scene": Path(f).stem}, f, {}) for f in spec["scenes"]]
    else:
        grid = spec.get("grid", {})
        combos = [dict(zip(grid, values)) for values in itertools.product(*grid.values())]
        rows = spec.get("list", [{}]) or [{}]
        file = spec.get("scene") or spec.get("design")
        variants = [({**row, **combo}, file, {**row, **combo}) for row in rows for combo in combos]
    kind = "design" if "design" in spec else "run"
    jobs = []
    digests = {}  # each file hashed once, however many jobs share it
    for i, (params, file, varied) in enumerate(variants):
        sets = [f"{k}={json.dumps(v)}" for k, v in {**fixed, **varied}.items()]
        if file not in digests:
            digests[file] = _digest(file)
        jobs.append({"id": f"{i:04d}", "kind": kind, "file": file, "params": params, "sets": sets,
                     "file_sha256": digests[file]})
    return jobs


def _digest(file):
    """The file's content hash, so that a resumed sweep reruns the jobs of an edited scene."""
    try:
        return hashlib.sha256(Path(file).read_bytes()).hexdigest()
    except OSError:
        return None  # the job fails, as a row, when it runs


def short_labels(params, labels=None, reserved=()):
    """Column names for the varied parameters: the sweep file's `labels` where it gives one,
    else each path's last segments, as few as keep its name apart from the others' and from the
    `reserved` columns, and not a bare index ("radii.0", "radii.1", "solver" for
    ...ellipse.radii.0, ...ellipse.radii.1 and simulation.solver). Raises SceneError for labels
    that clash."""
    labels = labels or {}
    reserved = set(reserved)
    for path in labels:
        if path not in params:
            raise _error(f"sweep: /labels/{path}",
                         f"names no varied parameter (varied: {', '.join(params) or 'none'})")
    given = [labels[p] for p in params if labels.get(p)]
    for path in params:
        label = labels.get(path)
        if label and (label in reserved or given.count(label) > 1):
            raise _error(f"sweep: /labels/{path}",
                         f"the column name {label!r} is taken (by a result column or another label)")
    depth = {p: 1 for p in params}

    def name(p):
        return labels.get(p) or ".".join(p.split(".")[-depth[p]:])

    for _ in range(64):  # each round lengthens the names that clash
        names = {p: name(p) for p in params}
        clash = [p for p in params if not labels.get(p) and depth[p] <= p.count(".") and (
            list(names.values()).count(names[p]) > 1 or names[p] in reserved
            or names[p].split(".")[0].isdigit())]
        if not clash:
            return names
        for p in clash:
            depth[p] += 1
    return {p: name(p) for p in params}
