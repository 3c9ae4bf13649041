//! The contact search misses no contact: over 10⁵ random poses near
//! contact (tilt 0 to π/2, any azimuth, spin and depth, each pair in turn
//! brought to a penetration between −1 mm and 10 µm) every local minimum
//! of every pair's gap below zero that a dense reference shows
//! (`tests/common/search_reference.rs`: 16 384 samples per circle where
//! bounds cannot rule a minimum out, refined by bisection on `g′`) is
//! found, with its gap and contact point to 10⁻¹² m, and every minimum the
//! search returns below zero is a local minimum of the independent gap.
//! Half the poses use the Fig. 9 peg (50 mm bore, 25 µm radial clearance,
//! 1 mm fillets), half the insertion scene's peg (25 mm bore, 37.5 µm,
//! fillets 0.3 and 0.5 mm).

use crate::common::peg3d::fig9;
use crate::common::prescribed_rigid::{params, preloaded_state};
use crate::common::search_reference::{Pose, SAMPLES, TOL, Tally, campaign, compare};
use crate::insertion_split::insertion_peg;
use pegdyn::compliant_peg_3d::Pair;
use pegdyn::compliant_peg_3d::prescribed::{Motion, PrescribedPeg};
use pegdyn::rigid_peg::PegParams;

/// Poses per test (four tests: 10⁵ in all).
const POSES: usize = 25_000;

fn check(t: &Tally) {
    eprintln!(
        "{} poses ({} searches): reference contacts by pair {:?} (valid {:?}), unresolved \
         plateaus {}, library-only minima {}, largest gap error {:e} m, point error {:e} m, \
         most arcs {}, reference evaluations {}",
        t.poses,
        t.searches,
        t.contacts,
        t.valid,
        t.unresolved,
        t.library_only,
        t.gap_err,
        t.point_err,
        t.max_arcs,
        t.evals
    );
    assert!(
        t.failed == 0,
        "{} failures:\n{}",
        t.failed,
        t.failures.join("\n")
    );
    assert!(t.gap_err <= TOL && t.point_err <= TOL);
    // Every pair is exercised near contact.
    for (k, &n) in t.contacts.iter().enumerate() {
        assert!(n > POSES / 50, "{:?}: only {n} contacts", Pair::ALL[k]);
    }
    // And the contact path's validity: every pair has valid contacts.
    for (k, &n) in t.valid.iter().enumerate() {
        assert!(
            n > POSES / 200,
            "{:?}: only {n} valid contacts",
            Pair::ALL[k]
        );
    }
}

#[test]
fn search_finds_every_contact_of_the_fig9_peg_near_contact_seed_1() {
    check(&campaign(&fig9(), 0x5EA_0001, POSES));
}

#[test]
fn search_finds_every_contact_of_the_fig9_peg_near_contact_seed_2() {
    check(&campaign(&fig9(), 0x5EA_0002, POSES));
}

#[test]
fn search_finds_every_contact_of_the_insertion_peg_near_contact_seed_1() {
    check(&campaign(&insertion_peg(), 0x5EA_0003, POSES));
}

#[test]
fn search_finds_every_contact_of_the_insertion_peg_near_contact_seed_2() {
    check(&campaign(&insertion_peg(), 0x5EA_0004, POSES));
}

#[test]
fn cold_search_finds_the_three_point_lean_at_large_tilts() {
    // The rigid Fig. 9 lean (K on the peg's side, B1 and B2 where the rim
    // crosses the mouth edge) at tilts where a sampled scan of 48 angles
    // misses the edge-on-edge points (their dip is narrower than a
    // sample spacing), preloaded so that each carries m g (20 µm fillets,
    // k = 2.4·10¹⁰ N/m^{3/2}: about 0.4 µm deep): a fresh system, with no
    // warm start, finds all three, as the dense reference does.
    let rigid = PegParams::fig9();
    let k = 2.4e10;
    let w = rigid.mass * rigid.gravity;
    for gamma in [0.3, 0.45, 0.515, 0.7, 1.0] {
        let motion = Motion {
            gamma,
            gammadot: -2.0,
            psi: 0.0,
            psidot: 10.0,
        };
        let sys = PrescribedPeg::try_new(params(&rigid, k), motion).unwrap();
        let y = preloaded_state(&sys, &rigid, [w, w, w], k);
        let fresh = PrescribedPeg::try_new(params(&rigid, k), motion).unwrap();
        let forces = fresh.forces(0.0, &y).unwrap();
        let count = |p: Pair| forces.iter().filter(|f| f.contact.pair == p).count();
        assert_eq!(
            (count(Pair::EdgeSide), count(Pair::RimEdge), forces.len()),
            (1, 2, 3),
            "γ = {gamma}: {forces:?}"
        );
        for f in &forces {
            let depth = f.contact.penetration;
            assert!(depth > 1e-7 && depth < 1e-6, "γ = {gamma}: {depth}");
        }
        let q = motion.orientation(0.0);
        let pose = Pose {
            p: [y[0], y[1], y[2]],
            q: [q.w, q.i, q.j, q.k],
        };
        let mut t = Tally::default();
        compare(&sys.peg.params, sys.peg.param_vector(), &pose, &mut t);
        assert!(t.failed == 0, "γ = {gamma}: {:?}", t.failures);
        assert_eq!(
            (
                t.contacts[Pair::EdgeSide.index()],
                t.contacts[Pair::RimEdge.index()]
            ),
            (1, 2),
            "γ = {gamma}: the reference's contacts ({SAMPLES} samples per circle)"
        );
    }
}
