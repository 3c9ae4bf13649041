//! Instruction counts per call (valgrind callgrind) of every generated
//! function, its hand-derived form and the interpreter, on the bench
//! inputs: a load-independent companion to the wall-time benches.
//!
//! ```sh
//! benches/callgrind.sh target/callgrind     # runs this example under callgrind
//! ```
//!
//! `instr_count run` calls each form 1000 times inside
//! `callgrind_region`; the script has callgrind dump its counters on every
//! entry of that function (`--dump-before`), so dump `k + 2` holds region
//! `k` (0-based; the last region is in the final dump) plus the printing of
//! the next region's name; it prints the region names in order.
//! `instr_count report DIR` reads the dumps and that order from `DIR` and
//! prints the markdown table: per call, with the cost of an empty region
//! (loop, dynamic call, printing) subtracted.

#[allow(dead_code)]
#[path = "../cases.rs"]
mod cases;
#[allow(dead_code)]
#[path = "../hand.rs"]
mod hand;
#[macro_use]
#[path = "../list.rs"]
mod list;

use std::collections::BTreeMap;
use std::hint::black_box;
use std::path::Path;

use cases::Cases;
use pegdyn::generated;

/// Calls per region.
const CALLS: u64 = 1000;

/// The measured region: `CALLS` calls of `f`.
#[inline(never)]
fn callgrind_region(f: &mut dyn FnMut()) {
    for _ in 0..CALLS {
        f();
    }
}

/// Runs one region and prints its name (the dump order).
fn region(name: String, f: &mut dyn FnMut()) {
    println!("{name}");
    callgrind_region(f);
}

macro_rules! count {
    (@hand $id:expr ; ; $($a:ident),*) => {};
    (@hand $id:expr ; $h:path ; $($a:ident),*) => {
        region(format!("{}/hand", $id), &mut || {
            black_box($h($(black_box(&$a)),*));
        });
    };
    ($cases:expr, $m:ident :: $f:ident ($($a:ident),*) $(=> $h:path)?) => {{
        let mut case = $cases.take(stringify!($m), stringify!($f));
        let mut k = 0..;
        $( let $a = case.input(k.next().expect("endless range")); )*
        let id = concat!(stringify!($m), "/", stringify!($f));
        region(format!("{id}/generated"), &mut || {
            black_box(generated::$m::$f($(black_box(&$a)),*));
        });
        count!(@hand id ; $($h)? ; $($a),*);
        region(format!("{id}/interpreted"), &mut || {
            black_box(case.interpret());
        });
    }};
}

fn run() {
    let mut cases = Cases::new(0);
    region("empty".to_owned(), &mut || {});
    for_each_function!(count!(cases));
}

/// `summary:` / `totals:` of a callgrind dump (instructions).
fn total(path: &Path) -> Option<f64> {
    let text = std::fs::read_to_string(path).ok()?;
    text.lines()
        .find_map(|l| {
            l.strip_prefix("summary:")
                .or_else(|| l.strip_prefix("totals:"))
        })
        .and_then(|v| v.split_whitespace().next()?.parse().ok())
}

fn report(dir: &Path) {
    let order = std::fs::read_to_string(dir.join("order.txt")).unwrap_or_default();
    let mut per_call = BTreeMap::new();
    for (k, name) in order.lines().enumerate() {
        let last = k + 1 == order.lines().count();
        let dump = if last {
            dir.join("cg.out")
        } else {
            dir.join(format!("cg.out.{}", k + 2))
        };
        if let Some(ir) = total(&dump) {
            per_call.insert(name.to_owned(), ir / CALLS as f64);
        }
    }
    let empty = per_call.get("empty").copied().unwrap_or(0.0);
    let get = |id: &str| per_call.get(id).map(|v| v - empty);
    println!("Instructions per call (callgrind; loop overhead {empty:.1} subtracted).\n");
    println!(
        "| function | generated | hand | interpreted | generated / hand | interpreted / generated |"
    );
    println!("|---|---|---|---|---|---|");
    let mut ids: Vec<&str> = order
        .lines()
        .filter_map(|l| l.strip_suffix("/generated"))
        .collect();
    ids.dedup();
    let f = |v: Option<f64>| v.map_or("–".to_owned(), |v| format!("{v:.0}"));
    let r = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) if b > 0.0 => format!("{:.2}", a / b),
        _ => "–".to_owned(),
    };
    for id in ids {
        let (g, h, i) = (
            get(&format!("{id}/generated")),
            get(&format!("{id}/hand")),
            get(&format!("{id}/interpreted")),
        );
        println!(
            "| {id} | {} | {} | {} | {} | {} |",
            f(g),
            f(h),
            f(i),
            r(g, h),
            r(i, g)
        );
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("run") => run(),
        Some("report") if args.len() == 2 => report(Path::new(&args[1])),
        _ => {
            eprintln!("usage: instr_count run | instr_count report DIR");
            std::process::exit(2);
        }
    }
}
