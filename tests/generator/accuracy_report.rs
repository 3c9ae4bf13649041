//! `pegdyn::accuracy`: the measure itself (ulps, non-finite values) and
//! what it finds on the hard grid of every generated model, as
//! `docs/ACCURACY.md` reports it.

use pegdyn::accuracy::{entry_error, grid, measure, measure_function, ulp};
use pegdyn::generated::registry::DD_FUNCTIONS;
use pegdyn::scalar::Dd;

/// ulp(1) = 2⁻⁵², an error of one ulp is one ulp, NaN against a finite
/// reference is flagged, equal infinities are no error.
#[test]
fn the_measure_itself() {
    assert_eq!(ulp(1.0), f64::EPSILON);
    assert_eq!(ulp(-3.0), 2.0 * f64::EPSILON);
    let one_up = entry_error(1.0 + f64::EPSILON, Dd::ONE);
    assert_eq!(one_up.ulps, 1.0);
    assert_eq!(one_up.relative, f64::EPSILON);
    // Half an ulp below 1 + ε: the reference is between two doubles.
    let half = entry_error(1.0, Dd::new(1.0, 0.5 * f64::EPSILON));
    assert_eq!(half.ulps, 0.5);
    let nan = entry_error(f64::NAN, Dd::ONE);
    assert!(nan.non_finite && nan.ulps.is_infinite());
    assert_eq!(
        entry_error(f64::INFINITY, Dd::from(f64::INFINITY)).ulps,
        0.0
    );
}

/// Every registered module has a grid, and no generated function returns a
/// NaN or an infinity where the double-double evaluation is finite.
#[test]
fn every_module_has_a_grid_and_no_silent_non_finite() {
    let report = measure(&DD_FUNCTIONS, None).expect("every grid point names every input");
    assert!(
        report.skipped.is_empty(),
        "no grid for {:?}",
        report.skipped
    );
    assert_eq!(report.functions.len(), DD_FUNCTIONS.len());
    for f in &report.functions {
        assert_eq!(f.non_finite, 0, "{}", f.path);
        // Normwise (per output) error at most 1e-8 of the output's largest
        // entry everywhere on the grid (the worst, 4.7e-9, is the scalar
        // moment of `quasi_static::two_point` at θ = 1e-8, l = 1 nm: a
        // balance of terms of size r·f that nearly cancel).
        assert!(
            f.max_normwise <= 1e-8,
            "{}: normwise {:e}",
            f.path,
            f.max_normwise
        );
    }
}

/// The compliant peg at θ = 0 over the clearance × approach grid: contact
/// forces, penetrations and slips within 4 ulps, energies within 2, the
/// right-hand side and Jacobian normwise within 4 u (the figures of
/// `docs/ACCURACY.md`; before the stable rewrites: 1.7e10 ulps).
#[test]
fn compliant_peg_at_zero_tilt_is_accurate_to_a_few_ulps() {
    let points: Vec<_> = grid::points("compliant_peg")
        .expect("grid")
        .into_iter()
        .filter(|p| p.label.contains("theta=0e0"))
        .collect();
    for dd in DD_FUNCTIONS
        .iter()
        .filter(|dd| matches!(dd.function.module, "compliant_peg" | "compliant_peg_lean"))
    {
        let f = &dd.function;
        let a = measure_function(dd, &points).expect("inputs");
        let u = f64::EPSILON / 2.0;
        match f.name {
            "contacts" => assert!(
                a.max_ulps <= 4.0,
                "{}: {} ulps at {}",
                a.path,
                a.max_ulps,
                a.worst_at
            ),
            "energy" => assert!(a.max_ulps <= 2.0, "{}: {} ulps", a.path, a.max_ulps),
            _ => assert!(
                a.max_normwise <= 4.0 * u,
                "{}: normwise {:e}",
                a.path,
                a.max_normwise
            ),
        }
    }
}

/// The generated rigid three-point peg near γ0, clearances 50 µm to 1 nm,
/// γ = γ0(1 + ε) down to ε = 1e-12: the geometry (a1, a2, S1, b, …) within
/// 64 ulps — its forms are the stable products of the model — and every
/// output normwise within 8 u (single entries that vanish at γ0, such as
/// contact-velocity components, have large relative errors: they are sums of
/// terms of size D·γ̇ that cancel).
#[test]
fn generated_rigid_peg_near_gamma0() {
    let points = grid::points("rigid_peg").expect("grid");
    let u = f64::EPSILON / 2.0;
    for dd in DD_FUNCTIONS
        .iter()
        .filter(|dd| dd.function.module.starts_with("rigid_peg"))
    {
        let f = &dd.function;
        let a = measure_function(dd, &points).expect("inputs");
        if f.name == "geometry" {
            assert!(
                a.max_ulps <= 64.0,
                "{}: {} ulps at {}",
                a.path,
                a.max_ulps,
                a.worst_at
            );
        }
        assert!(
            a.max_normwise <= 8.0 * u,
            "{}: normwise {:e}",
            a.path,
            a.max_normwise
        );
    }
}
