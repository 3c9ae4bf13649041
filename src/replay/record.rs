//! The replay record: what the page draws, in SI units and the hole frame
//! (origin at the centre of the hole's top face, `z` up along the hole's
//! axis, the bore below `z = 0`).

use nalgebra::{UnitQuaternion, Vector3};

/// How the page shows the bodies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// Solids of revolution in 3-D (the compliant 3-D peg).
    Solid,
    /// The section through the hole's axis in the `x`–`z` plane, seen from
    /// the front (a planar model: its `y` coordinates are zero).
    Section,
}

impl View {
    /// `solid` or `section`.
    pub fn name(self) -> &'static str {
        match self {
            View::Solid => "solid",
            View::Section => "section",
        }
    }
}

/// The dimensions of the peg and the hole (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Geometry {
    /// Peg radius `r`.
    pub peg_radius: f64,
    /// Peg length `L`.
    pub peg_length: f64,
    /// Fillet radius of the peg's bottom rim `ρ_p`.
    pub rim_fillet: f64,
    /// Height of the peg's reference point (its [`Frame::centre`]) above
    /// its tip, along the axis: the centre of mass.
    pub centre_height: f64,
    /// Bore radius `R`.
    pub hole_radius: f64,
    /// Fillet radius of the hole's mouth `ρ_h`.
    pub mouth_fillet: f64,
    /// Bore depth below the top face.
    pub bore_depth: f64,
    /// Whether the bore has a bottom there (a planar model has none: its
    /// walls are drawn to `bore_depth`).
    pub bore_bottom: bool,
    /// Height `L_c` of the wrist's compliance centre above the tip, for a
    /// held peg.
    pub compliance_height: Option<f64>,
}

impl Geometry {
    /// The radial clearance `R − r`.
    pub fn clearance(&self) -> f64 {
        self.hole_radius - self.peg_radius
    }
}

/// One contact point of a frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Contact {
    /// Index of the contact pair in [`Replay::pairs`].
    pub pair: usize,
    /// Contact point (m).
    pub point: Vector3<f64>,
    /// Unit direction of the normal force on the peg.
    pub normal: Vector3<f64>,
    /// Normal force (N, ≥ 0).
    pub normal_force: f64,
    /// Friction force on the peg (N).
    pub friction: Vector3<f64>,
}

/// The state drawn at one instant.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// Time (s).
    pub t: f64,
    /// The peg's reference point (its centre of mass, m).
    pub centre: Vector3<f64>,
    /// The peg's orientation: body `z` is the peg's axis, tip to top.
    pub orientation: UnitQuaternion<f64>,
    /// The contacts that carry load.
    pub contacts: Vec<Contact>,
    /// The robot frame (where the compliance centre sits undeflected, and
    /// the wrist's orientation), for a held peg.
    pub robot: Option<(Vector3<f64>, UnitQuaternion<f64>)>,
    /// The contact state in words, e.g. `edge_side + rim_wall`.
    pub state: String,
    /// The value of each of [`Replay::series`] at this frame.
    pub values: Vec<f64>,
}

/// What an event mark stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MarkKind {
    /// A contact transition (a pair gains or loses a point).
    Contact,
    /// The peg reached its seat (or target) depth.
    Seat,
    /// A force limit stopped the run.
    ForceLimit,
    /// Any other event that ended the run (the axis missed the hole).
    Stop,
    /// The last state of the run.
    End,
}

impl MarkKind {
    /// `contact`, `seat`, `limit`, `stop`, `end`.
    pub fn name(self) -> &'static str {
        match self {
            MarkKind::Contact => "contact",
            MarkKind::Seat => "seat",
            MarkKind::ForceLimit => "limit",
            MarkKind::Stop => "stop",
            MarkKind::End => "end",
        }
    }
}

