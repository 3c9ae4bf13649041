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
    /// The argument's name (`x`, `p`).
    pub name: String,
    /// The symbol of each component, in order.
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
        /// Number of rows.
        rows: usize,
        /// Number of columns.
        cols: usize,
        /// The entries, row-major.
        entries: Vec<Id>,
    },
    /// Returned as `SMatrix<T, n, n>`; `entries` row-major, and the
    /// generator verifies that entry (i, j) is the same expression as (j, i).
    Symmetric {
        /// Number of rows and columns.
        n: usize,
        /// The entries, row-major.
        entries: Vec<Id>,
    },
}

/// A function to generate.
#[derive(Clone, Debug, PartialEq)]
pub struct FnSpec {
    /// The function's name (snake_case).
    pub name: String,
    /// Emitted as the function's doc comment: what it computes, the paper's
    /// equation numbers and units.
    pub doc: String,
    /// The arguments, in order.
    pub inputs: Vec<Input>,
    /// The named outputs, in order (one is returned as it is, several as
    /// the fields of a struct, [`Module::out_types`]).
    pub outputs: Vec<(String, Output)>,
}

/// A group of functions emitted as `pub mod name { .. }`, with the typed
/// structs of its inputs and outputs.
#[derive(Clone, Debug, PartialEq)]
pub struct Module {
    /// The module's name (`pub mod <name>`).
    pub name: String,
    /// The module's doc comment.
    pub doc: String,
    /// The functions, in emission order.
    pub functions: Vec<FnSpec>,
    /// Typed views of inputs (`Params` for `p`), emitted as structs with one
    /// documented field per component and conversions to and from the
    /// input vector.
    pub records: Vec<Record>,
    /// The structs returned by functions with several outputs; a function
    /// with several outputs that no entry lists returns `<Function>Out`.
    pub out_types: Vec<OutType>,
    /// The layout of the model's ODE adapter (`System`), for a model
    /// declared with one ([`Layout::adapter`]).
    pub adapter: Option<Layout>,
}

/// A typed view of one input of a module: `pub struct <name><T>` with one
/// field per component (named as its symbol, documented by `fields`), and
/// `From` conversions both ways between it and the `SVector` the
/// functions take.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// The input it types (`p`, `loads`).
    pub input: String,
    /// The struct's name (`Params`).
    pub name: String,
    /// The struct's doc comment.
    pub doc: String,
    /// What each component is, with its unit, in input order.
    pub fields: Vec<String>,
    /// `Some(module)`: the struct is the one of that earlier module (same
    /// fields, verified), re-exported rather than emitted again, so that one
    /// value serves both modules.
    pub shared_with: Option<String>,
}

/// A struct returned by functions with several outputs: one field per
/// output, named as the output.
#[derive(Clone, Debug, PartialEq)]
pub struct OutType {
    /// The struct's name (`EllipseOut`, `LinearSystem`).
    pub name: String,
    /// The struct's doc comment.
    pub doc: String,
    /// What each output is, with its unit, in output order.
    pub fields: Vec<String>,
    /// The functions returning it; all have the same output names and
    /// shapes (verified).
    pub functions: Vec<String>,
    /// `Some(module)`: the struct is the one of that earlier module (same
    /// name, fields and shapes, verified), re-exported rather than emitted
    /// again, so that code handling both models' results is written once.
    pub shared_with: Option<String>,
}

impl Module {
    /// A module of `functions` without typed inputs; every function with
    /// several outputs returns its default `<Function>Out`.
    pub fn new(name: &str, doc: &str, functions: Vec<FnSpec>) -> Module {
        Module {
            name: name.to_owned(),
            doc: doc.to_owned(),
            functions,
            records: Vec::new(),
            out_types: Vec::new(),
            adapter: None,
        }
    }

    /// The struct `f` returns when it has several outputs: its entry in
    /// [`Module::out_types`], else `(<Function>Out, no field docs)`.
    pub fn out_type_of(&self, f: &FnSpec) -> (String, Option<&OutType>) {
        match self
            .out_types
            .iter()
            .find(|o| o.functions.contains(&f.name))
        {
            Some(o) => (o.name.clone(), Some(o)),
            None => (default_out_name(&f.name), None),
        }
    }
}

/// `<Function>Out` in CamelCase: `rhs_jacobian` → `RhsJacobianOut`.
pub fn default_out_name(function: &str) -> String {
    let mut out: String = function
        .split('_')
        .filter(|w| !w.is_empty())
        .map(|w| {
            let mut cs = w.chars();
            cs.next()
                .map(|c| c.to_ascii_uppercase().to_string() + cs.as_str())
                .unwrap_or_default()
        })
        .collect();
    out.push_str("Out");
    out
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
