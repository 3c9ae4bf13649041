//! The Rosenbrock method RODAS3: its tableau against the Rosenbrock order
//! conditions and L-stability, its observed order, its step counts against
//! DOPRI5 on stiff problems, and events on its Hermite dense output.

use std::f64::consts::FRAC_PI_2;

use nalgebra::{Vector1, Vector2};
use pegdyn::integrate::tableau::RosenbrockTableau;
use pegdyn::integrate::{Direction, Event, Method, Options, Solver, StopReason, solve};
use pegdyn::reference_problems::{HarmonicOscillator, Pendulum, StiffLinear, VanDerPol};
use pegdyn::system::OdeSystem;

use crate::common::rosenbrock;
use rosenbrock::{Modulated, fixed_step, stability, stiff_accuracy_defect};

/// Rosenbrock order conditions (Hairer & Wanner II, §IV.7, Table 7.1) with
/// `βᵢⱼ = αᵢⱼ + γᵢⱼ` (j < i), `β'ᵢ = Σⱼ<ᵢ βᵢⱼ`, `αᵢ = Σⱼ αᵢⱼ`:
/// returns the residuals of the conditions of orders 1, 2, 3 for weights `w`.
fn residuals(t: &RosenbrockTableau<4>, w: &[f64; 4]) -> [f64; 3] {
    let g = t.gamma;
    let beta = |i: usize, j: usize| t.alpha[i][j] + t.gamma_lower[i][j];
    let beta_p: Vec<f64> = (0..4).map(|i| (0..i).map(|j| beta(i, j)).sum()).collect();
    let alpha: Vec<f64> = (0..4).map(|i| t.alpha[i].iter().sum()).collect();
    let dot = |v: &[f64]| -> f64 { w.iter().zip(v).map(|(a, b)| a * b).sum() };
    let order1 = (w.iter().sum::<f64>() - 1.0).abs();
    let order2 = (dot(&beta_p) - (0.5 - g)).abs();
    let a2: Vec<f64> = alpha.iter().map(|a| a * a).collect();
    let bb: Vec<f64> = (0..4)
        .map(|i| (0..i).map(|j| beta(i, j) * beta_p[j]).sum())
        .collect();
    let order3 = (dot(&a2) - 1.0 / 3.0)
        .abs()
        .max((dot(&bb) - (1.0 / 6.0 - g + g * g)).abs());
    [order1, order2, order3]
}

#[test]
fn rodas3_tableau_is_third_order_with_second_order_embedding() {
    let t = RosenbrockTableau::rodas3();
    let r = residuals(&t, &t.b);
    assert!(r.iter().all(|&x| x < 1e-15), "b residuals {r:?}");
    let r_hat = residuals(&t, &t.b_embedded);
    assert!(r_hat[0] < 1e-15 && r_hat[1] < 1e-15, "{r_hat:?}");
    assert!(
        r_hat[2] > 1e-3,
        "embedded must not be third order: {r_hat:?}"
    );
}

#[test]
fn rodas3_is_l_stable_on_the_negative_real_axis() {
    let t = RosenbrockTableau::rodas3();
    // Stiffly accurate: b is the last row of B = α + Γ, hence R(∞) = 0.
    assert!(stiff_accuracy_defect(&t) < 1e-15);
    assert!(stability(&t, -1e8).abs() < 1e-6);
    for k in 0..200 {
        let z = -10f64.powf(-3.0 + 0.05 * f64::from(k));
        assert!(stability(&t, z).abs() <= 1.0, "|R({z})| > 1");
    }
    // Consistent with e^z to third order near 0.
    let z: f64 = -1e-2;
    assert!((stability(&t, z) - z.exp()).abs() < 1e-8);
}

#[test]
fn rodas3_observed_order_is_three() {
    let pendulum = Pendulum { g_over_l: 9.81 };
    let reference = solve(
        &pendulum,
        Method::Dopri5,
        (0.0, Vector2::new(1.0, 0.0)),
        2.0,
        &Options::with_tolerances(1e-13, 1e-15),
    )
    .unwrap()
    .x_final;
    let pendulum_errors: Vec<f64> = [0.02, 0.01, 0.005]
        .iter()
        .map(|&h| {
            let sol = solve(
                &pendulum,
                Method::Rodas3,
                (0.0, Vector2::new(1.0, 0.0)),
                2.0,
                &fixed_step(h),
            )
            .unwrap();
            assert_eq!(sol.stats.steps, (2.0 / h).round() as usize);
            assert_eq!(sol.stats.rejected, 0);
            (sol.x_final - reference).norm()
        })
        .collect();
    let exact = 1.5 * 3.0f64.sin().exp();
    let modulated_errors: Vec<f64> = [0.05, 0.025, 0.0125]
        .iter()
        .map(|&h| {
            let sol = solve(
                &Modulated,
                Method::Rodas3,
                (0.0, Vector1::new(1.5)),
                3.0,
                &fixed_step(h),
            )
            .unwrap();
            (sol.x_final[0] - exact).abs()
        })
        .collect();
    for errors in [&pendulum_errors, &modulated_errors] {
        for pair in errors.windows(2) {
            let ratio = pair[0] / pair[1];
            assert!(
                (6.5..9.5).contains(&ratio),
                "ratio {ratio} (errors {errors:?})"
            );
        }
    }
}

