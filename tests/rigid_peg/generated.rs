//! Rigid three-point peg, generated model against the hand-derived one: the linear
//! systems, contact velocities and energies that the generator derives
//! (`pegdyn::generated::rigid_peg*`) equal the hand-derived forms
//! (`rigid_peg::kinematics`, `rigid_peg::dynamics`) to 1e-12 normwise over a grid of
//! states from γ0(1 + 1e-9) to 1.2 rad, for all four variants (and row by
//! row, each row of [A | b] against its own norm); the mass block
//! reproduces the kinetic energy (22)–(23).

use nalgebra::{SMatrix, SVector, Vector2, Vector3};
use pegdyn::generated::{
    rigid_peg, rigid_peg_frictionless, rigid_peg_planar, rigid_peg_planar_frictionless,
};
use pegdyn::rigid_peg::PegParams;
use pegdyn::rigid_peg::dynamics::{
    Matrix5, Vector5, forward_system, friction_directions, kinetic_energy, potential_energy,
    prescribed_system,
};
use pegdyn::rigid_peg::kinematics::Pose;
use rigid_peg::LinearSystem;
use rigid_peg_planar::LinearSystem as PlanarSystem;

use crate::common;
use common::Rng;
use common::rigid::{gammas, loads, planar_loads};

const TOL: f64 = 1e-12;

fn rel<const R: usize, const C: usize>(got: &SMatrix<f64, R, C>, want: &SMatrix<f64, R, C>) -> f64 {
    (got - want).norm() / want.norm()
}

/// Largest relative difference of one row of [A | b], each row measured
/// against its own norm (stricter than normwise: the lateral row's small
/// entries, which alone fix N_B1 − N_B2, count fully).
fn rowwise<const R: usize, const C: usize>(
    (ga, gb): (&SMatrix<f64, R, C>, &SVector<f64, R>),
    (ha, hb): (&SMatrix<f64, R, C>, &SVector<f64, R>),
) -> f64 {
    (0..R)
        .map(|i| {
            let d2 = (ga.row(i) - ha.row(i)).norm_squared() + (gb[i] - hb[i]).powi(2);
            (d2 / (ha.row(i).norm_squared() + hb[i] * hb[i])).sqrt()
        })
        .fold(0.0, f64::max)
}

const PSIS: [f64; 3] = [0.0, 0.7, -2.0];
const RATES: [(f64, f64); 4] = [(-2.0, 10.0), (1.5, -3.0), (-0.3, -0.7), (2.0, 0.5)];

struct State {
    q: Vector2<f64>,
    qd: Vector2<f64>,
    pose: Pose,
    t: [Vector3<f64>; 3],
}

fn states(p: &PegParams) -> Vec<State> {
    let mut v = Vec::new();
    for gamma in gammas(p) {
        for psi in PSIS {
            for (gd, pd) in RATES {
                let (q, qd) = (Vector2::new(gamma, psi), Vector2::new(gd, pd));
                let pose = Pose::try_new(p, gamma, psi).unwrap();
                let t = friction_directions(&pose.kinematics(qd)).unwrap();
                v.push(State { q, qd, pose, t });
            }
        }
    }
    v
}

fn x4(s: &State) -> SVector<f64, 4> {
    SVector::<f64, 4>::new(s.q[0], s.q[1], s.qd[0], s.qd[1])
}

fn t9(t: &[Vector3<f64>; 3]) -> SVector<f64, 9> {
    SVector::<f64, 9>::from_iterator(t.iter().flat_map(|v| v.iter().copied()))
}

/// The hand 5×5 system reduced to the planar unknowns: rows (γ, η, z),
/// columns (first, N_K, N_B1 + N_B2).
fn reduce((a, b): (Matrix5, Vector5)) -> (SMatrix<f64, 3, 3>, SVector<f64, 3>) {
    let rows = [0, 2, 4];
    let ar = SMatrix::<f64, 3, 3>::from_fn(|i, j| match j {
        0 => a[(rows[i], 0)],
        1 => a[(rows[i], 2)],
        _ => a[(rows[i], 3)] + a[(rows[i], 4)],
    });
    (ar, SVector::<f64, 3>::from_fn(|i, _| b[rows[i]]))
}

/// Asserts generated [forward, prescribed] systems (A, b) equal the hand
/// ones to [`TOL`]: parts 0–3 normwise (A and b of each), parts 4–5 row by
/// row; `worst` keeps the largest normwise and row-wise differences.
fn compare<const N: usize>(
    generated: [(&SMatrix<f64, N, N>, &SVector<f64, N>); 2],
    hand: [(&SMatrix<f64, N, N>, &SVector<f64, N>); 2],
    worst: &mut [f64; 2],
    context: std::fmt::Arguments,
) {
    let [(ga, gb), (pa, pb)] = generated;
    let [(fa, fb), (ha, hb)] = hand;
    let errs = [
        rel(ga, fa),
        rel(gb, fb),
        rel(pa, ha),
        rel(pb, hb),
        rowwise((ga, gb), (fa, fb)),
        rowwise((pa, pb), (ha, hb)),
    ];
    for (k, e) in errs.iter().enumerate() {
        assert!(*e < TOL, "{context}: part {k} rel {e:e}");
        worst[k / 4] = worst[k / 4].max(*e);
    }
}

