"""The sweep file fuzzed: a thousand seeded mutations of a valid sweep (keys dropped or added,
values of every JSON type, deep nesting, huge grids, broken bytes). Each is either loaded and
expanded or refused with membra.SceneError naming the file; any other exception is a bug.
(libFuzzer covers the C++ parsers, tests/fuzz; the sweep file is read in Python.)"""
import json
import random

import membra
from membra.sweep_spec import expand, load_sweep

BASE = {
    "name": "fuzz",
    "scene": "scene.json",
    "set": {"sheet.resolution": [9, 9], "simulation.solver": "newton"},
    "grid": {"protocol.1.pattern.ellipse.radii.0": [40, 50], "simulation.K": [0.5, 0.6]},
    "list": [{"simulation.G": 0}, {"simulation.G": 9.81}],
}
KEYS = ["name", "description", "scene", "design", "scenes", "set", "grid", "list", "bogus", ""]


def random_value(rng, depth=0):
    kind = rng.randrange(9 if depth < 3 else 6)
    if kind == 0:
        return None
    if kind == 1:
        return rng.choice([True, False])
    if kind == 2:
        return rng.choice([0, -1, 1, 2**63, -(2**70), 7])
    if kind == 3:
        return rng.choice([0.0, -1e308, 1e308, 1e-320, 3.5])
    if kind == 4:
        return rng.choice(["", "scene.json", "../../etc/passwd", "x" * 1000, "\u00e9\u2212", "a.b.c"])
    if kind == 5:
        return []
    if kind == 6:
        return [random_value(rng, depth + 1) for _ in range(rng.randrange(4))]
    if kind == 7:
        return {rng.choice(KEYS + ["a.b", "x"]): random_value(rng, depth + 1)
                for _ in range(rng.randrange(4))}
    return list(range(rng.randrange(1, 2000)))  # a long grid axis


def mutate(rng, spec):
    spec = json.loads(json.dumps(spec))
    for _ in range(rng.randrange(1, 4)):
        op = rng.randrange(5)
        target = spec
        if op == 4 and isinstance(spec.get("grid"), dict):
            target = spec["grid"]  # grow the grid: several long axes multiply
            target[f"k{rng.randrange(6)}"] = list(range(rng.randrange(1, 200)))
            continue
        key = rng.choice(KEYS)
        if op == 0:
            target.pop(key, None)
        elif op in (1, 2):
            target[key] = random_value(rng)
        else:
            inner = target.get(key)
            if isinstance(inner, dict) and inner:
                inner[rng.choice(list(inner))] = random_value(rng)
            elif isinstance(inner, list) and inner:
                inner[rng.randrange(len(inner))] = random_value(rng)
    return spec


def broken_bytes(rng, text):
    b = bytearray(text.encode())
    for _ in range(rng.randrange(1, 5)):
        if not b:
            break
        i = rng.randrange(len(b))
        op = rng.randrange(3)
        if op == 0:
            del b[i:]
        elif op == 1:
            b[i] = rng.randrange(256)
        else:
            b[i:i] = bytes([rng.randrange(256)])
    return bytes(b)


def test_mutated_sweeps_load_or_fail_with_scene_error(tmp_path):
    (tmp_path / "scene.json").write_text("{}")
    rng = random.Random(20261202)
    loaded = refused = 0
    for n in range(1200):
        spec = mutate(rng, BASE)
        file = tmp_path / "s.sweep.json"
        if n % 4 == 0:
            file.write_bytes(broken_bytes(rng, json.dumps(spec)))
            source = file
        else:
            source = spec if n % 2 else file
            if source is file:
                file.write_text(json.dumps(spec))
        try:
            jobs = expand(load_sweep(source, base_dir=tmp_path))
            assert len(jobs) <= 100_000
            loaded += 1
        except membra.SceneError as e:
            # A refusal names the file (or "sweep" for a dict) and says why.
            assert str(e).startswith(str(file) if source is file else "sweep"), str(e)
            assert e.detail, str(e)
            refused += 1
    assert loaded > 100 and refused > 100, (loaded, refused)
