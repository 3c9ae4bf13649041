//! A kept arc's decision carried to a nearby pose: how far the profile's
//! value and first two derivatives can have moved over the arc, from the
//! change of the profile's coefficients, against the margins by which the
//! arc's enclosures decided it.
//!
//! A search from a tracked record ([`super::certified::minima_on`])
//! visits the arcs the record's full search kept. Each was kept because
//! its enclosures at the record's pose showed it monotone (`h′` of one
//! sign), concave (`h″ < 0`) or convex (`h″ > 0`). Where the profile at
//! the new pose differs from the record's by at most `D₀, D₁, D₂` in `h,
//! h′, h″` over the arc, the old enclosures widened by those contain the
//! new values, and the decision stands while its margin exceeds the
//! widening: the arc needs no enclosure at the new pose (a convex arc
//! still needs its end slopes and Newton for its minimum).
//!
//! **Trigonometric profiles.** `h` is linear in its coefficients, so the
//! change is the trigonometric polynomial of the coefficients'
//! differences `Δ`, with amplitudes `ν₁ = |(Δa₁, Δb₁)|`, `ν₂ = |(Δa₂,
//! Δb₂)|`: `D₀ = |Δa₀| + ν₁ + ν₂`, `D₁ = ν₁ + 2ν₂`, `D₂ = ν₁ + 4ν₂` over
//! the whole circle.
//!
//! **The rim on the mouth edge**, `h = Φ₀(F, Z) = (√F − R_m)² + Z²`, with
//! `F` and `Z` trigonometric (their changes bounded as above by `E_k` and
//! `G_k`): by the mean value theorem on each derivative as a function of
//! `(F, F′, F″, Z, Z′, Z″)`,
//!
//! ```text
//! h′ = Φ₁ = F′ (1 − R/ρ) + 2 Z Z′
//! h″ = Φ₂ = F″ (1 − R/ρ) + R F′²/(2ρ³) + 2 Z′² + 2 Z Z″      (ρ = √F)
//! D₀ = K E₀ + 2|Z| G₀
//! D₁ = K E₁ + R|F′|/(2ρ³) E₀ + 2|Z′| G₀ + 2|Z| G₁
//! D₂ = K E₂ + R|F′|/ρ³ E₁ + (R|F″|/(2ρ³) + 3R F′²/(4ρ⁵)) E₀
//!      + 2|Z″| G₀ + 4|Z′| G₁ + 2|Z| G₂
//! ```
//!
//! with `K = max|1 − R/ρ|` and every magnitude the largest over the box of
//! the arc's old enclosures of `F, F′, F″, Z, Z′, Z″` widened by `E_k`,
//! `G_k` (which holds both poses' values, and so the segment between
//! them); none where that box reaches `F ≤ 0`.
//!
//! The sums of non-negative terms are widened by `10⁻⁹` of themselves for
//! their rounding.

use super::interval::{Iv, down};
use super::profile::Profile;
use super::trig::{Enclosure, Trig2, amplitude};

/// How a kept arc was decided at the record's pose.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// `h′` kept one sign: no stationary point.
    Monotone,
    /// `h″ < 0`: a stationary point is a maximum.
    Concave,
    /// `h″ > 0`: at most one minimum, found from the end slopes.
    Convex,
    /// A leaf, or cut by a higher derivative: decided again.
    Other,
}

/// A kept arc's decision and the enclosures that made it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Note {
    /// How the arc was decided.
    pub kind: Kind,
    /// The enclosures of `h`, `h′`, `h″` over the arc.
    pub h: Enclosure,
    /// For the rim on the mouth edge, those of `F` and `Z` over the arc.
    pub parts: Option<(Enclosure, Enclosure)>,
}

/// The bounds `(Δ₀, Δ₁, Δ₂)` on the change of a trigonometric polynomial
/// of degree two and its first two derivatives, from the change of its
/// coefficients.
fn changes(old: &Trig2, new: &Trig2) -> [f64; 3] {
    let (d0, d1, e1, d2, e2) = (
        new.a0 - old.a0,
        new.a1 - old.a1,
        new.b1 - old.b1,
        new.a2 - old.a2,
        new.b2 - old.b2,
    );
    let (n1, n2) = (amplitude(d1, e1), amplitude(d2, e2));
    [
        widen(d0.abs() + n1 + n2),
        widen(n1 + 2.0 * n2),
        widen(n1 + 4.0 * n2),
    ]
}

/// A sum of non-negative terms widened for its rounding.
fn widen(v: f64) -> f64 {
    v * (1.0 + 1e-9) + f64::MIN_POSITIVE
}

