//! Turns criterion's results into the tables of `docs/BENCHMARKS.md`.
//!
//! ```sh
//! cargo bench -p pegdyn-benches --bench lib                        # writes target/criterion
//! cp -r target/criterion /tmp/run1               # … repeat for run2, run3
//! cargo run --release -p pegdyn-benches --bin bench_report -- /tmp/run1 /tmp/run2 /tmp/run3
//! ```
//!
//! For every bench id it takes criterion's median time per iteration from
//! `<dir>/<group>/<bench>/new/estimates.json` in each directory, then the
//! median over the directories (repeated runs). It prints markdown tables:
//! generated vs hand vs interpreted per function with their ratios; per
//! function the operation counts of the code generator
//! (`pegdyn::generated::REPORT`), the op-count floor and the ratio of the
//! measured time to it; the per-operation costs; the whole runs.
//!
//! The floor of a function is `Σ count(op) · cost(op)` with `cost(op)` the
//! measured throughput cost of one operation (`ops/<op>` benches: time per
//! 256-element array / 256); the transcendental cost is the mean of `sin`,
//! `powf` and `hypot` (the calls the generated code makes).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Median of a non-empty list.
fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// The median point estimate (ns) in a criterion `estimates.json`.
fn median_estimate(json: &str) -> Option<f64> {
    let rest = &json[json.find("\"median\"")?..];
    let rest = &rest[rest.find("\"point_estimate\"")? + "\"point_estimate\"".len()..];
    let rest = rest.trim_start().strip_prefix(':')?.trim_start();
    let end = rest.find([',', '}']).unwrap_or(rest.len());
    rest[..end].trim().parse().ok()
}

/// `id → median ns` of one criterion directory (ids `group/bench`, or
/// `bench` for ungrouped benches, read from `benchmark.json`).
fn read_dir(root: &Path) -> BTreeMap<String, f64> {
    let mut out = BTreeMap::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(dir) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for e in entries.flatten() {
            let path = e.path();
            if path.is_dir() {
                if path.file_name().is_some_and(|n| n == "new") {
                    let est = std::fs::read_to_string(path.join("estimates.json")).ok();
                    let bench = std::fs::read_to_string(path.join("benchmark.json")).ok();
                    if let (Some(est), Some(bench)) = (est, bench) {
                        if let (Some(ns), Some(id)) = (median_estimate(&est), full_id(&bench)) {
                            out.insert(id, ns);
                        }
                    }
                } else if path
                    .file_name()
                    .is_some_and(|n| n != "report" && n != "base")
                {
                    stack.push(path);
                }
            }
        }
    }
    out
}

/// The `"full_id":"…"` of a criterion `benchmark.json`.
fn full_id(json: &str) -> Option<String> {
    let rest = &json[json.find("\"full_id\"")? + "\"full_id\"".len()..];
    let rest = rest
        .trim_start()
        .strip_prefix(':')?
        .trim_start()
        .strip_prefix('"')?;
    Some(rest[..rest.find('"')?].to_owned())
}

/// One row of the generator's operation-count report.
struct Ops {
    module: String,
    function: String,
    counts: [f64; 6],
}

/// Parses `pegdyn::generated::REPORT`.
fn op_counts() -> Vec<Ops> {
    pegdyn::generated::REPORT
        .lines()
        .skip(1)
        .filter_map(|line| {
            let f: Vec<&str> = line.split_whitespace().collect();
            if f.len() < 8 {
                return None;
            }
            let mut counts = [0.0; 6];
            for (c, s) in counts.iter_mut().zip(&f[2..8]) {
                *c = s.parse().ok()?;
            }
            Some(Ops {
                module: f[0].to_owned(),
                function: f[1].to_owned(),
                counts,
            })
        })
        .collect()
}

fn fmt_ns(ns: Option<f64>) -> String {
    match ns {
        Some(v) if v >= 1e6 => format!("{:.2} ms", v / 1e6),
        Some(v) if v >= 1e3 => format!("{:.2} µs", v / 1e3),
        Some(v) => format!("{v:.1} ns"),
        None => "–".to_owned(),
    }
}