#[test]
fn two_dof_systems_equal_the_hand_derived_systems() {
    let mut worst = [0.0f64; 2];
    for friction in [0.2, 0.0] {
        let p = PegParams {
            friction,
            ..PegParams::fig9()
        };
        let (pv, lv) = (p.to_vector(), loads().to_vector());
        let qdd = Vector2::new(3.0, -40.0);
        for s in states(&p) {
            let (fa, fb) = forward_system(&p, &loads(), &s.pose, s.qd, &s.t);
            let (ha, hb) = prescribed_system(&p, &loads(), &s.pose, s.qd, qdd, &s.t);
            let x = x4(&s);
            let (ga, gb, pa, pb) = if friction > 0.0 {
                let t = t9(&s.t);
                let LinearSystem { a: ga, b: gb } = rigid_peg::forward(&x, &pv, &lv, &t);
                let LinearSystem { a: pa, b: pb } = rigid_peg::prescribed(&x, &qdd, &pv, &lv, &t);
                (ga, gb, pa, pb)
            } else {
                let LinearSystem { a: ga, b: gb } = rigid_peg_frictionless::forward(&x, &pv, &lv);
                let LinearSystem { a: pa, b: pb } =
                    rigid_peg_frictionless::prescribed(&x, &qdd, &pv, &lv);
                (ga, gb, pa, pb)
            };
            compare(
                [(&ga, &gb), (&pa, &pb)],
                [(&fa, &fb), (&ha, &hb)],
                &mut worst,
                format_args!("f = {friction}, {:?}", s.q),
            );
        }
    }
    eprintln!(
        "2-DOF generated vs hand: worst normwise {:e}, worst row-wise {:e}",
        worst[0], worst[1]
    );
}

#[test]
fn planar_systems_equal_the_hand_derived_systems_at_psi_zero() {
    let mut worst = [0.0f64; 2];
    for friction in [0.2, 0.0] {
        let p = PegParams {
            friction,
            ..PegParams::fig9()
        };
        let l = planar_loads();
        let (pv, lv) = (
            p.to_vector(),
            SVector::<f64, 3>::new(l.m_gamma, l.force[0], l.force[2]),
        );
        let qdd = Vector2::new(3.0, 0.0);
        for gamma in gammas(&p) {
            for gd in [-2.0, 1.5] {
                let (q, qd) = (Vector2::new(gamma, 0.0), Vector2::new(gd, 0.0));
                let pose = Pose::try_new(&p, gamma, 0.0).unwrap();
                let t = friction_directions(&pose.kinematics(qd)).unwrap();
                let (fa, fb) = reduce(forward_system(&p, &l, &pose, qd, &t));
                let (ha, hb) = reduce(prescribed_system(&p, &l, &pose, qd, qdd, &t));
                let (x, qdd1) = (
                    SVector::<f64, 2>::new(gamma, gd),
                    SVector::<f64, 1>::new(qdd[0]),
                );
                let (ga, gb, pa, pb) = if friction > 0.0 {
                    let t4 = SVector::<f64, 4>::new(t[0].x, t[0].z, t[1].x, t[1].z);
                    let PlanarSystem { a: ga, b: gb } =
                        rigid_peg_planar::forward(&x, &pv, &lv, &t4);
                    let PlanarSystem { a: pa, b: pb } =
                        rigid_peg_planar::prescribed(&x, &qdd1, &pv, &lv, &t4);
                    (ga, gb, pa, pb)
                } else {
                    let PlanarSystem { a: ga, b: gb } =
                        rigid_peg_planar_frictionless::forward(&x, &pv, &lv);
                    let PlanarSystem { a: pa, b: pb } =
                        rigid_peg_planar_frictionless::prescribed(&x, &qdd1, &pv, &lv);
                    (ga, gb, pa, pb)
                };
                compare(
                    [(&ga, &gb), (&pa, &pb)],
                    [(&fa, &fb), (&ha, &hb)],
                    &mut worst,
                    format_args!("f = {friction}, {q:?}"),
                );
            }
        }
    }
    eprintln!(
        "planar generated vs hand: worst normwise {:e}, worst row-wise {:e}",
        worst[0], worst[1]
    );
}

