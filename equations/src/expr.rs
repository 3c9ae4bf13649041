//! [`Expr`]: a copyable handle to a node, with operators, so that a model
//! reads like the paper's formulas.
//!
//! Every operator goes through the simplifier ([`crate::simplify`]), which
//! folds constants, applies identities and canonicalizes before the result is
//! hash-consed into the graph.

use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

use crate::graph::{Binary, Const, Graph, Id, Node, SymKind, Unary};
use crate::simplify;

/// A handle to a node of a [`Graph`]. Cheap to copy; equal handles of the
/// same graph denote structurally equal expressions.
#[derive(Clone, Copy)]
pub struct Expr<'g> {
    g: &'g Graph,
    id: Id,
}

impl<'g> Expr<'g> {
    /// Wraps an id of `g`.
    pub fn from_id(g: &'g Graph, id: Id) -> Expr<'g> {
        Expr { g, id }
    }

    /// The node id.
    pub fn id(self) -> Id {
        self.id
    }

    /// The graph this expression lives in.
    pub fn graph(self) -> &'g Graph {
        self.g
    }

    /// The stored node.
    pub fn node(self) -> Node {
        self.g.node(self.id)
    }

    /// `self`, with `name` recorded as the name of its value in generated
    /// code (`let delta = ..;`): a model names its main intermediates so
    /// that the emitted code reads like the derivation. The expression is
    /// returned unchanged (same node, same id; simplification and
    /// hash-consing do not see names); the first name given to a value
    /// wins, and the emitter makes it a valid, unique Rust identifier.
    ///
    /// ```
    /// use pegdyn_equations::Graph;
    /// let g = Graph::new();
    /// let (x, y) = (g.var("x"), g.var("y"));
    /// let d = (x - y).named("delta");
    /// assert_eq!(d, x - y);
    /// assert_eq!(g.label(d.id()).as_deref(), Some("delta"));
    /// ```
    pub fn named(self, name: &str) -> Expr<'g> {
        self.g.set_label(self.id, name);
        self
    }

    /// The value, if this expression is a constant.
    pub fn as_const(self) -> Option<f64> {
        match self.g.node(self.id) {
            Node::Const(c) => Some(c.value()),
            _ => None,
        }
    }

    fn wrap(self, id: Id) -> Expr<'g> {
        Expr { g: self.g, id }
    }

    fn lift(self, v: f64) -> Expr<'g> {
        self.g.constant(v)
    }

    /// `self ^ n` for an integer `n`.
    pub fn powi(self, n: i32) -> Expr<'g> {
        self.pow(self.lift(f64::from(n)))
    }

    /// `self ^ a` for a real constant `a`.
    pub fn powf(self, a: f64) -> Expr<'g> {
        self.pow(self.lift(a))
    }

    /// `self ^ e`.
    pub fn pow(self, e: Expr<'g>) -> Expr<'g> {
        self.wrap(simplify::pow(self.g, self.id, e.id))
    }

    /// `sqrt(self)`, stored as `self ^ 0.5`.
    pub fn sqrt(self) -> Expr<'g> {
        self.powf(0.5)
    }

    /// `self²`.
    pub fn square(self) -> Expr<'g> {
        self.powi(2)
    }

    /// A one-argument function of `self`.
    pub fn apply(self, op: Unary) -> Expr<'g> {
        self.wrap(simplify::unary(self.g, op, self.id))
    }

    /// Sine `sin(self)`.
    pub fn sin(self) -> Expr<'g> {
        self.apply(Unary::Sin)
    }
    /// Cosine `cos(self)`.
    pub fn cos(self) -> Expr<'g> {
        self.apply(Unary::Cos)
    }
    /// Tangent `tan(self)`.
    pub fn tan(self) -> Expr<'g> {
        self.apply(Unary::Tan)
    }
    /// Arcsine `asin(self)`.
    pub fn asin(self) -> Expr<'g> {
        self.apply(Unary::Asin)
    }
    /// Arccosine `acos(self)`.
    pub fn acos(self) -> Expr<'g> {
        self.apply(Unary::Acos)
    }
    /// Arctangent `atan(self)`.
    pub fn atan(self) -> Expr<'g> {
        self.apply(Unary::Atan)
    }
    /// Exponential `exp(self)`.
    pub fn exp(self) -> Expr<'g> {
        self.apply(Unary::Exp)
    }
    /// `exp(self) − 1`, accurate for small arguments.
    pub fn exp_m1(self) -> Expr<'g> {
        self.apply(Unary::Expm1)
    }
    /// Natural logarithm `ln(self)`.
    pub fn ln(self) -> Expr<'g> {
        self.apply(Unary::Ln)
    }
    /// `ln(1 + self)`, accurate for small arguments.
    pub fn ln_1p(self) -> Expr<'g> {
        self.apply(Unary::Ln1p)
    }
    /// Absolute value `|self|`.
    pub fn abs(self) -> Expr<'g> {
        self.apply(Unary::Abs)
    }
    /// `sign(self)`: −1, 0 or 1 (0 at 0), the derivative of `abs`.
    pub fn signum(self) -> Expr<'g> {
        self.apply(Unary::Sign)
    }
    /// Hyperbolic tangent `tanh(self)`.
    pub fn tanh(self) -> Expr<'g> {
        self.apply(Unary::Tanh)
    }
    /// `max(0, self)`: the unilateral contact law.
    pub fn max0(self) -> Expr<'g> {
        self.apply(Unary::Max0)
    }
    /// Heaviside step (0 at 0).
    pub fn step(self) -> Expr<'g> {
        self.apply(Unary::Step)
    }

    /// `atan2(self, x)`.
    pub fn atan2(self, x: Expr<'g>) -> Expr<'g> {
        self.wrap(simplify::binary(self.g, Binary::Atan2, self.id, x.id))
    }

    /// `hypot(self, y) = sqrt(self² + y²)`.
    pub fn hypot(self, y: Expr<'g>) -> Expr<'g> {
        self.wrap(simplify::binary(self.g, Binary::Hypot, self.id, y.id))
    }
}

impl Graph {
    /// The constant `v`.
    ///
    /// # Panics
    /// If `v` is NaN: a NaN constant in a model is a bug in the model.
    pub fn constant(&self, v: f64) -> Expr<'_> {
        let c = Const::new(v).expect("NaN constant in a model");
        Expr::from_id(self, self.intern(Node::Const(c)))
    }

    /// The state variable `name` (a generalized coordinate or velocity).
    pub fn var(&self, name: &str) -> Expr<'_> {
        let s = self.symbol(name, SymKind::Var);
        Expr::from_id(self, self.intern(Node::Sym(s)))
    }

    /// The parameter `name`.
    pub fn param(&self, name: &str) -> Expr<'_> {
        let s = self.symbol(name, SymKind::Param);
        Expr::from_id(self, self.intern(Node::Sym(s)))
    }

    /// Time, `t`.
    pub fn time(&self) -> Expr<'_> {
        let s = self.symbol("t", SymKind::Time);
        Expr::from_id(self, self.intern(Node::Sym(s)))
    }

    /// A handle to `id`.
    pub fn expr(&self, id: Id) -> Expr<'_> {
        Expr::from_id(self, id)
    }

    /// Sum of many expressions (empty sum is 0).
    pub fn sum<'g>(&'g self, terms: impl IntoIterator<Item = Expr<'g>>) -> Expr<'g> {
        let ids: Vec<Id> = terms.into_iter().map(|e| e.id).collect();
        Expr::from_id(self, simplify::add(self, &ids))
    }

    /// Product of many expressions (empty product is 1).
    pub fn product<'g>(&'g self, factors: impl IntoIterator<Item = Expr<'g>>) -> Expr<'g> {
        let ids: Vec<Id> = factors.into_iter().map(|e| e.id).collect();
        Expr::from_id(self, simplify::mul(self, &ids))
    }
}

