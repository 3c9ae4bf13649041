//! A pair searched from its last full search (only on the arcs that
//! search could not certify clear, while the pose stays within
//! `search::TRACK` of it) finds the contacts a fresh search finds: over
//! random poses near contact, each followed by a walk of small moves (1 nm
//! to 1 mm and the matching rotation, so that contacts appear where the
//! record had the circle clear), every contact of a fresh search
//! is found with its angle to 10⁻⁹ rad and its depth and point to
//! 10⁻¹² m, and nothing else deeper than grazing; the same when each move
//! also turns the peg about the hole's axis by up to π (the rim's pairs
//! keep their records through a turn, the peg's side against the mouth
//! edge does not).

use crate::common::peg3d::{fig9, orientation};
use crate::common::rng::Rng;
use crate::common::search_reference::{
    GRAZING, Geo, Pose, Tally, angle_distance, compare_contacts, near_contact,
};
use crate::insertion_split::{insertion_peg, split_pose};
use nalgebra::{SVector, Unit, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::{ContactPoint, Contacts, Pair, Peg3dParams, Search};
use std::f64::consts::PI;

/// `x` moved by `size` (m) in a random direction and turned by
/// `size / 0.02` rad about a random axis.
pub(crate) fn moved(x: &SVector<f64, 7>, size: f64, rng: &mut Rng) -> SVector<f64, 7> {
    let dir = Vector3::from_fn(|_, _| rng.uniform(-1.0, 1.0));
    let axis = Unit::new_normalize(Vector3::from_fn(|_, _| rng.uniform(-1.0, 1.0)));
    let q0 = UnitQuaternion::new_normalize(nalgebra::Quaternion::new(x[3], x[4], x[5], x[6]));
    let q = UnitQuaternion::from_axis_angle(&axis, size / 0.02) * q0;
    let p = Vector3::new(x[0], x[1], x[2]) + dir.normalize() * size;
    SVector::from([p.x, p.y, p.z, q.w, q.i, q.j, q.k])
}

/// `x` turned about the hole's axis `e_z` by `phi` (rad): position and
/// orientation both, the same pose relative to the hole.
fn turned(x: &SVector<f64, 7>, phi: f64) -> SVector<f64, 7> {
    let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), phi);
    let q0 = UnitQuaternion::new_normalize(nalgebra::Quaternion::new(x[3], x[4], x[5], x[6]));
    let q = turn * q0;
    let p = turn * Vector3::new(x[0], x[1], x[2]);
    SVector::from([p.x, p.y, p.z, q.w, q.i, q.j, q.k])
}

