"""The planar jamming sweep of scenes/jamming.toml in MuJoCo, defaults and tuned.

Optional peer (``pip install mujoco``; never run by CI). The same peg and
hole as pegdyn's sweep: steel peg r = 12.5 mm, clearance ratio c = 0.01
(hole D = 2r/(1-c)), length 0.1 m, 0.2 mm fillets on the hole edges, friction
mu = 0.3, no gravity, F_z = 20 N, a 13 x 13 grid of Whitney-frame load ratios
(F_x/F_z in [-4.5, 4.5], M/(r F_z) in [-6, 6]), load constant in the peg
frame and applied at the peg tip, each run from the two-point lean at tilt
0.0261 rad (pegdyn's start state for depth 10 mm) for at most 0.3 s.
Classification as in pegdyn: inserted when the tip advances 1 mm, stuck when
it advances less than 2 um in a 50 ms window; a grid point is stuck when the
run from either lean sticks (the other lean under q is this lean under -q).

Usage:
    python benches/peers/mujoco_jamming.py [--pegdyn out/jamming_sweep.csv] [--n 13]

Prints, per setting, the classes' agreement with pegdyn's sweep CSV (when
given) and the wall time per simulated second of one thread.
"""

import argparse
import csv
import math
import time

import mujoco
import numpy as np

R = 0.0125
C = 0.01
D = 2 * R / (1 - C)
L = 0.1
RHO = 7850.0
MU = 0.3
FZ = 20.0
FILLET = 0.0002
THETA = 0.0261  # start tilt, rad
DEPTH = 0.01039  # Whitney depth of the start: tip face to edge contact, m
T_MAX, WINDOW, ADVANCE, STALL = 0.3, 0.05, 0.001, 2e-6

MASS = RHO * math.pi * R * R * L
INERTIA = MASS * (3 * R * R + L * L) / 12


def model_xml(setting):
    """The planar peg (slide x, slide z, hinge y) and the hole's two walls."""
    opt, geom_extra = "", ""
    if setting == "tuned":
        opt = '<option timestep="1e-5" cone="elliptic" impratio="10" noslip_iterations="50" gravity="0 0 0"/>'
        geom_extra = 'solref="4e-4 1" solimp="0.99 0.999 1e-5 0.5 2"'
    else:
        opt = '<option gravity="0 0 0"/>'
    half_wall = 0.02
    return f"""
<mujoco>
  {opt}
  <worldbody>
    <geom type="box" size="{half_wall} 0.02 0.05" pos="{-D / 2 - half_wall} 0 -0.05" friction="{MU} 0 0" {geom_extra}/>
    <geom type="box" size="{half_wall} 0.02 0.05" pos="{D / 2 + half_wall} 0 -0.05" friction="{MU} 0 0" {geom_extra}/>
    <geom type="cylinder" size="{FILLET} 0.02" pos="{-D / 2 - FILLET} 0 {-FILLET}" euler="90 0 0" friction="{MU} 0 0" {geom_extra}/>
    <geom type="cylinder" size="{FILLET} 0.02" pos="{D / 2 + FILLET} 0 {-FILLET}" euler="90 0 0" friction="{MU} 0 0" {geom_extra}/>
    <body name="peg" pos="0 0 0">
      <joint name="x" type="slide" axis="1 0 0"/>
      <joint name="z" type="slide" axis="0 0 1"/>
      <joint name="th" type="hinge" axis="0 1 0"/>
      <inertial pos="0 0 0" mass="{MASS}" diaginertia="{INERTIA} {INERTIA} {INERTIA}"/>
      <geom type="box" size="{R} 0.01 {L / 2}" friction="{MU} 0 0" {geom_extra}/>
    </body>
  </worldbody>
</mujoco>"""


def start_state(data):
    """Centre of mass such that the lean touches the left edge and right wall."""
    s, c = math.sin(THETA), math.cos(THETA)
    # tip (bottom-face centre) at depth DEPTH*cos below the edge, leaning right:
    # right wall contact: bottom-right corner at x = D/2.
    corner_local = np.array([R, -L / 2])
    rot = np.array([[c, s], [-s, c]])  # hinge about +y: x' = c x + s z
    com_x = D / 2 - (rot @ corner_local)[0]
    tip_world_z = -DEPTH * c
    com_z = tip_world_z - (rot @ np.array([0.0, -L / 2]))[1]
    data.qpos[:] = [com_x, com_z, THETA]
    data.qvel[:] = 0


def run(model, q):
    data = mujoco.MjData(model)
    start_state(data)
    mujoco.mj_forward(model, data)
    peg = model.body("peg").id
    fx, fz, m_tip = q[0] * FZ, FZ, q[1] * R * FZ

    def tip_depth():
        th = data.qpos[2]
        return -(data.qpos[1] - L / 2 * math.cos(th))

    d_start = tip_depth()
    d_window, t_window = d_start, 0.0
    while data.time < T_MAX:
        th = data.qpos[2]
        s, c = math.sin(th), math.cos(th)
        # load constant in the peg frame: axial push fz along -peg axis, fx across
        f_world = np.array([fx * c - fz * s, 0.0, -fx * s - fz * c])
        tip_offset = np.array([-(L / 2) * s, 0.0, -(L / 2) * c])
        torque = np.cross(tip_offset, f_world) + np.array([0.0, m_tip, 0.0])
        data.xfrc_applied[peg, :3] = f_world
        data.xfrc_applied[peg, 3:] = torque
        mujoco.mj_step(model, data)
        d = tip_depth()
        if d - d_start >= ADVANCE:
            return "inserted", data.time
        if data.time - t_window >= WINDOW:
            if d - d_window < STALL:
                return "stuck", data.time
            d_window, t_window = d, data.time
    return "other", data.time


def combine(a, b):
    if "stuck" in (a, b):
        return "stuck"
    return "inserted" if (a, b) == ("inserted", "inserted") else "other"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pegdyn", help="pegdyn's out/jamming_sweep.csv")
    ap.add_argument("--n", type=int, default=13)
    ap.add_argument("--settings", default="defaults,tuned")
    args = ap.parse_args()
    n = args.n
    xs = np.linspace(-4.5, 4.5, n)
    ys = np.linspace(-6.0, 6.0, n)
    ref = None
    if args.pegdyn:
        with open(args.pegdyn) as f:
            ref = [("stuck" if r["class"] in ("jammed", "wedged") else r["class"]) for r in csv.DictReader(f)]
    for setting in args.settings.split(","):
        model = mujoco.MjModel.from_xml_string(model_xml(setting))
        raw, sim, wall = [], 0.0, 0.0
        for j in range(n):
            for i in range(n):
                t0 = time.perf_counter()
                cls, t_sim = run(model, (xs[i], ys[j]))
                wall += time.perf_counter() - t0
                sim += t_sim
                raw.append(cls)
        classes = [combine(raw[k], raw[(n - 1 - k // n) * n + (n - 1 - k % n)]) for k in range(n * n)]
        agree = sum(a == b for a, b in zip(classes, ref)) if ref and len(ref) == len(classes) else None
        counts = {c: classes.count(c) for c in ("inserted", "stuck", "other")}
        print(f"{setting}: classes {counts}, agreement with pegdyn {agree}/{n * n}, wall {wall:.2f} s for {sim:.2f} simulated s: {wall / sim:.4f} s per simulated s")


if __name__ == "__main__":
    main()
