"""membra.run against the CLI, the arrays' shapes and units, the step-by-step Membrane."""

import json
import subprocess
import threading
import time

import numpy as np
import pytest

import membra

TIMING_KEYS = {"wall_seconds", "seconds"}


def without_timings(value):
    """A report without its wall-clock times, the only values two runs may differ in."""
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k not in TIMING_KEYS}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def test_run_writes_what_the_cli_writes(root, cli, cli_env, tmp_path):
    scene = root / "examples" / "synclastic_ellipse.json"
    sets = ["sheet.resolution=[13,13]", "simulation.solver=newton"]
    args = [cli, "run", str(scene), "--quiet", "--out", str(tmp_path / "cli")]
    subprocess.run(args + [a for s in sets for a in ("--set", s)], check=True,
                   env=cli_env)
    result = membra.run(membra.Scene(scene, set=sets), out=tmp_path / "py")
    cli_files = sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert sorted(p.name for p in (tmp_path / "py").iterdir()) == cli_files
    for name in ("final.obj", "final.ply", "pattern.svg", "pattern.dxf"):
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    cli_report = json.loads((tmp_path / "cli" / "report.json").read_text())
    py_report = json.loads((tmp_path / "py" / "report.json").read_text())
    assert without_timings(py_report) == without_timings(cli_report)
    assert without_timings(result.report) == without_timings(cli_report)


def test_arrays_have_their_shapes_and_units(small_ellipse):
    r = membra.run(small_ellipse)
    n = r.report["particles"]
    assert r.positions.shape == (n, 3) and r.positions.dtype == np.float64
    assert r.paper_positions.shape == (n, 2)
    assert r.triangles.shape == (r.report["triangles"], 3)
    assert r.triangles.min() == 0 and r.triangles.max() == n - 1
    assert r.gaussian_curvature.shape == (n,) and r.stress.shape == (n,)
    # mm: the paper sheet is 200 mm square; the height is the report's (mm).
    assert r.paper_positions.min() == pytest.approx(0.0)
    assert r.paper_positions.max() == pytest.approx(200.0)
    z = r.positions[:, 2]
    assert np.ptp(z) == pytest.approx(r.report["shape"]["z_range"], rel=1e-9)
    # 1/m^2 and MPa: the extremes are the report's.
    assert r.gaussian_curvature.max() == pytest.approx(r.report["curvature"]["max_density"], rel=1e-9)
    assert r.gaussian_curvature.min() == pytest.approx(r.report["curvature"]["min_density"], rel=1e-9)
    assert 0 < r.stress.max() <= r.report["stress"]["max"] * (1 + 1e-9)
    assert r.converged and not r.diverged


def test_a_grid_too_coarse_for_the_pattern_warns(small_ellipse, root):
    # 13 x 13 nodes: the ellipse's 1.6 mm latex gaps are a fraction of a 16.7 mm spacing.
    with pytest.warns(membra.MembraWarning, match=r"sheet.resolution: the narrowest"):
        r = membra.run(small_ellipse)
    assert r.warnings == r.report["warnings"] and len(r.warnings) == 1
    # A sheet without a pattern has nothing to resolve.
    plain = membra.Scene(root / "examples" / "exp1_basic.json", set={"sheet.resolution": [9, 9]})
    assert membra.run(plain).warnings == []


def test_membrane_step_by_step_is_membra_run(small_ellipse):
    whole = membra.run(small_ellipse)
    m = membra.Membrane(small_ellipse)
    assert m.stretch(lambda_=[1.5, 1.0])
    assert np.ptp(m.positions[:, 0]) == pytest.approx(300.0)  # stretched 1.5x on the frame
    for entry in small_ellipse.data["protocol"][1:]:
        assert m.step(entry)
    assert [s["step"] for s in m.steps] == ["stretch", "impregnate", "release"]
    # A result is in the reading pose; the membrane goes on in the frame it was simulated in.
    pose = whole.report["pose"]
    R, t = np.array(pose["rotation"]), np.array(pose["translation"])
    assert np.allclose(m.positions @ R.T + t, whole.positions, atol=1e-9)
    assert np.array_equal(m.result().positions, whole.positions)
    assert without_timings(m.result().report) == without_timings(whole.report)


def test_a_membrane_writes_the_files_of_its_steps(small_ellipse, tmp_path):
    m = membra.Membrane(small_ellipse)
    m.run_protocol()
    m.result().write(tmp_path)
    written = {p.name for p in tmp_path.iterdir()}
    assert {"final.obj", "report.json", "pattern.svg", "pattern.png", "curvature.png"} <= written


def test_a_membrane_interrupted_half_way_refuses_further_steps(small_ellipse):
    import _thread

    m = membra.Membrane(small_ellipse.with_set({"sheet.resolution": [31, 31],
                                                "simulation.solver": "static"}))
    m.stretch(lambda_=[1.5, 1.0])
    m.step(small_ellipse.data["protocol"][1])
    timer = threading.Timer(0.5, _thread.interrupt_main)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        m.release(increments=10)
    timer.cancel()
    with pytest.raises(RuntimeError, match="interrupted half-way"):
        m.solve()


def test_the_solve_releases_the_gil(small_ellipse):
    scene = small_ellipse.with_set({"sheet.resolution": [21, 21]})
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.005)

    t = threading.Thread(target=tick)
    t.start()
    start = time.perf_counter()
    membra.run(scene)
    seconds = time.perf_counter() - start
    done.set()
    t.join()
    during = [x for x in ticks if start < x < start + seconds]
    # A thread that sleeps 5 ms between ticks ticks ~200 times a second unless the GIL is held.
    assert len(during) > 0.3 * seconds / 0.005, (len(during), seconds)


def test_ctrl_c_stops_a_run(small_ellipse):
    import _thread

    scene = small_ellipse.with_set({"sheet.resolution": [31, 31], "simulation.solver": "static"})
    timer = threading.Timer(0.5, _thread.interrupt_main)
    timer.start()
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        membra.run(scene)
    assert time.perf_counter() - start < 10.0
    timer.cancel()


def test_progress_is_reported(small_ellipse):
    seen = []
    membra.run(small_ellipse, progress=seen.append)
    assert seen and {"stage", "iteration", "residual_relative"} <= set(seen[0])
    # The whole run's share done grows, never goes back, and stays within [0, 1]; the release
    # (10 of its 12 weights: stretch 1, impregnate 1, release 10) is most of it.
    done = [p["run_done"] for p in seen]
    assert all(0.0 <= d <= 1.0 for d in done)
    assert done == sorted(done)
    assert max(done) >= 2 / 12 + 0.5 * 10 / 12
