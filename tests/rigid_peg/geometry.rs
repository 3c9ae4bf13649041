//! Rigid three-point peg geometry and kinematics, checked from first principles in 3-D:
//! the contact points lie on the hole edge and on the peg's surface, an
//! independent Newton solve of the contact conditions reproduces the closed
//! forms (1)–(9), the material velocities equal finite-difference
//! derivatives of material points, and no contact has a penetration rate.

use nalgebra::{Matrix3, Rotation3, Unit, Vector2, Vector3};
use pegdyn::rigid_peg::PegParams;
use pegdyn::rigid_peg::kinematics::{Geometry, Pose};

fn peg() -> PegParams {
    PegParams::fig9()
}

/// γ grid from γ0(1 + 1e-9) to 1.2 rad and ψ grid over a full turn.
fn grid(p: &PegParams) -> Vec<(f64, f64)> {
    let g0 = p.gamma0();
    let gammas = [
        g0 * (1.0 + 1e-9),
        g0 * (1.0 + 1e-6),
        g0 * 1.01,
        g0 * 1.3,
        0.1,
        0.3,
        0.5,
        0.8,
        1.2,
    ];
    let psis = [0.0, 0.4, -1.3, 2.5, 3.9];
    gammas
        .iter()
        .flat_map(|&g| psis.iter().map(move |&s| (g, s)))
        .collect()
}

/// Rotation of the peg from its upright reference: R = Rz(ψ) Ry(−γ).
fn rotation(gamma: f64, psi: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&Vector3::z_axis(), psi)
        * Rotation3::from_axis_angle(&Vector3::y_axis(), -gamma)
}

#[test]
fn contact_points_lie_on_hole_edge_and_peg_surface() {
    let p = peg();
    let (half, r, h) = (0.5 * p.hole_diameter, p.radius(), p.height);
    let tol = 1e-12 * p.hole_diameter;
    for (gamma, psi) in grid(&p) {
        let pose = Pose::try_new(&p, gamma, psi).unwrap();
        let u = pose.axis;
        for (i, c) in pose.contacts.iter().enumerate() {
            // On the hole edge: z = 0, |ρ| = D/2.
            assert!(c.z.abs() < tol, "contact {i} z = {} at γ = {gamma}", c.z);
            assert!(
                (c.xy().norm() - half).abs() < tol,
                "contact {i} off the hole edge at γ = {gamma}"
            );
        }
        // K on the peg's side: distance r from the axis, axial coordinate in [0, H].
        let rk = pose.contacts[0] - pose.o2;
        let axial = rk.dot(&u);
        assert!(
            ((rk - u * axial).norm() - r).abs() < tol,
            "K off the side at γ = {gamma}"
        );
        assert!(axial > 0.0 && axial < h, "K beyond the peg's ends: {axial}");
        // B1, B2 on the rim of the bottom face: in its plane, at distance r from O2.
        for b in &pose.contacts[1..] {
            let rb = b - pose.o2;
            assert!(
                rb.dot(&u).abs() < tol,
                "B off the bottom plane at γ = {gamma}"
            );
            assert!(
                (rb.norm() - r).abs() < tol,
                "B off the rim at γ = {gamma}: {}",
                rb.norm() - r
            );
        }
        // B1 and B2 are mirror images about the symmetry plane (e_η, e_z).
        let n = pose.frame.n;
        let (b1, b2) = (pose.contacts[1], pose.contacts[2]);
        assert!((b1 - n * (2.0 * b1.dot(&n)) - b2).norm() < tol);
        // B1 leads for ψ̇ > 0: it lies ahead of the plane in the e_n direction.
        assert!(b1.dot(&n) > 0.0);
    }
}

