"""Bad input raises membra.SceneError naming the field; unwritable outputs raise OutputError."""

import os
import subprocess
import sys

import pytest

import membra


def test_a_bad_field_names_its_json_pointer(root):
    with pytest.raises(membra.SceneError) as e:
        membra.Scene(root / "examples" / "exp1_basic.json", set={"sheet.size": [-200, 200]})
    assert e.value.pointer.endswith("/sheet/size/0")
    assert "exp1_basic.json" in str(e.value)
    assert "sheet.size=" in str(e.value)  # the override at fault is named
    assert isinstance(e.value, ValueError)


def test_a_dict_scene_is_validated_like_a_file():
    with pytest.raises(membra.SceneError) as e:
        membra.Scene({"name": "x", "sheet": {"size": [100, 100], "resolution": [1, 9]}})
    assert e.value.pointer == "/sheet/resolution/0"
    with pytest.raises(membra.SceneError) as e:
        membra.Scene({"name": "x", "shet": {}})
    assert "shet" in str(e.value)


def test_malformed_json_text_and_missing_files():
    with pytest.raises(membra.SceneError, match="malformed JSON"):
        membra.Scene('{"name": "x",')
    with pytest.raises(membra.SceneError, match="no_such_scene.json"):
        membra.Scene("no_such_scene.json")
    with pytest.raises(membra.SceneError, match="no_such_design.json"):
        membra.design("no_such_design.json")


def test_a_bad_step_names_its_place_in_the_protocol(small_ellipse):
    m = membra.Membrane(small_ellipse)
    m.stretch(lambda_=[1.5, 1.0])
    with pytest.raises(membra.SceneError) as e:
        m.release(increments=-3)
    assert e.value.pointer == "/protocol/1/increments"
    assert [s["step"] for s in m.steps] == ["stretch"]  # the bad step was not applied


def test_validate_counts_what_a_run_builds(small_ellipse):
    counts = membra.validate(small_ellipse)
    assert counts["particles"] == 13 * 13 and counts["springs"] > 0


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into read-only folders")
def test_an_unwritable_folder_raises_output_error(small_ellipse, tmp_path):
    result = membra.run(small_ellipse)
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    with pytest.raises(membra.OutputError):
        result.write(locked / "out")


def test_a_file_in_the_way_raises_output_error(small_ellipse, tmp_path):
    result = membra.run(small_ellipse)
    (tmp_path / "file").write_text("not a folder")
    with pytest.raises(membra.OutputError):
        result.write(tmp_path / "file" / "out")
    assert (tmp_path / "file").read_text() == "not a folder"


def test_the_version_is_the_clis(cli):
    out = subprocess.run([cli, "--version"], capture_output=True, text=True, check=True).stdout
    assert out.strip() == f"membra {membra.__version__}"


def test_an_interpreter_without_numpy_fails_at_import_naming_the_right_one():
    # numpy hidden from this interpreter: the import fails at once, not at the first array.
    code = "import sys; sys.modules['numpy'] = None; import membra"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       env=dict(os.environ))
    assert r.returncode != 0
    assert "membra needs numpy" in r.stderr
    assert "run it with " in r.stderr


def test_another_python_version_fails_at_import_naming_the_right_one():
    # As if this were a Python 3.99: its extension suffix matches no native module here.
    code = ("import importlib.machinery as m; "
            "m.EXTENSION_SUFFIXES[:] = ['.cpython-399-x86_64-linux-gnu.so', '.abi3.so', '.so']; "
            "import membra")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       env=dict(os.environ))
    assert r.returncode != 0
    assert "was built for" in r.stderr and "run it with " in r.stderr
