//! The Rosenbrock methods RODAS3 and RODAS4, one table over their tableaux:
//! each tableau against the Rosenbrock order conditions up to its order
//! (Hairer & Wanner II, §IV.7, Table 7.1) with an embedding one order lower,
//! stiff accuracy and L-stability, the observed order, and events on the
//! dense output; then RODAS4's stage nodes and its step counts against
//! RODAS3. The stiff problems against DOPRI5 are in `stiff.rs`.

use std::ops::Range;

use nalgebra::{Vector1, Vector2};
use pegdyn::integrate::tableau::RosenbrockTableau;
use pegdyn::integrate::{Direction, Event, Method, Options, Solver, StopReason, solve};
use pegdyn::reference_problems::{Pendulum, VanDerPol};

use crate::common::rosenbrock::{Modulated, fixed_step, stability, stiff_accuracy_defect};

/// One row of the table: a method, its tableau and what it must show.
struct Row<const S: usize> {
    method: Method,
    tableau: fn() -> RosenbrockTableau<S>,
    /// Classical order `p`; the embedding has order `p − 1`.
    order: usize,
    /// Largest residual of a condition that holds (rounding of the
    /// published coefficients).
    residual: f64,
    /// Smallest residual of the embedding's order-`p` conditions (it must
    /// not be of order `p`).
    embedded_gap: f64,
    /// `|R(z) − e^z|` at z = −0.01 (about |z|^{p+1}).
    consistency: f64,
    /// DOPRI5 tolerances (rtol, atol) of the pendulum's reference.
    reference: (f64, f64),
    /// Fixed steps on the pendulum and on the modulated scalar problem.
    pendulum_h: [f64; 3],
    modulated_h: [f64; 3],
    /// Error ratio per halving of the step: about 2^p.
    pendulum_ratio: Range<f64>,
    modulated_ratio: Range<f64>,
}

const RODAS3: Row<4> = Row {
    method: Method::Rodas3,
    tableau: RosenbrockTableau::rodas3,
    order: 3,
    residual: 1e-15,
    embedded_gap: 1e-3,
    consistency: 1e-8,
    reference: (1e-13, 1e-15),
    pendulum_h: [0.02, 0.01, 0.005],
    modulated_h: [0.05, 0.025, 0.0125],
    pendulum_ratio: 6.5..9.5,
    modulated_ratio: 6.5..9.5,
};

// On the scalar linear non-autonomous problem the conditions of order 5
// collapse to fewer, and RODAS4 shows about 2⁵ per halving: at least 2⁴.
const RODAS4: Row<6> = Row {
    method: Method::Rodas4,
    tableau: RosenbrockTableau::rodas4,
    order: 4,
    residual: 1e-12,
    embedded_gap: 1e-4,
    consistency: 1e-10,
    reference: (1e-14, 1e-16),
    pendulum_h: [0.04, 0.02, 0.01],
    modulated_h: [0.1, 0.05, 0.025],
    pendulum_ratio: 14.0..18.0,
    modulated_ratio: 14.0..f64::INFINITY,
};

