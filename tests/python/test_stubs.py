"""membra's type stubs (python/membra/__init__.pyi) against the module: every public name has a
stub, and each stubbed function and method takes the parameters the module's does."""

import ast
import inspect
from pathlib import Path

import membra

STUB = Path(membra.__file__).with_name("__init__.pyi")


def stub_tree():
    return ast.parse(STUB.read_text(encoding="utf-8"))


def params(fn):
    return [p.arg for p in fn.args.posonlyargs + fn.args.args + fn.args.kwonlyargs]


def runtime_params(obj):
    return [n for n, p in inspect.signature(obj).parameters.items()
            if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]


def test_every_public_name_has_a_stub():
    names = set()
    for node in stub_tree().body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
    assert set(membra.__all__) <= names, set(membra.__all__) - names


def test_stubbed_signatures_match_the_module():
    from membra.sweeps import sweep as real_sweep

    checked = 0
    for node in stub_tree().body:
        if isinstance(node, ast.FunctionDef):
            real = real_sweep if node.name == "sweep" else getattr(membra, node.name)
            assert params(node) == runtime_params(real), node.name
            checked += 1
        elif isinstance(node, ast.ClassDef) and hasattr(membra, node.name):
            cls = getattr(membra, node.name)
            for fn in node.body:
                if not isinstance(fn, ast.FunctionDef):
                    continue
                assert hasattr(cls, fn.name), f"{node.name}.{fn.name}"
                real = inspect.getattr_static(cls, fn.name)
                if isinstance(real, property) or fn.args.kwarg:
                    continue  # properties; the step methods take the step's fields
                assert params(fn)[1:] == runtime_params(real)[1:], f"{node.name}.{fn.name}"
                checked += 1
    assert checked >= 15


def test_the_package_is_marked_typed():
    assert STUB.with_name("py.typed").exists()
