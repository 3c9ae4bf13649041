//! What a search returns and how it places one minimum: the angles found
//! ([`Angles`]), the work done ([`Work`]), the safeguarded Newton iteration
//! on `h′` inside a bracket where `h′` changes sign (`newton`), and the
//! set insertion that keeps minima apart ([`push`]). Shared by the branch
//! and bound ([`super::certified`]) and the higher-derivative cut
//! ([`super::order`]).

use super::profile::Profile;
use std::f64::consts::TAU;

/// The most minima one search returns (a trigonometric polynomial of
/// degree two has at most two; the two tori's `h` at most six).
pub const MAX_MINIMA: usize = 8;

/// The angles (rad) of the minima a search found.
pub type Angles = arrayvec::ArrayVec<f64, MAX_MINIMA>;

/// What a search did: arcs visited and whether it ran out of budget or
/// room.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Work {
    /// Arcs whose enclosures were evaluated.
    pub arcs: usize,
    /// Profile evaluations at a point (end-point slopes and Newton).
    pub points: usize,
    /// Arcs left unresolved by the budget (0 in a complete search).
    pub unresolved: usize,
    /// The profile is constant: no isolated minimum (an aligned peg's rim
    /// over a plane).
    pub flat: bool,
    /// No search: the pair was certified apart at an earlier pose that
    /// this one is too close to for a contact.
    pub cached: bool,
    /// Arcs ended as leaves (too short to halve, or `h′` within its
    /// rounding of zero): 0 when every arc was decided by its enclosures.
    pub leaves: usize,
    /// Arcs decided by the sign of `h‴` or `h⁗` ([`super::order`]).
    pub ordered: usize,
    /// Arcs of a tracked record decided by their record's enclosures,
    /// which still hold by their margins ([`super::reuse`]): not enclosed
    /// again, and not in `arcs`.
    pub reused: usize,
    /// Searched only on the arcs an earlier full search at a nearby pose
    /// kept (the rest of the circle was certified clear from there).
    pub tracked: bool,
    /// The least lower bound of `h` over the arcs dropped because `h` was
    /// at least the level there (`None`: no such arc).
    pub floor: Option<f64>,
    /// The least distance (m) by which the window's coordinate kept out
    /// of the window over the arcs it dropped (`None`: no such arc).
    pub window_floor: Option<f64>,
}

impl Work {
    /// Whether arcs were dropped because the pair's
    /// [`super::profile::Window`] excluded them (no valid contact there,
    /// whatever the gap): by this search, or by the record a tracked
    /// search started from.
    pub fn windowed(&self) -> bool {
        self.window_floor.is_some()
    }
}

/// `a` lowered to `v` (`None` stands for no bound yet).
pub(super) fn lower(a: &mut Option<f64>, v: f64) {
    *a = Some(a.map_or(v, |a| a.min(v)));
}

/// The slope `h′` and curvature `h″` at an end of a bracket.
pub(super) type End = (f64, f64);

/// The zero of `h′` in `[lo, hi]`, `h′` increasing there, from the slopes
/// and curvatures at the ends, `h′(lo) ≤ 0 ≤ h′(hi)`: Newton on `h′`
/// from the end nearer the zero (by the slopes' sizes), with bisection
/// whenever a step leaves the bracket or `h″ ≤ 0`. The first step uses
/// that end's `h′`, `h″` as given (evaluated at the end itself: the
/// circle's end `2π`, whose slope the search takes at `0`, is evaluated
/// again). A zero at an end (a pose symmetric about that angle) is found
/// in one step.
pub(super) fn newton(
    prof: &Profile,
    (mut lo, mut hi): (f64, f64),
    at_lo: End,
    at_hi: End,
    work: &mut Work,
) -> f64 {
    if at_lo.0 == 0.0 {
        return lo;
    }
    if at_hi.0 == 0.0 {
        return hi;
    }
    let from_lo = -at_lo.0 < at_hi.0;
    let mut a = if from_lo { lo } else { hi };
    let mut known = if from_lo {
        Some(at_lo)
    } else if hi < TAU {
        Some(at_hi)
    } else {
        None
    };
    for _ in 0..100 {
        let (d1, d2) = known.take().unwrap_or_else(|| {
            work.points += 1;
            prof.slope(a)
        });
        if d1 == 0.0 {
            return a;
        }
        if d1 > 0.0 {
            hi = a;
        } else {
            lo = a;
        }
        let newton = a - d1 / d2;
        let resolution = 2.0 * f64::EPSILON * a.abs().max(1.0);
        // A Newton step below the angle's resolution: `a` is the zero to
        // rounding (also where the zero lies on the bracket's end, which
        // a strict bracket test would otherwise bisect towards for ~50
        // steps: a pose symmetric about `0` or `π`).
        if d2 > 0.0 && (newton - a).abs() <= resolution {
            return a;
        }
        let next = if d2 > 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - a).abs() <= resolution || next <= lo || next >= hi {
            return next.clamp(lo, hi);
        }
        a = next;
    }
    a
}

/// `a` (rad) wrapped into `[0, 2π)`.
pub fn wrap(a: f64) -> f64 {
    if (0.0..TAU).contains(&a) {
        return a;
    }
    let a = a.rem_euclid(TAU);
    if a >= TAU { 0.0 } else { a }
}

/// Adds the angle `a` (wrapped into `[0, 2π)`) unless a minimum within
/// `10⁻⁹` rad is there already; false when `out` is full.
pub fn push(out: &mut Angles, a: f64) -> bool {
    let a = wrap(a);
    // Both in [0, 2π): the distance along the circle.
    let near = |m: f64| {
        let d = (m - a).abs();
        d.min(TAU - d) <= 1e-9
    };
    out.iter().any(|&m| near(m)) || out.try_push(a).is_ok()
}
