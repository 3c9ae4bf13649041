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
                    "rate of (x, v)",
                    pegdyn_equations::model::Output::vector(&[v, f - k * x]),
                ),
                (
                    "power",
                    "power of the force, W/kg",
                    pegdyn_equations::model::Output::scalar(f * v),
                ),
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
    use pegdyn_equations::models::{self, compliant_peg_3d as peg3d};
    let mut own = Generator::new(Options::default());
    own.model(peg3d::NAME, peg3d::DOC, peg3d::declare).unwrap();
    let mut builtin = Generator::new(Options::default());
    models::declare_all(&mut builtin).unwrap();
    let (a, b) = (own.render().unwrap(), builtin.render().unwrap());
    let module = |src: &str| {
        let start = src.find("pub mod compliant_peg_3d").unwrap();
        let doc = src[..start].rfind("\n\n").unwrap();
        let end = src[start..].find("\n}\n").unwrap();
        src[doc..start + end].to_owned()
    };
    assert_eq!(module(&a.source), module(&b.source));
    assert!(a.source.contains("pub fn rim_edge<T: Real>"));
}

/// A two-parameter oscillator with one two-output function, declared in
/// `g` as model `name` (stiffness documented by `k_doc`), sharing its
/// structs with the model `share` when given.
fn typed_model(
    g: &mut Generator,
    name: &str,
    k_doc: &str,
    share: Option<&str>,
) -> Result<(), GenError> {
    use pegdyn_equations::model::Output;
    g.model(name, "Oscillator.", |m| {
        if let Some(first) = share {
            m.share_input_type("p", first);
            m.share_output_type("SplitOut", first);
        }
        let x = m.state("x", "displacement, m")?;
        let v = m.state("v", "velocity, m/s")?;
        let k = m.parameter("k", k_doc)?;
        let c = m.parameter("c", "damping per mass, 1/s")?;
        m.outputs(Outputs::NONE);
        m.function(
            "split",
            "Spring and damper accelerations.",
            &[("y", &[x, v])],
            vec![
                (
                    "spring",
                    "spring acceleration, m/s^2",
                    Output::scalar(-k * x),
                ),
                (
                    "damper",
                    "damper acceleration, m/s^2",
                    Output::scalar(-c * v),
                ),
            ],
        )
    })
    .map(|_| ())
}

const K_DOC: &str = "stiffness per mass, 1/s^2";

#[test]
fn parameters_and_several_outputs_are_typed_structs() {
    let mut g = Generator::new(Options::default());
    typed_model(&mut g, "osc", K_DOC, None).unwrap();
    let src = g.render().unwrap().source;
    // One documented field per parameter, conversions both ways.
    assert!(src.contains("pub struct Params<T>"), "{src}");
    assert!(
        src.contains("/// Stiffness per mass, 1/s^2.\n        pub k: T,"),
        "{src}"
    );
    assert!(src.contains("impl<T: Real> From<Params<T>> for SVector<T, 2>"));
    assert!(src.contains("impl<T: Real> From<&SVector<T, 2>> for Params<T>"));
    assert!(src.contains("pub const NAMES: [&'static str; 2] = P_NAMES;"));
    // The two outputs come back as a struct with named, documented fields.
    assert!(src.contains("pub struct SplitOut<T: Real>"), "{src}");
    assert!(src.contains("/// Spring acceleration, m/s^2.\n        pub spring: T,"));
    assert!(src.contains("-> SplitOut<T>"));
    assert!(!src.contains("-> (T, T)"));
}

#[test]
fn a_shared_struct_is_re_exported_when_it_matches_the_earlier_module() {
    let mut shared = Generator::new(Options::default());
    typed_model(&mut shared, "first", K_DOC, None).unwrap();
    typed_model(&mut shared, "second", K_DOC, Some("first")).unwrap();
    let src = shared.render().unwrap().source;
    assert!(src.contains("pub use super::first::Params;"), "{src}");
    assert!(src.contains("pub use super::first::SplitOut;"));
    assert_eq!(src.matches("pub struct SplitOut").count(), 1);
    // Same names, another meaning: not the same struct.
    let mut other = Generator::new(Options::default());
    typed_model(&mut other, "first", K_DOC, None).unwrap();
    typed_model(&mut other, "second", "stiffness, N/m", Some("first")).unwrap();
    match other.render() {
        Err(GenError::Struct { module, item, .. }) => {
            assert_eq!((module.as_str(), item.as_str()), ("second", "Params"));
        }
        r => panic!(
            "expected a struct error, got {:?}",
            r.map(|r| r.source.len())
        ),
    }
}

#[test]
fn a_typed_input_no_function_takes_is_an_error() {
    let mut g = Generator::new(Options::default());
    let e = g
        .model("untyped", "", |m| {
            m.typed_input("loads", "Loads", "Applied loads.")?;
            let x = m.state("x", "m")?;
            let f = m.input_parameter("f", "force, N")?;
            m.outputs(Outputs::NONE);
            m.function(
                "h",
                "",
                &[("x", &[x]), ("u", &[f])],
                vec![("y", "x f", pegdyn_equations::model::Output::scalar(x * f))],
            )
        })
        .err()
        .unwrap();
    assert_eq!(
        model_error(e),
        ("untyped".into(), "typed_input".into(), "loads".into())
    );
}
