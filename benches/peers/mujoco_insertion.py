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
  round, the bottom a disc. The mouth's capsules circumscribe their circle
  and the boxes' faces touch theirs at segment midpoints, the rim's
  capsules meet on their circle at vertices, each at azimuth 0 and pi (the
  scene's lateral error and tilt lie in the x-z plane, where the contacts
  are): a rim vertex meets a wall face in one point, not a flat segment
  lying on a flat face. Only pegdyn's five pairs collide: side with round (edge_side), rim
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
  contacts of one pair, each within 0.2 r of another (neighbouring
  segments share a point); its force is their sum. Forces are each pair's
  normal force averaged over the 0.1 ms between checks: MuJoCo's contact
  forces alternate from step to step (the impulse over the interval is
  what moves the peg).

Usage::

    python3 benches/peers/mujoco_insertion.py            # both settings, five scenes (about 3 min CPU)
    python3 benches/peers/mujoco_insertion.py --quick    # insert_rcc, both settings (about 30 s CPU)
    python3 benches/peers/mujoco_insertion.py --variations   # also lateral errors 0.1 and 0.6 mm
    python3 benches/peers/mujoco_insertion.py --converge scenes/insert_rcc.toml   # the ladder

Prints, per scene and setting, outcome, seat (end) time, peak contact force,
peak wrist force and CPU s per simulated second beside pegdyn's
(``target/release/pegdyn run <scene> --out <tmp> --no-replay``, one
thread: its summary and its CSV).
"""

import argparse
import csv
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
CLUSTER = 0.2  # contacts of one pair closer than this times r are one point
PAIR_NAMES = ["edge_side", "rim_wall", "rim_top", "rim_bottom", "rim_edge"]
PAIRS = {("side", "mouth"): "edge_side", ("rim", "mouth"): "rim_edge", ("rim", "wall"): "rim_wall",
         ("rim", "top"): "rim_top", ("rim", "bottom"): "rim_bottom"}


class Peer:
    """One compiled model of a scene under one setting, and its run."""

    def __init__(self, sc, setting):
        self.sc, self.setting = sc, setting
        self.model = mujoco.MjModel.from_xml_string(model_xml(sc, setting))
        self.data = mujoco.MjData(self.model)
        m = self.model
        kind = [re.sub(r"\d+$", "", m.geom(g).name) for g in range(m.ngeom)]
        self.pair_of = np.full((m.ngeom, m.ngeom), -1, dtype=int)
        for a in range(m.ngeom):
            for b in range(m.ngeom):
                name = PAIRS.get((kind[a], kind[b])) or PAIRS.get((kind[b], kind[a]))
                if name:
                    self.pair_of[a, b] = PAIR_NAMES.index(name)
        self.elliptic = setting["cone"] == "elliptic"
        self.window_force = np.zeros(len(PAIR_NAMES))
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

    def pair_forces(self):
        """Normal force (N) of each pair of PAIR_NAMES at the last step,
        summed over its contacts, and the pair index of each contact."""
        d = self.data
        n = d.ncon
        if n == 0:
            return np.zeros(len(PAIR_NAMES)), None, None
        con = d.contact
        pair = self.pair_of[con.geom1[:n], con.geom2[:n]]
        addr = con.efc_address[:n]
        if self.elliptic:
            fn = d.efc_force[addr]
        else:  # pyramidal: the normal force is the sum over the cone's edges
            fn = sum(d.efc_force[addr + k] for k in range(2 * (int(con.dim[0]) - 1)))
        keep = pair >= 0
        return np.bincount(pair[keep], weights=fn[keep], minlength=len(PAIR_NAMES)), pair, fn

    def points(self):
        """Contact points at the last step: {pair: [(force N, position)]};
        contacts of one pair within CLUSTER * r of each other (single
        linkage) are one point, their forces summed."""
        _, pair, fn = self.pair_forces()
        out = {}
        if pair is None:
            return out
        pos = np.array(self.data.contact.pos[: len(pair)])
        reach = CLUSTER * self.sc.r
        for k in set(int(v) for v in pair if v >= 0):
            idx = [i for i in range(len(pair)) if pair[i] == k and fn[i] > 0]
            groups = []
            for i in idx:
                near = [g for g in groups if any(np.linalg.norm(pos[i] - pos[j]) < reach for j in g)]
                merged = [i] + [j for g in near for j in g]
                groups = [g for g in groups if g not in near] + [merged]
            if groups:
                out[PAIR_NAMES[k]] = [[float(sum(fn[j] for j in g)), pos[g[0]]] for g in groups]
        return out

    # -- run -------------------------------------------------------------
    def release(self):
        """pegdyn's release test: (held, points after, force before, after)."""
        m, d = self.model, self.data
        before = float(self.window_force.sum())
        saved = (m.jnt_stiffness.copy(), m.dof_damping.copy())
        for j in self.wrist_joints:
            m.jnt_stiffness[j] = 0.0
        for i in self.wrist_dofs + self.ball_dofs:
            m.dof_damping[i] = 0.0
        n = max(1, round(self.sc.release_time / self.h))
        # Mean over the last CHECK of the test, as the run's forces.
        acc, k_acc = np.zeros(len(PAIR_NAMES)), 0
        for k in range(n):
            for i in self.robot_dofs:
                d.qvel[i] = 0.0
            mujoco.mj_step(m, d)
            if k >= n - self.n_sub:
                acc += self.pair_forces()[0]
                k_acc += 1
        npts = sum(len(p) for p in self.points().values())
        after = float(acc.sum() / max(k_acc, 1))
        m.jnt_stiffness[:], m.dof_damping[:] = saved
        return npts >= 2 and after >= 0.5 * before, npts, before, after

    def stuck(self, pts, limit):
        names = " + ".join(f"{k} x{len(v)}" if len(v) > 1 else k for k, v in sorted(pts.items()))
        held, *_ = self.release()
        cls = "wedged" if held else "jammed"
        return f"{cls} ({names}{'; ' + limit if limit else ''})"

    def run(self, timeout):
        """One insertion: dict of outcome, end time, peaks, CPU s per
        simulated s (MuJoCo's steps alone, and the whole run with the
        checks in Python)."""
        sc, m, d = self.sc, self.model, self.data
        c0 = time.process_time()
        step_cpu = 0.0
        self.reset()
        t_prev, depth_prev = 0.0, -self.tip()[2]
        peak_c, peak_w = 0.0, self.wrist_force()
        self.peak_at = (0.0, 0.0, "")
        n_max = round(sc.t_end / self.h)
        steps, outcome, t_end = 0, None, None
        while steps < n_max:
            if time.process_time() - c0 > timeout:
                outcome, t_end = "timeout", d.time
                break
            # One check interval: the robot reset, then each step's pair
            # forces averaged (MuJoCo's contact forces alternate from step
            # to step at the resolution of the step; the mean is the impulse
            # over the interval).
            self.drive(d.time)
            n = min(self.n_sub, n_max - steps)
            acc = np.zeros(len(PAIR_NAMES))
            seen = np.zeros(len(PAIR_NAMES), dtype=bool)
            for _ in range(n):
                s0 = time.process_time()
                mujoco.mj_step(m, d)
                step_cpu += time.process_time() - s0
                f = self.pair_forces()[0]
                acc += f
                seen |= f > 0
            steps += n
            self.window_force = acc / n
            tip = self.tip()
            depth = -tip[2]
            if not (math.isfinite(depth) and np.all(np.isfinite(d.qvel))):
                outcome, t_end = "failed (non-finite state)", d.time
                break
            pts = self.points()
            fc = float(self.window_force.max())
            fw = self.wrist_force()
            npts = max(sum(len(p) for p in pts.values()), int(seen.sum()))
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
            if seen[PAIR_NAMES.index("rim_top")] and math.hypot(tip[0], tip[1]) > sc.R:
                outcome, t_end = "missed", d.time
                break
            if fc > peak_c:
                self.peak_at = (d.time, depth, PAIR_NAMES[int(self.window_force.argmax())])
            peak_c, peak_w = max(peak_c, fc), max(peak_w, fw)
            t_prev, depth_prev = d.time, depth
        if outcome is None:
            t_end = d.time
            pts = self.points()
            npts = sum(len(p) for p in pts.values())
            vel = np.zeros(6)  # (angular, linear) at the peg frame's origin, world axes
            mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_BODY, self.peg, vel, 0)
            speed = np.linalg.norm(vel[3:])
            if -self.tip()[2] > sc.rho_h and npts >= 2 and speed < 1e-4:
                outcome = self.stuck(pts, "")
            else:
                outcome = "stopped (end of span)"
        cpu = time.process_time() - c0
        sim = max(d.time, 1e-12)
        return {"outcome": outcome, "t": t_end, "peak_contact": peak_c, "peak_wrist": peak_w,
                "cpu_per_s": step_cpu / sim, "cpu_all_per_s": cpu / sim, "depth": -self.tip()[2]}


