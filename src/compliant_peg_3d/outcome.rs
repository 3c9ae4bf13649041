//! How an insertion ends, as a value, and the contact-state events of a
//! run.
//!
//! Terminal conditions (event functions, located on the integrator's
//! dense output):
//!
//! - `seated`: the tip's depth reaches the seat depth;
//! - `wrist force limit`: `|F_w|` reaches the wrist limit (a robot stops);
//! - `contact force limit`: the largest contact normal force reaches the
//!   contact limit;
//! - `missed`: the rim rests on the top face while the tip's centre is
//!   outside the bore radius (the axis missed the hole).
//!
//! A run stopped by a force limit while the peg is inside the bore on two
//! or more contacts, or at the end of its time span without progress, is
//! then told apart by a release test ([`release`]): the wrist is removed
//! and the peg integrated on its own for a short time. If the contacts
//! keep at least half of their normal force, the peg is `Wedged` (held by
//! its own elastic deformation); otherwise it was `Jammed` (held by the
//! applied forces inside the friction cones). A jam or wedge found after
//! a force-limit stop keeps the limit ([`LimitStop`]), so that its summary
//! says what stopped the run.

use super::contact::{ContactPoint, Pair};
use super::insertion::{Insertion, N_STATE, peg_state};
use crate::integrate::{Direction, Event, Method, Options, Solver};
use nalgebra::SVector;
use std::cell::RefCell;

/// The force limit whose terminal event stopped a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LimitStop {
    /// `wrist` or `contact`.
    pub which: &'static str,
    /// The force at the stop (N): the wrist force, or the contact limit.
    pub force: f64,
}

/// When a run ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Criteria {
    /// Tip depth at which the peg counts as seated (m).
    pub seat_depth: f64,
    /// Largest wrist force a robot accepts (N).
    pub wrist_force_limit: f64,
    /// Largest contact normal force accepted (N).
    pub contact_force_limit: f64,
    /// Duration of the release test (s).
    pub release_time: f64,
}

/// The outcome of an insertion.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// The tip reached the seat depth.
    Seated,
    /// Held by the applied forces inside the friction cones at the named
    /// contacts; released when the wrist force is removed.
    Jammed {
        /// The contacts, e.g. `edge_side, rim_wall`.
        contacts: String,
        /// The force limit that stopped the run, if one did (else the run
        /// ended without progress).
        limit: Option<LimitStop>,
    },
    /// Held by the contacts' own elastic deformation: the contact forces
    /// stay when the wrist force is removed.
    Wedged {
        /// The contacts.
        contacts: String,
        /// The force limit that stopped the run, if one did.
        limit: Option<LimitStop>,
    },
    /// The axis missed the hole: the rim rests on the top face.
    Missed,
    /// A force limit was reached outside a jam or wedge.
    ForceLimit {
        /// `wrist` or `contact`.
        which: &'static str,
        /// The force (N).
        force: f64,
    },
    /// The contact force limit was reached by a jump: the largest contact
    /// force at the previous output sample was below a tenth of the limit.
    /// A contact point entered its pair's valid region already deep, i.e.
    /// the overlap grew where no contact pair of the model looks (for
    /// example the peg's cylindrical side on the bore wall): a gap of the
    /// contact model, not a robot stop.
    ContactJump {
        /// The largest contact force at the previous sample (N).
        before: f64,
        /// The time of that sample (s).
        since: f64,
    },
    /// The integration ended otherwise (end of the time span, step size,
    /// step budget, non-finite state), as the integrator describes it.
    Stopped {
        /// The integrator's description.
        reason: String,
    },
}

