//! Node kinds of the expression DAG.
//!
//! The canonical forms are few on purpose, so that the simplifier has fewer
//! cases to look at:
//! - subtraction `a - b` is `Add[a, Mul[-1, b]]`;
//! - negation `-a` is `Mul[-1, a]`;
//! - division `a / b` is `Mul[a, Pow(b, -1)]`;
//! - `sqrt(a)` is `Pow(a, 0.5)`.
//!
//! The emitter turns these back into `-`, `/` and `.sqrt()`.

/// Index of a node in its [`Graph`](super::Graph). Ids compare in arena order,
/// which is a topological order (children first).
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct Id(pub(crate) u32);

impl Id {
    /// Position of the node in the arena.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// Index of a named symbol (variable, parameter or time) in its graph.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct Sym(pub(crate) u32);

impl Sym {
    /// Position of the symbol in the graph's symbol table.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// What a named symbol stands for.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum SymKind {
    /// A state variable: a generalized coordinate or velocity.
    Var,
    /// A model parameter (mass, length, friction coefficient, ...).
    Param,
    /// Time.
    Time,
}

/// An `f64` constant, stored by its bits so that nodes can be hashed.
///
/// NaN is never stored (the constructors refuse it) and `-0.0` is stored as
/// `0.0`, so that bit equality is value equality.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct Const(u64);

impl Const {
    /// A constant of value `v`; `None` for NaN.
    pub fn new(v: f64) -> Option<Const> {
        if v.is_nan() {
            None
        } else if v == 0.0 {
            Some(Const(0.0f64.to_bits()))
        } else {
            Some(Const(v.to_bits()))
        }
    }

    /// The value.
    pub fn value(self) -> f64 {
        f64::from_bits(self.0)
    }
}

/// One-argument functions.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub enum Unary {
    /// Sine.
    Sin,
    /// Cosine.
    Cos,
    /// Tangent.
    Tan,
    /// Arcsine.
    Asin,
    /// Arccosine.
    Acos,
    /// Arctangent.
    Atan,
    /// Exponential.
    Exp,
    /// `exp(x) - 1`, accurate for small `x`.
    Expm1,
    /// Natural logarithm.
    Ln,
    /// `ln(1 + x)`, accurate for small `x`.
    Ln1p,
    /// Absolute value.
    Abs,
    /// `sign(x)`: -1, 0 or 1 (0 at 0). The derivative of `abs`.
    Sign,
    /// Hyperbolic tangent.
    Tanh,
    /// `max(0, x)`: the unilateral contact law.
    Max0,
    /// Heaviside step: 1 for `x > 0`, 0 for `x <= 0`. The derivative of
    /// `max(0, x)`, with the value 0 at 0 (a contact that just touches
    /// transmits no force and has no stiffness yet).
    Step,
}

/// Two-argument functions other than `Pow`.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub enum Binary {
    /// `atan2(y, x)`, first operand `y`.
    Atan2,
    /// `hypot(x, y) = sqrt(x² + y²)` without overflow or cancellation.
    Hypot,
}

/// A node of the DAG. Children are ids of nodes stored earlier.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub enum Node {
    /// A finite or infinite constant (never NaN).
    Const(Const),
    /// A symbol: a variable, parameter or the time.
    Sym(Sym),
    /// n-ary sum, at least two terms, in canonical order.
    Add(Box<[Id]>),
    /// n-ary product, at least two factors, in canonical order; at most one
    /// constant factor, which comes first.
    Mul(Box<[Id]>),
    /// `base ^ exponent`.
    Pow(Id, Id),
    /// A one-argument function of a node.
    Unary(Unary, Id),
    /// A two-argument function of two nodes.
    Binary(Binary, Id, Id),
}

impl Node {
    /// Calls `f` on every child id, in order.
    pub fn for_each_child(&self, mut f: impl FnMut(Id)) {
        match self {
            Node::Const(_) | Node::Sym(_) => {}
            Node::Add(xs) | Node::Mul(xs) => xs.iter().copied().for_each(f),
            Node::Pow(a, b) | Node::Binary(_, a, b) => {
                f(*a);
                f(*b);
            }
            Node::Unary(_, a) => f(*a),
        }
    }
}
