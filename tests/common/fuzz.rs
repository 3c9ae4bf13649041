//! Scene fuzzing shared by `tests/scene_cli/fuzz.rs` (a bounded case count in
//! CI) and `benches/tools/fuzz_scenes.rs` (runs for a given time): generators of
//! hostile scene texts and the two properties every scene must satisfy.
//!
//! - [`parse_case`]: arbitrary TOML — shipped scenes with byte-level
//!   mutations and structured replacements of their values — goes to the
//!   parser and validator, which must answer `Ok` or typed errors.
//! - [`run_case`]: valid-but-extreme scenes — every number of a shipped
//!   scene replaced, with some probability, by a value drawn log-uniformly
//!   over 600 decades with a random sign — go to `check` and, if accepted,
//!   to a short run bounded by a `[limits]` table; the run must end with a
//!   summary or a typed error and leave only complete, finite files.

#![allow(dead_code)]

use std::path::{Path, PathBuf};

use proptest::prelude::*;

/// The shipped scenes, `(name, text)`: `scenes/` of the crate that
/// includes this file (pegdyn, or the benches crate one level below it).
pub fn shipped_scenes() -> Vec<(String, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = [root.join("scenes"), root.join("../scenes")]
        .into_iter()
        .find(|d| d.is_dir())
        .unwrap_or_default();
    let mut out: Vec<(String, String)> = std::fs::read_dir(&dir)
        .map(|d| {
            d.filter_map(Result::ok)
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|e| e == "toml"))
                .filter_map(|p| {
                    let name = p.file_stem()?.to_string_lossy().into_owned();
                    Some((name, std::fs::read_to_string(&p).ok()?))
                })
                .collect()
        })
        .unwrap_or_default();
    out.sort();
    out
}

/// Byte spans of the numeric values of a TOML text (after `=`, `[` or `,`,
/// outside comments and strings).
pub fn number_spans(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut spans = Vec::new();
    let (mut i, mut in_comment, mut in_string) = (0, false, false);
    let mut prev = b'\n';
    while i < b.len() {
        let c = b[i];
        if in_comment {
            in_comment = c != b'\n';
            if c == b'\n' {
                prev = c;
            }
            i += 1;
            continue;
        }
        if in_string {
            in_string = c != b'"';
            i += 1;
            continue;
        }
        match c {
            b'#' => in_comment = true,
            b'"' => in_string = true,
            b' ' | b'\t' => {}
            b'0'..=b'9' | b'+' | b'-' | b'.' if matches!(prev, b'=' | b'[' | b',') => {
                let start = i;
                while i < b.len()
                    && matches!(b[i], b'0'..=b'9' | b'+' | b'-' | b'.' | b'e' | b'E' | b'_')
                {
                    i += 1;
                }
                let token = text[start..i].replace('_', "");
                if token.parse::<f64>().is_ok() {
                    spans.push((start, i));
                }
                prev = b'0';
                continue;
            }
            _ => prev = c,
        }
        i += 1;
    }
    spans
}

/// A TOML float literal for `v` (TOML spells the specials `nan`, `inf`).
pub fn literal(v: f64) -> String {
    if v.is_nan() {
        "nan".into()
    } else if v.is_infinite() {
        if v > 0.0 { "inf".into() } else { "-inf".into() }
    } else {
        format!("{v:e}")
    }
}

/// `text` with the spans replaced by the given strings (spans sorted).
pub fn replace_spans(text: &str, spans: &[(usize, usize)], with: &[Option<String>]) -> String {
    let mut out = String::with_capacity(text.len());
    let mut at = 0;
    for (&(s, e), w) in spans.iter().zip(with) {
        if let Some(w) = w {
            out.push_str(&text[at..s]);
            out.push_str(w);
            at = e;
        }
    }
    out.push_str(&text[at..]);
    out
}

/// A value log-uniform over 600 decades (`1e-300` to `1e300`) with a
/// random sign.
pub fn extreme() -> impl Strategy<Value = f64> {
    (-300.0..300.0f64, any::<bool>()).prop_map(|(e, neg)| {
        let v = 10f64.powf(e);
        if neg { -v } else { v }
    })
}