impl Outcome {
    /// A short name: `seated`, `jammed`, `wedged`, `missed`, `force_limit`,
    /// `contact_jump`, `stopped`.
    pub fn name(&self) -> &'static str {
        match self {
            Outcome::Seated => "seated",
            Outcome::Jammed { .. } => "jammed",
            Outcome::Wedged { .. } => "wedged",
            Outcome::Missed => "missed",
            Outcome::ForceLimit { .. } => "force_limit",
            Outcome::ContactJump { .. } => "contact_jump",
            Outcome::Stopped { .. } => "stopped",
        }
    }

    /// A numeric code for heat maps: seated 0, jammed 1, wedged 2,
    /// missed 3, force limit 4, stopped 5, contact jump 6.
    pub fn code(&self) -> f64 {
        match self {
            Outcome::Seated => 0.0,
            Outcome::Jammed { .. } => 1.0,
            Outcome::Wedged { .. } => 2.0,
            Outcome::Missed => 3.0,
            Outcome::ForceLimit { .. } => 4.0,
            Outcome::Stopped { .. } => 5.0,
            Outcome::ContactJump { .. } => 6.0,
        }
    }
}

/// Every [`Outcome::code`] with the outcome's name for a figure's legend,
/// in code order.
pub const CODE_LEGEND: [(f64, &str); 7] = [
    (0.0, "seated"),
    (1.0, "jammed"),
    (2.0, "wedged"),
    (3.0, "missed"),
    (4.0, "force limit"),
    (5.0, "stopped"),
    (6.0, "contact jump (model gap)"),
];

/// The names of the terminal events of [`terminal_events`], in order.
pub const TERMINAL_NAMES: [&str; 4] = [
    "seated",
    "wrist force limit",
    "contact force limit",
    "missed",
];

/// The point count of each pair, in the order of [`Pair::ALL`].
pub type Counts = [usize; Pair::ALL.len()];

/// The number of contact points of each pair (order of [`Pair::ALL`]).
pub fn counts(contacts: &[ContactPoint]) -> Counts {
    counts_of(contacts.iter().map(|c| c.pair))
}

/// The number of times each pair occurs in `pairs` (order of
/// [`Pair::ALL`]): [`counts`] of contacts given by their pairs.
pub fn counts_of(pairs: impl IntoIterator<Item = Pair>) -> Counts {
    let mut n = [0; Pair::ALL.len()];
    for p in pairs {
        n[p.index()] += 1;
    }
    n
}

/// Whether the pairs in contact make two-point contact in the jamming
/// sense (Whitney): the mouth edge on the peg's side (`edge_side`) together
/// with the rim on the bore wall (`rim_wall`). The rim on the rounded mouth
/// and on the wall at once (`rim_edge + rim_wall`, the rim sliding off the
/// chamfer into the bore) is not: both points lie on the rim, the peg is
/// not held between the mouth and the wall.
pub fn two_point(pairs: impl IntoIterator<Item = Pair>) -> bool {
    let (mut edge, mut wall) = (false, false);
    for p in pairs {
        edge |= p == Pair::EdgeSide;
        wall |= p == Pair::RimWall;
    }
    edge && wall
}

/// [`two_point`] of a state given as point counts per pair (order of
/// [`Pair::ALL`]).
pub fn two_point_counts(counts: &[usize]) -> bool {
    two_point(
        Pair::ALL
            .iter()
            .zip(counts)
            .filter(|(_, n)| **n > 0)
            .map(|(p, _)| *p),
    )
}

/// A contact state in words: `none`, or the pairs with their point
/// counts, e.g. `edge_side x2 + rim_wall` (a three-point lean on the
/// mouth).
pub fn label(counts: &[usize]) -> String {
    let parts: Vec<String> = Pair::ALL
        .iter()
        .zip(counts)
        .filter(|(_, n)| **n > 0)
        .map(|(p, n)| {
            if *n == 1 {
                p.name().to_string()
            } else {
                format!("{} x{n}", p.name())
            }
        })
        .collect();
    if parts.is_empty() {
        "none".into()
    } else {
        parts.join(" + ")
    }
}

/// A state `(t, y)` and its contact counts.
type Memo = (f64, SVector<f64, N_STATE>, Counts);

/// A memo of the contact counts of the last state asked for, so that the
/// per-pair transition events of one state share one contact search.
pub struct CountCache<'a> {
    system: &'a Insertion,
    last: RefCell<Option<Memo>>,
}

