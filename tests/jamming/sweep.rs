//! The sweep driver classifies a grid in parallel and compares the class
//! boundary with the parallelogram. With the exact static-friction verdict
//! (cone membership, independent of the diagram's formulas) as the
//! "simulator", no grid point contradicts the exact parallelogram, and
//! Whitney's small-angle parallelogram is contradicted near its corners
//! where the finite tilt matters.

use std::sync::Mutex;

use pegdyn::jamming::PegHole;
use pegdyn::jamming::diagram::{exact_parallelogram, whitney_parallelogram};
use pegdyn::jamming::statics::quasi_static_class;
use pegdyn::jamming::sweep::{self, Axis, Grid, RunClass};

#[test]
fn static_verdict_matches_exact_parallelogram_on_a_grid() {
    let p = PegHole::try_new(0.0125, 0.01, 0.1).unwrap();
    let l = 0.005;
    let g = exact_parallelogram(&p, l).unwrap().unwrap();
    let grid = Grid {
        x: Axis {
            min: -12.0,
            max: 12.0,
            n: 49,
        },
        y: Axis {
            min: -6.0,
            max: 6.0,
            n: 49,
        },
    };
    let seen = Mutex::new(Vec::new());
    let points = sweep::run(
        &grid,
        |q| Ok::<_, ()>(quasi_static_class(&p, l, g.theta, q)),
        |done, total| seen.lock().unwrap().push((done, total)),
    )
    .unwrap();
    assert_eq!(points.len(), 49 * 49);
    let mut seen = seen.into_inner().unwrap();
    seen.sort();
    assert_eq!(seen.last(), Some(&(49 * 49, 49 * 49)));
    let inserted = points
        .iter()
        .filter(|s| s.class == RunClass::Inserted)
        .count();
    assert!(inserted > 100, "{inserted}");
    // exact parallelogram: only points on the boundary itself may disagree
    let exact = sweep::check(&g, &points, 1e-9);
    assert!(exact.mismatches.is_empty(), "{:?}", exact.mismatches);
    assert!(exact.judged > 2000);
    // Whitney's is off by more than a grid cell at this tilt (θ = 0.059)
    let w = whitney_parallelogram(&p, l).unwrap();
    let whitney = sweep::check(&w, &points, grid.resolution());
    assert!(
        whitney.mismatches.len() > 10,
        "{}",
        whitney.mismatches.len()
    );
}

/// When l < μd (λ < 1) wedging is possible: the two contacts can then hold
/// loads inside the parallelogram too (with internal forces), so the
/// jamming diagram bounds jamming only for λ > 1.
#[test]
fn inside_loads_are_holdable_when_wedging_is_possible() {
    use pegdyn::jamming::forces::Wrench;
    use pegdyn::jamming::statics::holds;
    let p = PegHole::try_new(0.0125, 0.002, 0.3).unwrap();
    for (l, wedge) in [(0.005, true), (0.01, false)] {
        assert_eq!(p.lambda(l) < 1.0, wedge);
        let g = exact_parallelogram(&p, l).unwrap().unwrap();
        let (_, icpt) = g.two_point_line();
        let q = [0.0, 0.8 * icpt];
        assert!(g.avoids_jamming(q));
        let w = Wrench {
            fx: q[0],
            fz: 1.0,
            m: q[1] * p.r(),
        };
        assert_eq!(holds(&p, l, g.theta, &w), wedge, "l = {l}");
    }
}