/// What a walk compared: searches from a tracked record, searches whose
/// pair's window dropped arcs, contacts matched, failures.
#[derive(Default)]
struct Walks {
    tracked: usize,
    cached: usize,
    windowed: usize,
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

/// Walks of eight moves by `step` from poses near contact of `pairs` in
/// turn, each search from the walk's record compared with a fresh one.
fn walk(
    prm: &Peg3dParams,
    seed: u64,
    starts: usize,
    pairs: &[Pair],
    step: impl Fn(&SVector<f64, 7>, Pair, &mut Rng) -> SVector<f64, 7>,
) -> Walks {
    let g = Geo::of(prm);
    walk_from(
        prm,
        seed,
        starts,
        pairs,
        |pair, rng| near_contact(&g, pair, rng).x(),
        step,
    )
}

/// [`walk`] from the poses `begin` gives.
fn walk_from(
    prm: &Peg3dParams,
    seed: u64,
    starts: usize,
    pairs: &[Pair],
    begin: impl Fn(Pair, &mut Rng) -> SVector<f64, 7>,
    step: impl Fn(&SVector<f64, 7>, Pair, &mut Rng) -> SVector<f64, 7>,
) -> Walks {
    let mut rng = Rng(seed);
    let mut w = Walks::default();
    for n in 0..starts {
        let pair = pairs[n % pairs.len()];
        let mut s = Search::default();
        let mut x = begin(pair, &mut rng);
        find(&mut s, pair, prm, &x);
        for _ in 0..8 {
            x = step(&x, pair, &mut rng);
            let kept = find(&mut s, pair, prm, &x);
            w.tracked += usize::from(s.work.tracked);
            w.cached += usize::from(s.work.cached);
            w.windowed += usize::from(s.work.windowed());
            let fresh = find(&mut Search::default(), pair, prm, &x);
            compare(pair, &x, &kept, &fresh, &mut w);
        }
    }
    w
}

/// Walks of every pair, each move of 1 nm to 1 mm, and, with `turns`,
/// turned about the hole's axis by up to π as well (the same pose
/// relative to the hole for the rim's pairs, the mouth edge's points moved
/// along its circle for the peg's side).
fn walks(prm: &Peg3dParams, seed: u64, starts: usize, turns: bool) -> Walks {
    walk(prm, seed, starts, &Pair::ALL, |x, _, rng| {
        let size = 10f64.powf(rng.uniform(-9.0, -3.0));
        let x = moved(x, size, rng);
        if turns {
            turned(&x, rng.uniform(-PI, PI))
        } else {
            x
        }
    })
}

/// Walks of the two pairs with a window (the rim against the bore wall,
/// the mouth edge against the peg's side), each move a slide of 1 µm to
/// 0.1 mm along the window's coordinate (down or up the hole's axis for
/// the wall, along the peg's axis for its side), which moves no gap and
/// carries a contact into or out of the part of the surface that exists.
fn walks_along(prm: &Peg3dParams, seed: u64, starts: usize) -> Walks {
    walk(
        prm,
        seed,
        starts,
        &[Pair::RimWall, Pair::EdgeSide],
        |x, pair, rng| {
            let size = 10f64.powf(rng.uniform(-6.0, -4.0));
            let sign = if rng.next_f64() < 0.5 { -1.0 } else { 1.0 };
            let along = match pair {
                Pair::RimWall => Vector3::z(),
                _ => pegdyn::compliant_peg_3d::axis_of(x),
            };
            let mut x = *x;
            for i in 0..3 {
                x[i] += sign * size * along[i];
            }
            x
        },
    )
}

/// Walks of the mouth edge against the peg's side, each move a turn of
/// 0.1 µrad to 1 mrad about a random axis through the point of the peg's
/// axis nearest the mouth's centre (where a leaning peg pivots: the move
/// that brings the side's gap nearest its bound), then a spin about the
/// peg's own axis by up to π (which moves no gap of the side).
fn walks_pivoting(prm: &Peg3dParams, seed: u64, starts: usize) -> Walks {
    walk(prm, seed, starts, &[Pair::EdgeSide], |x, _, rng| {
        let angle = 10f64.powf(rng.uniform(-7.0, -3.0));
        let axis = Unit::new_normalize(Vector3::from_fn(|_, _| rng.uniform(-1.0, 1.0)));
        let turn = UnitQuaternion::from_axis_angle(&axis, angle);
        let q0 = UnitQuaternion::new_normalize(nalgebra::Quaternion::new(x[3], x[4], x[5], x[6]));
        let a = q0 * Vector3::z();
        let p0 = Vector3::new(x[0], x[1], x[2]);
        let o = Vector3::new(0.0, 0.0, -prm.mouth_fillet);
        let pivot = p0 + a * (o - p0).dot(&a);
        let p = pivot + turn * (p0 - pivot);
        let spin = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(-PI, PI));
        let q = turn * q0 * spin;
        SVector::from([p.x, p.y, p.z, q.w, q.i, q.j, q.k])
    })
}

