//! The 3-D no-jamming inequalities agree with the vector equilibrium of
//! Eqs. 81–82: a load that holds the peg in two-point sliding in any tilt
//! plane lies exactly on the inequality boundary, loads inside the planar
//! parallelogram lifted into any plane avoid jamming, and the set is
//! invariant under rotation about the hole axis.

use nalgebra::Vector3;
use pegdyn::jamming::PegHole;
use pegdyn::jamming::diagram::exact_parallelogram;
use pegdyn::jamming::geometry::{contact_points, two_point_tilt};
use pegdyn::jamming::space3d::*;

fn setup() -> (
    PegHole,
    f64,
    f64,
    NoJamSpace,
    pegdyn::jamming::diagram::Parallelogram,
) {
    let p = PegHole::try_new(0.0125, 0.01, 0.3).unwrap();
    let l = 0.01;
    let th = two_point_tilt(&p, l).unwrap().unwrap();
    let g = exact_parallelogram(&p, l).unwrap().unwrap();
    (p, l, th, NoJamSpace::new(&g, p.r()), g)
}

/// Lift a planar (x, z) vector into the plane of azimuth φ.
fn lift(v: [f64; 2], phi: f64) -> Vector3<f64> {
    Vector3::new(v[0] * phi.cos(), v[0] * phi.sin(), v[1])
}

#[test]
fn two_point_sliding_load_is_on_the_boundary_in_every_plane() {
    let (p, l, th, space, _) = setup();
    let mu = p.mu();
    let (tip, edge, t) = contact_points(&p, l, th);
    let (s, c) = th.sin_cos();
    for phi in [0.0, 0.7, 2.0, -2.9] {
        let rel = |q: [f64; 2]| lift([q[0] - t[0], q[1] - t[1]], phi);
        let contacts = [
            Contact3 {
                at: rel(tip),
                normal: lift([1.0, 0.0], phi),
                velocity: Vector3::z(),
                f: 1.7,
            },
            Contact3 {
                at: rel(edge),
                normal: lift([-c, -s], phi),
                velocity: lift([-s, c], phi),
                f: 2.2,
            },
        ];
        let (f_c, m_c) = resultant(mu, &contacts, &Vector3::zeros(), &Vector3::zeros());
        let (f_ext, m_ext) = (-f_c, -m_c);
        let (rf, rm) = resultant(mu, &contacts, &f_ext, &m_ext);
        assert!(rf.norm() < 1e-12 && rm.norm() < 1e-14);
        let force = SphericalForce::from_vector(&f_ext).unwrap();
        let v = space.values(&force, &m_ext).unwrap();
        assert!((v[0] - 1.0).abs() < 1e-9, "phi={phi}: {v:?}");
        assert!(v[1] < 1.0);
        // 1 % more moment is past the two-point line, 1 % less is inside
        assert!(!space.avoids_jamming(&force, &(m_ext * 1.01)));
        assert!(space.avoids_jamming(&force, &(m_ext * 0.99)));
        // the in-plane ratio is the planar sliding point
        let q = space.in_plane(&force, &m_ext, phi).unwrap();
        let planar = pegdyn::jamming::forces::sliding_wrench(
            &p,
            l,
            th,
            pegdyn::jamming::forces::ContactForces {
                tip: 1.7,
                edge: 2.2,
            },
        );
        assert!((q[0] - planar.fx / planar.fz).abs() < 1e-12);
        assert!((q[1] - planar.m / (p.r() * planar.fz)).abs() < 1e-9);
    }
}

#[test]
fn planar_verdict_lifts_to_any_plane() {
    let (p, _, _, space, g) = setup();
    let fz = 10.0;
    for q in [
        [0.0, 0.0],
        [1.0, 1.5],
        [-2.0, -3.0],
        [2.0, 6.0],
        [0.5, 9.0],
        [-3.4, 0.0],
    ] {
        for phi in [0.0, 1.1, 3.0] {
            let f = lift([q[0] * fz, fz], phi);
            // planar moment τ = −M·(z × e_φ): M along −(z × e_φ)
            let e_perp = Vector3::new(-phi.sin(), phi.cos(), 0.0);
            let m = -q[1] * p.r() * fz * e_perp;
            let force = SphericalForce::from_vector(&f).unwrap();
            assert_eq!(
                space.avoids_jamming(&force, &m),
                g.avoids_jamming(q),
                "q={q:?} phi={phi}"
            );
        }
    }
}

#[test]
fn rotation_about_axis_changes_nothing_and_mz_is_free() {
    let (_, _, _, space, _) = setup();
    let f = SphericalForce::try_new(20.0, 0.2, 0.4).unwrap();
    let m = Vector3::new(0.01, -0.03, 0.0);
    let v0 = space.values(&f, &m).unwrap();
    let rot = nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), 1.3);
    let f1 = SphericalForce::from_vector(&(rot * f.vector())).unwrap();
    let v1 = space.values(&f1, &(rot * m)).unwrap();
    assert!((v0[0] - v1[0]).abs() < 1e-12 && (v0[1] - v1[1]).abs() < 1e-12);
    let v2 = space.values(&f, &Vector3::new(0.01, -0.03, 5.0)).unwrap();
    assert_eq!(v0, v2);
    // a pulling force (β > π/2) is not an insertion
    let pull = SphericalForce::try_new(20.0, 2.0, 0.0).unwrap();
    assert!(space.values(&pull, &m).is_none() && !space.avoids_jamming(&pull, &m));
}
