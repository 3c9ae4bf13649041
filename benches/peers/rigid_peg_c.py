"""Generated C for the rigid peg's forward system (benches/peers/rigid_peg.py):
SymPy's C printer after sympy.cse, and CasADi's Function.generate. Each is
compiled with cc into a shared library together with a timing loop, so the
call can be timed inside C (no Python in the loop) and through ctypes.

Both libraries export
    void peer_forward(const double *x, const double *p, const double *loads,
                      const double *t, double *a, double *b)
(a row-major from SymPy, column-major from CasADi)
    double peer_bench(long calls, same inputs and outputs)     (ns per call)
The timing loop includes the generated source in the same translation unit
(the compiler may inline it, as rustc inlines pegdyn's #[inline] function)
and puts a compiler barrier (asm volatile with a "memory" clobber) after
every call, so that inputs are reloaded and outputs stored each time, as
std::hint::black_box does in pegdyn's loop.
"""
import ctypes
import subprocess

import numpy as np

from rigid_peg_model import FRICTION, LOADS, PARAMS, STATE

BENCH = r"""
#include <time.h>
double peer_bench(long calls, const double *x, const double *p, const double *l,
                  const double *t, double *a, double *b) {
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (long i = 0; i < calls; ++i) {
        peer_forward(x, p, l, t, a, b);
        __asm__ volatile("" : : "r"(x), "r"(a) : "memory");
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    return ((t1.tv_sec - t0.tv_sec) * 1e9 + (t1.tv_nsec - t0.tv_nsec)) / (double)calls;
}
"""


def sympy_source(model):
    """C source of peer_forward from the SymPy expressions (cse + ccode)."""
    import sympy as sp

    exprs = [e for row in model["A"] for e in row] + list(model["b"])
    lets, reduced = sp.cse(exprs, symbols=sp.numbered_symbols("w"))
    lines = ["#include <math.h>", "",
             "void peer_forward(const double *in_x, const double *in_p, const double *in_l,",
             "                  const double *in_t, double *out_a, double *out_b) {"]
    for arr, names in (("in_x", STATE), ("in_p", PARAMS), ("in_l", LOADS), ("in_t", FRICTION)):
        lines += [f"    const double {n} = {arr}[{k}];" for k, n in enumerate(names)]
    lines += [f"    const double {s} = {sp.ccode(e)};" for s, e in lets]
    lines += [f"    out_a[{k}] = {sp.ccode(e)};" for k, e in enumerate(reduced[:25])]
    lines += [f"    out_b[{k}] = {sp.ccode(e)};" for k, e in enumerate(reduced[25:])]
    lines.append("}")
    return "\n".join(lines) + "\n", len(lets)


def casadi_function(model, cse=False):
    """The CasADi SX Function rigid_forward(x, p, loads, t) -> (A, b), dense;
    `cse` is CasADi's Function option (off by default: then each separately
    built sin(gamma) etc. stays a separate instruction)."""
    import casadi as ca

    a = ca.densify(ca.blockcat(model["A"]))
    b = ca.densify(ca.vertcat(*model["b"]))
    args = [ca.vertcat(*model[k]) for k in ("x", "p", "loads", "t")]
    return ca.Function("rigid_forward", args, [a, b], ["x", "p", "loads", "t"], ["a", "b"], {"cse": cse})


def casadi_source(fn, directory, stem):
    """C source of peer_forward wrapping the code of fn.generate, written to
    `<directory>/<stem>.c` (A column-major)."""
    import os
    import shutil

    # generate() writes into the working directory; move it.
    fn.generate(f"{stem}.c", {"with_header": False})
    shutil.move(f"{stem}.c", os.path.join(directory, f"{stem}.c"))
    return r"""
#include "STEM.c"
static casadi_real peer_w[1024];
static casadi_int peer_iw[64];
/* a is written column-major, as CasADi (and nalgebra) store it. */
void peer_forward(const double *x, const double *p, const double *l, const double *t,
                  double *a, double *b) {
    const casadi_real *arg[4] = {x, p, l, t};
    casadi_real *res[2] = {a, b};
    rigid_forward(arg, res, peer_iw, peer_w, 0);
}
""".replace("STEM", stem), fn.sz_w()


def compile_library(source, directory, name, flags):
    """Writes `<name>.c` (source + the timing loop) and compiles it into
    `<name>.so` with `cc <flags> -fPIC -shared`; returns the ctypes library."""
    c_path = f"{directory}/{name}.c"
    so_path = f"{directory}/{name}.so"
    with open(c_path, "w") as fh:
        fh.write(source + BENCH)
    cmd = ["cc", *flags, "-fPIC", "-shared", "-o", so_path, c_path, "-lm"]
    subprocess.run(cmd, check=True, cwd=directory)
    lib = ctypes.CDLL(so_path)
    dp = ctypes.POINTER(ctypes.c_double)
    lib.peer_forward.argtypes = [dp] * 6
    lib.peer_forward.restype = None
    lib.peer_bench.argtypes = [ctypes.c_long] + [dp] * 6
    lib.peer_bench.restype = ctypes.c_double
    return lib, " ".join(cmd)


class CForward:
    """A compiled peer_forward with preallocated buffers."""

    def __init__(self, lib, column_major=False):
        self.lib, self.column_major = lib, column_major
        self.bufs = [np.zeros(n) for n in (4, 7, 5, 9, 25, 5)]
        dp = ctypes.POINTER(ctypes.c_double)
        self.ptrs = [buf.ctypes.data_as(dp) for buf in self.bufs]

    def __call__(self, x, p, loads, t):
        for buf, v in zip(self.bufs, (x, p, loads, t)):
            buf[:] = v
        self.lib.peer_forward(*self.ptrs)
        a = self.bufs[4].reshape(5, 5)
        return (a.T if self.column_major else a).copy(), self.bufs[5].copy()

    def call_only(self):
        """The bare ctypes call on the current buffers (for timing)."""
        self.lib.peer_forward(*self.ptrs)

    def bench_ns(self, calls):
        return self.lib.peer_bench(calls, *self.ptrs)
