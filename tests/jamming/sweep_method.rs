//! `sweep.method` of the `jamming` scene reads the integrators' one
//! vocabulary (`integrate::MethodKind`) with the spellings `rodas4`,
//! `rodas3` and `dopri5`; without it the runs use RODAS4.

use pegdyn::integrate::{Method, MethodKind};
use pegdyn::scene::kinds::jamming::sweep::SweepParams;

/// The `[sweep]` table of `scenes/jamming.toml` with `extra` appended.
fn sweep(extra: &str) -> Result<SweepParams, toml::de::Error> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/jamming.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let table = text.split("[sweep]").nth(1).unwrap();
    toml::from_str(&format!("{table}\n{extra}"))
}

#[test]
fn sweep_method_reads_the_three_adaptive_spellings() {
    let default = sweep("").unwrap();
    assert_eq!(
        (default.method, default.method()),
        (None, MethodKind::Rodas4)
    );
    for (name, kind, method) in [
        ("rodas4", MethodKind::Rodas4, Method::Rodas4),
        ("rodas3", MethodKind::Rodas3, Method::Rodas3),
        ("dopri5", MethodKind::Dopri5, Method::Dopri5),
    ] {
        let p = sweep(&format!("method = \"{name}\"")).unwrap();
        assert_eq!(p.method, Some(kind));
        assert_eq!(p.method().name(), name);
        assert_eq!(p.prepare().unwrap().spec.integrator, method);
    }
}

#[test]
fn sweep_method_refuses_rk4_and_unknown_names() {
    for name in ["rk4", "rodas", "Rodas4"] {
        let e = sweep(&format!("method = \"{name}\""))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains(name) && e.contains("rodas4") && e.contains("dopri5"),
            "{name}: {e}"
        );
    }
    let mut p = sweep("").unwrap();
    p.method = Some(MethodKind::Rk4);
    let e = p.prepare().unwrap_err();
    assert!(format!("{e:?}").contains("sweep.method"), "{e:?}");
}
