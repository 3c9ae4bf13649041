//! The certified search for the local minima of a profile `h(θ)` below a
//! level `T` on the circle: branch and bound over arcs with the
//! enclosures of [`Profile::enclose`].
//!
//! The circle is cut into [`START`] arcs. An arc is dropped when its
//! enclosures show that it holds no local minimum below `T`:
//!
//! - `h > T` on the arc (the value's lower bound is at least `T`),
//! - `h′ ≠ 0` on the arc (the slope's enclosure excludes zero: `h` is
//!   monotone on the closed arc, so it has no stationary point there),
//! - `h″ < 0` on the arc (concave: a stationary point there is a maximum),
//! - for the contact path ([`minima_kept`], [`minima_on`]), the pair's
//!   [`Window`] excludes the arc: the contact's coordinate (the rim's
//!   height on the bore wall, the axial coordinate on the peg's side)
//!   keeps out of the part of the surface that exists, so no minimum
//!   there is a contact.
//!
//! An arc with `h″ > 0` on it (convex) has at most one stationary point,
//! a minimum, which exists exactly when `h′` changes sign from the arc's
//! start to its end; it is found by Newton's method safeguarded by
//! bisection on the sign of `h′`. Every other arc is halved. A local
//! minimum `θ*` with `h(θ*) < T` has `h′(θ*) = 0` and `h″(θ*) ≥ 0`, so no
//! arc containing it is dropped: it lies in a convex arc (found) or in a
//! leaf, an arc too short to halve ([`DEPTH`] halvings, about `10⁻¹³`
//! rad) or one on which `h′` is within its rounding allowance of zero
//! (halving it would not narrow the slope's enclosure: a flat stretch,
//! such as two minima and their col about to merge). In a leaf, as in a
//! convex arc, a minimum is found when `h′(lo) ≤ 0 ≤ h′(hi)`: a slope that
//! rounds to exactly zero at the end shared by two leaves (a minimum of a
//! flat stretch that falls on the end) is found by both, as one point,
//! where a strict test would let each leave it to the other. Minima and
//! maxima that alternate within one leaf, whose slopes are below the
//! rounding of `h′`, are below the resolution of `f64` and may be found
//! as one. Neighbouring arcs share their end points and evaluate `h′`
//! there identically, so a sign change at a shared end is seen by one of
//! them.
//!
//! An arc that is neither dropped nor convex, from [`ORDER_DEPTH`] on, is
//! first tried by the sign of `h‴` or `h⁗` over it ([`order`]): when one
//! of them keeps its sign, the arc is cut into pieces where `h″` has a
//! proven sign and short arcs about the roots, which go back on the stack
//! (and are not tried again that way); otherwise it is halved.
//!
//! A search that ends in a leaf says so ([`Work::leaves`]): where `h′` is
//! below its rounding the minima it reports are as good as `f64` resolves
//! them, but not certified, so such a search certifies no clearance
//! ([`super::Search::find`]).

use super::minimum::{Angles, Work, lower, newton, push};
use super::order;
use super::profile::{Profile, Window};
use super::reuse::{Carried, Kind, Note, Shift, carry};
use super::start;
use std::f64::consts::TAU;

/// The room for arcs still to visit.
const STACK: usize = 128;

pub use super::start::START;

/// The most halvings of a start arc (`2π/8 · 2⁻⁴⁰ ≈ 7·10⁻¹³` rad).
pub const DEPTH: u32 = 40;

/// The least depth at which an undecided arc is first tried by the sign of
/// a higher derivative ([`order`]) before it is halved.
pub const ORDER_DEPTH: u32 = 2;

/// The most arcs visited in one search: none of the pairs comes near it
/// (the work is about twice the depth per minimum); reaching it stops the
/// search with what it has found and says so.
pub const BUDGET: usize = 4096;

/// The enclosure's half-width for the arc `[lo, hi]` about `m`: the arc
/// widened by `10⁻¹⁵` rad (which also covers the difference between the
/// float `2π` and the end of the circle).
fn half_width(lo: f64, hi: f64, m: f64) -> f64 {
    (hi - m).max(m - lo) * (1.0 + 4.0 * f64::EPSILON) + 1e-15
}

/// An arc `[lo, hi]` of the circle (rad) as the search holds it: its
/// depth (halvings from a start arc) and whether it may still be decided
/// by a higher derivative.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Arc {
    /// The arc's start (rad).
    pub lo: f64,
    /// The arc's end (rad).
    pub hi: f64,
    /// Halvings from its start arc.
    pub depth: u32,
    /// Whether [`order`] may still decide it.
    pub higher: bool,
}

