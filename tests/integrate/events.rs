//! Event location on the dense output: zero crossings against analytic
//! times, direction filters, terminal versus non-terminal events, output
//! truncation and restarts from a located event.

use std::f64::consts::{FRAC_PI_2, PI};

use nalgebra::Vector2;
use pegdyn::integrate::{Direction, Event, Method, Options, OutputMode, Solver, StopReason};
use pegdyn::reference_problems::{HarmonicOscillator, Pendulum, elliptic_k};
use pegdyn::system::FnSystem;

fn tight() -> Options {
    Options::with_tolerances(1e-10, 1e-12)
}

/// `θ = x[0]` falling through zero, terminal.
fn theta_falls_to_zero<'a>() -> Event<'a, 2> {
    Event::new(|_t, x: &Vector2<f64>| x[0])
        .direction(Direction::Falling)
        .terminal()
}

fn stop_time(stop: StopReason) -> f64 {
    match stop {
        StopReason::Event { t, .. } => t,
        other => panic!("expected a terminal event, got {other:?}"),
    }
}

/// K(k) by the arithmetic–geometric mean, written out here so the test
/// does not trust the library's copy.
fn agm_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    while (a - b).abs() > 1e-15 * a {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    FRAC_PI_2 / a
}

#[test]
fn linear_oscillator_zero_crossing_is_located_to_1e_10() {
    // q = cos(ωt) from rest at q = 1: first zero at π/(2ω).
    for omega in [1.0, 2.0, 7.5] {
        let osc = HarmonicOscillator { omega };
        let sol = Solver::new(Method::Dopri5, tight())
            .with_event(theta_falls_to_zero())
            .solve(&osc, 0.0, Vector2::new(1.0, 0.0), 10.0)
            .unwrap();
        let t = stop_time(sol.stop);
        let exact = FRAC_PI_2 / omega;
        assert!((t - exact).abs() < 1e-10, "ω={omega}: t={t}, exact {exact}");
        assert_eq!(sol.t_final, t);
        assert!(sol.x_final[0] <= 0.0 && sol.x_final[0] > -1e-10);
        // The trajectory ends on the event point.
        assert_eq!(*sol.t.last().unwrap(), t);
    }
}

#[test]
fn nonlinear_pendulum_quarter_period_matches_elliptic_integral() {
    let pendulum = Pendulum { g_over_l: 9.81 };
    for theta0 in [0.1, 1.0, 2.5, 3.0] {
        let sol = Solver::new(Method::Dopri5, tight())
            .with_event(theta_falls_to_zero())
            .solve(&pendulum, 0.0, Vector2::new(theta0, 0.0), 10.0)
            .unwrap();
        let t = stop_time(sol.stop);
        let k = (0.5 * theta0).sin();
        let exact = agm_k(k) / pendulum.g_over_l.sqrt();
        assert!((elliptic_k(k) - agm_k(k)).abs() < 1e-14);
        assert!(
            (t - exact).abs() < 1e-10,
            "θ0={theta0}: t={t}, K/ω={exact}, diff {:e}",
            t - exact
        );
        // Energy at the event equals the initial potential energy.
        let e0 = pendulum.energy(&Vector2::new(theta0, 0.0));
        assert!((pendulum.energy(&sol.x_final) - e0).abs() < 1e-8 * e0);
    }
}

#[test]
fn direction_filters_select_rising_falling_or_both() {
    // q = cos t on [0, 10]: falling zeros at π/2, 5π/2; rising at 3π/2.
    let osc = HarmonicOscillator { omega: 1.0 };
    let q = |_t: f64, x: &Vector2<f64>| x[0];
    let sol = Solver::new(Method::Dopri5, tight())
        .with_event(Event::new(q).direction(Direction::Rising))
        .with_event(Event::new(q).direction(Direction::Falling))
        .with_event(Event::new(q))
        .solve(&osc, 0.0, Vector2::new(1.0, 0.0), 10.0)
        .unwrap();
    assert_eq!(sol.stop, StopReason::ReachedEnd);
    let times = |index: usize| -> Vec<f64> {
        sol.events
            .iter()
            .filter(|e| e.index == index)
            .map(|e| e.t)
            .collect()
    };
    let expect = |got: Vec<f64>, want: &[f64]| {
        assert_eq!(got.len(), want.len(), "{got:?} vs {want:?}");
        for (g, w) in got.iter().zip(want) {
            assert!((g - w).abs() < 1e-9, "{got:?} vs {want:?}");
        }
    };
    expect(times(0), &[1.5 * PI]);
    expect(times(1), &[0.5 * PI, 2.5 * PI]);
    expect(times(2), &[0.5 * PI, 1.5 * PI, 2.5 * PI]);
    for hit in &sol.events {
        let rising = (hit.t - 1.5 * PI).abs() < 1e-6;
        assert_eq!(hit.rising, rising, "{hit:?}");
    }
    // Hits are reported in time order.
    assert!(sol.events.windows(2).all(|w| w[0].t <= w[1].t));
}

#[test]
fn terminal_event_stops_after_earlier_non_terminal_ones() {
    // q = cos t, q̇ = −sin t: q crosses zero at π/2 (non-terminal), q̇
    // rises through zero at π (terminal), q crosses again at 3π/2 (never seen).
    let osc = HarmonicOscillator { omega: 1.0 };
    let sol = Solver::new(Method::Dopri5, tight())
        .with_event(Event::new(|_t, x: &Vector2<f64>| x[0]))
        .with_event(
            Event::new(|_t, x: &Vector2<f64>| x[1])
                .direction(Direction::Rising)
                .terminal(),
        )
        .solve(&osc, 0.0, Vector2::new(1.0, 0.0), 10.0)
        .unwrap();
    let t = stop_time(sol.stop);
    assert!((t - PI).abs() < 1e-10);
    assert!(matches!(sol.stop, StopReason::Event { index: 1, .. }));
    assert_eq!(sol.events.len(), 2);
    assert_eq!(sol.events[0].index, 0);
    assert!((sol.events[0].t - FRAC_PI_2).abs() < 1e-10);
    assert_eq!(sol.events[1].index, 1);
    assert!((sol.x_final - Vector2::new(-1.0, 0.0)).amax() < 1e-9);
}

