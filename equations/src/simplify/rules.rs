//! The rewrite table: every law the simplifier applies, one row each.
//!
//! A row names the law, states it, gives the domain on which it preserves
//! the value, and says why it cannot loop. Rows with [`Site::Core`] are
//! applied by the constructors in [`super`] (they are the bookkeeping every
//! computer-algebra system does and are listed here so that this table is
//! the one place that documents all rewrites); every other row carries the
//! function that applies it, and is tried, in table order, each time a node
//! of its site is built.
//!
//! To add a law, write its function (in `super::laws` or a new sibling
//! module) and add a row. A [`Site::Sum`] rule must strictly decrease the
//! number of `cos` and `exp` occurrences in the sum (counted as a tree,
//! `laws::sum_measure`): that is the measure that proves the sum rules terminate, and `rewrite_sum` refuses
//! (and in debug builds reports) a rewrite that does not decrease it.

use super::{laws, stable, trig};
use crate::graph::{Binary, Graph, Id, Unary};

/// Rewrites a sum whose like terms are already collected (the constant, if
/// any, last); returns the new, uncollected terms.
pub type SumRule = fn(&Graph, &[Id]) -> Option<Vec<Id>>;
/// Rewrites a product `c · f₁ · … · fₙ` whose like factors are collected
/// (the factors non-constant, in canonical order, `c ≠ 0`).
pub type ProductRule = fn(&Graph, f64, &[Id]) -> Option<Id>;
/// Rewrites `base ^ exponent` after constant folding and the 0/1 identities.
pub type PowRule = fn(&Graph, Id, Id) -> Option<Id>;
/// Rewrites `op(x)` for a non-constant `x`.
pub type UnaryRule = fn(&Graph, Unary, Id) -> Option<Id>;
/// Rewrites `op(a, b)` when not both operands are constants.
pub type BinaryRule = fn(&Graph, Binary, Id, Id) -> Option<Id>;

/// Where a rule looks, with the function that applies it.
#[derive(Clone, Copy)]
pub enum Site {
    /// Applied by the constructors in [`crate::simplify`] (no function here).
    Core,
    /// Tried on every sum.
    Sum(SumRule),
    /// Tried on every product.
    Product(ProductRule),
    /// Tried on every power.
    Pow(PowRule),
    /// Tried only for this function.
    Unary(Unary, UnaryRule),
    /// Tried only for this function.
    Binary(Binary, BinaryRule),
}

/// One rewrite law.
#[derive(Clone, Copy)]
pub struct Rule {
    /// Short identifier, unique in the table.
    pub name: &'static str,
    /// The law, left side to right side.
    pub law: &'static str,
    /// Where the law preserves the value (outside, the left side is
    /// undefined or the law is not applied).
    pub domain: &'static str,
    /// Why applying the law cannot loop.
    pub terminates: &'static str,
    /// Where it applies.
    pub site: Site,
    /// A stable numerical form (a rewrite for accuracy, not for size):
    /// switched off in a graph built by
    /// [`Graph::with_stable_rewrites`]`(false)` so that its
    /// effect can be measured.
    pub stable: bool,
}

const fn core(name: &'static str, law: &'static str, domain: &'static str) -> Rule {
    Rule {
        name,
        law,
        domain,
        terminates: "applied once by the constructor",
        site: Site::Core,
        stable: false,
    }
}

const SMALLER: &str = "rebuilds from strictly smaller subexpressions";
const ODD_T: &str = "the argument of the result is not negative (exactly one of u, -u is)";

