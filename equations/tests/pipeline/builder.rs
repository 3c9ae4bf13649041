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

#[test]
fn functions_with_their_own_inputs_need_no_dynamics_without_an_adapter() {
    // A forced oscillator whose right-hand side takes the force as an input
    // (summed at run time, as a contact wrench is), with two named outputs.
    let mut g = Generator::new(Options::default());
    g.model("forced", "Mass on a spring under a given force.", |m| {
        let x = m.state("x", "displacement, m")?;
        let v = m.state("v", "velocity, m/s")?;
        let k = m.parameter("k", "stiffness per mass, 1/s^2")?;
        let f = m.symbol("f", "force per mass, m/s^2")?;
        m.outputs(Outputs::NONE);
        m.function(
            "rhs",
            "Right-hand side under the force f.",
            &[("y", &[x, v]), ("u", &[f])],
            vec![
                (
                    "ydot",
                    pegdyn_equations::model::Output::vector(&[v, f - k * x]),
                ),
                ("power", pegdyn_equations::model::Output::scalar(f * v)),
            ],
        )
    })
    .unwrap();
    let out = g.render().unwrap();
    assert!(out.source.contains("pub fn rhs<T: Real>"), "{}", out.source);
    assert!(out.source.contains("y: &SVector<T, 2>"));
    assert!(out.source.contains("u: &SVector<T, 1>"));
    assert!(!out.source.contains("impl pegdyn::system::OdeSystem"));
    let v = g
        .interpret("forced", "rhs", &[&[0.5, 2.0], &[3.0], &[4.0]])
        .unwrap();
    assert_eq!(v, vec![vec![2.0, 3.0 - 4.0 * 0.5], vec![6.0]]);
    // The same function name twice is an error naming it.
    let e = g
        .model("twice_fn", "", |m| {
            let f = m.symbol("f", "")?;
            m.outputs(Outputs {
                adapter: false,
                ..Outputs::default()
            });
            m.function("h", "", &[("u", &[f])], vec![])?;
            m.function("h", "", &[("u", &[f])], vec![])
        })
        .err()
        .unwrap();
    assert_eq!(model_error(e).1, "h");
}

#[test]
fn the_compliant_3d_peg_declared_downstream_renders_like_the_builtin() {
    use pegdyn_equations::models::compliant_peg_3d as peg3d;
    let mut own = Generator::new(Options::default());
    own.model(peg3d::NAME, peg3d::DOC, peg3d::declare).unwrap();
    let mut builtin = Generator::new(Options::default());
    builtin.module(peg3d::module);
    let (a, b) = (own.render().unwrap(), builtin.render().unwrap());
    assert_eq!(a.source, b.source);
    assert!(a.source.contains("pub fn rim_edge<T: Real>"));
}
