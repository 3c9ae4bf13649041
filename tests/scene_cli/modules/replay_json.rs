//! The items of `src/replay/json.rs`.

use pegdyn::replay::json::*;

#[test]
fn numbers_are_short_and_exact_to_their_resolution() {
    assert_eq!(number(0.012_500_123_4, LENGTH), "0.012500123");
    assert_eq!(number(-0.0000000001, LENGTH), "0");
    assert_eq!(number(1.0, ROTATION), "1");
    assert_eq!(number(1234.5678, VALUE), "1234.6");
    assert_eq!(number(-0.000_012_3, VALUE), "-1.23e-5");
    assert_eq!(number(0.0, VALUE), "0");
    assert_eq!(number(0.201_584_271_115_138_8, TIME), "0.201584271115");
    assert_eq!(number(2.5e-7, TIME), "2.5e-7");
    assert_eq!(number(123_456.0, VALUE), "1.2346e5");
    for x in [3.0e-7, -2.5, 1e10, 0.1] {
        let back: f64 = number(x, VALUE).parse().unwrap();
        assert!((back - x).abs() <= 1e-5 * x.abs(), "{x}");
    }
}

#[test]
fn strings_cannot_close_the_script_element() {
    assert_eq!(
        string("a</script>\"\\\n"),
        "\"a\\u003c/script>\\\"\\\\\\u000a\""
    );
}
