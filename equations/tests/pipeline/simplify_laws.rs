//! The simplifier's laws as a table, one row per law (egg's `test_fn!`
//! style): the left side, built through the operators, must hash-cons to the
//! same node as the right side. Rows compare ids, not strings.
//!
//! A second table lists rewrites the simplifier must NOT do because they
//! change a value where it is defined (`sqrt(x^2)` is `|x|`, not `x`).

use std::collections::HashMap;

use pegdyn_equations::simplify::rules::{RULES, Site};
use pegdyn_equations::{Expr, Graph, Id, Node, simplify};
use proptest::prelude::*;

/// The leaves every row may use: variables `x`, `y`, parameters `a`, `b`.
struct Leaves<'g> {
    g: &'g Graph,
    x: Expr<'g>,
    y: Expr<'g>,
    a: Expr<'g>,
    b: Expr<'g>,
}

fn leaves(g: &Graph) -> Leaves<'_> {
    Leaves {
        g,
        x: g.var("x"),
        y: g.var("y"),
        a: g.param("a"),
        b: g.param("b"),
    }
}

macro_rules! laws {
    ($($name:ident: |$l:ident| $lhs:expr => $rhs:expr;)*) => {$(
        #[test]
        fn $name() {
            let g = Graph::new();
            let $l = leaves(&g);
            let (lhs, rhs) = ($lhs, $rhs);
            assert_eq!(lhs.id(), rhs.id(), "{}: got {lhs}, want {rhs}", stringify!($lhs));
        }
    )*};
}

macro_rules! not_laws {
    ($($name:ident: |$l:ident| $lhs:expr => $rhs:expr;)*) => {$(
        #[test]
        fn $name() {
            let g = Graph::new();
            let $l = leaves(&g);
            let (lhs, rhs) = ($lhs, $rhs);
            assert_ne!(lhs.id(), rhs.id(), "{} must stay distinct from {rhs}", stringify!($lhs));
        }
    )*};
}

