//! The items of `src/output/plot.rs`.

use pegdyn::output::plot::*;

#[test]
fn split_feasible_shares_switch_points() {
    let pts: Vec<(f64, f64)> = (0..6).map(|i| (i as f64, i as f64)).collect();
    let ok = [true, true, false, false, true, true];
    let [a, b] = Series::split_feasible("y", &pts, &ok, 3);
    let drawn = |s: &Series| s.points.iter().filter(|p| p.0.is_finite()).count();
    assert_eq!(drawn(&a), 4);
    // infeasible points 2, 3 plus their neighbours 1 and 4
    assert_eq!(drawn(&b), 4);
    assert_eq!(b.style, Style::Dashed);
    assert_eq!((a.color, b.color), (Some(3), Some(3)));
}
