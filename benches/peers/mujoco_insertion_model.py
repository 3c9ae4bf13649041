"""The robot insertion of pegdyn's ``insert_rcc`` scenes (the compliant 3-D
peg held through a remote-centre-compliance wrist) as a MuJoCo model (MJCF
text), and the scene's parameters read from its TOML, for
``mujoco_insertion.py``.

Frames: the hole frame of ``docs/insertion.md`` (z up, top face at z = 0,
bore along -z). The robot is a heavy body on three world-axis slides whose
position and velocity are imposed every sub-step; the peg hangs from it on
the wrist: three slides along the robot's axes and a ball joint at the
compliance centre, with the scene's stiffnesses and dampers as joint
springs and dampers (``K d`` along the slides, ``K_theta`` times the ball's
rotation vector: ``2 K u^2 = K theta^2 / 2 + O(theta^4)`` of pegdyn's
quaternion spring for small deflections).
"""

import math
import sys

ROBOT_MASS = 1e9  # kg: 100 N moves it 5e-16 m over a 0.1 ms check interval
GRAVITY = 9.81  # m/s^2: pegdyn's default [peg] gravity

# Solver settings. "defaults": MuJoCo's own (2 ms step, pyramidal cone,
# solref (0.02, 1), solimp (0.9, 0.95, 0.001, 0.5, 2), impratio 1, Euler)
# with 32 segments per ring. "converged": on insert_rcc, the outcome and
# seat time change by 2e-5 s when the step and the contact time constant
# are halved and the segments doubled (elliptic cone, impratio 10, the time
# constant five steps; docs/bench/peers-mujoco.md, "The 3-D
# insertion", has the ladder).
SETTINGS = {
    "defaults": {"step": 2e-3, "timeconst": None, "segments": 32, "cone": "pyramidal", "impratio": 1.0},
    "converged": {"step": 2.5e-5, "timeconst": 1.25e-4, "segments": 128, "cone": "elliptic", "impratio": 10.0},
}


def _get(table, key, where, default=None):
    if key in table:
        v = table[key]
    elif default is not None:
        v = default
    else:
        sys.exit(f"{where}.{key}: missing")
    try:
        v = float(v)
    except (TypeError, ValueError):
        sys.exit(f"{where}.{key} = {v!r}: expected a number")
    if not math.isfinite(v):
        sys.exit(f"{where}.{key} = {v!r}: expected a finite number")
    return v