fn ratio(a: Option<f64>, b: Option<f64>) -> String {
    match (a, b) {
        (Some(a), Some(b)) if b > 0.0 => format!("{:.2}", a / b),
        _ => "–".to_owned(),
    }
}

fn main() {
    let dirs: Vec<PathBuf> = std::env::args_os().skip(1).map(PathBuf::from).collect();
    let dirs = if dirs.is_empty() {
        vec![PathBuf::from("target/criterion")]
    } else {
        dirs
    };
    let mut all: BTreeMap<String, Vec<f64>> = BTreeMap::new();
    for d in &dirs {
        for (id, ns) in read_dir(d) {
            all.entry(id).or_default().push(ns);
        }
    }
    let runs = all.values().map(Vec::len).max().unwrap_or(0);
    let t: BTreeMap<String, f64> = all.into_iter().map(|(k, v)| (k, median(v))).collect();
    let get = |id: &str| t.get(id).copied();
    println!("Median over {runs} run(s) of criterion's median time per call.\n");

    // Per-operation costs (ns per element of the 256-element arrays).
    let op = |name: &str| get(&format!("ops/{name}")).map(|ns| ns / 256.0);
    let transc: Vec<f64> = ["sin", "powf", "hypot"]
        .iter()
        .filter_map(|n| op(n))
        .collect();
    let transc = (!transc.is_empty()).then(|| transc.iter().sum::<f64>() / transc.len() as f64);
    let costs = [
        op("add"),
        op("mul"),
        op("div"),
        op("sqrt"),
        transc,
        op("branch"),
    ];
    println!("#### Per-operation cost (throughput, ns per operation)\n");
    println!("| add | mul | div | sqrt | sin | powf | hypot | transc (mean) | branch |");
    println!("|---|---|---|---|---|---|---|---|---|");
    let c = |v: Option<f64>| v.map_or("–".to_owned(), |v| format!("{v:.3}"));
    println!(
        "| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
        c(costs[0]),
        c(costs[1]),
        c(costs[2]),
        c(costs[3]),
        c(op("sin")),
        c(op("powf")),
        c(op("hypot")),
        c(costs[4]),
        c(costs[5])
    );

    println!("#### Generated vs hand vs interpreted (time per call)\n");
    println!(
        "| function | generated | hand | interpreted | generated / hand | interpreted / generated |"
    );
    println!("|---|---|---|---|---|---|");
    let ops = op_counts();
    for o in &ops {
        let id = format!("{}/{}", o.module, o.function);
        let g = get(&format!("{id}/generated"));
        let h = get(&format!("{id}/hand"));
        let i = get(&format!("{id}/interpreted"));
        println!(
            "| {id} | {} | {} | {} | {} | {} |",
            fmt_ns(g),
            fmt_ns(h),
            fmt_ns(i),
            ratio(g, h),
            ratio(i, g)
        );
    }

    println!("\n#### Operation counts and floor\n");
    println!(
        "| function | add | mul | div | sqrt | transc | branch | generated | floor | generated / floor |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for o in &ops {
        let id = format!("{}/{}", o.module, o.function);
        let g = get(&format!("{id}/generated"));
        let floor = costs
            .iter()
            .zip(&o.counts)
            .try_fold(0.0, |acc, (c, n)| c.map(|c| acc + c * n));
        let n = |k: usize| o.counts[k] as usize;
        println!(
            "| {id} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            n(0),
            n(1),
            n(2),
            n(3),
            n(4),
            n(5),
            fmt_ns(g),
            fmt_ns(floor),
            ratio(g, floor)
        );
    }

    println!("\n#### Whole runs\n");
    println!("| bench | time |");
    println!("|---|---|");
    for (id, ns) in &t {
        let per_function = ops
            .iter()
            .any(|o| id.starts_with(&format!("{}/{}/", o.module, o.function)));
        if !per_function && !id.starts_with("ops/") {
            println!("| {id} | {} |", fmt_ns(Some(*ns)));
        }
    }
}