laws! {
    // Regression (proptest `simplified_forms_are_fixed_points`): |y|·|y|
    // becomes y^2 after y·y was collected, and the two must merge.
    abs_square_merges_with_square: |l| l.y.abs() * l.y * l.y.abs() * l.y => l.y.powi(4);
    fold_sum: |l| l.g.constant(2.0) + l.g.constant(3.0) => l.g.constant(5.0);
    fold_function: |l| l.g.constant(0.0).cos() => l.g.constant(1.0);
    fold_sqrt: |l| l.g.constant(9.0).sqrt() => l.g.constant(3.0);
    add_zero: |l| l.x + 0.0 => l.x;
    mul_one: |l| l.x * 1.0 => l.x;
    mul_zero: |l| l.x * 0.0 => l.g.constant(0.0);
    pow_zero: |l| l.x.powi(0) => l.g.constant(1.0);
    pow_one: |l| l.x.powf(1.0) => l.x;
    one_pow: |l| l.g.constant(1.0).pow(l.x) => l.g.constant(1.0);
    add_commutes: |l| l.x + l.y => l.y + l.x;
    mul_commutes: |l| l.x * l.y => l.y * l.x;
    add_associates: |l| (l.x + l.y) + l.a => l.x + (l.y + l.a);
    mul_associates: |l| (l.x * l.y) * l.a => l.x * (l.y * l.a);
    x_plus_x: |l| l.x + l.x => 2.0 * l.x;
    x_plus_x_plus_x: |l| l.x + (l.x + l.x) => 3.0 * l.x;
    coefficients_collect: |l| 2.0 * l.x * l.y + 3.0 * l.y * l.x => 5.0 * l.x * l.y;
    x_minus_x: |l| l.x - l.x => l.g.constant(0.0);
    sum_minus_sum: |l| (l.x + l.a) - (l.a + l.x) => l.g.constant(0.0);
    x_over_x: |l| l.x / l.x => l.g.constant(1.0);
    x_times_x: |l| l.x * l.x => l.x.powi(2);
    powers_collect: |l| l.x.powi(2) * l.x.powi(3) => l.x.powi(5);
    sqrt_times_sqrt: |l| l.x.sqrt() * l.x.sqrt() => l.x;
    sqrt_of_product_squared_recollects: |l| (l.x * l.y).sqrt() * (l.x * l.y).sqrt() * l.x => l.x.powi(2) * l.y;
    sqrt_squared: |l| l.x.sqrt().square() => l.x;
    pow_of_pow_int: |l| l.x.powf(1.5).powi(2) => l.x.powi(3);
    pow_of_product_int: |l| (l.x * l.y).powi(2) => l.x.powi(2) * l.y.powi(2);
    divide_by_constant: |l| l.x / 4.0 => 0.25 * l.x;
    common_coefficient_of_sum: |l| (l.x + l.y) / (2.0 * l.x + 2.0 * l.y) => l.g.constant(0.5);
    sign_of_sum_under_even_power: |l| (l.x - l.y).square() => (l.y - l.x).square();
    difference_over_reversed: |l| (l.a - l.b) / (l.b - l.a) => l.g.constant(-1.0);
    sqrt_of_scaled_sum: |l| (4.0 * l.x + 4.0).sqrt() => 2.0 * (l.x + 1.0).sqrt();
    neg_neg: |l| -(-l.x) => l.x;
    distribute_scalar: |l| 2.0 * (l.x + l.y) => 2.0 * l.x + 2.0 * l.y;
    neg_difference: |l| -(l.x - l.y) => l.y - l.x;
    pythagorean: |l| l.x.sin().square() + l.x.cos().square() => l.g.constant(1.0);
    pythagorean_with_factor: |l| l.a * l.x.sin().square() + l.a * l.x.cos().square() + l.b => l.a + l.b;
    pythagorean_with_coefficient: |l| 3.0 * l.x.sin().square() + 3.0 * l.x.cos().square() => l.g.constant(3.0);
    one_minus_cos: |l| 1.0 - l.x.cos() => 2.0 * (l.x / 2.0).sin().square();
    c_minus_c_cos: |l| 3.0 - 3.0 * l.x.cos() => 6.0 * (l.x / 2.0).sin().square();
    a_minus_a_cos: |l| l.a - l.a * l.x.cos() + l.y => 2.0 * l.a * (l.x / 2.0).sin().square() + l.y;
    cos_minus_one: |l| l.x.cos() - 1.0 => -2.0 * (l.x / 2.0).sin().square();
    one_minus_cos_squared: |l| 1.0 - l.x.cos().square() => l.x.sin().square();
    a_minus_a_cos_squared: |l| l.a * l.b - l.a * l.b * l.x.cos().square() => l.a * l.b * l.x.sin().square();
    cos_difference: |l| l.x.cos() * l.y.cos() + l.x.sin() * l.y.sin() => (l.x - l.y).cos();
    cos_sum: |l| l.x.cos() * l.y.cos() - l.x.sin() * l.y.sin() => (l.x + l.y).cos();
    sin_difference: |l| l.x.sin() * l.y.cos() - l.x.cos() * l.y.sin() => (l.x - l.y).sin();
    sin_sum: |l| l.x.sin() * l.y.cos() + l.x.cos() * l.y.sin() => (l.x + l.y).sin();
    cos_difference_with_factor: |l| 2.0 * l.a * l.b * l.x.cos() * l.y.cos() + 2.0 * l.a * l.b * l.x.sin() * l.y.sin() + l.b
        => 2.0 * l.a * l.b * (l.x - l.y).cos() + l.b;
    sin_difference_with_factor: |l| 3.0 * l.a * l.x.cos() * l.y.sin() - 3.0 * l.a * l.x.sin() * l.y.cos()
        => 3.0 * l.a * (l.y - l.x).sin();
    double_pendulum_speed_expanded: |l| (l.a * l.x.cos() + l.b * l.y.cos()).square().expand() + (l.a * l.x.sin() + l.b * l.y.sin()).square().expand()
        => l.a.square() + l.b.square() + 2.0 * l.a * l.b * (l.x - l.y).cos();
    expand_product_of_sums: |l| ((l.x + l.a) * (l.y - l.b)).expand() => l.x * l.y - l.x * l.b + l.a * l.y - l.a * l.b;
    expand_cube: |l| (l.x + 1.0).powi(3).expand() => l.x.powi(3) + 3.0 * l.x.square() + 3.0 * l.x + 1.0;
    sin_odd: |l| (-l.x).sin() => -l.x.sin();
    sin_odd_difference: |l| (l.y - l.x).sin() + (l.x - l.y).sin() => l.g.constant(0.0);
    tan_odd: |l| (-2.0 * l.x).tan() => -(2.0 * l.x).tan();
    asin_odd: |l| (-l.x).asin() => -l.x.asin();
    atan_odd: |l| (-l.x).atan() => -l.x.atan();
    tanh_odd: |l| (-l.x).tanh() => -l.x.tanh();
    sign_odd: |l| (-l.x).signum() => -l.x.signum();
    cos_even: |l| (-l.x).cos() => l.x.cos();
    cos_even_difference: |l| (l.y - l.x).cos() => (l.x - l.y).cos();
    abs_even: |l| (-l.x).abs() => l.x.abs();
    abs_scale: |l| (-3.0 * l.x * l.y).abs() => 3.0 * (l.x * l.y).abs();
    abs_abs: |l| l.x.abs().abs() => l.x.abs();
    abs_of_square: |l| l.x.square().abs() => l.x.square();
    sqrt_of_square: |l| l.x.square().sqrt() => l.x.abs();
    sqrt_of_fourth_power: |l| l.x.powi(4).sqrt() => l.x.square();
    abs_squared: |l| l.x.abs().square() => l.x.square();
    hypot_commutes: |l| l.x.hypot(l.y) => l.y.hypot(l.x);
    hypot_even: |l| (-l.x).hypot(l.y - l.a) => l.x.hypot(l.a - l.y);
}

