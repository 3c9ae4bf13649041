//! The compliant 3-D peg: contact geometry against brute-force searches on
//! dense samplings of the edge circles, the gradient against the force
//! direction and lever arm, and the energy balance of the dynamics.

use crate::common::peg3d;

use crate::common::rng;

use nalgebra::{SVector, UnitQuaternion, Vector3};
use peg3d::{fig9, orientation, rim_on_mouth, tight_dopri5};
use pegdyn::compliant_peg_3d::{Contacts, HertzMode, Pair, Peg3d, Peg3dParams, Search, pose_state};
use pegdyn::integrate::{Method, Options, solve};
use rng::Rng;
use std::f64::consts::TAU;

fn pose(p: Vector3<f64>, q: &UnitQuaternion<f64>) -> SVector<f64, 7> {
    SVector::<f64, 7>::from_column_slice(&[p.x, p.y, p.z, q.w, q.i, q.j, q.k])
}

/// The gap of `pair` at angle `a`, computed independently of the generated
/// code (nalgebra rotations, projections).
fn brute_gap(
    prm: &Peg3dParams,
    pair: Pair,
    p: &Vector3<f64>,
    q: &UnitQuaternion<f64>,
    a: f64,
) -> f64 {
    let (r, big_r) = (prm.peg_radius(), prm.bore_radius());
    match pair {
        Pair::EdgeSide => {
            let rc = big_r + prm.mouth_fillet;
            let c = Vector3::new(rc * a.cos(), rc * a.sin(), -prm.mouth_fillet);
            let axis = q * Vector3::z();
            let u = c - p;
            (u - axis * u.dot(&axis)).norm() - r - prm.mouth_fillet
        }
        _ => {
            let rr = r - prm.rim_fillet;
            let c = p + q * Vector3::new(
                rr * a.cos(),
                rr * a.sin(),
                prm.rim_fillet - 0.5 * prm.length,
            );
            match pair {
                Pair::RimWall => big_r - prm.rim_fillet - c.xy().norm(),
                Pair::RimTop => c.z - prm.rim_fillet,
                Pair::RimEdge => {
                    (c - mouth_closest(prm, &c)).norm() - prm.rim_fillet - prm.mouth_fillet
                }
                _ => c.z - prm.rim_fillet + prm.bore_depth,
            }
        }
    }
}

/// The point of the mouth fillet's tube-centre circle closest to `c`: the
/// circle's point in the direction of `c`'s projection on the circle's plane.
fn mouth_closest(prm: &Peg3dParams, c: &Vector3<f64>) -> Vector3<f64> {
    let centre = Vector3::new(0.0, 0.0, -prm.mouth_fillet);
    let mut proj = c - centre;
    proj.z = 0.0;
    centre + proj.normalize() * (prm.bore_radius() + prm.mouth_fillet)
}

const DENSE: usize = 20_000;

