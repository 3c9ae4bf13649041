//! Checks of the generated spherical-pendulum model: the generated code
//! against the generator's interpreter, the exact Jacobian against finite
//! differences, and the conserved energy and angular momentum of a
//! simulation that hits the floor.

#[path = "../model.rs"]
mod model;

use nalgebra::SVector;
use own_model::generated::spherical_pendulum as sp;
use own_model::{initial_state, parameters};
use pegdyn::integrate::{Method, Options, solve};
use pegdyn::system::{OdeSystem, finite_difference_jacobian};
use pegdyn_equations::{GenError, Generator};

/// Distance in units in the last place between two finite `f64`s.
fn ulps(a: f64, b: f64) -> u64 {
    let key = |x: f64| {
        let bits = x.to_bits() as i64;
        if bits < 0 { i64::MIN - bits } else { bits }
    };
    key(a).abs_diff(key(b))
}

/// States spread over the swing, some in contact with the floor.
fn states() -> Vec<SVector<f64, 4>> {
    (0..40)
        .map(|i| {
            let s = f64::from(i);
            SVector::from([
                0.05 + 0.03 * s,
                0.7 * s,
                (0.37 * s).sin() * 3.0,
                (0.11 * s).cos() * 2.0,
            ])
        })
        .collect()
}

#[test]
fn generated_code_matches_the_interpreter() {
    let mut generator = Generator::new(pegdyn_equations::Options::default());
    model::declare(&mut generator).unwrap();
    let p = SVector::from(parameters());
    let mut worst = 0;
    let mut in_contact = 0;
    for x in states() {
        let rhs = generator
            .interpret(model::MODEL, "rhs", &[x.as_slice(), p.as_slice()])
            .unwrap();
        for (a, b) in sp::rhs(&x, &p).iter().zip(&rhs[0]) {
            worst = worst.max(ulps(*a, *b));
        }
        let e = generator
            .interpret(model::MODEL, "energy", &[x.as_slice(), p.as_slice()])
            .unwrap();
        worst = worst.max(ulps(sp::energy(&x, &p), e[0][0]));
        if sp::floor_load(&x, &p) > 0.0 {
            in_contact += 1;
        }
    }
    // The time-dependent model: inputs (x, p, t).
    model::declare_forced(&mut generator).unwrap();
    let pf = [2.0, 0.5, 1.3];
    for i in 0..20 {
        let s = f64::from(i);
        let (x, t) = ([0.3 * s - 2.0, (0.7 * s).sin()], 0.45 * s);
        let rhs = generator
            .interpret(model::FORCED, "rhs", &[&x, &pf, &[t]])
            .unwrap();
        let generated = own_model::generated::forced_oscillator::rhs(
            &SVector::from(x),
            &SVector::from(pf),
            &SVector::from([t]),
        );
        for (a, b) in generated.iter().zip(&rhs[0]) {
            worst = worst.max(ulps(*a, *b));
        }
    }
    // Same expression DAG, same operation order: equal up to a few ulps
    // (the emitter may fuse or reorder a sum).
    assert!(worst <= 4, "worst difference {worst} ulps");
    assert!(in_contact > 0, "no sample state touches the floor");
}

#[test]
fn exact_jacobian_matches_finite_differences() {
    let system = sp::System::new(parameters());
    for x in states() {
        let exact = system.jacobian(0.0, &x);
        let fd = finite_difference_jacobian(|x| system.rhs(0.0, x), &x);
        let scale = exact.abs().max().max(1.0);
        let diff = (exact - fd).abs().max();
        assert!(
            diff <= 1e-5 * scale,
            "x = {x:?}: |J - J_fd| = {diff}, |J| = {scale}"
        );
        // Kinematic rows: d(theta)/dt = theta_dot, d(phi)/dt = phi_dot.
        assert_eq!(exact[(sp::X_THETA, sp::X_THETA_DOT)], 1.0);
        assert_eq!(exact[(sp::X_PHI, sp::X_PHI_DOT)], 1.0);
    }
}

