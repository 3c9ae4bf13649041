"""Timings of the Python package (the numbers in docs/bench/python.md,
summarized in docs/BENCHMARKS.md, section "Python package").

1. A vectorized generated function called from Python, ns per point at
   N = 1, 1e3, 1e6, against the same Rust loop without Python and, when
   installed, SymPy (a numpy ``lambdify`` of the same expression) and
   CasADi (the same function built from SX symbols, evaluated on all
   points by ``Function.map(N)``); the peers' values are checked against
   pegdyn's first.
2. One cheap scene run (a 10 ms pendulum) in memory (``run()``) against
   writing its files (``run(out=...)``).
3. A sweep of N runs of that scene locally against a two-worker
   ``LocalCluster`` (one thread per worker process): the engine's
   overhead in %.

    python python/examples/benchmark.py [--runs 10000] [--skip-dask]

Build the package in release mode first (``pip install ./python``);
SymPy and CasADi are optional (``pip install sympy casadi``): a peer that
is not installed is left out of the table.
"""

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import pegdyn

ROOT = Path(__file__).resolve().parents[2]


def best(f, repeats):
    t = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        f()
        t.append(time.perf_counter() - t0)
    return min(t)


def pendulum_points(rng, n):
    """theta, thetadot in [0.5, 1.5); m, l, g in [0.5, 1.5)."""
    return [rng.uniform(0.5, 1.5, size=(n, 2)), rng.uniform(0.5, 1.5, size=(n, 3))]


def rigid_points(rng, n):
    """States of the Fig. 9 peg (D = 50 mm, d = 49.95 mm, H = 70 mm, 1 kg,
    f = 0.2) with gamma in (gamma0, 1.2 rad), random loads and unit
    friction directions; one parameter row per point."""
    from rigid_peg_model import gamma0

    peg = [0.050, 0.04995, 0.070, 1.0, 9.81, 0.2]
    g0 = gamma0(peg[0], peg[1])
    x = np.column_stack([
        rng.uniform(g0 * (1 + 1e-3), 1.2, n), rng.uniform(-1, 1, n),
        rng.uniform(-3, 3, n), rng.uniform(-12, 12, n),
    ])
    p = np.tile(peg + [g0], (n, 1))
    loads = np.column_stack([rng.uniform(-0.2, 0.2, (n, 2)), rng.uniform(-20, 20, (n, 3))])
    t = rng.normal(size=(n, 3, 3))
    t = (t / np.linalg.norm(t, axis=2, keepdims=True)).reshape(n, 9)
    return [x, p, loads, t]


def casadi_pendulum():
    """pendulum::energy in CasADi SX: E = m l^2 thetadot^2 / 2 - m g l cos(theta)."""
    import casadi as ca

    x, p = ca.SX.sym("x", 2), ca.SX.sym("p", 3)
    th, thd, m, l, g = x[0], x[1], p[0], p[1], p[2]
    e = m * l**2 * thd**2 / 2 - m * g * l * ca.cos(th)
    return ca.Function("energy", [x, p], [e])


def casadi_rigid():
    """rigid_peg::forward in CasADi SX, derived from the same formulas by
    benches/peers/rigid_peg_model.py (CasADi differentiating on its own)."""
    import casadi as ca
    import rigid_peg_model as model

    m = model.derive(model.CasADi())
    a = ca.densify(ca.reshape(ca.vertcat(*[ca.horzcat(*row) for row in m["A"]]).T, 25, 1))
    b = ca.densify(ca.vertcat(*m["b"]))
    args = [ca.vertcat(*m[k]) for k in ("x", "p", "loads", "t")]
    return ca.Function("forward", args, [ca.vertcat(a, b)], {"cse": True})


def casadi_numpy(fn, n, xs):
    """``fn`` mapped over n points, called as a numpy user calls it: the
    (N, len) arrays in (transposed to CasADi's one column per point),
    an (N, total) array out."""
    mapped = fn.map(n, "serial")
    return lambda: mapped(*[x.T for x in xs]).full().T, np.asarray


def casadi_dm(fn, n, xs):
    """The same map called on inputs already converted to ``casadi.DM``,
    its DM result kept (CasADi's evaluation alone)."""
    import casadi as ca

    mapped = fn.map(n, "serial")
    args = [ca.DM(np.ascontiguousarray(x.T)) for x in xs]
    return lambda: mapped(*args), lambda v: v.full().T