/// Compares the search's minima of every pair at one pose with the discrete
/// local minima of a dense sampling: every penetrating brute-force dip is
/// found (angle within two samples, gap at or below the sampled one and
/// within the sampling error), every found minimum is at or below the
/// samples around it, and the normal and gradient agree with the
/// independent geometry. Returns the number of penetrating minima.
fn check_pose(prm: &Peg3dParams, p: Vector3<f64>, q: UnitQuaternion<f64>) -> usize {
    let sys = Peg3d::new(*prm);
    let pv = *sys.param_vector();
    let x = pose(p, &q);
    let h = TAU / DENSE as f64;
    let mut count = 0;
    for pair in Pair::ALL {
        let gaps: Vec<f64> = (0..DENSE)
            .map(|k| brute_gap(prm, pair, &p, &q, k as f64 * h))
            .collect();
        let found = Search::default().minima(pair, &x, &pv, 1e-3);
        let span = gaps.iter().cloned().fold(f64::MIN, f64::max)
            - gaps.iter().cloned().fold(f64::MAX, f64::min);
        // The sampling error of a minimum: |g''| h^2 / 8 with |g''| <= span-scale.
        let sample_err = (span + prm.bore_radius()) * h * h;
        for k in 0..DENSE {
            let (g, gp, gn) = (
                gaps[k],
                gaps[(k + DENSE - 1) % DENSE],
                gaps[(k + 1) % DENSE],
            );
            let distinct = span > 1e-9;
            if g < 0.0 && g < gp && g <= gn && distinct {
                let a = k as f64 * h;
                let hit = found.iter().find(|&&m| {
                    let d = (m - a).rem_euclid(TAU);
                    d.min(TAU - d) <= 2.0 * h
                });
                let Some(&m) = hit else {
                    panic!(
                        "{pair:?}: brute-force minimum at {a} (gap {g}) not found; found {found:?}"
                    );
                };
                let gm = pair.eval(&x, m, &pv).gap;
                assert!(
                    gm <= g + 1e-13 && gm >= g - sample_err,
                    "{pair:?}: gap {gm} vs sampled {g}"
                );
            }
        }
        for &m in &found {
            let e = pair.eval(&x, m, &pv);
            let (gap, d1, d2, grad, normal, point) = (e.gap, e.d1, e.d2, e.grad, e.normal, e.point);
            assert!(
                (gap - brute_gap(prm, pair, &p, &q, m)).abs() < 1e-14,
                "{pair:?}: generated gap"
            );
            assert!(
                d2 > 0.0 && d1.abs() <= 1e-8 * d2.max(1e-12),
                "{pair:?}: not a minimum"
            );
            let k = ((m / h).round() as usize) % DENSE;
            for j in [k + DENSE - 2, k + DENSE - 1, k, k + 1, k + 2] {
                assert!(
                    gap <= gaps[j % DENSE] + 1e-13,
                    "{pair:?}: found minimum above a sample"
                );
            }
            if gap < 0.0 {
                count += 1;
            }
            // Normal: from the independent closest-point construction.
            let brute_n = match pair {
                Pair::EdgeSide => {
                    let rc = prm.bore_radius() + prm.mouth_fillet;
                    let c = Vector3::new(rc * m.cos(), rc * m.sin(), -prm.mouth_fillet);
                    let axis = q * Vector3::z();
                    let foot = p + axis * (c - p).dot(&axis);
                    (foot - c).normalize()
                }
                Pair::RimWall => {
                    let rr = prm.peg_radius() - prm.rim_fillet;
                    let c = p + q * Vector3::new(
                        rr * m.cos(),
                        rr * m.sin(),
                        prm.rim_fillet - 0.5 * prm.length,
                    );
                    -Vector3::new(c.x, c.y, 0.0).normalize()
                }
                Pair::RimEdge => {
                    let rr = prm.peg_radius() - prm.rim_fillet;
                    let c = p + q * Vector3::new(
                        rr * m.cos(),
                        rr * m.sin(),
                        prm.rim_fillet - 0.5 * prm.length,
                    );
                    (c - mouth_closest(prm, &c)).normalize()
                }
                _ => Vector3::z(),
            };
            assert!(
                (normal - brute_n).norm() < 1e-12,
                "{pair:?}: normal {normal} vs {brute_n}"
            );
            // Gradient in the centre of mass = the force direction; in the
            // quaternion, (1/2) Xi(q)^T grad_q = body moment of n about the
            // centre of mass through the contact point.
            let gp = Vector3::new(grad[0], grad[1], grad[2]);
            assert!(
                (gp - normal).norm() < 1e-10,
                "{pair:?}: grad_p {gp} vs n {normal}"
            );
            let (w, i, j, kq) = (x[3], x[4], x[5], x[6]);
            let gq = [grad[3], grad[4], grad[5], grad[6]];
            let tau_body = 0.5
                * Vector3::new(
                    -i * gq[0] + w * gq[1] + kq * gq[2] - j * gq[3],
                    -j * gq[0] - kq * gq[1] + w * gq[2] + i * gq[3],
                    -kq * gq[0] + j * gq[1] - i * gq[2] + w * gq[3],
                );
            let expect = q.inverse() * (point - p).cross(&normal);
            assert!(
                (tau_body - expect).norm() < 1e-10,
                "{pair:?}: moment {tau_body} vs {expect}"
            );
        }
    }
    count
}

#[test]
fn contact_points_match_brute_force_over_random_poses() {
    let prm = fig9();
    let mut rng = Rng(0x3D_9E6);
    let mut penetrating = 0;
    for _ in 0..40 {
        let q = orientation(
            rng.uniform(0.0, 0.5),
            rng.uniform(0.0, TAU),
            rng.uniform(0.0, TAU),
        );
        let p = Vector3::new(
            rng.uniform(-2e-3, 2e-3),
            rng.uniform(-2e-3, 2e-3),
            rng.uniform(-0.03, 0.05),
        );
        penetrating += check_pose(&prm, p, q);
    }
    eprintln!("random poses: {penetrating} penetrating minima");
    assert!(
        penetrating > 20,
        "random poses gave only {penetrating} penetrating minima"
    );
}

#[test]
fn aligned_peg_pressed_sideways_touches_edge_and_wall_at_the_analytic_depth() {
    // Axis vertical at lateral offset e = 40 um: the bore-radius clearance
    // R - r = 25 um is overrun by 15 um at angle 0 on both the mouth edge
    // and the bore wall (rim below the fillet).
    let prm = fig9();
    let e = 40e-6;
    let p = Vector3::new(e, 0.0, -0.02);
    let q = UnitQuaternion::identity();
    assert_eq!(check_pose(&prm, p, q), 2);
    let sys = Peg3d::new(prm);
    let y = pose_state(p, q, Vector3::zeros(), Vector3::zeros());
    let c = sys.contacts(&y);
    assert_eq!(c.len(), 2);
    for pt in &c {
        assert!(
            pt.angle.min(TAU - pt.angle) < 1e-9,
            "{:?} at {}",
            pt.pair,
            pt.angle
        );
        assert!(
            (pt.penetration - 15e-6).abs() < 1e-15,
            "{:?}: {}",
            pt.pair,
            pt.penetration
        );
        assert!((pt.normal - Vector3::new(-1.0, 0.0, 0.0)).norm() < 1e-15);
    }
}