# -- pegdyn's side ----------------------------------------------------------
def pegdyn_run(binary, scene_path):
    """Runs pegdyn on the scene (one thread); its outcome, end time, peak
    wrist force (summary), peak contact force per pair (the largest sum of
    a pair's point forces over the rows of <scene>.csv, as the peer's) and
    the summary's per-point peak, CPU s per simulated s."""
    env = {**os.environ, "RAYON_NUM_THREADS": "1"}
    with tempfile.TemporaryDirectory() as out:
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        p = subprocess.run([str(binary), "run", str(scene_path), "--out", out, "--no-replay"],
                           capture_output=True, text=True, timeout=900, env=env)
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        table = Path(out) / f"{Path(scene_path).stem}.csv"
        pair_peak = math.nan
        if table.exists():
            with open(table, newline="") as f:
                rows = list(csv.DictReader(f))
            pair_peak = 0.0
            for r in rows:
                for name in PAIR_NAMES:
                    total = sum(float(r[k]) for k in r if k.startswith(name + "_") and k.endswith("_N_N") and r[k])
                    pair_peak = max(pair_peak, total)
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
    return {"outcome": m.group(1) if m else "?", "t": t, "peak_contact": pair_peak,
            "peak_point": num("peak contact normal force"), "peak_wrist": num("peak wrist force"),
            "cpu_per_s": cpu / t if t > 0 else math.nan, "text": text}


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
    cpu = f"{r['cpu_per_s']:.3g}"
    if "cpu_all_per_s" in r:
        cpu += f" ({r['cpu_all_per_s']:.3g})"
    peak = f"{r['peak_contact']:.1f}"
    if "peak_point" in r:
        peak += f" ({r['peak_point']:.1f})"
    return f"| {label} | {src} | {r['outcome']} | {r['t']:.4f} | {peak} | {r['peak_wrist']:.2f} | {cpu} |"