/// How far one pose's profile can be from another's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shift {
    /// A trigonometric profile: `(D₀, D₁, D₂)` over the whole circle.
    Trig([f64; 3]),
    /// The rim on the mouth edge: the changes `E` of `F` and `G` of `Z`
    /// (and their derivatives), and `R_m`.
    Tori {
        /// Bounds on the change of `F`, `F′`, `F″`.
        e: [f64; 3],
        /// Bounds on the change of `Z`, `Z′`, `Z″`.
        g: [f64; 3],
        /// `R_m` (m).
        rm: f64,
    },
}

impl Shift {
    /// The shift from the profile `old` to `new` (of the same pair), or
    /// `None` where they are not of one kind.
    pub fn between(old: &Profile, new: &Profile) -> Option<Shift> {
        match (old, new) {
            (Profile::Trig(a), Profile::Trig(b)) => Some(Shift::Trig(changes(&a.f, &b.f))),
            (
                Profile::Tori { f: fa, z: za, rm },
                Profile::Tori {
                    f: fb,
                    z: zb,
                    rm: rb,
                },
            ) if rm == rb => Some(Shift::Tori {
                e: changes(&fa.f, &fb.f),
                g: changes(&za.f, &zb.f),
                rm: *rm,
            }),
            _ => None,
        }
    }

    /// `(D₀, D₁, D₂)` over the arc of `note` (the module's bounds), or
    /// `None` where they cannot be had.
    pub fn over(&self, note: &Note) -> Option<[f64; 3]> {
        match *self {
            Shift::Trig(d) => Some(d),
            Shift::Tori { e, g, rm } => {
                let (fe, ze) = note.parts?;
                let box_of = |x: Iv, by: f64| Iv::new(x.lo - by, x.hi + by);
                let (f0, f1, f2) = (
                    box_of(fe.value, e[0]),
                    box_of(fe.d1, e[1]),
                    box_of(fe.d2, e[2]),
                );
                let (z0, z1, z2) = (
                    box_of(ze.value, g[0]).mag(),
                    box_of(ze.d1, g[1]).mag(),
                    box_of(ze.d2, g[2]).mag(),
                );
                let f_lo = down(f0.lo);
                if f_lo <= 0.0 || !f0.hi.is_finite() {
                    return None;
                }
                let (rho_lo, rho_hi) = (down(f_lo.sqrt()), f0.hi.sqrt() * (1.0 + 1e-15));
                // |1 − R/ρ| at its ends, and the rounding of the difference.
                let k = (1.0 - rm / rho_lo).abs().max((1.0 - rm / rho_hi).abs())
                    + 4.0 * f64::EPSILON * (1.0 + rm / rho_lo);
                let (a1, a2) = (f1.mag(), f2.mag());
                let r3 = rm / (rho_lo * rho_lo * rho_lo);
                let r5 = r3 / (rho_lo * rho_lo);
                let d0 = k * e[0] + 2.0 * z0 * g[0];
                let d1 = k * e[1] + 0.5 * r3 * a1 * e[0] + 2.0 * z1 * g[0] + 2.0 * z0 * g[1];
                let d2 = k * e[2]
                    + r3 * a1 * e[1]
                    + (0.5 * r3 * a2 + 0.75 * r5 * a1 * a1) * e[0]
                    + 2.0 * z2 * g[0]
                    + 4.0 * z1 * g[1]
                    + 2.0 * z0 * g[2];
                let d = [widen(d0), widen(d1), widen(d2)];
                d.iter().all(|v| v.is_finite()).then_some(d)
            }
        }
    }
}

/// What a kept arc's decision says at the new pose, `d` the bounds of
/// [`Shift::over`] and `level` the search's level.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Carried {
    /// `h ≥ level` on the arc: dropped, with this lower bound of `h`.
    Above(f64),
    /// No minimum on the arc (monotone or concave still).
    Clear,
    /// Convex still: its one minimum, if any, from the end slopes.
    Convex,
    /// The margins do not cover the change: decide the arc afresh.
    Afresh,
}

/// The decision of `note` carried by the change bounds `d` at `level`.
pub fn carry(note: &Note, d: [f64; 3], level: f64) -> Carried {
    let h = &note.h;
    let floor = h.value.lo - d[0];
    if floor >= level {
        return Carried::Above(floor);
    }
    match note.kind {
        Kind::Monotone if h.d1.lo - d[1] > 0.0 || h.d1.hi + d[1] < 0.0 => Carried::Clear,
        Kind::Concave if h.d2.hi + d[2] < 0.0 => Carried::Clear,
        Kind::Convex if h.d2.lo - d[2] > 0.0 => Carried::Convex,
        _ => Carried::Afresh,
    }
}
