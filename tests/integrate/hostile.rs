//! The integrator engine under hostile options and systems: tolerances
//! f64 cannot meet and absurd step budgets are typed errors, and a run that
//! turns non-finite stops naming the component, the time and a likely
//! cause.

use nalgebra::{SVector, Vector2};
use pegdyn::integrate::{
    IntegrateError, MAX_STEP_BUDGET, MIN_ATOL, MIN_RTOL, Method, NonFiniteQuantity, Options,
    StopReason, solve,
};
use pegdyn::system::{FnSystem, OdeSystem};

fn oscillator() -> FnSystem<impl Fn(f64, &Vector2<f64>) -> Vector2<f64>> {
    FnSystem(|_t: f64, x: &Vector2<f64>| Vector2::new(x[1], -x[0]))
}

fn refused(options: &Options) -> (&'static str, f64) {
    match solve(
        &oscillator(),
        Method::Dopri5,
        (0.0, Vector2::new(1.0, 0.0)),
        1.0,
        options,
    ) {
        Err(IntegrateError::InvalidOption { name, value, .. }) => (name, value),
        other => panic!("{options:?} gave {other:?}"),
    }
}

#[test]
fn tolerances_below_f64_resolution_and_absurd_budgets_are_typed_errors() {
    // The fuzzed rigid-peg scene ran without end at rtol = 1.3e-293.
    let o = Options::with_tolerances(1.3e-293, 1e-12);
    assert_eq!(refused(&o), ("rtol", 1.3e-293));
    let o = Options::with_tolerances(f64::INFINITY, 1e-12);
    assert_eq!(refused(&o), ("rtol", f64::INFINITY));
    let o = Options::with_tolerances(1e-6, 1e-320);
    assert_eq!(refused(&o), ("atol", 1e-320));
    let o = Options {
        max_steps: MAX_STEP_BUDGET + 1,
        ..Options::default()
    };
    assert_eq!(refused(&o), ("max_steps", (MAX_STEP_BUDGET + 1) as f64));
    // The floors themselves are accepted and run to the end, close to cos.
    let o = Options::with_tolerances(MIN_RTOL, MIN_ATOL);
    let sol = solve(
        &oscillator(),
        Method::Dopri5,
        (0.0, Vector2::new(1.0, 0.0)),
        1.0,
        &o,
    )
    .unwrap();
    assert_eq!(sol.stop, StopReason::ReachedEnd);
    assert!(
        (sol.x_final[0] - 1f64.cos()).abs() < 1e-13,
        "{}",
        sol.x_final[0]
    );
    assert!(sol.non_finite.is_none());
}

/// `ẋ = 1`, `v̇ = 0` before `t = 0.5`, NaN from there on: the rate of the
/// second component, named `v`, turns non-finite at a finite state.
struct Breaks;

impl OdeSystem<2> for Breaks {
    fn rhs(&self, t: f64, _x: &Vector2<f64>) -> Vector2<f64> {
        Vector2::new(1.0, if t < 0.5 { 0.0 } else { f64::NAN })
    }
    fn state_names(&self) -> &'static [&'static str] {
        &["x", "v"]
    }
}

#[test]
fn a_non_finite_stop_names_the_component_and_the_time() {
    for method in [Method::Dopri5, Method::Rodas4, Method::Rk4 { h: 0.01 }] {
        let sol = solve(
            &Breaks,
            method,
            (0.0, Vector2::zeros()),
            1.0,
            &Options::default(),
        )
        .unwrap();
        let StopReason::NonFinite { t } = sol.stop else {
            panic!("{method:?}: {:?}", sol.stop)
        };
        assert!((0.48..0.5).contains(&t), "{method:?}: t = {t}");
        let nf = sol.non_finite.expect("the probe finds the component");
        assert_eq!(
            (nf.index, nf.name, nf.quantity, nf.t),
            (1, Some("v"), NonFiniteQuantity::Rate, t),
            "{method:?}"
        );
        assert!(nf.value.is_nan() && nf.last_finite == 0.0);
        assert!(
            nf.likely_cause().contains("undefined"),
            "{}",
            nf.likely_cause()
        );
        assert_eq!(nf.component(), "`v`");
    }
}

/// `ẋ₀ = 1`, `ẋ₁ = x₁³` from `x₁ = 1e100`: blows up at `t = 5e-201`, far
/// below the step floor, so the first step overflows.
#[test]
fn overflow_is_named_as_the_likely_cause() {
    let blow_up = FnSystem(|_t: f64, x: &Vector2<f64>| Vector2::new(1.0, x[1].powi(3)));
    let sol = solve(
        &blow_up,
        Method::Dopri5,
        (0.0, Vector2::new(0.0, 1e100)),
        1.0,
        &Options::default(),
    )
    .unwrap();
    assert!(
        matches!(sol.stop, StopReason::NonFinite { t } if t == 0.0),
        "{:?}",
        sol.stop
    );
    let nf = sol.non_finite.expect("probed");
    assert_eq!((nf.index, nf.name), (1, None));
    assert_eq!(nf.component(), "component #1");
    assert!(nf.largest >= 1e299, "{}", nf.largest);
    assert!(
        nf.likely_cause().starts_with("overflow"),
        "{}",
        nf.likely_cause()
    );
    let x: SVector<f64, 2> = sol.x_final;
    assert!(x.iter().all(|v| v.is_finite()));
}
