//! Runs the scene fuzz targets of `tests/scene_cli/fuzz.rs` for a given time
//! instead of a fixed case count, and reports cases run and findings.
//!
//! ```text
//! cargo run --release -p pegdyn-benches --bin fuzz_scenes -- parse 10    # target, minutes
//! cargo run --release -p pegdyn-benches --bin fuzz_scenes -- run 10
//! cargo run --release -p pegdyn-benches --bin fuzz_scenes -- run3d 10  # the 3-D kinds
//! ```
//!
//! A panic, a finding of the target's property, or a case that takes more
//! than 120 s (a hang) is printed with the scene text; the exit status is 1
//! if anything was found. See `docs/fuzzing.md`.

#[path = "../../tests/common/fuzz.rs"]
mod fuzz;

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

const HANG: Duration = Duration::from_secs(120);

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let target = args.first().map_or("parse", String::as_str).to_owned();
    let minutes: f64 = args.get(1).and_then(|m| m.parse().ok()).unwrap_or(1.0);
    let seed: u64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(20261124);
    if !["parse", "run", "run3d"].contains(&target.as_str()) {
        eprintln!("usage: fuzz_scenes parse|run|run3d [MINUTES] [SEED]");
        std::process::exit(2);
    }
    let scenes = fuzz::shipped_scenes().len();
    if scenes == 0 {
        eprintln!("fuzz_scenes: no shipped scene found under scenes/");
        std::process::exit(2);
    }
    eprintln!("fuzz_scenes: mutating the {scenes} shipped scenes");
    let mut seed_bytes = [0u8; 32];
    seed_bytes[..8].copy_from_slice(&seed.to_le_bytes());
    let mut runner = TestRunner::new_with_rng(
        Config::default(),
        TestRng::from_seed(RngAlgorithm::ChaCha, &seed_bytes),
    );
    // Watchdog: the current case and when it started.
    let current = Arc::new(Mutex::new(String::new()));
    let started = Arc::new(AtomicU64::new(0));
    let epoch = Instant::now();
    {
        let (current, started) = (Arc::clone(&current), Arc::clone(&started));
        std::thread::spawn(move || {
            loop {
                std::thread::sleep(Duration::from_secs(5));
                let since = epoch.elapsed().as_secs() - started.load(Ordering::Relaxed);
                if since > HANG.as_secs() {
                    let text = current.lock().map(|c| c.clone()).unwrap_or_default();
                    eprintln!("HANG: a case has run for {since} s:\n{text}");
                    std::process::exit(1);
                }
            }
        });
    }
    std::panic::set_hook(Box::new(|_| {}));
    let deadline = epoch + Duration::from_secs_f64(minutes * 60.0);
    let out = std::env::temp_dir().join(format!("pegdyn-fuzz-example-{}", std::process::id()));
    let (mut cases, mut accepted, mut findings) = (0u64, 0u64, 0u64);
    while Instant::now() < deadline {
        let (name, text) = if target == "parse" {
            let tree = fuzz::mutated_scene().new_tree(&mut runner);
            (
                "fuzz".to_owned(),
                tree.map(|t| t.current()).unwrap_or_default(),
            )
        } else if target == "run" {
            let tree = fuzz::extreme_scene().new_tree(&mut runner);
            tree.map(|t| t.current()).unwrap_or_default()
        } else {
            let tree = fuzz::extreme_3d_scene().new_tree(&mut runner);
            tree.map(|t| t.current()).unwrap_or_default()
        };
        if let Ok(mut c) = current.lock() {
            c.clone_from(&text);
        }
        started.store(epoch.elapsed().as_secs(), Ordering::Relaxed);
        let result = std::panic::catch_unwind(|| {
            if target == "parse" {
                fuzz::parse_case(&text).map(|()| true)
            } else {
                fuzz::run_case(&name, &text, &out)
            }
        });
        cases += 1;
        match result {
            Ok(Ok(ok)) => accepted += u64::from(ok),
            Ok(Err(finding)) => {
                findings += 1;
                println!("FINDING: {finding}");
            }
            Err(panic) => {
                findings += 1;
                let msg = panic
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| panic.downcast_ref::<&str>().map(|s| (*s).to_owned()))
                    .unwrap_or_default();
                println!("PANIC: {msg}\n{text}");
            }
        }
    }
    let _ = std::fs::remove_dir_all(&out);
    println!(
        "target {target}: {cases} cases in {:.1} min ({accepted} accepted), {findings} findings",
        epoch.elapsed().as_secs_f64() / 60.0
    );
    if findings > 0 {
        std::process::exit(1);
    }
}