/// All rewrites, in the order they are tried within a site.
pub static RULES: &[Rule] = &[
    // ---- constructor laws (simplify/mod.rs) ----
    core(
        "fold",
        "f(c1, …) = value for constants",
        "result finite (else the node is kept)",
    ),
    core("add_zero", "x + 0 = x", "all x"),
    core("mul_one", "1·x = x", "all x"),
    core("mul_zero", "0·x = 0", "finite x"),
    core("pow_zero", "x^0 = 1", "all x (as powi/powf)"),
    core("pow_one", "x^1 = x; 1^x = 1", "all x"),
    core(
        "flatten",
        "(a + b) + c = a + b + c; (a·b)·c = a·b·c",
        "all (order of rounding changes)",
    ),
    core(
        "order",
        "operands of + and · sorted by id",
        "all (order of rounding changes)",
    ),
    core(
        "collect_terms",
        "a·x + b·x = (a+b)·x; x − x = 0",
        "finite x",
    ),
    core(
        "collect_factors",
        "x^a · x^b = x^(a+b); x/x = 1",
        "where both factors are defined, x ≠ 0",
    ),
    // ---- sums ----
    Rule {
        name: "pythagorean",
        law: "c·F·sin(u)^2 + c·F·cos(u)^2 = c·F",
        domain: "all u, F",
        terminates: "removes a cos",
        site: Site::Sum(laws::pythagorean),
        stable: false,
    },
    Rule {
        name: "cos_angle_sum",
        law: "c·F·cos a·cos b ± c·F·sin a·sin b = c·F·cos(a ∓ b) (a ≠ b)",
        domain: "all a, b, F",
        terminates: "removes a cos (a and b once instead of twice)",
        site: Site::Sum(trig::cos_angle_sum),
        stable: false,
    },
    Rule {
        name: "sin_angle_sum",
        law: "c·F·sin a·cos b ± c·F·cos a·sin b = c·F·sin(a ± b) (a ≠ b)",
        domain: "all a, b, F",
        terminates: "removes both cos (a and b once instead of twice)",
        site: Site::Sum(trig::sin_angle_sum),
        stable: false,
    },
    Rule {
        name: "one_minus_cos",
        law: "c·F − c·F·cos(u) = 2·c·F·sin(u/2)^2 (no cancellation at small u)",
        domain: "all u, F",
        terminates: "removes a cos",
        site: Site::Sum(laws::one_minus_cos),
        stable: true,
    },
    Rule {
        name: "one_minus_cos_squared",
        law: "c·F − c·F·cos(u)^2 = c·F·sin(u)^2 (no cancellation near u = 0)",
        domain: "all u, F",
        terminates: "removes a cos",
        site: Site::Sum(laws::one_minus_cos_squared),
        stable: true,
    },
    Rule {
        name: "cos_near_equal",
        law: "a − b·cos(u) = (a − b) + 2b·sin²(u/2) for alike parameter products a, b (d − D cos γ)",
        domain: "all u, a, b",
        terminates: "removes every cos(u) of the sum",
        site: Site::Sum(stable::cos_near_equal),
        stable: true,
    },
    Rule {
        name: "exp_minus_one",
        law: "c·F·exp(u) − c·F = c·F·exp_m1(u)",
        domain: "all u, F",
        terminates: "removes an exp",
        site: Site::Sum(stable::exp_minus_one),
        stable: true,
    },
    // ---- products ----
    Rule {
        name: "distribute_scalar",
        law: "c·(a + b) = c·a + c·b",
        domain: "all (rounding changes)",
        terminates: "the sum constructor scales terms without building products",
        site: Site::Product(laws::distribute_scalar),
        stable: false,
    },
    // ---- powers ----
    Rule {
        name: "pow_of_pow_int",
        law: "(x^a)^n = x^(a·n) for integer n",
        domain: "where x^a is defined",
        terminates: SMALLER,
        site: Site::Pow(laws::pow_of_pow_int),
        stable: false,
    },
    Rule {
        name: "even_root",
        law: "(x^n)^e = |x|^(n·e) for even n and integer n·e (e.g. sqrt(x^2) = |x|, never x)",
        domain: "all x",
        terminates: SMALLER,
        site: Site::Pow(laws::even_root),
        stable: false,
    },
    Rule {
        name: "abs_even_pow",
        law: "|x|^n = x^n for even integer n",
        domain: "all x",
        terminates: SMALLER,
        site: Site::Pow(laws::abs_even_pow),
        stable: false,
    },
    Rule {
        name: "pow_of_product_int",
        law: "(x·y)^n = x^n·y^n for integer n",
        domain: "all x, y",
        terminates: SMALLER,
        site: Site::Pow(laws::pow_of_product_int),
        stable: false,
    },
    Rule {
        name: "pow_sum_content",
        law: "(c·s)^e = c^e·s^e for a sum whose coefficients are all ±c (2x + 2y, -a + b)",
        domain: "integer e: all; other e: c > 0, where s^e is defined",
        terminates: "the new sum's leading coefficient is 1",
        site: Site::Pow(laws::pow_sum_content),
        stable: false,
    },
    Rule {
        name: "hypot_of_squares",
        law: "(x² + y² + …)^e = hypot(hypot(x, y), …)^(2e) for non-integer e (sqrt(x² + y²) = hypot(x, y))",
        domain: "all x, y",
        terminates: "the result's base is not a sum",
        site: Site::Pow(stable::hypot_of_squares),
        stable: true,
    },
    // ---- odd and even functions ----
    Rule {
        name: "sin_odd",
        law: "sin(-u) = -sin(u)",
        domain: "all u",
        terminates: ODD_T,
        site: Site::Unary(Unary::Sin, laws::odd),
        stable: false,
    },
    Rule {
        name: "tan_odd",
        law: "tan(-u) = -tan(u)",
        domain: "all u",
        terminates: ODD_T,
        site: Site::Unary(Unary::Tan, laws::odd),
        stable: false,
    },
    Rule {
        name: "asin_odd",
        law: "asin(-u) = -asin(u)",
        domain: "|u| <= 1",
        terminates: ODD_T,
        site: Site::Unary(Unary::Asin, laws::odd),
        stable: false,
    },
    Rule {
        name: "atan_odd",
        law: "atan(-u) = -atan(u)",
        domain: "all u",
        terminates: ODD_T,
        site: Site::Unary(Unary::Atan, laws::odd),
        stable: false,
    },
    Rule {
        name: "tanh_odd",
        law: "tanh(-u) = -tanh(u)",
        domain: "all u",
        terminates: ODD_T,
        site: Site::Unary(Unary::Tanh, laws::odd),
        stable: false,
    },
    Rule {
        name: "sign_odd",
        law: "sign(-u) = -sign(u)",
        domain: "all u",
        terminates: ODD_T,
        site: Site::Unary(Unary::Sign, laws::odd),
        stable: false,
    },
    Rule {
        name: "cos_even",
        law: "cos(-u) = cos(u)",
        domain: "all u",
        terminates: ODD_T,
        site: Site::Unary(Unary::Cos, laws::even),
        stable: false,
    },
    Rule {
        name: "abs_scale",
        law: "|c·u| = |c|·|u|; |-u| = |u|",
        domain: "all u",
        terminates: "the argument of the result has coefficient 1 and is not negative",
        site: Site::Unary(Unary::Abs, laws::abs_scale),
        stable: false,
    },
    Rule {
        name: "abs_idempotent",
        law: "| |u| | = |u|; |u^n| = u^n for even n",
        domain: "all u",
        terminates: "returns the argument",
        site: Site::Unary(Unary::Abs, laws::abs_of_nonneg),
        stable: false,
    },
    Rule {
        name: "ln_one_plus",
        law: "ln(1 + x) = ln_1p(x)",
        domain: "x > −1",
        terminates: "the result is not a ln",
        site: Site::Unary(Unary::Ln, stable::ln_one_plus),
        stable: true,
    },
    Rule {
        name: "atan_of_ratio",
        law: "atan(n/d) = atan2(n, d) for d never negative (|x|, hypot, exp, even powers, sqrt)",
        domain: "d > 0 (at d = 0 the left side is ±π/2 by IEEE rules, as the right)",
        terminates: "the result is not an atan",
        site: Site::Unary(Unary::Atan, stable::atan_of_ratio),
        stable: true,
    },
    Rule {
        name: "hypot_canonical",
        law: "hypot(±a, ±b) = hypot(a, b) = hypot(b, a), operands sorted",
        domain: "all a, b",
        terminates: "the result's operands are sorted and not negative",
        site: Site::Binary(Binary::Hypot, laws::hypot_canonical),
        stable: false,
    },
    // Not a rule, on purpose: atan2(-y, x) = -atan2(y, x) fails on the branch
    // cut (y = ±0, x < 0), where the sign of a computed zero picks ±π.
];