def converge(path, timeout):
    """The ladder from 32 segments, a 1e-4 s step and a 5e-4 s contact time
    constant (elliptic cone, impratio 10): halve step and time constant and
    double the segments until the outcome holds and the end (seat) time
    moves < 1e-4 s. The time constant stays five steps: at two steps (the
    least MuJoCo accepts) the contact force alternates between zero and
    twice its mean from one step to the next."""
    sc = Scene(load(path), Path(path).stem)
    base = {"step": 1e-4, "timeconst": 5e-4, "segments": 32, "cone": "elliptic", "impratio": 10.0}
    print(f"MuJoCo {mujoco.__version__}: convergence ladder on {path}")
    print("| step s | time const s | segments | cone | impratio | outcome | end time s | peak contact N | "
          "peak wrist N | CPU s / sim s (steps; whole run) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    prev = None
    s = dict(base)
    for _ in range(5):
        r = Peer(sc, s).run(timeout)
        print(f"| {s['step']:g} | {s['timeconst']:g} | {s['segments']} | {s['cone']} | {s['impratio']:g} | "
              f"{r['outcome']} | {r['t']:.5f} | {r['peak_contact']:.1f} | {r['peak_wrist']:.2f} | "
              f"{r['cpu_per_s']:.3g}; {r['cpu_all_per_s']:.3g} |", flush=True)
        if prev and short(prev["outcome"]) == short(r["outcome"]) and abs(prev["t"] - r["t"]) < 1e-4:
            print(f"converged: {prev_s}")
            return
        prev, prev_s = r, dict(s)
        s = {**s, "step": s["step"] / 2, "timeconst": s["timeconst"] / 2, "segments": s["segments"] * 2}
    print("not converged within the ladder")


def main():
    ap = argparse.ArgumentParser(description="pegdyn's insert_rcc scenes in MuJoCo beside pegdyn.")
    ap.add_argument("--quick", action="store_true", help="insert_rcc only (about 30 s CPU)")
    ap.add_argument("--variations", action="store_true",
                    help="also insert_rcc with lateral errors of 0.1 and 0.6 mm")
    ap.add_argument("--scenes", help="comma-separated scene files instead of the shipped five")
    ap.add_argument("--settings", default="defaults,converged", help="comma-separated settings")
    ap.add_argument("--pegdyn", default=str(REPO / "target" / "release" / "pegdyn"), help="pegdyn binary")
    ap.add_argument("--no-pegdyn", action="store_true", help="MuJoCo only")
    ap.add_argument("--timeout", type=float, default=300.0, help="CPU s per MuJoCo run (default 300)")
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
    print("peak contact: per pair, its points summed (pegdyn: over the rows of its CSV, every 1 ms; in brackets its "
          "summary's per-point peak over samples and events; MuJoCo: each pair's force averaged over each 0.1 ms)")
    print("CPU: pegdyn's process (one thread); MuJoCo's mj_step calls (in brackets the whole run with the Python checks)")
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