#[test]
fn energy_and_angular_momentum_are_conserved_through_floor_contacts() {
    let params = parameters();
    let system = sp::System::new(params);
    let p = system.p;
    let x0 = initial_state();
    let (e0, l0) = (sp::energy(&x0, &p), sp::angular_momentum(&x0, &p));
    for (method, rtol, bound) in [(Method::Dopri5, 1e-10, 1e-7), (Method::Rodas3, 1e-9, 1e-5)] {
        let sol = solve(
            &system,
            method,
            (0.0, x0),
            3.0,
            &Options::with_tolerances(rtol, rtol * 1e-2),
        )
        .unwrap();
        assert!(sol.stop.is_success(), "{method:?}: {:?}", sol.stop);
        let touched = sol.x.iter().filter(|x| sp::floor_load(x, &p) > 0.0).count();
        assert!(touched > 0, "{method:?}: the bob never touched the floor");
        let max_load = sol
            .x
            .iter()
            .map(|x| sp::floor_load(x, &p))
            .fold(0.0, f64::max);
        // The floor holds the bob up: its load exceeds the weight m g.
        assert!(
            max_load > params.m * params.g,
            "{method:?}: peak load {max_load} N"
        );
        for x in &sol.x {
            let de = (sp::energy(x, &p) - e0).abs() / e0.abs();
            let dl = (sp::angular_momentum(x, &p) - l0).abs() / l0.abs();
            assert!(de < bound, "{method:?}: relative energy drift {de}");
            assert!(dl < bound, "{method:?}: relative L_z drift {dl}");
        }
    }
}

#[test]
fn an_incomplete_model_is_an_error_naming_model_and_symbol() {
    let mut generator = Generator::new(pegdyn_equations::Options::default());
    let err = generator
        .model("broken", "Two coordinates, one force.", |m| {
            let a = m.coordinate("a", "m")?;
            m.coordinate("b", "m")?;
            m.lagrange(a.v.square(), a.q.square(), &[m.g().constant(0.0)]);
            Ok(())
        })
        .err()
        .unwrap();
    match &err {
        GenError::Model {
            model,
            function,
            symbol,
            ..
        } => {
            assert_eq!(
                (model.as_str(), function.as_str(), symbol.as_str()),
                ("broken", "lagrange", "forces")
            );
        }
        other => panic!("unexpected error {other}"),
    }
    assert_eq!(
        err.to_string(),
        "model `broken`, lagrange: `forces`: 1 generalized forces for 2 coordinates"
    );
}

#[test]
fn every_generated_function_is_accurate_against_double_double() {
    use pegdyn::accuracy::{grid::Point, measure_function};
    // The registry's DD_FUNCTIONS evaluate each function at f64 and at
    // double-double;
    // `measure_function` reports the worst error in ulps of the reference.
    let points: Vec<Point> = states()
        .iter()
        .enumerate()
        .map(|(i, x)| {
            Point::new(
                format!("state {i}"),
                &[
                    ("theta", x[0]),
                    ("phi", x[1]),
                    ("theta_dot", x[2]),
                    ("phi_dot", x[3]),
                    ("theta_ddot", 0.3),
                    ("phi_ddot", -1.1),
                    ("m", 1.0),
                    ("l", 1.0),
                    ("g", 9.81),
                    ("h", 0.95),
                    ("k", 1.0e6),
                ],
            )
        })
        .collect();
    assert_eq!(own_model::generated::registry::DD_FUNCTIONS.len(), 11);
    for dd in own_model::generated::registry::DD_FUNCTIONS
        .iter()
        .filter(|dd| dd.function.module == model::MODEL)
    {
        let acc = measure_function(dd, &points).unwrap();
        assert_eq!(acc.non_finite, 0, "{}", acc.path);
        assert!(
            acc.max_normwise < 1e-13,
            "{}: normwise error {} at {}",
            acc.path,
            acc.max_normwise,
            acc.worst_at
        );
    }
}

#[test]
fn forced_oscillator_follows_its_closed_form_solution() {
    use own_model::generated::forced_oscillator as fo;
    let p = fo::Params {
        omega0: 2.0,
        a: 0.5,
        omega: 1.3,
    };
    assert_eq!(fo::Params::<f64>::NAMES, ["omega0", "a", "omega"]);
    // The vector of the generated functions holds the fields in that order.
    assert_eq!(SVector::from(p), SVector::from([2.0, 0.5, 1.3]));
    let (w0, a, w) = (p.omega0, p.a, p.omega);
    let exact = |t: f64| a * ((w * t).cos() - (w0 * t).cos()) / (w0 * w0 - w * w);
    let system = fo::System::new(p);
    // The exact time derivative: d/dt of the forcing a cos(ωt) is −aω sin(ωt).
    let x = SVector::from([0.1, 0.2]);
    let dt = system.time_derivative(0.7, &x);
    assert_eq!(dt[fo::X_Y], 0.0);
    assert!((dt[fo::X_V] + a * w * (w * 0.7).sin()).abs() < 1e-15);
    for method in [Method::Dopri5, Method::Rodas3] {
        let opts = Options::with_tolerances(1e-10, 1e-12);
        let sol = solve(&system, method, (0.0, SVector::zeros()), 10.0, &opts).unwrap();
        for (t, x) in sol.t.iter().zip(&sol.x) {
            let err = (x[fo::X_Y] - exact(*t)).abs();
            assert!(err < 2e-6, "{method:?}: |y - exact| = {err} at t = {t}");
        }
    }
}
