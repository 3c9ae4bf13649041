//! Trigonometric polynomials of degree two in an angle, and enclosures of
//! them and their first two derivatives over an arc.
//!
//! ```text
//! f(θ) = a₀ + a₁ cos θ + b₁ sin θ + a₂ cos 2θ + b₂ sin 2θ
//! ```
//!
//! With the amplitudes `n₁ = |(a₁, b₁)|`, `n₂ = |(a₂, b₂)|` every
//! derivative is bounded by `|f⁽ʲ⁾| ≤ n₁ + 2ʲ n₂` (`j ≥ 1`), so over an
//! arc `|θ − m| ≤ w` Taylor's theorem with the Lagrange remainder gives,
//! with `M₃ = n₁ + 8 n₂` and `fⱼ = f⁽ʲ⁾(m)`,
//!
//! ```text
//! f(θ)   ∈ f₀ + {f₁ δ + f₂ δ²/2 : |δ| ≤ w} ± M₃ w³/6
//! f′(θ)  ∈ f₁ ± (|f₂| w + M₃ w²/2)
//! f″(θ)  ∈ f₂ ± M₃ w
//! ```
//!
//! The values `fⱼ` are computed in floating point from `cos m`, `sin m`
//! (each within an ulp) with a handful of operations, each term at most
//! the sum `Sⱼ` of the absolute coefficients (`2ʲ`-weighted for the second
//! harmonic, `a₀` only in `S₀`); their rounding error is below `8 u Sⱼ`
//! (`u = 2⁻⁵³`), and the enclosures add `64 u Sⱼ`.

use super::interval::{Iv, down, up};

/// The rounding allowance per unit of `Sⱼ` (`64 u`).
const ROUND: f64 = 32.0 * f64::EPSILON;

/// An upper bound on `√(a² + b²)`: the rounded root of the rounded sum
/// errs by under two ulps, and `10⁻¹⁵⁰` covers squares that underflow.
pub fn amplitude(a: f64, b: f64) -> f64 {
    (a * a + b * b).sqrt() * (1.0 + 4.0 * f64::EPSILON) + 1e-150
}

/// `a₀ + a₁ cos θ + b₁ sin θ + a₂ cos 2θ + b₂ sin 2θ`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Trig2 {
    /// Constant term.
    pub a0: f64,
    /// `cos θ` coefficient.
    pub a1: f64,
    /// `sin θ` coefficient.
    pub b1: f64,
    /// `cos 2θ` coefficient.
    pub a2: f64,
    /// `sin 2θ` coefficient.
    pub b2: f64,
}

/// Enclosures of a function and its first two derivatives over an arc.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Enclosure {
    /// The function's values.
    pub value: Iv,
    /// Its first derivative.
    pub d1: Iv,
    /// Its second derivative.
    pub d2: Iv,
    /// Whether a shorter arc can still narrow the slope's enclosure: false
    /// once the part that shrinks with the arc is below the rounding
    /// allowance (a flat stretch, such as two minima about to merge).
    pub refinable: bool,
}

impl std::ops::Neg for Trig2 {
    type Output = Trig2;

    /// `−f`.
    fn neg(self) -> Trig2 {
        Trig2 {
            a0: -self.a0,
            a1: -self.a1,
            b1: -self.b1,
            a2: -self.a2,
            b2: -self.b2,
        }
    }
}

impl Trig2 {
    /// `(f, f′, f″)` at the angle whose cosine and sine are `(c, s)`.
    #[inline]
    pub fn at(&self, c: f64, s: f64) -> [f64; 3] {
        let (c2, s2) = (c * c - s * s, 2.0 * c * s);
        let h1 = self.a1 * c + self.b1 * s;
        let h2 = self.a2 * c2 + self.b2 * s2;
        let k1 = self.b1 * c - self.a1 * s;
        let k2 = self.b2 * c2 - self.a2 * s2;
        [self.a0 + h1 + h2, k1 + 2.0 * k2, -h1 - 4.0 * h2]
    }

    /// `(f, f′, f″, f‴, f⁗)` at the angle whose cosine and sine are
    /// `(c, s)`: `f‴ = −k₁ − 8k₂`, `f⁗ = h₁ + 16h₂` with the harmonics
    /// `hⱼ` and their quadratures `kⱼ` of [`Trig2::at`].
    #[inline]
    pub fn jet(&self, c: f64, s: f64) -> [f64; 5] {
        let (c2, s2) = (c * c - s * s, 2.0 * c * s);
        let h1 = self.a1 * c + self.b1 * s;
        let h2 = self.a2 * c2 + self.b2 * s2;
        let k1 = self.b1 * c - self.a1 * s;
        let k2 = self.b2 * c2 - self.a2 * s2;
        [
            self.a0 + h1 + h2,
            k1 + 2.0 * k2,
            -h1 - 4.0 * h2,
            -k1 - 8.0 * k2,
            h1 + 16.0 * h2,
        ]
    }

    /// `(n₁, n₂)`: the amplitudes of the two harmonics, rounded up.
    pub fn amplitudes(&self) -> (f64, f64) {
        (amplitude(self.a1, self.b1), amplitude(self.a2, self.b2))
    }

    /// Whether the polynomial is constant (no harmonic).
    pub fn is_constant(&self) -> bool {
        self.a1 == 0.0 && self.b1 == 0.0 && self.a2 == 0.0 && self.b2 == 0.0
    }

