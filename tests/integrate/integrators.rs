//! Integrator correctness: tableaux against the Runge–Kutta order
//! conditions, observed convergence orders, tolerance proportionality,
//! conservation, output modes, statistics and non-finite handling.

use nalgebra::{Vector1, Vector2};
use pegdyn::integrate::tableau::{Tableau, dopri5_dense_weights};
use pegdyn::integrate::{IntegrateError, Method, Options, OutputMode, Solver, StopReason, solve};
use pegdyn::reference_problems::{ExponentialDecay, HarmonicOscillator, Pendulum, VanDerPol};
use pegdyn::system::FnSystem;

// ---------------------------------------------------------------------------
// Order conditions (Hairer, Nørsett & Wanner I, §II.2, Table 2.2): for every
// rooted tree τ of order ρ(τ) ≤ p, Σ bᵢ Φᵢ(τ) = 1/γ(τ).

type V = Vec<f64>;

fn mat_vec<const S: usize>(a: &[[f64; S]; S], v: &[f64]) -> V {
    (0..S)
        .map(|i| (0..S).map(|j| a[i][j] * v[j]).sum())
        .collect()
}
fn mul(u: &[f64], v: &[f64]) -> V {
    u.iter().zip(v).map(|(x, y)| x * y).collect()
}

/// (order ρ, γ, elementary weight Φ) for all 17 trees of order ≤ 5.
fn trees<const S: usize>(t: &Tableau<S>) -> Vec<(u32, f64, V)> {
    let a = &t.a;
    let one = vec![1.0; S];
    let c = t.c.to_vec();
    let c2 = mul(&c, &c);
    let c3 = mul(&c2, &c);
    let ac = mat_vec(a, &c);
    let ac2 = mat_vec(a, &c2);
    let aac = mat_vec(a, &ac);
    vec![
        (1, 1.0, one),
        (2, 2.0, c.clone()),
        (3, 3.0, c2.clone()),
        (3, 6.0, ac.clone()),
        (4, 4.0, c3.clone()),
        (4, 8.0, mul(&c, &ac)),
        (4, 12.0, ac2.clone()),
        (4, 24.0, aac.clone()),
        (5, 5.0, mul(&c3, &c)),
        (5, 10.0, mul(&c2, &ac)),
        (5, 15.0, mul(&c, &ac2)),
        (5, 30.0, mul(&c, &aac)),
        (5, 20.0, mul(&ac, &ac)),
        (5, 20.0, mat_vec(a, &c3)),
        (5, 40.0, mat_vec(a, &mul(&c, &ac))),
        (5, 60.0, mat_vec(a, &ac2)),
        (5, 120.0, mat_vec(a, &aac)),
    ]
}

/// Largest residual of the order conditions of exactly order `rho`, for
/// weights `w` that should reproduce `θ^ρ` (θ = 1 for a full step).
fn residual<const S: usize>(t: &Tableau<S>, w: &[f64], rho: u32, theta: f64) -> f64 {
    trees(t)
        .iter()
        .filter(|(r, _, _)| *r == rho)
        .map(|(_, gamma, phi)| {
            let lhs: f64 = w.iter().zip(phi).map(|(b, p)| b * p).sum();
            (lhs - theta.powi(rho as i32) / gamma).abs()
        })
        .fold(0.0, f64::max)
}

fn check_nodes<const S: usize>(t: &Tableau<S>) {
    for i in 0..S {
        let row: f64 = t.a[i].iter().sum();
        assert!(
            (row - t.c[i]).abs() < 1e-15,
            "{}: c[{i}] != row sum",
            t.name
        );
        for j in i..S {
            assert_eq!(t.a[i][j], 0.0, "{}: a[{i}][{j}] not explicit", t.name);
        }
    }
}

#[test]
fn rk4_tableau_satisfies_order_conditions_to_order_4_only() {
    let t = Tableau::rk4();
    check_nodes(&t);
    for rho in 1..=4 {
        assert!(residual(&t, &t.b, rho, 1.0) < 1e-15, "order {rho}");
    }
    assert!(residual(&t, &t.b, 5, 1.0) > 1e-3, "RK4 is not fifth order");
}

