//! Parameter Jacobians `∂f/∂p` (`Options::parameter_jacobians`): the
//! functions they add, their values through the interpreter against
//! Richardson-extrapolated central differences of the function they
//! differentiate, and the errors of a wrong declaration.

use pegdyn_equations::model::Output;
use pegdyn_equations::{GenError, Generator, Options, Outputs};

fn selecting(models: &[&str]) -> Options {
    Options {
        parameter_jacobians: models.iter().map(|m| (*m).to_owned()).collect(),
        ..Options::default()
    }
}

/// `∂/∂p_k` of `f` at `p` by central differences at steps `h` and `h/2`,
/// Richardson-extrapolated (error O(h⁴)).
fn richardson(f: &dyn Fn(&[f64]) -> Vec<f64>, p: &[f64], k: usize) -> Vec<f64> {
    let central = |h: f64| {
        let (mut a, mut b) = (p.to_vec(), p.to_vec());
        a[k] += h;
        b[k] -= h;
        let (fa, fb) = (f(&a), f(&b));
        fa.iter()
            .zip(&fb)
            .map(|(x, y)| (x - y) / (2.0 * h))
            .collect::<Vec<f64>>()
    };
    let h = 1e-3 * p[k].abs().max(1e-2);
    let (d1, d2) = (central(h), central(0.5 * h));
    d1.iter()
        .zip(&d2)
        .map(|(a, b)| (4.0 * b - a) / 3.0)
        .collect()
}

fn assert_close(exact: f64, fd: f64, scale: f64, what: &str) {
    assert!(
        (exact - fd).abs() <= 1e-8 * scale.max(1e-12),
        "{what}: exact {exact}, finite differences {fd}"
    );
}

/// A damped, driven oscillator with a nonlinear spring, explicit form.
fn oscillator(g: &mut Generator) -> Result<(), GenError> {
    g.model("osc", "", |m| {
        let x = m.state("x", "m")?;
        let v = m.state("v", "m/s")?;
        let k = m.parameter("k", "N/m")?;
        let c = m.parameter("c", "N s/m")?;
        let a = m.parameter("a", "N")?;
        m.outputs(Outputs::FUNCTIONS);
        m.explicit(&[v, a * (x * k).sin() - c * v * v.abs() - k * x.powi(3)]);
        Ok(())
    })?;
    Ok(())
}

#[test]
fn an_explicit_model_gets_rhs_p_only_when_selected() {
    let names = |o: Options| {
        let mut g = Generator::new(o);
        oscillator(&mut g).unwrap();
        let out = g.render().unwrap();
        out.report
            .rows
            .iter()
            .map(|r| r.function.clone())
            .collect::<Vec<_>>()
    };
    assert!(!names(Options::default()).contains(&"rhs_p".to_owned()));
    let with = names(selecting(&["osc"]));
    assert!(with.contains(&"rhs_p".to_owned()), "{with:?}");
}

#[test]
fn rhs_p_matches_central_differences_of_rhs() {
    let mut g = Generator::new(selecting(&["osc"]));
    oscillator(&mut g).unwrap();
    let x = [0.3, -1.7];
    let p = [2.5, 0.4, 1.3];
    let rhs = |p: &[f64]| g.interpret("osc", "rhs", &[&x, p]).unwrap().remove(0);
    let exact = g.interpret("osc", "rhs_p", &[&x, &p]).unwrap().remove(0);
    let scale = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for k in 0..3 {
        let fd = richardson(&rhs, &p, k);
        for (i, d) in fd.iter().enumerate() {
            assert_close(exact[i * 3 + k], *d, scale, &format!("∂f{i}/∂p{k}"));
        }
    }
}

#[test]
fn lagrangian_parameter_terms_give_the_acceleration_sensitivity() {
    // Pendulum with a moving support: T = ½ m l² θ̇², V = −m g l cos θ,
    // Q = −b θ̇; M = m l², so ∂θ̈/∂p = terms / (m l²).
    let mut g = Generator::new(selecting(&["pend"]));
    g.model("pend", "", |m| {
        let th = m.coordinate("th", "rad")?;
        let mass = m.parameter("m", "kg")?;
        let l = m.parameter("l", "m")?;
        let grav = m.parameter("grav", "m/s²")?;
        let b = m.parameter("b", "N m s")?;
        m.outputs(Outputs::FUNCTIONS);
        let t = 0.5 * mass * l.square() * th.v.square();
        let v = -(mass * grav * l * th.q.cos());
        m.lagrange(t, v, &[-(b * th.v)]);
        Ok(())
    })
    .unwrap();
    let x = [0.7, -0.4];
    let p = [1.3, 0.8, 9.81, 0.2];
    let qdd = |p: &[f64]| {
        let r = g.interpret("pend", "rhs", &[&x, p]).unwrap().remove(0);
        vec![r[1]]
    };
    let a = qdd(&p);
    let terms = g
        .interpret("pend", "parameter_terms", &[&x, &a, &p])
        .unwrap()
        .remove(0);
    let mass = p[0] * p[1] * p[1];
    for k in 0..4 {
        let fd = richardson(&qdd, &p, k)[0];
        assert_close(terms[k] / mass, fd, a[0].abs() / p[k], &format!("∂θ̈/∂p{k}"));
    }
}

