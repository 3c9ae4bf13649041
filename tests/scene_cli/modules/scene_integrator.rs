//! The items of `src/scene/integrator.rs`.

use pegdyn::integrate::MethodKind;
use pegdyn::scene::integrator::*;

fn spec(method: Method) -> IntegratorSpec {
    IntegratorSpec {
        method,
        rtol: 1e-8,
        atol: 1e-10,
        h: None,
        t0: 0.0,
        t_end: 1.0,
        output_interval: Some(0.3),
        max_steps: 10,
        atol_scale: Default::default(),
    }
}

#[test]
fn output_times_end_at_t_end() {
    let ts: Vec<f64> = spec(Method::Named(MethodKind::Dopri5))
        .output_times()
        .collect();
    assert_eq!(ts.len(), 5);
    assert_eq!(ts[4], 1.0);
    assert!((ts[3] - 0.9).abs() < 1e-15);
}

#[test]
fn auto_takes_the_scene_kind_default_and_a_named_method_stays() {
    let (r, why) = spec(Method::Auto).resolved(DefaultMethod::STIFF_CONTACT);
    assert_eq!(r.method, Method::Named(MethodKind::Rodas4));
    assert!(why.contains("compliant contact"), "{why}");
    let (r, _) = spec(Method::Auto).resolved(DefaultMethod::NON_STIFF);
    assert_eq!(r.method, Method::Named(MethodKind::Dopri5));
    let (r, why) = spec(Method::Named(MethodKind::Dopri5)).resolved(DefaultMethod::STIFF_CONTACT);
    assert_eq!(r.method, Method::Named(MethodKind::Dopri5));
    assert_eq!(why, "named by the scene");
    let toml_spec: IntegratorSpec = toml::from_str("t_end = 1.0").unwrap();
    assert_eq!(toml_spec.method, Method::Auto);
}

#[test]
fn output_times_are_lazy_for_absurd_spans() {
    let mut s = spec(Method::Named(MethodKind::Dopri5));
    s.t_end = 1e9;
    s.output_interval = Some(1e-300);
    let mut ts = s.output_times();
    assert_eq!(ts.next(), Some(0.0));
    assert_eq!(ts.next(), Some(1e-300));
    let w = s.work("integrator");
    assert_eq!(w[0].field, "integrator.output_interval");
    assert!(w[0].count.is_infinite());
}

#[test]
fn rk4_needs_h_and_bad_tolerances_are_named() {
    let e = spec(Method::Named(MethodKind::Rk4))
        .check("integrator")
        .unwrap_err();
    assert!(e.to_string().contains("integrator.h"), "{e}");
    let mut s = spec(Method::Named(MethodKind::Dopri5));
    s.rtol = 1e-293;
    let e = s.check("integrator").unwrap_err().to_string();
    assert!(e.contains("integrator.rtol") && e.contains("1e-15"), "{e}");
    s.rtol = -1e-6;
    s.t_end = -1.0;
    let e = s.check("integrator").unwrap_err().to_string();
    assert!(e.contains("integrator.rtol") && e.contains("-1e-6"), "{e}");
    assert!(e.contains("integrator.t_end"), "{e}");
}

#[test]
fn atol_scale_values_are_checked_and_described() {
    let mut s = spec(Method::Named(MethodKind::Rodas4));
    s.atol_scale.insert("wx".into(), 50.0);
    assert!(s.check("integrator").is_ok());
    // The described tolerance is atol (1e-10) times the factor.
    assert!(s.describe().contains("atol[wx]=5e-9"), "{}", s.describe());
    s.atol_scale.insert("wy".into(), 0.0);
    s.atol_scale.insert("wz".into(), f64::NAN);
    let e = s.check("integrator").unwrap_err().to_string();
    assert!(e.contains("integrator.atol_scale.wy"), "{e}");
    assert!(e.contains("integrator.atol_scale.wz"), "{e}");
    assert!(!e.contains("atol_scale.wx"), "{e}");
    // A factor whose tolerance overflows or falls below the smallest
    // normal f64 is refused by name, before the run.
    let mut s = spec(Method::Named(MethodKind::Rodas4));
    s.atol = 1e10;
    s.atol_scale.insert("wx".into(), 1e300);
    s.atol_scale.insert("wy".into(), 1e-320);
    let e = s.check("integrator").unwrap_err().to_string();
    assert!(e.contains("integrator.atol_scale.wx"), "{e}");
    assert!(e.contains("integrator.atol_scale.wy"), "{e}");
}
