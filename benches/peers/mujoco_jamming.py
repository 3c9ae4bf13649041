"""The planar jamming sweep of scenes/jamming.toml in MuJoCo (optional peer).

Not run by CI. Needs ``pip install mujoco`` (measured with 4.0.0) and numpy.

The same peg, hole, loads, start state and classification rules as pegdyn's
dynamic sweep (the ``[sweep]`` table of the scene; ``src/jamming/dynamic.rs``,
``src/compliant_peg/simulate.rs``):

* Geometry (the compliant planar peg of ``docs/compliant.md``): peg radius r,
  hole diameter D = 2r/(1 - c), peg length L, both fillets 0.2 mm. The peg is
  a box of half-width r whose two bottom corners are cylinders (capsules
  along the out-of-plane axis) of the peg fillet radius; the hole's two top
  edges are cylinders of the hole fillet radius and its walls are boxes
  below them. Only the contacts pegdyn models collide: peg side with hole
  edge, peg bottom fillet with hole edge or wall.
* Motion: slide x, slide z (into the hole), hinge about the out-of-plane
  axis; the joint coordinates are pegdyn's (x, z, theta) of the centre of
  mass. Steel (7850 kg/m^3) cylinder mass and inertia, no gravity.
* Load: pegdyn's Whitney-frame grid (F_x/F_z, M/(r F_z)) converted to the
  peg frame at the start tilt (axial f1, radial f2, moment about the centre
  of mass, ``to_paper_frame``) and applied by three ``general`` actuators
  with a ``site`` transmission at the centre of mass: the gear wrench acts
  in the site's frame, so a constant ctrl is a load constant in the peg
  frame with nothing computed in Python per step.
* Start: at rest in two-point contact with zero penetration at the exact
  two-point tilt of the requested depth (``PegState::two_point``).
* Classes: inserted when the bottom face advances ``advance_m``; exited
  (other) when it rises above the edge fillet; stuck when it advances less
  than 2 um in a window of ``window_s``, or earlier once settled (every tenth
  of the window: advance below the window rule's mean speed, every speed
  |x'|, |z'|, r|theta'| below 2 um / window, edge and wall normal forces
  steady to 1 %); a stuck run is wedged (two-point, contact line inside both
  friction cones), jammed (other contact) or stalled (no contact: other);
  unfinished (other) at ``t_max_s``. A grid point is stuck when the run from
  either lean sticks; the other lean under q is this lean under -q, so one
  run per grid point.

Usage (after ``pegdyn run scenes/jamming.toml``, which writes
``out/jamming.sweep.csv``)::

    python3 benches/peers/mujoco_jamming.py --setting defaults --pegdyn out/jamming.sweep.csv
    python3 benches/peers/mujoco_jamming.py --setting tuned --pegdyn out/jamming.sweep.csv \\
        --out out/mujoco_tuned.csv
    python3 benches/peers/mujoco_jamming.py --setting tuned --step 4e-5 ...   # convergence check
    python3 benches/peers/mujoco_jamming.py --setting defaults --option cone=elliptic \\
        --geom "solref=4e-4 1" --step 1e-5 ...                            # one tuning trial
    python3 benches/peers/mujoco_jamming.py --ratio 0,5.2 --window 0.3 --no-early-stop

Prints the classes, their agreement with pegdyn's sweep CSV (stuck = jammed
or wedged) and with the exact parallelogram (by the sign of the CSV's
``margin_exact``: inside = inserted, outside = stuck), and the wall and CPU
time per simulated second of the runs (one thread).
"""

import argparse
import csv
import math
import sys
import time
from pathlib import Path

try:
    import tomllib
except ImportError:  # Python < 3.11
    tomllib = None

try:
    import mujoco
except ImportError:
    sys.exit(
        "mujoco_jamming.py needs MuJoCo's Python bindings: pip install mujoco "
        "(measured with 4.0.0)"
    )

import numpy as np

