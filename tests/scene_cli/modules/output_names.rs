//! The items of `src/output/names.rs`.

use pegdyn::output::names::*;
use std::path::Path;

#[test]
fn names_of_two_scenes_never_coincide() {
    // Pairs of scene names that collided with `_` as the separator.
    let pairs = [("a", "a_events"), ("insert", "insert_rcc"), ("x", "x_run")];
    let parts = [Part::Main, Part::Sub("events"), Part::Sub("views")];
    for (a, b) in pairs {
        for pa in parts {
            for pb in parts {
                for ext in ["csv", "svg", "toml"] {
                    assert_ne!(pa.file_name(a, ext), pb.file_name(b, ext));
                }
            }
            assert!(!of_scene(a, &pa.file_name(b, "csv")), "{a} {b} {pa:?}");
            assert!(!of_scene(b, &pa.file_name(a, "csv")), "{a} {b} {pa:?}");
            assert_ne!(pa.file_name(a, "toml"), manifest(b));
        }
        assert_ne!(manifest(a), manifest(b));
    }
    assert_eq!(Part::Sub("events").file_name("a", "csv"), "a.events.csv");
    assert_eq!(Part::Main.file_name("a_events", "csv"), "a_events.csv");
}

#[test]
fn scene_names_with_the_separator_are_refused_with_a_suggestion() {
    for ok in ["pendulum", "a_events", "Übung 3", "x-run", "a\u{fffd}b"] {
        assert_eq!(check_scene_name(ok), Ok(()), "{ok}");
    }
    let e = check_scene_name("x.run").unwrap_err();
    assert!(e.to_string().contains("`x_run.toml`"), "{e}");
    for bad in ["", ".hidden", "v1.2", "a/b", "a\\b", "a\nb", "a\0b"] {
        assert!(check_scene_name(bad).is_err(), "{bad:?}");
    }
}

#[test]
fn temporary_files_are_recognized_with_their_process() {
    let tmp = temporary(Path::new("out/drop_3d.csv"));
    let file = tmp.file_name().unwrap().to_str().unwrap();
    assert_eq!(temporary_of("drop_3d", file), Some(std::process::id()));
    assert_eq!(temporary_of("drop", file), None);
    assert_eq!(temporary_of("a", ".a.csv.tmp-12"), Some(12));
    assert_eq!(temporary_of("a", ".a.csv.tmp-"), None);
    assert_eq!(temporary_of("a", ".a.csv.tmp-1x"), None);
    assert_eq!(temporary_of("a", "a.csv"), None);
    assert_eq!(temporary_of("a", ".a_b.csv.tmp-3"), None);
}
