"""Integration part of benches/peers/rigid_peg.py: scenes/align_forward.toml
(Fig. 9 peg, f = 0.2, released at gamma = 0.3 rad with psidot = 10 1/s under
M_gamma = -0.15 N m, exact Coulomb sliding on K, B1, B2) from its initial
state to t = 12 ms, before its first event (lift-off of K at 12.98 ms), as
`benches/tools/work_precision` integrates it (`rigid_forward`): no events,
atol = 1e-2 rtol, error = max(|d gamma|, |d psi|) at 12 ms against pegdyn's
DOPRI5 at rtol 1e-14. SciPy's nfev (the "rhs calls" column) does not count
the right-hand sides of Radau's finite-difference Jacobians (4 per "jac").

The peers' right-hand side is what a user writes: contact velocities v_i,
friction directions t_i = -v_i/|v_i|, A and b, u = numpy.linalg.solve(A, b),
xdot = (gammadot, psidot, u0, u1). pegdyn's (rigid_peg::forward::PegSystem) also
clamps gamma into the three-point range; on this interval gamma stays in
[0.2965, 0.3] rad, far from gamma0 = 0.0447, so the clamp never acts.
"""
import math
import statistics
import time

import numpy as np
from scipy.integrate import solve_ivp

LOADS = [-0.15, 0.0, 0.0, 0.0, 0.0]
T_END = 0.012
SETTINGS = [("RK45", [1e-6, 1e-8, 1e-10]), ("DOP853", [1e-6, 1e-8, 1e-10]), ("Radau", [1e-6, 1e-8])]


def directions(v):
    v = np.asarray(v, dtype=float).reshape(3, 3)
    return list((-v / np.linalg.norm(v, axis=1, keepdims=True)).ravel())


def rhs_lambdify(sym, p):
    """SymPy lambdify (math module, cse) for v and for A, b; numpy solve."""
    import sympy as sp

    args = [sym["x"], sym["p"], sym["loads"], sym["t"]]
    # Flat lists: lambdify's cse=True leaves nested lists alone.
    fwd = sp.lambdify(args, [e for row in sym["A"] for e in row] + list(sym["b"]), modules="math", cse=True)
    vel = sp.lambdify([sym["x"], sym["p"]], [e for v in sym["v"] for e in v], modules="math", cse=True)

    def rhs(_t, x):
        ab = fwd(x, p, LOADS, directions(vel(x, p)))
        u = np.linalg.solve(np.reshape(ab[:25], (5, 5)), ab[25:])
        return [x[2], x[3], u[0], u[1]]
    return rhs


def casadi_rhs_function(cas, p):
    """The whole right-hand side x -> xdot as one CasADi SX Function
    (friction directions and casadi.solve inside), parameters fixed, with
    CasADi's common-subexpression elimination (Function option cse)."""
    import casadi as ca

    x = ca.vertcat(*cas["x"])
    t = []
    for vi in cas["v"]:
        vi = ca.vertcat(*vi)
        t += ca.vertsplit(-vi / ca.norm_2(vi))
    a = ca.blockcat(cas["A"])
    b = ca.vertcat(*cas["b"])
    a, b = (ca.substitute([e], cas["t"], t)[0] for e in (a, b))
    u = ca.solve(a, b)
    xdot = ca.vertcat(x[2], x[3], u[0], u[1])
    xdot = ca.substitute([xdot], cas["p"] + cas["loads"], [ca.SX(v) for v in p + LOADS])[0]
    return ca.Function("rigid_rhs", [x], [xdot], {"cse": True})


def rhs_casadi(fn):
    def rhs(_t, x):
        return fn(x).full().ravel()
    return rhs


def run(rhs, y0, method, rtol):
    return solve_ivp(rhs, (0.0, T_END), y0, method=method, rtol=rtol, atol=1e-2 * rtol)


