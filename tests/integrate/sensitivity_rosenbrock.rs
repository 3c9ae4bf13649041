//! Forward sensitivities by the Rosenbrock methods: the state and its
//! columns as one system whose Jacobian has the variational block form
//! (one factorization of the state's `cI − J` per step), the coupling
//! blocks `∂(J s + ∂f/∂p)/∂y` by differences of the rate.
//!
//! Van der Pol's oscillator `ẍ = μ (1 − x²) ẋ − x`, stiff at `μ = 20`,
//! with the sensitivities to `μ` and to the initial position through a
//! located event: RODAS3 and RODAS4 agree with a tight Dormand–Prince run
//! to the tolerance's order, and their error falls with the tolerance as
//! the methods' order says. Without the coupling blocks (a W-method's
//! Jacobian) RODAS4 at rtol 1e-7 is 4e-3 off and takes 100× the steps.

use nalgebra::{SMatrix, SVector, Vector2};
use pegdyn::integrate::{Method, Options, StopReason};
use pegdyn::sensitivity::{ParameterJacobian, SensitivityEvent, SensitivityRun, integrate};
use pegdyn::system::OdeSystem;

/// Van der Pol with `p = (μ, x₀)`; `x₀` enters only the start.
struct VanDerPol(f64);

impl OdeSystem<2> for VanDerPol {
    fn rhs(&self, _t: f64, y: &SVector<f64, 2>) -> SVector<f64, 2> {
        Vector2::new(y[1], self.0 * (1.0 - y[0] * y[0]) * y[1] - y[0])
    }
    fn jacobian(&self, _t: f64, y: &SVector<f64, 2>) -> SMatrix<f64, 2, 2> {
        SMatrix::from_row_slice(&[
            0.0,
            1.0,
            -2.0 * self.0 * y[0] * y[1] - 1.0,
            self.0 * (1.0 - y[0] * y[0]),
        ])
    }
    fn time_derivative(&self, _t: f64, _y: &SVector<f64, 2>) -> SVector<f64, 2> {
        SVector::zeros()
    }
}

impl ParameterJacobian<2, 2> for VanDerPol {
    fn parameters(&self) -> SVector<f64, 2> {
        Vector2::new(self.0, 2.0)
    }
    fn parameter_jacobian(&self, _t: f64, y: &SVector<f64, 2>) -> SMatrix<f64, 2, 2> {
        SMatrix::from_row_slice(&[0.0, 0.0, (1.0 - y[0] * y[0]) * y[1], 0.0])
    }
}

const T_END: f64 = 50.0;

/// The run of `method` at `rtol` with the crossings of `x = 1` as
/// non-terminal events (three in the span, at the relaxation jumps).
fn run(method: Method, rtol: f64) -> SensitivityRun<2, 2> {
    let crossing = SensitivityEvent::new(
        |_, y: &SVector<f64, 2>| y[0] - 1.0,
        |_, _| (Vector2::new(1.0, 0.0), Vector2::zeros()),
    );
    let options = Options {
        max_steps: 2_000_000,
        ..Options::with_tolerances(rtol, rtol * 1e-2)
    };
    // s(0) = ∂y₀/∂p: x₀ is the second parameter.
    let s0 = SMatrix::<f64, 2, 2>::from_row_slice(&[0.0, 1.0, 0.0, 0.0]);
    let r = integrate::<_, 2, 2, 6>(
        &VanDerPol(20.0),
        (0.0, Vector2::new(2.0, 0.0), s0),
        T_END,
        method,
        &options,
        vec![crossing],
    )
    .expect("runs");
    assert_eq!(r.stop, StopReason::ReachedEnd);
    r
}

/// The largest difference of the final sensitivities and the events'
/// time derivatives, relative to their size.
fn difference(a: &SensitivityRun<2, 2>, b: &SensitivityRun<2, 2>) -> f64 {
    assert_eq!(a.events.len(), b.events.len(), "the same crossings");
    let s = (a.s - b.s).amax() / a.s.amax();
    a.events
        .iter()
        .zip(&b.events)
        .map(|(x, y)| (x.dt_dp - y.dt_dp).amax() / x.dt_dp.amax())
        .fold(s, f64::max)
}

#[test]
fn rosenbrock_sensitivities_of_a_stiff_oscillator_match_a_tight_explicit_run() {
    let reference = run(Method::Dopri5, 1e-12);
    assert!(
        reference.events.len() >= 2,
        "crossings: {}",
        reference.events.len()
    );
    for (method, rtol, bound) in [
        (Method::Rodas4, 1e-7, 2e-5),
        (Method::Rodas4, 1e-9, 2e-7),
        (Method::Rodas3, 1e-8, 1e-5),
    ] {
        let r = run(method, rtol);
        let d = difference(&reference, &r);
        assert!(d < bound, "{method:?} rtol {rtol}: {d:.2e}");
        // the linearly implicit path: one Jacobian per step
        assert!(r.stats.jacobian_calls > 0 && r.stats.lu_factorizations >= r.stats.steps);
    }
}

#[test]
fn the_rosenbrock_sensitivities_error_falls_with_the_tolerance() {
    let reference = run(Method::Dopri5, 1e-12);
    let coarse = difference(&reference, &run(Method::Rodas4, 1e-6));
    let fine = difference(&reference, &run(Method::Rodas4, 1e-8));
    // a method of order 4 with its error controlled on the sensitivities:
    // 100× tighter gives well over 10× smaller errors
    assert!(
        fine < coarse / 10.0,
        "rtol 1e-6: {coarse:.2e}, 1e-8: {fine:.2e}"
    );
}
