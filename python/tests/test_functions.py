"""Vectorized generated functions agree with single calls; shapes and dtypes
are checked."""

import numpy as np
import pytest

import pegdyn

RNG = np.random.default_rng(20261124)


def inputs_for(f, n):
    # Positive values away from zero keep every model's inputs in its domain
    # (lengths, masses, radii); the state components vary too.
    return [RNG.uniform(0.5, 1.5, size=(n, len(s))) for _, s in f.inputs]


@pytest.mark.parametrize("f", pegdyn.functions(), ids=lambda f: f.path)
def test_vectorized_equals_single_calls(f):
    n = 7
    xs = inputs_for(f, n)
    # Random points can leave a model's domain (the rigid peg's geometry
    # gives NaN there): compared as computed, without the warning.
    many = f(*xs, errors="propagate")
    assert set(many) == {name for name, _ in f.outputs}
    for i in range(n):
        one = f(*[x[i] for x in xs], errors="propagate")
        for name, k in f.outputs:
            got = many[name][i]
            assert np.array_equal(np.asarray(got), np.asarray(one[name]), equal_nan=True), (name, i)
    flat = f.raw(*xs, errors="propagate")
    assert flat.shape == (n, sum(k for _, k in f.outputs))


def test_pendulum_energy_value():
    # E = m l^2 thetadot^2 / 2 - m g l cos(theta)
    x = np.array([[0.3, 2.0], [0.0, 0.0]])
    p = np.array([2.0, 0.5, 9.81])
    e = pegdyn.generated.pendulum.energy(x, p)["energy"]
    want = 2.0 * 0.25 * np.array([4.0, 0.0]) / 2 - 2.0 * 9.81 * 0.5 * np.cos([0.3, 0.0])
    np.testing.assert_allclose(e, want, rtol=1e-14)
    assert e.shape == (2,)


def test_broadcast_row_and_matrix_outputs():
    f = pegdyn.function("double_pendulum", "dynamics")
    x = RNG.uniform(-1, 1, size=(5, 4))
    p = np.ones((1, len(f.inputs[1][1])))
    out = f(x, p)
    assert out["mass"].shape == (5, 4) and out["forcing"].shape == (5, 2)
    # The mass matrix is symmetric (row-major 2x2).
    np.testing.assert_array_equal(out["mass"][:, 1], out["mass"][:, 2])


def test_wrong_shapes_and_dtypes():
    f = pegdyn.generated.pendulum.energy
    with pytest.raises(ValueError, match="`x` must have 2 columns"):
        f(np.zeros((3, 3)), np.ones(3))
    with pytest.raises(ValueError, match="rows"):
        f(np.zeros((3, 2)), np.ones((2, 3)))
    with pytest.raises(ValueError, match="shape"):
        f(np.zeros((3, 2, 1)), np.ones(3))
    with pytest.raises(TypeError, match="dtype"):
        f(np.zeros((3, 2), dtype=complex), np.ones(3))
    with pytest.raises(TypeError, match="dtype"):
        f(np.array([["a", "b"]]), np.ones(3))
    with pytest.raises(TypeError, match="takes 2 inputs"):
        f(np.zeros((3, 2)))
    with pytest.raises(KeyError):
        pegdyn.function("pendulum", "nothing")


def test_non_contiguous_and_integer_inputs():
    f = pegdyn.generated.pendulum.energy
    big = RNG.uniform(size=(6, 4))
    x = big[:, ::2]  # strided view
    a = f(x, [1, 1, 10])["energy"]  # integer parameters are converted
    b = f(np.ascontiguousarray(x), np.array([1.0, 1.0, 10.0]))["energy"]
    np.testing.assert_array_equal(a, b)


def test_empty_input():
    f = pegdyn.generated.pendulum.energy
    assert f(np.zeros((0, 2)), np.ones(3))["energy"].shape == (0,)
