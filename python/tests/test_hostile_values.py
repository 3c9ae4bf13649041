"""Python values that used to crash or mislead: a dict or list that contains
itself or nests ~20,000 deep (every entry point that walks Python values
raises, never kills the interpreter), NaN/inf inputs and masked arrays in
the generated functions, and a misspelled sweep key.

The nesting cases run in a child interpreter each, so that a crash fails
the case (with its signal) instead of ending the test session."""

import subprocess
import sys
import textwrap
import warnings

import numpy as np
import pytest

import pegdyn

SETUP = """
import sys
import numpy as np
import pegdyn
base = {"kind": "pendulum",
        "pendulum": {"length": 1.0, "mass": 1.0, "theta0_deg": 30.0},
        "integrator": {"method": "dopri5", "t_end": 0.1}}
scene = pegdyn.from_dict(base)
def deep_list(n):
    root = x = []
    for _ in range(n):
        x.append([])
        x = x[0]
    return root
def deep_dict(n):
    root = x = {}
    for _ in range(n):
        x["a"] = {}
        x = x["a"]
    return root
looped_list = [1.0]
looped_list.append(looped_list)
looped_dict = {"x": 1.0}
looped_dict["self"] = looped_dict
"""

# (what, the call, the words the error must contain)
CASES = [
    ("from_dict: a dict holding itself", "d = dict(base); d['pendulum'] = dict(base['pendulum'], extra=looped_dict); pegdyn.from_dict(d)", "contains itself"),
    ("from_dict: the root holding itself", "d = dict(base); d['me'] = d; pegdyn.from_dict(d)", "contains itself"),
    ("from_dict: a list holding itself", "d = dict(base); d['pendulum'] = dict(base['pendulum'], mass=looped_list); pegdyn.from_dict(d)", "contains itself"),
    ("from_dict: 20,000 nested dicts", "d = dict(base); d['deep'] = deep_dict(20_000); pegdyn.from_dict(d)", "levels deep"),
    ("from_dict: 20,000 nested lists", "d = dict(base); d['pendulum'] = dict(base['pendulum'], mass=deep_list(20_000)); pegdyn.from_dict(d)", "levels deep"),
    ("with_values: a list holding itself", "scene.with_values({'pendulum.mass': looped_list})", "contains itself"),
    ("with_values: 20,000 nested lists", "scene.with_values({'pendulum.mass': deep_list(20_000)})", "levels deep"),
    ("with_values: 20,000 nested dicts", "scene.with_values({'pendulum.mass': deep_dict(20_000)})", "levels deep"),
    ("sweep grid: a dict holding itself", "pegdyn.sweep(scene, {'pendulum.mass': [1.0, looped_dict]})", "contains itself"),
    ("sweep points: 20,000 nested lists", "pegdyn.sweep(scene, points=[{'pendulum.mass': 1.0}, {'pendulum.mass': deep_list(20_000)}])", "levels deep"),
    ("sweep: 20,000 nested dicts", "pegdyn.sweep(scene, {'pendulum.mass': [deep_dict(20_000)]})", "levels deep"),
    ("function: a list holding itself", "pegdyn.generated.pendulum.energy([0.1, looped_list], [1.0, 1.0, 9.81])", "sequence"),
    ("function: 20,000 nested lists", "pegdyn.generated.pendulum.energy(deep_list(20_000), [1.0, 1.0, 9.81])", "dim"),
]


