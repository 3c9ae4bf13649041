//! Each pair's gap along its circle as a trigonometric polynomial of the
//! angle (or, for the rim on the mouth, a function of two of them), built
//! once per pose: the functions the certified search bounds.
//!
//! With the pose's rotation `R = (e₁ e₂ a)` and `ϱ = r − ρ_p`, the rim's
//! tube-centre circle is `c(β) = c_r + ϱ (cos β e₁ + sin β e₂)`,
//! `c_r = p + (ρ_p − L/2) a`, and the mouth's is
//! `m(α) = R_m (cos α, sin α, 0) − ρ_h e_z`, `R_m = R + ρ_h`.
//!
//! - **Rim against a plane** `z = z₀`: `g(β) = c_z(β) − ρ_p − z₀`, a
//!   sinusoid `c_{r,z} + ϱ (e₁,z cos β + e₂,z sin β) − ρ_p − z₀` with its
//!   one minimum at `(cos β, sin β) = −(e₁,z, e₂,z)/|(e₁,z, e₂,z)|`.
//! - **Rim against the bore wall**: `g = R − ρ_p − √F(β)`,
//!   `F = |c_xy|²`, a trigonometric polynomial of degree two:
//!   `F = |c_{r,xy}|² + ϱ²(1 + a_z²)/2 + 2ϱ (c_{r,xy}·e₁ cos β + c_{r,xy}·e₂
//!   sin β) + ϱ²((e₂,z² − e₁,z²)/2 cos 2β − e₁,z e₂,z sin 2β)`
//!   (with `|e_{i,xy}|² = 1 − e_{i,z}²` and `e₁·e₂ = 0`). The minima of `g`
//!   are the maxima of `F`: the search minimizes `h = −F`, and `g < g_b`
//!   exactly where `h < −(R − ρ_p − g_b)²`.
//! - **Mouth edge against the peg's side** (the axis line `p + t a`):
//!   `g = √F(α) − r − ρ_h`, `F = |u|² − (u·a)²`, `u = m(α) − p`:
//!   with `o = −ρ_h e_z − p`,
//!   `F = |o × a|² + R_m²(a_z² + (a_x² + a_y²)/2) + 2R_m((o_x − (o·a) a_x)
//!   cos α + (o_y − (o·a) a_y) sin α) − R_m²((a_x² − a_y²)/2 cos 2α +
//!   a_x a_y sin 2α)`. `h = F`, `g < g_b` where `h < (r + ρ_h + g_b)²`.
//! - **Rim against the mouth edge** (two tori): `g = √h − ρ_p − ρ_h`,
//!   `h(β) = (ρ − R_m)² + Z²` with `ρ = √F(β)` (the bore wall's `F`) and
//!   `Z = c_z + ρ_h` a sinusoid;
//!
//!   ```text
//!   h′ = F′ (1 − R_m/ρ) + 2 Z Z′
//!   h″ = F″ (1 − R_m/ρ) + R_m F′²/(2ρ³) + 2 Z′² + 2 Z Z″
//!   ```
//!
//!   and `g < g_b` where `h < (ρ_p + ρ_h + g_b)²`.
//!
//! In each case `g` is an increasing function of `h` wherever `g` is
//! smooth, so the local minima of `g` are those of `h`, at the same angles.

use super::interval::Iv;
use super::start;
use super::tori;
use super::trig::{Bounded, Enclosure, Trig2, amplitude};
use crate::compliant_peg_3d::contact::Pair;
use nalgebra::SVector;

/// The function of one angle whose local minima are a pair's contacts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Profile {
    /// A trigonometric polynomial `h` of degree two.
    Trig(Bounded),
    /// The rim against the mouth edge: `h = (√F − R_m)² + Z²`.
    Tori {
        /// `F = |c_xy|²` of the rim circle.
        f: Bounded,
        /// `Z = c_z + ρ_h` of the rim circle (first harmonic only).
        z: Bounded,
        /// `R_m = R + ρ_h` (m).
        rm: f64,
    },
}

