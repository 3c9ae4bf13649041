//! The contact search: for each pair, every local minimum of the gap
//! `g(α)` along its circle that lies below zero (every contact), found
//! with certainty.
//!
//! Each pair's gap is an increasing function of a simpler profile `h`
//! ([`profile`]): a trigonometric polynomial of degree two for the mouth
//! edge on the peg's side and the rim on the bore wall (squared distances
//! to a line and to the hole's axis), a sinusoid for the rim on a plane,
//! and for the rim on the mouth edge the squared distance between the two
//! tube-centre circles, `(√F − R_m)² + Z²`. The plane pairs have their one
//! minimum in closed form. The others are searched by branch and bound
//! over arcs ([`certified`]): an arc is dropped only when an enclosure of
//! `h`, `h′` or `h″` over it ([`trig`], [`interval`]) proves that it holds
//! no minimum below the level, and the minimum of a convex arc is found by
//! safeguarded Newton. An arc on which `h‴` or `h⁗` keeps one sign (about
//! a minimum that splits into two, where the enclosures would halve down
//! to the distance between the stationary points) is cut instead into
//! pieces where `h″` has a proven sign ([`order`]). A minimum is never
//! missed by sampling between
//! points; the search needs no warm start, so it is as certain at a start,
//! after an impact, along a sweep and along a smooth run.
//!
//! Along a run, [`Search::find`] keeps two records of a pair's last full
//! search, each with the bound `moved_within` on how far any point's gap can
//! have changed since: a pair found apart by `m` is not searched again
//! while the pose moves less than `m`; otherwise, while the pose stays
//! within [`TRACK`] of the last full search, only the arcs that search
//! could not show to be at least [`CLEARANCE`] clear are searched again
//! (the others keep a gap of at least `CLEARANCE − TRACK`), for the minima
//! below [`TRACKED_BELOW`] only. `moved_within` counts only the motion the fixed
//! surface sees: the horizontal part for the bore wall, the vertical part
//! for the faces, the part across the peg's axis for its side. Either way
//! every contact is found as by a fresh search, and agrees with a fresh
//! search's to rounding (`tests/compliant_peg_3d/tracked_search.rs`).
//!
//! Only penetrating minima (`g < 0`) on the part of each surface that
//! exists (see [`Pair::valid`]) become contacts; minima closer than
//! `10⁻⁹` rad are one.

pub mod certified;
pub mod interval;
pub mod minimum;
pub mod order;
pub mod profile;
pub mod reuse;
pub mod start;
pub mod tori;
pub mod trig;

use super::contact::{ContactPoint, Contacts, Pair, axis_of};
use super::merge;
use super::params::Peg3dParams;
use nalgebra::SVector;

pub use minimum::{Angles, MAX_MINIMA, Work};
use profile::Problem;

/// The minimum at `a` (from the profile) as a root of the generated
/// function's own `g′`: one Newton step on the generated derivatives, kept
/// when it is short (`10⁻⁹` rad) and lowers `|g′|`. The two agree to
/// rounding; the step makes a contact of a symmetric pose lie exactly on
/// the plane of symmetry, as the generated derivative says. Returns the
/// angle and the generated outputs there.
fn polish(
    pair: Pair,
    x: &SVector<f64, 7>,
    p: &SVector<f64, 16>,
    a: f64,
) -> (f64, super::contact::PairOut<f64>) {
    let e = pair.eval(x, a, p);
    if e.d1 != 0.0 && e.d2 > 0.0 {
        let next = a - e.d1 / e.d2;
        // A step below the angle's resolution leaves `a` (and its outputs).
        if next != a && (next - a).abs() < 1e-9 {
            let en = pair.eval(x, next, p);
            if en.d1.abs() < e.d1.abs() {
                return (minimum::wrap(next), en);
            }
        }
    }
    (a, e)
}

/// The gap up to which [`Search::find`] also finds the minima of a pair
/// out of contact (m): their least gap is the clearance by which the pose
/// may move before the pair can touch.
pub const CLEARANCE: f64 = 3e-5;

/// A pair certified apart at a pose: every point of the pair's circle has
/// a gap of at least `margin` there.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Clear {
    pose: SVector<f64, 7>,
    margin: f64,
    /// Arcs were dropped by the pair's window: the bound counts the
    /// whole displacement ([`moved_within`]).
    windowed: bool,
}

