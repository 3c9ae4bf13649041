//! The contracts of the functions a node applies, each written once: the
//! one-argument functions ([`Unary::spec`]), the two-argument ones
//! ([`Binary::spec`]) and the power `b^e` ([`PowForm`]).
//!
//! The interpreter ([`crate::eval`]) evaluates with these rows, the printer
//! ([`crate::display`]) prints their names, the emitter
//! ([`crate::codegen::emit`]) writes their `Real` method or form, the
//! scheduler ([`crate::schedule`]) asks whether they are calls
//! worth a `let` and which operand they repeat, and the operation counter
//! charges their [`Cost`]. A generated function and the interpreter
//! therefore compute every function the same way, bit for bit.

use super::node::{Binary, Unary};

/// What one application of a function costs, in the units of the
/// generation report. `abs` and negation cost nothing (sign-bit
/// operations); `powi(n)` costs the multiplications of square-and-multiply.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Cost {
    /// Multiplications.
    pub mul: usize,
    /// Divisions.
    pub div: usize,
    /// Square roots.
    pub sqrt: usize,
    /// Calls of transcendental functions (`cbrt`, `powf`, trigonometric,
    /// exponential and logarithmic functions, `atan2`, `hypot`).
    pub transcendental: usize,
    /// `if` conditions.
    pub branch: usize,
}

const FREE: Cost = Cost {
    mul: 0,
    div: 0,
    sqrt: 0,
    transcendental: 0,
    branch: 0,
};
const CALL: Cost = Cost {
    transcendental: 1,
    ..FREE
};
const fn branches(n: usize) -> Cost {
    Cost { branch: n, ..FREE }
}

/// One row of the function table.
#[derive(Clone, Copy, Debug)]
pub struct FuncSpec<F> {
    /// Name in infix notation (`sin`, `expm1`).
    pub name: &'static str,
    /// The method of `pegdyn::scalar::Real` (and of `f64`) the generated
    /// code calls (`sin`, `exp_m1`).
    pub method: &'static str,
    /// The value, as both the interpreter and the generated code compute it.
    pub eval: F,
    /// The cost of one call.
    pub cost: Cost,
}

impl<F> FuncSpec<F> {
    /// True for a call worth binding to a `let` of its own (a transcendental
    /// function or a branch; not `abs`).
    pub fn is_call(&self) -> bool {
        self.cost != FREE
    }
}

/// `sign(x)`: -1, 0 or 1, signed zero kept, NaN propagated.
fn sign(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        x * 0.0
    }
}

/// `max(0, x)` with NaN propagated (`f64::max` would swallow it).
fn max0(x: f64) -> f64 {
    if x > 0.0 || x.is_nan() { x } else { 0.0 }
}

/// Heaviside step, 0 at 0, NaN propagated.
fn step(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x.is_nan() {
        x
    } else {
        0.0
    }
}

impl Unary {
    /// The table row of this function.
    pub fn spec(self) -> FuncSpec<fn(f64) -> f64> {
        let row = |name, method, eval: fn(f64) -> f64, cost| FuncSpec {
            name,
            method,
            eval,
            cost,
        };
        match self {
            Unary::Sin => row("sin", "sin", f64::sin, CALL),
            Unary::Cos => row("cos", "cos", f64::cos, CALL),
            Unary::Tan => row("tan", "tan", f64::tan, CALL),
            Unary::Asin => row("asin", "asin", f64::asin, CALL),
            Unary::Acos => row("acos", "acos", f64::acos, CALL),
            Unary::Atan => row("atan", "atan", f64::atan, CALL),
            Unary::Exp => row("exp", "exp", f64::exp, CALL),
            Unary::Expm1 => row("expm1", "exp_m1", f64::exp_m1, CALL),
            Unary::Ln => row("ln", "ln", f64::ln, CALL),
            Unary::Ln1p => row("ln1p", "ln_1p", f64::ln_1p, CALL),
            Unary::Tanh => row("tanh", "tanh", f64::tanh, CALL),
            Unary::Abs => row("abs", "abs", f64::abs, FREE),
            Unary::Sign => row("sign", "sign", sign, branches(2)),
            Unary::Max0 => row("max0", "max0", max0, branches(1)),
            Unary::Step => row("step", "step", step, branches(2)),
        }
    }
}

impl Binary {
    /// The table row of this function (first operand first).
    pub fn spec(self) -> FuncSpec<fn(f64, f64) -> f64> {
        match self {
            Binary::Atan2 => FuncSpec {
                name: "atan2",
                method: "atan2",
                eval: f64::atan2,
                cost: CALL,
            },
            Binary::Hypot => FuncSpec {
                name: "hypot",
                method: "hypot",
                eval: f64::hypot,
                cost: CALL,
            },
        }
    }
}

/// The exponent computed as `cbrt` (the `f64` nearest 1/3).
pub const ONE_THIRD: f64 = 1.0 / 3.0;
/// The exponent computed as `cbrt(x)²` (the `f64` nearest 2/3).
pub const TWO_THIRDS: f64 = 2.0 / 3.0;

