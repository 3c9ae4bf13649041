"""The rigid three-point peg derived from first principles,
once, for two symbolic engines: SymPy and CasADi SX (the same formulas,
each engine differentiating on its own). Used by benches/peers/rigid_peg.py.

The model is pegdyn's `rigid_peg` (docs/rigid-model.md): nutation gamma and
precession psi, spin held; every vector in the rotating components
(e_eta, e_n, e_z); kinetic energy of the rigid cylinder, potential m g z_C,
generalized forces by virtual power, Lagrange rows for gamma and psi, and
the centre-of-mass rows m a_C = F + m g + sum N_i (n_i + f t_i). The five
rows R are linear in u = (gammaddot, psiddot, N_K, N_B1, N_B2); the forward
system is A = dR/du, b = -R at u = 0. Inputs as pegdyn's generated
`rigid_peg::forward`: x (4), p = (D_hole, d_peg, H, m, g, f, gamma0) (7),
loads = (M_gamma, M_psi, F_x, F_y, F_z) (5), t (9, friction directions of K,
B1, B2 in rotating components). Geometry near gamma0 in the cancellation-free
product forms of docs/rigid-model.md (gamma0 is an input, as in pegdyn).
SI units.
"""
import math

STATE = ["gamma", "psi", "gammadot", "psidot"]
PARAMS = ["D_hole", "d_peg", "H", "m", "g", "f", "gamma0"]
LOADS = ["M_gamma", "M_psi", "F_x", "F_y", "F_z"]
FRICTION = [f"t_{c}_{a}" for c in ("K", "B1", "B2") for a in ("eta", "n", "z")]


class SymPy:
    """SymPy backend: real symbols, sympy.diff."""

    def __init__(self):
        import sympy

        self.sp = sympy
        self.sin, self.cos, self.sqrt = sympy.sin, sympy.cos, sympy.sqrt
        self.half = sympy.Rational(1, 2)

    def sym(self, name):
        return self.sp.Symbol(name, real=True)

    def diff(self, e, v):
        return self.sp.diff(e, v)

    def at_zero(self, e, vs):
        return e.xreplace({v: 0 for v in vs})


class CasADi:
    """CasADi SX backend: scalar SX symbols, casadi.jacobian."""

    def __init__(self):
        import casadi

        self.ca = casadi
        self.sin, self.cos, self.sqrt = casadi.sin, casadi.cos, casadi.sqrt
        self.half = 0.5

    def sym(self, name):
        return self.ca.SX.sym(name)

    def diff(self, e, v):
        if not isinstance(e, self.ca.SX):
            return 0
        return self.ca.jacobian(e, v)

    def at_zero(self, e, vs):
        z = [self.ca.SX(0)] * len(vs)
        return self.ca.substitute([e], vs, z)[0]


def add(a, b):
    return [a[k] + b[k] for k in range(3)]


def sub(a, b):
    return [a[k] - b[k] for k in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def derive(B):
    """Symbols and expressions of the model in backend B: returns a dict with
    the input lists x, p, loads, t, the 5x5 A (list of rows), b (5), and the
    contact velocities v (3 rows of 3, rotating components; depend on x, p)."""
    x = [B.sym(n) for n in STATE]
    p = [B.sym(n) for n in PARAMS]
    loads = [B.sym(n) for n in LOADS]
    t_flat = [B.sym(n) for n in FRICTION]
    t = [t_flat[3 * i:3 * i + 3] for i in range(3)]
    gdd, pdd = B.sym("gammaddot"), B.sym("psiddot")
    normal = [B.sym(n) for n in ("N_K", "N_B1", "N_B2")]
    gam, psi, gd, pd = x
    dh, dp, h, m, g, fr, g0 = p
    half = B.half

    # Geometry at gamma (docs/rigid-model.md, cancellation-free forms).
    s, co = B.sin(gam), B.cos(gam)
    c = 2 * dh * B.sin(half * (gam + g0)) * B.sin(half * (gam - g0))  # d - D cos
    e = (dh - dp) + 2 * dp * B.sin(half * gam) ** 2  # D - d cos
    a1, a2 = c / (2 * s), e / (2 * s)
    s1 = (a2 - a1 * co) / s
    gap = c * co / s**2  # D/2 - S1
    b = B.sqrt(gap * (dh - gap))
    lever = half * h - a2
    centre = [-lever * s, 0, lever * co + a1]
    ob = B.sqrt((half * dh) ** 2 + a1**2)
    contacts = [[-half * dh, 0, 0], [s1, b, 0], [s1, -b, 0]]
    normals = [[co, 0, s], [-s1 / ob, -b / ob, a1 / ob], [-s1 / ob, b / ob, a1 / ob]]
    axis, transverse, e_n = [-s, 0, co], [co, 0, s], [0, 1, 0]

    # Kinematics: d/dt by the chain rule, transport theorem with Omega = psidot e_z.
    pairs = [(gam, gd), (psi, pd), (gd, gdd), (pd, pdd)]

    def dt(expr):
        return sum(B.diff(expr, q) * qd for q, qd in pairs)

    frame = [0, 0, pd]
    v_c = add([dt(ci) for ci in centre], cross(frame, centre))
    a_c = add([dt(vi) for vi in v_c], cross(frame, v_c))
    omega = [0, -gd, pd]
    v = [add(v_c, cross(omega, sub(P, centre))) for P in contacts]

    # Energies of the rigid cylinder.
    r = half * dp
    i_axial = half * m * r**2
    i_trans = m * (3 * r**2 + h**2) / 12
    kinetic = (half * m * dot(v_c, v_c) + half * i_axial * dot(omega, axis) ** 2
               + half * i_trans * (dot(omega, transverse) ** 2 + dot(omega, e_n) ** 2))
    potential = m * g * centre[2]

    # Generalized forces by virtual power; the load F is fixed-frame, rotated by -psi.
    mg, mp, fx, fy, fz = loads
    sps, cps = B.sin(psi), B.cos(psi)
    force = [fx * cps + fy * sps, fy * cps - fx * sps, fz]
    rows = []
    for moment, q, rate in ((mg, gam, gd), (mp, psi, pd)):
        gen = moment + sum(force[k] * B.diff(v_c[k], rate) for k in range(3))
        gen += sum(fr * normal[i] * t[i][k] * B.diff(v[i][k], rate)
                   for i in range(3) for k in range(3))
        rows.append(dt(B.diff(kinetic, rate)) - B.diff(kinetic, q) + B.diff(potential, q) - gen)
    weight = [0, 0, -m * g]
    for k in range(3):
        rows.append(m * a_c[k] - force[k] - weight[k]
                    - sum(normal[i] * (normals[i][k] + fr * t[i][k]) for i in range(3)))
    u = [gdd, pdd] + normal
    a = [[B.diff(row, uk) for uk in u] for row in rows]
    bvec = [-B.at_zero(row, u) for row in rows]
    return {"x": x, "p": p, "loads": loads, "t": t_flat, "A": a, "b": bvec, "v": v}


def gamma0(dh, dp):
    """gamma0 = arccos(d/D) as pegdyn computes it (PegParams::gamma0)."""
    return 2.0 * math.asin(math.sqrt((dh - dp) / (2.0 * dh)))
