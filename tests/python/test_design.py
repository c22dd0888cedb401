"""membra.design on a tiny design: the same result as `membra design target`."""

import json
import subprocess

import membra


def tiny_design(root):
    spec = json.loads((root / "examples" / "inverse_cap.json").read_text())
    spec["sheet"]["resolution"] = 11
    spec["design"] = {**spec.get("design", {}), "evaluations": 3}
    return spec


def test_design_matches_the_cli(root, cli, cli_env, tmp_path):
    spec = tiny_design(root)
    file = tmp_path / "cap.json"
    file.write_text(json.dumps(spec))
    subprocess.run([cli, "design", "target", str(file), "--quiet", "--out", str(tmp_path / "cli")],
                   check=True, env=cli_env)
    seen = []
    d = membra.design(file, out=tmp_path / "py", progress=seen.append)
    assert len(seen) == len(d.report["design"]["iterations"]) <= 3
    cli_report = json.loads((tmp_path / "cli" / "report.json").read_text())
    assert d.rms_error == cli_report["design"]["rms_error"]
    assert d.verdict == cli_report["design"]["verdict"] in (
        "meets_goal", "closer_than_flat", "no_closer_than_flat")
    assert d.verdict_note == cli_report["design"]["verdict_note"] != ""
    assert (tmp_path / "py" / "final.obj").read_bytes() == (tmp_path / "cli" / "final.obj").read_bytes()
    # The designed scene reproduces the form through membra.run.
    again = membra.run(membra.Scene(d.scene, base_dir=tmp_path))
    assert (again.positions == d.positions).all()


def test_an_adjoint_design_keeps_its_calibration_for_the_next(root, tmp_path, monkeypatch):
    monkeypatch.setenv("MEMBRA_CACHE_DIR", str(tmp_path / "cache"))
    spec = tiny_design(root)
    spec["design"].update({"method": "adjoint", "density_cell": 25, "evaluations": 4,
                           "stencil_trials": 1, "piece_evaluations": 0})  # the cache, not the design
    spec["resin"]["layout"] = "squares"  # the adjoint lays out squares, not the example's darts
    del spec["resin"]["darts"]
    first = membra.design(spec)
    assert first.report["design"]["calibration"]["cached"] is False
    assert len(list((tmp_path / "cache").glob("calibration-*.json"))) == 1
    second = membra.design(spec)
    assert second.report["design"]["calibration"]["cached"] is True
    assert second.report["design"]["calibration"]["density"] == \
        first.report["design"]["calibration"]["density"]
    assert membra.design(spec, cache=False).report["design"]["calibration"]["cached"] is False


def test_coats_on_both_faces_and_a_searched_stretch(root):
    wave = json.loads((root / "examples" / "inverse_wave.json").read_text())
    wave["sheet"]["resolution"] = 9
    d = membra.design(wave)
    assert d.pieces_bottom == 32 and d.prestretch == (1.8, 1.0)
    sides = [s["resin_side"] for s in d.scene["protocol"] if s["step"] == "impregnate"]
    assert sides == ["top", "bottom"]
    # From a stretch too small for the cylinder's radius, the search raises it.
    cylinder = json.loads((root / "examples" / "inverse_cylinder.json").read_text())
    cylinder["sheet"]["resolution"] = 11
    cylinder["frame"]["lambda"] = [1.3, 1.0]
    cylinder["design"] = {**cylinder["design"], "evaluations": 12, "search_stretch": True}
    c = membra.design(cylinder)
    assert c.prestretch[0] > 1.5 and c.prestretch[1] == 1.0 and c.pieces_bottom == 0
    stretch = [s["lambda"] for s in c.scene["protocol"] if s["step"] == "stretch"][0]
    assert tuple(stretch) == c.prestretch