from mujoco_jamming_model import HOLE_FILLET, SETTINGS, SETTLE_FORCE_RTOL, STALL, Sweep, model_xml

REPO = Path(__file__).resolve().parents[2]


class Peer:
    """One compiled model and the runs of the sweep on it."""

    def __init__(self, sw, setting, step, early_stop=True, option=None, geom=None, wall=0.02):
        s = SETTINGS[setting]
        self.sw = sw
        self.step = step if step else s["step"]
        self.option = {**s["option"], **(option or {})}
        self.geom = {**s["geom"], **(geom or {})}
        self.model = mujoco.MjModel.from_xml_string(
            model_xml(sw, self.option, self.geom, self.step, wall)
        )
        self.data = mujoco.MjData(self.model)
        self.early_stop = early_stop
        m = self.model
        self.edge_ids = {m.geom(f"edge{k:+d}").id for k in (-1, 1)}
        self.wall_ids = {m.geom(f"wall{k:+d}").id for k in (-1, 1)}
        self.side_of = {m.geom(f"{n}{k:+d}").id: k for n in ("edge", "wall") for k in (-1, 1)}
        # Integer step counts: window, settle interval, sub-chunk between
        # depth checks (at most 0.5 ms of simulated time).
        h = self.step
        n_int = max(1, round(0.1 * sw.window / h))
        self.n_win = n_int * max(1, round(sw.window / h / n_int))
        self.n_int = n_int
        self.n_sub = max(k for k in range(1, n_int + 1) if n_int % k == 0 and (k == 1 or k * h <= 5e-4))
        self.n_max = round(sw.t_max / h)
        self._force = np.zeros(6)

    def check_load(self, q):
        """The generalized force of the actuators against the peg-frame load
        computed by hand: Q = (f1 sin + f2 cos, f1 cos - f2 sin, M_C)."""
        m, d = self.model, self.data
        self.reset(q)
        mujoco.mj_forward(m, d)
        f1, f2, mc = self.sw.peg_frame_load(q)
        s, c = math.sin(self.sw.theta), math.cos(self.sw.theta)
        want = (f1 * s + f2 * c, f1 * c - f2 * s, mc)
        got = tuple(d.qfrc_actuator)
        return max(abs(a - b) for a, b in zip(got, want)), got, want

    def reset(self, q):
        m, d = self.model, self.data
        mujoco.mj_resetData(m, d)
        d.qpos[:] = self.sw.start()
        d.qvel[:] = 0.0
        f1, f2, mc = self.sw.peg_frame_load(q)
        d.ctrl[:] = (f2, f1, mc)  # actuators: radial, axial, moment

    def forces(self):
        """Normal forces (N) of the loaded edge and wall: per pair the side
        with the larger summed force (pegdyn's Sample picks by penetration)."""
        m, d = self.model, self.data
        edge, wall = {-1: 0.0, 1: 0.0}, {-1: 0.0, 1: 0.0}
        for i in range(d.ncon):
            con = d.contact[i]
            hole = con.geom1 if con.geom1 in self.side_of else con.geom2
            if hole not in self.side_of:
                continue
            mujoco.mj_contactForce(m, d, i, self._force)
            target = edge if hole in self.edge_ids else wall
            target[self.side_of[hole]] += self._force[0]
        return max(edge.values()), max(wall.values())

    def depth(self):
        q = self.data.qpos
        return self.sw.depth_of(q[0], q[1], q[2])

    def stuck_class(self, forces):
        f_edge, f_wall = forces
        q = self.data.qpos
        if f_edge > 0 and f_wall > 0 and self.sw.contact_line_in_cones(q[0], q[1], q[2]):
            return "wedged"
        if f_edge > 0 or f_wall > 0:
            return "jammed"
        return "stalled"

    def run(self, q):
        """One run from the reference lean under ratio q: (class, simulated s)."""
        sw, m, d = self.sw, self.model, self.data
        self.reset(q)
        mujoco.mj_forward(m, d)
        target = self.depth() + sw.advance
        exit_depth = HOLE_FILLET
        v_max = STALL / sw.window
        floor = 1e-9 * abs(sw.peg_frame_load(q)[0])
        d_w = self.depth()
        d_i = d_w
        last = self.forces()
        steps = 0
        while steps < self.n_max:
            n = min(self.n_sub, self.n_max - steps)
            mujoco.mj_step(m, d, nstep=n)
            steps += n
            depth = self.depth()
            if not math.isfinite(depth):
                return "failed", d.time
            if depth >= target:
                return "inserted", d.time
            if depth < exit_depth:
                return "exited", d.time
            if steps % self.n_int:
                continue
            window_done = steps % self.n_win == 0
            now = self.forces()
            if window_done:
                stuck = depth - d_w < STALL
            else:
                v = d.qvel
                stuck = (
                    self.early_stop
                    and depth - d_i < STALL * self.n_int / self.n_win
                    and abs(v[0]) < v_max
                    and abs(v[1]) < v_max
                    and abs(sw.r * v[2]) < v_max
                    and steady(now[0], last[0], floor)
                    and steady(now[1], last[1], floor)
                )
            if stuck:
                return self.stuck_class(now), d.time
            last, d_i = now, depth
            if window_done:
                d_w = depth
        return "unfinished", d.time


