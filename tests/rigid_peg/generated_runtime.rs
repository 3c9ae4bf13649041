//! Rigid three-point peg, the runtime of the generated model (`rigid_peg::generated_model`):
//! the variants agree with each other where they overlap (2-DOF with ψ̇ ≡ 0
//! = planar; frictionless = full with f = 0), the solutions equal the
//! hand-derived ones, the symmetric contacts carry equal loads without
//! precession, reactions scale with m g, and each variant refuses what it
//! cannot represent.

use nalgebra::{Vector2, Vector3};
use pegdyn::generated::{rigid_peg, rigid_peg_frictionless};
use pegdyn::rigid_peg::dynamics::{self, forward_system};
use pegdyn::rigid_peg::generated_model::{
    Variant, contact_velocities, forward, friction_directions, prescribed,
};
use pegdyn::rigid_peg::kinematics::Pose;
use pegdyn::rigid_peg::prescribed::{reactions, reactions_hand};
use pegdyn::rigid_peg::{Loads, PegParams, RigidError};

use crate::common;
use common::rigid::{gammas, loads, planar_loads};

fn directions(v: Variant, p: &PegParams, q: Vector2<f64>, qd: Vector2<f64>) -> [Vector3<f64>; 3] {
    friction_directions(&contact_velocities(v, p, q, qd).unwrap()).unwrap()
}

fn close(a: f64, b: f64, tol: f64, scale: f64) -> bool {
    (a - b).abs() <= tol * scale
}

#[test]
fn two_dof_model_without_precession_reproduces_the_planar_variant() {
    for friction in [0.2, 0.0] {
        let p = PegParams {
            friction,
            ..PegParams::fig9()
        };
        let (two, one) = if friction > 0.0 {
            (Variant::Full, Variant::Planar)
        } else {
            (Variant::Frictionless, Variant::PlanarFrictionless)
        };
        for gamma in gammas(&p) {
            for gd in [-2.0, 1.5] {
                let (q, qd) = (Vector2::new(gamma, 0.0), Vector2::new(gd, 0.0));
                let t = directions(two, &p, q, qd);
                let a = forward(two, &p, &planar_loads(), q, qd, &t).unwrap();
                let b = forward(one, &p, &planar_loads(), q, qd, &t).unwrap();
                let scale = b.normal.iter().fold(1.0f64, |m, n| m.max(n.abs()));
                assert!(close(a.qdd[0], b.qdd[0], 1e-9, b.qdd[0].abs().max(1.0)));
                assert!(
                    a.qdd[1].abs() < 1e-9 * b.qdd[0].abs().max(1.0),
                    "ψ̈ = {}",
                    a.qdd[1]
                );
                for i in 0..3 {
                    assert!(
                        close(a.normal[i], b.normal[i], 1e-9, scale),
                        "γ = {gamma}: N{i} {} vs {}",
                        a.normal[i],
                        b.normal[i]
                    );
                }
                assert_eq!(b.normal[1], b.normal[2], "planar: N_B1 = N_B2 = N_B");
            }
        }
    }
}

#[test]
fn forward_solutions_equal_the_hand_derived_solutions() {
    let p = PegParams::fig9();
    let loads = loads();
    for gamma in [0.1, 0.5, 1.2] {
        for psi in [0.0, 0.7, -2.0] {
            for (gd, pd) in [(-2.0, 10.0), (1.5, -3.0)] {
                let (q, qd) = (Vector2::new(gamma, psi), Vector2::new(gd, pd));
                let pose = Pose::try_new(&p, gamma, psi).unwrap();
                let t = dynamics::friction_directions(&pose.kinematics(qd)).unwrap();
                let (a, b) = forward_system(&p, &loads, &pose, qd, &t);
                let want = dynamics::solve(&a, &b, gamma).unwrap();
                let got = forward(Variant::Full, &p, &loads, q, qd, &t).unwrap();
                let got = [
                    got.qdd[0],
                    got.qdd[1],
                    got.normal[0],
                    got.normal[1],
                    got.normal[2],
                ];
                for k in 0..5 {
                    assert!(
                        close(got[k], want[k], 1e-10, want.amax()),
                        "{k}: {} vs {}",
                        got[k],
                        want[k]
                    );
                }
            }
        }
    }
}

