//! `Solver::with_step_observer`: the end of every accepted step, whatever
//! the output mode, and a terminal event's point for the step it ends: what
//! the scenes take their peaks over, so that an impact between two output
//! times is not missed.

use nalgebra::Vector2;
use pegdyn::integrate::{Direction, Event, Method, Options, OutputMode, Solver, StopReason};
use pegdyn::system::FnSystem;

#[test]
fn every_accepted_step_ends_there_and_a_terminal_event_ends_the_last() {
    // A damped oscillator sampled at three output times only, stopped
    // where x falls through −0.5: the observer sees one point per accepted
    // step, in increasing time, the last at the event; its largest |v|
    // exceeds the samples' (the peak speed falls between them).
    let sys = FnSystem(|_t: f64, y: &Vector2<f64>| Vector2::new(y[1], -25.0 * y[0] - 0.2 * y[1]));
    let options = Options {
        output: OutputMode::AtTimes(vec![0.0, 0.05, 0.1]),
        ..Options::with_tolerances(1e-8, 1e-10)
    };
    let mut seen: Vec<(f64, f64)> = Vec::new();
    let sol = {
        let mut solver = Solver::new(Method::Dopri5, options)
            .with_event(
                Event::new(|_, y: &Vector2<f64>| y[0] + 0.5)
                    .direction(Direction::Falling)
                    .terminal(),
            )
            .with_step_observer(|t, y| seen.push((t, y[1])));
        solver
            .solve(&sys, 0.0, Vector2::new(1.0, 0.0), 5.0)
            .expect("solves")
    };
    let StopReason::Event { t, .. } = sol.stop else {
        panic!("the run ends at its event: {:?}", sol.stop);
    };
    assert_eq!(seen.len(), sol.stats.steps);
    assert!(seen.windows(2).all(|w| w[0].0 < w[1].0));
    assert_eq!(seen.last().map(|p| p.0), Some(t));
    assert!(t > 0.1, "the event lies past the samples: {t}");
    let over_steps = seen.iter().map(|p| p.1.abs()).fold(0.0, f64::max);
    let over_samples = sol.x.iter().map(|y| y[1].abs()).fold(0.0, f64::max);
    // |v| peaks near 5 (x = cos 5t, v = −5 sin 5t) at t ≈ 0.31 s, past
    // the last sample.
    assert!(
        over_steps > 4.5 && over_samples < 2.5,
        "{over_steps}, {over_samples}"
    );
}