/// How `b^e` is computed, by exponent: the one contract of the
/// interpreter, the emitter, the scheduler and the operation counter.
///
/// | exponent            | form                       | emitted                 |
/// |---------------------|----------------------------|-------------------------|
/// | integer, `|n| ≤ 64` | [`PowForm::Int`]           | `b * b`, `b * b * b`, `b.powi(n)`; `1 / b^|n|` below 0 |
/// | `0.5`               | [`PowForm::Sqrt`]          | `b.sqrt()`              |
/// | `-0.5`              | [`PowForm::RecipSqrt`]     | `1 / b.sqrt()`          |
/// | `1.5`               | [`PowForm::SqrtCubed`]     | `b * b.sqrt()`          |
/// | `1/3`               | [`PowForm::Cbrt`]          | `b.cbrt()` (real root, defined below 0) |
/// | `2/3`               | [`PowForm::CbrtSquared`]   | `b.cbrt().powi(2)`      |
/// | anything else       | [`PowForm::Powf`]          | `b.powf(e)`             |
///
/// `b.powi(n)` and `b * b` (`b * b * b`) are the same bits for `n = 2, 3`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PowForm {
    /// An integer exponent `n` with `|n| <= 64`.
    Int(i32),
    /// `b^0.5`.
    Sqrt,
    /// `b^-0.5`.
    RecipSqrt,
    /// `b^1.5`.
    SqrtCubed,
    /// `b^(1/3)`.
    Cbrt,
    /// `b^(2/3)`.
    CbrtSquared,
    /// Any other exponent, or one that is not a constant (`None`).
    Powf(Option<f64>),
}

impl PowForm {
    /// The form for exponent `e` (`None`: not a constant).
    pub fn of(e: Option<f64>) -> PowForm {
        let Some(e) = e else {
            return PowForm::Powf(None);
        };
        if e.fract() == 0.0 && e.abs() <= 64.0 {
            PowForm::Int(e as i32)
        } else if e == 0.5 {
            PowForm::Sqrt
        } else if e == -0.5 {
            PowForm::RecipSqrt
        } else if e == 1.5 {
            PowForm::SqrtCubed
        } else if e == ONE_THIRD {
            PowForm::Cbrt
        } else if e == TWO_THIRDS {
            PowForm::CbrtSquared
        } else {
            PowForm::Powf(Some(e))
        }
    }

    /// `b^e` computed in this form (`e` the exponent it was made for).
    pub fn eval(self, b: f64, e: f64) -> f64 {
        match self {
            PowForm::Int(n) => b.powi(n),
            PowForm::Sqrt => b.sqrt(),
            PowForm::RecipSqrt => 1.0 / b.sqrt(),
            PowForm::SqrtCubed => b * b.sqrt(),
            PowForm::Cbrt => b.cbrt(),
            PowForm::CbrtSquared => {
                let c = b.cbrt();
                c * c
            }
            PowForm::Powf(_) => b.powf(e),
        }
    }

    /// The cost of one evaluation standing alone (a negative integer power
    /// is one division of `1` by the positive power).
    pub fn cost(self) -> Cost {
        match self {
            PowForm::Int(n) => Cost {
                mul: int_power_muls(n.unsigned_abs()),
                div: usize::from(n < 0),
                ..FREE
            },
            PowForm::Sqrt => Cost { sqrt: 1, ..FREE },
            PowForm::RecipSqrt => Cost {
                sqrt: 1,
                div: 1,
                ..FREE
            },
            PowForm::SqrtCubed => Cost {
                sqrt: 1,
                mul: 1,
                ..FREE
            },
            PowForm::Cbrt | PowForm::Powf(_) => CALL,
            PowForm::CbrtSquared => Cost { mul: 1, ..CALL },
        }
    }

    /// True for a call worth binding to a `let` of its own (everything but
    /// an integer power, which is a few multiplications).
    pub fn is_call(self) -> bool {
        !matches!(self, PowForm::Int(_))
    }

    /// True when the emitted form names the base more than once (`b * b`,
    /// `b * b.sqrt()`), so that the base must be a name.
    pub fn repeats_base(self) -> bool {
        match self {
            PowForm::Int(n) => is_repeated_mul(n.unsigned_abs()),
            PowForm::SqrtCubed => true,
            _ => false,
        }
    }
}

/// Integer powers written as repeated multiplication (`b * b`, `b * b * b`)
/// rather than `powi`.
pub fn is_repeated_mul(n: u32) -> bool {
    n == 2 || n == 3
}

/// Multiplications of `b^n`, `n >= 0`, by square-and-multiply (`b * b` and
/// `b * b * b` for `n = 2, 3` are the same count).
pub fn int_power_muls(n: u32) -> usize {
    if n <= 1 {
        return 0;
    }
    let bits = 32 - n.leading_zeros() as usize;
    (bits - 1) + (n.count_ones() as usize - 1)
}
