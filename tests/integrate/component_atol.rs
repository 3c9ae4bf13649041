//! `Options::component_atol`: an absolute tolerance per leading component,
//! for a state whose components have different units or scales.

use nalgebra::{Vector2, Vector3};
use pegdyn::integrate::{IntegrateError, Method, Options, Solver};
use pegdyn::system::FnSystem;

/// A damped oscillator `x″ = −x − 0.1 x′` written for `(x, v/s)`: the
/// velocity held in units `s` times larger, so that its values are `1/s`
/// of the plain form's.
fn oscillator(s: f64) -> FnSystem<impl Fn(f64, &Vector2<f64>) -> Vector2<f64>> {
    FnSystem(move |_t: f64, y: &Vector2<f64>| {
        let v = y[1] * s;
        Vector2::new(v, (-y[0] - 0.1 * v) / s)
    })
}

#[test]
fn a_component_scaled_with_its_tolerance_takes_the_same_steps() {
    // Scaling a component by a power of two and its absolute tolerance by
    // the same factor changes no rounding in DOPRI5: the weighted errors,
    // the steps and the unscaled solution are the same bit for bit. The
    // Rosenbrock methods' finite-difference Jacobian perturbs each
    // component by an amount not proportional to it, so there the steps
    // are the same and the solution agrees to 1e-9.
    let s = 2f64.powi(20);
    for method in [Method::Dopri5, Method::Rodas3, Method::Rodas4] {
        let plain = Solver::new(method, Options::with_tolerances(1e-6, 1e-6))
            .solve(&oscillator(1.0), 0.0, Vector2::new(1.0, 0.0), 20.0)
            .expect("solves");
        let scaled = Options {
            component_atol: vec![1e-6, 1e-6 / s],
            ..Options::with_tolerances(1e-6, 1e-6)
        };
        let sol = Solver::new(method, scaled)
            .solve(&oscillator(s), 0.0, Vector2::new(1.0, 0.0), 20.0)
            .expect("solves");
        assert_eq!(sol.stats.steps, plain.stats.steps, "{method:?}");
        assert_eq!(sol.stats.rejected, plain.stats.rejected, "{method:?}");
        let tol = if method == Method::Dopri5 { 0.0 } else { 1e-9 };
        assert!(
            (sol.x_final[0] - plain.x_final[0]).abs() <= tol
                && (sol.x_final[1] * s - plain.x_final[1]).abs() <= tol,
            "{method:?}: {:?} against {:?}",
            sol.x_final,
            plain.x_final
        );
        // One tolerance for both: the velocity, about 1e-6 in size, is
        // held to 1e-6 absolute, no digit at all, and the run takes fewer
        // steps than one that controls it.
        let one = Solver::new(method, Options::with_tolerances(1e-6, 1e-6))
            .solve(&oscillator(s), 0.0, Vector2::new(1.0, 0.0), 20.0)
            .expect("solves");
        assert!(
            one.stats.steps < plain.stats.steps,
            "{method:?}: {} against {}",
            one.stats.steps,
            plain.stats.steps
        );
    }
}

#[test]
fn components_past_the_list_keep_atol() {
    // A list shorter than the state: the rest use `atol`, so a list that
    // repeats `atol` is no list at all.
    let sys = FnSystem(|_t: f64, y: &Vector3<f64>| Vector3::new(y[1], -y[0], -y[2]));
    let y0 = Vector3::new(1.0, 0.0, 1e-3);
    let base = Options::with_tolerances(1e-7, 1e-9);
    let without = Solver::new(Method::Dopri5, base.clone())
        .solve(&sys, 0.0, y0, 5.0)
        .expect("solves");
    let repeated = Options {
        component_atol: vec![1e-9],
        ..base.clone()
    };
    let with = Solver::new(Method::Dopri5, repeated)
        .solve(&sys, 0.0, y0, 5.0)
        .expect("solves");
    assert_eq!(with.stats.steps, without.stats.steps);
    assert_eq!(with.x_final, without.x_final);
}

#[test]
fn bad_component_tolerances_are_refused_naming_the_option() {
    let sys = FnSystem(|_t: f64, y: &Vector2<f64>| -y);
    for list in [vec![1e-8, 0.0], vec![f64::NAN], vec![-1.0], vec![1e-8; 3]] {
        let options = Options {
            component_atol: list.clone(),
            ..Options::default()
        };
        match Solver::new(Method::Dopri5, options).solve(&sys, 0.0, Vector2::new(1.0, 1.0), 1.0) {
            Err(IntegrateError::InvalidOption { name, .. }) => {
                assert_eq!(name, "component_atol", "{list:?}")
            }
            other => panic!("{list:?}: {other:?}"),
        }
    }
}