/// Where a pair's contacts can be valid, as a coordinate along its circle:
/// the tube centre's height `c_z(β)` of the rim against the bore wall
/// (the wall spans `−h_b ≤ z ≤ −ρ_h`), the axial coordinate `(m(α) − p)·a`
/// of the mouth edge against the peg's side (the side spans `ρ_p − L/2 ≤
/// t ≤ L/2`). Both are sinusoids of the angle. An arc on which `t` keeps
/// out of `[lo, hi]` holds no valid contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    /// The coordinate `t(θ)` (m), first harmonic only.
    pub t: Bounded,
    /// The least valid `t` (m).
    pub lo: f64,
    /// The greatest valid `t` (m).
    pub hi: f64,
    /// How far out of `[lo, hi]` (m) `t` must keep for an arc to be
    /// dropped (the level's gap of the search).
    pub margin: f64,
}

impl Window {
    /// The window of the coordinate `t` on `[lo, hi]`, dropping what keeps
    /// more than `margin` out of it; `None` where `t` stays within
    /// `margin` of the range all round the circle (its range `a₀ ± n₁`):
    /// such a window could drop no arc, and no window (which only ever
    /// drops arcs) is always safe.
    fn new(t: Trig2, lo: f64, hi: f64, margin: f64) -> Option<Window> {
        let amp = amplitude(t.a1, t.b1);
        if t.a0 - amp >= lo - margin && t.a0 + amp <= hi + margin {
            return None;
        }
        Some(Window {
            t: t.bounded(),
            lo,
            hi,
            margin,
        })
    }

    /// When `t` keeps more than the margin out of the window over `|θ −
    /// m| ≤ w`, `(c, s)` the cosine and sine of `m`: a lower bound on how
    /// far (m) it keeps out (less a rounding allowance).
    pub fn outside(&self, c: f64, s: f64, w: f64) -> Option<f64> {
        let v = self.t.enclose(c, s, w).value;
        let out = (v.lo - self.hi).max(self.lo - v.hi);
        if out <= self.margin {
            return None;
        }
        let ends = self.lo.abs().max(self.hi.abs());
        Some(out * (1.0 - 1e-12) - 8.0 * f64::EPSILON * ends)
    }
}

/// A lower bound on `pair`'s gap (m) where its profile `h` is at least
/// `h_lo` (the inverse of the levels of [`Problem::of`], widened by a few
/// ulps of the body's size).
pub fn gap_at_least(pair: Pair, p: &SVector<f64, 16>, h_lo: f64) -> f64 {
    let (r, rho_p, big_r, rho_h) = (p[0], p[2], p[3], p[4]);
    let root = |h: f64| h.max(0.0).sqrt();
    let (gap, size) = match pair {
        Pair::RimWall => (big_r - rho_p - root(-h_lo), big_r),
        Pair::EdgeSide => (root(h_lo) - r - rho_h, big_r + rho_h),
        Pair::RimEdge => (root(h_lo) - rho_p - rho_h, rho_p + rho_h),
        // The plane pairs' one minimum is in closed form: no profile.
        Pair::RimTop | Pair::RimBottom => return f64::NEG_INFINITY,
    };
    gap - gap.abs() * 1e-12 - 16.0 * f64::EPSILON * size
}

/// How far (m) every point of the rim's tube-centre circle keeps
/// horizontally out of the part of `pair`'s plane that exists, when it
/// does: the top face is valid at radii `≥ R + ρ_h` (outside the mouth's
/// round), the bottom at radii `≤ R` ([`Pair::valid`]). The contact point
/// of the rim on a plane lies under its tube centre, at the radius `√F`;
/// `F = |c_xy|²` keeps within `a₀ ± (n₁ + n₂)`. `None` where the circle
/// may reach the face.
fn off_face(pair: Pair, f: &Trig2, big_r: f64, rho_h: f64) -> Option<f64> {
    let (n1, n2) = f.amplitudes();
    // The range's rounding: a few ulps of its terms.
    let slack = 1e-12 * (f.a0.abs() + n1 + n2);
    let out = match pair {
        Pair::RimTop => {
            let edge = big_r + rho_h;
            edge - (f.a0 + n1 + n2 + slack).max(0.0).sqrt()
        }
        Pair::RimBottom => (f.a0 - n1 - n2 - slack).max(0.0).sqrt() - big_r,
        _ => return None,
    };
    let by = out * (1.0 - 1e-12) - 16.0 * f64::EPSILON * (big_r + rho_h);
    (by > 0.0).then_some(by)
}

