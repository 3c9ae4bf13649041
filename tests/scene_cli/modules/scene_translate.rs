//! The items of `src/scene/translate.rs`.

use pegdyn::internals::scene::*;

#[test]
fn rust_types_read_as_toml_words() {
    assert_eq!(plain_type("u64"), "a non-negative integer");
    assert_eq!(plain_type("usize"), "a non-negative integer");
    assert_eq!(plain_type("f64"), "a number");
    assert_eq!(plain_type("struct PegTable"), "a table");
    assert_eq!(plain_value("integer `-3`"), "-3");
    assert_eq!(plain_value("floating point `1.5`"), "1.5");
    assert_eq!(
        plain_found("integer `99999999999999999999` as i128"),
        "an integer 99999999999999999999"
    );
    assert_eq!(plain_found("map"), "a table");
    assert_eq!(plain_found("sequence"), "an array");
    assert_eq!(plain_found("floating point `1.5`"), "a float 1.5");
    assert_eq!(
        plain_text("expected u64 as i128"),
        "expected non-negative integer"
    );
}
