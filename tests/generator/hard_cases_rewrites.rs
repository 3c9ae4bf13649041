//! Each stable numerical form of the generator (the rows of
//! `pegdyn_equations::simplify::rules::RULES` with `stable: true`) on the
//! hard case it exists for: the same expression is built with the stable
//! forms off (`Graph::with_stable_rewrites(false)`, the naive form) and on, both
//! are evaluated by the generator's `f64` interpreter, and both are
//! compared with the double-double evaluation of the stable form from the
//! same `f64` inputs (checked equal to the naive form's double-double
//! value, which itself cancels, to 1e-10). The naive form must fail the stated bound (so the
//! case is hard) and the stable form must meet it.

use crate::common;

use common::{eval_dd, eval_f64, ulps};
use pegdyn::scalar::Dd;
use pegdyn_equations::{Expr, Graph, Id};

/// Builds `f` in a fresh graph with the stable forms on or off, evaluates
/// it at `value` in f64, and returns (f64 value, double-double value, form).
fn both(
    stable: bool,
    f: impl for<'g> Fn(&'g Graph) -> Expr<'g>,
    value: &dyn Fn(&str) -> f64,
) -> (f64, Dd, String) {
    let g = Graph::with_stable_rewrites(stable);
    let e = f(&g);
    let id: Id = e.id();
    (
        eval_f64(&g, id, value),
        eval_dd(&g, id, value),
        e.to_string(),
    )
}

/// Errors in ulps of (naive, stable) against the double-double naive value.
fn naive_and_stable(
    f: impl for<'g> Fn(&'g Graph) -> Expr<'g> + Copy,
    value: &dyn Fn(&str) -> f64,
) -> (f64, f64) {
    let (naive, naive_dd, naive_form) = both(false, f, value);
    let (stable, reference, stable_form) = both(true, f, value);
    assert_ne!(naive_form, stable_form, "the rule did not fire");
    // Both forms are the same function: equal in double-double up to the
    // naive form's own cancellation (the reference is the stable form's
    // double-double value, which has none).
    let d = (reference - naive_dd).hi().abs();
    assert!(
        d <= 1e-10 * reference.hi().abs()
            || !reference.is_finite()
            // The naive form over- or underflows in double-double too.
            || !naive_dd.is_finite()
            || naive_dd.hi() == 0.0,
        "{naive_form} vs {stable_form}: {naive_dd} vs {reference}"
    );
    (ulps(naive, reference), ulps(stable, reference))
}

/// Compliant planar peg, edge contact ((14)): the penetration of the side
/// `u = −r` into the filleted edge of a hole of diameter D = 50 mm,
/// `δ = ρ + r − (D/2 + ρ + x) cos θ`, at θ = 0 and 1e-6 rad for clearances
/// D − 2r from 50 µm to 1 nm and δ from 1e-12 to 1e-6 m. Naively the terms
/// of size D/2 cancel after rounding (error ~ ulp(D/2) ≈ 3.5e-18 m, i.e.
/// up to millions of ulps of a picometre δ); `cos_near_equal` forms
/// `r − D/2 − x` from the inputs first: within 8 ulps.
#[test]
fn edge_penetration_small_clearance_cos_near_equal() {
    fn f(g: &Graph) -> Expr<'_> {
        let (r, d, rho) = (g.param("r"), g.param("D"), g.param("rho"));
        let (x, theta) = (g.var("x"), g.var("theta"));
        rho + r - (0.5 * d + rho + x) * theta.cos()
    }
    let mut worst_naive: f64 = 0.0;
    for clearance in [50e-6, 1e-6, 1e-8, 1e-9] {
        for delta in [1e-12, 1e-9, 1e-6] {
            for theta in [0.0, 1e-6] {
                let (dh, rho) = (0.05, 2e-4);
                let r = 0.5 * (dh - clearance);
                // δ at θ: r − D/2 − x + (D/2 + ρ + x)(1 − cos θ); solve for x at cos θ ≈ 1 − θ²/2.
                let x = r - 0.5 * dh - delta + (0.5 * dh + rho) * 0.5 * theta * theta;
                let value = |n: &str| match n {
                    "r" => r,
                    "D" => dh,
                    "rho" => rho,
                    "x" => x,
                    "theta" => theta,
                    _ => f64::NAN,
                };
                let (naive, stable) = naive_and_stable(f, &value);
                worst_naive = worst_naive.max(naive);
                assert!(
                    stable <= 8.0,
                    "c={clearance} δ={delta} θ={theta}: stable {stable} ulps"
                );
            }
        }
    }
    assert!(
        worst_naive > 1e5,
        "naive form worst {worst_naive} ulps: not a hard case"
    );
}