/// The most arcs a [`Kept`] record holds.
pub const KEPT: usize = 32;

/// The arcs of a search that its level did not drop, each as it was
/// decided (an arc cut by [`order`] whole, not its pieces): with the
/// arcs dropped because `h ≥ T` on them, or because the pair's window
/// excluded them, they cover the circle. `complete`
/// is false when they did not fit, or when the search could not decide
/// every arc (budget, room, a constant profile): such a record cannot
/// stand for the search.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Kept {
    /// The arcs, in the order they were decided.
    pub arcs: arrayvec::ArrayVec<Arc, KEPT>,
    /// How each arc was decided, with its enclosures (the same order).
    pub notes: arrayvec::ArrayVec<Note, KEPT>,
    /// Whether `arcs` and the level-dropped arcs cover the circle.
    pub complete: bool,
}

impl Kept {
    /// Whether the angle `a` (rad, in `[0, 2π)`) lies on one of the arcs.
    pub fn covers(&self, a: f64) -> bool {
        self.arcs.iter().any(|arc| arc.lo <= a && a <= arc.hi)
    }
}

/// Every local minimum of `prof` with `h < level` (and possibly other
/// local minima), angles in `[0, 2π)`, into `out`.
pub fn minima(prof: &Profile, level: f64, out: &mut Angles) -> Work {
    search(prof, level, None, &starts(), None, out, None)
}

/// The start arcs.
fn starts() -> [Arc; START] {
    std::array::from_fn(|k| {
        let (lo, hi) = start::arc(k);
        Arc {
            lo,
            hi,
            depth: 0,
            higher: true,
        }
    })
}

/// [`minima`] on the arcs where `window` admits a valid contact (the
/// others are dropped: [`Work::window_floor`]), with the arcs neither its
/// level nor the window dropped into `kept`.
pub fn minima_kept(
    prof: &Profile,
    level: f64,
    window: Option<&Window>,
    out: &mut Angles,
    kept: &mut Kept,
) -> Work {
    search(prof, level, window, &starts(), None, out, Some(kept))
}

/// Every local minimum of `prof` with `h < level` on the arcs `from` kept
/// by a search of the profile `was` (at another pose), and possibly other
/// local minima, into `out`: the branch and bound started from those
/// arcs instead of the start arcs. These are the minima below the level
/// everywhere except on the arcs that record's level dropped. An arc whose
/// decision there still holds by its margins against the change from `was`
/// to `prof` ([`super::reuse`]) is not enclosed again ([`Work::reused`]).
pub fn minima_on(
    prof: &Profile,
    level: f64,
    window: Option<&Window>,
    (from, was): (&Kept, &Profile),
    out: &mut Angles,
) -> Work {
    let shift = Shift::between(was, prof).map(|s| (&from.notes[..], s));
    search(prof, level, window, &from.arcs, shift, out, None)
}

/// A convex arc's (or a leaf's) one minimum below the level, if `h′`
/// changes sign from `lo` to `hi`: its end slopes, then Newton.
fn settle(prof: &Profile, (lo, hi): (f64, f64), leaf: bool, out: &mut Angles, work: &mut Work) {
    let at_lo = prof.slope(lo);
    // The circle's end is its start: one evaluation for both.
    let at_hi = prof.slope(if hi >= TAU { 0.0 } else { hi });
    work.points += 2;
    if leaf {
        work.leaves += 1;
    }
    let found = at_lo.0 <= 0.0 && at_hi.0 >= 0.0;
    if found && !push(out, newton(prof, (lo, hi), at_lo, at_hi, work)) {
        work.unresolved += 1;
    }
}