/// The rules applied in `g`: all, or all but the stable forms
/// ([`Graph::stable_rewrites`]).
fn active(g: &Graph) -> impl Iterator<Item = &'static Rule> {
    let stable = g.stable_rewrites();
    RULES.iter().filter(move |r| stable || !r.stable)
}

/// Applies the first sum rule that fires and decreases the measure.
pub(crate) fn rewrite_sum(g: &Graph, terms: &[Id]) -> Option<Vec<Id>> {
    for rule in active(g) {
        let Site::Sum(f) = rule.site else { continue };
        if let Some(next) = f(g, terms) {
            if laws::sum_measure(g, &next) < laws::sum_measure(g, terms) {
                return Some(next);
            }
            debug_assert!(
                false,
                "sum rule `{}` does not decrease the measure",
                rule.name
            );
        }
    }
    None
}

/// Applies the first product rule that fires.
pub(crate) fn rewrite_product(g: &Graph, c: f64, factors: &[Id]) -> Option<Id> {
    active(g).find_map(|r| match r.site {
        Site::Product(f) => f(g, c, factors),
        _ => None,
    })
}

/// Applies the first power rule that fires.
pub(crate) fn rewrite_pow(g: &Graph, base: Id, exponent: Id) -> Option<Id> {
    active(g).find_map(|r| match r.site {
        Site::Pow(f) => f(g, base, exponent),
        _ => None,
    })
}

/// Applies the first rule for `op` that fires.
pub(crate) fn rewrite_unary(g: &Graph, op: Unary, x: Id) -> Option<Id> {
    active(g).find_map(|r| match r.site {
        Site::Unary(o, f) if o == op => f(g, op, x),
        _ => None,
    })
}

/// Applies the first rule for `op` that fires.
pub(crate) fn rewrite_binary(g: &Graph, op: Binary, a: Id, b: Id) -> Option<Id> {
    active(g).find_map(|r| match r.site {
        Site::Binary(o, f) if o == op => f(g, op, a, b),
        _ => None,
    })
}