#[test]
fn dopri5_tableau_satisfies_order_conditions_to_order_5() {
    let t = Tableau::dopri5();
    check_nodes(&t);
    for rho in 1..=5 {
        let r = residual(&t, &t.b, rho, 1.0);
        assert!(r < 1e-14, "order {rho}: residual {r:e}");
    }
    // FSAL: the last stage row is b and is evaluated at t + h.
    assert_eq!(t.a[6], t.b);
    assert_eq!(t.c[6], 1.0);
}

#[test]
fn dopri5_embedded_weights_are_fourth_order_not_fifth() {
    let t = Tableau::dopri5();
    let b_hat = t.b_embedded.expect("dopri5 has an embedded pair");
    for rho in 1..=4 {
        let r = residual(&t, &b_hat, rho, 1.0);
        assert!(r < 1e-14, "order {rho}: residual {r:e}");
    }
    assert!(residual(&t, &b_hat, 5, 1.0) > 1e-5);
}

#[test]
fn dopri5_dense_output_is_fourth_order_for_every_theta() {
    let t = Tableau::dopri5();
    for theta in [0.1, 0.25, 0.5, 0.73, 0.9] {
        let w = dopri5_dense_weights(theta);
        for rho in 1..=4 {
            let r = residual(&t, &w, rho, theta);
            assert!(r < 1e-14, "theta {theta}, order {rho}: residual {r:e}");
        }
    }
    // Continuous at both ends: w(0) = 0 and w(1) = b.
    let (w0, w1) = (dopri5_dense_weights(0.0), dopri5_dense_weights(1.0));
    for i in 0..7 {
        assert_eq!(w0[i], 0.0);
        assert!((w1[i] - t.b[i]).abs() < 1e-15);
    }
}

// ---------------------------------------------------------------------------
// Observed convergence.

/// Global error at t = 2 of the pendulum from 1 rad, against a tight
/// DOPRI5 reference.
fn pendulum_reference() -> Vector2<f64> {
    let options = Options::with_tolerances(1e-13, 1e-15);
    let sol = solve(
        &Pendulum { g_over_l: 9.81 },
        Method::Dopri5,
        (0.0, Vector2::new(1.0, 0.0)),
        2.0,
        &options,
    )
    .unwrap();
    sol.x_final
}

#[test]
fn rk4_observed_order_is_four_on_step_halving() {
    let pendulum = Pendulum { g_over_l: 9.81 };
    let reference = pendulum_reference();
    let errors: Vec<f64> = [0.02, 0.01, 0.005]
        .iter()
        .map(|&h| {
            let sol = solve(
                &pendulum,
                Method::Rk4 { h },
                (0.0, Vector2::new(1.0, 0.0)),
                2.0,
                &Options::default(),
            )
            .unwrap();
            assert_eq!(sol.stop, StopReason::ReachedEnd);
            assert_eq!(sol.stats.steps, (2.0 / h).round() as usize);
            assert_eq!(sol.t_final, 2.0);
            (sol.x_final - reference).norm()
        })
        .collect();
    for pair in errors.windows(2) {
        let ratio = pair[0] / pair[1];
        assert!(
            (14.0..18.5).contains(&ratio),
            "error ratio {ratio} (errors {errors:?})"
        );
    }
}

#[test]
fn dopri5_global_error_tracks_tolerance() {
    let osc = HarmonicOscillator { omega: 2.0 };
    let x0 = Vector2::new(1.0, 0.5);
    let exact = osc.exact(&x0, 10.0);
    let tolerances = [1e-4, 1e-6, 1e-8, 1e-10];
    let errors: Vec<f64> = tolerances
        .iter()
        .map(|&tol| {
            let sol = solve(
                &osc,
                Method::Dopri5,
                (0.0, x0),
                10.0,
                &Options::with_tolerances(tol, tol),
            )
            .unwrap();
            assert_eq!(sol.stop, StopReason::ReachedEnd);
            (sol.x_final - exact).amax()
        })
        .collect();
    for (tol, err) in tolerances.iter().zip(&errors) {
        assert!(
            err / tol < 100.0 && err / tol > 1e-3,
            "tol {tol:e}: error {err:e}"
        );
    }
    for pair in errors.windows(2) {
        assert!(pair[1] < pair[0] / 10.0, "errors {errors:?}");
    }
    // log-log slope of error against tolerance over six decades.
    let slope = (errors[0] / errors[3]).log10() / 6.0;
    assert!(
        (0.7..1.2).contains(&slope),
        "slope {slope} (errors {errors:?})"
    );
}

