//! The items of `src/output/csv.rs`.

use pegdyn::output::csv::format_f64;

#[test]
fn round_trips_awkward_values() {
    for v in [
        0.1,
        -1.0 / 3.0,
        1e-300,
        f64::MIN_POSITIVE,
        5e-324,
        1.7976931348623157e308,
        123456789.12345679,
        1e15,
        9.999999999999998e14,
        -0.0,
        2.5e-4,
        9.99e-5,
    ] {
        let s = format_f64(v);
        let back: f64 = s.parse().unwrap();
        assert_eq!(back.to_bits(), v.to_bits(), "{v:?} -> {s}");
        assert!(s.len() <= 24, "{s}");
    }
    assert_eq!(format_f64(f64::NAN), "NaN");
    assert_eq!(format_f64(f64::NEG_INFINITY), "-inf");
}
