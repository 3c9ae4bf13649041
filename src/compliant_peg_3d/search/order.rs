//! Arcs decided by the sign of a higher derivative of the profile.
//!
//! Where a minimum of `h` is about to split into two about a col (or two
//! minima and their col are about to merge), `h′` and `h″` nearly vanish
//! at one angle, and the enclosures of [`super::certified`] decide the arcs
//! about it only once they are shorter than the distance between the
//! stationary points: the search halves to a depth set by how near the
//! split is. Over the same arc `h‴` or `h⁗` usually keeps one sign, and
//! then the arc's stationary points are few and located by evaluations at
//! points:
//!
//! - with `h⁽ʲ⁺¹⁾` of one sign on `[a, b]`, `h⁽ʲ⁾` is monotone there: it
//!   has one sign on all of `[a, b]` when its enclosure at the end where
//!   it is least in size says so, and otherwise changes sign once, at a
//!   root bracketed by two points where its enclosures have opposite signs
//!   (Newton's method safeguarded by bisection);
//! - so `h⁗` of one sign on the arc splits it into pieces where `h‴` has a
//!   proven sign and a short arc about the root, each piece into pieces
//!   where `h″` has a proven sign and short arcs (with `h‴` of one sign on
//!   the arc, the second split alone);
//! - a piece with `h″ > 0` (convex) holds a minimum exactly when `h′`
//!   changes sign from its start to its end, found as on a convex arc
//!   (safeguarded Newton); a piece with `h″ < 0` holds none; the short
//!   arcs go back to the branch and bound, which decides them by their
//!   enclosures or ends them as leaves;
//! - where `h″` is monotone, `h′` is convex or concave, and the sign of
//!   `h′` at one end can show that no minimum lies on the arc (or on the
//!   bracket of the root of `h″`) without the root: a minimum is an
//!   upward zero of `h′`, which a convex `h′` has only below its value at
//!   the right end and a concave one only above its value at the left end
//!   (`no_minimum`). The arc about an inflection next to a stationary
//!   point of a symmetric pose (where `h′` vanishes exactly) is decided
//!   this way instead of being narrowed to `10⁻¹²` rad.
//!
//! Every sign used is proven by an enclosure at a point
//! ([`Profile::point`]) and monotonicity, and the pieces and short arcs
//! cover the arc, so a minimum is missed no more than by the branch and
//! bound. An arc this cannot split (no derivative of one sign, a root
//! that cannot be bracketed) is halved as before.

use super::interval::{Iv, up};
use super::minimum::{Angles, Work, newton, push};
use super::profile::Profile;
use std::f64::consts::TAU;

/// The short arcs about roots, left to the branch and bound.
pub type Rest = arrayvec::ArrayVec<(f64, f64), 8>;

/// The bracket of a root is narrowed to about this width (rad).
const NARROW: f64 = 1e-12;

/// An angle and the enclosures of `h, …, h⁗` there.
#[derive(Clone, Copy, Debug)]
struct Pt {
    t: f64,
    j: [Iv; 5],
}

/// The sign of `±v` (`+` when `inc`) if its enclosure proves one, else 0.
fn sign(v: Iv, inc: bool) -> i8 {
    let v = if inc { v } else { Iv::new(-v.hi, -v.lo) };
    if v.lo > 0.0 {
        1
    } else if v.hi < 0.0 {
        -1
    } else {
        0
    }
}

/// Whether `h′` keeps one sign on `[l, r]`, where `h″` is monotone (the
/// bracket of a root of `h″` on an arc where `h‴` has one sign): with
/// `|h″| ≤ max(|h″(l)|, |h″(r)|)` there, `h′(t) ≥ h′(l) − (t − l)
/// max|h″|` (and alike from `r`), so `h′` of one proven sign at both ends,
/// each at least `(r − l) max|h″|` in size, has no zero between: the
/// bracket holds no stationary point and needs no narrower one.
fn no_stationary(l: &Pt, r: &Pt) -> bool {
    let side = sign(l.j[1], true);
    let least = |v: Iv| v.lo.abs().min(v.hi.abs());
    let curvature = l.j[2].mag().max(r.j[2].mag());
    side != 0
        && side == sign(r.j[1], true)
        && least(l.j[1]).min(least(r.j[1]))
            > up((r.t - l.t) * curvature * (1.0 + 4.0 * f64::EPSILON))
}