impl PartialEq for Expr<'_> {
    fn eq(&self, other: &Self) -> bool {
        std::ptr::eq(self.g, other.g) && self.id == other.id
    }
}
impl Eq for Expr<'_> {}

impl fmt::Debug for Expr<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", crate::display::infix(self.g, self.id))
    }
}

impl fmt::Display for Expr<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", crate::display::infix(self.g, self.id))
    }
}

impl<'g> Add for Expr<'g> {
    type Output = Expr<'g>;
    fn add(self, rhs: Expr<'g>) -> Expr<'g> {
        self.wrap(simplify::add(self.g, &[self.id, rhs.id]))
    }
}
impl<'g> Mul for Expr<'g> {
    type Output = Expr<'g>;
    fn mul(self, rhs: Expr<'g>) -> Expr<'g> {
        self.wrap(simplify::mul(self.g, &[self.id, rhs.id]))
    }
}
impl<'g> Neg for Expr<'g> {
    type Output = Expr<'g>;
    fn neg(self) -> Expr<'g> {
        self * -1.0
    }
}
impl<'g> Sub for Expr<'g> {
    type Output = Expr<'g>;
    fn sub(self, rhs: Expr<'g>) -> Expr<'g> {
        self.wrap(simplify::sub(self.g, self.id, rhs.id))
    }
}
impl<'g> Div for Expr<'g> {
    type Output = Expr<'g>;
    fn div(self, rhs: Expr<'g>) -> Expr<'g> {
        self.wrap(simplify::div(self.g, self.id, rhs.id))
    }
}

macro_rules! scalar_ops {
    ($($tr:ident $m:ident),*) => {$(
        impl<'g> $tr<f64> for Expr<'g> {
            type Output = Expr<'g>;
            fn $m(self, rhs: f64) -> Expr<'g> {
                $tr::$m(self, self.lift(rhs))
            }
        }
        impl<'g> $tr<Expr<'g>> for f64 {
            type Output = Expr<'g>;
            fn $m(self, rhs: Expr<'g>) -> Expr<'g> {
                $tr::$m(rhs.lift(self), rhs)
            }
        }
    )*};
}
scalar_ops!(Add add, Sub sub, Mul mul, Div div);
