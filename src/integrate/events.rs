//! Event functions `g(t, x)` and the location of their zeros on the dense
//! output of an accepted step.
//!
//! A sign change of `g` between the ends of a step is located by the
//! Illinois variant of regula falsi on `θ ↦ g(t(θ), x(θ))`, where `x(θ)` is
//! the step's interpolant, until the bracket is a few ulps of `t` wide (or
//! the event's own time tolerance, [`Event::tolerance`]). Two
//! sign changes inside one step cancel and are not seen: keep `h_max`
//! below the shortest time between zeros you need to resolve.

use nalgebra::SVector;

use super::dense::Interpolant;

/// Which sign changes of an event function fire the event.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Direction {
    /// From negative to non-negative.
    Rising,
    /// From positive to non-positive.
    Falling,
    /// Either.
    #[default]
    Both,
}

/// The function type of an event: `g(t, x)`, an event fires where `g`
/// changes sign.
pub type EventFn<'a, const N: usize> = dyn Fn(f64, &SVector<f64, N>) -> f64 + 'a;

/// An event function with its direction filter and whether it ends the
/// integration.
///
/// ```
/// use pegdyn::integrate::{Direction, Event};
/// // Stop when the first state component falls through zero.
/// let e = Event::<2>::new(|_t, x| x[0]).direction(Direction::Falling).terminal();
/// assert!(e.is_terminal());
/// ```
pub struct Event<'a, const N: usize> {
    function: Box<EventFn<'a, N>>,
    direction: Direction,
    terminal: bool,
    tolerance: f64,
}

impl<'a, const N: usize> Event<'a, N> {
    /// A non-terminal event firing on sign changes in both directions.
    pub fn new(function: impl Fn(f64, &SVector<f64, N>) -> f64 + 'a) -> Self {
        Event {
            function: Box::new(function),
            direction: Direction::Both,
            terminal: false,
            tolerance: 0.0,
        }
    }

    /// Locates the event's time to within `tolerance` (s) rather than a
    /// few ulps of `t`: for an event function that is piecewise constant
    /// (a count), whose location halves the bracket at each call, so that
    /// each factor of two of precision costs one evaluation. Negative or
    /// NaN values count as 0.
    pub fn tolerance(mut self, tolerance: f64) -> Self {
        self.tolerance = if tolerance > 0.0 { tolerance } else { 0.0 };
        self
    }

    /// Sets the direction filter.
    pub fn direction(mut self, direction: Direction) -> Self {
        self.direction = direction;
        self
    }

    /// Makes the event stop the integration when it fires.
    pub fn terminal(mut self) -> Self {
        self.terminal = true;
        self
    }

    /// Whether the event stops the integration.
    pub fn is_terminal(&self) -> bool {
        self.terminal
    }

    /// The direction filter.
    pub fn get_direction(&self) -> Direction {
        self.direction
    }

    /// Evaluates `g(t, x)`.
    pub fn eval(&self, t: f64, x: &SVector<f64, N>) -> f64 {
        (self.function)(t, x)
    }

    /// Whether going from `g0` to `g1` is a sign change this event reports.
    /// A step that starts exactly on zero (`g0 == 0`) reports nothing, so an
    /// integration restarted at a located event does not fire it again.
    pub(crate) fn fires(&self, g0: f64, g1: f64) -> Option<bool> {
        let rising = g0 < 0.0 && g1 >= 0.0;
        let falling = g0 > 0.0 && g1 <= 0.0;
        match self.direction {
            Direction::Rising if rising => Some(true),
            Direction::Falling if falling => Some(false),
            Direction::Both if rising || falling => Some(rising),
            _ => None,
        }
    }
}

impl<const N: usize> std::fmt::Debug for Event<'_, N> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Event")
            .field("direction", &self.direction)
            .field("terminal", &self.terminal)
            .field("tolerance", &self.tolerance)
            .finish_non_exhaustive()
    }
}

/// Locates the sign change of `event` in the step `[t0, t1]` whose end
/// values are `g0` (at `t0`) and `g1` (at `t1`, of the other sign or zero).
///
/// Returns the right end of the final bracket, i.e. the first time found at
/// which `g` already has its new sign, with the interpolated state there,
/// and the number of event-function calls made.
pub(crate) fn locate<const N: usize>(
    event: &Event<'_, N>,
    dense: &Interpolant<N>,
    (t0, g0): (f64, f64),
    (t1, g1, x1): (f64, f64, &SVector<f64, N>),
) -> (f64, SVector<f64, N>, usize) {
    if g1 == 0.0 {
        return (t1, *x1, 0);
    }
    let tol =
        (4.0 * f64::EPSILON * t0.abs().max(t1.abs()).max(f64::MIN_POSITIVE)).max(event.tolerance);
    let (mut a, mut ga) = (t0, g0);
    let (mut b, mut gb) = (t1, g1);
    let mut xb = *x1;
    let mut calls = 0;
    // Which end was kept in the previous iteration (for the Illinois halving).
    let mut kept_side = 0i8;
    while b - a > tol && calls < 200 {
        // Regula falsi point, safeguarded to stay strictly inside.
        let mut t = b - gb * (b - a) / (gb - ga);
        if !(t > a && t < b) {
            t = 0.5 * (a + b);
        }
        let x = dense.eval(t);
        let g = event.eval(t, &x);
        calls += 1;
        if g == 0.0 || g.signum() == gb.signum() {
            // The new point has the post-crossing sign: it is the new right end.
            b = t;
            gb = g;
            xb = x;
            if g == 0.0 {
                break;
            }
            if kept_side == -1 {
                ga *= 0.5;
            }
            kept_side = -1;
        } else {
            a = t;
            ga = g;
            if kept_side == 1 {
                gb *= 0.5;
            }
            kept_side = 1;
        }
    }
    (b, xb, calls)
}