#[test]
fn generated_reactions_equal_hand_reactions_and_invert_forward_dynamics() {
    let p = PegParams::fig9();
    let loads = Loads {
        force: [0.3, -0.2, 1.5],
        ..Loads::default()
    };
    for gamma in gammas(&p) {
        for (psi, qd) in [(0.0, (-2.0, 10.0)), (0.7, (1.5, -3.0)), (-2.0, (-2.0, 0.0))] {
            let (q, qd) = (Vector2::new(gamma, psi), Vector2::new(qd.0, qd.1));
            let qdd = Vector2::new(3.0, if qd[1] == 0.0 { 0.0 } else { -40.0 });
            let r = reactions(&p, &loads, q, qd, qdd).unwrap();
            let h = reactions_hand(&p, &loads, q, qd, qdd).unwrap();
            let scale = h.normal.iter().fold(1.0f64, |m, n| m.max(n.abs()));
            for i in 0..3 {
                assert!(
                    close(r.normal[i], h.normal[i], 1e-9, scale),
                    "N{i} at {q:?}"
                );
            }
            // Near γ0 the lateral force is balanced by large opposite N_B1,
            // N_B2: measure the moments against the reactions' moment scale.
            let moment_scale = (scale * p.hole_diameter).max(h.m_gamma.abs());
            assert!(
                close(r.m_gamma, h.m_gamma, 1e-9, moment_scale),
                "{q:?}: {r:?} vs {h:?}"
            );
            assert!(
                close(r.m_psi, h.m_psi, 1e-9, moment_scale),
                "{q:?}: {r:?} vs {h:?}"
            );
            let driven = Loads {
                m_gamma: r.m_gamma,
                m_psi: r.m_psi,
                ..loads
            };
            let t = directions(Variant::Full, &p, q, qd);
            let a = forward(Variant::Full, &p, &driven, q, qd, &t).unwrap();
            assert!(close(a.qdd[0], qdd[0], 1e-7, 1.0 + qdd.amax()), "{a:?}");
            assert!(close(a.qdd[1], qdd[1], 1e-7, 1.0 + qdd.amax()), "{a:?}");
        }
    }
}

#[test]
fn symmetric_contacts_carry_equal_loads_without_precession() {
    let p = PegParams::fig9();
    for gamma in gammas(&p) {
        let q = Vector2::new(gamma, 0.7);
        let qd = Vector2::new(-2.0, 0.0);
        let t = directions(Variant::Full, &p, q, qd);
        let a = forward(Variant::Full, &p, &Loads::default(), q, qd, &t).unwrap();
        let [_, b1, b2] = a.normal;
        assert!(
            (b1 - b2).abs() < 1e-9 * b1.abs(),
            "{b1} vs {b2} at γ = {gamma}"
        );
    }
}

#[test]
fn reactions_over_weight_do_not_depend_on_mass() {
    let light = PegParams::fig9();
    let heavy = PegParams { mass: 7.3, ..light };
    for v in Variant::ALL {
        let (pl, ph) = if v.has_friction() {
            (light, heavy)
        } else {
            (
                PegParams {
                    friction: 0.0,
                    ..light
                },
                PegParams {
                    friction: 0.0,
                    ..heavy
                },
            )
        };
        for gamma in gammas(&light) {
            let q = Vector2::new(gamma, 0.0);
            let qd = Vector2::new(-2.0, if v.is_planar() { 0.0 } else { 10.0 });
            let t = directions(v, &pl, q, qd);
            let a = prescribed(v, &pl, &Loads::default(), q, qd, Vector2::zeros(), &t).unwrap();
            let b = prescribed(v, &ph, &Loads::default(), q, qd, Vector2::zeros(), &t).unwrap();
            let scale = a.normal.iter().fold(0.0f64, |m, n| m.max(n.abs())) / pl.mass;
            for i in 0..3 {
                let (x, y) = (a.normal[i] / pl.mass, b.normal[i] / ph.mass);
                assert!(close(x, y, 1e-12, scale), "{v:?} N{i}/m: {x} vs {y}");
            }
            let mg = a.m_gamma / pl.mass;
            assert!(close(mg, b.m_gamma / ph.mass, 1e-12, mg.abs().max(1e-3)));
        }
    }
}

/// Entries within 1e-13 of the larger of 1 and the largest entry.
fn assert_close<const R: usize, const C: usize>(
    u: &nalgebra::SMatrix<f64, R, C>,
    v: &nalgebra::SMatrix<f64, R, C>,
    gamma: f64,
) {
    let scale = u.abs().max().max(1.0);
    assert!(
        (u - v).abs().max() <= 1e-13 * scale,
        "γ = {gamma}: {u} vs {v}"
    );
}

