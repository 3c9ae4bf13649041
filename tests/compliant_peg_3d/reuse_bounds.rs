//! The bounds by which a tracked search carries a kept arc's decision to
//! a nearby pose (`pegdyn::compliant_peg_3d::search::reuse`): over random
//! poses near contact of the three searched pairs, each moved by 1 nm to
//! 30 µm and turned to match, the change of the pair's profile `h`, `h′`,
//! `h″` at points of a random arc (from their point enclosures at both
//! poses) stays within the bounds `D₀, D₁, D₂` the arc's enclosures at the
//! first pose give; and the bounds are not idly loose (the largest change
//! seen reaches half its bound for each pair and derivative).

use crate::common::peg3d::fig9;
use crate::common::rng::Rng;
use crate::common::search_reference::{Geo, near_contact};
use crate::insertion_split::insertion_peg;
use crate::tracked_search::moved;
use pegdyn::compliant_peg_3d::search::CLEARANCE;
use pegdyn::compliant_peg_3d::search::interval::Iv;
use pegdyn::compliant_peg_3d::search::profile::Problem;
use pegdyn::compliant_peg_3d::search::reuse::{Carried, Kind, Note, Shift, carry};
use pegdyn::compliant_peg_3d::search::trig::Enclosure;
use pegdyn::compliant_peg_3d::{Pair, Peg3dParams};
use std::f64::consts::TAU;

/// The largest ratio of change to bound seen for `h`, `h′`, `h″`, and
/// the arcs compared, for `pair`; panics at a change above its bound.
fn check(prm: &Peg3dParams, pair: Pair, seed: u64, n: usize) -> ([f64; 3], usize) {
    let g = Geo::of(prm);
    let pv = prm.vector();
    let mut rng = Rng(seed);
    let mut worst = [0.0_f64; 3];
    let mut compared = 0;
    for _ in 0..n {
        let x0 = near_contact(&g, pair, &mut rng).x();
        let x1 = moved(&x0, 10f64.powf(rng.uniform(-9.0, -4.5)), &mut rng);
        let (Problem::Search { h: h0, .. }, Problem::Search { h: h1, .. }) = (
            Problem::of(pair, &x0, &pv, CLEARANCE),
            Problem::of(pair, &x1, &pv, CLEARANCE),
        ) else {
            continue;
        };
        let m = rng.uniform(0.0, TAU);
        let w = 10f64.powf(rng.uniform(-5.0, -0.5));
        let (s, c) = m.sin_cos();
        let note = Note {
            kind: Kind::Other,
            h: h0.enclose(c, s, w, f64::INFINITY),
            parts: h0.parts(c, s, w),
        };
        let Some(d) = Shift::between(&h0, &h1).and_then(|sh| sh.over(&note)) else {
            continue;
        };
        compared += 1;
        for i in 0..8 {
            let t = m + w * (2.0 * i as f64 / 7.0 - 1.0);
            let (Some(j0), Some(j1)) = (h0.point(t), h1.point(t)) else {
                continue;
            };
            for k in 0..3 {
                let change = (j1[k].mid() - j0[k].mid()).abs();
                let rounding = (j0[k].hi - j0[k].lo) + (j1[k].hi - j1[k].lo);
                assert!(
                    change <= d[k] + rounding,
                    "{pair:?} at {x0:?} -> {x1:?}, angle {t}: derivative {k} changed by \
                     {change:e}, bound {:e}",
                    d[k]
                );
                if rounding < 1e-3 * change {
                    worst[k] = worst[k].max(change / d[k]);
                }
            }
        }
    }
    (worst, compared)
}

#[test]
fn a_profiles_change_between_nearby_poses_stays_within_the_reuse_bounds() {
    for (prm, seed) in [(fig9(), 0xB0D_0001), (insertion_peg(), 0xB0D_0002)] {
        for pair in [Pair::EdgeSide, Pair::RimWall, Pair::RimEdge] {
            let (worst, compared) = check(&prm, pair, seed + pair.index() as u64, 4000);
            eprintln!("{pair:?}: {compared} arcs, largest change over bound {worst:?}");
            assert!(compared > 2000, "{pair:?}: {compared} arcs");
            for (k, r) in worst.iter().enumerate() {
                assert!(
                    *r > 0.5,
                    "{pair:?}: derivative {k} reaches {r} of its bound"
                );
            }
        }
    }
}

/// A note of `kind` with `h ∈ [0, 1]`, and `h′`, `h″` as given.
fn note(kind: Kind, d1: (f64, f64), d2: (f64, f64)) -> Note {
    Note {
        kind,
        h: Enclosure {
            value: Iv::new(0.0, 1.0),
            d1: Iv::new(d1.0, d1.1),
            d2: Iv::new(d2.0, d2.1),
            refinable: true,
        },
        parts: None,
    }
}

#[test]
fn a_decision_carries_while_its_margin_exceeds_the_change() {
    let convex = note(Kind::Convex, (-1.0, 1.0), (0.5, 2.0));
    assert_eq!(carry(&convex, [0.1, 0.1, 0.4], 0.5), Carried::Convex);
    assert_eq!(carry(&convex, [0.1, 0.1, 0.6], 0.5), Carried::Afresh);
    let rising = note(Kind::Monotone, (0.3, 1.0), (-1.0, 1.0));
    assert_eq!(carry(&rising, [0.1, 0.2, 9.0], 0.5), Carried::Clear);
    assert_eq!(carry(&rising, [0.1, 0.4, 0.0], 0.5), Carried::Afresh);
    let falling = note(Kind::Monotone, (-1.0, -0.3), (-1.0, 1.0));
    assert_eq!(carry(&falling, [0.1, 0.2, 0.0], 0.5), Carried::Clear);
    assert_eq!(carry(&falling, [0.1, 0.4, 0.0], 0.5), Carried::Afresh);
    let concave = note(Kind::Concave, (-1.0, 1.0), (-2.0, -0.5));
    assert_eq!(carry(&concave, [0.1, 9.0, 0.4], 0.5), Carried::Clear);
    assert_eq!(carry(&concave, [0.1, 0.0, 0.6], 0.5), Carried::Afresh);
    // Above the level by more than the value's change: dropped; a leaf or
    // an ordered cut is always decided afresh.
    assert_eq!(carry(&convex, [0.1, 0.0, 0.0], -0.2), Carried::Above(-0.1));
    let leaf = note(Kind::Other, (0.3, 1.0), (0.5, 2.0));
    assert_eq!(carry(&leaf, [0.0; 3], 0.5), Carried::Afresh);
}