/// Walks of the rim against the block's top face and the bore's bottom,
/// from a rim tilted by up to 0.05 rad with its lowest point within 10 µm
/// of the plane and its centre up to 1 mm past where the whole circle is
/// over the hole (the top) or over the bottom's disc, each move a
/// horizontal slide of 1 µm to 0.3 mm, which moves no gap of the plane and
/// carries the rim from over the hole onto the face (or out past the bore
/// wall over the bottom).
fn walks_across(prm: &Peg3dParams, seed: u64, starts: usize) -> Walks {
    let begin = |pair: Pair, rng: &mut Rng| near_a_face(prm, pair, rng);
    walk_from(
        prm,
        seed,
        starts,
        &[Pair::RimTop, Pair::RimBottom],
        begin,
        |x, _, rng| slid(x, rng),
    )
}

/// A rim tilted by up to 0.05 rad (half of them towards their offset,
/// the lowest point outermost) with its lowest point within 10 µm of
/// `pair`'s plane and its centre up to 1 mm past where the whole circle is
/// over the hole (the top face) or over the bottom's disc.
fn near_a_face(prm: &Peg3dParams, pair: Pair, rng: &mut Rng) -> SVector<f64, 7> {
    let (rho_p, half) = (prm.rim_fillet, 0.5 * prm.length);
    let rr = prm.peg_radius() - rho_p;
    let gamma = rng.uniform(0.0, 0.05);
    let phi = rng.uniform(-PI, PI);
    // Half the rims lean towards their offset: the lowest point outermost.
    let psi = if rng.next_f64() < 0.5 {
        phi
    } else {
        rng.uniform(-PI, PI)
    };
    let q = orientation(gamma, psi, rng.uniform(-PI, PI));
    let a = q * Vector3::z();
    let (plane, edge) = if pair == Pair::RimTop {
        (0.0, prm.bore_radius() + prm.mouth_fillet)
    } else {
        (-prm.bore_depth, prm.bore_radius())
    };
    let offset = rng.uniform(0.0, (edge - rr).max(0.0) + 1e-3);
    let sign = if rng.next_f64() < 0.5 { -1.0 } else { 1.0 };
    let gap = sign * 10f64.powf(rng.uniform(-9.0, -5.0));
    let centre = Vector3::new(
        offset * phi.cos(),
        offset * phi.sin(),
        plane + rho_p + gap + rr * gamma.sin(),
    );
    let p = centre - a * (rho_p - half);
    SVector::from([p.x, p.y, p.z, q.w, q.i, q.j, q.k])
}

/// `x` slid horizontally by 1 µm to 0.3 mm in a random direction.
fn slid(x: &SVector<f64, 7>, rng: &mut Rng) -> SVector<f64, 7> {
    let size = 10f64.powf(rng.uniform(-6.0, -3.5));
    let phi = rng.uniform(-PI, PI);
    let mut x = *x;
    x[0] += size * phi.cos();
    x[1] += size * phi.sin();
    x
}

/// Prints what the walks compared and fails on any mismatch.
fn report(w: &Walks) {
    eprintln!(
        "{} tracked searches ({} windowed), {} certified clear, {} contacts matched, {} failures",
        w.tracked,
        w.windowed,
        w.cached,
        w.matched,
        w.failures.len()
    );
    assert!(
        w.failures.is_empty(),
        "{}",
        w.failures[..w.failures.len().min(10)].join("\n")
    );
}

fn check(w: &Walks, starts: usize) {
    report(w);
    // The walks exercise the tracked search and meet contacts.
    assert!(w.tracked > starts, "{} tracked searches", w.tracked);
    assert!(w.windowed > starts / 10, "{} windowed searches", w.windowed);
    assert!(w.matched > starts, "{} contacts", w.matched);
}

#[test]
fn a_tracked_search_finds_the_fresh_searchs_contacts_on_the_fig9_peg() {
    let starts = 20_000;
    check(&walks(&fig9(), 0x72AC_0001, starts, false), starts);
}

#[test]
fn a_tracked_search_finds_the_fresh_searchs_contacts_as_the_peg_slides_out_of_a_window() {
    let starts = 20_000;
    check(&walks_along(&fig9(), 0x72AC_0004, starts), starts);
}

