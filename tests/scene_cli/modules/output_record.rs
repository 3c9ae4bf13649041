//! The items of `src/output/record.rs`.

use pegdyn::output::record::*;
use std::path::Path;
use std::time::Duration;
use std::time::UNIX_EPOCH;

#[test]
fn utc_dates_match_the_calendar() {
    let at = |s: u64| utc(UNIX_EPOCH + Duration::from_secs(s));
    assert_eq!(at(0), "1970-01-01T00:00:00Z");
    assert_eq!(at(951_782_400), "2000-02-29T00:00:00Z");
    assert_eq!(at(1_709_251_199), "2024-02-29T23:59:59Z");
    assert_eq!(at(4_102_444_800), "2100-01-01T00:00:00Z");
}

#[test]
fn this_process_is_alive_and_a_reaped_child_is_not() {
    assert_eq!(process_alive(std::process::id()), Some(true));
    if Path::new("/proc/self").exists() {
        let mut child = std::process::Command::new("true").spawn().unwrap();
        let pid = child.id();
        child.wait().unwrap();
        assert_eq!(process_alive(pid), Some(false));
    }
}