@pytest.mark.parametrize("what,call,words", CASES, ids=[c[0] for c in CASES])
def test_self_containing_and_deep_values_raise_not_crash(what, call, words):
    code = SETUP + textwrap.dedent(
        f"""
        try:
            {call}
        except (ValueError, RecursionError) as e:
            print(type(e).__name__, e)
            sys.exit(0)
        print("no error")
        sys.exit(3)
        """
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, f"{what}: exit {done.returncode}\n{done.stdout}\n{done.stderr[-2000:]}"
    assert words in done.stdout, done.stdout
    # A bounded message, naming a path.
    assert len(done.stdout) < 400, done.stdout


def test_the_depth_limit_leaves_ordinary_nesting_alone():
    # A value nested a few levels (an array of arrays) still reaches the
    # scene's own validation, which names the field.
    base = {
        "kind": "pendulum",
        "pendulum": {"length": 1.0, "mass": [[[[1.0]]]], "theta0_deg": 30.0},
        "integrator": {"method": "dopri5", "t_end": 0.1},
    }
    with pytest.raises(pegdyn.SceneError) as e:
        pegdyn.from_dict(base)
    assert e.value.field == "pendulum.mass"


# ---------------------------------------------------------------- non-finite

FUNCTIONS = [
    pegdyn.generated.pendulum.energy,
    pegdyn.function("double_pendulum", "dynamics"),
    pegdyn.functions()[-1],
]


def points(f, n, rng):
    return [rng.uniform(0.5, 1.5, size=(n, len(s))) for _, s in f.inputs]


@pytest.mark.parametrize("f", FUNCTIONS, ids=lambda f: f.path)
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_a_non_finite_input_warns_by_default_naming_it(f, bad):
    rng = np.random.default_rng(7)
    xs = points(f, 6, rng)
    arg, syms = f.inputs[-1]
    xs[-1][4, len(syms) - 1] = bad
    with pytest.warns(pegdyn.NonFiniteWarning) as w:
        out = f(*xs)
    msg = str(w[0].message)
    assert f"`{arg}`" in msg and f"`{syms[-1]}`" in msg and "row 4" in msg, msg
    # The values are returned as computed: the other rows are the clean ones.
    clean = f(*points(f, 6, np.random.default_rng(7)), errors="propagate")
    for name, _ in f.outputs:
        np.testing.assert_array_equal(np.delete(out[name], 4, axis=0), np.delete(clean[name], 4, axis=0))
    with pytest.raises(ValueError, match=f"`{syms[-1]}`"):
        f(*xs, errors="raise")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        f(*xs, errors="propagate")
        f(*points(f, 3, rng))  # finite in, finite out: silent by default


def test_a_non_finite_output_from_finite_inputs_is_reported():
    f = pegdyn.generated.pendulum.energy
    x = np.array([[0.1, 1.0], [0.2, 1e200], [0.3, 2.0]])  # thetadot^2 overflows
    with pytest.warns(pegdyn.NonFiniteWarning, match=r"output `energy` is inf at row 1 from finite inputs"):
        e = f(x, [1.0, 1.0, 9.81])["energy"]
    assert np.isinf(e[1]) and np.isfinite(e[[0, 2]]).all()
    with pytest.raises(ValueError, match="row 1"):
        f.raw(x, [1.0, 1.0, 9.81], errors="raise")
    with pytest.raises(ValueError, match="errors must be one of"):
        f(x, [1.0, 1.0, 9.81], errors="ignore")


@pytest.mark.parametrize("f", FUNCTIONS, ids=lambda f: f.path)
def test_masked_points_give_masked_outputs(f):
    rng = np.random.default_rng(11)
    xs = points(f, 5, rng)
    mask = np.zeros_like(xs[0], dtype=bool)
    mask[2, 0] = True
    hidden = xs[0].copy()
    hidden[2, 0] = np.nan  # under the mask: never reported, never shown
    m = np.ma.MaskedArray(hidden, mask=mask)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = f(m, *xs[1:])
        flat = f.raw(m, *xs[1:])
    plain = f(*xs)
    for name, k in f.outputs:
        got = out[name]
        assert isinstance(got, np.ma.MaskedArray), name
        rows_masked = np.ma.getmaskarray(got).reshape(5, -1).all(axis=1)
        assert rows_masked.tolist() == [False, False, True, False, False], name
        np.testing.assert_array_equal(np.delete(got.data, 2, axis=0), np.delete(plain[name], 2, axis=0))
    assert isinstance(flat, np.ma.MaskedArray) and np.ma.getmaskarray(flat)[2].all()
    assert not np.ma.getmaskarray(flat)[[0, 1, 3, 4]].any()


def test_a_masked_shared_row_masks_every_point_and_a_masked_point_is_masked():
    f = pegdyn.generated.pendulum.energy
    x = np.array([[0.1, 1.0], [0.2, 2.0]])
    p = np.ma.MaskedArray([1.0, 1.0, 9.81], mask=[False, True, False])
    out = f(x, p)["energy"]
    assert np.ma.getmaskarray(out).all()
    single = f(np.ma.MaskedArray([0.1, 1.0], mask=[True, False]), [1.0, 1.0, 9.81])["energy"]
    assert single is np.ma.masked
    unmasked = f(np.ma.MaskedArray([0.1, 1.0], mask=[False, False]), [1.0, 1.0, 9.81])["energy"]
    assert unmasked == f([0.1, 1.0], [1.0, 1.0, 9.81])["energy"]


# ---------------------------------------------------------------- sweeps


class NoClient:
    """A Dask client that fails the test if the sweep reaches it."""

    def __getattr__(self, name):
        raise AssertionError(f"the sweep used the client ({name}) before checking its keys")


@pytest.mark.parametrize(
    "key,named,listed",
    [
        ("pendulum.lenght", "pendulum.lenght", "`length`"),
        ("pendulm.length", "pendulm", "`pendulum`"),
        ("integrator.tend", "integrator.tend", "`t_end`"),
        ("pendulum.length.x", "pendulum.length", "not a table"),
    ],
)
def test_a_misspelled_sweep_key_raises_before_any_run(key, named, listed):
    scene = pegdyn.load("scenes/pendulum.toml")
    with pytest.raises(pegdyn.SceneError) as e:
        pegdyn.sweep(scene, {key: [1.0, 2.0]}, client=NoClient())
    msg = str(e.value)
    assert named in msg and listed in msg and "no point was run" in msg, msg


def test_a_valid_key_with_a_bad_value_stays_a_row_outcome():
    scene = pegdyn.load("scenes/pendulum.toml")
    rows = pegdyn.sweep(scene, {"pendulum.length": [-1.0, 1.0], "pendulum.gravity": [9.81]})
    assert rows["outcome"] == ["invalid", "ok"]
    assert "pendulum.length" in rows[0]["error"]