not_laws! {
    sqrt_of_square_is_not_x: |l| l.x.square().sqrt() => l.x;
    cube_root_of_square_keeps_power: |l| l.x.square().powf(1.0 / 3.0) => l.x.powf(2.0 / 3.0);
    sqrt_of_product_not_split: |l| (l.x * l.y).sqrt() => l.x.sqrt() * l.y.sqrt();
    atan2_not_odd: |l| (-l.y).atan2(l.x) => -l.y.atan2(l.x);
    sqrt_of_negated_sum_not_split: |l| (-l.x - l.y).sqrt() => -(l.x + l.y).sqrt();
    ln_exp_kept: |l| l.x.exp().ln() => l.x;
    angle_sum_needs_like_coefficients: |l| 2.0 * l.x.cos() * l.y.cos() + l.x.sin() * l.y.sin() => (l.x - l.y).cos() + l.x.cos() * l.y.cos();
}

#[test]
fn rules_table_is_complete_and_unique() {
    let mut names: Vec<&str> = RULES.iter().map(|r| r.name).collect();
    names.sort_unstable();
    let n = names.len();
    names.dedup();
    assert_eq!(names.len(), n, "duplicate rule names");
    for r in RULES {
        assert!(
            !r.law.is_empty() && !r.domain.is_empty() && !r.terminates.is_empty(),
            "{}",
            r.name
        );
    }
    let with_fn = RULES
        .iter()
        .filter(|r| !matches!(r.site, Site::Core))
        .count();
    assert!(with_fn >= 15, "only {with_fn} rules with a function");
}

use crate::common;

/// Rebuilds `id` bottom-up through the simplifying constructors.
fn rebuild(g: &Graph, id: Id, memo: &mut HashMap<Id, Id>) -> Id {
    if let Some(&r) = memo.get(&id) {
        return r;
    }
    let mut kids = |xs: &[Id]| -> Vec<Id> { xs.iter().map(|&x| rebuild(g, x, memo)).collect() };
    let r = match g.node(id) {
        Node::Const(_) | Node::Sym(_) => id,
        Node::Add(xs) => simplify::add(g, &kids(&xs)),
        Node::Mul(xs) => simplify::mul(g, &kids(&xs)),
        Node::Pow(b, e) => {
            let k = kids(&[b, e]);
            simplify::pow(g, k[0], k[1])
        }
        Node::Unary(op, a) => {
            let k = kids(&[a]);
            simplify::unary(g, op, k[0])
        }
        Node::Binary(op, a, b) => {
            let k = kids(&[a, b]);
            simplify::binary(g, op, k[0], k[1])
        }
    };
    memo.insert(id, r);
    r
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, failure_persistence: None, ..ProptestConfig::default() })]

    /// Simplified forms are canonical: rebuilding one through the
    /// constructors gives the same node, so equal expressions share ids
    /// however they were built.
    #[test]
    fn simplified_forms_are_fixed_points(t in common::tree()) {
        let g = Graph::new();
        let e = common::build(&g, &t);
        let r = rebuild(&g, e.id(), &mut HashMap::new());
        prop_assert_eq!(r, e.id(), "{} rebuilt as {}", e, g.expr(r));
    }
}
