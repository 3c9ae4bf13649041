//! Enclosures of the rim-on-mouth profile `h = (ρ − R_m)² + Z²`,
//! `ρ = √F`, over an arc, from those of the trigonometric polynomials `F`
//! and `Z` ([`Bounded::enclose`]).
//!
//! The natural interval extension of
//!
//! ```text
//! h′ = F′ (1 − R_m/ρ) + 2 Z Z′
//! h″ = F″ (1 − R_m/ρ) + R_m F′²/(2ρ³) + 2 Z′² + 2 Z Z″
//! ```
//!
//! overestimates by the size of its terms, which cancel near a shallow
//! minimum. So the second derivative is taken in centred form,
//! `h″(θ) ∈ h″(m) ± w H₃`, with a bound `H₃ ≥ |h‴|` over the arc: from
//! `h = (ρ − R_m)² + Z²`,
//!
//! ```text
//! h‴ = 2(ρ − R_m) ρ‴ + 6 ρ′ρ″ + 6 Z′Z″ + 2 Z Z‴
//! ρ′ = F′/(2ρ),  ρ″ = F″/(2ρ) − F′²/(4ρ³),
//! ρ‴ = F‴/(2ρ) − 3F′F″/(4ρ³) + 3F′³/(8ρ⁵)
//! ```
//!
//! bounded term by term with `ρ ≥ ρ_lo > 0`, `|F′| ≤ A₁`, `|F″| ≤ A₂`
//! (the arc's enclosures), `|F‴| ≤ M₃(F)`, `|Z‴| ≤ M₃(Z)`. Then
//! `h′(θ) ∈ h′(m) ± w max|h″|` and `h(θ) ≥ h(m) − |h′(m)| w + min(h″, 0)
//! w²/2` (Taylor with the Lagrange remainder), each intersected with the
//! natural extension. The values at the centre `m` are enclosed by the same
//! formulas on the point enclosures of `F` and `Z` (width: rounding).
//!
//! [`jet`] encloses `h` and its first four derivatives from those of `F`
//! and `Z` (at a point or over an arc), by differentiating `ρ² = F` and
//! `h = (ρ − R_m)² + Z²`:
//!
//! ```text
//! 2ρ ρ′ = F′,  2ρ ρ″ = F″ − 2ρ′²,  2ρ ρ‴ = F‴ − 6ρ′ρ″,
//! 2ρ ρ⁗ = F⁗ − 6ρ″² − 8ρ′ρ‴,
//! h‴ = 6ρ′ρ″ + 2(ρ − R_m)ρ‴ + 6Z′Z″ + 2ZZ‴,
//! h⁗ = 6ρ″² + 8ρ′ρ‴ + 2(ρ − R_m)ρ⁗ + 6Z″² + 8Z′Z‴ + 2ZZ⁗.
//! ```

use super::interval::{Iv, up};
use super::trig::{Bounded, Enclosure};

/// `ρ = √F` and `h = (ρ − R_m)² + Z²` from the enclosures of `F` and `Z`.
fn value(fe: &Enclosure, ze: &Enclosure, rm: f64) -> (Iv, Iv) {
    let rho = fe.value.sqrt();
    (rho, rho.plus(-rm).square() + ze.value.square())
}

/// `(h, Some((h′, h″, ρ)))` by the natural extension, `(h, None)` where
/// `F` may vanish.
fn natural(fe: &Enclosure, ze: &Enclosure, rm: f64) -> (Iv, Option<(Iv, Iv, Iv)>) {
    let (rho, value) = value(fe, ze, rm);
    natural_from(fe, ze, rm, rho, value)
}

/// [`natural`] with `ρ` and `h` of [`value`] already computed.
fn natural_from(
    fe: &Enclosure,
    ze: &Enclosure,
    rm: f64,
    rho: Iv,
    value: Iv,
) -> (Iv, Option<(Iv, Iv, Iv)>) {
    if fe.value.lo <= 0.0 {
        return (value, None);
    }
    // 1 − R_m/ρ and R_m/(2ρ³).
    let k = rho.recip_times(rm).scale(-1.0).plus(1.0);
    let q = (rho * rho * rho).recip_times(0.5 * rm);
    let d1 = fe.d1 * k + (ze.value * ze.d1).scale(2.0);
    let d2 =
        fe.d2 * k + fe.d1.square() * q + ze.d1.square().scale(2.0) + (ze.value * ze.d2).scale(2.0);
    (value, Some((d1, d2, rho)))
}

