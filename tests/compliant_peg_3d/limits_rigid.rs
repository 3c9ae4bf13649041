//! The compliant 3-D peg contains the rigid three-point peg as a limit:
//! its orientation driven along the rigid model's prescribed motion
//! (γ̇ = −2 1/s, ψ̇ = 0 and 10 1/s, the Fig. 9 peg), its translation free
//! under gravity with contact damping, the three contact forces approach
//! the rigid model's N_K, N_B1, N_B2 and the contact points approach K, B1,
//! B2 as the contacts stiffen.
//!
//! K is the peg's side on the mouth edge (pair `edge_side`), B1 and B2 the
//! peg's bottom rim on the mouth edge (pair `rim_edge`, the rim torus on
//! the mouth torus). The rigid model's edges are sharp; the
//! 3-D model's fillets shrink with the penetration (`ρ ∝ k^{−2/3}`), so that
//! both the fillets' and the compliance's departures from the rigid
//! geometry vanish together.

use crate::common::prescribed_rigid;

use pegdyn::compliant_peg_3d::Peg3dParams;
use pegdyn::compliant_peg_3d::prescribed::{Motion, PrescribedPeg};
use pegdyn::compliant_peg_3d::{HertzMode, Pair};
use pegdyn::rigid_peg::PegParams;
use pegdyn::system::OdeSystem;
use prescribed_rigid::{GAMMADOT, fillet, grid, print, run, worst};

#[test]
fn rigid_limit_with_precession_converges_as_the_contacts_stiffen() {
    // ψ̇ = 10 1/s from γ = 0.3 rad (where the rigid model's three-point
    // motion is feasible) to 0.06 rad; compared from 0.26 rad on.
    let gammas = grid(0.3, 0.06, 12);
    let mut table = Vec::new();
    for k in [2.4e9, 2.4e10, 2.4e11] {
        let rows = run(k, 10.0, 0.3, &gammas);
        print(&format!("k = {k:.1e}"), &rows);
        let (force, point) = worst(&rows[2..]);
        eprintln!(
            "k = {k:.1e} N/m^1.5, fillets {:.1e} m: max |N − N_rigid| = {force:.4} m g, max point distance {point:.2e} m",
            fillet(k)
        );
        table.push((force, point));
    }
    for w in table.windows(2) {
        assert!(
            w[1].0 < 0.3 * w[0].0,
            "force error does not shrink: {table:?}"
        );
        assert!(
            w[1].1 < 0.3 * w[0].1,
            "point error does not shrink: {table:?}"
        );
    }
    assert!(table[2].0 < 0.06, "{table:?}");
    assert!(table[2].1 < 3e-4, "{table:?}");
}

#[test]
fn rigid_limit_without_precession_follows_the_planar_motion_and_loses_k_where_the_rigid_one_pulls()
{
    // ψ̇ = 0: the rigid motion needs N_K < 0 for γ > 0.1426 rad. From
    // γ = 0.14 the 3-D peg follows it on three points with B1, B2
    // symmetric; from γ = 0.3 its K stays unloaded while the rigid one
    // pulls.
    let rows = run(2.4e10, 0.0, 0.14, &grid(0.14, 0.06, 8));
    print("ψ̇ = 0", &rows);
    let (force, point) = worst(&rows);
    eprintln!(
        "ψ̇ = 0 from 0.14 rad: max |N − N_rigid| = {force:.4} m g, max point distance {point:.2e} m"
    );
    assert!(force < 0.15 && point < 1e-3, "{force} {point}");
    for r in &rows {
        assert!(r.three_d.iter().all(|&n| n > 0.0));
        let asym = (r.three_d[1] - r.three_d[2]).abs() / r.three_d[1];
        assert!(asym < 1e-6, "B1, B2 differ by {asym:e} relative");
    }
    let rows = run(2.4e10, 0.0, 0.3, &grid(0.3, 0.16, 7));
    for r in &rows {
        assert!(r.rigid[0] < 0.0 && r.three_d[0] == 0.0, "{r:?}");
        assert!(r.three_d[1] > 0.0 && r.three_d[2] > 0.0, "{r:?}");
    }
}

