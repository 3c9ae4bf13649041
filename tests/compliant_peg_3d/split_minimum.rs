//! A rim-on-mouth minimum splitting into two about a col (the insertion
//! scene's peg where a second rim-on-mouth point appears): about the
//! split, the search decides the arcs by the sign of a higher derivative
//! of the profile. At poses straddling the split (the peg lowered or
//! raised by 10⁻¹² to 10⁻⁶ m, on the plane of symmetry and off it) every
//! penetrating minimum that the dense reference shows is found, with its
//! gap and point, and no point that is not a minimum; and the search no
//! longer halves its way down to the split.

use crate::common::search_reference::{Pose, Tally, compare};
use crate::insertion_split::{insertion_peg, split_pose};
use nalgebra::SVector;
use pegdyn::compliant_peg_3d::{Pair, Search};

/// The split pose lowered by `dz` and moved sideways by `dy` (m).
fn moved(dz: f64, dy: f64) -> SVector<f64, 7> {
    let mut x = split_pose();
    x[1] += dy;
    x[2] -= dz;
    x
}

const LOWER: [f64; 9] = [-1e-6, -1e-8, -1e-10, -1e-12, 0.0, 1e-12, 1e-10, 1e-8, 1e-6];
const ASIDE: [f64; 3] = [0.0, 1e-9, 1e-6];

#[test]
fn contacts_about_a_splitting_minimum_match_the_dense_reference() {
    let prm = insertion_peg();
    let pv = prm.vector();
    let mut t = Tally::default();
    for dz in LOWER {
        for dy in ASIDE {
            let x = moved(dz, dy);
            let pose = Pose {
                p: [x[0], x[1], x[2]],
                q: [x[3], x[4], x[5], x[6]],
            };
            compare(&prm, &pv, &pose, &mut t);
        }
    }
    eprintln!(
        "contacts by pair {:?}, plateaus {}, library-only {}, gap error {:e}, most arcs {}",
        t.contacts, t.unresolved, t.library_only, t.gap_err, t.max_arcs
    );
    assert!(
        t.failed == 0,
        "{} failures:\n{}",
        t.failed,
        t.failures.join("\n")
    );
    // The rim on the mouth edge touches at every pose: a contact the
    // reference resolves, or a plateau below its grid (skipped by it).
    let rim_edge = t.contacts[Pair::RimEdge.index()];
    assert!(rim_edge > 0 && rim_edge + t.unresolved >= LOWER.len() * ASIDE.len());
}

#[test]
fn the_search_about_a_split_is_decided_by_a_higher_derivative() {
    // Before, the branch and bound halved about the split down to arcs
    // shorter than the distance between the stationary points: 400 to
    // 850 arcs per search at the insertion's poses. With the pieces of
    // one sign of h‴ and h″, the whole circle takes a few tens.
    let prm = insertion_peg();
    let pv = prm.vector();
    for dz in LOWER {
        for dy in ASIDE {
            let x = moved(dz, dy);
            let mut s = Search::default();
            let found = s.minima(Pair::RimEdge, &x, &pv, 0.0);
            assert!(!found.is_empty(), "dz {dz}, dy {dy}: no minimum");
            assert!(s.work.ordered > 0, "dz {dz}, dy {dy}: {:?}", s.work);
            assert!(s.work.arcs <= 80, "dz {dz}, dy {dy}: {:?}", s.work);
        }
    }
}
