//! The replay of a run of the compliant planar peg, drawn as the section
//! through the hole's axis.
//!
//! The model's coordinates `(x, z, θ)` (centre of mass, `z` into the hole,
//! axis `e_a = (sin θ, cos θ)` towards the bottom, radial
//! `e_r = (cos θ, −sin θ)`; `docs/compliant.md`) become the hole frame's
//! `(x, 0, −z)` with the peg turned by `−θ` about `y`. The model reports the
//! forces of the more deeply penetrated contact of each kind ([`Sample`]);
//! the replay places them on the side whose gap is smaller:
//!
//! ```text
//! edge (side s = ∓1 left/right): fillet centre E = (s (D/2 + ρ_h), ρ_h),
//!   δ = ρ_h + r − s (E − C)·e_r, point E − s ρ_h e_r, normal on the peg −s e_r,
//!   friction along e_a;
//! wall (s = ±1 right/left): corner centre F = C + (l_c − ρ_p) e_a + s (r − ρ_p) e_r,
//!   δ = s F_x + ρ_p − D/2, point F + s ρ_p e_x, normal on the peg −s e_x,
//!   friction along +z.
//! ```
//!
//! The model locates no contact events; a change of the loaded contacts
//! between two output samples is marked at the later sample.

use super::decimate::Budget;
use super::error::ReplayError;
use super::record::{Contact, Frame, Geometry, Mark, MarkKind, Panel, Replay, Series, View};
use super::states::{of_solution, select};
use crate::compliant_peg::{CompliantParams, Sample};
use crate::integrate::{EventHit, Solution};
use nalgebra::{SVector, UnitQuaternion, Vector2, Vector3};

/// The contact names, in the model's order.
pub const PAIRS: [&str; 4] = ["edge_left", "wall_right", "edge_right", "wall_left"];

/// A run of the compliant planar peg, as a scene hands it over.
pub struct Run2d<'a, const N: usize> {
    /// The scene's name.
    pub title: &'a str,
    /// One line: the model and how the run ended.
    pub subtitle: String,
    /// The model's parameters.
    pub params: &'a CompliantParams,
    /// Peg length (m).
    pub peg_length: f64,
    /// How deep the walls are drawn (m): the model has no bore bottom.
    pub wall_depth: f64,
    /// The integration (state `x, z, θ, …`).
    pub solution: &'a Solution<N>,
    /// Contact forces of a state.
    pub sample: &'a dyn Fn(&SVector<f64, N>) -> Sample,
    /// What each event means (`None`: not shown), e.g. the target depth
    /// reached as [`MarkKind::Seat`].
    pub mark: &'a dyn Fn(&EventHit<N>) -> Option<(MarkKind, String)>,
}

/// A planar vector `(x, z)` (z into the hole) in the hole frame.
fn hole(v: Vector2<f64>) -> Vector3<f64> {
    Vector3::new(v.x, 0.0, -v.y)
}

/// The loaded contacts of a state (at most one edge and one wall).
fn contacts(p: &CompliantParams, y: &[f64], s: &Sample) -> Vec<Contact> {
    let g = &p.spec.geometry;
    let (r, rp, rh, half) = (
        g.peg_radius,
        g.peg_fillet,
        g.hole_fillet,
        0.5 * g.hole_diameter,
    );
    let lc = p.spec.com_height;
    let c = Vector2::new(y[0], y[1]);
    let (sn, cs) = y[2].sin_cos();
    let (ea, er) = (Vector2::new(sn, cs), Vector2::new(cs, -sn));
    let mut out = Vec::new();
    // Edge: left (s = −1) or right (s = +1), the deeper one.
    let edge = |s: f64| {
        let e = Vector2::new(s * (half + rh), rh);
        (rh + r - s * (e - c).dot(&er), e - er * (s * rh), er * -s)
    };
    let (left, right) = (edge(-1.0), edge(1.0));
    let (k, (_, point, normal)) = if right.0 > left.0 {
        (2, right)
    } else {
        (0, left)
    };
    if s.f_edge > 0.0 {
        out.push(Contact {
            pair: k,
            point: hole(point),
            normal: hole(normal),
            normal_force: s.f_edge,
            friction: hole(ea * s.friction_edge),
        });
    }
    // Wall: right (s = +1) or left (s = −1), the deeper one.
    let wall = |s: f64| {
        let f = c + ea * (lc - rp) + er * (s * (r - rp));
        let ex = Vector2::new(1.0, 0.0);
        (s * f.x + rp - half, f + ex * (s * rp), ex * -s)
    };
    let (right, left) = (wall(1.0), wall(-1.0));
    let (k, (_, point, normal)) = if left.0 > right.0 {
        (3, left)
    } else {
        (1, right)
    };
    if s.f_wall > 0.0 {
        out.push(Contact {
            pair: k,
            point: hole(point),
            normal: hole(normal),
            normal_force: s.f_wall,
            friction: hole(Vector2::new(0.0, s.friction_wall)),
        });
    }
    out
}

