"""pegdyn's robot insertion (``insert_rcc`` scenes) in MuJoCo (optional peer).

Not run by CI. Needs ``pip install mujoco`` (measured with 4.0.0), Python
>= 3.11 (tomllib) and pegdyn's release binary (``cargo build --release``).

The same peg, hole, wrist, robot motion, friction and outcome rules as
pegdyn's ``insert_rcc`` (``docs/insertion.md``), every number read from the
scene's TOML (``mujoco_insertion_model.py``):

* Geometry: the peg's side is a cylinder of radius r above the rim fillet,
  its rim fillet a ring of capsules of radius rho_p (the torus); the mouth
  round a ring of capsules of radius rho_h (the torus about the circle of
  radius R + rho_h at depth rho_h); the bore a ring of thin boxes whose
  faces touch the bore radius R, the top face a ring of boxes outside the
  round, the bottom a disc. Capsule rings circumscribe their circle and box
  faces touch theirs at segment midpoints, the first at azimuth 0 (the
  scene's lateral error and tilt lie in the x-z plane, where the contacts
  are). Only pegdyn's five pairs collide: side with round (edge_side), rim
  with round, wall, top face and bottom. Friction mu on every geom,
  condim 3.
* Wrist and robot: a heavy body (1e9 kg, gravity compensated) on three
  world slides, its position and velocity reset to the robot's descent
  ``z(t) = max(z0 - v t, z_end)`` every 0.1 ms; the peg on three slides
  along the robot's axes and a ball joint at the compliance centre, with the
  wrist's stiffnesses and dampers as joint springs and dampers. Start: the
  wrist undeflected but for the static sag m g / K_z.
* Outcomes (``src/compliant_peg_3d/outcome.rs``), checked every 0.1 ms of
  simulated time (pegdyn samples every 1 ms and locates events): seated
  when the tip's depth reaches ``criteria.seat_depth`` (time interpolated
  between checks); wrist force limit ``|F_w| >= criteria.wrist_force_limit``
  (spring + damper forces of the three slides); contact force limit;
  missed (rim on the top face with the tip outside the bore). A force-limit
  stop, or the end of ``integrator.t_end`` without motion, with the tip
  below the round and two or more contact points is jammed or wedged by
  pegdyn's release test: wrist springs and dampers removed, robot stopped,
  ``criteria.release_time`` simulated; wedged when two or more points keep
  half of the total normal force. A contact point is a cluster of MuJoCo
  contacts of one pair within 0.5 mm (neighbouring segments share a point);
  its force is their sum.

Usage::

    python3 benches/peers/mujoco_insertion.py            # both settings, five scenes (~10 min)
    python3 benches/peers/mujoco_insertion.py --quick    # insert_rcc, both settings (< 2 min)
    python3 benches/peers/mujoco_insertion.py --variations   # also lateral errors 0.1 and 0.6 mm
    python3 benches/peers/mujoco_insertion.py --converge scenes/insert_rcc.toml   # the ladder

Prints, per scene and setting, outcome, seat (end) time, peak contact force,
peak wrist force and CPU s per simulated second beside pegdyn's
(``target/release/pegdyn run <scene> --out <tmp> --no-replay``, its summary).
"""

import argparse
import math
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

try:
    import tomllib
except ImportError:  # Python < 3.11
    tomllib = None

try:
    import mujoco
except ImportError:
    sys.exit("mujoco_insertion.py needs MuJoCo's Python bindings: pip install mujoco (measured with 4.0.0)")

import numpy as np

from mujoco_insertion_model import SETTINGS, Scene, model_xml

REPO = Path(__file__).resolve().parents[2]
SCENES = ["insert_rcc"] + [f"industreal_round_{k}mm" for k in (4, 8, 12, 16)]
CHECK = 1e-4  # s between outcome checks
CLUSTER = 5e-4  # m: contacts of one pair closer than this are one point
PAIRS = {("side", "mouth"): "edge_side", ("rim", "mouth"): "rim_edge", ("rim", "wall"): "rim_wall",
         ("rim", "top"): "rim_top", ("rim", "bottom"): "rim_bottom"}


