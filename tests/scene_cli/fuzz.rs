//! Fuzz targets for scenes, run as property tests with a bounded case
//! count (`PEGDYN_FUZZ_CASES`, default small enough for CI). For long runs
//! use `benches/tools/fuzz_scenes.rs`; see `docs/fuzzing.md`.

use crate::common::fuzz;

use proptest::prelude::*;

#[test]
fn number_spans_find_the_values_of_a_scene() {
    let text = "kind = \"x\" # 1.0\n[t]\na = 1.5\nb = [0.0, -2e3]\nc = \"3\"\nn = 1_000\n";
    let spans = fuzz::number_spans(text);
    let found: Vec<&str> = spans.iter().map(|&(s, e)| &text[s..e]).collect();
    assert_eq!(found, ["1.5", "0.0", "-2e3", "1_000"]);
    assert!(fuzz::shipped_scenes().len() >= 6);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(fuzz::cases(512)))]

    /// Arbitrary TOML never makes the parser or the validator panic.
    #[test]
    fn parser_and_validator_never_panic(text in fuzz::mutated_scene()) {
        prop_assert_eq!(fuzz::parse_case(&text), Ok(()));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(fuzz::cases(128)))]

    /// Extreme but well-typed scenes are refused with a reason, or run to
    /// a summary or a typed error, leaving only complete, finite files.
    #[test]
    fn extreme_scenes_check_and_run_cleanly((name, text) in fuzz::extreme_scene()) {
        let out = std::env::temp_dir().join(format!("pegdyn-fuzz-run-{}", std::process::id()));
        let r = fuzz::run_case(&name, &text, &out);
        let _ = std::fs::remove_dir_all(&out);
        prop_assert!(r.is_ok(), "{:?}", r);
    }
}