/// Enclosures of `h, h′, …, h⁗` from enclosures `f` of `F, …, F⁗` and
/// `z` of `Z, …, Z⁗` (the module's formulas in interval arithmetic);
/// `None` where `F` may vanish.
pub fn jet(f: &[Iv; 5], z: &[Iv; 5], rm: f64) -> Option<[Iv; 5]> {
    if f[0].lo <= 0.0 {
        return None;
    }
    let rho = f[0].sqrt();
    if rho.lo <= 0.0 {
        return None;
    }
    let inv = rho.recip_times(0.5);
    let r1 = f[1] * inv;
    let r2 = (f[2] - r1.square().scale(2.0)) * inv;
    let r3 = (f[3] - (r1 * r2).scale(6.0)) * inv;
    let r4 = (f[4] - r2.square().scale(6.0) - (r1 * r3).scale(8.0)) * inv;
    let u = rho.plus(-rm);
    let [z0, z1, z2, z3, z4] = *z;
    Some([
        u.square() + z0.square(),
        (u * r1 + z0 * z1).scale(2.0),
        (r1.square() + u * r2 + z1.square() + z0 * z2).scale(2.0),
        (r1 * r2 + z1 * z2).scale(6.0) + (u * r3 + z0 * z3).scale(2.0),
        (r2.square() + z2.square()).scale(6.0)
            + (r1 * r3 + z1 * z3).scale(8.0)
            + (u * r4 + z0 * z4).scale(2.0),
    ])
}

/// `(h′, h″)` at the angle of cosine `c` and sine `s`.
pub fn slope(f: &Bounded, z: &Bounded, rm: f64, c: f64, s: f64) -> (f64, f64) {
    let [f0, f1, f2] = f.f.at(c, s);
    let [z0, z1, z2] = z.f.at(c, s);
    let rho = f0.sqrt();
    let k = 1.0 - rm / rho;
    (
        f1 * k + 2.0 * z0 * z1,
        f2 * k + rm * f1 * f1 / (2.0 * rho * rho * rho) + 2.0 * z1 * z1 + 2.0 * z0 * z2,
    )
}

/// The enclosures of `h`, `h′`, `h″` over `|θ − m| ≤ w`, `(c, s)` the
/// cosine and sine of `m` (derivatives unbounded where `F` may vanish, or
/// not computed where the value is at least `level`).
pub fn enclose(f: &Bounded, z: &Bounded, rm: f64, c: f64, s: f64, w: f64, level: f64) -> Enclosure {
    let fe = f.enclose(c, s, w);
    let ze = z.enclose(c, s, w);
    // The value alone first: an arc above the level needs no more.
    let (rho, value) = value(&fe, &ze, rm);
    if value.lo >= level {
        return Enclosure {
            value,
            d1: Iv::ALL,
            d2: Iv::ALL,
            refinable: true,
        };
    }
    let (value, arc) = natural_from(&fe, &ze, rm, rho, value);
    let centre = natural(&f.enclose_point(c, s), &z.enclose_point(c, s), rm);
    let (Some((n1, n2, rho)), (v0, Some((g1, g2, _)))) = (arc, centre) else {
        return Enclosure {
            value,
            d1: Iv::ALL,
            d2: Iv::ALL,
            refinable: true,
        };
    };
    let (a1, a2, a3) = (fe.d1.mag(), fe.d2.mag(), f.m3());
    let (b1, b2, b3) = (ze.d1.mag(), ze.d2.mag(), z.m3());
    let r = rho.lo;
    let p1 = a1 / (2.0 * r);
    let p2 = a2 / (2.0 * r) + a1 * a1 / (4.0 * r * r * r);
    let p3 =
        a3 / (2.0 * r) + 3.0 * a1 * a2 / (4.0 * r * r * r) + 3.0 * a1 * a1 * a1 / (8.0 * r.powi(5));
    // Sums and products of non-negative magnitudes: a relative allowance
    // covers their rounding.
    let h3 = up((2.0 * rho.plus(-rm).mag() * p3
        + 6.0 * p1 * p2
        + 6.0 * b1 * b2
        + 2.0 * ze.value.mag() * b3)
        * (1.0 + 64.0 * f64::EPSILON));
    let d2 = Iv::new(g2.lo - w * h3, g2.hi + w * h3).meet(n2);
    let d2 = Iv::new(d2.lo - up(d2.lo.abs() * 4.0 * f64::EPSILON), up(d2.hi));
    let slope = up(w * d2.mag());
    let d1 = Iv::new(g1.lo - slope, g1.hi + slope).meet(n1);
    let d1 = Iv::new(d1.lo - up(d1.lo.abs() * 4.0 * f64::EPSILON), up(d1.hi));
    let lower =
        v0.lo - up(g1.mag() * w) + d2.lo.min(0.0) * w * w * 0.5 * (1.0 + 4.0 * f64::EPSILON);
    let value = Iv::new(
        value.lo.max(lower - up(lower.abs() * 4.0 * f64::EPSILON)),
        value.hi,
    );
    Enclosure {
        value,
        d1,
        d2,
        refinable: slope > g1.hi - g1.lo,
    }
}
