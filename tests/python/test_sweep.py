"""Sweeps on Dask: a real scheduler and two workers on 127.0.0.1, a worker killed mid-sweep,
resume, the same results whatever the number of workers, failed scenes as rows."""

import json
import os
import shutil
import signal
import socket
import subprocess
import time
from pathlib import Path

import pandas as pd
import pytest

import membra
from membra.sweep_spec import expand, load_sweep

PHYSICS = ["status", "converged", "height", "global_height", "total_K", "total_K_global",
           "classification", "self_intersection"]


def four_scenes(root):
    """4 small releases: the ellipse's two radii over 2 x 2 values (each tiny run costs about
    a second of output work, so the sweep tests keep to a few)."""
    return {
        "name": "four",
        "scene": str(root / "examples" / "synclastic_ellipse.json"),
        "set": {"sheet.resolution": [11, 11], "simulation.solver": "newton",
                "output.image_size": [320, 240]},
        "grid": {"protocol.1.pattern.union.0.ellipse.radii.1": [50, 80],
                 "protocol.1.pattern.union.0.ellipse.radii.0": [100, 120]},
    }


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Cluster:
    """`dask scheduler` and `dask worker` processes on loopback, stopped at the end."""

    def __init__(self, workers):
        self.port = free_port()
        self.address = f"tcp://127.0.0.1:{self.port}"
        env = {**os.environ, "OMP_NUM_THREADS": "1"}
        # The `dask` command as a cluster's operator runs it (Debian's python3-dask).
        self.dask = [shutil.which("dask") or "dask"]
        self.scheduler = subprocess.Popen(
            self.dask + ["scheduler", "--host", "127.0.0.1", "--port", str(self.port),
                         "--no-dashboard", "--dashboard-address", ":0"],
            env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.workers = [self.start_worker(env) for _ in range(workers)]
        self.client = None
        try:
            from distributed import Client

            self.client = Client(self.address, timeout=30)
            self.client.wait_for_workers(workers, timeout=60)
        except Exception:
            self.close()  # no process left behind
            raise

    def start_worker(self, env):
        return subprocess.Popen(
            self.dask + ["worker", self.address, "--nthreads", "1", "--no-dashboard",
                         "--death-timeout", "120"], env=env, stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL, start_new_session=True)

    def close(self):
        if self.client is not None:
            self.client.close()
        for worker in self.workers:  # each worker is a nanny and its process: a group
            if worker.poll() is None:
                os.killpg(worker.pid, signal.SIGKILL)
            worker.wait(timeout=30)
        self.scheduler.kill()
        self.scheduler.wait(timeout=30)


@pytest.fixture
def cluster():
    c = Cluster(workers=2)
    yield c
    c.close()


def physics(table):
    return table.sort_values("id").reset_index(drop=True)[PHYSICS]


def test_the_sweep_file_expands_in_a_fixed_order(root):
    jobs = expand(load_sweep(four_scenes(root)))
    assert [j["id"] for j in jobs] == [f"{i:04d}" for i in range(4)]
    assert jobs[0]["params"] == {"protocol.1.pattern.union.0.ellipse.radii.1": 50,
                                 "protocol.1.pattern.union.0.ellipse.radii.0": 100}
    assert jobs[1]["params"]["protocol.1.pattern.union.0.ellipse.radii.0"] == 120
    assert 'sheet.resolution=[11, 11]' in jobs[0]["sets"]


def test_a_bad_sweep_file_names_its_field(tmp_path):
    with pytest.raises(membra.SceneError, match="/grid/x"):
        load_sweep({"scene": "a.json", "grid": {"x": []}})
    with pytest.raises(membra.SceneError, match="unknown key"):
        load_sweep({"scene": "a.json", "grids": {}})
    bad = tmp_path / "bad.sweep.json"
    bad.write_text("{")
    with pytest.raises(membra.SceneError, match="bad.sweep.json.*malformed JSON"):
        load_sweep(bad)


def test_a_sweep_on_a_real_scheduler_survives_a_killed_worker(root, tmp_path, cluster):
    spec = four_scenes(root)
    killed = []

    def kill_one_worker_after_first_row():
        # Runs in the sweep's thread between rows: the first worker dies with its scene.
        if not killed:
            worker = cluster.workers[0]
            os.killpg(worker.pid, signal.SIGKILL)
            killed.append(worker.pid)

    from membra import sweeps

    original = sweeps._progress

    def progress(done, total, row, quiet):
        original(done, total, row, quiet)
        kill_one_worker_after_first_row()

    sweeps._progress = progress
    try:
        table = membra.sweep(spec, out=tmp_path / "a", client=cluster.client)
    finally:
        sweeps._progress = original
    assert killed
    assert len(table) == 4 and (table["error"] == "").all(), table["error"].tolist()
    assert (Path(tmp_path / "a" / "results.csv")).is_file()
    assert (Path(tmp_path / "a" / "contact_sheet.png")).stat().st_size > 10_000
    assert (Path(tmp_path / "a" / "parameters.png")).stat().st_size > 10_000
    # The varied parameters under short names, mapped back to their paths.
    assert {"radii.0", "radii.1"} <= set(table.columns)
    assert json.loads((tmp_path / "a" / "parameters.json").read_text())["radii.0"] == \
        "protocol.1.pattern.union.0.ellipse.radii.0"
    assert sorted(table["radii.1"].tolist()) == [50, 50, 80, 80]
    # The sweep's page: a sortable table, one row per scene with a thumbnail linking to the
    # scene's own report.html.
    page = (tmp_path / "a" / "report.html").read_text()
    assert page.count("<tr>") == 4 + 1 and "th.addEventListener('click'" in page
    for i in range(4):
        assert f'<a href="scenes/{i:04d}/report.html"><img src="scenes/{i:04d}/curvature.png"' in page
        assert (tmp_path / "a" / "scenes" / f"{i:04d}" / "report.html").is_file()
    # The same physics on one local worker, from scratch.
    alone = membra.sweep(spec, out=tmp_path / "b", workers=1)
    pd.testing.assert_frame_equal(physics(table), physics(alone))
    for i in range(4):
        a = (tmp_path / "a" / "scenes" / f"{i:04d}" / "final.obj").read_bytes()
        b = (tmp_path / "b" / "scenes" / f"{i:04d}" / "final.obj").read_bytes()
        assert a == b, i


def test_a_failed_scene_is_a_row_and_a_resumed_sweep_skips_finished_ones(root, tmp_path):
    spec = four_scenes(root)
    spec["grid"] = {"protocol.1.pattern.union.0.ellipse.radii.1": [50, 65, 80]}
    spec["list"] = [{"simulation.solver": "newton"}, {"simulation.solver": "nonsense"}]
    out = tmp_path / "s"
    first = membra.sweep(spec, out=out, workers=2, contact_sheet=False)
    failed = first[first["error"] != ""]
    assert len(failed) == 3 and failed["error"].str.contains("/simulation/solver").all()
    assert (first[first["error"] == ""]["converged"]).all()
    # Interrupt a sweep: remove one finished row, as if the run had stopped before it.
    (out / "scenes" / "0002" / "row.json").unlink()
    stamps = {i: (out / "scenes" / f"{i:04d}" / "row.json").stat().st_mtime_ns for i in (0, 1)}
    again = membra.sweep(spec, out=out, workers=1, contact_sheet=False)
    for i, stamp in stamps.items():  # finished rows were not run again
        assert (out / "scenes" / f"{i:04d}" / "row.json").stat().st_mtime_ns == stamp
    assert (out / "scenes" / "0002" / "row.json").is_file()
    pd.testing.assert_frame_equal(physics(first), physics(again))


def test_the_cli_runs_a_sweep_file(root, cli, tmp_path):
    spec = four_scenes(root)
    spec["grid"] = {"protocol.1.pattern.union.0.ellipse.radii.1": [50, 80]}
    file = tmp_path / "two.sweep.json"
    file.write_text(json.dumps(spec))
    run = subprocess.run([cli, "sweep", str(file), "--out", str(tmp_path / "o"), "--workers", "1"],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    table = pd.read_csv(tmp_path / "o" / "results.csv")
    assert len(table) == 2 and table["converged"].all()
    bad = subprocess.run([cli, "sweep", str(tmp_path / "missing.json")], capture_output=True,
                         text=True, timeout=120)
    assert bad.returncode == 2 and "missing.json" in bad.stderr


def test_a_design_sweep_reports_each_design_error(root, tmp_path):
    spec = {"name": "caps", "design": str(root / "examples" / "inverse_cap.json"),
            "set": {"sheet.resolution": 9, "design.evaluations": 2},
            "grid": {"target.cap.height": [16, 24]}}
    table = membra.sweep(spec, out=tmp_path, workers=1, contact_sheet=False)
    assert (table["error"] == "").all(), table["error"].tolist()
    for _, row in table.iterrows():
        report = json.loads((Path(row["out"]) / "report.json").read_text())
        assert row["design_error"] == report["design"]["rms_error"] > 0


def test_columns_get_short_names_or_the_sweep_files_labels():
    from membra.sweep_spec import load_sweep, short_labels

    paths = ["protocol.1.pattern.union.0.ellipse.radii.0", "protocol.1.pattern.union.0.ellipse.radii.1",
             "simulation.solver"]
    assert short_labels(paths) == {paths[0]: "radii.0", paths[1]: "radii.1", paths[2]: "solver"}
    assert short_labels(paths, {paths[0]: "width"})[paths[0]] == "width"
    with pytest.raises(membra.SceneError, match="/labels/"):
        load_sweep({"name": "s", "scene": "x.json", "labels": {paths[0]: ""}})
    with pytest.raises(membra.SceneError, match="names no varied parameter"):
        short_labels(paths, {"sheet.size": "size"})
    with pytest.raises(membra.SceneError, match="is taken"):
        short_labels(paths, {paths[0]: "height"}, reserved=["height"])
    # A name that clashes with a result column is lengthened: target.cap.height -> cap.height.
    assert short_labels(["target.cap.height"], reserved=["height"]) == {"target.cap.height": "cap.height"}