/// A bound on how much any point's gap of `pair` changes from pose `a` to
/// pose `b` (unit quaternions), `p` the parameter vector.
///
/// A body point `b_B` (body frame) moves by `|Δp| + |ΔR b_B| ≤ |Δp| +
/// 2|Δq| |b_B|`: for unit quaternions with `q·q′ ≥ 0` (the sign of `q′`
/// chosen), `|q − q′| = 2 sin(φ/4)` and `|ΔR b_B| = 2 sin(φ/2) |b_B| ≤
/// 2|q − q′| |b_B|`, `φ` the rotation between them. Only the part of the
/// displacement that the fixed surface sees counts:
///
/// - the rim against the bore wall (a vertical cylinder about the axis):
///   the distance to it changes by at most the point's horizontal
///   displacement, `|Δp_xy| + 2|Δq| √(ϱ² + (L/2 − ρ_p)²)`;
/// - the rim against a horizontal plane: by at most the vertical one,
///   `|Δp_z| + 2|Δq| √(ϱ² + (L/2 − ρ_p)²)`;
/// - the rim against the mouth edge: by the whole displacement;
/// - the mouth edge's point `m` against the peg's axis line: by the
///   displacement across the axis of the axis point at the mouth, plus
///   the axis's own turn times the mouth's reach from that point
///   ([`side_moved`]: the side is a surface of revolution about the
///   peg's axis, so a spin about it moves no gap).
///
/// A search that dropped arcs by the pair's window ([`profile::Window`],
/// `windowed`), or certified the pair clear because its circle keeps off
/// the part of the surface that exists ([`Problem::Off`]), also needs the
/// window's coordinate to move less than the bound: the height of a rim
/// point (the bore wall) and its distance from the hole's axis (the
/// faces) move by at most `|Δp| + 2|Δq| √(ϱ² + (L/2 − ρ_p)²)`, the peg's
/// side's axial coordinate by the bound of [`side_moved`]; such a bound
/// counts the whole `|Δp|`.
///
/// The sum is widened by `10⁻¹²` of itself and `8ε |Δp|` for its rounding.
///
/// Every fixed surface (the bore wall, the faces, the mouth edge) is a
/// surface of revolution about the hole's axis `e_z`, so the gap of each
/// point of the peg's rim (its angle in the peg's frame) is the same at
/// `b` and at `b` turned about `e_z` by any angle φ (`p ↦ R_z(φ) p`,
/// `q ↦ q_z(φ) ⊗ q`): for the rim's pairs the bound is the lesser of the
/// bound to `b` and to `b` turned by the φ that brings its orientation
/// nearest `a`'s ([`turned_towards`]), so that a peg precessing about the
/// hole's axis moves only by what changes its pose relative to the hole.
/// The mouth edge against the peg's side runs over the mouth's circle,
/// fixed in the hole's frame: a turn moves its points by φ, and its bound
/// is the direct one.
///
/// Returns whether the bound is below `limit` (the turn is tried only
/// when the direct bound is not).
fn moved_within(
    pair: Pair,
    p: &SVector<f64, 16>,
    (a, b): (&SVector<f64, 7>, &SVector<f64, 7>),
    windowed: bool,
    limit: f64,
) -> bool {
    if moved_to(pair, p, a, b, windowed) < limit {
        return true;
    }
    if pair == Pair::EdgeSide {
        return false;
    }
    turned_towards(a, b).is_some_and(|t| {
        // The turned pose is rounded: its points lie within a few ulps of
        // the body's size of the exact turn's.
        let size = b.fixed_rows::<3>(0).norm() + p[0] + p[1] + p[3] + p[4];
        moved_to(pair, p, a, &t, windowed) + 16.0 * f64::EPSILON * size < limit
    })
}

