//! Every numeric kernel terminates and answers with a finite value or a
//! typed error, whatever it is fed: property tests over extreme magnitudes
//! (log-uniform over ±300 decades, both signs), zeros, subnormals, NaN and
//! ±inf.

use pegdyn::hertz::elliptic::{carlson_rd, carlson_rf, complete_integrals};
use pegdyn::hertz::ellipticity::{MAX_RATIO, solve, try_solve};
use pegdyn::hertz::{Curvatures, EllipticityMethod, HertzContact, HertzError, Material};
use proptest::prelude::*;

/// Any f64 a hostile scene could produce: log-uniform magnitudes over
/// ±300 decades with either sign, and the special values.
fn hostile() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => (-300.0..300.0f64, any::<bool>())
            .prop_map(|(e, neg)| if neg { -(10f64.powf(e)) } else { 10f64.powf(e) }),
        1 => prop_oneof![
            Just(0.0),
            Just(-0.0),
            Just(f64::MIN_POSITIVE / 8.0),
            Just(f64::MIN_POSITIVE),
            Just(f64::MAX),
            Just(f64::NAN),
            Just(f64::INFINITY),
            Just(f64::NEG_INFINITY),
            Just(1.0),
        ],
    ]
}

/// A positive magnitude, log-uniform over ±300 decades.
fn magnitude() -> impl Strategy<Value = f64> {
    (-300.0..300.0f64).prop_map(|e| 10f64.powf(e))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// `R_F`, `R_D`: NaN outside the domain, finite and positive inside it.
    #[test]
    fn carlson_terminates_with_finite_or_nan(x in hostile(), y in hostile(), z in hostile()) {
        for v in [carlson_rf(x, y, z), carlson_rd(x, y, z)] {
            prop_assert!(v.is_nan() || (v >= 0.0), "R = {v} at ({x:e}, {y:e}, {z:e})");
        }
        let in_domain = [x, y, z].iter().all(|v| v.is_finite() && *v > 0.0)
            && [x, y, z].iter().all(|v| *v > 1e-150 && *v < 1e150);
        if in_domain {
            let rf = carlson_rf(x, y, z);
            prop_assert!(rf.is_finite() && rf > 0.0, "R_F = {rf} at ({x:e}, {y:e}, {z:e})");
        }
    }

    /// `complete_integrals` on any complement: all-NaN outside `(0, 1]`,
    /// finite with `K ≥ π/2 ≥ ... ≥ E ≥ 1` inside.
    #[test]
    fn complete_integrals_terminate(mc in hostile()) {
        let i = complete_integrals(mc);
        if mc > 0.0 && mc <= 1.0 {
            prop_assert!(i.k.is_finite() && i.k >= std::f64::consts::FRAC_PI_2 - 1e-15, "{i:?}");
            prop_assert!(i.e >= 1.0 - 1e-12 && i.e <= std::f64::consts::FRAC_PI_2 + 1e-15, "{i:?}");
        } else {
            prop_assert!(i.k.is_nan() && i.e.is_nan(), "mc = {mc:e}: {i:?}");
        }
    }

    /// The ellipticity solve: a typed error or an ellipticity that
    /// reproduces the ratio.
    #[test]
    fn ellipticity_solve_answers_or_refuses(ratio in hostile()) {
        match try_solve(ratio) {
            Ok(el) => {
                prop_assert!(ratio > 0.0 && ratio <= MAX_RATIO, "accepted {ratio:e}");
                prop_assert!(el.kappa >= 1.0 && el.kappa.is_finite(), "{el:?}");
                if ratio > 2.0 {
                    let kk = el.kappa * el.kappa;
                    let back = (el.e * kk - el.k) / (el.k - el.e);
                    prop_assert!(((back - ratio) / ratio).abs() < 1e-9, "{ratio:e} -> {back:e}");
                }
            }
            Err(HertzError::LineContact { ratio: r, limit }) => {
                prop_assert!(r > limit && limit == MAX_RATIO);
            }
            Err(HertzError::Invalid { value, .. }) => {
                prop_assert!(value.is_nan() || value <= 0.0, "refused {value:e}");
            }
            Err(e) => prop_assert!(false, "unexpected {e} for {ratio:e}"),
        }
        // The untyped form agrees: NaN exactly when the typed one refuses.
        prop_assert_eq!(solve(ratio).kappa.is_nan(), try_solve(ratio).is_err());
    }

    /// A Hertz contact from extreme curvatures and moduli: refused with a
    /// typed error, or a finite positive stiffness and finite state.
    #[test]
    fn hertz_contact_is_finite_or_refused(
        c1 in hostile(), c2 in hostile(), angle in hostile(),
        e1 in magnitude(), e2 in magnitude(), q in magnitude(),
        fit in any::<bool>(),
    ) {
        let method = if fit { EllipticityMethod::HamrockBrewe } else { EllipticityMethod::Exact };
        let m1 = Material { youngs_modulus: e1, poisson_ratio: 0.3 };
        let m2 = Material { youngs_modulus: e2, poisson_ratio: 0.3 };
        let curv = Curvatures { body1: [c1, c2], body2: [0.0, 0.0], angle };
        if let Ok(c) = HertzContact::try_new(&curv, &m1, &m2, method) {
            let k = c.stiffness();
            prop_assert!(k.is_finite() && k > 0.0, "k = {k:e} for {c:?}");
            let s = c.state(q);
            prop_assert!(!s.a.is_nan() && !s.b.is_nan() && !s.delta.is_nan(), "{s:?}");
        }
    }
}

#[test]
fn degenerate_arguments_that_used_to_loop_return_nan() {
    // Two zero arguments: the duplication never brings the spread below
    // its tolerance.
    assert!(carlson_rd(0.0, 0.0, 1.0).is_nan());
    assert!(carlson_rf(0.0, 0.0, 1.0).is_nan());
    assert!(carlson_rf(f64::NAN, 1.0, 1.0).is_nan());
    // A fillet of 1e-200 m against a hole of radius 25 mm.
    assert!(matches!(
        try_solve(0.025 / 1e-200),
        Err(HertzError::LineContact { .. })
    ));
}

/// A pendulum released from rest with a tolerance far below f64
/// resolution, or with a first-step hint of 1e-300 s, takes steps instead
/// of stopping at t0 ("step size too small" before any step).
#[test]
fn first_step_from_rest_is_not_below_the_step_floor() {
    use nalgebra::Vector2;
    use pegdyn::integrate::{Method, Options, Solver, StopReason};
    use pegdyn::system::FnSystem;
    let g = 9.80665;
    let pendulum = FnSystem(move |_t: f64, x: &Vector2<f64>| Vector2::new(x[1], -g * x[0].sin()));
    for (atol, h0) in [(1e-25, None), (1e-12, Some(1e-300))] {
        let mut options = Options::with_tolerances(1e-10, atol);
        options.h0 = h0;
        let sol = Solver::new(Method::Dopri5, options)
            .solve(&pendulum, 0.0, Vector2::new(1.0, 0.0), 1.0)
            .unwrap();
        assert_eq!(sol.stop, StopReason::ReachedEnd, "atol {atol:e}, h0 {h0:?}");
        assert!(sol.stats.steps > 10);
        // The small-angle period is 2.006 s: at t = 1 s the pendulum has
        // swung to the other side.
        assert!(sol.x_final[0] < -0.9, "{}", sol.x_final[0]);
    }
}
