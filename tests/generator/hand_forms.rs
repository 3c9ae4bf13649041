//! The hand-derived closed forms the benches time against the generated
//! code (`benches/hand.rs`: textbook pendulum, double pendulum and cart-pole
//! from their closed-form mass matrices and forcing, Hertz (9)–(13), the
//! quasi-static Eqs. 51–54, the rigid peg's `rigid_peg::dynamics`) agree with the generated functions on seeded
//! inputs, for every function that `benches/list.rs` gives a hand form (so a
//! new one cannot be missed). Two independent derivations of the same physics; a bench that
//! timed a wrong hand form would compare nothing.

#[allow(dead_code)]
#[path = "../../benches/cases.rs"]
mod cases;
#[allow(dead_code)]
#[path = "../../benches/hand.rs"]
mod hand;
#[macro_use]
#[path = "../../benches/list.rs"]
mod list;

use cases::{Cases, flatten, max_rel_diff};
use pegdyn::generated;

/// For a function of `benches/list.rs` with a hand form: calls generated
/// and hand form on the inputs of `cases` and pushes (name, largest
/// relative difference) to `diffs`; functions without one are skipped.
macro_rules! diff {
    ($cases:expr, $diffs:expr, $m:ident :: $f:ident ($($a:ident),*)) => {};
    ($cases:expr, $diffs:expr, $m:ident :: $f:ident ($($a:ident),*) => $h:path) => {{
        let case = $cases.take(stringify!($m), stringify!($f));
        let mut k = 0..;
        $( let $a = case.input(k.next().expect("endless range")); )*
        let g = flatten(&generated::$m::$f($(&$a),*));
        let h = flatten(&$h($(&$a),*));
        let name = stringify!($m::$f);
        assert!(g.iter().any(|v| *v != 0.0), "{name}: all zero");
        $diffs.push((name, max_rel_diff(&h, &g)));
    }};
}

#[test]
fn hand_forms_match_generated_code() {
    for seed in 0..50 {
        let mut c = Cases::new(seed);
        let mut diffs = Vec::new();
        for_each_function!(diff!(c, diffs));
        assert!(diffs.len() >= 24, "{} hand forms checked", diffs.len());
        for (name, d) in diffs {
            assert!(d <= 1e-10, "seed {seed}, {name}: relative difference {d:e}");
        }
    }
}
