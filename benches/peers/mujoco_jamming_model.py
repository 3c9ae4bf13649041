"""The planar peg and hole of pegdyn's jamming sweep as a MuJoCo model (MJCF
text) and the sweep's parameters, for ``mujoco_jamming.py``.

Geometry and coordinates: ``docs/bench-methods.md``, "Peers" (MuJoCo).
"""

import math
import sys

# Fillet radii of the peg's bottom edge and the hole's top edge (m): the
# compliant planar peg's defaults (src/compliant_peg/geometry.rs,
# DEFAULT_FILLET), which the jamming sweep uses.
PEG_FILLET = 0.2e-3
HOLE_FILLET = 0.2e-3
DENSITY = 7850.0  # steel, kg/m^3
STALL = 2e-6  # advance per window below which a run is stuck, m
SETTLE_FORCE_RTOL = 1e-2
THICKNESS = 0.005  # half-thickness of the peg out of the plane, m

# Solver settings. "defaults" changes only what the problem fixes (no gravity,
# the friction coefficient): MuJoCo's 2 ms step, pyramidal cone, solref
# (0.02, 1), solimp (0.9, 0.95, 0.001, 0.5, 2). "tuned" is the cheapest
# setting found whose classes converge (docs/bench/peers-mujoco.md):
# elliptic friction cone, impratio 100 (friction that holds without creep),
# contact time constant 0.4 ms, step 80 us (halving it leaves every run's
# class unchanged); every other option at MuJoCo's default.
SETTINGS = {
    "defaults": {"option": {}, "geom": {}, "step": 2e-3},
    "tuned": {
        "option": {"cone": "elliptic", "impratio": "100"},
        "geom": {"solref": "4e-4 1"},
        "step": 8e-5,
    },
}


class Sweep:
    """The sweep's parameters (SI units) from the scene's [sweep] table."""

    def __init__(self, table):
        self.r = float(table["r_m"])
        self.c = float(table["c"])
        self.mu = float(table["mu"])
        self.depth = float(table["l_m"])
        self.fz = float(table["fz_n"])
        self.length = float(table["peg_length_m"])
        self.fx_max = float(table["fx_over_fz_max"])
        self.m_max = float(table["m_over_rfz_max"])
        self.n = int(table["n"])
        self.t_max = float(table["t_max_s"])
        self.advance = float(table["advance_m"])
        self.window = float(table["window_s"])
        self.big_d = 2 * self.r / (1 - self.c)
        self.mass = DENSITY * math.pi * self.r**2 * self.length
        self.inertia = self.mass * (3 * self.r**2 + self.length**2) / 12
        self.lc = 0.5 * self.length  # centre of mass above the bottom face
        self.theta = self.two_point_tilt()

    def two_point_tilt(self):
        """Exact tilt of two-point contact at depth l, sharp corners:
        l sin(theta) + d cos(theta) = D (src/jamming/geometry.rs)."""
        d, big_d, l = 2 * self.r, self.big_d, self.depth
        rho = math.hypot(l, d)
        if rho < big_d:
            sys.exit(f"sweep.l_m = {l}: two-point contact is impossible at this depth")
        s = math.sqrt((rho - big_d) * (rho + big_d))
        return math.atan2(l, d) - math.atan2(s, big_d)

    def start(self):
        """(x, z, theta) of the two-point lean with zero penetration: the
        right bottom fillet on the right wall, the left side on the left
        edge fillet (PegState::two_point)."""
        r, rp, rh, half_d, lc = self.r, PEG_FILLET, HOLE_FILLET, self.big_d / 2, self.lc
        s, c = math.sin(self.theta), math.cos(self.theta)
        x = half_d - rp - (lc - rp) * s - (r - rp) * c
        z = rh + (-rh - r + (half_d + rh + x) * c) / s
        return x, z, self.theta

    def depth_of(self, x, z, theta):
        """Depth of the bottom face's centre, m."""
        return z + self.lc * math.cos(theta)

    def peg_frame_load(self, q):
        """Grid ratio q = (F_x/F_z, M/(r F_z)) as (f1 axial, f2 radial, M_C)
        in the peg frame at the start tilt (to_paper_frame)."""
        fx, fz, m = q[0] * self.fz, self.fz, q[1] * self.r * self.fz
        s, c = math.sin(self.theta), math.cos(self.theta)
        x, y = -fx, fz
        return x * s + y * c, x * c - y * s, m - self.lc * (fz * s + fx * c)

    def grid(self):
        """Grid ratios, x fastest (pegdyn's order)."""
        n = self.n
        xs = [-self.fx_max + 2 * self.fx_max * i / (n - 1) for i in range(n)]
        ys = [-self.m_max + 2 * self.m_max * j / (n - 1) for j in range(n)]
        return [(xs[i], ys[j]) for j in range(n) for i in range(n)]

    def contact_line_in_cones(self, x, z, theta):
        """Whether the segment between the two contact points lies inside
        both friction cones (src/compliant_peg/simulate.rs)."""
        if theta < 0:
            x, theta = -x, -theta
        s, c = math.sin(theta), math.cos(theta)
        half_d, rh, rp = self.big_d / 2, HOLE_FILLET, PEG_FILLET
        ax, az = -(half_d + rh) + rh * c, rh - rh * s
        bz = z + (self.lc - rp) * c - (self.r - rp) * s
        dx, dz = half_d - ax, bz - az
        length = math.hypot(dx, dz)
        cone = math.atan(self.mu)
        angle_a = math.acos(max(-1.0, min(1.0, (dx * c - dz * s) / length)))
        angle_b = math.acos(max(-1.0, min(1.0, dx / length)))
        return angle_a <= cone and angle_b <= cone


