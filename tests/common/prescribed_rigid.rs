//! The rigid three-point limit of the compliant 3-D peg: the prescribed
//! Fig. 9 motion run on `pegdyn::compliant_peg_3d::prescribed`, compared
//! with the rigid model's reactions and contact points. Shared by
//! `tests/compliant_peg_3d/limits_rigid.rs` and (through `#[path]`)
//! `benches/tools/rigid_limit_table.rs`.

#![allow(dead_code)]

use nalgebra::{Matrix3, SVector, Vector2, Vector3};
use pegdyn::compliant_peg_3d::prescribed::{Motion, PrescribedPeg};
use pegdyn::compliant_peg_3d::{HertzMode, Pair, Peg3dParams, Search, axis_of};
use pegdyn::integrate::{Method, Options, OutputMode, solve};
use pegdyn::rigid_peg::kinematics::Pose;
use pegdyn::rigid_peg::prescribed::reactions;
use pegdyn::rigid_peg::{Loads, PegParams};

/// γ̇ of the Fig. 9 motion (1/s).
pub const GAMMADOT: f64 = -2.0;

/// Contact forces and points of one state: `[K, B1, B2]` (N, m); a missing
/// contact has force 0 and point NaN. K is the pair `edge_side`, B1 and B2
/// the pair `rim_edge` (the rim torus on the mouth torus; `rim_wall` too,
/// should the rim slip below the mouth): B1 on the `+e_n` side (the one
/// that leads when ψ̇ > 0). A merged B1–B2 counts as B1 or B2 by the side
/// it lies on. The elastic force of a col shared by B1 and B2 (the
/// continuous merge of `compliant_peg_3d::merge`, always opposite to both
/// points' forces near the merge) is taken off both, half each.
pub fn three_points(
    sys: &PrescribedPeg,
    t: f64,
    y: &SVector<f64, 7>,
) -> ([f64; 3], [Vector3<f64>; 3]) {
    let (_, psi) = sys.motion.angles(t);
    let e_n = Vector3::new(-psi.sin(), psi.cos(), 0.0);
    let mut n = [0.0; 3];
    let mut pts = [Vector3::repeat(f64::NAN); 3];
    for f in sys.forces(t, y).unwrap() {
        let c = &f.contact;
        let k = match c.pair {
            Pair::EdgeSide => 0,
            Pair::RimEdge | Pair::RimWall => {
                if c.point.dot(&e_n) >= 0.0 {
                    1
                } else {
                    2
                }
            }
            other => panic!("unexpected contact {other:?}"),
        };
        n[k] += f.normal_force;
        pts[k] = c.point;
        if f.col_force > 0.0 {
            assert!(k > 0, "a col on K: {f:?}");
            n[1] -= 0.5 * f.col_force;
            n[2] -= 0.5 * f.col_force;
        }
    }
    (n, pts)
}

/// The gaps `[K, B1, B2]` (m) with the centre of mass at `c` at time 0:
/// the smallest valid edge–side minimum and the smallest valid rim–mouth
/// (`rim_edge`) minima on either side of the symmetry plane.
pub fn gaps(sys: &PrescribedPeg, c: &Vector3<f64>) -> [f64; 3] {
    let prm = &sys.peg.params;
    let q = sys.motion.orientation(0.0);
    let x = SVector::<f64, 7>::from_column_slice(&[c.x, c.y, c.z, q.w, q.i, q.j, q.k]);
    let axis = axis_of(&x);
    let pv = sys.peg.param_vector();
    let e_n = Vector3::new(-sys.motion.psi.sin(), sys.motion.psi.cos(), 0.0);
    let mut g = [f64::NAN; 3];
    for pair in [Pair::EdgeSide, Pair::RimEdge] {
        for a in Search::default().minima(pair, &x, pv, 1e-3) {
            let e = pair.eval(&x, a, pv);
            let (gap, n, pt, axial) = (e.gap, e.normal, e.point, e.axial);
            if !(pair.valid(prm, &axis, &n, &pt, axial) && pair.rim_faces_out(&x, &n, &pt)) {
                continue;
            }
            let k = match pair {
                Pair::EdgeSide => 0,
                _ if pt.dot(&e_n) >= 0.0 => 1,
                _ => 2,
            };
            if g[k].is_nan() || gap < g[k] {
                g[k] = gap;
            }
        }
    }
    g
}

/// The centre of mass at which the three gaps are `−(N_i/k)^{2/3}`: the
/// compliant peg preloaded with the rigid model's reactions (Newton with a
/// central-difference Jacobian, from the rigid model's centre of mass).
pub fn preloaded_centre(
    sys: &PrescribedPeg,
    start: Vector3<f64>,
    normal: [f64; 3],
    k: f64,
) -> Vector3<f64> {
    let target = Vector3::from_fn(|i, _| -(normal[i].max(0.0) / k).powf(2.0 / 3.0));
    let resid = |c: &Vector3<f64>| Vector3::from(gaps(sys, c)) - target;
    let mut c = start;
    for _ in 0..30 {
        let r = resid(&c);
        assert!(
            r.iter().all(|v| v.is_finite()),
            "a contact is missing at {c}: {r}"
        );
        if r.norm() < 1e-14 {
            break;
        }
        let h = 1e-9;
        let jac = Matrix3::from_fn(|i, j| {
            let mut e = Vector3::zeros();
            e[j] = h;
            (resid(&(c + e))[i] - resid(&(c - e))[i]) / (2.0 * h)
        });
        c -= jac.lu().solve(&r).unwrap();
    }
    c
}

/// One row of the comparison: γ, the 3-D and rigid forces over m g, the
/// distance of each 3-D contact point from the rigid one.
#[derive(Clone, Copy, Debug)]
pub struct Row {
    pub gamma: f64,
    pub three_d: [f64; 3],
    pub rigid: [f64; 3],
    pub point_error: [f64; 3],
}