#[test]
fn a_tracked_search_finds_the_fresh_searchs_contacts_when_the_peg_turns_about_the_hole() {
    let starts = 20_000;
    check(&walks(&fig9(), 0x72AC_0003, starts, true), starts);
}

#[test]
fn a_tracked_search_finds_the_fresh_searchs_contacts_on_the_insertion_peg() {
    let starts = 20_000;
    check(&walks(&insertion_peg(), 0x72AC_0002, starts, false), starts);
}

#[test]
fn a_tracked_search_finds_the_fresh_searchs_contacts_as_the_peg_pivots_and_spins() {
    let starts = 20_000;
    check(&walks_pivoting(&fig9(), 0x72AC_0005, starts), starts);
}

#[test]
fn a_search_certified_off_the_faces_finds_the_fresh_searchs_contacts_as_the_rim_slides_across() {
    let starts = 20_000;
    let w = walks_across(&fig9(), 0x72AC_0006, starts);
    report(&w);
    // The plane pairs keep no tracked record: the walks exercise the
    // certificate off the face and its reuse, and meet contacts.
    assert!(w.windowed > starts / 20, "{} off the face", w.windowed);
    assert!(w.cached > starts, "{} certified clear", w.cached);
    assert!(w.matched > starts, "{} contacts", w.matched);
}

#[test]
fn the_contact_path_near_the_faces_edges_finds_the_dense_references_valid_contacts() {
    // Rims near the top face's and the bottom's edges, where the plane
    // pairs' certificates (the circle off the face, the one minimum off
    // it) decide: every valid contact of the dense reference is found.
    let prm = fig9();
    let pv = prm.vector();
    let mut rng = Rng(0x72AC_0007);
    let mut tally = Tally::default();
    for n in 0..4000 {
        let pair = if n % 2 == 0 {
            Pair::RimTop
        } else {
            Pair::RimBottom
        };
        let x = slid(&near_a_face(&prm, pair, &mut rng), &mut rng);
        let pose = Pose {
            p: [x[0], x[1], x[2]],
            q: [x[3], x[4], x[5], x[6]],
        };
        compare_contacts(&prm, &pv, &pose, &mut tally);
    }
    eprintln!(
        "valid reference contacts by pair {:?}, {} failures",
        tally.valid, tally.failed
    );
    assert!(tally.failed == 0, "{}", tally.failures.join("\n"));
    let planes = [Pair::RimTop.index(), Pair::RimBottom.index()];
    for k in planes {
        assert!(tally.valid[k] > 100, "{:?}", tally.valid);
    }
}

#[test]
fn a_tracked_search_finds_the_fresh_searchs_contacts_through_a_splitting_minimum() {
    // The insertion run's split of one rim-on-mouth minimum into two about
    // a col: walks from poses raised or lowered by up to 1 µm about it,
    // each move up or down by 10⁻¹² to 10⁻⁶ m and aside by up to 1 µm, so
    // that an arc its record decided convex may hold two minima now.
    let prm = insertion_peg();
    let starts = 4000;
    let w = walk_from(
        &prm,
        0x72AC_0008,
        starts,
        &[Pair::RimEdge],
        |_, rng| {
            let mut x = split_pose();
            x[2] += rng.uniform(-1e-6, 1e-6);
            x[1] += rng.uniform(-1e-7, 1e-7);
            x
        },
        |x, _, rng| {
            let sign = if rng.next_f64() < 0.5 { -1.0 } else { 1.0 };
            let mut x = *x;
            x[2] += sign * 10f64.powf(rng.uniform(-12.0, -6.0));
            x[1] += rng.uniform(-1e-6, 1e-6);
            x
        },
    );
    report(&w);
    assert!(
        w.tracked > starts && w.matched > starts,
        "{} {}",
        w.tracked,
        w.matched
    );
}