/// Pose `b` turned about the hole's axis `e_z` by the angle φ that brings
/// its orientation nearest `a`'s (unit quaternions `(w, i, j, k)`).
///
/// `q_z(φ) ⊗ q = c q + s K(q)` with `(c, s) = (cos φ/2, sin φ/2)` and
/// `K(w, i, j, k) = (−k, −j, i, w)`; `a·(c q + s K q) = c A + s B` (`A =
/// a·q`, `B = a·K(q)`) is greatest, `√(A² + B²)`, at `(c, s) = (A, B)/√(A²
/// + B²)`; the position turns by `cos φ = c² − s²`, `sin φ = 2cs`. `None`
/// when `A = B = 0` (no turn is nearer than another).
fn turned_towards(a: &SVector<f64, 7>, b: &SVector<f64, 7>) -> Option<SVector<f64, 7>> {
    let (w, i, j, k) = (b[3], b[4], b[5], b[6]);
    let big_a = a[3] * w + a[4] * i + a[5] * j + a[6] * k;
    let big_b = -a[3] * k - a[4] * j + a[5] * i + a[6] * w;
    let norm = big_a.hypot(big_b);
    if norm == 0.0 || !norm.is_finite() {
        return None;
    }
    let (c, s) = (big_a / norm, big_b / norm);
    let (cos, sin) = (c * c - s * s, 2.0 * c * s);
    Some(SVector::from([
        cos * b[0] - sin * b[1],
        sin * b[0] + cos * b[1],
        b[2],
        c * w - s * k,
        c * i - s * j,
        c * j + s * i,
        c * k + s * w,
    ]))
}

/// [`moved_within`] from `a` to `b` as they stand (no turn about the axis).
fn moved_to(
    pair: Pair,
    p: &SVector<f64, 16>,
    a: &SVector<f64, 7>,
    b: &SVector<f64, 7>,
    windowed: bool,
) -> f64 {
    let d = b.fixed_rows::<3>(0) - a.fixed_rows::<3>(0);
    let (qa, qb) = (a.fixed_rows::<4>(3), b.fixed_rows::<4>(3));
    let dq = (qb - qa).norm().min((qb + qa).norm());
    let (r, len, rho_p) = (p[0], p[1], p[2]);
    let rim = ((r - rho_p).powi(2) + (0.5 * len - rho_p).powi(2)).sqrt();
    let bound = match pair {
        Pair::RimWall if !windowed => (d[0] * d[0] + d[1] * d[1]).sqrt() + 2.0 * dq * rim,
        Pair::RimWall | Pair::RimEdge => d.norm() + 2.0 * dq * rim,
        Pair::RimTop | Pair::RimBottom if windowed => d.norm() + 2.0 * dq * rim,
        Pair::RimTop | Pair::RimBottom => d[2].abs() + 2.0 * dq * rim,
        Pair::EdgeSide => return side_moved(p, a, b, windowed),
    };
    bound * (1.0 + 1e-12) + 8.0 * f64::EPSILON * d.norm()
}

/// [`moved_to`] for the mouth edge against the peg's side: the side is a
/// surface of revolution about the peg's axis line, so the gap of a mouth
/// point `m` is `|(m − s) × a| − r − ρ_h` for any point `s` of the line
/// and a spin about the axis moves no gap. With `s = p + t a` the axis
/// point nearest the mouth's centre `o = −ρ_h e_z` at pose `a` (`t = (o −
/// p)·a`) and `s′ = p′ + t a′` the same body point at pose `b`,
///
/// ```text
/// (m − s′) × a′ = (m − s) × a + (m − s) × (a′ − a) − (s′ − s) × a′
/// ```
///
/// so the distance changes by at most `|Δs × a′| + |m − s| |a′ − a|`,
/// `|m − s| ≤ R + ρ_h + |s − o|`: the axis's turn `|a′ − a|` (not the
/// body's, which counts the spin) about the point of the axis at the
/// mouth (where a leaning peg pivots), not about its centre. The axial
/// coordinate `(m − p)·a = (m − s)·a + t` of a windowed search changes by
/// at most `|Δs| + |m − s| |a′ − a|`. The sum is widened for its rounding
/// (the axes' components are within a few ulps).
fn side_moved(
    p: &SVector<f64, 16>,
    a: &SVector<f64, 7>,
    b: &SVector<f64, 7>,
    windowed: bool,
) -> f64 {
    let (big_r, rho_h) = (p[3], p[4]);
    let (axis_a, axis_b) = (axis_of(a), axis_of(b));
    let (pa, pb) = (a.fixed_rows::<3>(0), b.fixed_rows::<3>(0));
    let o = nalgebra::Vector3::new(0.0, 0.0, -rho_h);
    let t = (o - pa).dot(&axis_a);
    let s = pa + axis_a * t;
    let ds = (pb + axis_b * t) - s;
    let across = if windowed {
        ds.norm()
    } else {
        (ds - axis_b * ds.dot(&axis_b)).norm()
    };
    let lever = big_r + rho_h + (s - o).norm();
    let bound = across + lever * (axis_b - axis_a).norm();
    let size = pa.norm() + pb.norm() + t.abs() + lever;
    bound * (1.0 + 1e-12) + 16.0 * f64::EPSILON * size
}

