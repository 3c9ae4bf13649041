//! The items of `src/compliant_peg_3d/search/interval.rs`.

use pegdyn::compliant_peg_3d::search::interval::{Iv, down, up};

#[test]
fn nudges_move_past_the_neighbouring_floats() {
    for x in [0.0, 1.0, -1.0, 1e-300, -3.5e7, std::f64::consts::TAU] {
        assert!(down(x) < x && up(x) > x, "{x}");
    }
}

#[test]
fn operations_contain_the_exact_results_of_their_bounds() {
    let a = Iv::new(-0.3, 0.7);
    let b = Iv::new(0.2, 0.5);
    let p = a * b;
    assert!(p.lo <= -0.15 && p.hi >= 0.35);
    assert_eq!(a.square().lo, 0.0);
    assert!(a.square().hi >= 0.49);
    let r = b.recip_times(1.0);
    assert!(r.lo <= 2.0 && r.hi >= 5.0);
    let s = b.sqrt();
    assert!(s.lo * s.lo <= 0.2 && s.hi * s.hi >= 0.5);
    assert!(!a.excludes_zero() && b.excludes_zero());
}