/// A hostile replacement for one TOML value: extreme numbers, specials,
/// integers at the type's edge, and values of the wrong type.
pub fn hostile_literal() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => extreme().prop_map(literal),
        1 => prop_oneof![
            Just("nan".to_owned()),
            Just("inf".to_owned()),
            Just("-inf".to_owned()),
            Just("0".to_owned()),
            Just("-0.0".to_owned()),
            Just("4.9e-324".to_owned()),
            Just("1.7976931348623157e308".to_owned()),
            Just("9223372036854775807".to_owned()),
            Just("-9223372036854775808".to_owned()),
            Just("\"text\"".to_owned()),
            Just("[]".to_owned()),
            Just("{}".to_owned()),
            Just("true".to_owned()),
            Just("1979-05-27".to_owned()),
        ],
    ]
}

/// Arbitrary scene text: a shipped scene with structured replacements
/// and byte-level mutations (insert, delete, overwrite).
pub fn mutated_scene() -> impl Strategy<Value = String> {
    let scenes = shipped_scenes();
    let n = scenes.len().max(1);
    (
        0..n,
        proptest::collection::vec(proptest::option::weighted(0.3, hostile_literal()), 64),
        proptest::collection::vec((any::<prop::sample::Index>(), 0u8..3, any::<u8>()), 0..6),
    )
        .prop_map(move |(k, values, edits)| {
            let text = scenes.get(k).map(|s| s.1.clone()).unwrap_or_default();
            let spans = number_spans(&text);
            let with: Vec<Option<String>> = spans
                .iter()
                .enumerate()
                .map(|(i, _)| values[i % 64].clone())
                .collect();
            let mut bytes = replace_spans(&text, &spans, &with).into_bytes();
            for (at, op, byte) in edits {
                if bytes.is_empty() {
                    bytes.push(byte);
                    continue;
                }
                let i = at.index(bytes.len());
                match op {
                    0 => bytes.insert(i, byte),
                    1 => {
                        bytes.remove(i);
                    }
                    _ => bytes[i] = byte,
                }
            }
            String::from_utf8_lossy(&bytes).into_owned()
        })
}

/// The `[limits]` of [`run_case`]: small, so that an accepted scene's run
/// is short.
pub const RUN_LIMITS: &str = "\n[limits]\nmax_output_samples = 20000\nmax_steps = 20000\nmax_grid_points = 2000\nmax_runs = 9\n";

/// A valid-but-extreme scene: a shipped scene whose numbers are each, with
/// probability 0.3, replaced by a value log-uniform over 600 decades, with
/// `max_steps = 20000` in its `[integrator]` and [`RUN_LIMITS`].
pub fn extreme_scene() -> impl Strategy<Value = (String, String)> {
    let scenes = shipped_scenes();
    let n = scenes.len().max(1);
    (
        0..n,
        proptest::collection::vec(proptest::option::weighted(0.3, extreme()), 64),
    )
        .prop_map(move |(k, values)| {
            let (name, text) = scenes.get(k).cloned().unwrap_or_default();
            let spans = number_spans(&text);
            let with: Vec<Option<String>> = spans
                .iter()
                .enumerate()
                .map(|(i, _)| values[i % 64].map(literal))
                .collect();
            let mut text = replace_spans(&text, &spans, &with);
            text = text.replace("[integrator]\n", "[integrator]\nmax_steps = 20000\n");
            text.push_str(RUN_LIMITS);
            (name, text)
        })
}

/// The kinds of the compliant 3-D peg, whose scenes [`extreme_3d_scene`]
/// draws from.
pub const KINDS_3D: [&str; 4] = ["drop_3d", "insert_rcc", "rotation_assist", "design_margins"];