#[test]
fn peg_at_gamma0_matches_brute_force_and_out_of_hole_has_no_contact() {
    let prm = fig9();
    let gamma0 = (prm.peg_diameter / prm.hole_diameter).acos();
    let mut rng = Rng(77);
    for k in 0..8 {
        let q = orientation(gamma0, rng.uniform(0.0, TAU), rng.uniform(0.0, TAU));
        let z = if k == 0 {
            0.0
        } else {
            rng.uniform(-0.02, 0.02)
        };
        let p = Vector3::new(rng.uniform(-1e-3, 1e-3), rng.uniform(-1e-3, 1e-3), z);
        check_pose(&prm, p, q);
    }
    // Above the top face, tilted, over the block: no overlap anywhere.
    let q = orientation(0.3, 1.0, 2.0);
    let p = Vector3::new(0.06, 0.0, 0.05);
    check_pose(&prm, p, q);
    for pair in [Pair::EdgeSide, Pair::RimTop] {
        let min = (0..DENSE)
            .map(|k| brute_gap(&prm, pair, &p, &q, k as f64 * TAU / DENSE as f64))
            .fold(f64::MAX, f64::min);
        assert!(min > 0.0, "{pair:?}: sampled gap {min}");
    }
    let sys = Peg3d::new(prm);
    assert!(
        sys.contacts(&pose_state(p, q, Vector3::zeros(), Vector3::zeros()))
            .is_empty()
    );
}

/// A peg released tilted over the top face with a spin, landing on its rim.
fn landing(prm: Peg3dParams) -> (Peg3d, SVector<f64, 15>) {
    let q = orientation(0.2, 0.3, 0.0);
    let sys = Peg3d::new(prm);
    // Lowest rim point 0.1 mm above the face.
    let rr = prm.peg_radius() - prm.rim_fillet;
    let low = (0..3600)
        .map(|k| {
            let a = k as f64 * TAU / 3600.0;
            (q * Vector3::new(
                rr * a.cos(),
                rr * a.sin(),
                prm.rim_fillet - 0.5 * prm.length,
            ))
            .z
        })
        .fold(f64::MAX, f64::min);
    let p = Vector3::new(0.07, 0.01, 1e-4 + prm.rim_fillet - low);
    let y = pose_state(
        p,
        q,
        Vector3::new(0.01, 0.02, -0.2),
        Vector3::new(3.0, -2.0, 20.0),
    );
    (sys, y)
}

#[test]
fn frictionless_undamped_landing_conserves_energy() {
    let mut prm = fig9();
    prm.hertz = HertzMode::Fixed(2e9);
    prm.force = Vector3::new(0.5, 0.0, -2.0);
    prm.moment = Vector3::new(0.0, 0.01, 0.0);
    let (sys, y0) = landing(prm);
    let e0 = sys.energy_balance(&y0).unwrap();
    let sol = tight_dopri5(&sys, y0, 0.02, 1e-13);
    let mut touched = false;
    let mut worst: f64 = 0.0;
    for y in &sol.x {
        touched |= !sys.contacts(y).is_empty();
        worst = worst.max((sys.energy_balance(y).unwrap() - e0).abs());
    }
    assert!(touched, "the peg never landed");
    eprintln!(
        "frictionless landing: {} steps, energy drift {worst:e} J",
        sol.x.len()
    );
    // Kinetic energy ~ 0.5 * 1.08 kg * (0.2 m/s)^2 ~ 2e-2 J.
    assert!(worst < 1e-8, "energy balance drifts by {worst} J");
}

#[test]
fn friction_and_damping_dissipate_and_close_the_balance() {
    let mut prm = fig9();
    prm.hertz = HertzMode::Fixed(2e9);
    prm.friction = 0.3;
    prm.damping = 0.5;
    let (sys, y0) = landing(prm);
    let e0 = sys.energy_balance(&y0).unwrap();
    let sol = tight_dopri5(&sys, y0, 0.02, 1e-13);
    let mut last = 0.0;
    let mut worst: f64 = 0.0;
    for y in &sol.x {
        assert!(
            y[14] >= last - 1e-15,
            "dissipation decreased: {} -> {}",
            last,
            y[14]
        );
        last = y[14];
        worst = worst.max((sys.energy_balance(y).unwrap() - e0).abs());
    }
    eprintln!("dissipative landing: dissipated {last:e} J, balance drift {worst:e} J");
    assert!(last > 1e-5, "dissipated only {last} J");
    assert!(worst < 1e-8, "energy balance drifts by {worst} J");
}

