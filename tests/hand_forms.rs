//! The hand-derived closed forms the benches time against the generated
//! code (`benches/hand.rs`: textbook pendulum, double pendulum and cart-pole
//! from their closed-form mass matrices and forcing, Hertz (9)–(13), the
//! quasi-static Eqs. 51–54, the rigid peg's `rigid::hand_dynamics`) agree with the generated functions on seeded
//! inputs. Two independent derivations of the same physics; a bench that
//! timed a wrong hand form would compare nothing.

#[allow(dead_code)]
#[path = "../benches/cases.rs"]
mod cases;
#[allow(dead_code)]
#[path = "../benches/hand.rs"]
mod hand;

use cases::{Cases, flatten, max_rel_diff};
use pegdyn::generated;

/// Calls generated and hand form on the inputs of `Cases::new(seed)` and
/// returns their largest relative difference.
macro_rules! diff {
    ($cases:expr, $m:ident :: $f:ident ($($a:ident),*)) => {{
        let case = $cases.take(stringify!($m), stringify!($f));
        let mut k = 0..;
        $( let $a = case.input(k.next().unwrap_or(0)); )*
        let g = flatten(&generated::$m::$f($(&$a),*));
        let h = flatten(&hand::$m::$f($(&$a),*));
        assert!(g.iter().any(|v| *v != 0.0), "{}: all zero", stringify!($m::$f));
        max_rel_diff(&h, &g)
    }};
}

#[test]
fn hand_forms_match_generated_code() {
    for seed in 0..50 {
        let mut c = Cases::new(seed);
        let diffs = [
            diff!(c, pendulum::dynamics(x, p)),
            diff!(c, pendulum::rhs(x, p)),
            diff!(c, pendulum::jacobian_terms(x, qdd, p)),
            diff!(c, pendulum::energy(x, p)),
            diff!(c, double_pendulum::dynamics(x, p)),
            diff!(c, double_pendulum::rhs(x, p)),
            diff!(c, double_pendulum::jacobian_terms(x, qdd, p)),
            diff!(c, double_pendulum::energy(x, p)),
            diff!(c, cart_pole::dynamics(x, p)),
            diff!(c, cart_pole::rhs(x, p)),
            diff!(c, cart_pole::jacobian_terms(x, qdd, p)),
            diff!(c, cart_pole::energy(x, p)),
            diff!(c, hertz::ellipse(load, k)),
            diff!(c, hertz::stiffness(k)),
            diff!(c, quasi_static::two_point(pose, load, acc, p)),
            diff!(c, quasi_static::edge_only(pose, load, acc, p)),
            diff!(c, quasi_static::tip_only(pose, load, acc, p)),
            diff!(c, quasi_static::whitney_tip(pose, w, q)),
            diff!(c, rigid_peg::forward(x, p, loads, t)),
            diff!(c, rigid_peg::prescribed(x, qdd, p, loads, t)),
            diff!(c, rigid_peg::contact_velocities(x, p)),
            diff!(c, rigid_peg::energy(x, p)),
            diff!(c, rigid_peg_frictionless::forward(x, p, loads)),
            diff!(c, rigid_peg_frictionless::prescribed(x, qdd, p, loads)),
        ];
        for (k, d) in diffs.iter().enumerate() {
            assert!(
                *d <= 1e-10,
                "seed {seed}, function #{k}: relative difference {d:e}"
            );
        }
    }
}
