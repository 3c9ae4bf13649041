"""Peer comparison for the rigid three-point peg, not run by CI: the forward
system A u = b of pegdyn's generated `rigid_peg::forward` built in SymPy
(lambdify; C from sympy's C printer after cse) and CasADi (SX Function; C
from Function.generate), checked against pegdyn's values, timed, and
integrated with SciPy's solve_ivp (and CasADi's CVODES) against pegdyn's
DOPRI5, all in one run.

    pip install -r benches/peers/requirements.txt
    python3 benches/peers/rigid_peg.py    # about 30 s here after the cargo build

It runs `cargo build --release -p pegdyn-benches --bin rigid_peer_values` and that
example (pegdyn's values, timing loop and DOPRI5 runs), writes the generated
C and the shared libraries to target/peers/, and prints markdown tables.
Options: --quick (fewer repeats), --json FILE (all numbers), --cflags
(default "-O3"; pegdyn is built at opt-level 3 without target-cpu=native,
so no -march=native here either).

Files: rigid_peg_model.py (the derivation, for SymPy and CasADi),
rigid_peg_c.py (generated C, timing loop in C), rigid_peg_integrate.py
(the integration study).
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import time
import timeit

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)

import rigid_peg_c as cgen  # noqa: E402
import rigid_peg_model as model  # noqa: E402
from rigid_peg_integrate import integration_study  # noqa: E402

# The Fig. 9 peg of scenes/align_forward.toml: D, d, H, m, g, f.
PEG = [0.050, 0.04995, 0.070, 1.0, 9.81, 0.2]
P = PEG + [model.gamma0(PEG[0], PEG[1])]


def example(*args, stdin=""):
    """Runs pegdyn's example (built by main) and returns its JSON lines."""
    cmd = [os.path.join(ROOT, "target", "release", "rigid_peer_values"), *args]
    out = subprocess.run(cmd, input=stdin, capture_output=True, text=True, cwd=ROOT, check=True)
    return [json.loads(line) for line in out.stdout.splitlines() if line.strip()]


def line(x, p, loads, t):
    return " ".join(repr(float(v)) for v in [*x, *p, *loads, *t])


def check_inputs():
    """States for the value check: gamma from gamma0(1 + 1e-9) to 1.2 rad,
    psi of both signs, rates of both signs, random loads and unit friction
    directions (seeded)."""
    rng = np.random.default_rng(0)
    g0 = P[6]
    gammas = [g0 * (1 + 1e-9), g0 * (1 + 1e-6), g0 * (1 + 1e-3), 0.1, 0.3, 0.5, 0.9, 1.2]
    cases = []
    for k, gam in enumerate(gammas):
        x = [gam, [0.0, 0.7, -2.0][k % 3], rng.uniform(-3, 3), rng.uniform(-12, 12)]
        loads = list(rng.uniform(-1, 1, 2) * 0.2) + list(rng.uniform(-20, 20, 3))
        t = rng.normal(size=(3, 3))
        t = list((t / np.linalg.norm(t, axis=1, keepdims=True)).ravel())
        cases.append((x, P, loads, t))
    return cases


def rel_rows(a, b, a_ref, b_ref):
    """Largest row-wise relative difference of [A | b] (each row against its
    own max norm)."""
    m, r = np.hstack([a, b[:, None]]), np.hstack([a_ref, b_ref[:, None]])
    return float(max(np.abs(m[i] - r[i]).max() / np.abs(r[i]).max() for i in range(5)))


def median_ns(fn, number, repeats):
    times = timeit.repeat(fn, number=number, repeat=repeats)
    return statistics.median(times) / number * 1e9