fn state_label(contacts: &[Contact]) -> String {
    if contacts.is_empty() {
        return "none".into();
    }
    let names: Vec<&str> = contacts.iter().map(|c| PAIRS[c.pair]).collect();
    names.join(" + ")
}

/// The replay of `run`, at most `budget` frames.
///
/// # Errors
/// [`ReplayError::NoFrames`] for a run without output samples,
/// [`ReplayError::NonFinite`] for a non-finite state.
pub fn replay<const N: usize>(run: &Run2d<'_, N>, budget: Budget) -> Result<Replay, ReplayError> {
    let p = run.params;
    let mut states = of_solution(run.solution, |e| (run.mark)(e), "end of the run")?;
    // Contact-state changes between samples, marked at the later sample.
    let mut previous: Option<String> = None;
    for s in &mut states {
        let label = state_label(&contacts(p, s.y.as_slice(), &(run.sample)(&s.y)));
        if let Some(prev) = &previous
            && *prev != label
            && s.mark.is_none()
        {
            s.keep = super::decimate::Keep::Event;
            s.mark = Some((MarkKind::Contact, format!("{prev} → {label}")));
        }
        previous = Some(label);
    }
    let sel = select(states, budget);
    let mut frames = Vec::with_capacity(sel.states.len());
    let mut marks = Vec::new();
    for st in &sel.states {
        let s = (run.sample)(&st.y);
        let y = st.y.as_slice();
        let cs = contacts(p, y, &s);
        frames.push(Frame {
            t: st.t,
            centre: Vector3::new(y[0], 0.0, -y[1]),
            orientation: UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -y[2]),
            state: state_label(&cs),
            contacts: cs,
            robot: None,
            values: vec![s.f_edge, s.f_wall, 1e3 * s.depth, y[2].to_degrees()],
        });
        if let Some((kind, label)) = &st.mark {
            marks.push(Mark {
                t: st.t,
                kind: *kind,
                label: label.clone(),
            });
        }
    }
    let g = &p.spec.geometry;
    let geometry = Geometry {
        peg_radius: g.peg_radius,
        peg_length: run.peg_length,
        rim_fillet: g.peg_fillet,
        centre_height: p.spec.com_height,
        hole_radius: 0.5 * g.hole_diameter,
        mouth_fillet: g.hole_fillet,
        bore_depth: run.wall_depth,
        bore_bottom: false,
        compliance_height: None,
    };
    let series = |panel, name: &str, unit| Series {
        panel,
        name: name.into(),
        unit,
    };
    Ok(Replay {
        title: run.title.to_string(),
        subtitle: run.subtitle.clone(),
        view: View::Section,
        pairs: PAIRS.to_vec(),
        frames,
        marks,
        series: vec![
            series(Panel::Force, "edge contact normal force", "N"),
            series(Panel::Force, "wall contact normal force", "N"),
            series(Panel::Depth, "tip depth", "mm"),
            series(Panel::Tilt, "tilt θ", "°"),
        ],
        states: sel.total,
        events: sel.events,
        exaggeration: Replay::suggested_exaggeration(geometry.hole_radius, geometry.clearance()),
        geometry,
    })
}

/// The page of `run` with the default [`Budget`]: [`replay`], then
/// [`super::html`].
///
/// # Errors
/// As [`replay`] and [`super::html`].
pub fn page<const N: usize>(run: &Run2d<'_, N>) -> Result<String, ReplayError> {
    super::html(&replay(run, Budget::default())?)
}