class Scene:
    """The insertion's parameters (SI units) from an ``insert_rcc`` scene."""

    def __init__(self, doc, name):
        if doc.get("kind") != "insert_rcc":
            sys.exit(f"{name}: kind = {doc.get('kind')!r}, expected \"insert_rcc\"")
        self.name = name
        p, w, r, c = (doc.get(k, {}) for k in ("peg", "wrist", "robot", "criteria"))
        self.big_d = _get(p, "hole_diameter", "peg")
        self.clearance = _get(p, "clearance_ratio", "peg")
        self.d = self.big_d * (1 - self.clearance)
        self.r, self.R = self.d / 2, self.big_d / 2
        self.length = _get(p, "length", "peg")
        self.rho_p = _get(p, "rim_fillet", "peg")
        self.rho_h = _get(p, "mouth_fillet", "peg")
        self.bore_depth = _get(p, "bore_depth", "peg")
        self.density = _get(p, "density", "peg")
        self.gravity = _get(p, "gravity", "peg", GRAVITY)
        self.mu = _get(p, "friction", "peg")
        self.mass = self.density * math.pi * self.r**2 * self.length
        self.j_t = self.mass * (3 * self.r**2 + self.length**2) / 12
        self.j_a = 0.5 * self.mass * self.r**2

        self.lc = _get(w, "centre_height", "wrist")
        self.kx = _get(w, "lateral_stiffness", "wrist")
        self.ky = _get(w, "lateral_stiffness_y", "wrist", self.kx)
        self.kz = _get(w, "axial_stiffness", "wrist")
        self.k_theta = _get(w, "angular_stiffness", "wrist")
        self.k_phi = _get(w, "torsional_stiffness", "wrist")
        self.c_lat = _get(w, "lateral_damping", "wrist")
        self.c_ax = _get(w, "axial_damping", "wrist")
        self.c_ang = _get(w, "angular_damping", "wrist")
        if abs(self.k_theta - self.k_phi) > 1e-12 * max(self.k_theta, self.k_phi):
            sys.exit(f"{name}: wrist.angular_stiffness = {self.k_theta} differs from wrist.torsional_stiffness = "
                     f"{self.k_phi}; the peer's ball joint has one stiffness")

        for key in ("axial_force",):
            if key in r:
                sys.exit(f"{name}: robot.{key}: the peer imposes a speed-controlled descent only")
        for key in ("precession_rate", "spin_rate", "spiral_pitch"):
            if _get(r, key, "robot", 0.0) != 0.0:
                sys.exit(f"{name}: robot.{key} = {r[key]}: the peer's robot does not precess, spin or search")
        self.e = _get(r, "lateral_error", "robot")
        self.e_dir = math.radians(_get(r, "lateral_error_direction_deg", "robot", 0.0))
        self.tilt = math.radians(_get(r, "angular_error_deg", "robot"))
        self.azimuth = math.radians(_get(r, "tilt_direction_deg", "robot", 180.0))
        self.h0 = _get(r, "start_height", "robot")
        if self.h0 < 0:
            sys.exit(f"{name}: robot.start_height = {self.h0}: the peer starts above the mouth only")
        self.speed = _get(r, "speed", "robot")
        self.overtravel = _get(r, "overtravel", "robot", 1e-3)

        self.seat = _get(c, "seat_depth", "criteria")
        self.wrist_limit = _get(c, "wrist_force_limit", "criteria")
        self.contact_limit = _get(c, "contact_force_limit", "criteria")
        self.release_time = _get(c, "release_time", "criteria", 0.02)
        self.t_end = _get(doc.get("integrator", {}), "t_end", "integrator")

        # The robot frame (tables.rs, robot.rs): axis a, start c_R(0), end height.
        s, co = math.sin(self.tilt), math.cos(self.tilt)
        self.axis = (s * math.cos(self.azimuth), s * math.sin(self.azimuth), co)
        tip = (self.e * math.cos(self.e_dir), self.e * math.sin(self.e_dir), self.h0)
        self.c0 = tuple(t + a * self.lc for t, a in zip(tip, self.axis))
        self.z_end = -(self.seat + self.overtravel) + self.lc * co
        # R_z(psi) R_y(theta) R_z(-psi): a rotation by theta about R_z(psi) e_y.
        h = 0.5 * self.tilt
        self.quat = (math.cos(h), -math.sin(self.azimuth) * math.sin(h), math.cos(self.azimuth) * math.sin(h), 0.0)

    def robot_position(self, t):
        """Displacement of the robot frame from its start, and its velocity."""
        z = self.c0[2] - self.speed * t
        if z > self.z_end:
            return (0.0, 0.0, z - self.c0[2]), (0.0, 0.0, -self.speed)
        return (0.0, 0.0, self.z_end - self.c0[2]), (0.0, 0.0, 0.0)

    def sag(self):
        """The wrist's start deflection in the robot's axes: the static sag
        m g / K_z along -z of the hole (held_start)."""
        s = self.mass * self.gravity / self.kz
        # R_R^T (0, 0, -s): the third row of R_R^T is a; R_R^T e_z = (a . e1, a . e2, a . e3) of R_R's columns.
        w, x, y, z = self.quat
        col = (2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y))  # R_R^T e_z
        return tuple(-s * v for v in col)


def attrs(d):
    return " ".join(f'{k}="{v}"' for k, v in d.items())


def _ring_capsules(name, n, radius, z, size, extra, inscribed=False):
    """n capsules along a polygon about the circle of `radius` at height z:
    circumscribed (segment midpoints on the circle, at azimuths 2 pi k / n)
    or inscribed (vertices on the circle, at azimuths 2 pi k / n)."""
    out = []
    rv = radius if inscribed else radius / math.cos(math.pi / n)
    half = 0.0 if inscribed else 0.5
    for k in range(n):
        a0 = (k - half) * 2 * math.pi / n
        a1 = (k + 1 - half) * 2 * math.pi / n
        p0 = (rv * math.cos(a0), rv * math.sin(a0), z)
        p1 = (rv * math.cos(a1), rv * math.sin(a1), z)
        ft = " ".join(repr(v) for v in p0 + p1)
        out.append(f'<geom name="{name}{k}" type="capsule" size="{size!r}" fromto="{ft}" {extra}/>')
    return out


