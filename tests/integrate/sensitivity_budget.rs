//! The step budget of a forward-sensitivity run bounds the whole run: its
//! restarts at the located events share `Options::max_steps` instead of
//! each starting afresh. An oscillator `ẍ = −k x` crosses `x = 0` every
//! `π/√k`; with half the attempts the full run needs, the run stops short
//! on `MaxSteps` having attempted no more than that, although each of its
//! pieces between crossings needs far fewer.

use nalgebra::{SMatrix, SVector, Vector1, Vector2};
use pegdyn::integrate::{Method, Options, StopReason};
use pegdyn::sensitivity::{ParameterJacobian, SensitivityEvent, integrate};
use pegdyn::system::OdeSystem;

struct Oscillator(f64);

impl OdeSystem<2> for Oscillator {
    fn rhs(&self, _t: f64, y: &SVector<f64, 2>) -> SVector<f64, 2> {
        Vector2::new(y[1], -self.0 * y[0])
    }
    fn jacobian(&self, _t: f64, _y: &SVector<f64, 2>) -> SMatrix<f64, 2, 2> {
        SMatrix::from_row_slice(&[0.0, 1.0, -self.0, 0.0])
    }
}

impl ParameterJacobian<2, 1> for Oscillator {
    fn parameters(&self) -> SVector<f64, 1> {
        Vector1::new(self.0)
    }
    fn parameter_jacobian(&self, _t: f64, y: &SVector<f64, 2>) -> SMatrix<f64, 2, 1> {
        SMatrix::from_row_slice(&[0.0, -y[0]])
    }
}

fn run(max_steps: usize) -> pegdyn::sensitivity::SensitivityRun<2, 1> {
    let crossing = SensitivityEvent::new(
        |_, y: &SVector<f64, 2>| y[0],
        |_, _| (Vector2::new(1.0, 0.0), Vector1::zeros()),
    );
    let options = Options {
        max_steps,
        ..Options::with_tolerances(1e-10, 1e-12)
    };
    integrate::<_, 2, 1, 4>(
        &Oscillator(4.0),
        (0.0, Vector2::new(1.0, 0.0), SMatrix::zeros()),
        10.0,
        Method::Dopri5,
        &options,
        vec![crossing],
    )
    .unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn the_restarts_share_the_step_budget() {
    let full = run(1_000_000);
    assert_eq!(full.stop, StopReason::ReachedEnd);
    // x = cos 2t crosses zero at π/4 + jπ/2: six times before t = 10.
    assert_eq!(full.events.len(), 6);
    let (t, want) = (full.events[0].t, std::f64::consts::FRAC_PI_4);
    assert!((t - want).abs() < 1e-9, "{t} vs {want}");
    let attempts = full.stats.steps + full.stats.rejected;
    let half = attempts / 2;
    let short = run(half);
    let StopReason::MaxSteps { t, steps } = short.stop else {
        panic!("{:?}", short.stop)
    };
    assert_eq!(steps, short.stats.steps + short.stats.rejected);
    assert!(steps <= half && steps + 2 > half, "{steps} of {half}");
    assert!(t < 10.0 && short.t < 10.0 && short.events.len() < 6, "{t}");
}

#[test]
fn a_stop_rule_ends_the_run_without_an_event_and_an_observer_sees_every_step() {
    // x = cos 2t with a step function for a stop rule (x below 0.5: the
    // rule's value jumps, which a gradient could not serve): the run ends
    // at 2t = π/3 with nothing in `events`, and ∂x/∂k there is the exact
    // −t sin(√k t)/(2√k) = −(t/4) sin 2t (x = cos(√k t), k = 4).
    let rule = SensitivityEvent::stop(|_, y: &SVector<f64, 2>| if y[0] < 0.5 { 1.0 } else { -1.0 })
        .direction(pegdyn::integrate::Direction::Rising);
    let options = Options::with_tolerances(1e-10, 1e-12);
    let mut seen = Vec::new();
    let run = pegdyn::sensitivity::integrate_observed::<_, 2, 1, 4>(
        &Oscillator(4.0),
        (0.0, Vector2::new(1.0, 0.0), SMatrix::zeros()),
        10.0,
        Method::Dopri5,
        &options,
        vec![rule],
        &mut |t, y, s| seen.push((t, y[0], s[(0, 0)])),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let StopReason::Event { index: 0, t } = run.stop else {
        panic!("the rule ends the run: {:?}", run.stop);
    };
    assert!(run.events.is_empty());
    let want = std::f64::consts::PI / 6.0;
    assert!((t - want).abs() < 1e-9, "{t} vs {want}");
    let exact = -(t / 4.0) * (2.0 * t).sin();
    assert!(
        (run.s[(0, 0)] - exact).abs() < 1e-8,
        "{} vs {exact}",
        run.s[(0, 0)]
    );
    // The start and every accepted step's end, the last at the stop.
    assert_eq!(seen.len(), run.stats.steps + 1);
    assert_eq!(seen.last().map(|p| p.0), Some(t));
    for (t, x, s) in &seen {
        assert!((x - (2.0 * t).cos()).abs() < 1e-8);
        assert!((s + (t / 4.0) * (2.0 * t).sin()).abs() < 1e-8);
    }
}