#[test]
fn terminal_event_truncates_requested_output_times() {
    let osc = HarmonicOscillator { omega: 1.0 };
    let times: Vec<f64> = (0..=40).map(|i| 0.25 * f64::from(i)).collect();
    let options = Options {
        output: OutputMode::AtTimes(times),
        ..tight()
    };
    let sol = Solver::new(Method::Dopri5, options)
        .with_event(theta_falls_to_zero())
        .solve(&osc, 0.0, Vector2::new(1.0, 0.0), 10.0)
        .unwrap();
    // Output at 0, 0.25, …, 1.5 only (the event is at π/2 ≈ 1.5708).
    assert_eq!(sol.t.len(), 7);
    assert_eq!(*sol.t.last().unwrap(), 1.5);
    for (t, x) in sol.t.iter().zip(&sol.x) {
        assert!((x[0] - t.cos()).abs() < 1e-9);
    }
}

#[test]
fn restart_from_located_event_does_not_fire_it_again() {
    let osc = HarmonicOscillator { omega: 1.0 };
    let first = Solver::new(Method::Dopri5, tight())
        .with_event(theta_falls_to_zero())
        .solve(&osc, 0.0, Vector2::new(1.0, 0.0), 20.0)
        .unwrap();
    let t1 = stop_time(first.stop);
    let second = Solver::new(Method::Dopri5, tight())
        .with_event(theta_falls_to_zero())
        .solve(&osc, t1, first.x_final, 20.0)
        .unwrap();
    let t2 = stop_time(second.stop);
    assert!((t2 - t1 - 2.0 * PI).abs() < 1e-9, "t1={t1}, t2={t2}");
}

#[test]
fn rk4_locates_events_on_its_hermite_interpolant() {
    let osc = HarmonicOscillator { omega: 1.0 };
    let sol = Solver::new(Method::Rk4 { h: 0.01 }, Options::default())
        .with_event(theta_falls_to_zero())
        .solve(&osc, 0.0, Vector2::new(1.0, 0.0), 10.0)
        .unwrap();
    let t = stop_time(sol.stop);
    assert!((t - FRAC_PI_2).abs() < 1e-9, "t={t}");
    assert_eq!(sol.stats.steps, 158);
}

#[test]
fn falling_body_reaches_ground_at_sqrt_2h_over_g() {
    // ẍ = −g from height 1 m at rest: ground contact at √(2/g) s.
    let g = 9.81;
    let fall = FnSystem(move |_t: f64, x: &Vector2<f64>| Vector2::new(x[1], -g));
    let sol = Solver::new(Method::Dopri5, Options::default())
        .with_event(
            Event::new(|_t, x: &Vector2<f64>| x[0])
                .direction(Direction::Falling)
                .terminal(),
        )
        .solve(&fall, 0.0, Vector2::new(1.0, 0.0), 5.0)
        .unwrap();
    let t = stop_time(sol.stop);
    assert!((t - (2.0 / g).sqrt()).abs() < 1e-13, "t={t}");
    assert!((sol.x_final[1] + (2.0 * g).sqrt()).abs() < 1e-12);
}

/// The number of evaluations a piecewise-constant event (the sign of
/// `cos t`, a count's kind of function) takes to be located, and the time
/// located, with the given time tolerance.
fn step_event_location(tolerance: f64) -> (f64, usize) {
    let osc = HarmonicOscillator { omega: 1.0 };
    let sol = Solver::new(Method::Dopri5, tight())
        .with_event(
            Event::new(|_t, x: &Vector2<f64>| if x[0] > 0.0 { 1.0 } else { -1.0 })
                .tolerance(tolerance),
        )
        .solve(&osc, 0.0, Vector2::new(1.0, 0.0), 2.0)
        .unwrap();
    assert_eq!(sol.events.len(), 1);
    (sol.events[0].t, sol.stats.event_calls)
}

#[test]
fn a_time_tolerance_bounds_the_location_of_a_step_event_and_saves_halvings() {
    // cos t changes sign at π/2; a step function is located by halving, so
    // the located time is the right end of a bracket no wider than the
    // tolerance (or a few ulps of t without one).
    let (t_ulps, calls_ulps) = step_event_location(0.0);
    assert!(
        t_ulps >= FRAC_PI_2 - 1e-10 && t_ulps - FRAC_PI_2 < 1e-10,
        "{t_ulps}"
    );
    for tol in [1e-9, 1e-6, 1e-3] {
        let (t, calls) = step_event_location(tol);
        // The interpolant's own zero is within 1e-10 of π/2.
        assert!(
            t >= FRAC_PI_2 - 1e-10 && t - FRAC_PI_2 <= tol + 1e-10,
            "{tol}: {t}"
        );
        // Each factor of two of the bracket not taken is one call saved.
        let saved = (tol / (4.0 * f64::EPSILON * 2.0)).log2().floor() as usize;
        assert!(
            calls + saved <= calls_ulps + 2,
            "{tol}: {calls} vs {calls_ulps}"
        );
    }
    // A negative or NaN tolerance is none.
    assert_eq!(step_event_location(-1.0), (t_ulps, calls_ulps));
    assert_eq!(step_event_location(f64::NAN), (t_ulps, calls_ulps));
}
