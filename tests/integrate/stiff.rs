//! RODAS3 on stiff problems: its step counts against DOPRI5 (a stiff linear
//! system, Van der Pol at μ = 100 and 1000), the finite-difference Jacobian,
//! and a right-hand side that turns non-finite. The tableaux, orders and
//! events of RODAS3 and RODAS4 are in `rosenbrock.rs`.

use std::f64::consts::FRAC_PI_2;

use nalgebra::{Vector1, Vector2};
use pegdyn::integrate::{Method, Options, StopReason, solve};
use pegdyn::reference_problems::{HarmonicOscillator, StiffLinear, VanDerPol};
use pegdyn::system::OdeSystem;

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
