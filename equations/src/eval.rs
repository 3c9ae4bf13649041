//! The interpreter: evaluates any DAG at `f64` inputs.
//!
//! Tests use it as the oracle for generated code; benches use it as the
//! "interpreted" baseline. [`Tape`] compiles the nodes reachable from a set
//! of roots into a flat, topologically ordered program once, so that repeated
//! evaluation does no hashing and no recursion.

use crate::graph::{Binary, Graph, Id, Node, PowForm, Sym, Unary};
use crate::schedule::{Schedule, factor_sum, sum_order};

/// Value of a one-argument function: the table row's
/// [`eval`](crate::graph::FuncSpec::eval), the definition the generated code
/// uses (`max0`, `step` and `sign` propagate NaN).
pub fn unary(op: Unary, x: f64) -> f64 {
    (op.spec().eval)(x)
}

/// Value of a two-argument function ([`Binary::spec`]).
pub fn binary(op: Binary, a: f64, b: f64) -> f64 {
    (op.spec().eval)(a, b)
}

/// Value of `base ^ exponent` as the emitter computes it: the form
/// [`PowForm::of`] chooses for the exponent (`sqrt`, `cbrt`, `powi`, ...),
/// the one table of the interpreter, emitter, scheduler and counter.
pub fn pow(b: f64, e: f64) -> f64 {
    PowForm::of(Some(e)).eval(b, e)
}

/// One instruction: the operands are slots of earlier instructions.
#[derive(Clone, Copy, Debug)]
enum Op {
    Const(f64),
    Sym(u32),
    /// Sum of the slots `args[start..start + len]`, left to right.
    Add {
        start: u32,
        len: u32,
    },
    /// Product of the slots `args[start..start + len]`, left to right.
    Mul {
        start: u32,
        len: u32,
    },
    Pow(u32, u32),
    Unary(Unary, u32),
    Binary(Binary, u32, u32),
}

/// A compiled program for the nodes reachable from some roots: one
/// instruction per node (plus the products and sum of each factored sum,
/// [`factor_sum`]), in arena (topological) order, the operands of sums
/// and products in one flat array. Evaluation allocates nothing beyond the
/// caller's scratch buffer.
#[derive(Clone, Debug)]
pub struct Tape {
    ops: Vec<Op>,
    args: Vec<u32>,
    roots: Vec<u32>,
    n_syms: usize,
}

impl Tape {
    /// Compiles the nodes reachable from `roots`.
    pub fn new(g: &Graph, roots: &[Id]) -> Tape {
        // Sums are factored where `factor_sum` factors them under this
        // plan of the canonical DAG (the emitter plans the lowered one).
        let sched = Schedule::new(g, roots);
        let live = &sched.live;
        let n = live.len();
        let mut slot = vec![u32::MAX; n];
        let mut ops = Vec::new();
        let mut args = Vec::new();
        for i in 0..n {
            if !live[i] {
                continue;
            }
            let op = g.with_node(Id(i as u32), |node| {
                let s = |id: &Id| slot[id.index()];
                let list = |args: &mut Vec<u32>, xs: &[Id]| {
                    let start = args.len() as u32;
                    args.extend(xs.iter().map(s));
                    (start, xs.len() as u32)
                };
                match node {
                    Node::Const(c) => Op::Const(c.value()),
                    Node::Sym(sym) => Op::Sym(sym.index() as u32),
                    Node::Add(xs) => {
                        let order = sum_order(g, xs);
                        match factor_sum(g, &order, |t| sched.is_named(t)) {
                            Some(f) => {
                                // common · (Σ c·rest): the extra values get
                                // slots of their own before this node's.
                                let mut terms = Vec::with_capacity(f.rest.len());
                                for (c, rest) in &f.rest {
                                    let mut xs: Vec<u32> = Vec::with_capacity(rest.len() + 1);
                                    if *c != 1.0 || rest.is_empty() {
                                        xs.push(ops.len() as u32);
                                        ops.push(Op::Const(*c));
                                    }
                                    xs.extend(rest.iter().map(s));
                                    let start = args.len() as u32;
                                    args.extend(&xs);
                                    terms.push(ops.len() as u32);
                                    ops.push(Op::Mul {
                                        start,
                                        len: xs.len() as u32,
                                    });
                                }
                                let start = args.len() as u32;
                                args.extend(&terms);
                                let sum = ops.len() as u32;
                                ops.push(Op::Add {
                                    start,
                                    len: terms.len() as u32,
                                });
                                let start = args.len() as u32;
                                args.extend(f.common.iter().map(s));
                                args.push(sum);
                                Op::Mul {
                                    start,
                                    len: f.common.len() as u32 + 1,
                                }
                            }
                            None => {
                                let (start, len) = list(&mut args, &order);
                                Op::Add { start, len }
                            }
                        }
                    }
                    Node::Mul(xs) => {
                        let (start, len) = list(&mut args, xs);
                        Op::Mul { start, len }
                    }
                    Node::Pow(a, b) => Op::Pow(s(a), s(b)),
                    Node::Unary(u, a) => Op::Unary(*u, s(a)),
                    Node::Binary(o, a, b) => Op::Binary(*o, s(a), s(b)),
                }
            });
            slot[i] = ops.len() as u32;
            ops.push(op);
        }
        Tape {
            ops,
            args,
            roots: roots.iter().map(|r| slot[r.index()]).collect(),
            n_syms: g.symbols().len(),
        }
    }