/// Fillet radius of both edges for stiffness `k`: 20 µm at
/// `k = 2.4·10¹⁰ N/m^{3/2}` (steel fillets of that size), scaled like the
/// penetration `(Q/k)^{2/3}`, about ten times the penetration under the
/// Fig. 9 loads (and below `ρ_p + ρ_h`, where the tube circles would cross).
pub fn fillet(k: f64) -> f64 {
    2e-5 * (k / 2.4e10).powf(-2.0 / 3.0)
}

/// The compliant 3-D peg matched to the rigid peg `rigid` (its size, mass,
/// gravity and friction), with [`fillet`]`(k)` on both edges, fixed Hertz
/// stiffness `k`, Hunt–Crossley damping 50 s/m and `v_s = 10⁻⁴ m/s`.
pub fn params(rigid: &PegParams, k: f64) -> Peg3dParams {
    let rho = fillet(k);
    let mut prm = Peg3dParams::steel(
        rigid.peg_diameter,
        rigid.height,
        rigid.hole_diameter,
        rho,
        rho,
        0.1,
    );
    prm.mass = rigid.mass;
    prm.gravity = rigid.gravity;
    prm.friction = rigid.friction;
    prm.slip_scale = 1e-4;
    prm.damping = 50.0;
    prm.hertz = HertzMode::Fixed(k);
    prm
}

/// The prescribed peg's state at the start of its motion: the rigid
/// pose's centre moved so that the contacts carry `normal` (stiffness
/// `k`, [`preloaded_centre`]), with the rigid centre-of-mass velocity.
pub fn preloaded_state(
    sys: &PrescribedPeg,
    rigid: &PegParams,
    normal: [f64; 3],
    k: f64,
) -> SVector<f64, 7> {
    let m = &sys.motion;
    let pose = Pose::try_new(rigid, m.gamma, m.psi).unwrap();
    let v = pose.kinematics(Vector2::new(m.gammadot, m.psidot)).v_c;
    let c = preloaded_centre(sys, pose.c, normal, k);
    SVector::<f64, 7>::from_column_slice(&[c.x, c.y, c.z, v.x, v.y, v.z, 0.0])
}

/// The prescribed run from `gamma_s` (the compliant peg preloaded with the
/// rigid reactions there, moving with the rigid centre-of-mass velocity)
/// with stiffness `k`, Hunt–Crossley damping 50 s/m, friction 0.2 with
/// `v_s = 10⁻⁴ m/s`, sampled at `gammas`.
pub fn run(k: f64, psidot: f64, gamma_s: f64, gammas: &[f64]) -> Vec<Row> {
    let rigid = PegParams::fig9();
    let motion = Motion {
        gamma: gamma_s,
        gammadot: GAMMADOT,
        psi: 0.0,
        psidot,
    };
    let sys = PrescribedPeg::try_new(params(&rigid, k), motion).unwrap();
    let react = |gamma: f64, psi: f64| {
        reactions(
            &rigid,
            &Loads::default(),
            Vector2::new(gamma, psi),
            Vector2::new(GAMMADOT, psidot),
            Vector2::zeros(),
        )
        .unwrap()
        .normal
    };
    let y0 = preloaded_state(&sys, &rigid, react(gamma_s, 0.0), k);
    let times: Vec<f64> = gammas.iter().map(|g| (g - gamma_s) / GAMMADOT).collect();
    let mut opts = Options::with_tolerances(1e-8, 1e-12);
    opts.output = OutputMode::AtTimes(times.clone());
    let t_end = *times.last().unwrap();
    let sol = solve(&sys, Method::Dopri5, (0.0, y0), t_end, &opts).unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    let w = rigid.mass * rigid.gravity;
    sol.t
        .iter()
        .zip(&sol.x)
        .map(|(&t, y)| {
            let (gamma, psi) = motion.angles(t);
            let (n, pts) = three_points(&sys, t, y);
            let rp = Pose::try_new(&rigid, gamma, psi).unwrap();
            Row {
                gamma,
                three_d: n.map(|f| f / w),
                rigid: react(gamma, psi).map(|f| f / w),
                point_error: [0, 1, 2].map(|i| (pts[i] - rp.contacts[i]).norm()),
            }
        })
        .collect()
}

/// Largest force difference (over m g) and point distance (m) over rows;
/// a contact the 3-D peg has lost counts as an infinite distance.
pub fn worst(rows: &[Row]) -> (f64, f64) {
    rows.iter().fold((0.0_f64, 0.0_f64), |(f, p), r| {
        let df = (0..3)
            .map(|i| (r.three_d[i] - r.rigid[i]).abs())
            .fold(0.0, f64::max);
        let dp = r
            .point_error
            .iter()
            .map(|&e| if e.is_nan() { f64::INFINITY } else { e })
            .fold(0.0, f64::max);
        (f.max(df), p.max(dp))
    })
}

pub fn print(label: &str, rows: &[Row]) {
    for r in rows {
        eprintln!(
            "{label} γ {:.4}: 3-D [{:.3} {:.3} {:.3}] rigid [{:.3} {:.3} {:.3}] points [{:.1e} {:.1e} {:.1e}] m",
            r.gamma,
            r.three_d[0],
            r.three_d[1],
            r.three_d[2],
            r.rigid[0],
            r.rigid[1],
            r.rigid[2],
            r.point_error[0],
            r.point_error[1],
            r.point_error[2]
        );
    }
}

/// `count + 1` values of γ from `from` down to `to`.
pub fn grid(from: f64, to: f64, count: usize) -> Vec<f64> {
    (0..=count)
        .map(|i| from + (to - from) * i as f64 / count as f64)
        .collect()
}