/// Rigid three-point peg: `c = d − D cos γ` at γ = γ0(1 + ε), γ0 =
/// acos(d/D), D = 50 mm, clearances 50 µm and 1 nm, ε = 1e-3 … 1e-12. The
/// value is ill-conditioned in γ (relative condition ≈ 2/ε), so no `f64`
/// formula is accurate to an ulp; the attainable bound is the rounding of
/// the rewritten terms, `4 u · 2D sin²(γ/2)` (u = 2⁻⁵³). The naive form's
/// error is `~u·D`, larger by 1/γ0² (2.5e3 at 50 µm, 2.5e7 at 1 nm).
#[test]
fn gap_near_gamma0_cos_near_equal() {
    fn f(g: &Graph) -> Expr<'_> {
        g.param("d") - g.param("D") * g.var("gamma").cos()
    }
    let u = f64::EPSILON / 2.0;
    for clearance in [50e-6f64, 1e-9] {
        let dh = 0.05;
        let dp = dh - clearance;
        let gamma0 = 2.0 * (clearance / (2.0 * dh)).sqrt().asin();
        let mut worst_ratio: f64 = 0.0;
        for k in 3..=12 {
            let gamma = gamma0 * (1.0 + 10f64.powi(-k));
            let value = |n: &str| match n {
                "d" => dp,
                "D" => dh,
                "gamma" => gamma,
                _ => f64::NAN,
            };
            let (naive, _, _) = both(false, f, &value);
            let (stable, reference, form) = both(true, f, &value);
            assert!(form.contains("sin(gamma/2)^2"), "{form}");
            let floor = 4.0 * u * 2.0 * dh * (0.5 * gamma).sin().powi(2);
            let err = |v: f64| (Dd::from(v) - reference).hi().abs();
            assert!(
                err(stable) <= floor,
                "ε=1e-{k}: stable error {} > {floor}",
                err(stable)
            );
            worst_ratio = worst_ratio.max(err(naive) / floor);
        }
        assert!(
            worst_ratio > 10.0,
            "clearance {clearance}: naive only {worst_ratio}× the floor"
        );
    }
}

/// `exp(x) − 1` at x = 1e-15 … 1e-5 (a Hunt–Crossley-type exponential law
/// near 0): naive loses up to all digits; `exp_minus_one` emits
/// `exp_m1(x)`, within 1 ulp.
#[test]
fn exp_minus_one_small_argument() {
    fn f(g: &Graph) -> Expr<'_> {
        g.var("x").exp() - 1.0
    }
    let mut worst: f64 = 0.0;
    for x in [1e-15, 1e-12, 1e-9, 1e-5, -1e-7] {
        let (naive, stable) = naive_and_stable(f, &|_| x);
        assert!(stable <= 1.0, "x={x}: {stable} ulps");
        worst = worst.max(naive);
    }
    assert!(worst > 1e6, "naive worst {worst} ulps");
}

/// `ln(1 + x)` at x = 1e-15 … 1e-5 (a logarithmic strain near 0): naive
/// rounds `1 + x` first; `ln_one_plus` emits `ln_1p(x)`, within 1 ulp.
#[test]
fn ln_one_plus_small_argument() {
    fn f(g: &Graph) -> Expr<'_> {
        (1.0 + g.var("x")).ln()
    }
    let mut worst: f64 = 0.0;
    for x in [1e-15, 1e-12, 1e-9, 1e-5, -3e-8] {
        let (naive, stable) = naive_and_stable(f, &|_| x);
        assert!(stable <= 1.0, "x={x}: {stable} ulps");
        worst = worst.max(naive);
    }
    assert!(worst > 1e6, "naive worst {worst} ulps");
}

/// `sqrt(x² + y²)` (a contact-normal length) at |x|, |y| ≈ 1e±200: the
/// naive squares overflow to ∞ or underflow to 0; `hypot_of_squares`
/// emits `x.hypot(y)`, finite and within 1 ulp. At ordinary magnitudes
/// both are within 1 ulp.
#[test]
fn hypot_of_squares_extreme_magnitudes() {
    fn f(g: &Graph) -> Expr<'_> {
        (g.var("x").square() + g.var("y").square()).sqrt()
    }
    for (x, y) in [(3e200, 4e200), (3e-200, 4e-200), (0.3, 0.4)] {
        let value = |n: &str| if n == "x" { x } else { y };
        let (naive, stable) = naive_and_stable(f, &value);
        assert!(stable <= 1.0, "({x}, {y}): {stable} ulps");
        if !(1e-100..=1e100).contains(&x) {
            assert!(naive > 1e6, "({x}, {y}): naive only {naive} ulps");
        }
    }
}

/// `atan(y / hypot(a, b))` (the tilt of a contact normal from its
/// components) when the normal vanishes, a = b = y = 0: naive is
/// `atan(0/0) = NaN`, a silent NaN; `atan_of_ratio` emits
/// `atan2(y, hypot(a, b)) = 0`. Elsewhere both are within 2 ulps.
#[test]
fn atan_of_ratio_degenerate_normal() {
    fn f(g: &Graph) -> Expr<'_> {
        (g.var("y") / g.var("a").hypot(g.var("b"))).atan()
    }
    let zero = |_: &str| 0.0;
    let (naive, _, _) = both(false, f, &zero);
    let (stable, _, form) = both(true, f, &zero);
    assert!(naive.is_nan());
    assert_eq!(stable, 0.0, "{form}");
    let value = |n: &str| match n {
        "y" => 0.7,
        "a" => 1e-3,
        _ => 2.0,
    };
    let (naive, stable) = naive_and_stable(f, &value);
    assert!(naive <= 2.0 && stable <= 1.0, "{naive} {stable}");
}

/// `1 − cos θ` (the `one_minus_cos` row, switchable like the others) at θ =
/// 1e-9 … 1e-3: naive cancels to 0 or a few bits; `2 sin²(θ/2)` within 2 ulps.
#[test]
fn one_minus_cos_small_angle() {
    fn f(g: &Graph) -> Expr<'_> {
        1.0 - g.var("theta").cos()
    }
    let mut worst: f64 = 0.0;
    for t in [1e-9, 1e-6, 1e-3] {
        let (naive, stable) = naive_and_stable(f, &|_| t);
        assert!(stable <= 2.0, "θ={t}: {stable} ulps");
        worst = worst.max(naive);
    }
    assert!(worst > 1e6, "naive worst {worst} ulps");
}
