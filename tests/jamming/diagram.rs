//! The jamming parallelogram: Whitney's small-angle corners are the exact
//! finite-angle corners at θ = 0 and their limit as c → 0; the exact
//! two-point equilibrium is checked against moments summed from the contact
//! points; two-point contact is refused where it is geometrically impossible;
//! a static-friction feasibility search confirms that loads inside the
//! parallelogram cannot be held by the contacts (no jam) while loads past the
//! two-point line can (jam); and past the right side the force lies inside
//! the edge contact's friction cone (one-point jam).

use pegdyn::jamming::PegHole;
use pegdyn::jamming::diagram::*;
use pegdyn::jamming::forces::*;
use pegdyn::jamming::geometry::*;

const R: f64 = 0.0125;
const SCENE: [(f64, f64); 4] = [(0.002, 0.1), (0.002, 0.3), (0.01, 0.1), (0.01, 0.3)];

fn peg(c: f64, mu: f64) -> PegHole {
    PegHole::try_new(R, c, mu).unwrap()
}

fn dist(a: Ratio, b: Ratio) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

#[test]
fn exact_corners_at_zero_tilt_are_whitneys() {
    for (c, mu) in SCENE {
        let p = peg(c, mu);
        for l in [0.001, 0.005, 0.01] {
            let w = whitney_parallelogram(&p, l).unwrap();
            let e = exact_parallelogram_at_tilt(&p, l, 0.0);
            for (a, b) in w.corners.iter().zip(e.corners.iter()) {
                assert!(dist(*a, *b) < 1e-12 * (1.0 + a[1].abs()), "{a:?} {b:?}");
            }
            // Whitney's closed form for the two-point line
            let lam = p.lambda(l);
            let (slope, icpt) = w.two_point_line();
            assert!((slope - mu * (1.0 + lam)).abs() < 1e-12 * slope);
            assert!((icpt - lam).abs() < 1e-12 * lam);
        }
    }
}

#[test]
fn exact_corners_converge_to_whitneys_linearly_in_tilt() {
    let (mu, l) = (0.3, 0.01);
    let mut last = f64::INFINITY;
    for c in [1e-2, 1e-3, 1e-4, 1e-5] {
        let p = peg(c, mu);
        let e = exact_parallelogram(&p, l).unwrap().unwrap();
        let w = whitney_parallelogram(&p, l).unwrap();
        let gap = (0..4)
            .map(|i| dist(e.corners[i], w.corners[i]))
            .fold(0.0, f64::max);
        // first order in θ ≈ cD/l: the gap over θ stays bounded
        assert!(gap / e.theta < 10.0 * (1.0 + p.lambda(l)), "c={c}: {gap}");
        assert!(gap < last / 5.0, "c={c}: gap {gap} did not shrink");
        last = gap;
    }
}

#[test]
fn exact_parallelogram_is_convex_and_centrally_symmetric() {
    for (c, mu) in SCENE {
        let p = peg(c, mu);
        for l in [0.005, 0.01, 0.03] {
            let g = exact_parallelogram(&p, l).unwrap().unwrap();
            for i in 0..4 {
                let (a, b, q) = (g.corners[i], g.corners[(i + 1) % 4], g.corners[(i + 2) % 4]);
                let cross = (b[0] - a[0]) * (q[1] - b[1]) - (b[1] - a[1]) * (q[0] - b[0]);
                assert!(cross > 0.0, "not counter-clockwise convex at corner {i}");
                let opp = g.corners[(i + 2) % 4];
                assert!(dist(a, [-opp[0], -opp[1]]) < 1e-12 * (1.0 + a[1].abs()));
            }
            assert!(g.avoids_jamming([0.0, 0.0]));
        }
    }
}

#[test]
fn two_point_contact_refused_when_too_shallow() {
    // scene values: l = 1 mm is below l_min for both clearances
    for (c, l_min_mm) in [(0.002, 1.583), (0.01, 3.562)] {
        let p = peg(c, 0.3);
        let l_min = min_two_point_depth(&p);
        assert!((l_min * 1e3 - l_min_mm).abs() < 1e-3, "{l_min}");
        assert!(exact_parallelogram(&p, 0.001).unwrap().is_none());
        assert!(exact_parallelogram(&p, l_min * 0.999).unwrap().is_none());
        let th = two_point_tilt(&p, l_min * 1.001).unwrap().unwrap();
        // just above l_min the tip corner is just inside the hole mouth
        let (tip, _, _) = contact_points(&p, l_min * 1.001, th);
        assert!(tip[1] > 0.0 && tip[1] < 0.1 * l_min, "{tip:?}");
    }
}

/// Net wrench about the tip summed from contact points and force directions.
fn summed_wrench(p: &PegHole, l: f64, th: f64, f: ContactForces) -> Wrench {
    let mu = p.mu();
    let (tip, edge, t) = contact_points(p, l, th);
    let (s, c) = th.sin_cos();
    // forces on the peg: wall +x with friction −z; edge −n with friction +u
    let ft = [f.tip, -mu * f.tip];
    let fe = [f.edge * (-c + mu * s), f.edge * (-s - mu * c)];
    let tau = |at: [f64; 2], g: [f64; 2]| (at[0] - t[0]) * g[1] - (at[1] - t[1]) * g[0];
    // applied = −(contact)
    Wrench {
        fx: -(ft[0] + fe[0]),
        fz: -(ft[1] + fe[1]),
        m: -(tau(tip, ft) + tau(edge, fe)),
    }
}

