//! Rigid three-point peg dynamics (hand-derived forms): the paper's kinetic energy
//! (22)–(23) is the exact rigid-body energy, the mass matrix and velocity
//! terms are the Lagrange derivatives of that energy, the forward and the
//! prescribed-motion systems are inverse to each other, and the reactions
//! have the symmetries and scaling the physics demands.

use nalgebra::Vector2;
use pegdyn::rigid_peg::dynamics::{
    forward_system, friction_directions, kinetic_energy, mass_matrix, solve, velocity_terms,
};
use pegdyn::rigid_peg::kinematics::Pose;
use pegdyn::rigid_peg::prescribed::reactions;
use pegdyn::rigid_peg::{Loads, PegParams, RigidError};

fn states(p: &PegParams) -> Vec<(Vector2<f64>, Vector2<f64>)> {
    let g0 = p.gamma0();
    let mut v = Vec::new();
    for gamma in [g0 * (1.0 + 1e-9), g0 * 1.001, 0.07, 0.2, 0.5, 1.0] {
        for (psi, qd) in [(0.0, (-2.0, 10.0)), (1.1, (1.5, -3.0)), (-2.0, (-0.3, 0.7))] {
            v.push((Vector2::new(gamma, psi), Vector2::new(qd.0, qd.1)));
        }
    }
    v
}

/// T from the paper's (22)–(23) with the corrected symbols.
fn paper_energy(p: &PegParams, pose: &Pose, qd: Vector2<f64>) -> f64 {
    let g = &pose.geo;
    let (s, c) = g.gamma.sin_cos();
    let v2 = (g.deta_c.powi(2) + g.dz_c.powi(2)) * qd[0].powi(2);
    let i_o1z =
        p.inertia_transverse() * s * s + p.inertia_axial() * c * c + p.mass * g.eta_c.powi(2);
    0.5 * p.mass * v2 + 0.5 * p.inertia_transverse() * qd[0].powi(2) + 0.5 * i_o1z * qd[1].powi(2)
}

#[test]
fn paper_kinetic_energy_is_the_exact_rigid_body_energy() {
    let p = PegParams::fig9();
    for (q, qd) in states(&p) {
        let pose = Pose::try_new(&p, q[0], q[1]).unwrap();
        let exact = kinetic_energy(&p, &pose, &pose.kinematics(qd));
        let paper = paper_energy(&p, &pose, qd);
        assert!(
            (exact - paper).abs() <= 1e-13 * exact,
            "T = {exact} vs (22) = {paper} at {q:?}"
        );
    }
}

#[test]
fn mass_matrix_and_velocity_terms_are_lagrange_derivatives_of_t() {
    // d/dt ∂T/∂q̇ − ∂T/∂q along a path with q̈ = 0 equals h; ∂²T/∂q̇² = M.
    let p = PegParams::fig9();
    let t = |q: Vector2<f64>, qd: Vector2<f64>| {
        let pose = Pose::try_new(&p, q[0], q[1]).unwrap();
        kinetic_energy(&p, &pose, &pose.kinematics(qd))
    };
    let e = [Vector2::new(1.0, 0.0), Vector2::new(0.0, 1.0)];
    for (q, qd) in states(&p) {
        if q[0] < p.gamma0() * 1.01 {
            continue; // finite differences would step below γ0
        }
        let pose = Pose::try_new(&p, q[0], q[1]).unwrap();
        let m = mass_matrix(&p, &pose);
        let h = velocity_terms(&p, &pose, qd);
        let (hq, hv) = (1e-5, 0.5); // T is quadratic in q̇: any hv is exact
        let dt_dqd =
            |q: Vector2<f64>, j: usize| (t(q, qd + e[j] * hv) - t(q, qd - e[j] * hv)) / (2.0 * hv);
        for j in 0..2 {
            for k in 0..2 {
                let d2 = (t(q, qd + e[j] * hv + e[k] * hv)
                    - t(q, qd + e[j] * hv - e[k] * hv)
                    - t(q, qd - e[j] * hv + e[k] * hv)
                    + t(q, qd - e[j] * hv - e[k] * hv))
                    / (4.0 * hv * hv);
                assert!((d2 - m[(j, k)]).abs() < 1e-9 * m.norm(), "M[{j},{k}]");
            }
            let ddt = (dt_dqd(q + qd * hq, j) - dt_dqd(q - qd * hq, j)) / (2.0 * hq);
            let dtdq = (t(q + e[j] * hq, qd) - t(q - e[j] * hq, qd)) / (2.0 * hq);
            let scale = m.norm() * qd.norm_squared();
            assert!(
                (ddt - dtdq - h[j]).abs() < 1e-6 * scale,
                "h[{j}] = {} vs FD {}",
                h[j],
                ddt - dtdq
            );
        }
    }
}