/// Solves, by Newton with a finite-difference Jacobian, for the bottom centre
/// O2 = (η, z) and the rim angle θ of B1 such that the side generatrix
/// touches K = (−D/2, 0, 0) and the rim point lies on the hole-edge circle.
fn newton_contact(p: &PegParams, gamma: f64, x0: Vector3<f64>) -> Vector3<f64> {
    let (half, r) = (0.5 * p.hole_diameter, p.radius());
    let (s, c) = gamma.sin_cos();
    let u = Vector3::new(-s, 0.0, c);
    let w = Vector3::new(c, 0.0, s);
    let res = |x: &Vector3<f64>| {
        let o2 = Vector3::new(x[0], 0.0, x[1]);
        let k = Vector3::new(-half, 0.0, 0.0);
        let rk = k - o2;
        let dist = (rk - u * rk.dot(&u)).norm();
        let rim = o2 + (w * x[2].cos() + Vector3::y() * x[2].sin()) * r;
        Vector3::new(dist - r, rim.z, rim.norm() - half)
    };
    let mut x = x0;
    for _ in 0..50 {
        let f = res(&x);
        let mut jac = Matrix3::zeros();
        for k in 0..3 {
            let mut xp = x;
            let step = 1e-7 * (1.0 + x[k].abs());
            xp[k] += step;
            jac.set_column(k, &((res(&xp) - f) / step));
        }
        x -= jac.lu().solve(&f).unwrap();
    }
    x
}

#[test]
fn newton_solution_of_contact_conditions_matches_closed_forms() {
    let p = peg();
    for gamma in [p.gamma0() * 1.05, 0.1, 0.3, 0.6, 1.0] {
        let pose = Pose::try_new(&p, gamma, 0.0).unwrap();
        let guess = Vector3::new(pose.o2.x * 1.01, pose.o2.z * 0.99 - 1e-4, 0.9);
        let x = newton_contact(&p, gamma, guess);
        assert!(
            (x[0] - pose.o2.x).abs() < 1e-9,
            "O2 η: {} vs {}",
            x[0],
            pose.o2.x
        );
        assert!(
            (x[1] - pose.o2.z).abs() < 1e-9,
            "O2 z: {} vs {}",
            x[1],
            pose.o2.z
        );
        let b = p.radius() * x[2].sin();
        assert!((b - pose.geo.b).abs() < 1e-9, "b: {b} vs {}", pose.geo.b);
    }
}

#[test]
fn hole_edge_does_not_penetrate_the_peg() {
    let p = peg();
    for (gamma, psi) in grid(&p) {
        let pose = Pose::try_new(&p, gamma, psi).unwrap();
        for k in 0..3600 {
            let a = k as f64 * std::f64::consts::TAU / 3600.0;
            let q = Vector3::new(a.cos(), a.sin(), 0.0) * (0.5 * p.hole_diameter);
            let rq = q - pose.o2;
            let axial = rq.dot(&pose.axis);
            let radial = (rq - pose.axis * axial).norm();
            let inside = axial > 0.0 && axial < p.height && radial < p.radius();
            let depth = (p.radius() - radial).min(axial);
            assert!(
                !inside || depth < 1e-12,
                "edge point at {a} inside the peg by {depth} (γ = {gamma})"
            );
        }
    }
}

#[test]
fn point_a_moves_along_the_hole_wall_and_l_is_the_instant_centre() {
    let p = peg();
    for gamma in [p.gamma0() * 1.01, 0.2, 0.7] {
        let g = Geometry::try_new(&p, gamma).unwrap();
        let pose = Pose::try_new(&p, gamma, 0.0).unwrap();
        let (s, c) = gamma.sin_cos();
        let a = pose.o2 + Vector3::new(c, 0.0, s) * p.radius();
        assert!(
            (a.x - 0.5 * p.hole_diameter).abs() < 1e-15,
            "η_A = D/2, eq. (4a)"
        );
        // Material velocity is zero at L for the planar motion (ψ̇ = 0).
        let (eta_l, z_l) = g.centre_l();
        let kin = pose.kinematics(Vector2::new(1.0, 0.0));
        let v_l = kin.v_c + kin.omega.cross(&(Vector3::new(eta_l, 0.0, z_l) - pose.c));
        assert!(v_l.norm() < 1e-12, "v_L = {v_l}");
        assert!((g.kl - (pose.contacts[0] - Vector3::new(eta_l, 0.0, z_l)).norm()).abs() < 1e-15);
        let bmid = Vector3::new(g.s1, 0.0, 0.0);
        assert!((g.bl - (bmid - Vector3::new(eta_l, 0.0, z_l)).norm()).abs() < 1e-15);
    }
}

