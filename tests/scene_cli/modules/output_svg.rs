//! The items of `src/output/svg.rs`.

use pegdyn::error::OutputError;
use pegdyn::internals::output::bounds;
use pegdyn::output::plot::Series;
use pegdyn::output::plot::{Figure, Panel, Scale, Style};
use pegdyn::output::svg::*;

fn count(svg: &str, what: &str) -> usize {
    svg.matches(what).count()
}

#[test]
fn gaps_split_a_series_into_segments() {
    let pts = vec![
        (0.0, 1.0),
        (1.0, 2.0),
        (2.0, f64::NAN),
        (3.0, 1.0),
        (4.0, 0.5),
    ];
    assert_eq!(segments(&pts, Scale::Linear, Scale::Linear).len(), 2);
    // On a log axis the non-positive point is a gap too.
    let pts = vec![(1.0, 1.0), (2.0, -1.0), (3.0, 1.0), (4.0, 2.0)];
    assert_eq!(segments(&pts, Scale::Log, Scale::Log).len(), 2);
}

#[test]
fn renders_title_labels_legend_and_log_axes() {
    let pts: Vec<(f64, f64)> = (1..30).map(|i| (i as f64, (i as f64).powi(-4))).collect();
    let fig = Figure {
        panels: vec![
            Panel::new("work-precision", "error [-]", "time [s]")
                .scales(Scale::Log, Scale::Log)
                .with(Series::line("dopri5", pts.clone()).styled(Style::LineMarkers))
                .with(Series::line("rk4", pts).styled(Style::Dashed)),
            Panel::new("second", "t [s]", "x [m]")
                .with(Series::line("", vec![(0.0, 0.0), (1.0, 1.0)])),
        ],
        ..Figure::new()
    };
    let svg = fig.render().unwrap();
    for text in [
        "work-precision",
        "error [-]",
        "time [s]",
        "dopri5",
        "rk4",
        "second",
        "x [m]",
    ] {
        assert!(svg.contains(text), "{text} missing");
    }
    assert!(count(&svg, "<circle") >= 29);
}

#[test]
fn extreme_data_ranges_render() {
    // Each of these made plotters' tick search loop without end: an
    // axis width that overflows (reactions near f64::MAX from a fuzzed
    // rigid-peg scene), and widths below f64 resolution of the values.
    let one = |y: f64| vec![(0.0, y)];
    type Points = Vec<(f64, f64)>;
    let cases: Vec<(Scale, Vec<Points>)> = vec![
        (
            Scale::Linear,
            vec![
                one(-1.2775898627013294e308),
                one(4.3210618057165163e307),
                one(7.036673849690435e307),
            ],
        ),
        (Scale::Linear, vec![vec![(0.0, -f64::MAX), (1.0, f64::MAX)]]),
        (
            Scale::Linear,
            vec![vec![(0.0, 1000.0), (1.0, 1000.0 + 1e-12)]],
        ),
        (Scale::Linear, vec![vec![(0.0, 0.3), (1.0, 0.3 + 5e-17)]]),
        (
            Scale::Linear,
            vec![vec![(0.0, 7.7e-154), (1.0, 7.7e-154 * (1.0 + 1e-15))]],
        ),
        (Scale::Log, vec![vec![(1.0, 5e-324), (2.0, f64::MAX)]]),
        (Scale::Log, vec![vec![(1.0, 1.0), (2.0, 1.0 + 1e-15)]]),
    ];
    for (scale, series) in cases {
        let mut panel = Panel::new("extreme", "t [s]", "y").scales(Scale::Linear, scale);
        for (i, pts) in series.into_iter().enumerate() {
            panel = panel.with(Series::line(format!("s{i}"), pts));
        }
        let (lo, hi) = bounds(&panel, scale, |p| p.1).unwrap();
        assert!(lo.is_finite() && hi.is_finite() && (hi - lo).is_finite() && hi > lo);
        assert!((hi / lo).is_finite() || scale == Scale::Linear);
        let fig = Figure {
            panels: vec![panel],
            ..Figure::new()
        };
        let svg = fig.render().unwrap();
        assert!(svg.contains("extreme"));
    }
}

#[test]
fn empty_panel_is_an_error() {
    let fig = Figure {
        panels: vec![
            Panel::new("nothing", "x", "y").with(Series::line("a", vec![(f64::NAN, 1.0)])),
        ],
        ..Figure::new()
    };
    assert!(matches!(fig.render(), Err(OutputError::EmptyPlot { .. })));
}