#[test]
fn sliding_equilibrium_matches_moments_from_contact_points() {
    let p = peg(0.05, 0.3); // l_min = 8.2 mm
    for l in [0.01, 0.02, 0.04] {
        let th = two_point_tilt(&p, l).unwrap().unwrap();
        for (ft, fe) in [(1.0, 0.0), (0.0, 1.0), (2.5, 0.7)] {
            let f = ContactForces { tip: ft, edge: fe };
            let a = sliding_wrench(&p, l, th, f);
            let b = summed_wrench(&p, l, th, f);
            assert!((a.fx - b.fx).abs() < 1e-12 && (a.fz - b.fz).abs() < 1e-12);
            assert!((a.m - b.m).abs() < 1e-14, "l={l}: {} vs {}", a.m, b.m);
            let back = sliding_contact_forces(&p, th, a.fx, a.fz);
            assert!((back.tip - ft).abs() < 1e-12 && (back.edge - fe).abs() < 1e-12);
        }
        // Whitney's small-angle form is the θ = 0 case
        let f = ContactForces {
            tip: 1.3,
            edge: 0.4,
        };
        let (w, e) = (
            whitney_sliding_wrench(&p, l, f),
            sliding_wrench(&p, l, 0.0, f),
        );
        assert!((w.fx - e.fx).abs() < 1e-15 && (w.fz - e.fz).abs() < 1e-15);
        assert!((w.m - e.m).abs() < 1e-15);
    }
}

/// Can the two contacts of the reference tilt hold load ratio `q` statically
/// (static friction anywhere inside the cones)? Brute force over the tip
/// friction ratio; the other three unknowns follow from the balance.
fn holdable(p: &PegHole, l: f64, th: f64, q: Ratio) -> bool {
    let (mu, r) = (p.mu(), p.r());
    let w = [q[0], 1.0, q[1] * r];
    let (tip, edge, t) = contact_points(p, l, th);
    let (s, c) = th.sin_cos();
    let (at, ae) = (
        [tip[0] - t[0], tip[1] - t[1]],
        [edge[0] - t[0], edge[1] - t[1]],
    );
    let tau = |a: [f64; 2], g: [f64; 2]| a[0] * g[1] - a[1] * g[0];
    (0..=2000).any(|k| {
        let st = mu * (k as f64 / 1000.0 - 1.0);
        // columns: f_t·(1, −st), f_e·(−c, −s), g_e·(s, −c) (friction along u)
        let cols = [[1.0, -st], [-c, -s], [s, -c]];
        let pts = [at, ae, ae];
        let m = nalgebra::Matrix3::from_fn(|i, j| match i {
            0 | 1 => cols[j][i],
            _ => tau(pts[j], cols[j]),
        });
        let rhs = nalgebra::Vector3::new(-w[0], -w[1], -w[2]);
        m.lu()
            .solve(&rhs)
            .is_some_and(|x| x[0] >= 0.0 && x[1] >= 0.0 && x[2].abs() <= mu * x[1] + 1e-12)
    })
}

#[test]
fn inside_slides_outside_past_two_point_line_holds() {
    for (c, mu) in SCENE {
        let p = peg(c, mu);
        let l = 0.01;
        let th = two_point_tilt(&p, l).unwrap().unwrap();
        let g = exact_parallelogram(&p, l).unwrap().unwrap();
        let (slope, icpt) = g.two_point_line();
        // abscissae well inside both corners' range (|P₁ₓ| < 1/μ at finite θ)
        let xmax = g.corners[2][0];
        for fx in [-0.8 * xmax, -0.3 * xmax, 0.0, 0.4 * xmax, 0.8 * xmax] {
            let on = slope * fx + icpt;
            let inside = [fx, on - 0.05 * icpt];
            assert!(g.avoids_jamming(inside), "{inside:?}");
            // neither tilt can hold it: reference, and mirrored via −q
            assert!(!holdable(&p, l, th, inside), "c={c} mu={mu} {inside:?}");
            assert!(!holdable(&p, l, th, [-inside[0], -inside[1]]));
            // past the reference two-point line: held, the peg jams
            let past = [fx, on + 0.05 * icpt];
            assert!(!g.avoids_jamming(past));
            assert!(holdable(&p, l, th, past), "c={c} mu={mu} {past:?}");
        }
    }
}

#[test]
fn right_side_is_the_edge_friction_cone_limit() {
    for (c, mu) in SCENE {
        let p = peg(c, mu);
        for l in [0.005, 0.01] {
            let g = exact_parallelogram(&p, l).unwrap().unwrap();
            let th = g.theta;
            let x_side = g.corners[2][0];
            // angle between the applied force (x, 1) and the edge normal (cosθ, sinθ)
            let off_normal = |x: f64| {
                let (s, c) = th.sin_cos();
                ((x * s - c) / (x * c + s)).atan().abs()
            };
            let alpha = mu.atan();
            assert!((off_normal(x_side) - alpha).abs() < 1e-12);
            assert!(
                off_normal(x_side * 1.01) < alpha,
                "beyond: inside the edge cone"
            );
            assert!(off_normal(x_side * 0.99) > alpha);
            // the side is vertical and the corners sit on the two-point lines
            assert!((g.corners[1][0] - x_side).abs() < 1e-12);
            let (slope, icpt) = g.two_point_line();
            let q = g.corners[1];
            assert!((q[1] - (slope * q[0] - icpt)).abs() < 1e-9 * (1.0 + icpt));
            assert!(!g.avoids_jamming([x_side * 1.01, 0.5 * (q[1] + g.corners[2][1])]));
            assert!(g.avoids_jamming([x_side * 0.99, 0.5 * (q[1] + g.corners[2][1])]));
            // at finite tilt the tip-only end of the two-point line is outside
            let (p2, _) = two_point_segment(&p, l, th);
            assert!(!g.avoids_jamming(p2) && p2[0] < -x_side);
        }
    }
}