#[test]
fn material_velocities_equal_finite_difference_derivatives() {
    let p = peg();
    let qd = Vector2::new(-2.0, 10.0);
    let h = 1e-6;
    for (gamma, psi) in grid(&p) {
        if gamma < p.gamma0() * 1.001 {
            continue; // the central difference would step below γ0
        }
        let pose = Pose::try_new(&p, gamma, psi).unwrap();
        let kin = pose.kinematics(qd);
        let r0 = rotation(gamma, psi);
        assert!((r0 * Vector3::z() - pose.axis).norm() < 1e-15);
        // Position at time t of the material point that is at `x0` at t = 0.
        let track = |x0: Vector3<f64>, t: f64| {
            let (g1, s1) = (gamma + qd[0] * t, psi + qd[1] * t);
            let pose1 = Pose::try_new(&p, g1, s1).unwrap();
            pose1.c + rotation(g1, s1) * (r0.inverse() * (x0 - pose.c))
        };
        let fd = |x0: Vector3<f64>| (track(x0, h) - track(x0, -h)) / (2.0 * h);
        let scale = qd.norm() * p.height;
        assert!((fd(pose.c) - kin.v_c).norm() < 1e-7 * scale);
        for (i, c) in pose.contacts.iter().enumerate() {
            let err = (fd(*c) - kin.v_contacts[i]).norm();
            assert!(
                err < 1e-7 * scale,
                "contact {i} at γ = {gamma}: |Δv| = {err}"
            );
        }
        // Angular velocity: Ṙ Rᵀ = [ω]×.
        let rdot = (rotation(gamma + qd[0] * h, psi + qd[1] * h).matrix()
            - rotation(gamma - qd[0] * h, psi - qd[1] * h).matrix())
            / (2.0 * h);
        let wx = rdot * r0.matrix().transpose();
        let w = Vector3::new(wx[(2, 1)], wx[(0, 2)], wx[(1, 0)]);
        assert!((w - kin.omega).norm() < 1e-7 * qd.norm());
    }
}

#[test]
fn geometry_derivatives_equal_finite_differences() {
    let p = peg();
    for gamma in [p.gamma0() * 1.2, 0.1, 0.4, 1.0] {
        let h = 1e-5 * gamma;
        let g = Geometry::try_new(&p, gamma).unwrap();
        let gp = Geometry::try_new(&p, gamma + h).unwrap();
        let gm = Geometry::try_new(&p, gamma - h).unwrap();
        let d = |a: f64, b: f64| (a - b) / (2.0 * h);
        assert!((d(gp.eta_c, gm.eta_c) - g.deta_c).abs() < 1e-8);
        assert!((d(gp.z_c, gm.z_c) - g.dz_c).abs() < 1e-8);
        assert!((d(gp.deta_c, gm.deta_c) - g.d2eta_c).abs() < 1e-6);
        assert!((d(gp.dz_c, gm.dz_c) - g.d2z_c).abs() < 1e-6);
    }
}

#[test]
fn no_penetration_rate_at_any_contact() {
    let p = peg();
    for (gamma, psi) in grid(&p) {
        let pose = Pose::try_new(&p, gamma, psi).unwrap();
        for qd in [
            Vector2::new(1.0, 0.0),
            Vector2::new(0.0, 1.0),
            Vector2::new(-2.0, 10.0),
        ] {
            let kin = pose.kinematics(qd);
            for i in 0..3 {
                let vn = kin.v_contacts[i].dot(&pose.normals[i]);
                assert!(
                    vn.abs() < 1e-14 * kin.v_contacts[i].norm().max(1e-3),
                    "v·n = {vn} at {i}, γ = {gamma}"
                );
            }
        }
    }
}

#[test]
fn edge_contact_normals_are_common_perpendiculars_of_the_edge_tangents() {
    let p = peg();
    for (gamma, psi) in grid(&p) {
        if gamma < p.gamma0() * 1.001 {
            continue; // tangents nearly parallel: the cross product loses digits
        }
        let pose = Pose::try_new(&p, gamma, psi).unwrap();
        for b in &pose.contacts[1..] {
            let t_peg = pose.axis.cross(&(b - pose.o2));
            let t_hole = Vector3::z().cross(b);
            let n = Unit::new_normalize(t_peg.cross(&t_hole));
            let i = if b == &pose.contacts[1] { 1 } else { 2 };
            assert!(n.dot(&pose.normals[i]).abs() > 1.0 - 1e-12);
            assert!(pose.normals[i].z > 0.0, "the edge pushes the peg up");
        }
        // K: the side normal is perpendicular to the axis and lies in the symmetry plane.
        assert!(pose.normals[0].dot(&pose.axis).abs() < 1e-15);
        assert!(pose.normals[0].dot(&pose.frame.n).abs() < 1e-15);
    }
}