/// A pair's full search at a pose, kept for the poses near it: the arcs
/// its level dropped had `g ≥ CLEARANCE` there, so at a pose that moved
/// by `δ` ([`moved_within`]) their gap is at least `CLEARANCE − δ`, and only the
/// other arcs ([`certified::Kept`]) can hold a contact.
#[derive(Clone, Debug, PartialEq)]
struct Tracked {
    pose: SVector<f64, 7>,
    /// The profile searched there.
    profile: profile::Profile,
    kept: certified::Kept,
    /// Arcs were dropped by the pair's window ([`Clear::windowed`]).
    windowed: bool,
}

/// How far (m) a pose may move from a pair's last full search before the
/// pair is searched in full again: the dropped arcs keep a gap of at
/// least `CLEARANCE − TRACK` (half the clearance).
pub const TRACK: f64 = 0.5 * CLEARANCE;

/// The gap (m) below which a search from a tracked record finds the
/// minima: every contact, and a clearance of this much for the pair when
/// none touches (at most `CLEARANCE − TRACK`, what the arcs its record
/// dropped keep).
pub const TRACKED_BELOW: f64 = 0.1 * CLEARANCE;
const _: () = assert!(TRACKED_BELOW <= CLEARANCE - TRACK);

/// The contact search of one pair: the work its last call did, the
/// clearance it certified and the last full search it may search from.
#[derive(Clone, Debug, Default)]
pub struct Search {
    /// What the last search did (arcs visited, points evaluated).
    pub work: Work,
    clear: Option<Clear>,
    tracked: Option<Tracked>,
}

impl Search {
    /// Every local minimum of `pair`'s gap below `below` (m) at pose `x`
    /// (unit quaternion), `p` the generated functions' parameter vector
    /// ([`Peg3dParams::vector`]): angles in `[0, 2π)`. The result may hold
    /// further local minima of the gap (at or above `below`), never a point
    /// that is not one.
    pub fn minima(
        &mut self,
        pair: Pair,
        x: &SVector<f64, 7>,
        p: &SVector<f64, 16>,
        below: f64,
    ) -> Angles {
        self.work = Work::default();
        self.minima_of(Problem::of(pair, x, p, below))
    }

    /// The minima of a search problem already built (see [`Search::minima`]).
    fn minima_of(&mut self, problem: Problem) -> Angles {
        let mut out = Angles::new();
        match problem {
            Problem::Nothing | Problem::Off(_) | Problem::Invalid(_) => {}
            Problem::Closed(None) => self.work.flat = true,
            Problem::Closed(Some(a)) => {
                minimum::push(&mut out, a);
            }
            Problem::Search { h, level } => {
                self.work = certified::minima(&h, level, &mut out);
            }
        }
        out
    }

    /// The local minima of `pair`'s gap at pose `x` below a bound (and
    /// possibly others), and that bound, which the gap away from them is
    /// at least: from a `Tracked` search whose pose is less than [`TRACK`]
    /// away (by [`moved_within`]), the minima below [`TRACKED_BELOW`] on the arcs
    /// that search kept (the others keep a gap of at least `CLEARANCE −
    /// TRACK`); otherwise a full search for the minima below
    /// [`CLEARANCE`], kept for the poses after it, whose bound is the least
    /// of its dropped arcs' floors (at least `CLEARANCE`).
    fn minima_tracked(
        &mut self,
        pair: Pair,
        x: &SVector<f64, 7>,
        p: &SVector<f64, 16>,
    ) -> (Angles, f64) {
        let mut out = Angles::new();
        self.work = Work::default();
        if let Some(t) = &self.tracked {
            if moved_within(pair, p, (&t.pose, x), t.windowed, TRACK) {
                if let (Problem::Search { h, level }, window) =
                    Problem::with_window(pair, x, p, TRACKED_BELOW)
                {
                    self.work = certified::minima_on(
                        &h,
                        level,
                        window.as_ref(),
                        (&t.kept, &t.profile),
                        &mut out,
                    );
                }
                self.work.tracked = true;
                // The arcs the record's window dropped are still out of it
                // by more than `CLEARANCE − TRACK`.
                if t.windowed {
                    minimum::lower(&mut self.work.window_floor, CLEARANCE - TRACK);
                }
                return (out, TRACKED_BELOW);
            }
        }
        let (h, level, window) = match Problem::with_window(pair, x, p, CLEARANCE) {
            (Problem::Search { h, level }, window) => (h, level, window),
            (Problem::Off(by), _) => {
                // No valid contact while the circle keeps off the face.
                self.tracked = None;
                self.work.window_floor = Some(by);
                return (out, by);
            }
            (Problem::Invalid(least), _) => {
                // The one minimum is no contact; every gap is at least its.
                self.tracked = None;
                return (out, least);
            }
            // The plane pairs' closed form, or nothing below the clearance.
            (problem, _) => {
                self.tracked = None;
                return (self.minima_of(problem), CLEARANCE);
            }
        };
        let mut kept = certified::Kept::default();
        self.work = certified::minima_kept(&h, level, window.as_ref(), &mut out, &mut kept);
        let windowed = self.work.windowed();
        self.tracked = kept.complete.then_some(Tracked {
            pose: *x,
            profile: h,
            kept,
            windowed,
        });
        // Every local minimum off the dropped arcs was found: the gap is at
        // least the dropped arcs' floors there.
        let floor = self
            .work
            .floor
            .map_or(f64::INFINITY, |h| profile::gap_at_least(pair, p, h));
        (
            out,
            floor.min(self.work.window_floor.unwrap_or(f64::INFINITY)),
        )
    }

