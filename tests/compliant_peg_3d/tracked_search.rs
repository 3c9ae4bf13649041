//! A pair searched from its last full search (only on the arcs that
//! search could not certify clear, while the pose stays within
//! `search::TRACK` of it) finds the contacts a fresh search finds: over
//! random poses near contact, each followed by a walk of small moves (1 nm
//! to 1 mm and the matching rotation, so that contacts appear where the
//! record had the circle clear), every contact of a fresh search
//! is found with its angle to 10⁻⁹ rad and its depth and point to
//! 10⁻¹² m, and nothing else deeper than grazing.

use crate::common::peg3d::fig9;
use crate::common::rng::Rng;
use crate::common::search_reference::{GRAZING, Geo, Pose, angle_distance, near_contact};
use crate::insertion_split::insertion_peg;
use nalgebra::{SVector, Unit, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::{ContactPoint, Contacts, Pair, Peg3dParams, Search};

/// `x` moved by `size` (m) in a random direction and turned by
/// `size / 0.02` rad about a random axis.
fn moved(x: &SVector<f64, 7>, size: f64, rng: &mut Rng) -> SVector<f64, 7> {
    let dir = Vector3::from_fn(|_, _| rng.uniform(-1.0, 1.0));
    let axis = Unit::new_normalize(Vector3::from_fn(|_, _| rng.uniform(-1.0, 1.0)));
    let q0 = UnitQuaternion::new_normalize(nalgebra::Quaternion::new(x[3], x[4], x[5], x[6]));
    let q = UnitQuaternion::from_axis_angle(&axis, size / 0.02) * q0;
    let p = Vector3::new(x[0], x[1], x[2]) + dir.normalize() * size;
    SVector::from([p.x, p.y, p.z, q.w, q.i, q.j, q.k])
}

/// What a walk compared: searches from a tracked record, contacts
/// matched, failures.
#[derive(Default)]
struct Walks {
    tracked: usize,
    matched: usize,
    failures: Vec<String>,
}

fn find(s: &mut Search, pair: Pair, prm: &Peg3dParams, x: &SVector<f64, 7>) -> Contacts {
    let mut out = Contacts::new();
    s.find(pair, prm, x, &prm.vector(), &mut out);
    out
}

fn compare(
    pair: Pair,
    x: &SVector<f64, 7>,
    kept: &[ContactPoint],
    fresh: &[ContactPoint],
    w: &mut Walks,
) {
    let mut used = vec![false; kept.len()];
    for f in fresh {
        let hit = kept
            .iter()
            .enumerate()
            .find(|(i, k)| !used[*i] && angle_distance(k.angle, f.angle) <= 1e-9);
        match hit {
            Some((i, k)) => {
                used[i] = true;
                w.matched += 1;
                let depth = (k.penetration - f.penetration).abs();
                let point = (k.point - f.point).norm();
                if depth > 1e-12 || point > 1e-12 {
                    w.failures.push(format!(
                        "{pair:?} at {x:?}: depth {depth:e}, point {point:e} apart"
                    ));
                }
            }
            None if f.penetration > GRAZING => {
                w.failures
                    .push(format!("{pair:?} at {x:?}: missed {f:?}; found {kept:?}"));
            }
            None => {}
        }
    }
    for (k, _) in kept.iter().zip(&used).filter(|(_, u)| !**u) {
        if k.penetration > GRAZING {
            w.failures.push(format!("{pair:?} at {x:?}: extra {k:?}"));
        }
    }
}

fn walks(prm: &Peg3dParams, seed: u64, starts: usize) -> Walks {
    let g = Geo::of(prm);
    let mut rng = Rng(seed);
    let mut w = Walks::default();
    for n in 0..starts {
        let pair = Pair::ALL[n % 5];
        let start: Pose = near_contact(&g, pair, &mut rng);
        let mut s = Search::default();
        let mut x = start.x();
        find(&mut s, pair, prm, &x);
        for _ in 0..8 {
            let size = 10f64.powf(rng.uniform(-9.0, -3.0));
            x = moved(&x, size, &mut rng);
            let kept = find(&mut s, pair, prm, &x);
            w.tracked += usize::from(s.work.tracked);
            let fresh = find(&mut Search::default(), pair, prm, &x);
            compare(pair, &x, &kept, &fresh, &mut w);
        }
    }
    w
}

fn check(w: &Walks, starts: usize) {
    eprintln!(
        "{} tracked searches, {} contacts matched, {} failures",
        w.tracked,
        w.matched,
        w.failures.len()
    );
    assert!(
        w.failures.is_empty(),
        "{}",
        w.failures[..w.failures.len().min(10)].join("\n")
    );
    // The walks exercise the tracked search and meet contacts.
    assert!(w.tracked > starts, "{} tracked searches", w.tracked);
    assert!(w.matched > starts, "{} contacts", w.matched);
}

#[test]
fn a_tracked_search_finds_the_fresh_searchs_contacts_on_the_fig9_peg() {
    let starts = 20_000;
    check(&walks(&fig9(), 0x72AC_0001, starts), starts);
}

#[test]
fn a_tracked_search_finds_the_fresh_searchs_contacts_on_the_insertion_peg() {
    let starts = 20_000;
    check(&walks(&insertion_peg(), 0x72AC_0002, starts), starts);
}
