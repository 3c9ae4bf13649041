"""Fuzzes the Python package's entry points for a given time.

    python benches/tools/fuzz_python.py MINUTES [SEED]

Each case calls one entry point — ``loads``, ``from_dict``,
``Scene.with_values``, ``Scene.run``, ``sweep``, a generated function —
with hostile arguments: the shipped scenes with values replaced by
extreme numbers, NaN, infinities, huge integers, strings, bytes, lists,
dicts, objects that contain themselves or nest thousands deep; unknown or
malformed keys; limits of every type; arrays of every dtype and shape.

The property: every call returns, or raises one of the documented
exceptions (``pegdyn.SceneError``, ``pegdyn.RunError``, ``ValueError``,
``TypeError``, ``KeyError``, ``OverflowError``, ``RecursionError``). A
different exception is a finding; so is a crash of the interpreter (the
cases run in a child process, which a parent restarts) and a case that
runs longer than 120 s (a hang). Prints the findings with the case and
ends with the number of cases; exits 1 if anything was found. See
``docs/fuzzing.md``.
"""

import math
import os
import pathlib
import random
import subprocess
import sys
import tempfile
import time
import traceback
import warnings

HANG_S = 120
ROOT = pathlib.Path(__file__).resolve().parents[2]


def hostile_value(rng, depth=0):
    """One hostile Python value."""
    pick = rng.randrange(16)
    if pick == 0:
        return rng.choice([math.nan, math.inf, -math.inf, -0.0, 5e-324, 1.7e308])
    if pick == 1:
        return (-1) ** rng.randrange(2) * 10.0 ** rng.uniform(-300, 300)
    if pick == 2:
        return rng.choice([0, -1, 2**63, -(2**63) - 1, 2**64, 10**400, True, False])
    if pick == 3:
        return rng.choice(["", "nan", "1e999", "\x00", "é" * 50, "x" * 100_000, "[a]"])
    if pick == 4:
        return rng.choice([b"\xff\xfe", bytearray(3), None, object(), 1j, Ellipsis])
    if pick == 5 and depth < 3:
        return [hostile_value(rng, depth + 1) for _ in range(rng.randrange(4))]
    if pick == 6 and depth < 3:
        return {rng.choice(["a", "", "x.y", "kind", "\x00"]): hostile_value(rng, depth + 1)}
    if pick == 7:
        looped = [1.0]
        looped.append(looped)
        return looped
    if pick == 8:
        root = x = {}
        for _ in range(rng.choice([100, 3000, 30_000])):
            x["a"] = {}
            x = x["a"]
        return root
    if pick == 9:
        import numpy as np

        a = np.empty(2, dtype=object)
        a[0], a[1] = rng.choice([(1.0, math.nan), ([1, 2], [3]), ("a", None)])
        return a
    return rng.uniform(-10, 10)


def shipped(rng):
    paths = sorted((ROOT / "scenes").glob("*.toml"))
    path = rng.choice(paths)
    return path.stem, path.read_text()


def mutate_text(rng, text):
    """A scene text with some numbers replaced by hostile literals."""
    import re

    literals = ["nan", "inf", "-inf", "1e308", "-1e-308", "0", "-0.0", "9223372036854775808", '"x"', "[]", "{}"]

    def repl(m):
        return rng.choice(literals) if rng.random() < 0.15 else m.group(0)

    return re.sub(r"(?<==\s)-?[0-9][0-9eE.+_-]*", repl, text)


def flatten(d, prefix=""):
    for k, v in d.items():
        if isinstance(v, dict):
            yield from flatten(v, f"{prefix}{k}.")
        else:
            yield f"{prefix}{k}", v


