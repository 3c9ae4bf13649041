//! How scene summaries and descriptions print numbers.

/// `v` rounded to six significant digits, printed in its shortest form
/// (plain decimal for `1e-3 <= |v| < 1e6`, scientific otherwise), so that
/// a summary never prints hundreds of digits.
///
/// ```
/// use pegdyn::scene::significant;
/// assert_eq!(significant(0.123456789), "0.123457");
/// assert_eq!(significant(1e200), "1e200");
/// assert_eq!(significant(2.5), "2.5");
/// assert_eq!(significant(-0.0), "0");
/// ```
pub fn significant(v: f64) -> String {
    if v == 0.0 {
        // Either sign: "-0" reads as a value below zero.
        return "0".to_owned();
    }
    if !v.is_finite() {
        return format!("{v}");
    }
    let rounded: f64 = format!("{v:.5e}").parse().unwrap_or(v);
    if (1e-3..1e6).contains(&rounded.abs()) {
        format!("{rounded}")
    } else {
        format!("{rounded:e}")
    }
}