def timed(rhs, y0, method, rtol, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        sol = run(rhs, y0, method, rtol)
        times.append(time.perf_counter() - start)
    return sol, statistics.median(times)


def integration_study(sym, cas, example, p, repeats, out_dir, cflags):
    """Prints the integration tables; returns their numbers."""
    import casadi as ca
    import os
    import subprocess

    rtols = [10.0 ** -k for k in range(4, 13)]
    peg = example("integrate", str(repeats), *[repr(r) for r in rtols])
    y0, ref = peg[0]["x0"], peg[1]
    x_ref = np.array(ref["x_final"])
    peg_rows = {r["rtol"]: r for r in peg[2:]}
    err = lambda x: float(np.abs(np.asarray(x)[:2] - x_ref[:2]).max())  # noqa: E731

    fn = casadi_rhs_function(cas, p)
    cwd = os.getcwd()
    os.chdir(out_dir)
    fn.generate("rigid_rhs_casadi.c")
    os.chdir(cwd)
    so = os.path.join(out_dir, "rigid_rhs_casadi.so")
    subprocess.run(["cc", *cflags, "-fPIC", "-shared", "-o", so, os.path.join(out_dir, "rigid_rhs_casadi.c"),
                    "-lm"], check=True)
    rhs_peers = {
        "SymPy lambdify (math, cse) + numpy.linalg.solve": rhs_lambdify(sym, p),
        "CasADi SX Function (whole rhs, casadi.solve, cse)": rhs_casadi(fn),
        "CasADi generated C of the whole rhs via casadi.external": rhs_casadi(ca.external("rigid_rhs", so)),
    }
    out = {"pegdyn_reference": ref, "rows": [], "rhs": {}}
    # Right-hand sides against pegdyn's PegSystem at states along the path.
    states = [y0, [0.2975, 0.03, -0.4, 5.0], [0.29656, 0.0651, -0.604, 0.816]]
    vals = example("values", stdin="\n".join(
        " ".join(repr(float(v)) for v in [*s, *p, *LOADS, *[0.0] * 9]) for s in states) + "\n")
    sci_ref = run(rhs_peers["SymPy lambdify (math, cse) + numpy.linalg.solve"], y0, "DOP853", 1e-13)
    print("\n## Integration: scenes/align_forward.toml to 12 ms (no events), atol = 1e-2 rtol\n")
    print(f"Reference: pegdyn DOPRI5 rtol 1e-14 ({ref['steps']} steps), gamma(12 ms) = "
          f"{x_ref[0]:.15f}, psi = {x_ref[1]:.15f}; SciPy DOP853 rtol 1e-13 with the lambdify rhs "
          f"differs from it by {err(sci_ref.y[:, -1]):.1e} rad.\n")
    print("| right-hand side | rhs relative difference to pegdyn's PegSystem | us per rhs call |")
    print("|---|---|---|")
    for name, rhs in rhs_peers.items():
        diff = max(float(np.abs(np.asarray(rhs(0, s)) - v["xdot"]).max() / np.abs(v["xdot"]).max())
                   for s, v in zip(states, vals))
        n = 2000
        start = time.perf_counter()
        for _ in range(n):
            rhs(0.0, y0)
        us = (time.perf_counter() - start) / n * 1e6
        out["rhs"][name] = {"rel_diff": diff, "us": us}
        print(f"| {name} | {diff:.1e} | {us:.1f} |")
    print("| pegdyn PegSystem::rhs | - | see the per-call table |")

    # Peer rows first (printed at the end); pegdyn's DOPRI5 is timed three times spread over
    # the study (before, between and after the peers) and its median taken, so that a burst
    # of load on the shared machine does not decide its time.
    peg_runs = [peg]
    rows = []
    reps = repeats
    name0 = "SymPy lambdify (math, cse) + numpy.linalg.solve"
    jobs = [(m, r, name0) for m, rs in SETTINGS for r in rs]
    jobs += [("RK45", 1e-8, n) for n in rhs_peers if n != name0]
    for method, rtol, name in jobs:
        sol, wall = timed(rhs_peers[name], y0, method, rtol, reps)
        e = err(sol.y[:, -1]) if sol.success else math.inf
        rows.append({"who": f"SciPy {method} ({name})", "rtol": rtol, "steps": len(sol.t) - 1,
                     "nfev": int(sol.nfev), "jac": int(sol.njev), "ms": wall * 1e3, "err": e})
    peg_runs.append(example("integrate", str(repeats), *[repr(r) for r in rtols]))
    # For comparison: CasADi's own integrator (SUNDIALS CVODES through casadi.integrator; exact
    # Jacobian by AD), the SX right-hand side evaluated by CasADi's virtual machine or jit-compiled
    # (CasADi generates C for the rhs and its Jacobian and compiles it with cc and the flags here).
    xs = ca.SX.sym("x", 4)
    dae = {"x": xs, "ode": fn(xs)}
    for lmm, jit in (("adams", False), ("bdf", False), ("adams", True), ("bdf", True)):
        for rtol in (1e-6, 1e-8, 1e-10):
            opts = {"reltol": rtol, "abstol": 1e-2 * rtol, "linear_multistep_method": lmm}
            if jit:
                opts.update({"jit": True, "compiler": "shell", "jit_options": {"flags": cflags}})
            integ = ca.integrator("F", "cvodes", dae, 0.0, T_END, opts)
            xf = np.array(integ(x0=y0)["xf"]).ravel()
            st = integ.stats()
            times = []
            for _ in range(reps):
                start = time.perf_counter()
                integ(x0=y0)
                times.append(time.perf_counter() - start)
            who = f"CasADi integrator cvodes {lmm} ({'rhs jit-compiled' if jit else 'SX rhs, virtual machine'})"
            rows.append({"who": who, "rtol": rtol, "steps": int(st["nsteps"]), "nfev": int(st["nfevals"]),
                         "jac": "-", "ms": statistics.median(times) * 1e3, "err": err(xf)})
    peg_runs.append(example("integrate", str(repeats), *[repr(r) for r in rtols]))
    peg_rows = {}
    for k, rtol in enumerate(rtols):
        r = peg_runs[0][2 + k]
        ms = statistics.median(run_[2 + k]["wall_ms"] for run_ in peg_runs)
        peg_rows[rtol] = {"who": "pegdyn DOPRI5", "rtol": rtol, "steps": r["steps"], "nfev": r["rhs_calls"],
                          "jac": 0, "ms": ms, "err": err(r["x_final"])}

    def matched(e):
        """Wall time (ms) of the fastest pegdyn run with an error <= e."""
        ok = [r["ms"] for r in peg_rows.values() if r["err"] <= e]
        return min(ok) if ok else math.nan

    print("\n| integrator (rhs) | rtol | steps | rhs calls | jac | time (ms) | error at 12 ms (rad) | "
          "time / pegdyn DOPRI5 same rtol | time / pegdyn DOPRI5 same or smaller error |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in list(peg_rows.values()) + rows:
        pegdyn = r["who"] == "pegdyn DOPRI5"
        same = "1" if pegdyn else f"{r['ms'] / peg_rows[r['rtol']]['ms']:.0f}"
        best = "-" if pegdyn else f"{r['ms'] / matched(r['err']):.0f}"
        print(f"| {r['who']} | {r['rtol']:.0e} | {r['steps']} | {r['nfev']} | {r['jac']} | "
              f"{r['ms']:.3g} | {r['err']:.1e} | {same} | {best} |")
    out["rows"] = list(peg_rows.values()) + rows
    return out
