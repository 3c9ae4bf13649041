//! The items of `src/output/axes.rs`.

use pegdyn::internals::output::*;

#[test]
fn tick_labels_are_short() {
    assert_eq!(tick(1e-11 * (1.0 - f64::EPSILON), 0.0), "1e-11");
    assert_eq!(tick(-1e-17, 2.0), "0");
    assert_eq!(tick(-1e-17, 1e-15), "-1e-17");
    assert_eq!(tick(0.25, 1.0), "0.25");
    assert_eq!(tick(2.0, 1.0), "2");
    assert_eq!(tick(123456.0, 1.0), "1.23e5");
}
