"""Sweeps: many scenes run on a Dask cluster, one table of results (docs/sweeps.md).

    import membra
    table = membra.sweep("examples/python/ellipse_axes.sweep.json", out="out/axes")
    table = membra.sweep(spec, out="out/axes", scheduler="tcp://head-node:8786")

Dask distributed does the scheduling: a LocalCluster of worker processes by default, or any
running `dask scheduler` (with workers started by `dask worker`, dask-jobqueue's Slurm or PBS,
Kubernetes, ...). Every worker must be able to `import membra` and to read the scene files and
write to `out` (a shared file system on a cluster).
"""

import json
import os
import sys
import time
import uuid
from pathlib import Path

from .sweep_job import finished_row, run_job
from .sweep_spec import expand, load_sweep, short_labels

# The columns of the results table, after the varied parameters.
COLUMNS = ["status", "converged", "stable", "height", "global_height", "total_K",
           "total_K_global", "classification", "quadric", "quadric_k1", "quadric_k2",
           "self_intersection", "design_error", "wall_seconds", "error", "out"]


def _client(scheduler, workers):
    """A Dask client: on `scheduler` ("tcp://HOST:8786") or a LocalCluster of `workers`
    single-threaded worker processes. Returns (client, cluster or None)."""
    from distributed import Client, LocalCluster

    if scheduler:
        return Client(scheduler), None
    # Worker processes import membra from where this process found it.
    package_root = str(Path(__file__).resolve().parent.parent)
    paths = os.environ.get("PYTHONPATH", "").split(os.pathsep)
    if package_root not in paths:
        os.environ["PYTHONPATH"] = os.pathsep.join([package_root] + [p for p in paths if p])
    cluster = LocalCluster(n_workers=workers or 2, threads_per_worker=1, processes=True,
                           dashboard_address=":0")  # any free port: never in the way
    return Client(cluster), cluster


def _submit(client, jobs, out, name):
    """Runs the jobs on the cluster; yields their rows in completion order. A job whose
    workers keep dying (Dask's KilledWorker after its allowed failures) is a row with that
    error."""
    from distributed import as_completed

    token = uuid.uuid4().hex[:8]  # keys unique to this run of the sweep
    futures = client.map(run_job, jobs, out=str(out),
                         key=[f"membra-{name}-{j['id']}-{token}" for j in jobs])
    by_key = {f.key: j for f, j in zip(futures, jobs)}
    for future in as_completed(futures):
        job = by_key[future.key]
        try:
            row = future.result()
        except Exception as e:  # the worker died with it, again and again
            row = {"id": job["id"], **job["params"], "status": "failed", "converged": False,
                   "error": f"{type(e).__name__}: {e}"}
        yield row


def _progress(done, total, row, quiet):
    if quiet:
        return
    state = row.get("status") or "?"
    print(f"membra sweep: {done}/{total}  {row['id']}  {state}"
          + (f"  {row['error'][:120]}" if row.get("error") else ""), file=sys.stderr, flush=True)


def sweep(spec, out, scheduler=None, workers=None, client=None, resume=True, contact_sheet=True,
          quiet=False):
    """Runs a sweep and returns its results as a pandas DataFrame, one row per job in the
    sweep's order (parameters, converged, height (mm), total_K (rad), classification,
    design_error (% of the target's diameter), wall_seconds, out, error, ...).

    spec: a sweep file path or dict (membra.sweep_spec).
    out: the folder of the results: scenes/NNNN/ per job, results.csv, report.html (a sortable
        table with a thumbnail per scene), contact_sheet.png.
    scheduler: "tcp://HOST:8786" of a running Dask scheduler; default a LocalCluster of
        `workers` processes (default 2). client: an existing distributed.Client instead.
    resume: take the rows of jobs finished by an earlier run (their scenes/NNNN/row.json)
        instead of running them again; failed jobs are always run again.
    A job that fails is a row with its error, never a lost sweep.
    """
    import pandas as pd

    spec = load_sweep(spec)
    jobs = expand(spec)
    # The varied parameters' columns under short names (the sweep file's "labels", else the
    # paths' last segments), checked before anything runs; parameters.json maps them back.
    labels = short_labels(_params(jobs), spec.get("labels"), reserved=["id", *COLUMNS])
    out = Path(out).resolve()
    (out / "scenes").mkdir(parents=True, exist_ok=True)
    done = {}
    if resume:
        for job in jobs:
            row = finished_row(out, job)
            if row is not None:
                row.pop("job", None)
                done[job["id"]] = row
    todo = [j for j in jobs if j["id"] not in done]
    if not quiet:
        print(f"membra sweep: {spec['name']}: {len(jobs)} scenes, {len(done)} already done",
              file=sys.stderr, flush=True)
    start = time.perf_counter()
    if todo:
        own, cluster = (client, None) if client is not None else _client(scheduler, workers)
        try:
            for row in _submit(own, todo, out, spec["name"]):
                done[row["id"]] = row
                _progress(len(done), len(jobs), row, quiet)
        finally:
            if client is None:
                own.close()
                if cluster is not None:
                    cluster.close()
    table = _table(jobs, done, pd).rename(columns=labels)
    table.to_csv(out / "results.csv", index=False)
    (out / "parameters.json").write_text(
        json.dumps({name: path for path, name in labels.items()}, indent=1) + "\n", encoding="utf-8")
    from .sweep_page import write_sweep_page

    params = list(labels.values())
    write_sweep_page(table, params, out, spec["name"])
    if contact_sheet:
        from .contact_sheet import write_contact_sheet, write_parameter_plot

        write_contact_sheet(table, params, out / "contact_sheet.png", spec["name"])
        write_parameter_plot(table, params, out / "parameters.png", spec["name"])
    if not quiet:
        failed = int((table["error"].fillna("") != "").sum())
        print(f"membra sweep: {len(jobs)} scenes in {time.perf_counter() - start:.1f} s, "
              f"{failed} failed; results in {out}/results.csv", file=sys.stderr, flush=True)
    return table


def _params(jobs):
    params = []
    for job in jobs:
        for k in job["params"]:
            if k not in params:
                params.append(k)
    return params


def _table(jobs, rows, pd):
    params = _params(jobs)
    records = [rows[j["id"]] for j in jobs]
    table = pd.DataFrame.from_records(records)
    for c in COLUMNS:
        if c not in table:
            table[c] = None
    table["error"] = table["error"].fillna("")
    return table[["id"] + params + COLUMNS]