def case(rng, tmp):
    """One case: returns (description, thunk)."""
    import numpy as np
    import pegdyn

    limits_choices = [None, {"max_runs": 3}, {"max_runs": -1}, {"max_steps": "x"}, {"nope": 1}, [1], "max_runs=1", {"max_memory_mb": 1e300}]
    pick = rng.randrange(7)
    name, text = shipped(rng)
    if pick == 0:
        t = mutate_text(rng, text)
        return f"loads(mutated {name})", lambda: pegdyn.loads(t, name, limits=rng.choice(limits_choices))
    if pick == 1:
        import tomllib

        d = tomllib.loads(text)
        keys = list(flatten(d))
        for _ in range(rng.randrange(1, 4)):
            key, _ = rng.choice(keys)
            table, _, field = key.rpartition(".")
            target = d
            for part in table.split(".") if table else []:
                target = target[part]
            target[field] = hostile_value(rng)
        return f"from_dict({name} with hostile values)", lambda: pegdyn.from_dict(d, name, limits=rng.choice(limits_choices))
    if pick == 2:
        import tomllib

        keys = [k for k, _ in flatten(tomllib.loads(text))]
        values = {rng.choice(keys + ["x.y", "", ".", "a..b", "kind"]): hostile_value(rng) for _ in range(rng.randrange(1, 3))}

        def thunk():
            return pegdyn.loads(text, name).with_values(values)

        return f"{name}.with_values({list(values)})", thunk
    if pick == 3:
        # A short run of a scene with one value changed, in memory or to a directory.
        import tomllib

        keys = [k for k, v in flatten(tomllib.loads(text)) if isinstance(v, float)]
        key = rng.choice(keys) if keys else "x"
        value = rng.choice([0.5, 2.0, 1e-3, 1e3])
        small = {"max_steps": 5000, "max_runs": 40, "max_output_samples": 5000}

        def thunk():
            scene = pegdyn.loads(text, name, limits=small)
            base = dict(flatten(tomllib.loads(text)))
            scene = scene.with_values({key: base.get(key, 1.0) * value})
            out = tmp / f"run{rng.randrange(3)}" if rng.random() < 0.3 else None
            return scene.run(out)

        return f"run({name}, {key} scaled by {value})", thunk
    if pick == 4:
        grid_key = rng.choice(["pendulum.length", "pendulum.theta0_deg", "pendulum.mass", "pendulum.nope", "", "integrator.t_end"])
        values = [rng.choice([0.5, 1.0, hostile_value(rng)]) for _ in range(rng.randrange(0, 4))]

        def thunk():
            scene = pegdyn.loads((ROOT / "scenes/pendulum.toml").read_text(), "pendulum")
            return pegdyn.sweep(scene, {grid_key: values}, threads=rng.choice([None, 1, 0, -1, 2**70]), limits=rng.choice(limits_choices))

        return f"sweep(pendulum, {grid_key}: {[type(v).__name__ for v in values]})", thunk
    # A generated function with arrays of any dtype and shape.
    fs = pegdyn.functions()
    f = rng.choice(fs)
    dtype = rng.choice([np.float64, np.float32, np.int64, np.bool_, np.complex128, object, np.uint8])
    n_inputs = len(f.inputs) + rng.choice([0, 0, 0, -1, 1])

    def arg(size):
        shape = rng.choice([(size,), (size, 3), (3, size), (), (0, size), (size, 1, 2)])
        if dtype is object:
            a = np.empty(max(size, 1), dtype=object)
            for i in range(a.size):
                a[i] = hostile_value(rng)
            return a
        return (np.random.default_rng(rng.randrange(2**32)).standard_normal(shape) * 10.0 ** rng.uniform(-5, 5)).astype(dtype)

    args = [arg(rng.choice([1, 2, 5])) for _ in range(max(n_inputs, 0))]
    errors = rng.choice(["warn", "raise", "propagate", "ignore", 3])
    return f"{f.module}::{f.name}({[(a.dtype, a.shape) for a in args]}, errors={errors!r})", lambda: f(*args, errors=errors)


def child(seed, minutes, log):
    import pegdyn

    allowed = (pegdyn.SceneError, pegdyn.RunError, ValueError, TypeError, KeyError, OverflowError, RecursionError)
    rng = random.Random(seed)
    warnings.simplefilter("ignore")
    deadline = time.monotonic() + minutes * 60
    n = findings = 0
    with tempfile.TemporaryDirectory() as d:
        tmp = pathlib.Path(d)
        while time.monotonic() < deadline:
            what, thunk = case(rng, tmp)
            with open(log, "w") as f:
                f.write(f"{n} {what}\n")
            try:
                thunk()
            except allowed:
                pass
            except Exception:  # noqa: BLE001 — anything else is a finding
                findings += 1
                print(f"FINDING: {what}\n{traceback.format_exc()}", flush=True)
            n += 1
    print(f"CASES {n} FINDINGS {findings}", flush=True)


def parent(minutes, seed):
    deadline = time.monotonic() + minutes * 60
    log = tempfile.NamedTemporaryFile(delete=False, suffix=".case").name
    total = findings = 0
    while (left := deadline - time.monotonic()) > 1:
        p = subprocess.Popen([sys.executable, __file__, "--child", str(seed), str(left / 60), log], stdout=subprocess.PIPE, text=True)
        lines = []
        while p.poll() is None:
            time.sleep(1)
            if time.time() - os.path.getmtime(log) > HANG_S and os.path.getsize(log) > 0:
                p.kill()
                print(f"HANG: {open(log).read()}")
                findings += 1
        lines = p.stdout.read().splitlines()
        for line in lines:
            if line.startswith("CASES"):
                _, n, _, f = line.split()
                total += int(n)
                findings += int(f)
            else:
                print(line)
        if p.returncode != 0:
            findings += 1
            last = open(log).read().strip()
            total += int(last.split()[0]) + 1 if last else 0
            print(f"CRASH (exit {p.returncode}): {last}")
        seed += 1
    os.unlink(log)
    print(f"target python: {total} cases in {minutes:.1f} min, {findings} findings")
    return 1 if findings else 0


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        child(int(sys.argv[2]), float(sys.argv[3]), sys.argv[4])
    else:
        minutes = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0
        seed = int(sys.argv[2]) if len(sys.argv) > 2 else 20261126
        sys.exit(parent(minutes, seed))
