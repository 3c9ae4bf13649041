"""Peer comparison (not run by CI): the simple pendulum of scenes/pendulum.toml
derived with SymPy (Lagrange), evaluated with sympy.lambdify, and integrated
with SciPy's solve_ivp, timed like pegdyn's benches.

    pip install sympy scipy
    python3 benches/peers/pendulum.py

Prints ns per right-hand-side call (lambdify, scalar math module) and, for
RK45 (Dormand-Prince 5(4), as pegdyn's DOPRI5), DOP853 and Radau at several
rtol, the error of theta at t = 10 s against DOP853 at rtol 1e-13, the number
of RHS calls and the median wall time of 5 runs. Compare with the rows
`pendulum/rhs/generated` and the pendulum work-precision table of
docs/BENCHMARKS.md.
"""
import math
import statistics
import time
import timeit

import sympy as sp
from scipy.integrate import solve_ivp

m, l, g, t = sp.symbols("m l g t", positive=True)
th = sp.Function("theta")(t)
lag = sp.Rational(1, 2) * m * l**2 * th.diff(t) ** 2 + m * g * l * sp.cos(th)
eq = sp.diff(lag.diff(th.diff(t)), t) - lag.diff(th)
thdd = sp.solve(eq, th.diff(t, 2))[0]
q, w = sp.symbols("q w")
acc = thdd.subs({th.diff(t): w, th: q})
f = sp.lambdify((q, w, m, l, g), [w, acc], modules="math")
P = (1.0, 1.0, 9.80665)


def rhs(_t, y):
    return f(y[0], y[1], *P)


n = 200_000
ns = min(timeit.repeat(lambda: rhs(0.0, (0.3, 0.1)), number=n, repeat=5)) / n * 1e9
print(f"lambdify rhs: {ns:.0f} ns per call")

y0 = [math.radians(60.0), 0.0]
ref = solve_ivp(rhs, (0.0, 10.0), y0, method="DOP853", rtol=1e-13, atol=1e-13)
theta_ref = ref.y[0, -1]
print("| method | rtol | rhs calls | time (ms, median of 5) | error of theta at 10 s |")
print("|---|---|---|---|---|")
for method, rtols in [("RK45", [1e-4, 1e-6, 1e-8, 1e-10]), ("DOP853", [1e-6, 1e-8, 1e-10]), ("Radau", [1e-4, 1e-6, 1e-8])]:
    for rtol in rtols:
        times = []
        for _ in range(5):
            start = time.perf_counter()
            sol = solve_ivp(rhs, (0.0, 10.0), y0, method=method, rtol=rtol, atol=rtol)
            times.append(time.perf_counter() - start)
        err = abs(sol.y[0, -1] - theta_ref)
        print(f"| {method} | {rtol:.0e} | {sol.nfev} | {statistics.median(times) * 1e3:.2f} | {err:.1e} |")