#[test]
fn dopri5_conserves_oscillator_energy_to_tolerance() {
    let osc = HarmonicOscillator { omega: 1.0 };
    let x0 = Vector2::new(0.0, 1.0);
    let e0 = osc.energy(&x0);
    let sol = solve(
        &osc,
        Method::Dopri5,
        (0.0, x0),
        100.0,
        &Options::with_tolerances(1e-10, 1e-12),
    )
    .unwrap();
    let drift = sol
        .x
        .iter()
        .map(|x| (osc.energy(x) - e0).abs() / e0)
        .fold(0.0, f64::max);
    assert!(drift < 1e-8, "relative energy drift {drift:e}");
    assert!(sol.t.len() > 100);
}

#[test]
fn dopri5_decay_matches_exact_solution() {
    let decay = ExponentialDecay { lambda: 0.7 };
    let sol = solve(
        &decay,
        Method::Dopri5,
        (0.0, Vector1::new(2.0)),
        5.0,
        &Options::with_tolerances(1e-9, 1e-12),
    )
    .unwrap();
    for (t, x) in sol.t.iter().zip(&sol.x) {
        let exact = decay.exact(2.0, *t)[0];
        assert!((x[0] - exact).abs() < 1e-8 * exact.abs().max(1e-3), "t={t}");
    }
}

#[test]
fn dopri5_dense_output_at_requested_times_matches_exact() {
    let osc = HarmonicOscillator { omega: 3.0 };
    let x0 = Vector2::new(1.0, 0.0);
    let times: Vec<f64> = (0..=250).map(|i| 0.02 * f64::from(i)).collect();
    let options = Options {
        output: OutputMode::AtTimes(times.clone()),
        ..Options::with_tolerances(1e-8, 1e-10)
    };
    let sol = solve(&osc, Method::Dopri5, (0.0, x0), 5.0, &options).unwrap();
    assert_eq!(sol.t, times);
    // Far fewer steps than output points: the points come from the interpolant.
    assert!(sol.stats.steps < times.len());
    for (t, x) in sol.t.iter().zip(&sol.x) {
        let err = (x - osc.exact(&x0, *t)).amax();
        assert!(err < 1e-6, "t={t}: error {err:e}");
    }
}

#[test]
fn dopri5_counts_rhs_calls_exactly() {
    let vdp = VanDerPol { mu: 1.0 };
    let sol = solve(
        &vdp,
        Method::Dopri5,
        (0.0, Vector2::new(2.0, 0.0)),
        10.0,
        &Options::default(),
    )
    .unwrap();
    let s = sol.stats;
    assert!(s.steps > 10);
    // f(t0), one probe for the starting step, then 6 new stages per attempt (FSAL).
    assert_eq!(s.rhs_calls, 2 + 6 * (s.steps + s.rejected));
    assert_eq!(s.jacobian_calls, 0);
}

#[test]
fn observer_and_progress_see_every_step() {
    let osc = HarmonicOscillator { omega: 1.0 };
    let mut observed = Vec::new();
    let mut last_progress = f64::NAN;
    let mut calls = 0;
    let sol = {
        let mut solver = Solver::new(
            Method::Dopri5,
            Options {
                store: false,
                ..Options::default()
            },
        )
        .with_observer(|t, _x: &Vector2<f64>| observed.push(t))
        .with_progress(|t| {
            last_progress = t;
            calls += 1;
        });
        solver
            .solve(&osc, 0.0, Vector2::new(1.0, 0.0), 3.0)
            .unwrap()
    };
    assert!(sol.t.is_empty() && sol.x.is_empty());
    assert_eq!(observed.len(), sol.stats.steps + 1);
    assert_eq!(calls, sol.stats.steps);
    assert_eq!(last_progress, 3.0);
    assert_eq!(*observed.last().unwrap(), 3.0);
}