#[test]
fn centred_tilted_peg_meets_the_mouth_edge_at_the_filleted_gamma0() {
    // Axis through the centre of the mouth-edge tube circle, tilted by γ
    // about y: the distance from c(α) to the axis is
    // (R+ρ_h) √(cos²γ + sin²α sin²γ), smallest at α = 0 and π, so the gap
    // there is (R+ρ_h) cos γ − r − ρ_h, which crosses zero at
    // γ0' = arccos((r+ρ_h)/(R+ρ_h)) (γ0 = arccos(d/D) for sharp edges).
    // Only α = 0 is on the fillet's upper-inner quarter (force direction
    // (−cos γ, 0, sin γ)); at α = π the direction points down into the bore
    // and the contact is not the mouth fillet's.
    let prm = fig9();
    let (r, big_r, rho) = (prm.peg_radius(), prm.bore_radius(), prm.mouth_fillet);
    let gamma0f = ((r + rho) / (big_r + rho)).acos();
    let sys = Peg3d::new(prm);
    for (gamma, expect) in [(gamma0f * 0.999, 0), (gamma0f * 1.001, 1), (0.3, 1)] {
        let q = orientation(gamma, 0.0, 0.4);
        // Centre of mass on the axis through (0, 0, −ρ_h), 10 mm above it.
        let p = Vector3::new(0.0, 0.0, -rho) + q * Vector3::new(0.0, 0.0, 0.01);
        let y = pose_state(p, q, Vector3::zeros(), Vector3::zeros());
        let c = sys.contacts(&y);
        let edge: Vec<_> = c.iter().filter(|c| c.pair == Pair::EdgeSide).collect();
        assert_eq!(edge.len(), expect, "γ = {gamma}: {c:?}");
        let gap = (big_r + rho) * gamma.cos() - r - rho;
        for e in edge {
            assert!(e.angle.min(TAU - e.angle) < 1e-9, "angle {}", e.angle);
            let n = Vector3::new(-gamma.cos(), 0.0, gamma.sin());
            assert!((e.normal - n).norm() < 1e-12, "normal {}", e.normal);
            assert!(
                (e.penetration + gap).abs() < 1e-15,
                "{} vs {}",
                e.penetration,
                -gap
            );
        }
    }
}

#[test]
fn tilted_rim_on_the_top_face_has_the_torus_curvatures() {
    // At the lowest point of the tilted rim the torus normal is −e_z and
    // the outward radial direction from the peg's axis dips by γ, so the
    // parallel curvature is sin γ / (r − ρ_p + ρ_p sin γ); the meridian
    // curvature is 1/ρ_p; the face is flat.
    let prm = fig9();
    let sys = Peg3d::new(prm);
    let rr = prm.peg_radius() - prm.rim_fillet;
    for gamma in [0.05, 0.3, 1.0] {
        let q = orientation(gamma, 0.7, 1.1);
        let axis = q * Vector3::z();
        // Lowest tube-centre point: h a_z − (r − ρ_p) |((R e_x)_z, (R e_y)_z)|,
        // placed 1 µm less than ρ_p above the face.
        let (ex, ey) = (q * Vector3::x(), q * Vector3::y());
        let lowest = (prm.rim_fillet - 0.5 * prm.length) * axis.z - rr * ex.z.hypot(ey.z);
        let p = Vector3::new(0.08, -0.01, prm.rim_fillet - 1e-6 - lowest);
        let y = pose_state(p, q, Vector3::zeros(), Vector3::zeros());
        let c = sys.contacts(&y);
        assert_eq!(c.len(), 1, "γ = {gamma}: {c:?}");
        assert_eq!(c[0].pair, Pair::RimTop);
        assert!((c[0].penetration - 1e-6).abs() < 1e-15);
        let curv = pegdyn::compliant_peg_3d::curvature::at(&prm, &c[0], &p, &axis);
        let expect = gamma.sin() / (rr + prm.rim_fillet * gamma.sin());
        assert!(
            (curv.body1[0] - expect).abs() < 1e-9 * expect,
            "γ = {gamma}: {} vs {expect}",
            curv.body1[0]
        );
        assert!((curv.body1[1] - 1.0 / prm.rim_fillet).abs() < 1e-9);
        assert_eq!(curv.body2, [0.0, 0.0]);
    }
}

#[test]
fn landing_with_curvature_hertz_runs_and_dissipates() {
    // Stiffness from the rim torus on the flat face at every evaluation
    // (steel on steel): the rhs meets no Hertz error, S never decreases,
    // and the peak normal force exceeds the peg's weight (an impact).
    let mut prm = fig9();
    prm.friction = 0.2;
    prm.damping = 0.5;
    let (sys, y0) = landing(prm);
    let sol = solve(
        &sys,
        Method::Dopri5,
        (0.0, y0),
        0.02,
        &Options::with_tolerances(1e-9, 1e-12),
    )
    .unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    assert!(sol.model_error.is_none(), "{:?}", sol.model_error);
    let mut last = 0.0;
    let mut peak: f64 = 0.0;
    let mut k_range = (f64::MAX, 0.0_f64);
    for y in &sol.x {
        assert!(y[14] >= last - 1e-15);
        last = y[14];
        for f in sys.forces(y).unwrap() {
            peak = peak.max(f.normal_force);
            k_range = (k_range.0.min(f.stiffness), k_range.1.max(f.stiffness));
        }
    }
    eprintln!(
        "curvature landing: peak force {peak} N, k in [{:e}, {:e}], dissipated {last:e} J",
        k_range.0, k_range.1
    );
    assert!(peak > prm.mass * prm.gravity, "peak {peak} N");
    assert!(last > 0.0);
}