    /// The rounding allowances `(e₀, …, e₄)` of `f`, …, `f⁗` computed by
    /// [`Trig2::at`] and [`Trig2::jet`] (`eⱼ = 64 u (S₁ + 2ʲ S₂)`, `a₀`
    /// in `e₀` only).
    fn rounding(&self) -> [f64; 5] {
        let s1 = self.a1.abs() + self.b1.abs();
        let s2 = self.a2.abs() + self.b2.abs();
        [
            ROUND * (self.a0.abs() + s1 + s2),
            ROUND * (s1 + 2.0 * s2),
            ROUND * (s1 + 4.0 * s2),
            ROUND * (s1 + 8.0 * s2),
            ROUND * (s1 + 16.0 * s2),
        ]
    }

    /// The polynomial with the constants of its enclosures.
    pub fn bounded(self) -> Bounded {
        let (n1, n2) = self.amplitudes();
        let [e0, e1, e2, _, _] = self.rounding();
        Bounded {
            f: self,
            m3: up(n1 + 8.0 * n2),
            n: (n1, n2),
            e: [e0, e1, e2],
        }
    }
}

/// A [`Trig2`] with its amplitudes `(n₁, n₂)` (the derivatives' bounds
/// `Mⱼ = n₁ + 2ʲ n₂`), the bound `M₃ ≥ |f‴|` and the rounding allowances
/// of its values, computed once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounded {
    /// The polynomial.
    pub f: Trig2,
    m3: f64,
    n: (f64, f64),
    e: [f64; 3],
}

impl Bounded {
    /// The bound `M₃ ≥ |f‴|` (`n₁ + 8 n₂`).
    pub fn m3(&self) -> f64 {
        self.m3
    }

    /// The enclosures of `f`, `f′`, `f″` over `|θ − m| ≤ w`, `(c, s)` the
    /// cosine and sine of `m` (see the module's inequalities).
    pub fn enclose(&self, c: f64, s: f64, w: f64) -> Enclosure {
        let [f0, f1, f2] = self.f.at(c, s);
        let [e0, e1, e2] = self.e;
        let m3 = self.m3;
        let rem0 = up(m3 * w * w * w / 6.0);
        // {f₁ δ + f₂ δ²/2 : |δ| ≤ w}: the ends and, inside, the vertex.
        let (qa, qb) = (-f1 * w + 0.5 * f2 * w * w, f1 * w + 0.5 * f2 * w * w);
        let (mut qlo, mut qhi) = (qa.min(qb), qa.max(qb));
        if f2 != 0.0 && (f1 / f2).abs() <= w {
            let v = -0.5 * f1 * f1 / f2;
            qlo = qlo.min(v);
            qhi = qhi.max(v);
        }
        // The quadratic's own rounding is a few ulps of its terms.
        let qe = ROUND * (f1.abs() * w + f2.abs() * w * w);
        let value = Iv::new(
            down(f0 + qlo - rem0 - e0 - qe),
            up(f0 + qhi + rem0 + e0 + qe),
        );
        let shrinks = f2.abs() * w + 0.5 * m3 * w * w;
        let r1 = up(shrinks + e1 + ROUND * f2.abs() * w);
        let r2 = up(m3 * w + e2);
        Enclosure {
            value,
            d1: Iv::around(f1, r1),
            d2: Iv::around(f2, r2),
            refinable: shrinks > e1,
        }
    }
}

impl Bounded {
    /// [`Bounded::enclose`] at `w = 0`, the angle alone: the arc's terms
    /// (the quadratic, its rounding, the slope's part that shrinks with
    /// the arc) are zero there and left out, which changes no bound.
    pub fn enclose_point(&self, c: f64, s: f64) -> Enclosure {
        let [f0, f1, f2] = self.f.at(c, s);
        let [e0, e1, e2] = self.e;
        let rem0 = up(0.0);
        Enclosure {
            value: Iv::new(down(f0 - rem0 - e0), up(f0 + rem0 + e0)),
            d1: Iv::around(f1, up(e1)),
            d2: Iv::around(f2, up(e2)),
            refinable: false,
        }
    }

    /// Enclosures of `f, f′, …, f⁗` at the angle whose cosine and sine are
    /// `(c, s)` (each within an ulp of the angle's): the computed jet
    /// widened by its rounding allowances.
    pub fn point(&self, c: f64, s: f64) -> [Iv; 5] {
        let v = self.f.jet(c, s);
        let e = self.f.rounding();
        std::array::from_fn(|j| Iv::around(v[j], e[j]))
    }

    /// Enclosures of `f, f′, …, f⁗` over `|θ − m| ≤ w`, `(c, s)` the
    /// cosine and sine of `m`: the first three from [`Bounded::enclose`],
    /// the others by the mean value theorem, `f⁽ʲ⁾(θ) ∈ f⁽ʲ⁾(m) ±
    /// M_{j+1} w` (`j = 3, 4`; `M₄ = n₁ + 16 n₂`, `M₅ = n₁ + 32 n₂`).
    pub fn arc(&self, c: f64, s: f64, w: f64) -> [Iv; 5] {
        let e = self.enclose(c, s, w);
        let v = self.f.jet(c, s);
        let r = self.f.rounding();
        let (n1, n2) = self.n;
        let (m4, m5) = (up(n1 + 16.0 * n2), up(n1 + 32.0 * n2));
        [
            e.value,
            e.d1,
            e.d2,
            Iv::around(v[3], up(m4 * w + r[3])),
            Iv::around(v[4], up(m5 * w + r[4])),
        ]
    }
}
