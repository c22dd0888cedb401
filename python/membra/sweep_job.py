"""One job of a sweep, run where Dask puts it: the scene (or design) run, its files written to
the job's folder, and its row of the results table returned.

A job's folder holds the files `membra run` (or `membra design`) writes and, written last,
`row.json`: the row. A folder with a row.json of the same job is complete, and a resumed sweep
takes its row from there instead of running the job again.
"""

import json
import math
import os
import time
import traceback
from pathlib import Path

ROW_FILE = "row.json"


def job_dir(out, job):
    return Path(out) / "scenes" / job["id"]


def finished_row(out, job):
    """The row of a job that finished in an earlier run of the sweep, or None."""
    try:
        with open(job_dir(out, job) / ROW_FILE, encoding="utf-8") as f:
            row = json.load(f)
    except (OSError, ValueError):
        return None
    return row if row.get("job") == job else None


def _measures(report):
    """The columns taken from a run's report.json."""
    curvature = report.get("curvature", {})
    shape = report.get("shape", {})
    return {
        "status": report.get("status"),
        "converged": bool(report.get("converged", False)),
        "height": shape.get("height", math.nan),
        "global_height": shape.get("global_height", math.nan),
        "total_K": curvature.get("total", math.nan),
        "total_K_global": curvature.get("global", {}).get("total", math.nan),
        "classification": curvature.get("global", {}).get("classification"),
        "quadric": shape.get("quadric", {}).get("classification"),
        "quadric_k1": shape.get("quadric", {}).get("k1", math.nan),
        "quadric_k2": shape.get("quadric", {}).get("k2", math.nan),
        "stable": report.get("stability", {}).get("stable"),
        # pairs of triangles crossing: the form passes through itself (docs/measures.md)
        "self_intersection": report.get("self_intersection", {}).get("pairs"),
    }


def _run(job, folder):
    from . import _membra
    from .design import DesignResult
    from .result import Result
    from .scene import Scene

    if job["kind"] == "design":
        with open(job["file"], encoding="utf-8") as f:
            text = _membra.apply_overrides(f.read(), job["sets"])
        spec = _membra.parse_design(text, str(Path(job["file"]).parent))
        result = DesignResult(_membra.design(spec, None))
        result.write(folder)
        _save_form(folder, result)
        row = _measures(result.report)
        row["design_error"] = result.rms_error
        return row
    scene = Scene(job["file"], set=job["sets"])
    result = Result(_membra.run(scene._native, None), scene)
    result.write(folder)
    _save_form(folder, result)
    row = _measures(result.report)
    row["design_error"] = math.nan
    return row


def _save_form(folder, result):
    """The posed form as numbers (form.npz: positions mm, triangles, gaussian_curvature 1/m^2),
    for the contact sheet to draw every job on one colour range and one scale."""
    import numpy as np

    if getattr(result, "diverged", False):
        return
    # A design's result has no curvature per particle: its form is drawn white.
    k = getattr(result, "gaussian_curvature", None)
    np.savez_compressed(folder / "form.npz", positions=result.positions,
                        triangles=result.triangles,
                        gaussian_curvature=np.zeros(len(result.positions)) if k is None else k)


def run_job(job, out):
    """Runs one job into its folder under `out` and returns its row (a dict). A job that fails
    is a row with its error; it never raises, so that one bad scene loses no sweep."""
    folder = job_dir(out, job)
    # An earlier run's row goes first: if this run fails, no stale success is resumed from it.
    for stale in (ROW_FILE, "form.npz"):  # nor a stale form drawn for a failed rerun
        try:
            (folder / stale).unlink()
        except FileNotFoundError:
            pass
    start = time.perf_counter()
    row = {"id": job["id"], **job["params"]}
    try:
        row.update(_run(job, folder))
        row["error"] = ""
    except Exception as e:  # a failed scene is a row, not a lost sweep
        row.update(status="failed", converged=False, error=f"{type(e).__name__}: {e}")
        if not hasattr(e, "pointer"):  # not a scene error: keep where it happened
            row["error"] += " | " + traceback.format_exc(limit=3).replace("\n", " ")
    row["wall_seconds"] = time.perf_counter() - start
    row["out"] = str(folder)
    row["worker_pid"] = os.getpid()
    if not row["error"]:
        tmp = folder / (ROW_FILE + ".tmp")
        with open(tmp, "w", encoding="utf-8") as f:
            json.dump({**row, "job": job}, f, indent=1)
        os.replace(tmp, folder / ROW_FILE)  # last, and atomic: the job is complete
    return row