class Peer:
    """One compiled model of a scene under one setting, and its run."""

    def __init__(self, sc, setting):
        self.sc, self.setting = sc, setting
        self.model = mujoco.MjModel.from_xml_string(model_xml(sc, setting))
        self.data = mujoco.MjData(self.model)
        m = self.model
        self.kind = {}
        for gid in range(m.ngeom):
            name = m.geom(gid).name
            self.kind[gid] = re.sub(r"\d+$", "", name)
        self.robot_dofs = [m.jnt_dofadr[m.joint(n).id] for n in ("rx", "ry", "rz")]
        self.robot_qpos = [m.jnt_qposadr[m.joint(n).id] for n in ("rx", "ry", "rz")]
        self.wrist_dofs = [m.jnt_dofadr[m.joint(n).id] for n in ("dx", "dy", "dz")]
        self.wrist_qpos = [m.jnt_qposadr[m.joint(n).id] for n in ("dx", "dy", "dz")]
        self.wrist_joints = [m.joint(n).id for n in ("dx", "dy", "dz", "rot")]
        ball = m.joint("rot").id
        self.ball_dofs = list(range(m.jnt_dofadr[ball], m.jnt_dofadr[ball] + 3))
        self.peg = m.body("peg").id
        self.h = float(m.opt.timestep)
        self.n_sub = max(1, round(CHECK / self.h))
        self._f = np.zeros(6)

    # -- state -----------------------------------------------------------
    def drive(self, t):
        pos, vel = self.sc.robot_position(t)
        d = self.data
        for k in range(3):
            d.qpos[self.robot_qpos[k]] = pos[k]
            d.qvel[self.robot_dofs[k]] = vel[k]

    def reset(self):
        m, d = self.model, self.data
        mujoco.mj_resetData(m, d)
        for a, s in zip(self.wrist_qpos, self.sc.sag()):
            d.qpos[a] = s
        self.drive(0.0)
        mujoco.mj_forward(m, d)

    def tip(self):
        """Tip (centre of the bottom face) in the hole frame."""
        d = self.data
        rot = d.xmat[self.peg].reshape(3, 3)
        return d.xpos[self.peg] + rot[:, 2] * (-self.sc.lc)

    def wrist_force(self):
        d = self.data
        f = [d.qfrc_spring[i] + d.qfrc_damper[i] for i in self.wrist_dofs]
        return math.sqrt(sum(v * v for v in f))

    def points(self):
        """Contact points: {pair: [(force N, position)]}, MuJoCo contacts of
        one pair within CLUSTER merged (forces summed)."""
        m, d = self.model, self.data
        out = {}
        for i in range(d.ncon):
            c = d.contact[i]
            k1, k2 = self.kind[c.geom1], self.kind[c.geom2]
            pair = PAIRS.get((k1, k2)) or PAIRS.get((k2, k1))
            if pair is None:
                continue
            mujoco.mj_contactForce(m, d, i, self._f)
            fn = float(self._f[0])
            if fn <= 0:
                continue
            pts = out.setdefault(pair, [])
            pos = np.array(c.pos)
            for p in pts:
                if np.linalg.norm(p[1] - pos) < CLUSTER:
                    p[0] += fn
                    break
            else:
                pts.append([fn, pos])
        return out

    # -- run -------------------------------------------------------------
    def release(self):
        """pegdyn's release test: (held, points after, force before, after)."""
        m, d = self.model, self.data
        before = sum(f for pts in self.points().values() for f, _ in pts)
        saved = (m.jnt_stiffness.copy(), m.dof_damping.copy())
        for j in self.wrist_joints:
            m.jnt_stiffness[j] = 0.0
        for i in self.wrist_dofs + self.ball_dofs:
            m.dof_damping[i] = 0.0
        for i in self.robot_dofs:
            d.qvel[i] = 0.0
        n = max(1, round(self.sc.release_time / self.h))
        for _ in range(0, n, self.n_sub):
            for i in self.robot_dofs:
                d.qvel[i] = 0.0
            mujoco.mj_step(m, d, nstep=min(self.n_sub, n))
        mujoco.mj_forward(m, d)
        pts = self.points()
        after = sum(f for p in pts.values() for f, _ in p)
        npts = sum(len(p) for p in pts.values())
        m.jnt_stiffness[:], m.dof_damping[:] = saved
        return npts >= 2 and after >= 0.5 * before, npts, before, after

    def stuck(self, pts, limit):
        names = " + ".join(f"{k} x{len(v)}" if len(v) > 1 else k for k, v in sorted(pts.items()))
        held, *_ = self.release()
        cls = "wedged" if held else "jammed"
        return f"{cls} ({names}{'; ' + limit if limit else ''})"

    def run(self, timeout):
        """One insertion: dict of outcome, end time, peaks, CPU s."""
        sc, m, d = self.sc, self.model, self.data
        c0 = time.process_time()
        self.reset()
        t_prev, depth_prev = 0.0, -self.tip()[2]
        peak_c, peak_w = 0.0, self.wrist_force()
        n_max = round(sc.t_end / self.h)
        steps, outcome, t_end = 0, None, None
        while steps < n_max:
            if time.process_time() - c0 > timeout:
                outcome, t_end = "timeout", d.time
                break
            self.drive(d.time)
            n = min(self.n_sub, n_max - steps)
            mujoco.mj_step(m, d, nstep=n)
            steps += n
            mujoco.mj_rnePostConstraint(m, d)
            tip = self.tip()
            depth = -tip[2]
            if not (math.isfinite(depth) and np.all(np.isfinite(d.qvel))):
                outcome, t_end = "failed (non-finite state)", d.time
                break
            pts = self.points()
            fc = max((f for p in pts.values() for f, _ in p), default=0.0)
            fw = self.wrist_force()
            npts = sum(len(p) for p in pts.values())
            inside = depth > sc.rho_h
            if depth >= sc.seat:
                s = (sc.seat - depth_prev) / (depth - depth_prev)
                outcome, t_end = "seated", t_prev + s * (d.time - t_prev)
                peak_c, peak_w = max(peak_c, fc), max(peak_w, fw)
                break
            if fw >= sc.wrist_limit or fc >= sc.contact_limit:
                which = "wrist" if fw >= sc.wrist_limit else "contact"
                peak_c, peak_w = max(peak_c, fc), max(peak_w, fw)
                t_end = d.time
                if inside and npts >= 2:
                    outcome = self.stuck(pts, f"{which} force limit")
                else:
                    outcome = f"force limit ({which})"
                break
            if "rim_top" in pts and math.hypot(tip[0], tip[1]) > sc.R:
                outcome, t_end = "missed", d.time
                break
            peak_c, peak_w = max(peak_c, fc), max(peak_w, fw)
            t_prev, depth_prev = d.time, depth
        if outcome is None:
            t_end = d.time
            pts = self.points()
            npts = sum(len(p) for p in pts.values())
            speed = np.linalg.norm(d.cvel[self.peg][3:])
            if -self.tip()[2] > sc.rho_h and npts >= 2 and speed < 1e-4:
                outcome = self.stuck(pts, "")
            else:
                outcome = "stopped (end of span)"
        cpu = time.process_time() - c0
        return {"outcome": outcome, "t": t_end, "peak_contact": peak_c, "peak_wrist": peak_w,
                "cpu_per_s": cpu / max(d.time, 1e-12), "depth": -self.tip()[2]}