#[test]
fn closed_form_mouth_point_is_the_closest_of_a_dense_sampling() {
    // The rim-against-mouth gap takes the closest point of the mouth
    // fillet's tube-centre circle in closed form; a dense sampling of that
    // circle agrees (distance to 1e-12 m) at points around the mouth.
    let prm = fig9();
    let rm = prm.bore_radius() + prm.mouth_fillet;
    let mut rng = Rng(4242);
    for _ in 0..20 {
        let c = Vector3::new(
            rng.uniform(-0.03, 0.03),
            rng.uniform(-0.03, 0.03),
            rng.uniform(-0.005, 0.005),
        );
        let exact = (c - mouth_closest(&prm, &c)).norm();
        let n = 200_000;
        let sampled = (0..n)
            .map(|k| {
                let t = k as f64 * TAU / n as f64;
                (c - Vector3::new(rm * t.cos(), rm * t.sin(), -prm.mouth_fillet)).norm()
            })
            .fold(f64::MAX, f64::min);
        // Sampling error of a minimum of the distance: at most
        // rm |c_xy| h² / (2 |c − m|) for half a sample step h/2.
        let h = TAU / n as f64;
        assert!(
            exact <= sampled + 1e-15 && sampled - exact < rm * c.xy().norm() * h * h / exact,
            "{exact} vs {sampled}"
        );
    }
}

#[test]
fn aligned_rim_on_the_mouth_fillet_touches_at_the_analytic_depth_and_curvatures() {
    // Aligned peg shifted by e along x so that its rim tube-centre circle
    // passes s = 0.5 mm inside the mouth's tube-centre circle at β = 0 and
    // dz above it: the tube centres are sqrt(s² + dz²) apart, the closest
    // pair of all (the rim circle's radial distance is largest at β = 0).
    let prm = fig9();
    let (rho_p, rho_h) = (prm.rim_fillet, prm.mouth_fillet);
    let rr = prm.peg_radius() - rho_p;
    let rm = prm.bore_radius() + rho_h;
    let s = 5e-4;
    let depth = 10e-6;
    let dist = rho_p + rho_h - depth;
    let dz = (dist * dist - s * s).sqrt();
    let e = rm - s - rr;
    let z = -rho_h + dz + 0.5 * prm.length - rho_p;
    let p = Vector3::new(e, 0.0, z);
    let q = UnitQuaternion::identity();
    let sys = Peg3d::new(prm);
    let y = pose_state(p, q, Vector3::zeros(), Vector3::zeros());
    let c: Vec<_> = sys
        .contacts(&y)
        .into_iter()
        .filter(|c| c.pair == Pair::RimEdge)
        .collect();
    assert_eq!(c.len(), 1, "{c:?}");
    let c = c[0];
    assert!(c.angle.min(TAU - c.angle) < 1e-9, "angle {}", c.angle);
    assert!((c.penetration - depth).abs() < 1e-15, "{}", c.penetration);
    let n = Vector3::new(-s, 0.0, dz) / dist;
    assert!((c.normal - n).norm() < 1e-12, "normal {}", c.normal);
    // Midway point: the mouth tube centre + (ρ_h − depth/2) n.
    let mid = Vector3::new(rm, 0.0, -rho_h) + n * (rho_h - 0.5 * depth);
    assert!((c.point - mid).norm() < 1e-14, "point {} vs {mid}", c.point);
    // Curvatures: meridians 1/ρ_p and 1/ρ_h; the parallels, by Meusnier,
    // (N·ê_ρ)/ρ with the rim's outward normal −n about the peg's axis and
    // the mouth's n about the hole's axis; both parallels along y (ω = 0).
    let rim_pt = mid - n * (0.5 * depth);
    let mouth_pt = mid + n * (0.5 * depth);
    let curv = pegdyn::compliant_peg_3d::curvature::at(&prm, &c, &p, &Vector3::z());
    let kp_rim = (s / dist) / (rim_pt.x - e);
    let kp_mouth = (-s / dist) / mouth_pt.x;
    for (got, want) in [
        (curv.body1[0], kp_rim),
        (curv.body1[1], 1.0 / rho_p),
        (curv.body2[0], kp_mouth),
        (curv.body2[1], 1.0 / rho_h),
    ] {
        assert!((got - want).abs() < 1e-9 * want.abs(), "{got} vs {want}");
    }
    assert!(curv.angle.abs() < 1e-9, "angle {}", curv.angle);
    // And the brute-force comparison at this pose and tilted neighbours.
    check_pose(&prm, p, q);
    let mut rng = Rng(99);
    let mut met = 0;
    for _ in 0..12 {
        let q = orientation(
            rng.uniform(0.0, 0.4),
            rng.uniform(0.0, TAU),
            rng.uniform(0.0, TAU),
        );
        // Put the rim's lowest-outermost point near the mouth fillet.
        let p = p + Vector3::new(rng.uniform(-1e-3, 1e-3), rng.uniform(-1e-3, 1e-3), 0.0);
        check_pose(&prm, p, q);
        let sys = Peg3d::new(prm);
        let y = pose_state(p, q, Vector3::zeros(), Vector3::zeros());
        met += sys
            .contacts(&y)
            .iter()
            .filter(|c| c.pair == Pair::RimEdge)
            .count();
    }
    eprintln!("rim on the mouth: {met} rim-edge contacts over 12 tilted poses");
    assert!(met >= 3, "only {met} rim-edge contacts");
}