/// The branch and bound from the arcs `from`, dropping the arcs outside
/// `window` and recording into `kept` the arcs neither its level nor the
/// window dropped, with their decisions; `reuse` holds the decisions of
/// the arcs `from` at another pose and the shift of the profile since.
fn search(
    prof: &Profile,
    level: f64,
    window: Option<&Window>,
    from: &[Arc],
    reuse: Option<(&[Note], Shift)>,
    out: &mut Angles,
    mut kept: Option<&mut Kept>,
) -> Work {
    let mut work = Work::default();
    if let Some(k) = kept.as_deref_mut() {
        k.arcs.clear();
        k.notes.clear();
        k.complete = false;
    }
    if let Profile::Trig(f) = prof
        && f.f.is_constant()
    {
        work.flat = true;
        return work;
    }
    let mut overflow = false;
    let recording = kept.is_some();
    let mut keep = |arc: Arc, inside: bool, note: Option<Note>| {
        if let Some(k) = kept.as_deref_mut()
            && !inside
            && let Some(note) = note
            && (k.arcs.try_push(arc).is_err() || k.notes.try_push(note).is_err())
        {
            overflow = true;
        }
    };
    // The note of an arc kept as `kind` with the enclosures `e` (only
    // while recording: the parts cost two enclosures).
    let note = |kind: Kind, e, (c, s, w)| {
        recording.then(|| Note {
            kind,
            h: e,
            parts: prof.parts(c, s, w),
        })
    };
    // The higher-derivative cut's last end points, shared by its arcs.
    let mut memo = order::Memo::default();
    // An entry: the arc, whether it lies inside an arc already recorded
    // whole (a piece of an arc cut by a higher derivative), and its index
    // in `from` (whose decision `reuse` may carry).
    let mut stack = arrayvec::ArrayVec::<(Arc, bool, Option<usize>), STACK>::new();
    for (i, arc) in from.iter().enumerate().rev() {
        if stack.try_push((*arc, false, Some(i))).is_err() {
            work.unresolved += 1;
        }
    }
    while let Some((arc, inside, from_index)) = stack.pop() {
        let Arc {
            lo,
            hi,
            depth,
            higher,
        } = arc;
        if work.arcs >= BUDGET {
            work.unresolved += 1 + stack.len();
            break;
        }
        // A record's decision that still holds settles the arc before its
        // window is asked: the window only ever drops arcs (a minimum it
        // would have dropped is found, and is no contact).
        let carried = reuse.as_ref().and_then(|(notes, shift)| {
            let note = notes.get(from_index?)?;
            Some(carry(note, shift.over(note)?, level))
        });
        match carried {
            Some(Carried::Above(floor)) => {
                work.reused += 1;
                lower(&mut work.floor, floor);
                continue;
            }
            Some(Carried::Clear) => {
                work.reused += 1;
                continue;
            }
            Some(Carried::Convex) => {
                work.reused += 1;
                settle(prof, (lo, hi), false, out, &mut work);
                continue;
            }
            Some(Carried::Afresh) | None => {}
        }
        work.arcs += 1;
        let m = 0.5 * (lo + hi);
        let (s, c) = start::sin_cos(m);
        let w = half_width(lo, hi, m);
        if let Some(out) = window.and_then(|win| win.outside(c, s, w)) {
            lower(&mut work.window_floor, out);
            continue;
        }
        let e = prof.enclose(c, s, w, level);
        if e.value.lo >= level {
            lower(&mut work.floor, e.value.lo);
            continue;
        }
        if e.d1.excludes_zero() || e.d2.hi < 0.0 {
            let kind = if e.d1.excludes_zero() {
                Kind::Monotone
            } else {
                Kind::Concave
            };
            keep(arc, inside, note(kind, e, (c, s, w)));
            continue;
        }
        let leaf = depth >= DEPTH || m <= lo || m >= hi || !e.refinable;
        if e.d2.lo > 0.0 || leaf {
            let kind = if leaf { Kind::Other } else { Kind::Convex };
            keep(arc, inside, note(kind, e, (c, s, w)));
            settle(prof, (lo, hi), leaf, out, &mut work);
            continue;
        }
        if higher && depth >= ORDER_DEPTH {
            let mut rest = order::Rest::new();
            if order::decide(prof, lo, hi, c, s, w, out, &mut work, &mut rest, &mut memo) {
                work.ordered += 1;
                keep(arc, inside, note(Kind::Other, e, (c, s, w)));
                for (a, b) in rest {
                    let piece = Arc {
                        lo: a,
                        hi: b,
                        depth: depth + 1,
                        higher: false,
                    };
                    if stack.try_push((piece, true, None)).is_err() {
                        work.unresolved += 1;
                    }
                }
                continue;
            }
        }
        // Halving adds one arc per level; each decided arc at most
        // `order::Rest`'s capacity.
        let half = |lo, hi| Arc {
            lo,
            hi,
            depth: depth + 1,
            higher,
        };
        if stack.try_push((half(m, hi), inside, None)).is_err()
            || stack.try_push((half(lo, m), inside, None)).is_err()
        {
            work.unresolved += 1;
        }
    }
    if let Some(k) = kept {
        k.complete = !overflow && work.unresolved == 0;
    }
    work
}
