//! The replay of a run of the compliant 3-D peg ([`Insertion`]: free, under
//! a follower moment, or held by a wrist that a robot moves): per frame the
//! peg's pose, every loaded contact point with its normal and friction
//! force, the robot frame; the contact transitions, the seat and the force
//! limits as events; forces, the tip's depth and the tilt as plots.

use super::decimate::Budget;
use super::error::ReplayError;
use super::record::{Contact, Frame, Geometry, MarkKind, Panel, Replay, Series, View};
use super::states::{of_solution, select};
use crate::compliant_peg_3d::Pair;
use crate::compliant_peg_3d::insertion::{Insertion, N_STATE, Sample, motion, peg_state};
use crate::compliant_peg_3d::outcome::{Transition, counts, label};
use crate::integrate::{EventHit, Solution};
use nalgebra::SVector;

/// What an event of the run means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Meaning {
    /// A contact transition: pair `.0` (index into [`Pair::ALL`]) crossing
    /// between `.1 − 1` and `.1` points.
    Transition(Transition),
    /// The tip reached the seat depth.
    Seated,
    /// The wrist's force limit.
    WristForceLimit,
    /// The contact force limit.
    ContactForceLimit,
    /// The axis missed the hole.
    Missed,
}

impl Meaning {
    /// The mark of this event (`rising`: the event function went up).
    pub fn mark(self, rising: bool) -> (MarkKind, String) {
        match self {
            Meaning::Transition((pair, k)) => {
                let name = Pair::ALL.get(pair).map_or("contact", |p| p.name());
                let (from, to) = if rising { (k - 1, k) } else { (k, k - 1) };
                (MarkKind::Contact, format!("{name} {from} → {to}"))
            }
            Meaning::Seated => (MarkKind::Seat, "seated".into()),
            Meaning::WristForceLimit => (MarkKind::ForceLimit, "wrist force limit".into()),
            Meaning::ContactForceLimit => (MarkKind::ForceLimit, "contact force limit".into()),
            Meaning::Missed => (MarkKind::Stop, "missed the hole".into()),
        }
    }
}

/// A run of the compliant 3-D peg, as a scene hands it over.
pub struct Run3d<'a> {
    /// The scene's name.
    pub title: &'a str,
    /// One line: the model and how the run ended.
    pub subtitle: String,
    /// The system that was integrated.
    pub system: &'a Insertion,
    /// Its integration.
    pub solution: &'a Solution<N_STATE>,
    /// What each event of the solution means (`None`: not shown).
    pub meaning: &'a dyn Fn(&EventHit<N_STATE>) -> Option<Meaning>,
}

/// The plotted series of a free and of a held peg.
fn series(held: bool) -> Vec<Series> {
    let mut s = vec![
        Series {
            panel: Panel::Force,
            name: "sum of contact normal forces".into(),
            unit: "N",
        },
        Series {
            panel: Panel::Force,
            name: "largest contact normal force".into(),
            unit: "N",
        },
    ];
    if held {
        s.push(Series {
            panel: Panel::Force,
            name: "wrist force |F|".into(),
            unit: "N",
        });
    }
    s.push(Series {
        panel: Panel::Depth,
        name: "tip depth".into(),
        unit: "mm",
    });
    s.push(Series {
        panel: Panel::Tilt,
        name: "tilt".into(),
        unit: "°",
    });
    s
}

/// The frame of state `y` at `t`.
fn frame(sys: &Insertion, t: f64, y: &SVector<f64, N_STATE>) -> Result<Frame, ReplayError> {
    let s: Sample = sys
        .sample(t, y)
        .map_err(|source| ReplayError::Model { t, source })?;
    let m = motion(&peg_state(y));
    let points: Vec<_> = s.forces.iter().map(|f| f.contact).collect();
    let contacts = s
        .forces
        .iter()
        .filter(|f| f.normal_force > 0.0)
        .map(|f| Contact {
            pair: Pair::ALL
                .iter()
                .position(|p| *p == f.contact.pair)
                .unwrap_or(0),
            point: f.contact.point,
            normal: f.contact.normal,
            normal_force: f.normal_force,
            friction: f.friction,
        })
        .collect();
    let mut values = vec![s.total_normal(), s.peak_normal()];
    if let Some(w) = &s.wrist {
        values.push(w.force.norm());
    }
    values.push(1e3 * s.depth);
    values.push(s.tilt.to_degrees());
    Ok(Frame {
        t,
        centre: m.centre,
        orientation: m.orientation,
        contacts,
        robot: s.frame.map(|f| (f.position, f.orientation)),
        state: label(&counts(&points)),
        values,
    })
}

/// The replay of `run`, at most `budget` frames.
///
/// # Errors
/// [`ReplayError::NoFrames`] for a run without output samples,
/// [`ReplayError::NonFinite`] for a non-finite state,
/// [`ReplayError::Model`] when the contact model refuses a state.
pub fn replay(run: &Run3d<'_>, budget: Budget) -> Result<Replay, ReplayError> {
    let sys = run.system;
    let states = of_solution(
        run.solution,
        |e| (run.meaning)(e).map(|m| m.mark(e.rising)),
        "end of the run",
    )?;
    let sel = select(states, budget);
    let mut frames = Vec::with_capacity(sel.states.len());
    let mut marks = Vec::new();
    for s in &sel.states {
        frames.push(frame(sys, s.t, &s.y)?);
        if let Some((kind, label)) = &s.mark {
            marks.push(super::record::Mark {
                t: s.t,
                kind: *kind,
                label: label.clone(),
            });
        }
    }
    let p = &sys.peg.params;
    let geometry = Geometry {
        peg_radius: p.peg_radius(),
        peg_length: p.length,
        rim_fillet: p.rim_fillet,
        centre_height: 0.5 * p.length,
        hole_radius: p.bore_radius(),
        mouth_fillet: p.mouth_fillet,
        bore_depth: p.bore_depth,
        bore_bottom: true,
        compliance_height: sys.held.map(|h| h.wrist.centre_height),
    };
    Ok(Replay {
        title: run.title.to_string(),
        subtitle: run.subtitle.clone(),
        view: View::Solid,
        pairs: Pair::ALL.iter().map(|p| p.name()).collect(),
        frames,
        marks,
        series: series(sys.held.is_some()),
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
pub fn page(run: &Run3d<'_>) -> Result<String, ReplayError> {
    super::html(&replay(run, Budget::default())?)
}