def _ring_boxes(name, n, inner, thick, z_top, z_bottom, extra):
    """n boxes whose inner faces are tangent to the circle of radius `inner`
    (face centres on it, the first at azimuth 0), radial thickness `thick`."""
    out = []
    half_w = (inner + thick) * math.tan(math.pi / n)
    hz = 0.5 * (z_top - z_bottom)
    for k in range(n):
        a = k * 2 * math.pi / n
        rc = inner + 0.5 * thick
        pos = f"{rc * math.cos(a)!r} {rc * math.sin(a)!r} {0.5 * (z_top + z_bottom)!r}"
        out.append(
            f'<geom name="{name}{k}" type="box" size="{0.5 * thick!r} {half_w!r} {hz!r}" pos="{pos}" '
            f'euler="0 0 {a!r}" {extra}/>'
        )
    return out


def model_xml(sc, setting):
    """MJCF of the scene `sc` under the setting dict (step, timeconst,
    segments, cone, impratio)."""
    n = int(setting["segments"])
    geom = {"friction": f"{sc.mu!r} 0.005 0.0001", "condim": "3"}
    if setting.get("timeconst"):
        geom["solref"] = f"{setting['timeconst']!r} 1"
    g = attrs(geom)
    opt = {"timestep": repr(setting["step"]), "gravity": f"0 0 {-sc.gravity!r}",
           "cone": setting["cone"], "impratio": repr(setting["impratio"])}
    # contype/conaffinity: the peg's side (1) meets the mouth round only;
    # the rim (3) meets the mouth round (1) and the wall, top face and
    # bottom (2): pegdyn's five pairs edge_side, rim_edge, rim_wall,
    # rim_top, rim_bottom.
    mouth = f'contype="0" conaffinity="1" {g}'
    flat = f'contype="0" conaffinity="2" {g}'
    R, rh = sc.R, sc.rho_h
    top_w = max(5e-3, 2 * sc.d)
    hole = []
    hole += _ring_capsules("mouth", n, R + rh, -rh, rh, mouth)
    hole += _ring_boxes("wall", n, R, rh, -rh, -sc.bore_depth, flat)
    hole += _ring_boxes("top", n, R + rh, top_w, 0.0, -rh, flat)
    hole.append(f'<geom name="bottom" type="cylinder" size="{R!r} {rh!r}" pos="0 0 {-sc.bore_depth - rh!r}" {flat}/>')
    # The peg in its body frame: origin at the compliance centre, z along
    # the axis; the tip lc below it.
    tip = -sc.lc
    rim = _ring_capsules("rim", n, sc.r - sc.rho_p, tip + sc.rho_p, sc.rho_p, f'contype="3" conaffinity="0" {g}',
                         inscribed=True)
    side = (f'<geom name="side" type="cylinder" fromto="0 0 {tip + sc.rho_p!r} 0 0 {tip + sc.length!r}" '
            f'size="{sc.r!r}" contype="1" conaffinity="0" {g}/>')
    ix, iy, iz = sc.c0
    w, x, y, z = sc.quat
    com = tip + 0.5 * sc.length
    nl = "\n        "
    big = ROBOT_MASS
    return f"""
<mujoco model="insert_rcc peer">
  <compiler angle="radian"/>
  <option {attrs(opt)}/>
  <worldbody>
    {nl.join(hole)}
    <body name="robot" pos="{ix!r} {iy!r} {iz!r}" gravcomp="1">
      <joint name="rx" type="slide" axis="1 0 0"/>
      <joint name="ry" type="slide" axis="0 1 0"/>
      <joint name="rz" type="slide" axis="0 0 1"/>
      <inertial pos="0 0 0" mass="{big!r}" diaginertia="{big!r} {big!r} {big!r}"/>
      <body name="peg" quat="{w!r} {x!r} {y!r} {z!r}">
        <joint name="dx" type="slide" axis="1 0 0" stiffness="{sc.kx!r}" damping="{sc.c_lat!r}"/>
        <joint name="dy" type="slide" axis="0 1 0" stiffness="{sc.ky!r}" damping="{sc.c_lat!r}"/>
        <joint name="dz" type="slide" axis="0 0 1" stiffness="{sc.kz!r}" damping="{sc.c_ax!r}"/>
        <joint name="rot" type="ball" pos="0 0 0" stiffness="{sc.k_theta!r}" damping="{sc.c_ang!r}"/>
        <inertial pos="0 0 {com!r}" mass="{sc.mass!r}" diaginertia="{sc.j_t!r} {sc.j_t!r} {sc.j_a!r}"/>
        {side}
        {nl.join(rim)}
      </body>
    </body>
  </worldbody>
</mujoco>"""
