"""Choosing a compliant wrist with exact gradients: the compliance centre's
height and the angular stiffness that minimize the peak contact force of
the robot insertion (``scenes/insert_rcc_sensitivities.toml``: a steel
peg, D = 25 mm, 0.3 mm and 1 degree errors, from 1 mm above the mouth to
the seat at 8 mm), subject to seating within a time.

Each evaluation is one run of the scene with its ``[sensitivities]``
table: the peak contact force, the seat time and their derivatives with
respect to ``wrist.centre_height`` and ``wrist.angular_stiffness`` come
from the same run (forward sensitivities, ``docs/sensitivities.md``).
``scipy.optimize.minimize`` (SLSQP) takes them as the objective's and the
constraint's gradients. A grid search over the same box (plain runs, in
parallel) is run beside it, and both optima are evaluated the same way,
so the designs and the number of runs each needed can be compared.

    python python/examples/design_rcc.py [--grid 9] [--max-seat-time 0.95] [--small]

``--small`` (what CI runs) loosens the tolerance, coarsens the grid to
2 x 2 and stops the optimizer after two iterations: it checks that the
pieces fit, not the optimum. The full form's result is in
``docs/insertion.md``.
"""

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np
from scipy.optimize import minimize

import pegdyn

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "insert_rcc_sensitivities.toml"

HEIGHT = "wrist.centre_height"
STIFFNESS = "wrist.angular_stiffness"
PEAK = "peak_contact_force_N"
SEAT = "seat_time_s"

# The design box: the compliance centre from the tip to 20 mm above it,
# the angular stiffness from 5 to 80 N m/rad, searched in its logarithm
# (the optimizer's steps are then relative changes). The optimizer works
# in millimetres and the logarithm, both of order one.
HEIGHT_MM = (0.0, 20.0)
LOG_STIFFNESS = (math.log(5.0), math.log(80.0))


def design_values(x):
    """The scene fields of the design point ``x = (h in mm, ln k)``."""
    return {HEIGHT: 1e-3 * float(x[0]), STIFFNESS: math.exp(float(x[1]))}


class Evaluations:
    """One sensitivity run per design point, kept: the objective, the
    constraint and their gradients at a point come from one run."""

    def __init__(self, scene):
        self.scene = scene
        self.runs = {}

    def at(self, x):
        key = (round(float(x[0]), 12), round(float(x[1]), 12))
        if key not in self.runs:
            values = design_values(key)
            s = self.scene.with_values(values).run().sensitivities
            # d/d(h in mm) = 1e-3 d/dh; d/d(ln k) = k d/dk.
            scales = {HEIGHT: 1e-3, STIFFNESS: values[STIFFNESS]}
            self.runs[key] = {m: metric(s, m, scales, values) for m in (PEAK, SEAT)}
        return self.runs[key]

    def peak(self, x):
        return self.at(x)[PEAK]

    def seat_margin(self, limit):
        return (
            lambda x: limit - self.at(x)[SEAT][0],
            lambda x: -self.at(x)[SEAT][1],
        )


def metric(s, name, scales, values):
    """The value of metric ``name`` and its gradient along the design
    fields (in the optimizer's variables), refusing a flagged one."""
    rows = s["metric"] == name
    grad = []
    for field, scale in scales.items():
        row = rows & (s["parameter"] == field)
        if not row.any():
            sys.exit(f"the scene does not name {field} in [sensitivities]")
        flag = s["flag"][row][0]
        if flag:
            sys.exit(f"{name} along {field} at {values}: no derivative ({flag})")
        grad.append(scale * s["derivative"][row][0])
    return s["value"][rows][0], np.array(grad)


def plain_scene(overrides):
    """The scene's plain run: the scene file without its [sensitivities]
    table (its last), with ``overrides``."""
    text = SCENE.read_text()
    plain = text[: text.index("\n[sensitivities]")] + "\n"
    return pegdyn.loads(plain, SCENE.stem + "_plain").with_values(overrides)


def grid_search(plain, n, limit):
    """The point of an n x n grid over the box that seats within
    ``limit`` with the least peak contact force, from plain runs (a local
    parallel sweep; the peak over the output samples and the events)."""
    heights = np.linspace(*HEIGHT_MM, n)
    logs = np.linspace(*LOG_STIFFNESS, n)
    points = [design_values((h, lk)) for h in heights for lk in logs]
    rows = pegdyn.sweep(plain, points=points)
    best = None
    for p, r in zip(points, rows):
        seated = r["outcome"] == "ok" and r["outcome (summary)"] == 0.0
        t, peak = r["end time [s]"], r["peak contact normal force [N]"]
        if seated and t <= limit and (best is None or peak < best[0]):
            best = (peak, p)
    return best, len(points)


def show(label, x, ev, runs, seconds):
    (peak, _), (seat, _) = ev.at(x)[PEAK], ev.at(x)[SEAT]
    v = design_values(x)
    print(
        f"{label}: centre height {1e3 * v[HEIGHT]:.2f} mm, angular stiffness "
        f"{v[STIFFNESS]:.2f} N m/rad -> peak contact force {peak:.3f} N, seat time "
        f"{seat:.4f} s ({runs} run{'' if runs == 1 else 's'}, {seconds:.0f} s)"
    )


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--grid", type=int, default=9, help="grid points per design field (default 9)")
    ap.add_argument("--max-seat-time", type=float, default=0.95, help="seat within this time, s (default 0.95)")
    ap.add_argument("--small", action="store_true", help="CI form: rtol 1e-6, a 2 x 2 grid, 2 iterations")
    args = ap.parse_args()

    n, maxiter, overrides = args.grid, 50, {}
    if args.small:
        n, maxiter = 2, 2
        overrides = {"integrator.rtol": 1e-6, "integrator.atol": 1e-10}
    scene = pegdyn.load(SCENE).with_values(overrides)

    ev = Evaluations(scene)
    x0 = np.array([0.0, math.log(20.0)])
    start = time.perf_counter()
    ev.at(x0)
    show("the shipped design", x0, ev, 1, time.perf_counter() - start)
    seat_margin, seat_margin_grad = ev.seat_margin(args.max_seat_time)
    start = time.perf_counter()
    opt = minimize(
        ev.peak,
        x0,
        jac=True,
        method="SLSQP",
        bounds=[HEIGHT_MM, LOG_STIFFNESS],
        constraints=[{"type": "ineq", "fun": seat_margin, "jac": seat_margin_grad}],
        options={"maxiter": maxiter, "ftol": 1e-9},
    )
    opt_seconds = time.perf_counter() - start
    opt_runs = len(ev.runs)
    print(f"SLSQP: {opt.message} after {opt.nit} iterations")
    show("SLSQP with exact gradients", opt.x, ev, opt_runs, opt_seconds)

    start = time.perf_counter()
    best, runs = grid_search(plain_scene(overrides), n, args.max_seat_time)
    grid_seconds = time.perf_counter() - start
    if best is None:
        print(f"grid {n} x {n}: no point seats within {args.max_seat_time} s ({runs} runs)")
        return
    _, p = best
    x = (1e3 * p[HEIGHT], math.log(p[STIFFNESS]))
    show(f"grid {n} x {n} (plain runs)", x, ev, runs, grid_seconds)


if __name__ == "__main__":
    main()