def attrs(d):
    return " ".join(f'{k}="{v}"' for k, v in d.items())


def model_xml(sw, option, geom, step, wall=0.02):
    """MJCF of the planar peg and the hole. World frame: x across the hole,
    z up (pegdyn's z points into the hole: the z slide's axis is -z), hole
    mouth at z = 0; the hinge axis is -y so that its angle is pegdyn's tilt
    (axis towards the tip (sin theta, cos theta) in pegdyn's frame). `wall`
    is the thickness (m) of the wall boxes beside the hole."""
    r, rp, rh, half_d, lc, mu = sw.r, PEG_FILLET, HOLE_FILLET, sw.big_d / 2, sw.lc, sw.mu
    ty = THICKNESS
    wy = 2 * ty  # hole geoms are longer out of plane than the peg
    wall_hw, wall_hh = 0.5 * wall, 0.05
    # contype/conaffinity: walls (1), edges (2); peg side box touches edges
    # only, the peg's bottom fillets touch both.
    g = f'friction="{mu} 0 0" {attrs(geom)}'
    opt = {"timestep": repr(step), "gravity": "0 0 0", **option}
    hole = []
    for side in (-1, 1):
        hole.append(
            f'<geom name="wall{side:+d}" type="box" size="{wall_hw} {wy} {wall_hh}" '
            f'pos="{side * (half_d + wall_hw)} 0 {-rh - wall_hh}" contype="0" conaffinity="1" {g}/>'
        )
        ex = side * (half_d + rh)
        hole.append(
            f'<geom name="edge{side:+d}" type="capsule" size="{rh}" '
            f'fromto="{ex} {-wy} {-rh} {ex} {wy} {-rh}" contype="0" conaffinity="2" {g}/>'
        )
    fillets = []
    for side in (-1, 1):
        fx = side * (r - rp)
        fillets.append(
            f'<geom name="fillet{side:+d}" type="capsule" size="{rp}" '
            f'fromto="{fx} {-ty} {-lc + rp} {fx} {ty} {-lc + rp}" contype="3" conaffinity="0" {g}/>'
        )
    side_half = 0.5 * (sw.length - rp)
    nl = "\n      "
    return f"""
<mujoco model="planar peg in hole">
  <option {attrs(opt)}/>
  <worldbody>
    {nl.join(hole)}
    <body name="peg">
      <joint name="x" type="slide" axis="1 0 0"/>
      <joint name="z" type="slide" axis="0 0 -1"/>
      <joint name="theta" type="hinge" axis="0 -1 0"/>
      <inertial pos="0 0 0" mass="{sw.mass!r}" diaginertia="{sw.inertia!r} {sw.inertia!r} {sw.inertia!r}"/>
      <geom name="side" type="box" size="{r} {ty} {side_half}" pos="0 0 {rp / 2}" contype="2" conaffinity="0" {g}/>
      {nl.join(fillets)}
      <site name="com" pos="0 0 0"/>
    </body>
  </worldbody>
  <actuator>
    <general name="radial" site="com" gear="1 0 0 0 0 0"/>
    <general name="axial" site="com" gear="0 0 -1 0 0 0"/>
    <general name="moment" site="com" gear="0 0 0 0 -1 0"/>
  </actuator>
</mujoco>"""
