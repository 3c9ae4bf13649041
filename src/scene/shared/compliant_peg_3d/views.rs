//! The side (x–z) and top (x–y) views of the compliant 3-D peg and the
//! hole at a state, and the figure of views at the start, at each contact
//! transition and at the end of a run.

use nalgebra::{SVector, Vector3};

use super::output::EventRow;
use crate::compliant_peg_3d::insertion::{Insertion, N_STATE, motion, peg_state};
use crate::error::RunError;
use crate::output::names::Part;
use crate::output::plot::{Figure, Panel, Series, Style};
use crate::scene::context::RunContext;

fn circle(c: Vector3<f64>, u: Vector3<f64>, v: Vector3<f64>, r: f64) -> Vec<Vector3<f64>> {
    (0..=48)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / 48.0;
            c + (u * a.cos() + v * a.sin()) * r
        })
        .collect()
}

/// The side (x–z) and top (x–y) views of the peg and the hole at state `y`,
/// titled `title`, in millimetres.
pub fn views(sys: &Insertion, y: &SVector<f64, N_STATE>, title: &str) -> [Panel; 2] {
    let prm = &sys.peg.params;
    let m = motion(&peg_state(y));
    let a = m.orientation * Vector3::z();
    let u = m.orientation * Vector3::x();
    let v = m.orientation * Vector3::y();
    let r = prm.peg_radius();
    let tip = m.centre - a * (0.5 * prm.length);
    let top = m.centre + a * (0.5 * prm.length);
    let mm = 1e3;
    let bottom = circle(tip, u, v, r);
    let upper = circle(top, u, v, r);
    let big_r = prm.bore_radius();
    let depth = prm.bore_depth.min(prm.length);
    let side_outline = |sel: fn(&Vector3<f64>) -> f64| -> Vec<(f64, f64)> {
        // The silhouette in the x–z plane: the two generators at ±x of the
        // axis, and the end ellipses.
        let mut pts: Vec<(f64, f64)> = bottom.iter().map(|p| (p.x * mm, sel(p) * mm)).collect();
        pts.push((f64::NAN, f64::NAN));
        pts.extend(upper.iter().map(|p| (p.x * mm, sel(p) * mm)));
        pts.push((f64::NAN, f64::NAN));
        for s in [1.0, -1.0] {
            let w = Vector3::new(a.z, 0.0, -a.x).normalize() * (s * r);
            let (p0, p1) = (tip + w, top + w);
            pts.push((p0.x * mm, sel(&p0) * mm));
            pts.push((p1.x * mm, sel(&p1) * mm));
            pts.push((f64::NAN, f64::NAN));
        }
        pts
    };
    let hole_side = vec![
        (-2.0 * big_r * mm, 0.0),
        (-big_r * mm, 0.0),
        (-big_r * mm, -depth * mm),
        (f64::NAN, f64::NAN),
        (big_r * mm, -depth * mm),
        (big_r * mm, 0.0),
        (2.0 * big_r * mm, 0.0),
    ];
    let side = Panel::new(&format!("{title}: side view"), "x [mm]", "z [mm]")
        .with(Series::line("hole", hole_side).colored(7))
        .with(Series::line("peg", side_outline(|p| p.z)).colored(0));
    let hole_top: Vec<(f64, f64)> = circle(Vector3::zeros(), Vector3::x(), Vector3::y(), big_r)
        .iter()
        .map(|p| (p.x * mm, p.y * mm))
        .collect();
    let mut contacts: Vec<(f64, f64)> = Vec::new();
    for c in sys.contacts(y) {
        contacts.push((c.point.x * mm, c.point.y * mm));
    }
    let top_view = Panel::new(&format!("{title}: top view"), "x [mm]", "y [mm]")
        .with(Series::line("hole", hole_top).colored(7))
        .with(Series::line("tip", bottom.iter().map(|p| (p.x * mm, p.y * mm)).collect()).colored(0))
        .with(
            Series::line("top", upper.iter().map(|p| (p.x * mm, p.y * mm)).collect())
                .styled(Style::Dashed)
                .colored(0),
        )
        .with(
            Series::line("contacts", contacts)
                .styled(Style::Markers)
                .colored(1),
        );
    [side, top_view]
}

/// Writes `<name>.views.svg`: side and top views at the start, at each
/// event (at most `max` of them) and at the end.
///
/// # Errors
/// Output errors.
pub fn write_views(
    ctx: &RunContext,
    sys: &Insertion,
    first: (f64, &SVector<f64, N_STATE>),
    events: &[EventRow],
    last: (f64, &SVector<f64, N_STATE>),
    max: usize,
) -> Result<(), RunError> {
    let mut fig = Figure::new();
    let mut add = |t: f64, y: &SVector<f64, N_STATE>, what: &str| {
        let [a, b] = views(
            sys,
            y,
            &format!("t = {} s, {what}", crate::scene::numbers::significant(t)),
        );
        fig.panels.push(a);
        fig.panels.push(b);
    };
    add(first.0, first.1, "start");
    for e in events.iter().take(max) {
        add(e.t, &e.y, &e.what);
    }
    add(last.0, last.1, "end");
    Ok(ctx.figure(Part::Sub("views"), &fig)?)
}
