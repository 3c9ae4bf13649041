//! The list of every generated function with its inputs and, where one
//! exists, its hand-derived form (`benches/hand.rs`), as a macro that calls
//! a callback per function: `for_each_function!(callback!(context…))`
//! expands to `callback!(context…, model::function(inputs…) [=> hand])` for
//! each. Used by the criterion groups (`benches/functions.rs`) and the
//! instruction counts (`examples/instr_count.rs`). Adding a model: one line
//! per function here.

macro_rules! for_each_function {
    ($cb:ident!($($ctx:tt)*)) => {
        $cb!($($ctx)*, pendulum::dynamics(x, p) => hand::pendulum::dynamics);
        $cb!($($ctx)*, pendulum::rhs(x, p) => hand::pendulum::rhs);
        $cb!($($ctx)*, pendulum::jacobian_terms(x, qdd, p) => hand::pendulum::jacobian_terms);
        $cb!($($ctx)*, pendulum::energy(x, p) => hand::pendulum::energy);
        $cb!($($ctx)*, double_pendulum::dynamics(x, p) => hand::double_pendulum::dynamics);
        $cb!($($ctx)*, double_pendulum::rhs(x, p) => hand::double_pendulum::rhs);
        $cb!($($ctx)*, double_pendulum::jacobian_terms(x, qdd, p) => hand::double_pendulum::jacobian_terms);
        $cb!($($ctx)*, double_pendulum::energy(x, p) => hand::double_pendulum::energy);
        $cb!($($ctx)*, cart_pole::dynamics(x, p) => hand::cart_pole::dynamics);
        $cb!($($ctx)*, cart_pole::rhs(x, p) => hand::cart_pole::rhs);
        $cb!($($ctx)*, cart_pole::jacobian_terms(x, qdd, p) => hand::cart_pole::jacobian_terms);
        $cb!($($ctx)*, cart_pole::energy(x, p) => hand::cart_pole::energy);
        $cb!($($ctx)*, hertz::ellipse(load, k) => hand::hertz::ellipse);
        $cb!($($ctx)*, hertz::stiffness(k) => hand::hertz::stiffness);
        $cb!($($ctx)*, compliant_peg::rhs(y, p));
        $cb!($($ctx)*, compliant_peg::jacobian(y, p));
        $cb!($($ctx)*, compliant_peg::contacts(y, p));
        $cb!($($ctx)*, compliant_peg::energy(y, p));
        $cb!($($ctx)*, compliant_peg_lean::rhs(y, p));
        $cb!($($ctx)*, compliant_peg_lean::jacobian(y, p));
        $cb!($($ctx)*, compliant_peg_lean::contacts(y, p));
        $cb!($($ctx)*, compliant_peg_lean::energy(y, p));
        $cb!($($ctx)*, quasi_static::two_point(pose, load, acc, p) => hand::quasi_static::two_point);
        $cb!($($ctx)*, quasi_static::edge_only(pose, load, acc, p) => hand::quasi_static::edge_only);
        $cb!($($ctx)*, quasi_static::tip_only(pose, load, acc, p) => hand::quasi_static::tip_only);
        $cb!($($ctx)*, quasi_static::whitney_tip(pose, w, q) => hand::quasi_static::whitney_tip);
        $cb!($($ctx)*, rigid_peg::forward(x, p, loads, t) => hand::rigid_peg::forward);
        $cb!($($ctx)*, rigid_peg::prescribed(x, qdd, p, loads, t) => hand::rigid_peg::prescribed);
        $cb!($($ctx)*, rigid_peg::contact_velocities(x, p) => hand::rigid_peg::contact_velocities);
        $cb!($($ctx)*, rigid_peg::energy(x, p) => hand::rigid_peg::energy);
        $cb!($($ctx)*, rigid_peg::geometry(x, p));
        $cb!($($ctx)*, rigid_peg_frictionless::forward(x, p, loads) => hand::rigid_peg_frictionless::forward);
        $cb!($($ctx)*, rigid_peg_frictionless::prescribed(x, qdd, p, loads) => hand::rigid_peg_frictionless::prescribed);
        $cb!($($ctx)*, rigid_peg_frictionless::contact_velocities(x, p) => hand::rigid_peg_frictionless::contact_velocities);
        $cb!($($ctx)*, rigid_peg_frictionless::energy(x, p) => hand::rigid_peg_frictionless::energy);
        $cb!($($ctx)*, rigid_peg_planar::forward(x, p, loads, t));
        $cb!($($ctx)*, rigid_peg_planar::prescribed(x, qdd, p, loads, t));
        $cb!($($ctx)*, rigid_peg_planar::contact_velocities(x, p));
        $cb!($($ctx)*, rigid_peg_planar::energy(x, p));
        $cb!($($ctx)*, rigid_peg_planar_frictionless::forward(x, p, loads));
        $cb!($($ctx)*, rigid_peg_planar_frictionless::prescribed(x, qdd, p, loads));
        $cb!($($ctx)*, rigid_peg_planar_frictionless::contact_velocities(x, p));
        $cb!($($ctx)*, rigid_peg_planar_frictionless::energy(x, p));
    };
}