impl<'a> CountCache<'a> {
    /// A cache over `system`'s contact search.
    pub fn new(system: &'a Insertion) -> Self {
        CountCache {
            system,
            last: RefCell::new(None),
        }
    }

    /// The contact counts of `y` at `t`.
    pub fn counts(&self, t: f64, y: &SVector<f64, N_STATE>) -> Counts {
        if let Some((tl, yl, c)) = &*self.last.borrow()
            && *tl == t
            && yl == y
        {
            return *c;
        }
        let c = self.system.peg.with_contacts(&peg_state(y), counts);
        *self.last.borrow_mut() = Some((t, *y, c));
        c
    }
}

/// The time (s) to which a contact transition is located: the counts are
/// piecewise constant, so each halving of the bracket costs a contact
/// search; `10⁻⁹ s` is ten thousand times below the transitions' accuracy
/// target (`10⁻⁵ s`) and saves about half of the searches of the location.
pub const TRANSITION_TOLERANCE: f64 = 1e-9;

/// One contact-state event: `(pair index, k)`: the pair's point count
/// crosses from `k − 1` to `k` (rising) or back (falling).
pub type Transition = (usize, usize);

/// The contact-transition events (pair count crossing 1 and 2, both
/// directions, non-terminal) and what each is.
pub fn transition_events<'a>(
    cache: &'a CountCache<'a>,
) -> (Vec<Event<'a, N_STATE>>, Vec<Transition>) {
    let mut events = Vec::new();
    let mut what = Vec::new();
    for i in 0..Pair::ALL.len() {
        for k in 1..=2usize {
            events.push(
                Event::new(move |t, y: &SVector<f64, N_STATE>| {
                    cache.counts(t, y)[i] as f64 - k as f64 + 0.5
                })
                .direction(Direction::Both)
                .tolerance(TRANSITION_TOLERANCE),
            );
            what.push((i, k));
        }
    }
    (events, what)
}

/// The condition of a terminal event: stop where it rises through zero.
pub type TerminalCondition<'a> = Box<dyn Fn(f64, &SVector<f64, N_STATE>) -> f64 + 'a>;

/// The terminal events of [`TERMINAL_NAMES`] for a held peg.
pub fn terminal_events<'a>(system: &'a Insertion, c: Criteria) -> Vec<Event<'a, N_STATE>> {
    terminal_conditions(system, c)
        .into_iter()
        .map(|g| Event::new(g).direction(Direction::Rising).terminal())
        .collect()
}

/// The functions of [`terminal_events`], in the order of
/// [`TERMINAL_NAMES`], each stopping the run where it rises through zero:
/// the tip's depth past the seat depth, the wrist's force and the largest
/// contact normal force past their limits, and the rim on the hole's top
/// face with the tip outside the bore (`+½` then, `−½` otherwise).
pub fn terminal_conditions<'a>(system: &'a Insertion, c: Criteria) -> Vec<TerminalCondition<'a>> {
    let prm = system.peg.params;
    let seated = move |_t, y: &SVector<f64, N_STATE>| {
        super::insertion::depth_tilt(&prm, &peg_state(y)).0 - c.seat_depth
    };
    let wrist = move |t, y: &SVector<f64, N_STATE>| {
        system
            .wrist_load(t, &peg_state(y))
            .map_or(-1.0, |(_, l)| l.force.norm() - c.wrist_force_limit)
    };
    let contact = move |_t, y: &SVector<f64, N_STATE>| {
        let f = system.peg.forces(&peg_state(y)).unwrap_or_default();
        f.iter().map(|f| f.normal_force).fold(0.0, f64::max) - c.contact_force_limit
    };
    let missed = move |_t, y: &SVector<f64, N_STATE>| {
        let ys = peg_state(y);
        let m = super::insertion::motion(&ys);
        let a = m.orientation * nalgebra::Vector3::z();
        let tip = m.centre - a * (0.5 * prm.length);
        let on_top = system
            .peg
            .contacts(&ys)
            .iter()
            .any(|c| c.pair == Pair::RimTop);
        if on_top && tip.xy().norm() > prm.bore_radius() {
            0.5
        } else {
            -0.5
        }
    };
    vec![
        Box::new(seated),
        Box::new(wrist),
        Box::new(contact),
        Box::new(missed),
    ]
}

