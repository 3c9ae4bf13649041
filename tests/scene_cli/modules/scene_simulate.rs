//! The items of `src/scene/simulate.rs`.

use nalgebra::Vector2;
use pegdyn::integrate::Direction;
use pegdyn::integrate::{
    self, Event, MethodKind, NonFiniteAt, NonFiniteQuantity, OutputMode, StopReason,
};
use pegdyn::internals::scene::*;
use pegdyn::scene::Progress;
use pegdyn::scene::integrator::IntegratorSpec;
use pegdyn::scene::integrator::Method;
use pegdyn::system::FnSystem;

fn spec(method: Method, h: Option<f64>) -> IntegratorSpec {
    IntegratorSpec {
        method,
        rtol: 1e-9,
        atol: 1e-12,
        h,
        t0: 0.0,
        t_end: 2.0,
        output_interval: Some(0.5),
        max_steps: 100_000,
        atol_scale: Default::default(),
    }
}

#[test]
fn config_maps_methods_and_output_times() {
    let (m, o) = solver_config(&spec(Method::Named(MethodKind::Rk4), Some(0.01)), &[]).unwrap();
    assert_eq!(m, integrate::Method::Rk4 { h: 0.01 });
    assert_eq!(o.output, OutputMode::AtTimes(vec![0.0, 0.5, 1.0, 1.5, 2.0]));
    assert_eq!(o.h0, None);
    let (m, o) = solver_config(&spec(Method::Named(MethodKind::Dopri5), Some(1e-3)), &[]).unwrap();
    assert_eq!(
        (m, o.h0, o.rtol, o.atol),
        (integrate::Method::Dopri5, Some(1e-3), 1e-9, 1e-12)
    );
    assert!(solver_config(&spec(Method::Named(MethodKind::Rk4), None), &[]).is_err());
    let (m, _) = solver_config(&spec(Method::Named(MethodKind::Rodas3), None), &[]).unwrap();
    assert_eq!(m, integrate::Method::Rodas3);
}

#[test]
fn atol_scale_sets_the_named_components_and_names_a_wrong_one() {
    let names = ["x", "v", "w", "e"];
    let mut s = spec(Method::Named(MethodKind::Rodas4), None);
    let (_, o) = solver_config(&s, &names).unwrap();
    assert!(o.component_atol.is_empty());
    s.atol_scale.insert("w".into(), 64.0);
    s.atol_scale.insert("x".into(), 0.5);
    let (_, o) = solver_config(&s, &names).unwrap();
    // atol (1e-12) times the factor up to the last named component; the
    // others keep atol.
    assert_eq!(o.component_atol, vec![0.5e-12, 1e-12, 64e-12]);
    assert_eq!(
        (o.atol_of(1), o.atol_of(2), o.atol_of(3)),
        (1e-12, 64e-12, 1e-12)
    );
    s.atol_scale.insert("omega".into(), 10.0);
    let e = solver_config(&s, &names).unwrap_err().to_string();
    assert!(e.contains("integrator.atol_scale.omega"), "{e}");
    assert!(e.contains("x, v, w, e"), "{e}");
}

#[test]
fn terminal_event_is_named_in_the_summary() {
    // Falling body from 1 m: hits the ground at t = sqrt(2/g).
    let g = 9.81;
    let fall = FnSystem(move |_t: f64, x: &Vector2<f64>| Vector2::new(x[1], -g));
    let ground = Event::new(|_t, x: &Vector2<f64>| x[0])
        .direction(Direction::Falling)
        .terminal();
    let s = spec(Method::Named(MethodKind::Dopri5), None);
    let mut progress = Progress::silent();
    let sol = integrate(
        &fall,
        Vector2::new(1.0, 0.0),
        &s,
        vec![ground],
        &mut progress,
    )
    .unwrap();
    let summary = integration_summary(&s, &sol, &["ground"]);
    assert!(summary.success);
    assert!(
        (summary.t_end - (2.0 / g).sqrt()).abs() < 1e-9,
        "{}",
        summary.t_end
    );
    assert!(
        summary.stop.starts_with("event `ground` at t = 0.45"),
        "{}",
        summary.stop
    );
    assert!(summary.rhs_calls > summary.steps);
    let [hit] = &summary.events[..] else {
        panic!("{:?}", summary.events)
    };
    assert_eq!(
        (hit.name.as_str(), hit.t, hit.terminal),
        ("ground", summary.t_end, true)
    );
    assert_eq!(hit.details[0], ("direction".to_string(), -1.0));
    assert_eq!(hit.details[1].0, "x[0]");
    assert!(hit.details[1].1.abs() < 1e-9, "{:?}", hit.details);
}

#[test]
fn passing_events_are_reported_before_the_terminal_one() {
    // Falling body from 1 m: passes 0.5 m at sqrt(1/g), lands at sqrt(2/g).
    let g = 9.81;
    let fall = FnSystem(move |_t: f64, x: &Vector2<f64>| Vector2::new(x[1], -g));
    let half = Event::new(|_t, x: &Vector2<f64>| x[0] - 0.5);
    let ground = Event::new(|_t, x: &Vector2<f64>| x[0]).terminal();
    let s = spec(Method::Named(MethodKind::Dopri5), None);
    let mut progress = Progress::silent();
    let sol = integrate(
        &fall,
        Vector2::new(1.0, 0.0),
        &s,
        vec![half, ground],
        &mut progress,
    )
    .unwrap();
    let events = event_records(&sol, &["half_way"]);
    let got: Vec<(&str, bool)> = events
        .iter()
        .map(|e| (e.name.as_str(), e.terminal))
        .collect();
    assert_eq!(got, [("half_way", false), ("#1", true)]);
    assert!(
        (events[0].t - (1.0 / g).sqrt()).abs() < 1e-9,
        "{}",
        events[0].t
    );
    assert!(
        (events[0].details[1].1 - 0.5).abs() < 1e-9,
        "{:?}",
        events[0].details
    );
    assert!(
        (events[1].t - (2.0 / g).sqrt()).abs() < 1e-9,
        "{}",
        events[1].t
    );
}

#[test]
fn a_non_finite_stop_names_component_time_and_cause() {
    let nf = NonFiniteAt {
        t: 0.25,
        index: 3,
        name: Some("psidot"),
        quantity: NonFiniteQuantity::Rate,
        value: f64::INFINITY,
        last_finite: 6.3e76,
        largest: 1e300,
    };
    let s = describe_stop_at(&StopReason::NonFinite { t: 0.25 }, Some(&nf), &[]);
    for part in [
        "t = 0.25 s",
        "rate of `psidot`",
        "inf",
        "6.3e76",
        "likely cause: overflow",
    ] {
        assert!(s.contains(part), "{part:?} missing in {s}");
    }
    // Without a probe the generic account stays.
    let s = describe_stop_at(&StopReason::NonFinite { t: 0.25 }, None, &[]);
    assert!(
        s.starts_with("state became non-finite after t = 0.25 s"),
        "{s}"
    );
}

#[test]
fn unplanned_stops_are_described() {
    let s = describe_stop(&StopReason::MaxSteps { t: 0.5, steps: 10 }, &[]);
    assert_eq!(s, "step budget of 10 steps exhausted at t = 0.5 s");
    let s = describe_stop(&StopReason::Event { index: 2, t: 1.0 }, &["a"]);
    assert_eq!(s, "event #2 at t = 1 s");
}