#[test]
fn rim_points_on_the_mouth_merge_without_a_force_jump() {
    let mut prm = fig9();
    let k = 2e10;
    prm.hertz = HertzMode::Fixed(k);
    let sys = Peg3d::new(prm);
    let count = |g: f64| {
        sys.contacts(&rim_on_mouth(&prm, g, 10e-6))
            .iter()
            .filter(|c| c.pair == Pair::RimEdge)
            .count()
    };
    assert_eq!(count(0.02), 1);
    assert_eq!(count(0.04), 2);
    // Net normal force of the pair (points less subtracted cols) along a
    // fine sweep through the merge, against the naive sum of the points.
    let (mut prev, mut prev_naive) = (None::<f64>, None::<f64>);
    let (mut jump, mut jump_naive, mut scale) = (0.0_f64, 0.0_f64, 0.0_f64);
    let mut split = 0;
    let n = 3000;
    for i in 0..=n {
        let g = 0.02 + 0.02 * i as f64 / n as f64;
        let y = rim_on_mouth(&prm, g, 10e-6);
        let f = sys.forces(&y).unwrap();
        let rim: Vec<_> = f
            .iter()
            .filter(|f| f.contact.pair == Pair::RimEdge)
            .collect();
        let sum: f64 = rim.iter().map(|f| f.normal_force - f.col_force).sum();
        let naive: f64 = rim
            .iter()
            .map(|f| k * f.contact.penetration.powf(1.5))
            .sum();
        split += usize::from(rim.iter().any(|f| f.contact.saddle.is_some()));
        if let (Some(a), Some(b)) = (prev, prev_naive) {
            jump = jump.max((sum - a).abs());
            jump_naive = jump_naive.max((naive - b).abs());
        }
        scale = scale.max(sum);
        prev = Some(sum);
        prev_naive = Some(naive);
    }
    eprintln!(
        "merge sweep: peak {scale:.4} N, largest step {jump:.3e} N (naive {jump_naive:.3e} N), \
         {split} poses with a shared col"
    );
    assert!(split > 10, "the col rule never acted ({split} poses)");
    // At the merge the naive sum jumps by one point's force (632 N at 10 µm);
    // the net force moves by less than a twentieth of that per step.
    assert!(jump_naive > 600.0, "the naive sum did not jump");
    assert!(jump < 0.05 * jump_naive, "step {jump} N");
}

#[test]
fn forces_with_a_shared_col_are_minus_the_gradient_of_the_potential() {
    // With a fixed stiffness and the peg at rest, the contact wrench is
    // −∂V/∂(pose) of V = Σ (2/5) k δ_eff^{5/2}: translations along the hole
    // axes give the force, rotations about them (about the centre of mass)
    // the moment; central differences, step 1e-9 m and 1e-9 rad.
    let mut prm = fig9();
    prm.hertz = HertzMode::Fixed(2e10);
    let sys = Peg3d::new(prm);
    let mut checked = 0;
    for gamma in [0.025, 0.03, 0.035, 0.04] {
        let y = rim_on_mouth(&prm, gamma, 10e-6);
        let f = sys.forces(&y).unwrap();
        checked += f.iter().filter(|f| f.contact.saddle.is_some()).count();
        let w = Peg3d::wrench(&y, &f);
        let pot = |y: &SVector<f64, 15>| -> f64 {
            sys.forces(y).unwrap().iter().map(|f| f.potential).sum()
        };
        let h = 1e-9;
        for axis in 0..3 {
            let mut e = Vector3::zeros();
            e[axis] = 1.0;
            let shifted = |s: f64| {
                let mut z = y;
                for k in 0..3 {
                    z[k] += s * e[k];
                }
                z
            };
            let force = -(pot(&shifted(h)) - pot(&shifted(-h))) / (2.0 * h);
            let turned = |s: f64| {
                let q = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
                    y[3], y[4], y[5], y[6],
                ));
                let q = UnitQuaternion::from_scaled_axis(e * s) * q;
                let mut z = y;
                z[3] = q.w;
                z[4] = q.i;
                z[5] = q.j;
                z[6] = q.k;
                z
            };
            let moment = -(pot(&turned(h)) - pot(&turned(-h))) / (2.0 * h);
            let fs = w.fixed_rows::<3>(0).norm();
            assert!(
                (force - w[axis]).abs() < 1e-5 * fs,
                "γ = {gamma}: F{axis} {force} vs {}",
                w[axis]
            );
            assert!(
                (moment - w[3 + axis]).abs() < 1e-5 * fs * 0.05,
                "γ = {gamma}: T{axis} {moment} vs {}",
                w[3 + axis]
            );
        }
    }
    assert!(checked >= 2, "only {checked} contacts with a col");
}