/// Whether `[l, r]`, on which `h′` is convex (`convex`: `h″` increasing)
/// or concave, holds no local minimum of `h`. A minimum is where `h′`
/// crosses zero upwards. A convex `h′` falls, then rises: it crosses
/// upwards only where it rises, and then stays below `h′(r)`, so `h′(r) <
/// 0` leaves no minimum. A concave `h′` rises, then falls: it crosses
/// upwards only where it rises, above `h′(l)`, so `h′(l) > 0` leaves none.
/// The other stationary points are maxima, which the search does not
/// report.
fn no_minimum(l: &Pt, r: &Pt, convex: bool) -> bool {
    if convex {
        sign(r.j[1], true) < 0
    } else {
        sign(l.j[1], true) > 0
    }
}

/// The last points one search evaluated, by angle: arcs decided in turn
/// that share an end evaluate it once.
#[derive(Clone, Copy, Debug, Default)]
pub struct Memo {
    points: [Option<(f64, Option<[Iv; 5]>)>; 2],
    next: usize,
}

/// One arc's decision: the profile, the minima found, the work, the short
/// arcs left and the search's last points.
struct Decider<'a> {
    prof: &'a Profile,
    out: &'a mut Angles,
    work: &'a mut Work,
    rest: &'a mut Rest,
    memo: &'a mut Memo,
}

impl Decider<'_> {
    /// The point `t` with its enclosures.
    fn at(&mut self, t: f64) -> Option<Pt> {
        self.work.points += 1;
        self.prof.point(t).map(|j| Pt { t, j })
    }

    /// [`Decider::at`] for an arc's end, which the arc decided before it
    /// may share.
    fn end(&mut self, t: f64) -> Option<Pt> {
        if let Some((_, j)) = self.memo.points.iter().flatten().find(|(u, _)| *u == t) {
            return j.map(|j| Pt { t, j });
        }
        let p = self.at(t);
        self.memo.points[self.memo.next] = Some((t, p.map(|p| p.j)));
        self.memo.next = 1 - self.memo.next;
        p
    }

    /// `[a, b]` on which `h⁽ʲ⁾` has the sign `s` (proven).
    fn piece(&mut self, j: usize, a: Pt, b: Pt, s: i8) -> Option<()> {
        if b.t <= a.t {
            return Some(());
        }
        match (j, s > 0) {
            (2, true) => {
                // Convex: one minimum exactly when h′ changes sign, the
                // end of the circle evaluated at its start (as the branch
                // and bound does).
                let lo = self.prof.slope(a.t);
                let hi = self.prof.slope(if b.t >= TAU { 0.0 } else { b.t });
                self.work.points += 2;
                if lo.0 <= 0.0
                    && hi.0 >= 0.0
                    && !push(self.out, newton(self.prof, (a.t, b.t), lo, hi, self.work))
                {
                    self.work.unresolved += 1;
                }
                Some(())
            }
            (2, false) => Some(()),
            _ => self.split(j - 1, a, b, s > 0),
        }
    }

    /// `[a, b]` on which `h⁽ʲ⁾` is increasing (`inc`) or decreasing:
    /// its pieces of one sign and the short arc about its root.
    fn split(&mut self, j: usize, a: Pt, b: Pt, inc: bool) -> Option<()> {
        let s = if inc { 1 } else { -1 };
        let (ga, gb) = (sign(a.j[j], inc), sign(b.j[j], inc));
        if ga > 0 {
            return self.piece(j, a, b, s);
        }
        if gb < 0 {
            return self.piece(j, a, b, -s);
        }
        if ga == 0 && gb == 0 {
            // Near zero over the whole piece: the arc is halved instead.
            return None;
        }
        if let Some(done) = self.by_chord(j - 1, a, b, inc) {
            return done;
        }
        let (l, r) = self.narrow(j, a, b, inc)?;
        self.piece(j, a, l, -s)?;
        if r.t > l.t && !(j == 2 && (no_stationary(&l, &r) || no_minimum(&l, &r, inc))) {
            self.rest.try_push((l.t, r.t)).ok()?;
        }
        self.piece(j, r, b, s)
    }

    /// `[a, b]` on which `h⁽ᵏ⁾` is convex (`convex`: `h⁽ᵏ⁺¹⁾` increasing)
    /// or concave, decided without the root of `h⁽ᵏ⁺¹⁾` where its end
    /// values allow: for `k = 1`, no minimum by [`no_minimum`]; for `k >
    /// 1`, a piece where `h⁽ᵏ⁾` has one sign when both end values have the
    /// sign that the chord bound carries to the whole arc (a convex
    /// function lies below its chord, `h⁽ᵏ⁾(t) ≤ (1 − λ) h⁽ᵏ⁾(a) + λ
    /// h⁽ᵏ⁾(b)` with `λ = (t − a)/(b − a)`; a concave one above it). `None`
    /// when neither holds (the root is then bracketed).
    fn by_chord(&mut self, k: usize, a: Pt, b: Pt, convex: bool) -> Option<Option<()>> {
        if k == 1 {
            return no_minimum(&a, &b, convex).then_some(Some(()));
        }
        let s: i8 = if convex { -1 } else { 1 };
        let both = sign(a.j[k], !convex) == 1 && sign(b.j[k], !convex) == 1;
        both.then(|| self.piece(k, a, b, s))
    }

    /// A bracket `[l, r] ⊆ [a, b]` of the root of `g = ±h⁽ʲ⁾` (increasing):
    /// `g(l) < 0` proven (or `l = a`), `g(r) > 0` proven (or `r = b`), about
    /// [`NARROW`] wide where the enclosures allow.
    fn narrow(&mut self, j: usize, a: Pt, b: Pt, inc: bool) -> Option<(Pt, Pt)> {
        let g = |p: &Pt| if inc { p.j[j].mid() } else { -p.j[j].mid() };
        let dg = |p: &Pt| {
            if inc {
                p.j[j + 1].mid()
            } else {
                -p.j[j + 1].mid()
            }
        };
        let (mut l, mut r) = (a, b);
        let mut x = if g(&a).abs() < g(&b).abs() { a } else { b };
        // A root within rounding of an end: tightened about that end.
        let mut centre = match (sign(a.j[j], inc), sign(b.j[j], inc)) {
            (0, _) => Some(a.t),
            (_, 0) => Some(b.t),
            _ => None,
        };
        for _ in 0..if centre.is_some() { 0 } else { 48 } {
            let d = dg(&x);
            let mut t = x.t - g(&x) / d;
            if !(d > 0.0 && t > l.t && t < r.t) {
                t = 0.5 * (l.t + r.t);
            }
            if !(t > l.t && t < r.t) {
                break;
            }
            let p = self.at(t)?;
            let close = (t - x.t).abs() <= 0.25 * NARROW;
            match sign(p.j[j], inc) {
                1 => r = p,
                -1 => l = p,
                _ => {
                    centre = Some(t);
                    break;
                }
            }
            if close || r.t - l.t <= NARROW {
                centre = Some(t);
                break;
            }
            if j == 2 && (no_stationary(&l, &r) || no_minimum(&l, &r, inc)) {
                return Some((l, r));
            }
            x = p;
        }
        // Tighten about the last point: a proven sign within NARROW/2,
        // 4 NARROW, ... of it on either side.
        if let Some(c) = centre {
            let mut d = 0.5 * NARROW;
            while c - d > l.t && c - l.t > NARROW {
                let p = self.at(c - d)?;
                if sign(p.j[j], inc) < 0 {
                    l = p;
                    break;
                }
                d *= 8.0;
            }
            let mut d = 0.5 * NARROW;
            while c + d < r.t && r.t - c > NARROW {
                let p = self.at(c + d)?;
                if sign(p.j[j], inc) > 0 {
                    r = p;
                    break;
                }
                d *= 8.0;
            }
        }
        Some((l, r))
    }
}