/// Residuals of the Rosenbrock order conditions of orders 1 to 4 for
/// weights `w` (`βᵢⱼ = αᵢⱼ + γᵢⱼ` for j < i, `β'ᵢ = Σⱼ βᵢⱼ`, `αᵢ = Σⱼ αᵢⱼ`):
/// order 1: `Σ wᵢ = 1`; order 2: `Σ wᵢβ'ᵢ = 1/2 − γ`;
/// order 3: `Σ wᵢαᵢ² = 1/3`, `Σ wᵢβᵢⱼβ'ⱼ = 1/6 − γ + γ²`;
/// order 4: `Σ wᵢαᵢ³ = 1/4`, `Σ wᵢαᵢαᵢⱼβ'ⱼ = 1/8 − γ/3`,
/// `Σ wᵢβᵢⱼαⱼ² = 1/12 − γ/3`, `Σ wᵢβᵢⱼβⱼₖβ'ₖ = 1/24 − γ/2 + 3γ²/2 − γ³`.
/// Returns the largest residual of each order.
fn residuals<const S: usize>(t: &RosenbrockTableau<S>, w: &[f64; S]) -> [f64; 4] {
    let g = t.gamma;
    let beta = |i: usize, j: usize| t.alpha[i][j] + t.gamma_lower[i][j];
    let beta_p: Vec<f64> = (0..S).map(|i| (0..i).map(|j| beta(i, j)).sum()).collect();
    let alpha: Vec<f64> = (0..S).map(|i| t.alpha[i].iter().sum()).collect();
    let dot = |v: &[f64]| -> f64 { w.iter().zip(v).map(|(a, b)| a * b).sum() };
    let lower = |m: &dyn Fn(usize, usize) -> f64, v: &[f64]| -> Vec<f64> {
        (0..S)
            .map(|i| (0..i).map(|j| m(i, j) * v[j]).sum())
            .collect()
    };
    let alpha_ij = |i: usize, j: usize| t.alpha[i][j];
    let bb = lower(&beta, &beta_p);
    let a2: Vec<f64> = alpha.iter().map(|a| a * a).collect();
    let a3: Vec<f64> = alpha.iter().map(|a| a * a * a).collect();
    let ab = lower(&alpha_ij, &beta_p);
    let a_ab: Vec<f64> = (0..S).map(|i| alpha[i] * ab[i]).collect();
    let b_a2 = lower(&beta, &a2);
    let bbb = lower(&beta, &bb);
    let order1 = (w.iter().sum::<f64>() - 1.0).abs();
    let order2 = (dot(&beta_p) - (0.5 - g)).abs();
    let order3 = (dot(&a2) - 1.0 / 3.0)
        .abs()
        .max((dot(&bb) - (1.0 / 6.0 - g + g * g)).abs());
    let order4 = [
        dot(&a3) - 0.25,
        dot(&a_ab) - (1.0 / 8.0 - g / 3.0),
        dot(&b_a2) - (1.0 / 12.0 - g / 3.0),
        dot(&bbb) - (1.0 / 24.0 - g / 2.0 + 1.5 * g * g - g * g * g),
    ]
    .iter()
    .fold(0.0f64, |m, r| m.max(r.abs()));
    [order1, order2, order3, order4]
}

/// `b` meets the conditions up to order p, the embedding up to p − 1 and
/// not p.
fn order_conditions<const S: usize>(row: &Row<S>) {
    let t = (row.tableau)();
    let p = row.order;
    let r = residuals(&t, &t.b);
    assert!(
        r[..p].iter().all(|&x| x < row.residual),
        "b residuals {r:?}"
    );
    let r_hat = residuals(&t, &t.b_embedded);
    assert!(
        r_hat[..p - 1].iter().all(|&x| x < row.residual),
        "{r_hat:?}"
    );
    assert!(
        r_hat[p - 1] > row.embedded_gap,
        "embedded must not be of order {p}: {r_hat:?}"
    );
}

/// Stiffly accurate (b is the last row of B = α + Γ, hence R(∞) = 0),
/// |R(z)| ≤ 1 on the negative real axis, R consistent with e^z near 0.
fn l_stability<const S: usize>(row: &Row<S>) {
    let t = (row.tableau)();
    let defect = stiff_accuracy_defect(&t);
    assert!(defect < row.residual, "stiff-accuracy defect {defect:e}");
    assert!(stability(&t, -1e8).abs() < 1e-6);
    for k in 0..200 {
        let z = -10f64.powf(-3.0 + 0.05 * f64::from(k));
        assert!(stability(&t, z).abs() <= 1.0, "|R({z})| > 1");
    }
    let z: f64 = -1e-2;
    assert!((stability(&t, z) - z.exp()).abs() < row.consistency);
}

/// Fixed steps halved twice on the pendulum (against a tight DOPRI5 run)
/// and on ẋ = cos(t)·x (against x₀ e^{sin t}): error ratios about 2^p.
fn observed_order<const S: usize>(row: &Row<S>) {
    let pendulum = Pendulum { g_over_l: 9.81 };
    let x0 = Vector2::new(1.0, 0.0);
    let (rtol, atol) = row.reference;
    let reference = solve(
        &pendulum,
        Method::Dopri5,
        (0.0, x0),
        2.0,
        &Options::with_tolerances(rtol, atol),
    )
    .unwrap()
    .x_final;
    let pendulum_errors: Vec<f64> = row
        .pendulum_h
        .iter()
        .map(|&h| {
            let sol = solve(&pendulum, row.method, (0.0, x0), 2.0, &fixed_step(h)).unwrap();
            assert_eq!(sol.stats.steps, (2.0 / h).round() as usize);
            assert_eq!(sol.stats.rejected, 0);
            (sol.x_final - reference).norm()
        })
        .collect();
    let exact = 1.5 * 3.0f64.sin().exp();
    let modulated_errors: Vec<f64> = row
        .modulated_h
        .iter()
        .map(|&h| {
            let sol = solve(
                &Modulated,
                row.method,
                (0.0, Vector1::new(1.5)),
                3.0,
                &fixed_step(h),
            )
            .unwrap();
            (sol.x_final[0] - exact).abs()
        })
        .collect();
    for (errors, range) in [
        (&pendulum_errors, &row.pendulum_ratio),
        (&modulated_errors, &row.modulated_ratio),
    ] {
        for pair in errors.windows(2) {
            let ratio = pair[0] / pair[1];
            assert!(range.contains(&ratio), "ratio {ratio} (errors {errors:?})");
        }
    }
}

