//! The items of `src/jamming/forces.rs`.

use pegdyn::jamming::forces::*;

/// k3 = 0 exactly and k3 = 1e-300 (far below the rounding bound
/// 8 u (1 + μ)², and the size at which the unchecked division gives
/// forces of 1e300 N or ±∞): the typed refusal, not a number.
#[test]
fn k3_zero_and_tiny_are_refused_with_a_type() {
    let mu = 0.3;
    let k = k_factors(mu, 0.1);
    for k3 in [0.0, -0.0, 1e-300, -1e-300, f64::MIN_POSITIVE, f64::NAN] {
        match forces_from_factors(mu, 0.1, (k.0, k.1, k3), 0.2, 1.0) {
            Err(e) => {
                assert_eq!(e.theta, 0.1);
                assert!(e.k3 == k3 || (k3.is_nan() && e.k3.is_nan()));
            }
            Ok(f) => panic!("k3 = {k3:e} accepted: {f:?}"),
        }
    }
    // Just above the bound it is accepted and finite, and equals the
    // unchecked closed form.
    let k3 = 8.0 * f64::EPSILON * (1.0 + mu).powi(2);
    let f = forces_from_factors(mu, 0.1, (k.0, k.1, k3), 0.2, 1.0).expect("above the bound");
    assert!(f.tip.is_finite() && f.edge.is_finite());
    assert_eq!(f.edge, (1.0 + mu * 0.2) / k3);
}
