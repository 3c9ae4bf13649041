//! The code generator: what it emits for each canonical form, what
//! verification rejects, identifier sanitizing, determinism and
//! write-only-when-changed. (That the emitted code computes what the
//! interpreter computes is `tests/generator/vs_interpreter.rs` at the
//! workspace root, which compiles it.)

use pegdyn_equations::codegen::names::snake_case;
use pegdyn_equations::codegen::{Entry, Rendered, render, write_if_changed};
use pegdyn_equations::model::{FnSpec, Input, Module, Output};
use pegdyn_equations::{Expr, GenError, Graph};
use pegdyn_equations::{Generator, Options, models};

/// A one-function module `m::f(x) -> outputs` over the symbols `syms`.
fn module(syms: &[Expr<'_>], outputs: Vec<(&str, Output)>) -> Module {
    Module::new(
        "m",
        "test",
        vec![FnSpec::new(
            "f",
            "test",
            vec![Input::new("x", syms)],
            outputs,
        )],
    )
}

/// `m`, built in `g`, rendered alone with the default options.
fn render_one(g: Graph, m: Module) -> Result<Rendered, GenError> {
    render(
        &[Entry {
            graph: g,
            module: m,
        }],
        &Options::default(),
    )
}

/// Every built-in model, rendered with the extras pegdyn's build turns on.
fn builtins(options: Options) -> Rendered {
    let mut g = Generator::new(options);
    models::declare_all(&mut g).unwrap_or_else(|e| panic!("{e}"));
    g.render().unwrap_or_else(|e| panic!("{e}"))
}

/// The options of pegdyn's own build: every extra on.
fn everything() -> Options {
    Options {
        registry: true,
        function_list: true,
        test_harness: true,
        ..Options::default()
    }
}

/// The emitted code of the scalar function `e` of a, b, c.
fn emitted(build: impl for<'g> Fn(&'g Graph, Expr<'g>, Expr<'g>, Expr<'g>) -> Expr<'g>) -> String {
    let g = Graph::new();
    let (a, b, c) = (g.var("a"), g.var("b"), g.var("c"));
    let m = module(&[a, b, c], vec![("y", Output::scalar(build(&g, a, b, c)))]);
    render_one(g, m).unwrap_or_else(|e| panic!("{e}")).source
}

#[test]
fn a_model_name_names_the_let_and_the_functions_of_it() {
    let code = emitted(|_, a, b, c| {
        let d = (a - b).named("diff");
        assert_eq!(d, a - b); // naming changes no node
        (d.sin() + c) * d.cos()
    });
    assert!(code.contains("let diff = a - b;"), "{code}");
    assert!(
        code.contains("let (sin_diff, cos_diff) = diff.sin_cos();"),
        "{code}"
    );
}

#[test]
fn canonical_forms_are_emitted_as_written_by_hand() {
    // (expression, text the emitted function must contain)
    let rows: Vec<(String, &str)> = vec![
        (emitted(|_, a, b, _| a - b), "a - b"),
        (
            emitted(|_, a, b, c| a - 2.0 * b * c),
            "a - T::from_f64(2.0) * b * c",
        ),
        (emitted(|_, a, b, _| -a + b), "b - a"),
        (emitted(|_, a, _, _| -a), "-a"),
        (emitted(|_, a, b, c| a / (b * c)), "a / (b * c)"),
        (emitted(|_, a, b, _| -a / b), "-a / b"),
        (emitted(|_, a, _, _| a.sqrt()), "a.sqrt()"),
        (
            emitted(|_, a, _, _| a.powf(-0.5)),
            "T::from_f64(1.0) / a.sqrt()",
        ),
        (emitted(|_, a, _, _| a.square()), "a * a"),
        (emitted(|_, a, _, _| a.powi(3)), "a * a * a"),
        (emitted(|_, a, _, _| a.powi(6)), "a.powi(6)"),
        (
            emitted(|_, a, _, _| a.powf(0.3)),
            "a.powf(T::from_f64(0.3))",
        ),
        (emitted(|_, a, b, _| a.atan2(b)), "a.atan2(b)"),
        (emitted(|_, a, b, _| a.hypot(b)), "a.hypot(b)"),
        (emitted(|_, a, _, _| a.exp_m1()), "a.exp_m1()"),
        (emitted(|_, a, _, _| a.ln_1p()), "a.ln_1p()"),
        (emitted(|_, a, b, _| (a + b).sin()), "(a + b).sin()"),
        (emitted(|_, a, _, _| a.powf(1.0 / 3.0)), "a.cbrt()"),
        (
            emitted(|_, a, b, c| a * c + 2.0 * b * c),
            "c * (a + T::from_f64(2.0) * b)",
        ),
        (emitted(|_, a, _, _| a.powf(2.0 / 3.0)), "a.cbrt().powi(2)"),
        (emitted(|_, a, _, _| a.max0()), "let max0_a = a.max0();"),
        (emitted(|_, a, b, c| (a - b) * (b - c)), "(a - b) * (b - c)"),
        // Exact small rationals print as a quotient, dyadic ones as decimals.
        (
            emitted(|_, a, _, _| a / 12.0),
            "T::from_f64(1.0 / 12.0) * a",
        ),
        (emitted(|_, a, _, _| a / 8.0), "T::from_f64(0.125) * a"),
    ];
    for (code, want) in &rows {
        assert!(code.contains(want), "expected `{want}` in:\n{code}");
    }
}

#[test]
fn shared_and_expensive_nodes_get_a_let_and_are_computed_once() {
    let code = emitted(|_, a, b, _| (a + b).sin() * (a + b).tan() + (a + b).sin());
    assert_eq!(code.matches(".sin()").count(), 1, "{code}");
    assert!(code.contains("let t0 = a + b;"), "{code}");
    let code = emitted(|_, a, _, _| a.sin() + a.tan());
    assert!(code.contains("let sin_a = a.sin();"), "{code}");
}

#[test]
fn sine_and_cosine_of_one_argument_are_one_sin_cos_call() {
    let code = emitted(|_, a, b, _| a.sin() * b + a.cos() + (a - b).cos() * (a - b).sin());
    assert!(code.contains("let (sin_a, cos_a) = a.sin_cos();"), "{code}");
    assert_eq!(code.matches(".sin_cos()").count(), 2, "{code}");
    assert!(
        !code.contains(".sin()") && !code.contains(".cos()"),
        "{code}"
    );
    assert!(code.contains("2 transcendental"), "{code}");
    // Different arguments: two calls.
    let code = emitted(|_, a, b, _| a.sin() * b.cos());
    assert!(
        code.contains("a.sin()") && code.contains("b.cos()"),
        "{code}"
    );
    assert!(!code.contains("sin_cos"), "{code}");
}

#[test]
fn docs_carry_the_operation_counts() {
    let code = emitted(|_, a, b, c| a * b / c + a.sin());
    assert!(
        code.contains("1 add/sub, 1 mul, 1 div, 0 sqrt, 1 transcendental, 0 branches"),
        "{code}"
    );
}

#[test]
fn symbol_names_become_snake_case_identifiers() {
    for (name, want) in [
        ("theta", "theta"),
        ("thetaDot", "theta_dot"),
        ("γ", "gamma"),
        ("ψ\u{307}", "psidot"),
        ("x_B1", "x_b1"),
        ("1st", "s1st"),
        ("m-1", "m_1"),
        ("", "s"),
    ] {
        assert_eq!(snake_case(name), want, "{name:?}");
    }
}

#[test]
fn clashing_names_are_renamed() {
    // A symbol called like the input, and one that is a keyword.
    let g = Graph::new();
    let (x, kw) = (g.var("x"), g.var("type"));
    let m = module(&[x, kw], vec![("y", Output::scalar(x * kw))]);
    let code = render_one(g, m).unwrap_or_else(|e| panic!("{e}")).source;
    assert!(
        code.contains("let x_2 = x[0];") && code.contains("let type_2 = x[1];"),
        "{code}"
    );
}

fn verify_error(build: impl for<'g> Fn(&'g Graph) -> Module) -> GenError {
    let g = Graph::new();
    let m = build(&g);
    match render_one(g, m) {
        Ok(_) => panic!("verification accepted an invalid module"),
        Err(e) => e,
    }
}