def peers():
    """Optional peers: {(module, name): {peer: factory(n, xs) -> (thunk,
    to_numpy)}}: ``thunk()`` evaluates at the points ``xs`` (timed),
    ``to_numpy(thunk())`` gives the (N, total) values."""
    out = {("pendulum", "energy"): {}, ("rigid_peg", "forward"): {}}
    try:
        import sympy  # noqa: F401

        lam = sympy_energy()
        out[("pendulum", "energy")]["SymPy lambdify"] = lambda n, xs: (
            lambda: lam(xs[0][:, 0], xs[0][:, 1], xs[1][:, 0], xs[1][:, 1], xs[1][:, 2]),
            np.asarray,
        )
    except ImportError:
        pass
    try:
        import casadi  # noqa: F401
    except ImportError:
        return out
    sys.path.insert(0, str(ROOT / "benches" / "peers"))
    for key, build in [(("pendulum", "energy"), casadi_pendulum), (("rigid_peg", "forward"), casadi_rigid)]:
        fn = build()
        out[key]["CasADi (numpy)"] = lambda n, xs, fn=fn: casadi_numpy(fn, n, xs)
        out[key]["CasADi (DM)"] = lambda n, xs, fn=fn: casadi_dm(fn, n, xs)
    return out


def agreement(f, factory, xs):
    """Largest difference of the peer's values from pegdyn's, relative to
    the largest |value| of each output entry over the points."""
    ours = f.raw(*xs)
    thunk, to_numpy = factory(len(xs[0]), xs)
    theirs = np.asarray(to_numpy(thunk()), dtype=float).reshape(ours.shape)
    scale = np.maximum(np.abs(ours).max(axis=0), 1e-300)
    return float((np.abs(theirs - ours) / scale).max())


def vectorized():
    rng = np.random.default_rng(1)
    sys.path.insert(0, str(ROOT / "benches" / "peers"))
    points = {("pendulum", "energy"): pendulum_points, ("rigid_peg", "forward"): rigid_points}
    table = peers()
    names = sorted({k for v in table.values() for k in v})
    print("function                      N   python ns/pt   rust ns/pt " + " ".join(f"{n:>16}" for n in names))
    for (module, name), make in points.items():
        f = pegdyn.function(module, name)
        for peer, factory in table[(module, name)].items():
            xs = make(rng, 1000)
            print(f"# {f.path} vs {peer}: max relative difference {agreement(f, factory, xs):.1e} (1000 points)")
        for n in (1, 1_000, 1_000_000):
            xs = make(rng, n)
            reps = 3 if n == 1_000_000 else 200
            py = best(lambda: f.raw(*xs), reps) * 1e9 / n
            rs = pegdyn._pegdyn.rust_loop_ns(f.module, f.name, n, reps)
            cells = []
            for peer in names:
                factory = table[(module, name)].get(peer)
                if factory is None:
                    cells.append(f"{'-':>16}")
                    continue
                thunk, _ = factory(n, xs)
                cells.append(f"{best(thunk, reps) * 1e9 / n:16.1f}")
            print(f"{f.path:26} {n:>8} {py:14.1f} {rs:12.1f} " + " ".join(cells))


def sympy_energy():
    try:
        import sympy as sp
    except ImportError:
        return None
    th, thd, m, l, g = sp.symbols("theta thetadot m l g")
    e = m * l**2 * thd**2 / 2 - m * g * l * sp.cos(th)
    return sp.lambdify((th, thd, m, l, g), e, "numpy")


def cheap_scene():
    return pegdyn.load(ROOT / "scenes" / "pendulum.toml").with_values(
        {"integrator.t_end": 0.01, "integrator.output_interval": 0.01}
    )


def no_output(runs=2000):
    scene = cheap_scene()
    t_mem = best(lambda: [scene.run() for _ in range(runs)], 3) / runs
    with tempfile.TemporaryDirectory() as d:
        t_files = best(lambda: [scene.run(out=d) for _ in range(runs)], 3) / runs
    print(f"one 10 ms pendulum run: in memory {t_mem * 1e6:.0f} us, writing CSV + SVG {t_files * 1e6:.0f} us")


def sweep(runs, dask=True):
    scene = cheap_scene()
    grid = {"pendulum.theta0_deg": np.linspace(1.0, 120.0, runs)}
    t_local = best(lambda: pegdyn.sweep(scene, grid, threads=2, limits={"max_runs": runs}), 2)
    print(f"sweep of {runs} runs: local (2 Rust threads) {t_local:.2f} s ({t_local / runs * 1e6:.0f} us per run)")
    if not dask:
        return
    from dask.distributed import Client, LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as client:
            pegdyn.sweep(scene, {"pendulum.theta0_deg": [1.0, 2.0]}, client=client)  # warm up imports
            t_dask = best(
                lambda: pegdyn.sweep(scene, grid, client=client, threads=1, limits={"max_runs": runs}), 2
            )
    print(f"sweep of {runs} runs: local (2 Rust threads) {t_local:.2f} s, "
          f"2-worker LocalCluster {t_dask:.2f} s, overhead {100 * (t_dask / t_local - 1):+.0f} %")


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=10_000)
    ap.add_argument("--skip-dask", action="store_true")
    ap.add_argument("--functions-only", action="store_true")
    a = ap.parse_args()
    vectorized()
    if not a.functions_only:
        no_output()
        sweep(a.runs, dask=not a.skip_dask)
