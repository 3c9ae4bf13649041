//! The compliant 3-D peg's cylindrical side against the bore wall. Along
//! one generator `k(t) = p + t a + r e(β)` of the side (`e(β)` the body's
//! radial direction, `t` the axial coordinate), the squared distance from
//! the hole's axis `|k_xy(t)|² = |k_xy(0)|² + 2 t k_xy(0)·a_xy + t² |a_xy|²`
//! is a convex quadratic in `t`, so the side's penetration into the wall is
//! largest at an end of the side's part inside the bore: its bottom end
//! (the circle where the rim fillet meets the side, taken by the rim–wall
//! pair with `n·a ≥ 0`) or its top end at the wall's top (where the mouth
//! fillet meets the wall, taken by the mouth-edge pair with `n_z ≥ 0`).
//! These tests find the deepest point of the side by brute force over poses
//! where a peg tilted in any direction and spun about its axis presses its
//! side against the wall, and check that an accepted contact carries it.

use crate::common::peg3d;

use crate::common::rng;

use nalgebra::{UnitQuaternion, Vector3};
use peg3d::{fig9, orientation};
use pegdyn::compliant_peg_3d::{Pair, Peg3d, Peg3dParams, pose_state};
use rng::Rng;
use std::f64::consts::TAU;

/// The deepest point of the peg's side in the bore wall, by brute force:
/// `(|k_xy| − R, k, at the bottom end)` over 4000 generators, each sampled
/// at 33 heights between the ends of its part inside the bore
/// (`−h_b ≤ z ≤ −ρ_h`, axial coordinate from `ρ_p − L/2` to `L/2`). Asserts
/// the convexity: no interior sample deeper than the deeper end.
fn side_deepest(prm: &Peg3dParams, p: &Vector3<f64>, q: &UnitQuaternion<f64>) -> (f64, bool) {
    let (r, big_r) = (prm.peg_radius(), prm.bore_radius());
    let a = q * Vector3::z();
    let (t_bottom, t_top) = (prm.rim_fillet - 0.5 * prm.length, 0.5 * prm.length);
    let mut best = (f64::NEG_INFINITY, false);
    for i in 0..4000 {
        let b = i as f64 * TAU / 4000.0;
        let k0 = p + q * Vector3::new(r * b.cos(), r * b.sin(), 0.0);
        // z(t) = k0_z + t a_z, a_z > 0: the part with −h_b ≤ z ≤ −ρ_h.
        let lo = t_bottom.max((-prm.bore_depth - k0.z) / a.z);
        let hi = t_top.min((-prm.mouth_fillet - k0.z) / a.z);
        if lo > hi {
            continue;
        }
        let depth = |t: f64| (k0 + a * t).xy().norm() - big_r;
        let (d_lo, d_hi) = (depth(lo), depth(hi));
        for j in 1..32 {
            let d = depth(lo + (hi - lo) * j as f64 / 32.0);
            assert!(
                d <= d_lo.max(d_hi) + 1e-15,
                "interior of a generator deeper than its ends"
            );
        }
        if d_lo > best.0 {
            best = (d_lo, lo == t_bottom);
        }
        if d_hi > best.0 {
            best = (d_hi, false);
        }
    }
    best
}

#[test]
fn side_pressed_on_the_wall_is_carried_by_an_accepted_contact_at_the_deeper_end() {
    let prm = fig9();
    let sys = Peg3d::new(prm);
    let mut rng = Rng(0x51DE_3A11);
    let (mut bottom, mut top) = (0, 0);
    let mut worst: f64 = 0.0;
    for _ in 0..60 {
        // Tilts small enough that the centred peg's side clears the wall
        // (γ ℓ / 2 below the 25 µm clearance over the side's part ℓ in the
        // bore), so a sideways shift presses one side only.
        let gamma = rng.uniform(0.0005, 0.003);
        let q = orientation(gamma, rng.uniform(0.0, TAU), rng.uniform(0.0, TAU));
        let a = q * Vector3::z();
        let depth = rng.uniform(0.004, 0.015);
        let u = rng.uniform(0.0, TAU);
        let dir = Vector3::new(u.cos(), u.sin(), 0.0);
        let target = rng.uniform(5e-6, 40e-6);
        // The axis crosses the hole's axis halfway down the side's part in
        // the bore; the bottom face is about `depth` below the top face.
        let middle = Vector3::new(0.0, 0.0, -0.5 * (depth + prm.mouth_fillet));
        let centre = middle + a * (0.5 * prm.length - 0.5 * (depth - prm.mouth_fillet));
        // Shift sideways until the deepest side point is `target` deep.
        let mut e = 0.0;
        for _ in 0..4 {
            let (d, _) = side_deepest(&prm, &(centre + dir * e), &q);
            e += target - d;
        }
        let p = centre + dir * e;
        let (deep, at_bottom) = side_deepest(&prm, &p, &q);
        assert!(
            (deep - target).abs() < 1e-8,
            "shift did not converge: {deep}"
        );
        let y = pose_state(p, q, Vector3::zeros(), Vector3::zeros());
        let want = if at_bottom {
            Pair::RimWall
        } else {
            Pair::EdgeSide
        };
        let carried = sys
            .contacts(&y)
            .iter()
            .filter(|c| c.pair == want)
            .map(|c| c.penetration)
            .fold(f64::NEG_INFINITY, f64::max);
        // The rim torus reaches ρ_p (1 − cos) past the junction circle, the
        // mouth torus is measured across the peg's axis: O(ρ γ²) apart.
        let tol = 2.0 * prm.rim_fillet * gamma * gamma + 1e-8;
        assert!(
            (carried - deep).abs() <= tol,
            "{want:?}: carried {carried:e} vs the side's deepest {deep:e} (γ = {gamma})"
        );
        worst = worst.max((carried - deep).abs());
        if at_bottom {
            bottom += 1;
        } else {
            top += 1;
        }
    }
    eprintln!(
        "side on the wall: {bottom} deepest at the bottom end, {top} at the top; worst {worst:.2e} m"
    );
    assert!(bottom >= 10 && top >= 10, "bottom {bottom}, top {top}");
}
