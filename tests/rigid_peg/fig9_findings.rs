//! The rigid-peg paper's Fig. 9 claim tested: "N_B1 grows sharply near γ0
//! without rotation and rotation (ψ̇ = 10 1/s) lowers it". pegdyn finds a
//! finite limit without rotation, and with rotation a prescribed
//! three-point motion that becomes infeasible near γ0 (B1 would have to
//! pull), with N_B2 − N_B1 ∝ 1/b ∝ (γ − γ0)^(−1/2): the lateral balance
//! along e_n has only the edge normals' lateral components ±(b/|OB|) N_B to
//! balance a finite lateral force (friction against the precession,
//! Coriolis). See `docs/rigid-peg.md`.

use nalgebra::Vector2;
use pegdyn::rigid_peg::kinematics::Geometry;
use pegdyn::rigid_peg::prescribed::reactions;
use pegdyn::rigid_peg::{Loads, PegParams};

fn n_over_mg(p: &PegParams, rel: f64, psidot: f64) -> [f64; 3] {
    let gamma = p.gamma0() * (1.0 + rel);
    let r = reactions(
        p,
        &Loads::default(),
        Vector2::new(gamma, 0.0),
        Vector2::new(-2.0, psidot),
        Vector2::zeros(),
    )
    .unwrap();
    r.normal.map(|n| n / (p.mass * p.gravity))
}

#[test]
fn without_rotation_n_b1_tends_to_a_finite_limit() {
    let p = PegParams::fig9();
    let a = n_over_mg(&p, 1e-8, 0.0);
    let b = n_over_mg(&p, 1e-6, 0.0);
    // Symmetric, finite, O(1..10) m g, and no growth over two decades.
    assert!((a[1] - a[2]).abs() < 1e-9 * a[1]);
    assert!(a[1] > 1.0 && a[1] < 20.0, "{a:?}");
    assert!((a[1] - b[1]).abs() < 1e-3 * a[1], "{a:?} vs {b:?}");
}

#[test]
fn with_rotation_b1_would_pull_near_gamma0_and_the_split_scales_as_one_over_b() {
    let p = PegParams::fig9();
    let half = 0.5 * p.hole_diameter;
    let mut lateral = Vec::new();
    for rel in [1e-8, 1e-7, 1e-6] {
        let n = n_over_mg(&p, rel, 10.0);
        assert!(n[1] < 0.0 && n[2] > 0.0 && n[0] > 0.0, "{rel}: {n:?}");
        let g = Geometry::try_new(&p, p.gamma0() * (1.0 + rel)).unwrap();
        // Lateral component of the B reactions: (N_B2 − N_B1) b/|OB|.
        lateral.push((n[2] - n[1]) * g.b / half.hypot(g.a1));
    }
    // It converges (finite lateral force), so N_B2 − N_B1 ∝ 1/b.
    for w in lateral.windows(2) {
        assert!((w[0] - w[1]).abs() < 0.02 * w[1].abs(), "{lateral:?}");
    }
    // Bounded by friction at all contacts plus Coriolis (in units of m g):
    // f ΣN + 2 m |η_C' γ̇ ψ̇| / (m g).
    let n = n_over_mg(&p, 1e-8, 10.0);
    let g = Geometry::try_new(&p, p.gamma0() * (1.0 + 1e-8)).unwrap();
    let bound = p.friction * (n[0].abs() + n[1].abs() + n[2].abs())
        + 2.0 * (g.deta_c * 2.0 * 10.0).abs() / p.gravity;
    assert!(lateral[0].abs() <= bound, "{} vs {bound}", lateral[0]);
    // Far enough from γ0 the motion is feasible again.
    let far = n_over_mg(&p, 1e-3, 10.0);
    assert!(far.iter().all(|&v| v > 0.0), "{far:?}");
}

#[test]
fn rotation_lowers_n_b1_only_close_to_gamma0() {
    let p = PegParams::fig9();
    // Close to γ0 (feasible side) rotation lowers N_B1 ...
    let (still, spun) = (n_over_mg(&p, 1e-2, 0.0), n_over_mg(&p, 1e-2, 10.0));
    assert!(spun[1] < 0.5 * still[1], "{still:?} vs {spun:?}");
    // ... but at γ = 0.0866 rad it nearly triples it.
    let rel = 0.0866 / p.gamma0() - 1.0;
    let (still, spun) = (n_over_mg(&p, rel, 0.0), n_over_mg(&p, rel, 10.0));
    assert!(spun[1] > 2.0 * still[1], "{still:?} vs {spun:?}");
}