#[test]
fn frictionless_variant_is_the_full_variant_with_f_zero() {
    let p = PegParams {
        friction: 0.0,
        ..PegParams::fig9()
    };
    let (pv, lv) = (p.to_vector(), planar_loads().to_vector());
    for gamma in gammas(&p) {
        for (psi, gd, pd) in [(0.0, -2.0, 10.0), (0.7, 1.5, -3.0)] {
            let x = nalgebra::SVector::<f64, 4>::new(gamma, psi, gd, pd);
            let t = nalgebra::SVector::<f64, 9>::from_fn(|k, _| (k as f64 * 0.37).sin());
            let rigid_peg::LinearSystem { a, b } = rigid_peg::forward(&x, &pv, &lv, &t);
            let rigid_peg::LinearSystem { a: af, b: bf } =
                rigid_peg_frictionless::forward(&x, &pv, &lv);
            // Same values; the two modules are lowered apart (the full one
            // factors its friction terms), so they round differently.
            assert_close(&a, &af, gamma);
            assert_close(&b, &bf, gamma);
            let qdd = Vector2::new(1.0, -2.0);
            let full = rigid_peg::prescribed(&x, &qdd, &pv, &lv, &t);
            let frictionless = rigid_peg_frictionless::prescribed(&x, &qdd, &pv, &lv);
            assert_close(&full.a, &frictionless.a, gamma);
            assert_close(&full.b, &frictionless.b, gamma);
        }
    }
}

#[test]
fn smallest_variant_follows_the_scene() {
    let p = PegParams::fig9();
    let p0 = PegParams { friction: 0.0, ..p };
    let none = Loads::default();
    let lateral = Loads {
        force: [0.0, 0.1, 0.0],
        ..none
    };
    let twist = Loads { m_psi: 0.1, ..none };
    assert_eq!(Variant::smallest(&p, &none, true), Variant::Planar);
    assert_eq!(
        Variant::smallest(&p0, &none, true),
        Variant::PlanarFrictionless
    );
    assert_eq!(Variant::smallest(&p, &none, false), Variant::Full);
    assert_eq!(Variant::smallest(&p0, &none, false), Variant::Frictionless);
    assert_eq!(Variant::smallest(&p, &lateral, true), Variant::Full);
    assert_eq!(Variant::smallest(&p0, &twist, true), Variant::Frictionless);
    assert_eq!(
        Variant::smallest(&p, &planar_loads(), true),
        Variant::Planar
    );
    // At ψ = π/2 the fixed y axis lies in the symmetry plane.
    let half_pi = std::f64::consts::FRAC_PI_2;
    assert_eq!(
        Variant::smallest_at(&p, &planar_loads(), half_pi, true),
        Variant::Full
    );
}

#[test]
fn variants_refuse_what_they_cannot_represent() {
    let p = PegParams::fig9();
    let (q, qd) = (Vector2::new(0.3, 0.0), Vector2::new(-2.0, 1.0));
    let t = directions(Variant::Full, &p, q, qd);
    let unrep = |r: Result<_, RigidError>| matches!(r, Err(RigidError::Unrepresentable { .. }));
    assert!(unrep(forward(
        Variant::Frictionless,
        &p,
        &Loads::default(),
        q,
        qd,
        &t
    )));
    assert!(unrep(forward(
        Variant::Planar,
        &p,
        &Loads::default(),
        q,
        qd,
        &t
    )));
    let qd0 = Vector2::new(-2.0, 0.0);
    let t0 = directions(Variant::Planar, &p, q, qd0);
    let lateral = Loads {
        force: [0.0, 0.1, 0.0],
        ..Loads::default()
    };
    assert!(unrep(forward(Variant::Planar, &p, &lateral, q, qd0, &t0)));
    let twisted = [t0[0], t0[1], Vector3::new(t0[2].x, 0.1, t0[2].z)];
    assert!(unrep(forward(
        Variant::Planar,
        &p,
        &Loads::default(),
        q,
        qd0,
        &twisted
    )));
    let qdd = Vector2::new(0.0, 1.0);
    let r = prescribed(Variant::Planar, &p, &Loads::default(), q, qd0, qdd, &t0);
    assert!(
        matches!(r, Err(RigidError::Unrepresentable { .. })),
        "{r:?}"
    );
    for gamma in [p.gamma0(), 0.0, 2.0, f64::NAN] {
        let r = forward(
            Variant::Full,
            &p,
            &Loads::default(),
            Vector2::new(gamma, 0.0),
            qd,
            &t,
        );
        assert!(
            matches!(
                r,
                Err(RigidError::NotThreePoint { .. }) | Err(RigidError::Param { .. })
            ),
            "{r:?}"
        );
    }
    let r = forward(
        Variant::Full,
        &p,
        &Loads::default(),
        q,
        Vector2::new(f64::INFINITY, 0.0),
        &t,
    );
    assert!(
        matches!(r, Err(RigidError::Param { field: "qdot", .. })),
        "{r:?}"
    );
    let bad = PegParams {
        peg_diameter: 0.06,
        ..p
    };
    let r = forward(Variant::Full, &bad, &Loads::default(), q, qd, &t);
    assert!(matches!(
        r,
        Err(RigidError::Param {
            field: "peg_diameter",
            ..
        })
    ));
    let r = reactions(&p, &Loads::default(), q, Vector2::zeros(), Vector2::zeros());
    assert!(matches!(r, Err(RigidError::NoSliding { .. })), "{r:?}");
}