#[test]
fn contact_velocities_and_energies_equal_the_hand_derived_ones() {
    let p = PegParams::fig9();
    let pv = p.to_vector();
    for s in states(&p) {
        let kin = s.pose.kinematics(s.qd);
        let want = SMatrix::<f64, 3, 3>::from_fn(|i, k| kin.v_contacts_local[i][k]);
        let x = x4(&s);
        let got = rigid_peg::contact_velocities(&x, &pv);
        assert!(rel(&got, &want) < TOL, "{:?}: v {got} vs {want}", s.q);
        let got_f = rigid_peg_frictionless::contact_velocities(&x, &pv);
        assert!(rel(&got_f, &want) < TOL);
        let t = kinetic_energy(&p, &s.pose, &kin);
        let v = potential_energy(&p, &s.pose);
        for rigid_peg::EnergyOut { kinetic, total } in [
            rigid_peg::energy(&x, &pv),
            rigid_peg_frictionless::energy(&x, &pv),
        ] {
            assert!((kinetic - t).abs() < TOL * t, "T {kinetic} vs {t}");
            assert!((total - t - v).abs() < TOL * (t + v.abs()), "T + V");
        }
        if s.qd[1] == 0.0 || s.q[1] != 0.0 {
            continue;
        }
        // Planar: the same quantities at ψ = ψ̇ = 0.
        let pose0 = Pose::try_new(&p, s.q[0], 0.0).unwrap();
        let kin0 = pose0.kinematics(Vector2::new(s.qd[0], 0.0));
        let want0 = SMatrix::<f64, 3, 3>::from_fn(|i, k| kin0.v_contacts_local[i][k]);
        let x2 = SVector::<f64, 2>::new(s.q[0], s.qd[0]);
        for got in [
            rigid_peg_planar::contact_velocities(&x2, &pv),
            rigid_peg_planar_frictionless::contact_velocities(&x2, &pv),
        ] {
            assert!(rel(&got, &want0) < TOL, "planar v {got} vs {want0}");
        }
        let t0 = kinetic_energy(&p, &pose0, &kin0);
        let rigid_peg::EnergyOut { kinetic, total } = rigid_peg_planar::energy(&x2, &pv);
        assert!((kinetic - t0).abs() < TOL * t0);
        assert!((total - t0 - potential_energy(&p, &pose0)).abs() < TOL * total.abs().max(t0));
    }
}

#[test]
fn geometry_equals_the_hand_derived_geometry() {
    let p = PegParams::fig9();
    for gamma in gammas(&p).into_iter().chain([0.05, 0.3, 0.9]) {
        let h = pegdyn::rigid_peg::kinematics::Geometry::try_new(&p, gamma).unwrap();
        let (eta_l, z_l) = h.centre_l();
        let want = [
            h.a1, h.a2, h.s1, h.s2, h.b, h.sin_tau, h.cos_tau, h.eta_c, h.z_c, h.kl, h.bl, eta_l,
            z_l,
        ];
        let x = SVector::<f64, 4>::new(gamma, 0.3, 1.0, 1.0);
        let got = rigid_peg::geometry(&x, &p.to_vector());
        for (k, (g, w)) in got.iter().zip(want).enumerate() {
            // Each quantity to 1e-12 of itself, S2 too where it is small (near 0.3 rad).
            assert!(
                (g - w).abs() <= TOL * w.abs(),
                "γ = {gamma}, output {k}: {g} vs {w}"
            );
        }
    }
}

#[test]
fn mass_block_reproduces_the_kinetic_energy_22_23() {
    let p = PegParams::fig9();
    let (pv, lv) = (p.to_vector(), loads().to_vector());
    let (it, ia, m) = (p.inertia_transverse(), p.inertia_axial(), p.mass);
    let mut rng = Rng(7);
    for _ in 0..200 {
        let gamma = rng.uniform(p.gamma0() * 1.0001, 1.5);
        let q = Vector2::new(gamma, rng.uniform(-3.0, 3.0));
        let qd = Vector2::new(rng.uniform(-5.0, 5.0), rng.uniform(-20.0, 20.0));
        let pose = Pose::try_new(&p, q[0], q[1]).unwrap();
        let x = SVector::<f64, 4>::new(q[0], q[1], qd[0], qd[1]);
        let a = rigid_peg::forward(&x, &pv, &lv, &SVector::<f64, 9>::zeros()).a;
        let mass = a.fixed_view::<2, 2>(0, 0).into_owned();
        let t_m = 0.5 * qd.dot(&(mass * qd));
        // Rigid-body definition (hand, fixed-frame vectors).
        let t_body = kinetic_energy(&p, &pose, &pose.kinematics(qd));
        // The paper's (22)–(23) with the corrected symbols.
        let g = &pose.geo;
        let (s, c) = gamma.sin_cos();
        let i_o1z = it * s * s + ia * c * c + m * g.eta_c * g.eta_c;
        let t_paper = 0.5 * m * (g.deta_c.powi(2) + g.dz_c.powi(2)) * qd[0].powi(2)
            + 0.5 * it * qd[0].powi(2)
            + 0.5 * i_o1z * qd[1].powi(2);
        assert!(
            (t_m - t_body).abs() < TOL * t_body,
            "½q̇ᵀMq̇ = {t_m}, T = {t_body}"
        );
        assert!((t_m - t_paper).abs() < TOL * t_body, "(22)–(23): {t_paper}");
        assert_eq!(mass[(0, 1)], 0.0, "M is diagonal in (γ, ψ)");
        assert_eq!(mass[(1, 0)], 0.0);
        let x2 = SVector::<f64, 2>::new(q[0], qd[0]);
        let a1 = rigid_peg_planar_frictionless::forward(&x2, &pv, &SVector::<f64, 3>::zeros()).a;
        assert!((a1[(0, 0)] - mass[(0, 0)]).abs() < TOL * mass[(0, 0)]);
    }
}