def steady(a, b, floor):
    """Forces a, b (N) within SETTLE_FORCE_RTOL of each other; below floor
    counts as zero."""
    a, b = max(a, floor), max(b, floor)
    return abs(a - b) <= SETTLE_FORCE_RTOL * max(a, b)


STUCK = ("jammed", "wedged")


def combine(a, b):
    """A grid point's class from both leans (pegdyn's combine)."""
    for cls in ("wedged", "jammed"):
        if cls in (a, b):
            return cls
    return "inserted" if (a, b) == ("inserted", "inserted") else "other"


def coarse(cls):
    """inserted / stuck (jammed or wedged) / anything else as other."""
    if cls in STUCK:
        return "stuck"
    return "inserted" if cls == "inserted" else "other"


def read_pegdyn(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def step_error_table(args, sw, q, pairs):
    """One run under ratio q at each step of --steps: CPU per simulated second
    (best of three) and the end-state difference against the smallest step."""
    try:
        steps = sorted({float(v) for v in args.steps.split(",")}, reverse=True)
    except ValueError:
        sys.exit(f"--steps {args.steps!r}: expected comma-separated steps in s")
    if not steps or not all(math.isfinite(h) and 0 < h <= sw.window / 10 for h in steps):
        sys.exit(f"--steps {args.steps!r}: every step must be > 0 and at most a tenth of the window")
    rows = []
    for h in steps:
        peer = Peer(sw, args.setting, h, early_stop=not args.no_early_stop,
                    option=pairs(args.option, "--option"), geom=pairs(args.geom, "--geom"), wall=args.wall)
        best = math.inf
        for _ in range(3):
            c0 = time.process_time()
            cls, t = peer.run(q)
            best = min(best, time.process_time() - c0)
        rows.append((h, cls, t, best / t, tuple(float(v) for v in peer.data.qpos)))
    ref = rows[-1][4]
    print(f"MuJoCo {mujoco.__version__}, setting {args.setting}, ratio {q}, window {sw.window:g} s, "
          f"early stop {'off' if args.no_early_stop else 'on'}; reference: the step {rows[-1][0]:g} s")
    print("step_s,class,t_s,cpu_per_sim_s,end_difference_m")
    for h, cls, t, cost, (x, z, th) in rows:
        diff = max(abs(x - ref[0]), abs(z - ref[1]), sw.r * abs(th - ref[2]))
        print(f"{h:g},{cls},{t:.6f},{cost:.4g},{diff:.3e}")


def main():
    ap = argparse.ArgumentParser(
        description="pegdyn's planar jamming sweep in MuJoCo: classes and time per simulated second."
    )
    ap.add_argument("--scene", default=str(REPO / "scenes" / "jamming.toml"), help="scene with the [sweep] table")
    ap.add_argument("--pegdyn", help="pegdyn's jamming.sweep.csv (from `pegdyn run scenes/jamming.toml`) to compare with")
    ap.add_argument("--setting", choices=sorted(SETTINGS), default="tuned", help="MuJoCo solver setting")
    ap.add_argument("--step", type=float, help="time step, s (default: the setting's)")
    ap.add_argument("--no-early-stop", action="store_true", help="classify stuck runs only at window ends")
    ap.add_argument("--n", type=int, help="grid points per axis (default: the scene's)")
    ap.add_argument("--option", action="append", default=[], metavar="KEY=VALUE",
                    help="override an <option> attribute of the setting (repeatable), e.g. impratio=100")
    ap.add_argument("--geom", action="append", default=[], metavar="KEY=VALUE",
                    help="override a contact attribute of every geom (repeatable), e.g. solref=\"2e-4 1\"")
    ap.add_argument("--wall", type=float, default=0.02,
                    help="thickness of the hole's wall boxes, m (default 0.02; matters only where contacts are soft)")
    ap.add_argument("--ratio", metavar="FX,M",
                    help="one run from the reference lean under F_x/F_z = FX, M/(r F_z) = M instead of the sweep")
    ap.add_argument("--steps", metavar="H1,H2,...",
                    help="with --ratio: the run at each of these steps, its CPU per simulated second and its "
                         "end-state difference (max of |dx|, |dz|, r|dtheta|) against the run at the smallest step")
    ap.add_argument("--window", type=float, help="classification window, s (default: the scene's)")
    ap.add_argument("--out", help="write the classes to this CSV")
    args = ap.parse_args()

    if tomllib is None:
        sys.exit("mujoco_jamming.py needs Python >= 3.11 (tomllib) to read the scene")
    if not (math.isfinite(args.wall) and args.wall > 0):
        sys.exit(f"--wall {args.wall}: must be > 0")
    try:
        with open(args.scene, "rb") as f:
            scene = tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as e:
        sys.exit(f"--scene {args.scene}: {e}")
    if "sweep" not in scene:
        sys.exit(f"{args.scene}: no [sweep] table")
    sw = Sweep(scene["sweep"])
    if args.n:
        sw.n = args.n
    if args.window:
        sw.window = args.window
    def pairs(items, flag):
        out = {}
        for item in items:
            key, sep, value = item.partition("=")
            if not sep or not key:
                sys.exit(f"{flag} {item!r}: expected KEY=VALUE")
            out[key] = value
        return out

    if args.step is not None and not (math.isfinite(args.step) and 0 < args.step <= sw.window / 10):
        sys.exit(f"--step {args.step}: must be > 0 and at most a tenth of the window ({sw.window / 10} s)")
    if sw.n < 3:
        sys.exit(f"--n {sw.n}: must be at least 3")
    try:
        peer = Peer(sw, args.setting, args.step, early_stop=not args.no_early_stop,
                    option=pairs(args.option, "--option"), geom=pairs(args.geom, "--geom"), wall=args.wall)
    except ValueError as e:  # MuJoCo's XML errors
        sys.exit(f"MuJoCo refused the model: {e}")
    err, got, want = peer.check_load((1.5, -2.0))
    if err > 1e-9 * sw.fz:
        sys.exit(f"actuator load {got} differs from the peg-frame load {want}")

    if args.ratio:
        try:
            q = tuple(float(v) for v in args.ratio.split(","))
        except ValueError:
            q = ()
        if len(q) != 2:
            sys.exit(f"--ratio {args.ratio!r}: expected FX,M (two numbers)")
        if args.steps:
            step_error_table(args, sw, q, pairs)
            return
        w0, c0 = time.perf_counter(), time.process_time()
        cls, t = peer.run(q)
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        print(f"MuJoCo {mujoco.__version__}, setting {args.setting}, step {peer.step:g} s, window {sw.window:g} s, "
              f"early stop {'off' if args.no_early_stop else 'on'}; option {peer.option}, geom {peer.geom}")
        x, z, th = (float(v) for v in peer.data.qpos)
        print(f"ratio {q}: {cls} at t = {t:.6f} s; wall {wall / t:.4g} s, CPU {cpu / t:.4g} s per simulated s")
        print(f"end state: x = {x!r} m, z = {z!r} m, theta = {th!r} rad")
        return

    ratios = sw.grid()
    n = sw.n
    raw, sim, wall, cpu = [], 0.0, 0.0, 0.0
    for q in ratios:
        w0, c0 = time.perf_counter(), time.process_time()
        cls, t = peer.run(q)
        wall += time.perf_counter() - w0
        cpu += time.process_time() - c0
        sim += t
        raw.append((cls, t))
    rows = []
    for k, q in enumerate(ratios):
        i, j = k % n, k // n
        plus, t_plus = raw[k]
        minus, t_minus = raw[(n - 1 - j) * n + (n - 1 - i)]
        rows.append({"fx_over_fz": q[0], "m_over_rfz": q[1], "class": combine(plus, minus),
                     "lean_plus": plus, "lean_minus": minus, "t_plus_s": round(t_plus, 9)})

    ref = None
    if args.pegdyn:
        ref = read_pegdyn(args.pegdyn)
        if len(ref) != len(rows):
            sys.exit(f"{args.pegdyn} has {len(ref)} rows, the sweep {len(rows)}")
        for row, p in zip(rows, ref):
            if abs(float(p["fx_over_fz"]) - row["fx_over_fz"]) > 1e-9 or abs(float(p["m_over_rfz"]) - row["m_over_rfz"]) > 1e-9:
                sys.exit(f"{args.pegdyn}: grid point ({p['fx_over_fz']}, {p['m_over_rfz']}) is not the sweep's")
            margin = float(p["margin_exact"])
            row["pegdyn_class"] = p["class"]
            row["margin_exact"] = margin
            row["agrees_pegdyn"] = int(coarse(row["class"]) == coarse(p["class"]))
            row["lean_agrees_pegdyn"] = int(coarse(row["lean_plus"]) == coarse(p["lean_plus"]))
            row["agrees_exact"] = int(coarse(row["class"]) == ("inserted" if margin > 0 else "stuck"))

    counts = {}
    for row in rows:
        counts[row["class"]] = counts.get(row["class"], 0) + 1
    h = peer.step
    print(f"MuJoCo {mujoco.__version__}, setting {args.setting}, step {h:g} s, "
          f"early stop {'off' if args.no_early_stop else 'on'}, {len(rows)} grid points")
    print(f"option {peer.option}, geom {peer.geom}")
    print("classes:", ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    if ref:
        a_p = sum(r["agrees_pegdyn"] for r in rows)
        a_e = sum(r["agrees_exact"] for r in rows)
        a_l = sum(r["lean_agrees_pegdyn"] for r in rows)
        print(f"agreement with pegdyn: {a_p}/{len(rows)}; with the exact parallelogram: {a_e}/{len(rows)}; "
              f"single runs (reference lean) agreeing with pegdyn's: {a_l}/{len(rows)}")
    print(f"simulated {sim:.3f} s in {len(rows)} runs: wall {wall:.2f} s ({wall / sim:.4g} s per simulated s), "
          f"CPU {cpu:.2f} s ({cpu / sim:.4g} s per simulated s)")
    if args.out:
        with open(args.out, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()), lineterminator="\n")
            w.writeheader()
            for row in rows:
                w.writerow({k: (repr(v) if isinstance(v, float) else v) for k, v in row.items()})


if __name__ == "__main__":
    main()