    /// Number of operations (reachable nodes, plus the products and sums
    /// of factored sums, see [`factor_sum`]).
    pub fn len(&self) -> usize {
        self.ops.len()
    }

    /// True for an empty tape.
    pub fn is_empty(&self) -> bool {
        self.ops.is_empty()
    }

    /// Number of symbols the tape expects in `values` (by [`Sym::index`]).
    pub fn n_syms(&self) -> usize {
        self.n_syms
    }

    /// Number of roots, i.e. of values written by [`Tape::eval_into`].
    pub fn n_roots(&self) -> usize {
        self.roots.len()
    }

    /// Evaluates the roots with symbol values `values[sym.index()]`, using
    /// `scratch` as working memory (resized as needed, so a reused buffer
    /// makes evaluation allocation-free), writing `out[k]` for root `k`.
    ///
    /// Sums are evaluated left to right in [`sum_order`] (factored as
    /// [`factor_sum`] says), products left to right in canonical operand
    /// order; powers, functions and their NaN behaviour are [`pow`],
    /// [`unary`] and [`binary`], the definitions the emitted code uses.
    ///
    /// # Panics
    /// If `values` is shorter than a symbol index the tape reads.
    pub fn eval_into(&self, values: &[f64], scratch: &mut Vec<f64>, out: &mut [f64]) {
        scratch.clear();
        scratch.resize(self.ops.len(), 0.0);
        let args = &self.args[..];
        for (i, op) in self.ops.iter().enumerate() {
            let v = |k: u32| scratch[k as usize];
            let r = match *op {
                Op::Const(c) => c,
                Op::Sym(s) => values[s as usize],
                Op::Add { start, len } => {
                    let xs = &args[start as usize..(start + len) as usize];
                    xs[1..].iter().fold(v(xs[0]), |acc, &k| acc + v(k))
                }
                Op::Mul { start, len } => {
                    let xs = &args[start as usize..(start + len) as usize];
                    xs[1..].iter().fold(v(xs[0]), |acc, &k| acc * v(k))
                }
                Op::Pow(a, b) => pow(v(a), v(b)),
                Op::Unary(u, a) => unary(u, v(a)),
                Op::Binary(o, a, b) => binary(o, v(a), v(b)),
            };
            scratch[i] = r;
        }
        for (o, r) in out.iter_mut().zip(&self.roots) {
            *o = scratch[*r as usize];
        }
    }

    /// Evaluates the roots (allocating); see [`Tape::eval_into`].
    pub fn eval(&self, values: &[f64]) -> Vec<f64> {
        let mut scratch = Vec::new();
        let mut out = vec![0.0; self.roots.len()];
        self.eval_into(values, &mut scratch, &mut out);
        out
    }
}

/// Evaluates one expression with symbol values given by `value_of`.
pub fn eval(g: &Graph, root: Id, value_of: impl Fn(Sym) -> f64) -> f64 {
    let values: Vec<f64> = g.symbols().into_iter().map(|(s, _)| value_of(s)).collect();
    Tape::new(g, &[root]).eval(&values)[0]
}