#[test]
fn rigid_limit_with_precession_unloads_b1_towards_gamma0() {
    // ψ̇ = 10 1/s: the rigid model's leading contact B1 unloads towards γ0
    // (and lifts off for γ/γ0 − 1 < 5.5e-5); the stiff 3-D peg's B1 carries
    // less than B2 all the way and the gap between them widens, until the
    // two points merge.
    let rows = run(2.4e11, 10.0, 0.06, &grid(0.06, 0.0455, 29));
    print("near γ0", &rows);
    for r in &rows {
        assert!(r.three_d[1] < r.three_d[2], "{r:?}");
    }
    let (first, last) = (rows[0].three_d, rows[rows.len() - 1].three_d);
    let (ratio0, ratio1) = (first[1] / first[2], last[1] / last[2]);
    eprintln!("N_B1/N_B2: {ratio0:.4} at γ = 0.06, {ratio1:.4} at γ = 0.0455");
    assert!(ratio1 < ratio0 - 0.04, "{ratio0} {ratio1}");
}

#[test]
fn prescribed_peg_refuses_an_invalid_fixed_stiffness() {
    let motion = Motion {
        gamma: 0.3,
        gammadot: GAMMADOT,
        psi: 0.0,
        psidot: 0.0,
    };
    let mut prm = Peg3dParams::steel(0.04995, 0.07, 0.05, 1e-5, 1e-5, 0.1);
    for value in [-1.0, 0.0, f64::INFINITY] {
        prm.hertz = HertzMode::Fixed(value);
        match PrescribedPeg::try_new(prm, motion) {
            Err(pegdyn::hertz::HertzError::Invalid {
                field, value: v, ..
            }) => {
                assert_eq!(field, "hertz");
                assert_eq!(v, value);
            }
            Err(e) => panic!("{value}: {e:?}"),
            Ok(_) => panic!("{value} accepted"),
        }
    }
}

#[test]
fn prescribed_peg_with_curvature_stiffness_is_the_full_peg_translation() {
    // The Fig. 9 lean at γ = 0.3 preloaded with the rigid reactions (fixed
    // k), then the same state with the stiffness from the curvatures: K and
    // both rim–mouth points touch, each with its own Hertz stiffness, and
    // the prescribed right-hand side is the full peg's ṗ, v̇ and Ṡ.
    let k = 2.4e10;
    let rigid = PegParams::fig9();
    let mut prm = prescribed_rigid::params(&rigid, k);
    let motion = Motion {
        gamma: 0.3,
        gammadot: GAMMADOT,
        psi: 0.0,
        psidot: 10.0,
    };
    let fixed = PrescribedPeg::try_new(prm, motion).unwrap();
    let w = rigid.mass * rigid.gravity;
    let y = prescribed_rigid::preloaded_state(&fixed, &rigid, [0.3 * w, 0.5 * w, 0.5 * w], k);
    prm.hertz = HertzMode::Curvature;
    let sys = PrescribedPeg::try_new(prm, motion).unwrap();
    let forces = sys.forces(0.0, &y).unwrap();
    let count = |pair: Pair| forces.iter().filter(|f| f.contact.pair == pair).count();
    assert_eq!((count(Pair::EdgeSide), count(Pair::RimEdge)), (1, 2));
    let stiff = |pair: Pair| {
        forces
            .iter()
            .find(|f| f.contact.pair == pair)
            .unwrap()
            .stiffness
    };
    let (k_edge, k_rim) = (stiff(Pair::EdgeSide), stiff(Pair::RimEdge));
    eprintln!("curvature stiffness: K {k_edge:.3e}, B {k_rim:.3e} N/m^1.5");
    assert!(k_edge.is_finite() && k_rim.is_finite() && k_edge > 0.0 && k_rim > 0.0);
    assert!((k_edge / k_rim - 1.0).abs() > 0.01, "{k_edge} {k_rim}");
    let full = sys.full_state(0.0, &y);
    let whole = sys.peg.rhs(0.0, &full);
    let part = sys.rhs(0.0, &y);
    for (i, j) in [(0, 0), (1, 1), (2, 2), (3, 7), (4, 8), (5, 9), (6, 14)] {
        let tol = 1e-10 * (1.0 + whole[j].abs());
        assert!(
            (part[i] - whole[j]).abs() <= tol,
            "row {i}: {} vs {}",
            part[i],
            whole[j]
        );
    }
    assert!(part[5].abs() > 1.0, "no contact load: {part}");
}