    /// The penetrating, valid local minima of `pair`'s gap at pose `x`
    /// (unit quaternion), appended to `out` with the cols of
    /// [`merge::assign`].
    ///
    /// The search also finds the minima below [`CLEARANCE`]: when none
    /// penetrates and every arc was decided by its enclosures (no leaf:
    /// [`Work::leaves`]), their least gap, and on the arcs dropped the
    /// least lower bound of the gap there ([`Work::floor`], at least
    /// `CLEARANCE`) and of the distance out of the window
    /// ([`Work::window_floor`]), bound from below the gap of every point
    /// of the circle that can be a contact (the circle's least gap is a
    /// local minimum: one found, or one on a dropped arc); later calls at
    /// poses that moved less than that return at once with no contact (a
    /// body point moves by at most `|Δp| + 2|Δq| |b_B|`). A search from a
    /// tracked record bounds the rest of the circle by `TRACKED_BELOW`
    /// only.
    pub fn find(
        &mut self,
        pair: Pair,
        prm: &Peg3dParams,
        x: &SVector<f64, 7>,
        p: &SVector<f64, 16>,
        out: &mut Contacts,
    ) {
        if let Some(c) = self.clear
            && moved_within(pair, p, (&c.pose, x), c.windowed, c.margin)
        {
            self.work = Work {
                cached: true,
                ..Work::default()
            };
            return;
        }
        let (minima, mut lowest) = self.minima_tracked(pair, x, p);
        let axis = axis_of(x);
        let first = out.len();
        for &a in &minima {
            let (a, e) = polish(pair, x, p, a);
            lowest = lowest.min(e.gap);
            if e.gap < 0.0
                && pair.valid(prm, &axis, &e.normal, &e.point, e.axial)
                && pair.rim_faces_out(x, &e.normal, &e.point)
            {
                let point = ContactPoint {
                    pair,
                    angle: a,
                    penetration: -e.gap,
                    gradient: e.grad,
                    normal: e.normal,
                    point: e.point,
                    saddle: None,
                    ring: false,
                };
                if out.try_push(point).is_err() {
                    self.work.unresolved += 1;
                }
            }
        }
        // Apart (every minimum found, none below zero): certified clear.
        // A search that ended in a leaf (a flat stretch, its slope below
        // rounding) found its minima to the resolution of `f64` only: it
        // certifies nothing, and the next pose is searched again.
        let certain = self.work.unresolved == 0 && !self.work.flat && self.work.leaves == 0;
        self.clear = (certain && lowest > 0.0 && lowest.is_finite()).then_some(Clear {
            pose: *x,
            margin: lowest * (1.0 - 1e-9),
            windowed: self.work.windowed(),
        });
        // The record this search made or started from: off its kept arcs
        // (when none was dropped by the window) the gap is at least
        // `CLEARANCE − TRACK` > 0, so a col there is out of contact.
        let tracked = self.tracked.as_ref().filter(|t| !t.windowed);
        let apart = |a: f64| tracked.is_some_and(|t| !t.kept.covers(a));
        merge::assign(pair, x, p, &mut out[first..], apart);
    }
}