#[test]
fn forward_problem_inverts_prescribed_motion() {
    let p = PegParams::fig9();
    for (q, qd) in states(&p) {
        let qdd = Vector2::new(3.0, -40.0);
        let force = Loads {
            m_gamma: 0.0,
            m_psi: 0.0,
            force: [0.3, -0.2, 1.5],
        };
        let r = reactions(&p, &force, q, qd, qdd).unwrap();
        let loads = Loads {
            m_gamma: r.m_gamma,
            m_psi: r.m_psi,
            ..force
        };
        let pose = Pose::try_new(&p, q[0], q[1]).unwrap();
        let t = friction_directions(&pose.kinematics(qd)).unwrap();
        let (a, rhs) = forward_system(&p, &loads, &pose, qd, &t);
        let x = solve(&a, &rhs, q[0]).unwrap();
        let tol = 1e-8 * (1.0 + x.amax());
        assert!(
            (x[0] - qdd[0]).abs() < tol && (x[1] - qdd[1]).abs() < tol,
            "q̈ = {x} at {q:?}"
        );
        for i in 0..3 {
            assert!((x[2 + i] - r.normal[i]).abs() < 1e-8 * (1.0 + r.normal[i].abs()));
        }
    }
}

#[test]
fn symmetric_contacts_carry_equal_loads_without_precession() {
    let p = PegParams::fig9();
    for gamma in [p.gamma0() * (1.0 + 1e-9), 0.05, 0.3, 0.9] {
        let r = reactions(
            &p,
            &Loads::default(),
            Vector2::new(gamma, 0.7),
            Vector2::new(-2.0, 0.0),
            Vector2::zeros(),
        )
        .unwrap();
        let [_, b1, b2] = r.normal;
        assert!(
            (b1 - b2).abs() < 1e-9 * b1.abs(),
            "N_B1 = {b1}, N_B2 = {b2} at γ = {gamma}"
        );
        assert!(
            r.m_psi.abs() < 1e-9 * r.m_gamma.abs().max(1e-3),
            "M_ψ = {}",
            r.m_psi
        );
        assert!(b1 > 0.0);
    }
}

#[test]
fn reactions_over_weight_do_not_depend_on_mass() {
    let light = PegParams::fig9();
    let heavy = PegParams { mass: 7.3, ..light };
    for (q, qd) in states(&light) {
        let a = reactions(&light, &Loads::default(), q, qd, Vector2::zeros()).unwrap();
        let b = reactions(&heavy, &Loads::default(), q, qd, Vector2::zeros()).unwrap();
        for i in 0..3 {
            let (x, y) = (a.normal[i] / light.mass, b.normal[i] / heavy.mass);
            assert!(
                (x - y).abs() < 1e-9 * x.abs().max(1.0),
                "N_{i}/m: {x} vs {y}"
            );
        }
        assert!(
            (a.m_gamma / light.mass - b.m_gamma / heavy.mass).abs()
                < 1e-9 * (a.m_gamma / light.mass).abs().max(1e-3)
        );
    }
}

#[test]
fn states_outside_three_point_contact_are_refused() {
    let p = PegParams::fig9();
    let g0 = p.gamma0();
    for gamma in [g0, g0 * (1.0 - 1e-12), 0.0, -0.1, 2.0] {
        let err = reactions(
            &p,
            &Loads::default(),
            Vector2::new(gamma, 0.0),
            Vector2::new(-2.0, 0.0),
            Vector2::zeros(),
        );
        assert!(
            matches!(err, Err(RigidError::NotThreePoint { .. })),
            "{err:?}"
        );
    }
    let err = reactions(
        &p,
        &Loads::default(),
        Vector2::new(0.3, 0.0),
        Vector2::zeros(),
        Vector2::zeros(),
    );
    assert!(matches!(err, Err(RigidError::NoSliding { .. })));
    let bad = PegParams {
        peg_diameter: 0.05,
        ..p
    };
    assert!(matches!(
        bad.validate(),
        Err(RigidError::Param {
            field: "peg_diameter",
            ..
        })
    ));
}

#[test]
fn gamma0_is_arccos_d_over_d() {
    let p = PegParams::fig9();
    let g0 = (p.peg_diameter / p.hole_diameter).acos();
    assert!((p.gamma0() - g0).abs() < 1e-12, "{} vs {g0}", p.gamma0());
    assert!((p.gamma0() - 0.044725).abs() < 1e-6);
}
