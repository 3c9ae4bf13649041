//! Every generated function with its inputs and, where one exists, its
//! hand-derived form (`benches/hand.rs`), as a macro that calls a callback
//! per function: `for_each_function!(callback!(context…))` expands to
//! `callback!(context…, model::function(inputs…) [=> hand])` for each. Used
//! by the criterion groups (`benches/functions.rs`), the instruction counts
//! (`benches/tools/instr_count.rs`) and `tests/generator/hand_forms.rs`.
//!
//! The functions come from the generator (`for_each_generated!`, written
//! by build.rs beside the registry `pegdyn::generated::registry`), so a new
//! model needs no line here; only a new hand form does (`hand_form!`).

include!(concat!(env!("OUT_DIR"), "/generated_list.rs"));

/// Every generated output struct flattens its fields in order, as the
/// hand forms' tuples do (`cases::Flat`).
macro_rules! flat_struct {
    ($t:ty, $m:ident::$s:ident { $($f:ident),* }) => {
        impl super::cases::Flat for pegdyn::generated::$m::$s<$t> {
            fn flat(&self, out: &mut Vec<f64>) {
                $(self.$f.flat(out);)*
            }
        }
    };
}
for_each_output_struct!(flat_struct!(f64));

macro_rules! for_each_function {
    ($cb:ident!($($ctx:tt)*)) => {
        for_each_generated!(hand_form!($cb!($($ctx)*)));
    };
}

/// Adds `=> hand::<model>::<function>` to the models whose functions have a
/// hand form in `benches/hand.rs`.
#[rustfmt::skip]
macro_rules! hand_form {
    ($cb:ident!($($ctx:tt)*), rigid_peg::geometry $a:tt) => { $cb!($($ctx)*, rigid_peg::geometry $a) };
    ($cb:ident!($($ctx:tt)*), rigid_peg::forward_p $a:tt) => { $cb!($($ctx)*, rigid_peg::forward_p $a) };
    ($cb:ident!($($ctx:tt)*), pendulum::$f:ident $a:tt) => { $cb!($($ctx)*, pendulum::$f $a => hand::pendulum::$f) };
    ($cb:ident!($($ctx:tt)*), double_pendulum::$f:ident $a:tt) => { $cb!($($ctx)*, double_pendulum::$f $a => hand::double_pendulum::$f) };
    ($cb:ident!($($ctx:tt)*), cart_pole::$f:ident $a:tt) => { $cb!($($ctx)*, cart_pole::$f $a => hand::cart_pole::$f) };
    ($cb:ident!($($ctx:tt)*), hertz::$f:ident $a:tt) => { $cb!($($ctx)*, hertz::$f $a => hand::hertz::$f) };
    ($cb:ident!($($ctx:tt)*), quasi_static::$f:ident $a:tt) => { $cb!($($ctx)*, quasi_static::$f $a => hand::quasi_static::$f) };
    ($cb:ident!($($ctx:tt)*), rigid_peg::$f:ident $a:tt) => { $cb!($($ctx)*, rigid_peg::$f $a => hand::rigid_peg::$f) };
    ($cb:ident!($($ctx:tt)*), rigid_peg_frictionless::$f:ident $a:tt) => { $cb!($($ctx)*, rigid_peg_frictionless::$f $a => hand::rigid_peg_frictionless::$f) };
    ($cb:ident!($($ctx:tt)*), $m:ident::$f:ident $a:tt) => { $cb!($($ctx)*, $m::$f $a) };
}