/// The pendulum's first zero crossing of θ, located on the dense output,
/// against the exact quarter period.
fn locates_pendulum_crossing<const S: usize>(row: &Row<S>) {
    let pendulum = Pendulum { g_over_l: 9.81 };
    let theta0 = 1.0;
    let sol = Solver::new(row.method, Options::with_tolerances(1e-10, 1e-12))
        .with_event(
            Event::new(|_t, x: &Vector2<f64>| x[0])
                .direction(Direction::Falling)
                .terminal(),
        )
        .solve(&pendulum, 0.0, Vector2::new(theta0, 0.0), 5.0)
        .unwrap();
    let StopReason::Event { t, .. } = sol.stop else {
        panic!("{:?}", sol.stop)
    };
    let exact = pendulum.quarter_period(theta0);
    assert!((t - exact).abs() < 1e-10, "t={t}, exact {exact}");
}

/// The same four tests for each row of the table, one module per method.
macro_rules! per_method {
    ($($name:ident => $row:expr;)*) => {$(
        mod $name {
            #[test]
            fn tableau_meets_its_order_conditions() {
                super::order_conditions(&$row);
            }
            #[test]
            fn is_stiffly_accurate_and_l_stable_on_the_negative_real_axis() {
                super::l_stability(&$row);
            }
            #[test]
            fn observed_order_is_its_order() {
                super::observed_order(&$row);
            }
            #[test]
            fn locates_pendulum_crossing_on_dense_output() {
                super::locates_pendulum_crossing(&$row);
            }
        }
    )*};
}

per_method! {
    rodas3 => super::RODAS3;
    rodas4 => super::RODAS4;
}

#[test]
fn rodas4_stage_nodes_match_the_published_ones() {
    let t = RosenbrockTableau::rodas4();
    let alpha = [0.0, 0.386, 0.21, 0.63, 1.0, 1.0];
    let gamma_i = [0.25, -0.1043, 0.1035, -0.0362, 0.0, 0.0];
    for i in 0..6 {
        let a: f64 = t.alpha[i].iter().sum();
        let g: f64 = t.gamma + t.gamma_lower[i].iter().sum::<f64>();
        assert!((a - alpha[i]).abs() < 1e-12, "alpha_{i} = {a}");
        assert!((g - gamma_i[i]).abs() < 1e-12, "gamma_{i} = {g}");
    }
}

#[test]
fn rodas4_needs_fewer_steps_than_rodas3_on_stiff_van_der_pol_at_tight_tolerance() {
    let vdp = VanDerPol { mu: 1000.0 };
    let x0 = Vector2::new(2.0, 0.0);
    let options = Options::with_tolerances(1e-8, 1e-10);
    let r4 = solve(&vdp, Method::Rodas4, (0.0, x0), 300.0, &options).unwrap();
    let r3 = solve(&vdp, Method::Rodas3, (0.0, x0), 300.0, &options).unwrap();
    assert_eq!(r4.stop, StopReason::ReachedEnd);
    assert_eq!(r3.stop, StopReason::ReachedEnd);
    // Same answer (both within their tolerance of each other) ...
    let d = (r4.x_final - r3.x_final).norm() / r3.x_final.norm();
    assert!(
        d < 1e-4,
        "rodas4 {:?} vs rodas3 {:?}",
        r4.x_final,
        r3.x_final
    );
    // ... in fewer steps.
    assert!(
        2 * r4.stats.steps < r3.stats.steps,
        "rodas4 {} steps, rodas3 {}",
        r4.stats.steps,
        r3.stats.steps
    );
}
