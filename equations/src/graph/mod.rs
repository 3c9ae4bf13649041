//! The hash-consed expression arena.
//!
//! Every expression lives as a [`Node`] in one [`Graph`]. A node refers to its
//! children by [`Id`], and an `Id` is only ever handed out for a node whose
//! children are already in the arena. **Invariant: children come before their
//! parents**, so the arena order is a topological order and every pass
//! (evaluation, differentiation, emission) walks the vector once, forwards.
//!
//! Nodes are hash-consed: interning a node that is structurally equal to one
//! already stored returns the existing `Id`. Common subexpressions are
//! therefore shared by construction, and two expressions are equal as trees
//! exactly when their ids are equal.

mod arena;
pub mod func;
mod node;

pub use arena::{Graph, SymInfo};
pub use func::{Cost, FuncSpec, PowForm};
pub use node::{Binary, Const, Id, Node, Sym, SymKind, Unary};