/// Decides the arc `[lo, hi]` (about `m`, `(c, s)` its cosine and sine,
/// `w` the enclosures' half-width) when `h‴` or `h⁗` has one sign on it:
/// its minima into `out`, the short arcs left to the branch and bound into
/// `rest`. False (and `rest` to be discarded) when the arc is to be
/// halved; the minima already added are minima. `memo` holds the last
/// arcs' end points of the same search (the same profile).
#[allow(clippy::too_many_arguments)]
pub fn decide(
    prof: &Profile,
    lo: f64,
    hi: f64,
    c: f64,
    s: f64,
    w: f64,
    out: &mut Angles,
    work: &mut Work,
    rest: &mut Rest,
    memo: &mut Memo,
) -> bool {
    let Some(e) = prof.arc(c, s, w) else {
        return false;
    };
    let (j, inc) = if e[3].excludes_zero() {
        (2, e[3].lo > 0.0)
    } else if e[4].excludes_zero() {
        (3, e[4].lo > 0.0)
    } else {
        return false;
    };
    let mut d = Decider {
        prof,
        out,
        work,
        rest,
        memo,
    };
    let (Some(a), Some(b)) = (d.end(lo), d.end(hi)) else {
        return false;
    };
    d.split(j, a, b, inc).is_some()
}
