//! A pose where one rim-on-mouth minimum is splitting into two about a
//! col (the moment a second rim-on-mouth point appears in the insertion
//! scene's peg, seen by a run at a tight tolerance): the gap is flat
//! there to the rounding of its slope, and the computed slope of the
//! profile is exactly zero at the ends of the arcs that hold the two
//! minima. The search finds the penetrating minimum that a dense sampling
//! of the generated gap shows, and a search that has walked to a pose in
//! tiny steps returns the same contacts there as a fresh one.

use crate::insertion_split::{insertion_peg, split_pose};
use nalgebra::SVector;
use pegdyn::compliant_peg_3d::{Contacts, Pair, Peg3dParams, Search};
use std::f64::consts::TAU;

/// The rim-on-mouth contacts of a search at `x`.
fn rim_edge(search: &mut Search, prm: &Peg3dParams, x: &SVector<f64, 7>) -> Vec<(f64, f64)> {
    let mut out = Contacts::new();
    search.find(Pair::RimEdge, prm, x, &prm.vector(), &mut out);
    out.iter().map(|c| (c.angle, c.penetration)).collect()
}

#[test]
fn the_search_finds_a_penetrating_minimum_in_a_flat_stretch() {
    let prm = insertion_peg();
    let p = prm.vector();
    let x = split_pose();
    // The least gap over the circle by dense sampling of the generated
    // function: 10⁻⁴ rad over the circle, 10⁻⁸ rad within 10⁻³ rad of 0
    // (where the least values lie).
    let gap = |a: f64| Pair::RimEdge.eval(&x, a, &p).gap;
    let coarse = (0..62_832).map(|k| k as f64 * 1e-4);
    let fine = (-100_000..=100_000).map(|k| (k as f64 * 1e-8).rem_euclid(TAU));
    let (a_min, g_min) = coarse
        .chain(fine)
        .map(|a| (a, gap(a)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap();
    assert!(g_min < -4e-7, "the pose penetrates: {g_min} at {a_min}");
    let found = rim_edge(&mut Search::default(), &prm, &x);
    assert!(
        !found.is_empty(),
        "no rim-on-mouth contact; sampled gap {g_min}"
    );
    for &(a, depth) in &found {
        // The minima are within the flat stretch about 0 and as deep as
        // the sampled least gap (to 10⁻¹⁵ m: the stretch is flat).
        assert!(a.min(TAU - a) < 1e-4, "{found:?}");
        assert!((depth + g_min).abs() < 1e-15, "{depth} vs {g_min}");
    }
}

#[test]
fn a_search_walked_in_tiny_steps_returns_the_contacts_of_a_fresh_search() {
    // The tube pose above lowered by 10⁻¹² m per step, 200 steps, searched
    // in turn by one `Search` (which may keep a certified clearance from
    // one pose to the next) and at each pose by a fresh one.
    let prm = insertion_peg();
    let mut walked = Search::default();
    for k in 0..200 {
        let mut x = split_pose();
        x[2] -= k as f64 * 1e-12;
        let fresh = rim_edge(&mut Search::default(), &prm, &x);
        let step = rim_edge(&mut walked, &prm, &x);
        assert!(!fresh.is_empty(), "step {k}: no contact");
        assert_eq!(step, fresh, "step {k}");
    }
}