#[test]
fn verification_rejects_invalid_models() {
    let e = verify_error(|g| {
        module(
            &[g.var("a")],
            vec![("y", Output::scalar(g.var("a") * g.param("k")))],
        )
    });
    assert!(
        matches!(e, GenError::UnboundSymbol { ref symbol, .. } if symbol == "k"),
        "{e}"
    );

    let e = verify_error(|g| {
        module(
            &[g.var("a"), g.var("a")],
            vec![("y", Output::scalar(g.var("a")))],
        )
    });
    assert!(matches!(e, GenError::SymbolBoundTwice { .. }), "{e}");

    let e = verify_error(|g| {
        let (a, b) = (g.var("a"), g.var("b"));
        module(
            &[a, b],
            vec![("m", Output::symmetric(&[vec![a, b], vec![a, b]]))],
        )
    });
    assert!(
        matches!(e, GenError::NotSymmetric { row: 1, col: 0, .. }),
        "{e}"
    );

    let e = verify_error(|g| {
        let a = g.var("a");
        module(
            &[a],
            vec![(
                "m",
                Output::Matrix {
                    rows: 2,
                    cols: 2,
                    entries: vec![a.id(); 3],
                },
            )],
        )
    });
    assert!(matches!(e, GenError::Shape { entries: 3, .. }), "{e}");

    let e = verify_error(|g| {
        module(
            &[g.var("a")],
            vec![("y", Output::scalar(g.var("a") + f64::INFINITY))],
        )
    });
    assert!(matches!(e, GenError::NonFiniteConstant { .. }), "{e}");

    let e = verify_error(|g| module(&[g.var("a")], vec![]));
    assert!(matches!(e, GenError::Empty { .. }), "{e}");

    let e = verify_error(|g| {
        let mut m = module(&[g.var("a")], vec![("y", Output::scalar(g.var("a")))]);
        m.functions[0].name = "Rhs".to_owned();
        m
    });
    assert!(
        matches!(
            e,
            GenError::InvalidName {
                what: "function",
                ..
            }
        ),
        "{e}"
    );

    let e = verify_error(|g| {
        let mut m = module(&[g.var("a")], vec![("y", Output::scalar(g.var("a")))]);
        let mut f2 = m.functions[0].clone();
        f2.name = "f2".to_owned();
        f2.inputs = vec![Input::new("x", &[g.var("b")])];
        f2.outputs = vec![("y".to_owned(), Output::scalar(g.var("b")))];
        m.functions.push(f2);
        m
    });
    assert!(matches!(e, GenError::InconsistentInput { .. }), "{e}");
}

