//! The items of `src/output/atomic.rs`.

use pegdyn::error::OutputError;
use pegdyn::output::atomic::*;
use pegdyn::output::names;

#[test]
fn write_replaces_whole_and_leaves_no_temporary_file() {
    let dir = std::env::temp_dir().join(format!("pegdyn-atomic-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("a.csv");
    write(&path, b"one").unwrap();
    write(&path, b"two").unwrap();
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "two");
    assert!(!names::temporary(&path).exists());
    assert_eq!(resolved(&dir.join(".").join("a.csv")), resolved(&path));
    let missing = dir.join("no-such-dir").join("b.csv");
    assert!(matches!(write(&missing, b"x"), Err(OutputError::Io { .. })));
    std::fs::remove_dir_all(&dir).unwrap();
}