/// Whether the rim's tube centre at the angle of cosine and sine `(c, s)`
/// lies clearly (by `10⁻⁹` of the radius) off the part of `pair`'s plane
/// that exists (see [`off_face`]): its radius `√F` inside the top face's
/// `R + ρ_h`, or outside the bottom's `R`.
fn off_face_at(pair: Pair, f: &Trig2, (c, s): (f64, f64), big_r: f64, rho_h: f64) -> bool {
    let radial = f.at(c, s)[0].max(0.0).sqrt();
    match pair {
        Pair::RimTop => radial < (big_r + rho_h) * (1.0 - 1e-9),
        Pair::RimBottom => radial > big_r * (1.0 + 1e-9),
        _ => false,
    }
}

/// The level `T` of a pair's profile: `h < T` exactly where `g < below`
/// (m); `None` for the plane pairs (no profile), and for the others where
/// no point has a gap below `below` (the sum of the tubes' radii and
/// `below` not positive). The bore wall's `h = −F` is below every level
/// when `R − ρ_p − below ≤ 0`: its level is then `+∞`.
fn level(pair: Pair, p: &SVector<f64, 16>, below: f64) -> Option<f64> {
    let (r, rho_p, big_r, rho_h) = (p[0], p[2], p[3], p[4]);
    let positive = |v: f64| if v > 0.0 { Some(v * v) } else { None };
    match pair {
        Pair::RimWall => Some(positive(big_r - rho_p - below).map_or(f64::INFINITY, |v| -v)),
        Pair::EdgeSide => positive(r + rho_h + below),
        Pair::RimEdge => positive(rho_p + rho_h + below),
        Pair::RimTop | Pair::RimBottom => None,
    }
}

/// A pair's search problem at one pose: its profile `h` and the level
/// below which a minimum of `h` is a minimum of `g` below the asked
/// bound; or, for the plane pairs, the one minimum in closed form.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Problem {
    /// Find the minima of `h` below `level`.
    Search {
        /// The profile.
        h: Profile,
        /// The level `T`.
        level: f64,
    },
    /// The sinusoid's one minimum (rad), or `None` for a constant.
    Closed(Option<f64>),
    /// No point of the circle comes below the bound.
    Nothing,
    /// No point of the circle is over the part of its plane that exists
    /// (the block's top face outside the mouth's round, the bore's bottom
    /// inside its wall): every tube-centre point keeps out of it
    /// horizontally by at least this much (m). Only for the contact path
    /// ([`Problem::with_window`]).
    Off(f64),
    /// The plane's one minimum lies off the part of the plane that exists:
    /// no contact; every point's gap is at least this much (m, the
    /// minimum's, less its rounding). Only for the contact path.
    Invalid(f64),
}

/// `(e₁, e₂, a)`: the columns of the rotation matrix of the unit
/// quaternion `x[3..7]` (the generated functions' matrix).
fn columns(x: &SVector<f64, 7>) -> [[f64; 3]; 3] {
    let (w, i, j, k) = (x[3], x[4], x[5], x[6]);
    [
        [
            1.0 - 2.0 * (j * j + k * k),
            2.0 * (i * j + w * k),
            2.0 * (i * k - w * j),
        ],
        [
            2.0 * (i * j - w * k),
            1.0 - 2.0 * (i * i + k * k),
            2.0 * (j * k + w * i),
        ],
        [
            2.0 * (i * k + w * j),
            2.0 * (j * k - w * i),
            1.0 - 2.0 * (i * i + j * j),
        ],
    ]
}

/// `F = |c_xy(β)|²` and `c_z(β)` of the rim's tube-centre circle.
fn rim(x: &SVector<f64, 7>, p: &SVector<f64, 16>) -> (Trig2, Trig2) {
    let [e1, e2, a] = columns(x);
    let (r, len, rho_p) = (p[0], p[1], p[2]);
    let rr = r - rho_p;
    let h = rho_p - 0.5 * len;
    let cr = [x[0] + h * a[0], x[1] + h * a[1], x[2] + h * a[2]];
    let f = Trig2 {
        a0: cr[0] * cr[0] + cr[1] * cr[1] + 0.5 * rr * rr * (1.0 + a[2] * a[2]),
        a1: 2.0 * rr * (cr[0] * e1[0] + cr[1] * e1[1]),
        b1: 2.0 * rr * (cr[0] * e2[0] + cr[1] * e2[1]),
        a2: 0.5 * rr * rr * (e2[2] * e2[2] - e1[2] * e1[2]),
        b2: -rr * rr * e1[2] * e2[2],
    };
    let z = Trig2 {
        a0: cr[2],
        a1: rr * e1[2],
        b1: rr * e2[2],
        a2: 0.0,
        b2: 0.0,
    };
    (f, z)
}