# -- pegdyn's side ----------------------------------------------------------
def pegdyn_run(binary, scene_path):
    """Runs pegdyn on the scene; its outcome, end time, peaks, CPU s per simulated s."""
    with tempfile.TemporaryDirectory() as out:
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        p = subprocess.run([str(binary), "run", str(scene_path), "--out", out, "--no-replay"],
                           capture_output=True, text=True, timeout=900)
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    text = p.stdout + p.stderr
    if p.returncode != 0:
        return {"outcome": f"pegdyn failed ({p.returncode})", "t": math.nan, "peak_contact": math.nan,
                "peak_wrist": math.nan, "cpu_per_s": math.nan, "text": text}

    def num(label):
        m = re.search(rf"^\s*{re.escape(label)}\s*=\s*([-+0-9.eE]+)", text, re.M)
        return float(m.group(1)) if m else math.nan

    m = re.search(r"^\s*outcome\s*=\s*(.+?)\s*\(code", text, re.M)
    t = num("end time")
    return {"outcome": m.group(1) if m else "?", "t": t, "peak_contact": num("peak contact normal force"),
            "peak_wrist": num("peak wrist force"), "cpu_per_s": cpu / t if t > 0 else math.nan, "text": text}


def load(path):
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as e:
        sys.exit(f"{path}: {e}")


def variant(path, lateral_error):
    """The scene text with robot.lateral_error replaced, written to a temp file."""
    text = Path(path).read_text()
    new, n = re.subn(r"^(lateral_error\s*=\s*)[-+0-9.eE]+", rf"\g<1>{lateral_error!r}", text, flags=re.M)
    if n != 1:
        sys.exit(f"{path}: robot.lateral_error not found once")
    fd, name = tempfile.mkstemp(suffix=".toml", prefix=Path(path).stem + "_e")
    with os.fdopen(fd, "w") as f:
        f.write(new)
    return name


def short(outcome):
    return outcome.split(" (")[0]


def row(label, src, r):
    return (f"| {label} | {src} | {r['outcome']} | {r['t']:.4f} | {r['peak_contact']:.1f} | "
            f"{r['peak_wrist']:.2f} | {r['cpu_per_s']:.3g} |")