#[test]
fn invalid_input_is_an_error_not_a_panic() {
    let osc = HarmonicOscillator { omega: 1.0 };
    let x0 = Vector2::new(1.0, 0.0);
    let bad_rtol = Options {
        rtol: -1.0,
        ..Options::default()
    };
    assert!(matches!(
        solve(&osc, Method::Dopri5, (0.0, x0), 1.0, &bad_rtol),
        Err(IntegrateError::InvalidOption { name: "rtol", .. })
    ));
    assert!(matches!(
        solve(
            &osc,
            Method::Rk4 { h: 0.0 },
            (0.0, x0),
            1.0,
            &Options::default()
        ),
        Err(IntegrateError::InvalidOption { name: "h", .. })
    ));
    assert!(matches!(
        solve(&osc, Method::Dopri5, (1.0, x0), 0.0, &Options::default()),
        Err(IntegrateError::InvalidSpan { .. })
    ));
    let unsorted = Options {
        output: OutputMode::AtTimes(vec![0.5, 0.2]),
        ..Options::default()
    };
    assert!(matches!(
        solve(&osc, Method::Dopri5, (0.0, x0), 1.0, &unsorted),
        Err(IntegrateError::InvalidOutputTime { index: 1, .. })
    ));
    assert!(matches!(
        solve(
            &osc,
            Method::Dopri5,
            (0.0, Vector2::new(f64::NAN, 0.0)),
            1.0,
            &Options::default()
        ),
        Err(IntegrateError::NonFiniteInitialState { index: 0, .. })
    ));
}

#[test]
fn max_steps_stops_with_a_value() {
    let osc = HarmonicOscillator { omega: 1.0 };
    let options = Options {
        max_steps: 5,
        ..Options::with_tolerances(1e-10, 1e-12)
    };
    let sol = solve(
        &osc,
        Method::Dopri5,
        (0.0, Vector2::new(1.0, 0.0)),
        100.0,
        &options,
    )
    .unwrap();
    assert!(
        matches!(sol.stop, StopReason::MaxSteps { steps: 5, .. }),
        "{:?}",
        sol.stop
    );
    assert!(!sol.stop.is_success());
    assert!(sol.t_final < 100.0);
}

// ---------------------------------------------------------------------------
// Never integrate into NaN.

/// ẋ = −x, but NaN for t > 1.
fn nan_after_one() -> FnSystem<impl Fn(f64, &Vector1<f64>) -> Vector1<f64>> {
    FnSystem(|t: f64, x: &Vector1<f64>| if t > 1.0 { Vector1::new(f64::NAN) } else { -x })
}

#[test]
fn dopri5_stops_with_non_finite_and_keeps_trajectory_finite() {
    let sol = solve(
        &nan_after_one(),
        Method::Dopri5,
        (0.0, Vector1::new(1.0)),
        3.0,
        &Options::default(),
    )
    .unwrap();
    let StopReason::NonFinite { t } = sol.stop else {
        panic!("expected NonFinite, got {:?}", sol.stop)
    };
    assert!(t <= 1.0 && t > 1.0 - 1e-6, "stopped at {t}");
    assert!(sol.stats.rejected > 0);
    assert!(sol.x.iter().all(|x| x[0].is_finite()));
    assert!(sol.t.iter().all(|&ti| ti <= 1.0));
    assert!((sol.x_final[0] - (-sol.t_final).exp()).abs() < 1e-5);
}

#[test]
fn rk4_stops_with_non_finite_at_the_last_finite_step() {
    let sol = solve(
        &nan_after_one(),
        Method::Rk4 { h: 0.3 },
        (0.0, Vector1::new(1.0)),
        3.0,
        &Options::default(),
    )
    .unwrap();
    // Steps end at 0.3, 0.6, 0.9; the step from 0.9 samples t = 1.05.
    assert_eq!(
        sol.stop,
        StopReason::NonFinite {
            t: 0.8999999999999999
        }
    );
    assert!(sol.x.iter().all(|x| x[0].is_finite()));
}