/// `F = |u|² − (u·a)²` of the mouth circle against the peg's axis line,
/// and the axial coordinate `u·a = o·a + R_m (a_x cos α + a_y sin α)` of
/// its points.
fn edge(x: &SVector<f64, 7>, p: &SVector<f64, 16>) -> (Trig2, Trig2) {
    let a = columns(x)[2];
    let (big_r, rho_h) = (p[3], p[4]);
    let rm = big_r + rho_h;
    let o = [-x[0], -x[1], -rho_h - x[2]];
    let oa = o[0] * a[0] + o[1] * a[1] + o[2] * a[2];
    let cx = [
        o[1] * a[2] - o[2] * a[1],
        o[2] * a[0] - o[0] * a[2],
        o[0] * a[1] - o[1] * a[0],
    ];
    let axy = a[0] * a[0] + a[1] * a[1];
    let f = Trig2 {
        a0: cx[0] * cx[0] + cx[1] * cx[1] + cx[2] * cx[2] + rm * rm * (a[2] * a[2] + 0.5 * axy),
        a1: 2.0 * rm * (o[0] - oa * a[0]),
        b1: 2.0 * rm * (o[1] - oa * a[1]),
        a2: -0.5 * rm * rm * (a[0] * a[0] - a[1] * a[1]),
        b2: -rm * rm * a[0] * a[1],
    };
    let axial = Trig2 {
        a0: oa,
        a1: rm * a[0],
        b1: rm * a[1],
        a2: 0.0,
        b2: 0.0,
    };
    (f, axial)
}

impl Problem {
    /// The search problem of `pair` at pose `x` (unit quaternion) for the
    /// minima of the gap below `below` (m), `p` the generated functions'
    /// parameter vector.
    pub fn of(pair: Pair, x: &SVector<f64, 7>, p: &SVector<f64, 16>, below: f64) -> Problem {
        Problem::build(pair, x, p, below, false).0
    }

    /// [`Problem::of`] and, for the contact path, the pair's [`Window`]
    /// dropping what keeps more than `below` out of the existing part of
    /// its surface: the rim's tube-centre height against the bore wall's
    /// `[−h_b, −ρ_h]`, the mouth edge's axial coordinate against the
    /// side's `[ρ_p − L/2, L/2]` (built from the same coefficients).
    pub fn with_window(
        pair: Pair,
        x: &SVector<f64, 7>,
        p: &SVector<f64, 16>,
        below: f64,
    ) -> (Problem, Option<Window>) {
        Problem::build(pair, x, p, below, true)
    }