def converge(path, timeout):
    """The ladder from the defaults' segments at a 1e-4 s step and 2e-4 s time
    constant: halve step and time constant, double segments, one at a time,
    until the outcome holds and the seat time moves < 1e-4 s."""
    sc = Scene(load(path), Path(path).stem)
    base = {"step": 1e-4, "timeconst": 2e-4, "segments": 32, "cone": "elliptic", "impratio": 10.0}
    print(f"MuJoCo {mujoco.__version__}: convergence ladder on {path}")
    print("| step s | time const s | segments | cone | impratio | outcome | end time s | peak contact N | "
          "peak wrist N | CPU s / sim s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    prev = None
    s = dict(base)
    for _ in range(8):
        r = Peer(sc, s).run(timeout)
        print(f"| {s['step']:g} | {s['timeconst']:g} | {s['segments']} | {s['cone']} | {s['impratio']:g} | "
              f"{r['outcome']} | {r['t']:.5f} | {r['peak_contact']:.1f} | {r['peak_wrist']:.2f} | "
              f"{r['cpu_per_s']:.3g} |", flush=True)
        if prev and short(prev["outcome"]) == short(r["outcome"]) and abs(prev["t"] - r["t"]) < 1e-4:
            print(f"converged: {prev_s}")
            return
        prev, prev_s = r, dict(s)
        s = {**s, "step": s["step"] / 2, "timeconst": s["timeconst"] / 2, "segments": s["segments"] * 2}
    print("not converged within the ladder")


def main():
    ap = argparse.ArgumentParser(description="pegdyn's insert_rcc scenes in MuJoCo beside pegdyn.")
    ap.add_argument("--quick", action="store_true", help="insert_rcc only (< 2 min)")
    ap.add_argument("--variations", action="store_true",
                    help="also insert_rcc with lateral errors of 0.1 and 0.6 mm")
    ap.add_argument("--scenes", help="comma-separated scene files instead of the shipped five")
    ap.add_argument("--settings", default="defaults,converged", help="comma-separated settings")
    ap.add_argument("--pegdyn", default=str(REPO / "target" / "release" / "pegdyn"), help="pegdyn binary")
    ap.add_argument("--no-pegdyn", action="store_true", help="MuJoCo only")
    ap.add_argument("--timeout", type=float, default=120.0, help="CPU s per MuJoCo run (default 120)")
    ap.add_argument("--converge", metavar="SCENE", help="print the convergence ladder on SCENE")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="override a setting's step, timeconst, segments, cone or impratio")
    args = ap.parse_args()
    if tomllib is None:
        sys.exit("mujoco_insertion.py needs Python >= 3.11 (tomllib)")
    if args.converge:
        converge(args.converge, args.timeout)
        return
    if args.scenes:
        paths = args.scenes.split(",")
    else:
        paths = [str(REPO / "scenes" / f"{n}.toml") for n in (SCENES[:1] if args.quick else SCENES)]
    labels = [Path(p).stem for p in paths]
    if args.variations:
        base = str(REPO / "scenes" / "insert_rcc.toml")
        for e in (1e-4, 6e-4):
            paths.append(variant(base, e))
            labels.append(f"insert_rcc, e = {e * 1e3:g} mm")
    settings = args.settings.split(",")
    for s in settings:
        if s not in SETTINGS:
            sys.exit(f"--settings: {s!r} is not one of {sorted(SETTINGS)}")
    over = {}
    for item in args.set:
        k, sep, v = item.partition("=")
        if not sep or k not in SETTINGS["defaults"]:
            sys.exit(f"--set {item!r}: expected KEY=VALUE with KEY one of {sorted(SETTINGS['defaults'])}")
        over[k] = v if k == "cone" else float(v)
    binary = Path(args.pegdyn)
    if not args.no_pegdyn and not binary.exists():
        sys.exit(f"{binary}: not found (cargo build --release, or --no-pegdyn)")
    print(f"MuJoCo {mujoco.__version__}; settings: " +
          "; ".join(f"{s} {{{', '.join(f'{k}: {v}' for k, v in {**SETTINGS[s], **over}.items())}}}"
                    for s in settings))
    print(f"load: {os.getloadavg()[0]:.2f} (1-min average) at the start")
    print("| scene | run | outcome | end (seat) time s | peak contact N | peak wrist N | CPU s / sim s |")
    print("|---|---|---|---|---|---|---|")
    for path, label in zip(paths, labels):
        sc = Scene(load(path), label)
        if not args.no_pegdyn:
            print(row(label, "pegdyn", pegdyn_run(binary, path)), flush=True)
        for s in settings:
            r = Peer(sc, {**SETTINGS[s], **over}).run(args.timeout)
            print(row(label, f"MuJoCo {s}", r), flush=True)
    for path, label in zip(paths, labels):
        if label.startswith("insert_rcc, e"):
            os.unlink(path)


if __name__ == "__main__":
    main()
