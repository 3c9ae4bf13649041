//! What a model hands to the code generator: modules of functions, each with
//! named vector inputs and named outputs.
//!
//! A [`Module`] is emitted as `pub mod name { .. }`; each [`FnSpec`] as one
//! straight-line `pub fn f<T: Real>` taking `&SVector<T, N>` per [`Input`] and
//! returning `T`, `SVector` or `SMatrix` per [`Output`] (a tuple when there
//! are several). The ids refer to the [`Graph`] the model was built in.

use crate::eval::Tape;
use crate::expr::Expr;
use crate::graph::{Graph, Id, Node, Sym};

/// A vector input: `name: &SVector<T, syms.len()>`, component `k` bound to
/// symbol `syms[k]`. The module exports `<NAME>_NAMES` with the symbol names.
#[derive(Clone, Debug, PartialEq)]
pub struct Input {
    pub name: String,
    pub syms: Vec<Sym>,
}

/// One output of a function. Matrices are stored row-major.
#[derive(Clone, Debug, PartialEq)]
pub enum Output {
    /// Returned as the scalar `T`.
    Scalar(Id),
    /// Returned as `SVector<T, n>`.
    Vector(Vec<Id>),
    /// Returned as `SMatrix<T, rows, cols>`; `entries` row-major.
    Matrix {
        rows: usize,
        cols: usize,
        entries: Vec<Id>,
    },
    /// Returned as `SMatrix<T, n, n>`; `entries` row-major, and the
    /// generator verifies that entry (i, j) is the same expression as (j, i).
    Symmetric { n: usize, entries: Vec<Id> },
}

/// A function to generate.
#[derive(Clone, Debug, PartialEq)]
pub struct FnSpec {
    pub name: String,
    /// Emitted as the function's doc comment: what it computes, the paper's
    /// equation numbers and units.
    pub doc: String,
    pub inputs: Vec<Input>,
    pub outputs: Vec<(String, Output)>,
}

/// A group of functions emitted as `pub mod name { .. }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Module {
    pub name: String,
    pub doc: String,
    pub functions: Vec<FnSpec>,
}

/// What the ODE adapter of a model (`System`, implementing
/// `pegdyn::system::OdeSystem`) needs to know besides its functions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Layout {
    /// The model (module) name.
    pub model: String,
    /// State component names, in order.
    pub state: Vec<String>,
    /// What each state component is, with units.
    pub state_docs: Vec<String>,
    /// Parameter names, in order.
    pub params: Vec<String>,
    /// What each parameter is, with units.
    pub param_docs: Vec<String>,
    /// `Some(n)`: Lagrangian with `n` degrees of freedom (state (q, q̇)).
    /// `None`: explicit first-order system.
    pub dof: Option<usize>,
    /// Whether a closed-form `rhs` function was generated.
    pub closed_rhs: bool,
    /// Whether the functions take the time `t` (explicitly time-dependent).
    pub time: bool,
    /// Whether to emit the adapter.
    pub adapter: bool,
}

/// The symbol behind `e`.
///
/// # Panics
/// If `e` is not a symbol (a bug in the model that builds the input).
pub fn sym_of(e: Expr<'_>) -> Sym {
    match e.node() {
        Node::Sym(s) => s,
        _ => panic!("`{e}` is not a symbol and cannot be a function input"),
    }
}

impl Input {
    /// The input `name` made of the symbols `syms`, in order.
    ///
    /// # Panics
    /// If an element of `syms` is not a symbol.
    pub fn new(name: &str, syms: &[Expr<'_>]) -> Input {
        Input {
            name: name.to_owned(),
            syms: syms.iter().map(|&e| sym_of(e)).collect(),
        }
    }
}

impl Output {
    /// A scalar output.
    pub fn scalar(e: Expr<'_>) -> Output {
        Output::Scalar(e.id())
    }

    /// A vector output.
    pub fn vector(es: &[Expr<'_>]) -> Output {
        Output::Vector(es.iter().map(|e| e.id()).collect())
    }

    /// A matrix output from its rows (all of the same length).
    pub fn matrix(rows: &[Vec<Expr<'_>>]) -> Output {
        let cols = rows.first().map_or(0, Vec::len);
        let entries = rows.iter().flatten().map(|e| e.id()).collect();
        Output::Matrix {
            rows: rows.len(),
            cols,
            entries,
        }
    }

    /// A symmetric matrix output from its rows; verified symmetric at
    /// generation time.
    pub fn symmetric(rows: &[Vec<Expr<'_>>]) -> Output {
        let entries = rows.iter().flatten().map(|e| e.id()).collect();
        Output::Symmetric {
            n: rows.len(),
            entries,
        }
    }

    /// All entries (row-major for matrices).
    pub fn ids(&self) -> &[Id] {
        match self {
            Output::Scalar(id) => std::slice::from_ref(id),
            Output::Vector(v) => v,
            Output::Matrix { entries, .. } | Output::Symmetric { entries, .. } => entries,
        }
    }

    /// `(rows, cols)`; a vector is a column, a scalar is 1×1.
    pub fn shape(&self) -> (usize, usize) {
        match self {
            Output::Scalar(_) => (1, 1),
            Output::Vector(v) => (v.len(), 1),
            Output::Matrix { rows, cols, .. } => (*rows, *cols),
            Output::Symmetric { n, .. } => (*n, *n),
        }
    }
}

impl FnSpec {
    /// A function named `name` with its doc comment, inputs and named
    /// outputs.
    pub fn new(
        name: &str,
        doc: impl Into<String>,
        inputs: Vec<Input>,
        outputs: Vec<(&str, Output)>,
    ) -> FnSpec {
        FnSpec {
            name: name.to_owned(),
            doc: doc.into(),
            inputs,
            outputs: outputs
                .into_iter()
                .map(|(n, o)| (n.to_owned(), o))
                .collect(),
        }
    }

    /// Evaluates every output with the interpreter ([`Tape`]), `inputs[k]`
    /// giving the values of `self.inputs[k]`. Returns one vector per output
    /// (row-major for matrices). Symbols bound by no input read as NaN.
    ///
    /// This is the oracle the generated code is tested against.
    ///
    /// # Panics
    /// If `inputs` does not match `self.inputs` in number or lengths.
    pub fn interpret(&self, g: &Graph, inputs: &[&[f64]]) -> Vec<Vec<f64>> {
        assert_eq!(
            inputs.len(),
            self.inputs.len(),
            "{}: wrong number of inputs",
            self.name
        );
        let mut values = vec![f64::NAN; g.symbols().len()];
        for (input, vals) in self.inputs.iter().zip(inputs) {
            assert_eq!(
                input.syms.len(),
                vals.len(),
                "{}: input `{}` has wrong length",
                self.name,
                input.name
            );
            for (s, &v) in input.syms.iter().zip(vals.iter()) {
                values[s.index()] = v;
            }
        }
        let roots: Vec<Id> = self
            .outputs
            .iter()
            .flat_map(|(_, o)| o.ids().iter().copied())
            .collect();
        let flat = Tape::new(g, &roots).eval(&values);
        let mut rest = flat.as_slice();
        self.outputs
            .iter()
            .map(|(_, o)| {
                let (head, tail) = rest.split_at(o.ids().len());
                rest = tail;
                head.to_vec()
            })
            .collect()
    }
}