/// An event of the run: a place on the timeline to jump to.
#[derive(Clone, Debug, PartialEq)]
pub struct Mark {
    /// Time (s); the record holds a frame at exactly this time.
    pub t: f64,
    /// What happened.
    pub kind: MarkKind,
    /// In words, e.g. `rim_wall 0 → 1`.
    pub label: String,
}

/// The plot panel a series belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Panel {
    /// Forces (N).
    Force,
    /// Depth of the tip (mm).
    Depth,
    /// Tilt of the axis (degrees).
    Tilt,
}

impl Panel {
    /// `force`, `depth`, `tilt`.
    pub fn name(self) -> &'static str {
        match self {
            Panel::Force => "force",
            Panel::Depth => "depth",
            Panel::Tilt => "tilt",
        }
    }
}

/// A plotted quantity (its values are in [`Frame::values`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Panel.
    pub panel: Panel,
    /// Legend text.
    pub name: String,
    /// Unit of the values as stored.
    pub unit: &'static str,
}

/// Everything a replay page shows.
#[derive(Clone, Debug, PartialEq)]
pub struct Replay {
    /// The scene's name (the page's title).
    pub title: String,
    /// One line under the title: the model and how the run ended.
    pub subtitle: String,
    /// Solid or section.
    pub view: View,
    /// Dimensions.
    pub geometry: Geometry,
    /// Names of the contact pairs that [`Contact::pair`] indexes.
    pub pairs: Vec<&'static str>,
    /// Frames in time order.
    pub frames: Vec<Frame>,
    /// Events in time order.
    pub marks: Vec<Mark>,
    /// Plotted quantities.
    pub series: Vec<Series>,
    /// States the run produced (output samples, events, the final state)
    /// before decimation.
    pub states: usize,
    /// Events the run produced before decimation.
    pub events: usize,
    /// Suggested radial exaggeration of the gap (1 = true scale).
    pub exaggeration: f64,
}

impl Replay {
    /// A record without frames (refused by [`super::html`]); the geometry
    /// is a 10 mm peg in a 10.1 mm bore.
    pub fn empty(title: &str, view: View) -> Replay {
        Replay {
            title: title.to_string(),
            subtitle: String::new(),
            view,
            geometry: Geometry {
                peg_radius: 0.005,
                peg_length: 0.02,
                rim_fillet: 0.0002,
                centre_height: 0.01,
                hole_radius: 0.00505,
                mouth_fillet: 0.0002,
                bore_depth: 0.02,
                bore_bottom: true,
                compliance_height: None,
            },
            pairs: Vec::new(),
            frames: Vec::new(),
            marks: Vec::new(),
            series: Vec::new(),
            states: 0,
            events: 0,
            exaggeration: 1.0,
        }
    }

    /// Whether frames were left out to keep the page bounded.
    pub fn decimated(&self) -> bool {
        self.frames.len() < self.states
    }

    /// A note for the page when frames or events were left out.
    pub fn note(&self) -> Option<String> {
        let shown_events = self
            .marks
            .iter()
            .filter(|m| m.kind != MarkKind::End)
            .count();
        let mut parts = Vec::new();
        if self.decimated() {
            parts.push(format!(
                "showing {} of {} states",
                self.frames.len(),
                self.states
            ));
        }
        if shown_events < self.events {
            parts.push(format!("{shown_events} of {} events", self.events));
        } else if self.decimated() {
            parts.push("every event kept".to_string());
        }
        (!parts.is_empty())
            .then(|| format!("Decimated to keep the page small: {}.", parts.join(", ")))
    }

    /// The suggested exaggeration for a gap `clearance` in a bore of radius
    /// `radius`: the drawn gap about 3 % of the radius, at most 50, at
    /// least 1.
    pub fn suggested_exaggeration(radius: f64, clearance: f64) -> f64 {
        if clearance > 0.0 && radius > 0.0 {
            (0.03 * radius / clearance).round().clamp(1.0, 50.0)
        } else {
            1.0
        }
    }
}
