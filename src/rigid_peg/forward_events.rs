//! Contact-state events of the forward simulation, as
//! integrator [`Event`]s on x = (γ, ψ, γ̇, ψ̇), all terminal:
//!
//! - `gamma0`: γ − γ0 falling through 0 (B1 and B2 merge, b → 0);
//! - `lift_off_K`, `lift_off_B1`, `lift_off_B2`: N_i/W falling through 0,
//!   W the force scale of [`force_scale`] (m g when there is gravity);
//! - `stop` (exact Coulomb only): RMS sliding speed − v_stop falling
//!   through 0 (the peg comes to rest: decide stick or slip);
//! - `singular`: the normalized determinant of the forward system changing
//!   sign (Painlevé singularity);
//! - `jam`: the largest reaction rising through [`N_JAM`]·W: the
//!   determinant tends to zero and the reactions grow without bound before
//!   it changes sign (approach to a Painlevé singularity, a "dynamic jam"
//!   that a rigid model can only resolve by a tangential impulse).

use std::cell::Cell;
use std::rc::Rc;

use nalgebra::{Vector2, Vector4};

use crate::integrate::{Direction, Event};
use crate::rigid_peg::forward::{ForwardModel, FrictionLaw};

/// A state and its reactions (`None`: the model failed there).
type Memo = Option<(Vector4<f64>, Option<[f64; 3]>)>;

/// The normal reactions at the last state asked for: the integrator
/// evaluates every event function at the same state in turn, and the three
/// lift-off events and the jam event all need the one forward solution
/// there (one model evaluation instead of four). The value is a pure
/// function of `x`, so the memo changes no result.
struct LastReactions<'m> {
    model: &'m ForwardModel,
    start: Option<Vector2<f64>>,
    last: Cell<Memo>,
}

impl LastReactions<'_> {
    /// `[N_K, N_B1, N_B2]` at `x` (γ clamped); `None` where the model fails.
    fn at(&self, x: &Vector4<f64>) -> Option<[f64; 3]> {
        if let Some((y, n)) = self.last.get()
            && y == *x
        {
            return n;
        }
        let n = self
            .model
            .evaluate_clamped(x, self.start)
            .ok()
            .map(|a| a.normal);
        self.last.set(Some((*x, n)));
        n
    }
}

/// Reaction level (in units of m g) taken as unbounded by the `jam` event.
pub const N_JAM: f64 = 1e4;

/// What an event index means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventKind {
    /// γ reached γ0.
    Gamma0,
    /// Normal reaction `i` (0 = K, 1 = B1, 2 = B2) fell to zero.
    LiftOff(usize),
    /// The sliding speed fell to v_stop.
    Stop,
    /// The forward system became singular.
    Singular,
    /// A reaction exceeded [`N_JAM`]·W ([`force_scale`]).
    Jam,
}

/// The force W (N) in whose units the reactions are watched: the weight
/// m g; without gravity the applied loads' scale |F| + (|M_γ| + |M_ψ|)/H;
/// 1 N when there is neither (the reactions are then inertial only, and
/// `jam` fires at [`N_JAM`] N). Never zero, so N/W stays finite.
pub fn force_scale(model: &ForwardModel) -> f64 {
    let p = &model.params;
    let weight = p.mass * p.gravity;
    if weight > 0.0 {
        return weight;
    }
    let l = &model.loads;
    let f = l.force.iter().map(|c| c * c).sum::<f64>().sqrt();
    let applied = f + (l.m_gamma.abs() + l.m_psi.abs()) / p.height;
    if applied > 0.0 { applied } else { 1.0 }
}

/// The events for `model` with the sliding start `start`, and their kinds
/// in index order.
pub fn events(
    model: &ForwardModel,
    start: Option<Vector2<f64>>,
) -> (Vec<Event<'_, 4>>, Vec<EventKind>) {
    let g0 = model.params.gamma0();
    let weight = force_scale(model);
    let mut ev = vec![
        Event::new(move |_t, x: &Vector4<f64>| x[0] - g0)
            .direction(Direction::Falling)
            .terminal(),
    ];
    let mut kinds = vec![EventKind::Gamma0];
    let reactions = Rc::new(LastReactions {
        model,
        start,
        last: Cell::new(None),
    });
    for i in 0..3 {
        let reactions = Rc::clone(&reactions);
        ev.push(
            Event::new(move |_t, x: &Vector4<f64>| {
                reactions.at(x).map_or(f64::NAN, |n| n[i] / weight)
            })
            .direction(Direction::Falling)
            .terminal(),
        );
        kinds.push(EventKind::LiftOff(i));
    }
    if model.friction == FrictionLaw::Coulomb {
        let v_stop = model.v_stop;
        ev.push(
            Event::new(move |_t, x: &Vector4<f64>| model.speed(x) - v_stop)
                .direction(Direction::Falling)
                .terminal(),
        );
        kinds.push(EventKind::Stop);
    }
    ev.push(
        Event::new(move |_t, x: &Vector4<f64>| model.contact_determinant(x, start))
            .direction(Direction::Both)
            .terminal(),
    );
    kinds.push(EventKind::Singular);
    ev.push(
        Event::new(move |_t, x: &Vector4<f64>| {
            reactions.at(x).map_or(f64::NAN, |n| {
                n.iter().fold(f64::NEG_INFINITY, |m, &v| m.max(v)) / weight - N_JAM
            })
        })
        .direction(Direction::Rising)
        .terminal(),
    );
    kinds.push(EventKind::Jam);
    (ev, kinds)
}