#[test]
fn pruned_pairs_never_hide_a_contact() {
    // Over random poses around the mouth, inside the bore, near its bottom
    // and above the block, the contacts with the pruning bounds equal those
    // of a full scan of every pair.
    let prm = fig9();
    let pv = Peg3d::new(prm).param_vector().to_owned();
    let mut rng = Rng(0x9_2E);
    let (mut skipped, mut contacts) = (0, 0);
    for _ in 0..200 {
        let q = orientation(
            rng.uniform(0.0, 0.6),
            rng.uniform(0.0, TAU),
            rng.uniform(0.0, TAU),
        );
        let p = Vector3::new(
            rng.uniform(-0.03, 0.03),
            rng.uniform(-0.03, 0.03),
            rng.uniform(-0.08, 0.06),
        );
        let y = pose_state(p, q, Vector3::zeros(), Vector3::zeros());
        let x = Peg3d::pose(&y);
        let pruned = Peg3d::new(prm).contacts(&y);
        let mut full = Contacts::new();
        for pair in Pair::ALL {
            Search::default().find(pair, &prm, &x, &pv, &mut full);
            skipped += usize::from(!pegdyn::compliant_peg_3d::prune::can_touch(pair, &prm, &x));
        }
        assert_eq!(pruned, full.to_vec(), "pose {p} {q}");
        contacts += full.len();
    }
    eprintln!("pruning: {skipped} of 1000 pair scans skipped, {contacts} contacts");
    assert!(
        contacts > 20 && skipped > 300,
        "{contacts} contacts, {skipped} skipped"
    );
}

#[test]
fn curvature_stiffness_landing_closes_the_energy_balance() {
    // With the stiffness from the curvatures at every evaluation the force
    // includes −(2/5) δ^{5/2} ∂k/∂(pose), so the contact force is the full
    // −∂V/∂(pose) and T + m g z + V − W stays constant to the integrator's
    // tolerance, although k moves by a fraction of a per cent along the
    // landing (without the term the balance drifted by about that fraction
    // of the peak elastic energy).
    let prm = fig9();
    assert_eq!(prm.hertz, HertzMode::Curvature);
    let (sys, y0) = landing(prm);
    let e0 = sys.energy_balance(&y0).unwrap();
    let sol = tight_dopri5(&sys, y0, 0.02, 1e-13);
    let (mut worst, mut peak, mut k) = (0.0_f64, 0.0_f64, (f64::MAX, 0.0_f64));
    let mut term = 0.0_f64;
    for y in &sol.x {
        worst = worst.max((sys.energy_balance(y).unwrap() - e0).abs());
        for f in sys.forces(y).unwrap() {
            peak = peak.max(f.potential);
            k = (k.0.min(f.stiffness), k.1.max(f.stiffness));
            term = term.max(f.stiffness_torque.norm());
        }
    }
    let spread = (k.1 - k.0) / k.0;
    eprintln!(
        "curvature stiffness: {} steps, balance drift {worst:e} J, peak elastic energy {peak:e} J, k spread {spread:e}, largest stiffness moment {term:e} N·m",
        sol.x.len()
    );
    assert!(peak > 1e-3, "peak elastic energy {peak} J");
    assert!(spread > 1e-3, "k spread {spread}");
    assert!(term > 0.0, "no stiffness term");
    // Without the term the drift was 1.16e-5 J; with it, the bound of the
    // fixed-stiffness landings (whose drift is a few 1e-11 J here).
    assert!(worst < 1e-8, "drift {worst} J");
}

#[test]
fn rim_landing_on_the_mouth_fillet_conserves_energy() {
    // The peg of the merge sweep at γ = 0.03 rad, its rim 0.1 mm above the
    // mouth fillet, dropped at 0.2 m/s with a spin: it lands on the fillet
    // on the rim's two points sharing a col. Frictionless, undamped, fixed
    // stiffness: T + m g z + V − W stays constant.
    let mut prm = fig9();
    prm.hertz = HertzMode::Fixed(2e10);
    let sys = Peg3d::new(prm);
    let mut y0 = rim_on_mouth(&prm, 0.03, -1e-4);
    y0[9] = -0.2;
    y0[12] = 5.0;
    let e0 = sys.energy_balance(&y0).unwrap();
    let sol = tight_dopri5(&sys, y0, 3e-3, 1e-13);
    let (mut worst, mut cols, mut rim) = (0.0_f64, 0, 0);
    for y in &sol.x {
        worst = worst.max((sys.energy_balance(y).unwrap() - e0).abs());
        for c in sys.contacts(y) {
            rim += usize::from(c.pair == Pair::RimEdge);
            cols += usize::from(c.saddle.is_some());
        }
    }
    eprintln!(
        "rim on the mouth: {} steps, {rim} rim-mouth contacts, {cols} with a col, drift {worst:e} J",
        sol.x.len()
    );
    assert!(
        rim > 10 && cols > 0,
        "{rim} rim-mouth contacts, {cols} cols"
    );
    assert!(worst < 1e-8, "energy balance drifts by {worst} J");
}

#[test]
fn axis_of_a_pose_is_the_rotated_body_axis() {
    // a = R(q) e_z for orientations tilted and turned every way (the
    // validity tests, the pruning and the curvatures read it).
    let mut rng = Rng(7);
    for _ in 0..200 {
        let q = orientation(
            rng.uniform(0.0, 1.5),
            rng.uniform(0.0, TAU),
            rng.uniform(0.0, TAU),
        );
        let x = pose(Vector3::zeros(), &q);
        let a = pegdyn::compliant_peg_3d::axis_of(&x);
        let expect = q * Vector3::z();
        assert!((a - expect).norm() < 1e-15, "{a} vs {expect}");
    }
}

