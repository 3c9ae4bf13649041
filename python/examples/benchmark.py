"""Timings of the Python package (the numbers in docs/BENCHMARKS.md,
section "Python package").

1. A vectorized generated function called from Python, ns per point at
   N = 1, 1e3, 1e6, against the same Rust loop without Python and, when
   SymPy is installed, a numpy ``lambdify`` of the same expression.
2. A sweep of N runs of a cheap scene (a 10 ms pendulum) locally against
   a two-worker ``LocalCluster`` (one thread per worker process): the
   engine's overhead in %.

    python python/examples/benchmark.py [--runs 10000]

Build the package in release mode first (``pip install ./python``).
"""

import argparse
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


def vectorized():
    rng = np.random.default_rng(1)
    print("function                      N   python ns/pt   rust ns/pt   sympy ns/pt")
    for module, name in [("pendulum", "energy"), ("rigid_peg", None)]:
        fs = [f for f in pegdyn.functions() if f.module == module and (name is None or f.name == name)]
        if not fs:
            continue
        f = fs[0]
        lam = sympy_energy() if (module, name) == ("pendulum", "energy") else None
        for n in (1, 1_000, 1_000_000):
            xs = [rng.uniform(0.5, 1.5, size=(n, len(s))) for _, s in f.inputs]
            reps = 3 if n == 1_000_000 else 200
            py = best(lambda: f.raw(*xs), reps) * 1e9 / n
            rs = pegdyn._pegdyn.rust_loop_ns(f.module, f.name, n, reps)
            sp = ""
            if lam is not None:
                x, p = xs
                sp = f"{best(lambda: lam(x[:, 0], x[:, 1], p[:, 0], p[:, 1], p[:, 2]), reps) * 1e9 / n:12.1f}"
            print(f"{f.path:26} {n:>8} {py:14.1f} {rs:12.1f} {sp}")


def sympy_energy():
    try:
        import sympy as sp
    except ImportError:
        return None
    th, thd, m, l, g = sp.symbols("theta thetadot m l g")
    e = m * l**2 * thd**2 / 2 - m * g * l * sp.cos(th)
    return sp.lambdify((th, thd, m, l, g), e, "numpy")


def sweep(runs):
    from dask.distributed import Client, LocalCluster

    scene = pegdyn.load(ROOT / "scenes" / "pendulum.toml").with_values(
        {"integrator.t_end": 0.01, "integrator.output_interval": 0.01}
    )
    grid = {"pendulum.theta0_deg": np.linspace(1.0, 120.0, runs)}
    t_local = best(lambda: pegdyn.sweep(scene, grid, threads=2), 2)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as client:
            pegdyn.sweep(scene, {"pendulum.theta0_deg": [1.0, 2.0]}, client=client)  # warm up imports
            t_dask = best(lambda: pegdyn.sweep(scene, grid, client=client, threads=1), 2)
    print(f"sweep of {runs} runs: local (2 Rust threads) {t_local:.2f} s, "
          f"2-worker LocalCluster {t_dask:.2f} s, overhead {100 * (t_dask / t_local - 1):+.0f} %")


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=10_000)
    a = ap.parse_args()
    vectorized()
    sweep(a.runs)
