//! The items of `src/output/legend.rs`.

use pegdyn::internals::output::*;
use pegdyn::output::plot::Series;
use pegdyn::output::plot::{Panel, Scale, Style};

const AREA: (f64, f64) = (700.0, 280.0);

fn dots(points: &[(f64, f64)]) -> Panel {
    Panel::new("t", "x", "y")
        .with(Series::line("a long legend entry", points.to_vec()).styled(Style::Markers))
}

#[test]
fn a_free_upper_right_is_kept() {
    let p = dots(&[(0.0, 0.0), (1.0, 0.1)]);
    let plan = plan(&p, AREA, (0.0, 1.0), (0.0, 1.0));
    assert_eq!(plan.position, Place::UpperRight);
    assert_eq!(plan.y, (0.0, 1.0));
}

#[test]
fn a_point_under_the_upper_right_moves_the_legend_to_a_free_corner() {
    let p = dots(&[(0.98, 0.97), (0.0, 0.0), (1.0, 0.0)]);
    let plan = plan(&p, AREA, (0.0, 1.0), (0.0, 1.0));
    assert_eq!(plan.position, Place::UpperLeft);
    // The chosen box holds no point.
    let m = Mapping {
        size: AREA,
        x: (0.0, 1.0, Scale::Linear),
        y: (0.0, 1.0, Scale::Linear),
    };
    let size = legend_size(&["a long legend entry"]);
    assert!(!covers(&p, &m, place(plan.position, size, AREA)));
    assert!(covers(&p, &m, place(Place::UpperRight, size, AREA)));
}

#[test]
fn a_line_through_every_place_gets_a_band_above_the_data() {
    // A dense grid of markers fills every place.
    let grid: Vec<(f64, f64)> = (0..=20)
        .flat_map(|i| (0..=20).map(move |j| (i as f64 / 20.0, j as f64 / 20.0)))
        .collect();
    let p = dots(&grid);
    let plan = plan(&p, AREA, (0.0, 1.0), (0.0, 1.0));
    assert_eq!(plan.position, Place::UpperRight);
    assert!(plan.y.1 > 1.0 && plan.y.0 == 0.0, "{:?}", plan.y);
    let m = Mapping {
        size: AREA,
        x: (0.0, 1.0, Scale::Linear),
        y: (plan.y.0, plan.y.1, Scale::Linear),
    };
    let size = legend_size(&["a long legend entry"]);
    assert!(!covers(&p, &m, place(plan.position, size, AREA)));
    // A diagonal line crosses the upper right and the lower left corners.
    let p = Panel::new("t", "x", "y").with(Series::line("line", vec![(0.0, 0.0), (1.0, 1.0)]));
    let plan = pegdyn::internals::output::plan(&p, AREA, (0.0, 1.0), (0.0, 1.0));
    assert_eq!(plan.position, Place::UpperLeft);
}

#[test]
fn segments_and_boxes() {
    let r = (10.0, 10.0, 20.0, 20.0);
    assert!(crosses((0.0, 15.0), (30.0, 15.0), r));
    assert!(!crosses((0.0, 0.0), (30.0, 5.0), r));
    assert!(crosses((15.0, 15.0), (15.0, 15.0), r));
    assert!(!crosses((25.0, 15.0), (25.0, 15.0), r));
}