/// A 2×2 system A u = b in the unknowns u with A and b of the parameters.
fn linear(g: &mut Generator) -> Result<(), GenError> {
    g.model("lin", "", |m| {
        let s = m.symbol("s", "state, m")?;
        let (u0, u1) = (m.symbol("u0", "N")?, m.symbol("u1", "N")?);
        let (a, c) = (m.parameter("a", "m")?, m.parameter("c", "1")?);
        m.outputs(Outputs::NONE);
        let rows = vec![vec![a + s, c * s], vec![s.sin(), a * c + 2.0]];
        let bvec = [c * s.exp(), a.square() - s];
        m.function(
            "system",
            "A u = b",
            &[("s", &[s])],
            vec![
                ("a", "A", Output::matrix(&rows)),
                ("b", "b", Output::vector(&bvec)),
            ],
        )?;
        m.solution_parameter_jacobian("system", &[u0, u1])?;
        Ok(())
    })?;
    Ok(())
}

fn solve2(a: &[f64], b: &[f64]) -> Vec<f64> {
    let det = a[0] * a[3] - a[1] * a[2];
    vec![
        (b[0] * a[3] - a[1] * b[1]) / det,
        (a[0] * b[1] - a[2] * b[0]) / det,
    ]
}

#[test]
fn the_solution_of_a_linear_system_gets_its_parameter_jacobian() {
    let mut g = Generator::new(selecting(&["lin"]));
    linear(&mut g).unwrap();
    let s = [0.6];
    let p = [1.4, -0.7];
    let u_of = |p: &[f64]| {
        let ab = g.interpret("lin", "system", &[&s, p]).unwrap();
        solve2(&ab[0], &ab[1])
    };
    let u = u_of(&p);
    let ab = g.interpret("lin", "system", &[&s, &p]).unwrap();
    let r = g
        .interpret("lin", "system_p", &[&s, &u, &p])
        .unwrap()
        .remove(0);
    for k in 0..2 {
        let du = solve2(&ab[0], &[r[k], r[2 + k]]);
        let fd = richardson(&u_of, &p, k);
        for i in 0..2 {
            assert_close(du[i], fd[i], u[i].abs(), &format!("∂u{i}/∂p{k}"));
        }
    }
}

fn refused(o: Options, declare: fn(&mut Generator) -> Result<(), GenError>) -> (String, String) {
    let mut g = Generator::new(o);
    let e = declare(&mut g).and_then(|()| g.render().map(|_| ()));
    match e {
        Err(GenError::Model {
            function, symbol, ..
        }) => (function, symbol),
        other => panic!("expected a model error, got {other:?}"),
    }
}

#[test]
fn an_undeclared_model_in_the_options_is_refused() {
    let (function, symbol) = refused(selecting(&["osc", "ocs"]), oscillator);
    assert_eq!(
        (function.as_str(), symbol.as_str()),
        ("parameter_jacobians", "ocs")
    );
}

#[test]
fn marking_a_missing_function_or_a_matrix_output_is_refused() {
    let missing = |g: &mut Generator| -> Result<(), GenError> {
        g.model("m", "", |m| {
            let s = m.symbol("s", "m")?;
            let a = m.parameter("a", "1")?;
            m.outputs(Outputs::NONE);
            m.function(
                "f",
                "",
                &[("s", &[s])],
                vec![("y", "", Output::scalar(a * s))],
            )?;
            m.parameter_jacobian("g")
        })?;
        Ok(())
    };
    assert_eq!(refused(selecting(&["m"]), missing).1, "g");
    let matrix = |g: &mut Generator| -> Result<(), GenError> {
        g.model("m", "", |m| {
            let s = m.symbol("s", "m")?;
            let a = m.parameter("a", "1")?;
            m.outputs(Outputs::NONE);
            let rows = vec![vec![a * s]];
            m.function(
                "f",
                "",
                &[("s", &[s])],
                vec![("y", "", Output::matrix(&rows))],
            )?;
            m.parameter_jacobian("f")
        })?;
        Ok(())
    };
    assert_eq!(refused(selecting(&["m"]), matrix), ("f".into(), "y".into()));
}