    fn build(
        pair: Pair,
        x: &SVector<f64, 7>,
        p: &SVector<f64, 16>,
        below: f64,
        windowed: bool,
    ) -> (Problem, Option<Window>) {
        let (len, rho_p, big_r, rho_h, depth) = (p[1], p[2], p[3], p[4], p[5]);
        let window = |t, lo, hi| {
            if windowed {
                Window::new(t, lo, hi, below)
            } else {
                None
            }
        };
        match pair {
            Pair::RimTop | Pair::RimBottom => {
                let (f, z) = rim(x, p);
                if windowed && let Some(by) = off_face(pair, &f, big_r, rho_h) {
                    return (Problem::Off(by), None);
                }
                let plane = if pair == Pair::RimTop { 0.0 } else { -depth };
                let amp = amplitude(z.a1, z.b1);
                let least = z.a0 - amp - rho_p - plane;
                if least >= below {
                    return (Problem::Nothing, None);
                }
                // The minimum's direction (a rim level to rounding has none
                // to trust).
                let norm = (z.a1 * z.a1 + z.b1 * z.b1).sqrt();
                if windowed
                    && norm > 1e-140
                    && off_face_at(pair, &f, (-z.a1 / norm, -z.b1 / norm), big_r, rho_h)
                {
                    let size = z.a0.abs() + amp + rho_p + plane.abs();
                    return (Problem::Invalid(least - 1e-12 * size), None);
                }
                let tilted = z.a1 != 0.0 || z.b1 != 0.0;
                let angle =
                    tilted.then(|| f64::atan2(-z.b1, -z.a1).rem_euclid(std::f64::consts::TAU));
                (Problem::Closed(angle), None)
            }
            Pair::RimWall => {
                let (f, z) = rim(x, p);
                let level = level(pair, p, below).unwrap_or(f64::INFINITY);
                let h = Profile::Trig((-f).bounded());
                (Problem::Search { h, level }, window(z, -depth, -rho_h))
            }
            Pair::EdgeSide => match level(pair, p, below) {
                Some(level) => {
                    let (f, axial) = edge(x, p);
                    let h = Profile::Trig(f.bounded());
                    let side = window(axial, rho_p - 0.5 * len, 0.5 * len);
                    (Problem::Search { h, level }, side)
                }
                None => (Problem::Nothing, None),
            },
            Pair::RimEdge => match level(pair, p, below) {
                Some(level) => {
                    let (f, mut z) = rim(x, p);
                    z.a0 += rho_h;
                    let h = Profile::Tori {
                        f: f.bounded(),
                        z: z.bounded(),
                        rm: big_r + rho_h,
                    };
                    (Problem::Search { h, level }, None)
                }
                None => (Problem::Nothing, None),
            },
        }
    }
}

impl Profile {
    /// `(h′, h″)` at angle `t` (rad).
    pub fn slope(&self, t: f64) -> (f64, f64) {
        let (s, c) = start::sin_cos(t);
        match self {
            Profile::Trig(f) => {
                let [_, d1, d2] = f.f.at(c, s);
                (d1, d2)
            }
            Profile::Tori { f, z, rm } => tori::slope(f, z, *rm, c, s),
        }
    }

    /// For the rim on the mouth edge, the enclosures of `F` and `Z` over
    /// `|θ − m| ≤ w` (those [`Profile::enclose`] combines), `(c, s)` the
    /// cosine and sine of `m`; `None` for a trigonometric profile.
    pub fn parts(&self, c: f64, s: f64, w: f64) -> Option<(Enclosure, Enclosure)> {
        match self {
            Profile::Trig(_) => None,
            Profile::Tori { f, z, .. } => Some((f.enclose(c, s, w), z.enclose(c, s, w))),
        }
    }

    /// Enclosures of `h, h′, …, h⁗` at the angle `t` (rad), or `None`
    /// where they cannot be bounded (the rim's circle through the hole's
    /// axis).
    pub fn point(&self, t: f64) -> Option<[Iv; 5]> {
        let (s, c) = start::sin_cos(t);
        match self {
            Profile::Trig(f) => Some(f.point(c, s)),
            Profile::Tori { f, z, rm } => tori::jet(&f.point(c, s), &z.point(c, s), *rm),
        }
    }

    /// Enclosures of `h, h′, …, h⁗` over `|θ − m| ≤ w`, `(c, s)` the
    /// cosine and sine of `m` (natural extensions), or `None` where they
    /// cannot be bounded.
    pub fn arc(&self, c: f64, s: f64, w: f64) -> Option<[Iv; 5]> {
        match self {
            Profile::Trig(f) => Some(f.arc(c, s, w)),
            Profile::Tori { f, z, rm } => tori::jet(&f.arc(c, s, w), &z.arc(c, s, w), *rm),
        }
    }

    /// Enclosures of `h`, `h′`, `h″` over `|θ − m| ≤ w`, `(c, s)` the
    /// cosine and sine of `m` ([`Bounded::enclose`], [`tori::enclose`];
    /// the derivatives may be left unbounded where the value is at least
    /// `level`).
    pub fn enclose(&self, c: f64, s: f64, w: f64, level: f64) -> Enclosure {
        match self {
            Profile::Trig(f) => f.enclose(c, s, w),
            Profile::Tori { f, z, rm } => tori::enclose(f, z, *rm, c, s, w, level),
        }
    }
}
