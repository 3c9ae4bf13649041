//! Early stop of the dynamic jamming sweep (`compliant_peg::Settle`): a stuck
//! run is classified once it has settled, before its window ends, and the
//! classes of a grid over the shipped sweep's load range are the same with
//! and without the early stop, the same with RODAS4 as with RODAS3, and the
//! same at the scene's default tolerance (rtol 1e-4) as at rtol 1e-6, and
//! the same with the shipped scene's contact damping (Hunt–Crossley
//! α = 1.5 s/m) as with elastic contacts.

use pegdyn::compliant_peg::Settle;
use pegdyn::integrate::Method;
use pegdyn::jamming::dynamic::{self, SweepSetup, SweepSpec};

/// The shipped sweep of `scenes/jamming.toml` with the given integrator,
/// early-stop choice and relative tolerance (atol = 1e-4 rtol).
fn setup(integrator: Method, early_stop: bool, rtol: f64) -> SweepSetup {
    SweepSetup::new(SweepSpec {
        integrator,
        rtol,
        atol: 1e-4 * rtol,
        early_stop,
        ..SweepSpec::reference()
    })
    .unwrap()
}

#[test]
fn settle_rule_checks_ten_times_per_window() {
    let s = Settle::for_window(0.05);
    assert!((s.interval - 0.005).abs() < 1e-15);
    assert!(s.force_rtol > 0.0 && s.force_rtol < 0.1);
}

#[test]
fn shipped_classes_are_unchanged_by_early_stop_rodas4_the_default_tolerance_or_contact_damping() {
    let n = 5;
    let classes = |s: &SweepSetup| -> Vec<_> {
        dynamic::run(s, 4.5, 6.0, n, |_, _| {})
            .unwrap()
            .1
            .iter()
            .map(|p| (p.lean_plus, p.lean_minus))
            .collect()
    };
    let early = classes(&setup(Method::Rodas4, true, 1e-6));
    let full = classes(&setup(Method::Rodas4, false, 1e-6));
    let rodas3 = classes(&setup(Method::Rodas3, false, 1e-6));
    let coarse = classes(&setup(Method::Rodas4, true, 1e-4));
    let damped = SweepSetup::new(SweepSpec {
        contact_damping: 1.5,
        ..setup(Method::Rodas4, true, 1e-4).spec
    })
    .unwrap();
    assert_eq!(damped.params.spec.damping, 1.5);
    let damped = classes(&damped);
    assert_eq!(early, full);
    assert_eq!(full, rodas3);
    assert_eq!(coarse, early);
    assert_eq!(damped, early);
    // The grid has both classes: the comparison means something.
    let stuck = early.iter().filter(|(a, _)| a.is_stuck()).count();
    assert!(stuck > 0 && stuck < early.len(), "{early:?}");
}