#[test]
fn stiff_linear_problem_takes_far_fewer_steps_than_dopri5() {
    let stiff = StiffLinear::standard();
    let x0 = Vector2::new(2.0, 0.0);
    let options = Options::with_tolerances(1e-6, 1e-9);
    let exact = stiff.exact(&x0, 10.0);
    let rodas = solve(&stiff, Method::Rodas3, (0.0, x0), 10.0, &options).unwrap();
    let dopri = solve(&stiff, Method::Dopri5, (0.0, x0), 10.0, &options).unwrap();
    assert_eq!(rodas.stop, StopReason::ReachedEnd);
    assert_eq!(dopri.stop, StopReason::ReachedEnd);
    for sol in [&rodas, &dopri] {
        let err = (sol.x_final - exact).amax();
        assert!(err < 1e-5 * exact.amax(), "error {err:e}");
    }
    let (nr, nd) = (rodas.stats.steps, dopri.stats.steps);
    // DOPRI5 is held near its stability limit h ≈ 3.3/10⁴ for the whole run.
    assert!(nd > 10_000, "dopri5 steps {nd}");
    assert!(nd > 50 * nr, "rodas3 {nr} steps vs dopri5 {nd}");
    // One Jacobian per step start, one LU per attempt.
    let s = rodas.stats;
    assert_eq!(s.lu_factorizations, s.steps + s.rejected);
    assert!(s.jacobian_calls <= s.steps + s.rejected && s.jacobian_calls >= s.steps);
}

#[test]
fn stiff_van_der_pol_agrees_with_a_tight_reference_run() {
    let vdp = VanDerPol { mu: 100.0 };
    let x0 = Vector2::new(2.0, 0.0);
    let t_end = 200.0;
    let reference = solve(
        &vdp,
        Method::Dopri5,
        (0.0, x0),
        t_end,
        &Options::with_tolerances(1e-12, 1e-12),
    )
    .unwrap();
    assert_eq!(reference.stop, StopReason::ReachedEnd);
    let options = Options::with_tolerances(1e-7, 1e-9);
    let rodas = solve(&vdp, Method::Rodas3, (0.0, x0), t_end, &options).unwrap();
    let dopri = solve(&vdp, Method::Dopri5, (0.0, x0), t_end, &options).unwrap();
    assert_eq!(rodas.stop, StopReason::ReachedEnd);
    let err = (rodas.x_final - reference.x_final).amax();
    assert!(
        err < 1e-5,
        "rodas3 {:?} vs reference {:?}",
        rodas.x_final,
        reference.x_final
    );
    assert!(rodas.stats.steps < dopri.stats.steps);
}

#[test]
fn very_stiff_van_der_pol_slow_phase_takes_orders_of_magnitude_fewer_steps() {
    // μ = 1000 from (2, 0): on the slow manifold until t ≈ 800, Jacobian
    // eigenvalue ≈ −μ(x² − 1) ≈ −3000, so DOPRI5 is stability-bound at h ≈ 1e-3.
    let vdp = VanDerPol { mu: 1000.0 };
    let x0 = Vector2::new(2.0, 0.0);
    let options = Options::with_tolerances(1e-6, 1e-8);
    let rodas = solve(&vdp, Method::Rodas3, (0.0, x0), 300.0, &options).unwrap();
    let dopri = solve(&vdp, Method::Dopri5, (0.0, x0), 300.0, &options).unwrap();
    assert_eq!(rodas.stop, StopReason::ReachedEnd);
    assert_eq!(dopri.stop, StopReason::ReachedEnd);
    assert!((rodas.x_final - dopri.x_final).amax() < 1e-5);
    assert!(
        100 * rodas.stats.steps < dopri.stats.steps,
        "rodas3 {} steps, dopri5 {}",
        rodas.stats.steps,
        dopri.stats.steps
    );
}

#[test]
fn rodas3_locates_pendulum_crossing_on_hermite_output() {
    let pendulum = Pendulum { g_over_l: 9.81 };
    let theta0 = 1.0;
    let sol = Solver::new(Method::Rodas3, Options::with_tolerances(1e-10, 1e-12))
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

#[test]
fn rodas3_handles_oscillator_and_finite_difference_jacobian() {
    use pegdyn::system::FnSystem;
    // Same oscillator through the finite-difference default Jacobian.
    let osc = HarmonicOscillator { omega: 1.0 };
    let fd = FnSystem(|t: f64, x: &Vector2<f64>| osc.rhs(t, x));
    let options = Options::with_tolerances(1e-8, 1e-10);
    for sol in [
        solve(
            &osc,
            Method::Rodas3,
            (0.0, Vector2::new(1.0, 0.0)),
            FRAC_PI_2 * 4.0,
            &options,
        )
        .unwrap(),
        solve(
            &fd,
            Method::Rodas3,
            (0.0, Vector2::new(1.0, 0.0)),
            FRAC_PI_2 * 4.0,
            &options,
        )
        .unwrap(),
    ] {
        assert!(
            (sol.x_final - Vector2::new(1.0, 0.0)).amax() < 1e-6,
            "{:?}",
            sol.x_final
        );
    }
}

#[test]
fn rodas3_stops_with_non_finite_and_keeps_trajectory_finite() {
    use pegdyn::system::FnSystem;
    // ẋ = −x, but NaN for t > 1 (also inside the finite-difference ∂f/∂t).
    let nan_after_one =
        FnSystem(|t: f64, x: &Vector1<f64>| if t > 1.0 { Vector1::new(f64::NAN) } else { -x });
    let sol = solve(
        &nan_after_one,
        Method::Rodas3,
        (0.0, Vector1::new(1.0)),
        3.0,
        &Options::default(),
    )
    .unwrap();
    let StopReason::NonFinite { t } = sol.stop else {
        panic!("expected NonFinite, got {:?}", sol.stop)
    };
    assert!(t <= 1.0 && t > 0.99, "stopped at {t}");
    assert!(sol.x.iter().all(|x| x[0].is_finite()));
}