#[test]
fn generation_is_deterministic_and_path_free() {
    let (one, two) = (builtins(everything()), builtins(everything()));
    assert_eq!(one, two);
    assert!(
        one.source
            .starts_with("// @generated by pegdyn-equations (build.rs) — do not edit.")
    );
    let here = env!("CARGO_MANIFEST_DIR");
    let calls = one.calls.as_deref().unwrap_or_default();
    assert!(!one.source.contains(here) && !calls.contains(here));
}

#[test]
fn files_are_written_only_when_their_bytes_change() {
    let dir = std::env::temp_dir().join(format!("pegdyn-codegen-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("f.txt");
    let _ = std::fs::remove_file(&path);
    assert!(write_if_changed(&path, b"one").expect("write"));
    assert!(!write_if_changed(&path, b"one").expect("write"));
    assert!(write_if_changed(&path, b"two").expect("write"));
    // A crate's own models: the source and the report, no extras.
    let own = builtins(Options::default());
    assert!(own.calls.is_none() && own.list.is_none());
    assert!(!own.source.contains("pub mod registry"));
    own.write(&dir).expect("write");
    for f in ["generated_calls.rs", "generated_list.rs"] {
        assert!(!dir.join(f).exists(), "{f} written without being asked for");
    }
    // pegdyn's build: the registry, the function list and the test harness.
    let all = builtins(everything());
    assert!(all.source.contains("pub mod registry"));
    all.write(&dir).expect("write");
    for f in [
        "generated.rs",
        "codegen_report.txt",
        "generated_calls.rs",
        "generated_list.rs",
    ] {
        assert!(dir.join(f).is_file(), "{f} not written");
    }
    std::fs::remove_dir_all(&dir).expect("clean up");
}

/// `x - x` where `x` is one name, neither preceded nor followed by a
/// tighter operator (so `c * x - x` and `x - x * c` do not count).
fn self_differences(code: &str) -> Vec<String> {
    let tokens: Vec<&str> = code
        .split(|ch: char| ch.is_whitespace())
        .filter(|t| !t.is_empty())
        .collect();
    let is_name = |t: &str| t.chars().all(|ch| ch.is_alphanumeric() || ch == '_');
    let mut found = Vec::new();
    for k in 1..tokens.len().saturating_sub(2) {
        let (before, a, op, b) = (tokens[k - 1], tokens[k], tokens[k + 1], tokens[k + 2]);
        let b_name = b.trim_end_matches([';', ',', ')']);
        let after = tokens.get(k + 3).copied().unwrap_or(";");
        if op == "-"
            && is_name(a)
            && a == b_name
            && !matches!(before, "*" | "/")
            && (b != b_name || !matches!(after, "*" | "/"))
        {
            found.push(format!("{before} {a} - {b}"));
        }
    }
    found
}

#[test]
fn like_terms_meet_in_the_generated_code() {
    let src = builtins(Options::default()).source;
    let found = self_differences(&src);
    assert!(found.is_empty(), "x - x in the generated code: {found:?}");
    assert!(
        !src.contains("T::from_f64(1.0) + T::from_f64(1.0)"),
        "a constant sum is left unfolded"
    );
    // The scanner sees one when there is one.
    assert_eq!(self_differences("let t = lever - lever;").len(), 1);
    assert!(self_differences("let t = c * lever - lever;").is_empty());
}

#[test]
fn a_value_equal_to_a_named_one_carries_its_name() {
    // `s` is named, then only `2 s` (expanded by the simplifier into
    // 2a − 2b, no node of `s` itself) reaches the code twice.
    let code = emitted(|_, a, b, c| {
        let s = (a - b).named("s");
        let twice = 2.0 * s;
        twice.sin() * c + twice.cos()
    });
    assert!(code.contains("let twice_s = "), "{code}");
}

/// `let a = -b;` lines: a `let` that binds nothing but a negation.
fn pure_negations(code: &str) -> Vec<&str> {
    let is_name = |t: &str| !t.is_empty() && t.chars().all(|ch| ch.is_alphanumeric() || ch == '_');
    code.lines()
        .map(str::trim)
        .filter(|l| {
            let Some(rest) = l.strip_prefix("let ") else {
                return false;
            };
            let Some((name, value)) = rest.split_once(" = -") else {
                return false;
            };
            is_name(name) && value.strip_suffix(';').is_some_and(is_name)
        })
        .collect()
}

#[test]
fn signs_fold_into_their_users_in_every_model() {
    let src = builtins(Options::default()).source;
    let found = pure_negations(&src);
    assert!(found.is_empty(), "pure negations bound: {found:?}");
    // The scanner sees one when there is one.
    assert_eq!(pure_negations("        let t34 = -t33;\n").len(), 1);
    assert!(pure_negations("let t = -a * b;\nlet u = -T::from_f64(2.0);").is_empty());
}