/// What the release test found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Release {
    /// Total contact normal force before (N).
    pub before: f64,
    /// Total contact normal force at the end of the test (N).
    pub after: f64,
    /// Contact points at the end.
    pub points: usize,
}

impl Release {
    /// Whether the contacts held at least half their force on two or more
    /// points.
    pub fn held(&self) -> bool {
        self.points >= 2 && self.after >= 0.5 * self.before
    }
}

/// The release test: the peg of `system` at `y`, without its wrist and
/// follower moment, integrated for `duration` (Dormand–Prince 5(4),
/// rtol 1e-6).
pub fn release(system: &Insertion, y: &SVector<f64, N_STATE>, duration: f64) -> Release {
    let free = Insertion::new(system.peg.params, None, 0.0);
    let ys = peg_state(y);
    let before: f64 = free
        .peg
        .forces(&ys)
        .map(|f| f.iter().map(|f| f.normal_force).sum())
        .unwrap_or(0.0);
    let mut y0 = *y;
    y0[15] = 0.0;
    let mut opts = Options::with_tolerances(1e-6, 1e-12);
    opts.max_steps = 200_000;
    let mut solver = Solver::new(Method::Dopri5, opts);
    let end = match solver.solve(&free, 0.0, y0, duration) {
        Ok(sol) => sol.x_final,
        Err(_) => y0,
    };
    let ye = peg_state(&end);
    let forces = free.peg.forces(&ye).unwrap_or_default();
    Release {
        before,
        after: forces.iter().map(|f| f.normal_force).sum(),
        points: forces.len(),
    }
}

/// The outcome of a run that stopped at `(t, y)`: `terminal` is the index
/// into [`TERMINAL_NAMES`] of the terminal event that stopped it, if any,
/// `reason` the integrator's description otherwise.
pub fn classify(
    system: &Insertion,
    c: Criteria,
    t: f64,
    y: &SVector<f64, N_STATE>,
    terminal: Option<usize>,
    reason: &str,
) -> Outcome {
    let ys = peg_state(y);
    let contacts = system.peg.contacts(&ys);
    let (depth, ..) = super::insertion::depth_tilt(&system.peg.params, &ys);
    let names = label(&counts(&contacts));
    let inside = depth > system.peg.params.mouth_fillet;
    let stuck = |system: &Insertion, limit: Option<LimitStop>| {
        let r = release(system, y, c.release_time);
        if r.held() {
            Outcome::Wedged {
                contacts: names.clone(),
                limit,
            }
        } else {
            Outcome::Jammed {
                contacts: names.clone(),
                limit,
            }
        }
    };
    match terminal {
        Some(0) => Outcome::Seated,
        Some(3) => Outcome::Missed,
        Some(k @ (1 | 2)) => {
            let limit = LimitStop {
                which: if k == 1 { "wrist" } else { "contact" },
                force: if k == 1 {
                    system
                        .wrist_load(t, &ys)
                        .map_or(0.0, |(_, l)| l.force.norm())
                } else {
                    c.contact_force_limit
                },
            };
            if inside && contacts.len() >= 2 {
                stuck(system, Some(limit))
            } else {
                Outcome::ForceLimit {
                    which: limit.which,
                    force: limit.force,
                }
            }
        }
        _ => {
            let speed = ys.fixed_rows::<3>(7).norm();
            if inside && contacts.len() >= 2 && speed < 1e-4 {
                stuck(system, None)
            } else {
                Outcome::Stopped {
                    reason: reason.to_string(),
                }
            }
        }
    }
}