/// A valid-but-extreme scene of a 3-D kind: a shipped scene of one of
/// [`KINDS_3D`] with one to three of its numbers changed, each either
/// scaled by a factor log-uniform over `1e-3 ... 1e3` (most such scenes
/// pass `check` and run: corners of the valid ranges) or, one time in
/// five, replaced by a value log-uniform over 600 decades with a random
/// sign; with [`RUN_LIMITS_3D`].
pub fn extreme_3d_scene() -> impl Strategy<Value = (String, String)> {
    let scenes: Vec<(String, String)> = shipped_scenes()
        .into_iter()
        .filter(|(_, text)| {
            KINDS_3D
                .iter()
                .any(|k| text.contains(&format!("kind = \"{k}\"")))
        })
        .collect();
    let n = scenes.len().max(1);
    let change = (
        any::<usize>(),
        -3.0..3.0f64,
        proptest::option::weighted(0.2, extreme()),
    );
    (0..n, proptest::collection::vec(change, 1..=3)).prop_map(move |(k, changes)| {
        let (name, text) = scenes.get(k).cloned().unwrap_or_default();
        let spans = number_spans(&text);
        let mut with: Vec<Option<String>> = vec![None; spans.len()];
        if !spans.is_empty() {
            for (at, decades, wild) in changes {
                let i = at % spans.len();
                let (s, e) = spans[i];
                let scaled = text[s..e]
                    .replace('_', "")
                    .parse::<f64>()
                    .ok()
                    .map(|v| v * 10f64.powf(decades));
                with[i] = wild.or(scaled).map(literal);
            }
        }
        let mut text = replace_spans(&text, &spans, &with);
        text = text.replace("[integrator]\n", "[integrator]\nmax_steps = 4000\n");
        text.push_str(RUN_LIMITS_3D);
        (name, text)
    })
}

/// The `[limits]` of the 3-D target: room for the shipped grids (16 and
/// 26 insertions), each run cut at 4,000 steps (a cut run still writes its
/// outputs and summary, which are what is checked).
pub const RUN_LIMITS_3D: &str = "\n[limits]\nmax_output_samples = 20000\nmax_steps = 4000\nmax_grid_points = 2000\nmax_runs = 40\n";

/// The parser and validator answer any text with `Ok` or typed errors
/// that name a field or a place (a panic fails the caller).
pub fn parse_case(text: &str) -> Result<(), String> {
    match pegdyn::scene::parse_named(text, "fuzz") {
        Ok(_) => Ok(()),
        Err(e) => {
            let shown = e.to_string();
            if shown.trim().is_empty() {
                Err(format!("empty error message for:\n{text}"))
            } else {
                Ok(())
            }
        }
    }
}

/// Check, then a bounded run in `out` of an accepted scene: every file
/// left in `out` must be complete (no temporary file) and, for CSV, free of
/// NaN and infinities. Returns whether the scene was accepted.
pub fn run_case(name: &str, text: &str, out: &Path) -> Result<bool, String> {
    let Ok(loaded) = pegdyn::scene::parse_named(text, name) else {
        return Ok(false);
    };
    let _ = std::fs::remove_dir_all(out);
    std::fs::create_dir_all(out).map_err(|e| e.to_string())?;
    let sink = pegdyn::output::sink::Sink::directory(out, name);
    let mut ctx = pegdyn::scene::RunContext::new(sink, pegdyn::scene::Progress::silent());
    // Either a summary or a typed error: both are fine; what they leave
    // behind is checked below.
    let result = loaded.run(&mut ctx);
    let files: Vec<PathBuf> = std::fs::read_dir(out)
        .map(|d| d.filter_map(Result::ok).map(|e| e.path()).collect())
        .unwrap_or_default();
    for f in &files {
        let fname = f
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        if fname.starts_with('.') {
            return Err(format!(
                "temporary file {fname} left behind ({result:?}) by:\n{text}"
            ));
        }
        if fname.ends_with(".csv") {
            let csv = std::fs::read_to_string(f).map_err(|e| e.to_string())?;
            for line in csv.lines().skip(1) {
                for cell in line.split(',') {
                    let c = cell.trim_start_matches('-').to_ascii_lowercase();
                    if c == "nan" || c == "inf" {
                        return Err(format!("{fname} holds {cell} ({result:?}) for:\n{text}"));
                    }
                }
            }
        }
    }
    Ok(true)
}

/// The case count of the proptest targets: `PEGDYN_FUZZ_CASES`, else
/// `default`.
pub fn cases(default: u32) -> u32 {
    std::env::var("PEGDYN_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}
