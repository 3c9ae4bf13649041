//! Contact modes and Painlevé cases of the rigid three-point peg: without
//! friction the contact problem is a symmetric positive definite LCP (one
//! mode); with f = 0.2 a tipping peg (γ̇ > 0) has no consistent mode at all,
//! the paper's Fig. 9 state without rotation is indeterminate, and a forward
//! run driven towards a singular contact system is stopped and reported.

use nalgebra::{Vector2, Vector4};
use pegdyn::integrate::{Method, Options};
use pegdyn::rigid_peg::forward::ForwardModel;
use pegdyn::rigid_peg::forward_events::N_JAM;
use pegdyn::rigid_peg::modes::{Verdict, classify, contact_problem};
use pegdyn::rigid_peg::prescribed::reactions;
use pegdyn::rigid_peg::stop::{ForwardStop, PainleveCase};
use pegdyn::rigid_peg::trajectory::simulate;
use pegdyn::rigid_peg::{Loads, PegParams};

/// W = G M⁻¹ Gᵀ without friction: symmetric and positive definite (the
/// three normals are independent), so exactly one mode is consistent.
#[test]
fn frictionless_contact_problem_is_symmetric_positive_definite() {
    let p = PegParams {
        friction: 0.0,
        ..PegParams::fig9()
    };
    let m = ForwardModel::new(p, Loads::default()).unwrap();
    for gamma in [p.gamma0() * 1.001, 0.07, 0.3, 1.0] {
        for qd in [(1.0, 0.0), (-1.0, 3.0), (0.2, -10.0)] {
            let (q, qdot) = (Vector2::new(gamma, 0.4), Vector2::new(qd.0, qd.1));
            let w = contact_problem(&m, q, qdot).unwrap().w_matrix;
            assert!((w - w.transpose()).amax() < 1e-9 * w.amax(), "{w}");
            assert!(w.symmetric_eigenvalues().min() > 0.0, "{w}");
            let v = classify(&m, q, qdot).unwrap();
            assert!(
                matches!(v, Verdict::ThreePoint | Verdict::LiftOff(_)),
                "{v:?}"
            );
        }
    }
}

/// Tipping (γ̇ > 0, ψ̇ = 0) at γ = 0.0932 rad with f = 0.2: the forward
/// determinant is negative and no contact mode is consistent (K and the B
/// edge wedge the peg through friction). With f = 0.05 the same state is
/// consistent. The simulation refuses to start and reports it.
#[test]
fn tipping_with_friction_has_no_consistent_mode() {
    let state = Vector4::new(0.0932, 0.0, 1.0, 0.0);
    let (q, qdot) = (
        Vector2::new(state[0], state[1]),
        Vector2::new(state[2], state[3]),
    );
    let rough = ForwardModel::new(PegParams::fig9(), Loads::default()).unwrap();
    assert!(rough.contact_determinant(&state, None) < 0.0);
    assert_eq!(classify(&rough, q, qdot).unwrap(), Verdict::Inconsistent);
    let smooth = ForwardModel::new(
        PegParams {
            friction: 0.05,
            ..PegParams::fig9()
        },
        Loads::default(),
    )
    .unwrap();
    assert!(smooth.contact_determinant(&state, None) > 0.0);
    assert!(matches!(
        classify(&smooth, q, qdot).unwrap(),
        Verdict::ThreePoint | Verdict::LiftOff(_)
    ));
    let tr = simulate(&rough, state, 0.0, 0.1, Method::Dopri5, &Options::default()).unwrap();
    assert_eq!(
        tr.stop,
        ForwardStop::Painleve {
            t: 0.0,
            state,
            case: PainleveCase::Inconsistent
        }
    );
}

/// The paper's case (i) near γ0 (γ̇ = −2, ψ̇ = 0, driven by the moment
/// Fig. 9 needs): the three-point solution (N_B1 = 5.77 m g) is one of two
/// consistent modes; the other keeps only K. With ψ̇ = 10 1/s the
/// determinant is positive: precession turns the friction at the contacts
/// sideways and removes the indeterminacy.
#[test]
fn fig9_without_rotation_is_indeterminate_near_gamma0() {
    let p = PegParams::fig9();
    let q = Vector2::new(p.gamma0() * (1.0 + 1e-6), 0.0);
    let driven = |qdot: Vector2<f64>| {
        let r = reactions(&p, &Loads::default(), q, qdot, Vector2::zeros()).unwrap();
        ForwardModel::new(
            p,
            Loads {
                m_gamma: r.m_gamma,
                m_psi: r.m_psi,
                ..Loads::default()
            },
        )
        .unwrap()
    };
    let still = Vector2::new(-2.0, 0.0);
    let m = driven(still);
    let x = Vector4::new(q[0], q[1], still[0], still[1]);
    assert!(m.contact_determinant(&x, None) < 0.0);
    let Verdict::Indeterminate(modes) = classify(&m, q, still).unwrap() else {
        panic!("expected several modes");
    };
    let sets: Vec<[bool; 3]> = modes.iter().map(|m| m.in_contact).collect();
    assert!(sets.contains(&[true, true, true]) && sets.contains(&[true, false, false]));
    let spun = Vector2::new(-2.0, 10.0);
    let x = Vector4::new(q[0], q[1], spun[0], spun[1]);
    assert!(driven(spun).contact_determinant(&x, None) > 0.0);
}

/// Tipping while precessing, the forward system's determinant runs to zero
/// from above and the reactions grow like 1/det: the run stops at the `jam`
/// event instead of failing in the integrator.
#[test]
fn approach_to_a_singular_contact_system_is_reported() {
    let p = PegParams::fig9();
    let m = ForwardModel::new(
        p,
        Loads {
            m_gamma: 0.3,
            ..Loads::default()
        },
    )
    .unwrap();
    let tr = simulate(
        &m,
        Vector4::new(0.05, 0.0, 0.5, 3.0),
        0.0,
        0.5,
        Method::Dopri5,
        &Options::with_tolerances(1e-10, 1e-12),
    )
    .unwrap();
    let ForwardStop::Painleve {
        state,
        case: PainleveCase::Unbounded,
        ..
    } = tr.stop
    else {
        panic!("{}", tr.stop);
    };
    let det = m.contact_determinant(&state, None);
    let n = m.evaluate(&state, None).unwrap().normal;
    let w = p.mass * p.gravity;
    assert!(det > 0.0 && det < 1e-5, "det {det}");
    assert!(n.iter().any(|&v| v >= 0.999 * N_JAM * w), "{n:?}");
    // Earlier in the run the determinant was much larger.
    let first = m.contact_determinant(&tr.rows[0].x, None);
    assert!(first > 100.0 * det, "{first} vs {det}");
}
