//! The public builder API: what a model declaration produces and the
//! errors that name the model, function and symbol at fault.

use pegdyn_equations::{GenError, Generator, Options, Outputs};

fn model_error(e: GenError) -> (String, String, String) {
    match e {
        GenError::Model {
            model,
            function,
            symbol,
            ..
        } => (model, function, symbol),
        other => panic!("expected a model error, got {other}"),
    }
}

#[test]
fn a_name_declared_twice_is_an_error() {
    let mut g = Generator::new(Options::default());
    let e = g
        .model("twice", "", |m| {
            m.coordinate("x", "m")?;
            m.parameter("x", "kg")?;
            Ok(())
        })
        .err()
        .unwrap();
    assert_eq!(
        model_error(e),
        ("twice".into(), "declaration".into(), "x".into())
    );
}

#[test]
fn an_explicit_rhs_of_the_wrong_length_is_an_error() {
    let mut g = Generator::new(Options::default());
    let e = g
        .model("short", "", |m| {
            let y = m.state("y", "m")?;
            m.state("v", "m/s")?;
            m.explicit(&[y]);
            Ok(())
        })
        .err()
        .unwrap();
    assert_eq!(
        model_error(e),
        ("short".into(), "explicit".into(), "rhs".into())
    );
}

#[test]
fn outputs_choose_the_functions_and_options_the_forms() {
    let declare = |g: &mut Generator| {
        g.model("pendulum_like", "", |m| {
            let th = m.coordinate("th", "rad")?;
            let l = m.parameter("l", "m")?;
            m.outputs(Outputs {
                rhs: true,
                mass_forcing: false,
                jacobian: false,
                energy: false,
                adapter: false,
            });
            let zero = m.g().constant(0.0);
            // V = 1 - cos(th): the stable form is 2 sin²(th/2).
            m.lagrange(0.5 * l * th.v.square(), 1.0 - th.q.cos(), &[zero]);
            Ok(())
        })
        .map(|_| ())
    };
    let mut stable = Generator::new(Options::default());
    declare(&mut stable).unwrap();
    let out = stable.render().unwrap();
    let fns: Vec<&str> = out
        .report
        .rows
        .iter()
        .map(|r| r.function.as_str())
        .collect();
    assert_eq!(fns, ["rhs"]);
    assert!(!out.source.contains("impl pegdyn::system::OdeSystem"));
    let naive = Options {
        stable_rewrites: false,
        ..Options::default()
    };
    let mut g = Generator::new(naive);
    declare(&mut g).unwrap();
    assert!(
        g.render()
            .unwrap()
            .source
            .contains("Stable numerical rewrites: OFF")
    );
    assert!(!out.source.contains("Stable numerical rewrites: OFF"));
    // The interpreter evaluates the declared rhs: θ̈ = −sin θ / l.
    let r = stable
        .interpret("pendulum_like", "rhs", &[&[0.3, 0.0], &[2.0]])
        .unwrap();
    assert_eq!(r[0][0], 0.0);
    assert!((r[0][1] + 0.3f64.sin() / 2.0).abs() < 1e-16);
}