#[test]
fn state_names_follow_the_generated_state_layout() {
    use pegdyn::compliant_peg_3d::insertion::STATE_NAMES;
    use pegdyn::generated::compliant_peg_3d::Y_NAMES;
    use pegdyn::system::OdeSystem;
    // A non-finite stop names the component by these (hostile_integrator).
    assert_eq!(OdeSystem::state_names(&Peg3d::new(fig9())), &Y_NAMES[..]);
    assert_eq!(&STATE_NAMES[..15], &Y_NAMES[..]);
    assert_eq!(STATE_NAMES[15], "robot_work");
}

#[test]
fn a_contact_hertz_cannot_set_up_is_an_error_value_through_the_integrator() {
    // A peg 20 µm wider than its bore, 20 µm off-centre towards +x, tilted
    // by 1 mrad towards −x and 20 mm deep: its rim meets the concave wall at
    // +x, where the relative curvature along the circle, 1/r − 1/R, is
    // negative: no Hertz point contact exists. The error comes back as a
    // value from the forces, the fallible right-hand side and the
    // integration (which stops at once: the start state is refused).
    use pegdyn::hertz::HertzError;
    use pegdyn::system::{ModelError, OdeSystem};
    let mut prm = fig9();
    prm.peg_diameter = prm.hole_diameter + 20e-6;
    let sys = Peg3d::new(prm);
    let y = pose_state(
        Vector3::new(20e-6, 0.0, 0.5 * prm.length - 0.02),
        orientation(1e-3, std::f64::consts::PI, 0.0),
        Vector3::zeros(),
        Vector3::zeros(),
    );
    let contacts = sys.contacts(&y);
    assert!(
        contacts.iter().any(|c| c.pair == Pair::RimWall),
        "{contacts:?}"
    );
    let Err(HertzError::NotPointContact { a, .. }) = sys.forces(&y) else {
        panic!("{:?}", sys.forces(&y));
    };
    assert!(a < 0.0, "A = {a}");
    assert!(matches!(
        sys.try_rhs(0.0, &y),
        Err(ModelError::Hertz(HertzError::NotPointContact { .. }))
    ));
    assert!(sys.rhs(0.0, &y).iter().all(|v| v.is_nan()));
    assert!(sys.try_jacobian(0.0, &y).is_err());
    let sol = solve(
        &sys,
        Method::Dopri5,
        (0.0, y),
        1e-3,
        &Options::with_tolerances(1e-6, 1e-12),
    )
    .unwrap();
    assert!(!sol.stop.is_success(), "{:?}", sol.stop);
    assert!(
        matches!(
            sol.model_error,
            Some(ModelError::Hertz(HertzError::NotPointContact { .. }))
        ),
        "{:?}",
        sol.model_error
    );
}

#[test]
fn contacts_and_forces_asked_again_at_a_pose_equal_those_of_a_fresh_search() {
    // The system keeps the contacts and Hertz setups of the last pose it
    // searched; asked again at that pose (any velocity), after another
    // pose, or at a pose one ulp away, it must give what a system that
    // never searched before finds there.
    let prm = fig9();
    let peg = Peg3d::new(prm);
    let mut states = Vec::new();
    for (gamma, psi) in [(0.06, 0.0), (0.1, 1.0), (0.2, 2.5), (0.3, 4.0)] {
        let (c, q) = pegdyn::compliant_peg_3d::insertion::lean_pose(&prm, gamma, psi).unwrap();
        // Pressed 30 µm further in.
        let y = pose_state(
            c - Vector3::z() * 3e-5,
            q,
            Vector3::new(1e-3, -2e-3, -5e-3),
            Vector3::new(0.5, -0.2, 3.0),
        );
        states.push(y);
    }
    // The rim on the mouth fillet, pressed 20 µm in.
    for gamma in [0.02, 0.05] {
        let mut y = rim_on_mouth(&prm, gamma, 2e-5);
        y[7] = 1e-3;
        y[12] = 3.0;
        states.push(y);
    }
    let fresh = |y: &SVector<f64, 15>| {
        let p = Peg3d::new(prm);
        (p.contacts(y), p.forces(y))
    };
    let mut most = 0;
    for (k, y) in states.iter().enumerate() {
        let (contacts, forces) = fresh(y);
        assert!(!contacts.is_empty(), "{k}");
        most = most.max(contacts.len());
        assert_eq!(peg.contacts(y), contacts, "{k}");
        assert_eq!(peg.forces(y), forces, "{k}");
        assert_eq!(peg.contacts(y), contacts, "{k}: again");
        // Same pose, other velocities: the same contacts, the law anew.
        let mut moving = *y;
        moving[7] += 0.01;
        moving[12] -= 2.0;
        let (_, moving_forces) = fresh(&moving);
        assert_eq!(peg.forces(&moving), moving_forces, "{k}: moving");
        // One ulp away in height: searched again.
        let mut near = *y;
        near[2] = f64::from_bits(near[2].to_bits() + 1);
        assert_eq!(peg.forces(&near), fresh(&near).1, "{k}: near");
        // After the next pose, back to this one.
        let other = &states[(k + 1) % states.len()];
        assert_eq!(peg.contacts(other), fresh(other).0, "{k}: other");
        assert_eq!(peg.contacts(y), contacts, "{k}: back");
        assert_eq!(peg.forces(y), forces, "{k}: back");
    }
    // Some pose has more than one contact.
    assert!(most >= 2, "{most}");
}
