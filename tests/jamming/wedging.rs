//! Wedging angle θ_c: the exact finite-angle value (paper Eq. 85 with δ = 0)
//! agrees with its small-clearance series c/μ + (1 + 2μ²)c²/(2μ³), so
//! Whitney's c/μ is the right leading term and the paper's Eq. 86 (μc) is
//! not; at θ_c the contact forces self-equilibrate exactly on the edge
//! contact's friction cone.

use pegdyn::jamming::PegHole;
use pegdyn::jamming::geometry::{depth_at_tilt, min_two_point_depth, two_point_tilt};
use pegdyn::jamming::wedging::*;

fn peg(c: f64, mu: f64) -> PegHole {
    PegHole::try_new(0.0125, c, mu).unwrap()
}

#[test]
fn exact_angle_matches_series_to_third_order() {
    for mu in [0.1, 0.3, 0.6] {
        // θ_c exists for these c (wedging possible) and the series error
        // falls like c³: a tenfold smaller c gives ~1000× smaller error.
        let err = |c: f64| {
            let p = peg(c, mu);
            wedging_angle(&p).unwrap() - wedging_angle_series(&p)
        };
        let (c1, c2) = (1e-3, 1e-4);
        let ratio = err(c1) / err(c2);
        assert!((700.0..1400.0).contains(&ratio), "mu={mu}: ratio {ratio}");
        // and Whitney's leading term is right: relative error O(c)
        let p = peg(c2, mu);
        let rel = (wedging_angle(&p).unwrap() / wedging_angle_whitney(&p) - 1.0).abs();
        assert!(rel < 2.0 * c2 / mu / mu, "mu={mu}: rel {rel}");
    }
}

#[test]
fn paper_eq86_is_off_by_one_over_mu_squared() {
    for (c, mu) in [(0.002, 0.1), (0.01, 0.3), (0.002, 0.3)] {
        let p = peg(c, mu);
        let exact = wedging_angle(&p).unwrap();
        let ratio = exact / wedging_angle_paper_eq86(&p);
        assert!(
            (ratio * mu * mu - 1.0).abs() < 0.2,
            "c={c} mu={mu}: {ratio}"
        );
    }
}

#[test]
fn at_critical_angle_depth_is_mu_d_and_edge_cone_is_exactly_met() {
    for (c, mu) in [(0.002, 0.1), (0.002, 0.3), (0.01, 0.3), (0.05, 0.6)] {
        let p = peg(c, mu);
        let th = wedging_angle(&p).unwrap();
        let l = depth_at_tilt(&p, th);
        assert!((l - mu * p.peg_diameter()).abs() < 1e-12 * p.peg_diameter());
        // the exact two-point tilt at that depth is θ_c again
        let back = two_point_tilt(&p, l).unwrap().unwrap();
        assert!((back - th).abs() < 1e-12);
        // self-equilibrated forces along the contact line: on the edge cone
        let (tip, edge) = wedge_cone_margins(&p, l, th);
        assert!(edge.abs() < 1e-12, "edge margin {edge}");
        assert!(tip > 0.0, "tip margin {tip}");
        // slightly more tilt (shallower): inside both cones, wedging possible
        let th_up = th * 1.001;
        let (t, e) = wedge_cone_margins(&p, depth_at_tilt(&p, th_up), th_up);
        assert!(t > 0.0 && e > 0.0, "{t} {e}");
        // slightly less tilt (deeper): the edge force leaves its cone
        let th_dn = th * 0.999;
        let (_, e) = wedge_cone_margins(&p, depth_at_tilt(&p, th_dn), th_dn);
        assert!(e < 0.0, "{e}");
        // the paper's Eq. 86 tilt μc is far from wedging
        let thp = wedging_angle_paper_eq86(&p);
        let (_, e) = wedge_cone_margins(&p, depth_at_tilt(&p, thp), thp);
        assert!(e < -0.4, "paper angle edge margin {e}");
        assert!(!can_wedge_at_depth(&p, depth_at_tilt(&p, thp)));
    }
}

#[test]
fn edge_cone_angle_is_atan_l_over_d_at_any_tilt() {
    let p = peg(0.05, 0.3);
    for l in [0.01, 0.02, 0.04] {
        let th = two_point_tilt(&p, l).unwrap().unwrap();
        let (_, e) = wedge_cone_margins(&p, l, th);
        let expect = 0.3_f64.atan() - (l / p.peg_diameter()).atan();
        assert!((e - expect).abs() < 1e-12, "l={l}: {e} vs {expect}");
    }
}

#[test]
fn no_wedging_when_two_point_contact_cannot_be_that_shallow() {
    // (1 − c)²(1 + μ²) < 1: l_min = √(D² − d²) exceeds μd
    for (c, mu) in [(0.1, 0.2), (0.01, 0.1)] {
        let p = peg(c, mu);
        assert!(wedging_angle(&p).is_none(), "c={c} mu={mu}");
        assert!(min_two_point_depth(&p) > mu * p.peg_diameter());
    }
}