def build_peers(cflags):
    """All peers as callables forward(x, p, loads, t) -> (A (5x5), b)."""
    import casadi as ca
    import sympy as sp

    out_dir = os.path.join(ROOT, "target", "peers")
    os.makedirs(out_dir, exist_ok=True)
    info = {}
    t0 = time.perf_counter()
    sym = model.derive(model.SymPy())
    info["sympy_derive_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    cas = model.derive(model.CasADi())
    info["casadi_derive_s"] = time.perf_counter() - t0
    args = [sym["x"], sym["p"], sym["loads"], sym["t"]]
    t0 = time.perf_counter()
    # Out of the box: matrices, default modules (numpy), no cse.
    lam_default = sp.lambdify(args, [sp.Matrix(sym["A"]), sp.Matrix(sym["b"])])
    # Tuned: a flat list (lambdify's cse=True leaves nested lists alone), math module.
    flat = [e for row in sym["A"] for e in row] + list(sym["b"])
    lam_flat = sp.lambdify(args, flat, modules="math", cse=True)

    def lam_math(x, p, l, t):
        v = lam_flat(x, p, l, t)
        return [v[5 * r:5 * r + 5] for r in range(5)], v[25:]
    info["lambdify_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    src, n_lets = cgen.sympy_source(sym)
    info["sympy_ccode_s"] = time.perf_counter() - t0
    info["sympy_cse_lets"] = n_lets
    sympy_lib, cmd_s = cgen.compile_library(src, out_dir, "rigid_forward_sympy", cflags)
    fns, libs, cmds = {}, {}, [cmd_s]
    for cse in (False, True):
        tag = "_cse" if cse else ""
        fn = fns[cse] = cgen.casadi_function(cas, cse)
        info[f"casadi{tag}_n_instructions"] = fn.n_instructions()
        csrc, sz_w = cgen.casadi_source(fn, out_dir, f"rigid_forward_casadi{tag}")
        if sz_w > 1024:
            raise RuntimeError(f"CasADi work vector {sz_w} > 1024: enlarge peer_w")
        libs[cse], cmd = cgen.compile_library(csrc, out_dir, f"rigid_forward_casadi{tag}_peer", cflags)
        cmds.append(cmd)
    info["compile"] = cmds
    exts = {cse: ca.external("rigid_forward", os.path.join(out_dir, f"rigid_forward_casadi{tag}_peer.so"))
            for cse, tag in ((False, ""), (True, "_cse"))}

    def lam(f):
        return lambda x, p, l, t: tuple(np.array(v, dtype=float).reshape(s) for v, s in zip(f(x, p, l, t), [(5, 5), 5]))

    def cas_call(f):
        def call(x, p, l, t):
            a, b = f(x, p, l, t)
            return a.full(), b.full().ravel()
        return call

    peers = {
        "SymPy lambdify (default: numpy, no cse)": (lam(lam_default), lambda x, p, l, t: lam_default(x, p, l, t)),
        "SymPy lambdify (math, cse=True, flat list)": (lam(lam_math), lambda x, p, l, t: lam_flat(x, p, l, t)),
    }
    for cse, tag in ((False, ""), (True, ", cse=True")):
        peers[f"CasADi SX Function{tag}"] = (cas_call(fns[cse]), lambda x, p, l, t, f=fns[cse]: f(x, p, l, t))
        peers[f"CasADi generated C{tag} via casadi.external"] = (
            cas_call(exts[cse]), lambda x, p, l, t, f=exts[cse]: f(x, p, l, t))
    c_peers = {"SymPy generated C (cse)": cgen.CForward(sympy_lib),
               "CasADi generated C": cgen.CForward(libs[False], column_major=True),
               "CasADi generated C (cse=True)": cgen.CForward(libs[True], column_major=True)}
    return sym, cas, peers, c_peers, info


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="fewer repeats")
    ap.add_argument("--json", help="write every number to this file")
    ap.add_argument("--cflags", default="-O3", help="C compiler flags (default -O3)")
    a = ap.parse_args()
    repeats = 3 if a.quick else 9
    import casadi
    import scipy
    import sympy

    report = {"uptime_start": os.popen("uptime").read().strip(), "python": platform.python_version(),
              "sympy": sympy.__version__, "casadi": casadi.__version__, "scipy": scipy.__version__,
              "numpy": np.__version__, "cc": os.popen("cc --version").readline().strip(),
              "cflags": a.cflags}
    print(f"# {report['uptime_start']}")
    print(f"# Python {report['python']}, SymPy {report['sympy']}, CasADi {report['casadi']}, "
          f"SciPy {report['scipy']}, NumPy {report['numpy']}; {report['cc']}, {a.cflags}")
    subprocess.run(["cargo", "build", "--quiet", "--release", "-p", "pegdyn-benches", "--bin", "rigid_peer_values"],
                   cwd=ROOT, check=True)
    sym, cas, peers, c_peers, info = build_peers(a.cflags.split())
    report["build"] = info
    print(f"# derivation: SymPy {info['sympy_derive_s']:.2f} s, CasADi {info['casadi_derive_s']:.2f} s; "
          f"SymPy cse: {info['sympy_cse_lets']} temporaries; CasADi: {info['casadi_n_instructions']} "
          f"instructions ({info['casadi_cse_n_instructions']} with cse=True)")

    # 1. Values against pegdyn.
    cases = check_inputs()
    ref = example("values", stdin="\n".join(line(*c) for c in cases) + "\n")
    all_peers = {**{k: v[0] for k, v in peers.items()}, **c_peers}
    print("\n## Values against pegdyn's generated rigid_peg::forward\n")
    print("Largest row-wise relative difference of [A | b] (each row against its max norm) over "
          f"{len(cases)} states, gamma from gamma0(1 + 1e-9) to 1.2 rad; and of u = A^-1 b.\n")
    print("| peer | [A, b] | u |")
    print("|---|---|---|")
    report["values"] = {}
    for name, f in all_peers.items():
        worst_ab, worst_u = 0.0, 0.0
        for c, r in zip(cases, ref):
            aa, bb = f(*c)
            a_ref, b_ref = np.array(r["a"]).reshape(5, 5), np.array(r["b"])
            worst_ab = max(worst_ab, rel_rows(aa, bb, a_ref, b_ref))
            u, u_ref = np.linalg.solve(aa, bb), np.array(r["u"])
            worst_u = max(worst_u, float(np.abs(u - u_ref).max() / np.abs(u_ref).max()))
        report["values"][name] = {"ab": worst_ab, "u": worst_u}
        print(f"| {name} | {worst_ab:.1e} | {worst_u:.1e} |")
        if worst_ab > 1e-12:
            raise SystemExit(f"{name} does not match pegdyn ({worst_ab:.1e} > 1e-12)")

    # 2. Cost per call of A, b (one state of the align_forward scene).
    x0 = [0.3, 0.7, -0.5, 10.0]
    loads = [-0.15, 0.0, 0.0, 0.0, 0.0]
    t = list(np.array([[0.6, 0.0, 0.8], [-0.36, 0.48, 0.8], [0.6, 0.8, 0.0]]).ravel())
    inp = (x0, P, loads, t)
    calls = 20_000 if a.quick else 200_000
    # Compiled code: interleaved rounds (pegdyn's loop, then each C loop), so that a change of
    # the machine's load hits all alike; each round is a median of 3 loops; median over rounds.
    compiled = {"pegdyn generated Rust, timed in Rust (black_box loop)": [],
                **{f"{name}, timed in C (asm barrier loop)": [] for name in c_peers}}
    peg = []
    for fc in c_peers.values():
        fc(*inp)
    for _ in range(repeats):
        peg.append(example("time", str(calls), "3", stdin=line(*inp))[0])
        compiled["pegdyn generated Rust, timed in Rust (black_box loop)"].append(peg[-1]["forward_ns"])
        for name, fc in c_peers.items():
            compiled[f"{name}, timed in C (asm barrier loop)"].append(
                statistics.median(fc.bench_ns(calls) for _ in range(3)))
    peg_ns = statistics.median(compiled["pegdyn generated Rust, timed in Rust (black_box loop)"])
    peg_lu = statistics.median(r["forward_lu_ns"] for r in peg)
    peg_rhs = statistics.median(r["rhs_ns"] for r in peg)
    spread = {name: (min(v), max(v)) for name, v in compiled.items()}
    rows = [(name, statistics.median(v)) for name, v in compiled.items()]
    for name, fc in c_peers.items():
        rows.append((f"{name}, called through ctypes", median_ns(fc.call_only, calls // 4, repeats)))
    inp_np = tuple(np.array(v, dtype=float) for v in inp)
    inp_dm = tuple(casadi.DM(v) for v in inp_np)
    timed = [(name, raw, inp_np if "CasADi" in name else inp, "numpy array" if "CasADi" in name else "list")
             for name, (_, raw) in peers.items()]
    timed += [(name, raw, inp_dm, "casadi.DM") for name, (_, raw) in peers.items() if "CasADi" in name]
    for name, raw, args, kind in timed:
        n = max(200, calls // (20 if "flat" in name else 200))
        ns = median_ns(lambda r=raw, z=args: r(*z), n, repeats)
        rows.append((f"{name}, called from Python ({kind} inputs)", ns))
    print(f"\n## Cost of one evaluation of A and b ({a.cflags}; median of {repeats} rounds)\n")
    print("| implementation | ns per call | range over rounds | ratio to pegdyn |")
    print("|---|---|---|---|")
    report["per_call_ns"], report["per_call_range_ns"] = {}, spread
    for name, ns in rows:
        report["per_call_ns"][name] = ns
        lo_hi = f"{spread[name][0]:.0f}-{spread[name][1]:.0f}" if name in spread else "-"
        print(f"| {name} | {ns:,.0f} | {lo_hi} | {ns / peg_ns:.1f} |")
    report["pegdyn_forward_lu_ns"], report["pegdyn_rhs_ns"] = peg_lu, peg_rhs
    print(f"\npegdyn: forward + 5x5 LU solve {peg_lu:.0f} ns; whole PegSystem right-hand side "
          f"(friction directions, forward, LU) {peg_rhs:.0f} ns.")

    # 3. Integration.
    report["integration"] = integration_study(
        sym, cas, example, P, repeats, os.path.join(ROOT, "target", "peers"), a.cflags.split())
    report["uptime_end"] = os.popen("uptime").read().strip()
    print(f"\n# {report['uptime_end']}")
    if a.json:
        with open(a.json, "w") as fh:
            json.dump(report, fh, indent=1)


if __name__ == "__main__":
    main()
