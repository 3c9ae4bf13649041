//! [`ModelBuilder`]: one model declared by name — coordinates, parameters,
//! dynamics, functions — with what each symbol means and its unit. The
//! steps that turn a declaration into a [`Module`](crate::model::Module)
//! are in `finish.rs`.

use super::outputs::Outputs;
use crate::GenError;
use crate::expr::Expr;
use crate::graph::{Graph, Sym, SymKind};
use crate::model::{Output, sym_of};

/// One generalized coordinate `q` with its velocity `q̇` (both state
/// symbols) and acceleration `q̈` (used inside the Jacobian terms only).
#[derive(Clone, Copy, Debug)]
pub struct Coordinate<'g> {
    /// The coordinate `q`.
    pub q: Expr<'g>,
    /// Its velocity `q̇`, named `<q>_dot` unless named otherwise
    /// ([`ModelBuilder::coordinate_named`]).
    pub v: Expr<'g>,
    pub(super) accel: Expr<'g>,
}

/// How the model's motion is given.
#[derive(Clone, Debug)]
pub(super) enum Dynamics<'g> {
    /// T, V and one generalized force per coordinate.
    Lagrange {
        t: Expr<'g>,
        v: Expr<'g>,
        forces: Vec<Expr<'g>>,
    },
    /// ẋ = f(x, p[, t]) component by component.
    Explicit(Vec<Expr<'g>>),
}

/// A function declared with [`ModelBuilder::function`] or
/// [`ModelBuilder::output`]: its own inputs and its named, documented
/// outputs.
pub(super) struct Function<'g> {
    pub(super) name: String,
    pub(super) doc: String,
    pub(super) inputs: Vec<(String, Vec<Expr<'g>>)>,
    /// (name, doc, value).
    pub(super) outputs: Vec<(String, String, Output)>,
    /// Whether the inputs are `x` only (an [`ModelBuilder::output`]).
    pub(super) of_state: bool,
}

/// A function marked for its parameter Jacobian
/// ([`ModelBuilder::parameter_jacobian`]).
#[derive(Clone, Debug)]
pub(super) struct Mark<'g> {
    /// The marked function.
    pub(super) function: String,
    /// `Some(u)` when the function returns a linear system `A u = b` in
    /// the unknowns `u`: the derivative is then that of `b − A u`.
    pub(super) unknowns: Option<Vec<Expr<'g>>>,
}

/// Declares one model. Obtained inside [`super::Generator::model`]; every
/// expression it hands out lives in the model's own [`Graph`].
pub struct ModelBuilder<'g> {
    pub(super) g: &'g Graph,
    pub(super) name: String,
    pub(super) doc: String,
    pub(super) reference: String,
    pub(super) coords: Vec<Coordinate<'g>>,
    pub(super) states: Vec<Expr<'g>>,
    pub(super) params: Vec<Expr<'g>>,
    /// Name of the parameter vector input (`p` unless renamed).
    pub(super) param_input: String,
    /// What each declared symbol is, with its unit.
    pub(super) docs: Vec<(Sym, String)>,
    pub(super) time: Option<Expr<'g>>,
    pub(super) dynamics: Option<Dynamics<'g>>,
    pub(super) energy: Option<Expr<'g>>,
    pub(super) outputs: Outputs,
    pub(super) functions: Vec<Function<'g>>,
    /// Inputs given a typed struct: (input, struct name, doc).
    pub(super) typed: Vec<(String, String, String)>,
    /// Inputs whose struct is an earlier module's: (input, module).
    pub(super) shared_types: Vec<(String, String)>,
    /// Output structs shared by several functions: (struct name, doc,
    /// functions).
    pub(super) shared_outputs: Vec<(String, String, Vec<String>)>,
    /// Output structs that are an earlier module's: (struct name, module).
    pub(super) shared_out_types: Vec<(String, String)>,
    /// Functions marked for their parameter Jacobian.
    pub(super) param_marks: Vec<Mark<'g>>,
    /// Whether the generator's options ask for this model's parameter
    /// Jacobians.
    pub(crate) parameter_jacobians: bool,
    names: Vec<String>,
}

/// True for an ASCII identifier (letters, digits, `_`; a letter first).
pub(super) fn is_ident(n: &str) -> bool {
    !n.is_empty()
        && n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && n.starts_with(|c: char| c.is_ascii_alphabetic())
}

impl<'g> ModelBuilder<'g> {
    pub(crate) fn new(g: &'g Graph, name: &str, doc: &str) -> ModelBuilder<'g> {
        ModelBuilder {
            g,
            name: name.to_owned(),
            doc: doc.to_owned(),
            reference: String::new(),
            coords: Vec::new(),
            states: Vec::new(),
            params: Vec::new(),
            param_input: "p".to_owned(),
            docs: Vec::new(),
            time: None,
            dynamics: None,
            energy: None,
            outputs: Outputs::default(),
            functions: Vec::new(),
            typed: Vec::new(),
            shared_types: Vec::new(),
            shared_outputs: Vec::new(),
            shared_out_types: Vec::new(),
            param_marks: Vec::new(),
            parameter_jacobians: false,
            names: Vec::new(),
        }
    }

    /// The model's expression arena, for constants (`g().constant(2.0)`),
    /// sums and products.
    pub fn g(&self) -> &'g Graph {
        self.g
    }

    pub(super) fn error(
        &self,
        function: &str,
        symbol: &str,
        reason: impl Into<String>,
    ) -> GenError {
        GenError::Model {
            model: self.name.clone(),
            function: function.to_owned(),
            symbol: symbol.to_owned(),
            reason: reason.into(),
        }
    }

    fn claim(&mut self, name: &str) -> Result<(), GenError> {
        if !is_ident(name) {
            return Err(self.error("declaration", name, "not an ASCII identifier"));
        }
        if name == "t" || self.names.iter().any(|n| n == name) {
            return Err(self.error(
                "declaration",
                name,
                "declared twice (or `t`, reserved for time)",
            ));
        }
        self.names.push(name.to_owned());
        Ok(())
    }

    /// A new symbol `name` of `kind`, documented by `doc`.
    fn declare(&mut self, name: &str, kind: SymKind, doc: &str) -> Result<Expr<'g>, GenError> {
        self.claim(name)?;
        if let Some(s) = self.g.lookup(name)
            && self.g.sym_info(s).kind != kind
        {
            return Err(self.error(
                "declaration",
                name,
                "already a symbol of another kind in this model's arena",
            ));
        }
        let e = match kind {
            SymKind::Param => self.g.param(name),
            _ => self.g.var(name),
        };
        self.docs.push((sym_of(e), doc.to_owned()));
        Ok(e)
    }

    /// Replaces the model's doc comment (the one given to
    /// [`super::Generator::model`]), for a description computed while the
    /// model is declared.
    pub fn doc(&mut self, text: &str) {
        self.doc = text.to_owned();
    }

    /// Declares the generalized coordinate `name` and its velocity
    /// `<name>_dot`; `doc` says what it is, with units (it becomes the
    /// state's `X_DOCS` entry). Coordinates come first in the state
    /// `x = (q₁..qₙ, q̇₁..q̇ₙ)`, in declaration order.
    pub fn coordinate(&mut self, name: &str, doc: &str) -> Result<Coordinate<'g>, GenError> {
        let (v, a) = (format!("{name}_dot"), format!("{name}_ddot"));
        self.coordinate_named(name, &v, &a, doc)
    }

    /// [`ModelBuilder::coordinate`] with the velocity and acceleration named
    /// `velocity` and `acceleration` (`thetadot`, `thetaddot`) instead of
    /// `<name>_dot` and `<name>_ddot`.
    pub fn coordinate_named(
        &mut self,
        name: &str,
        velocity: &str,
        acceleration: &str,
        doc: &str,
    ) -> Result<Coordinate<'g>, GenError> {
        let q = self.declare(name, SymKind::Var, doc)?;
        let v = self.declare(velocity, SymKind::Var, &format!("rate of `{name}` ({doc})"))?;
        let accel = self.declare(
            acceleration,
            SymKind::Var,
            &format!("acceleration of `{name}` ({doc})"),
        )?;
        let c = Coordinate { q, v, accel };
        self.coords.push(c);
        Ok(c)
    }

    /// Declares the state component `name` of an explicit first-order
    /// model ([`ModelBuilder::explicit`]), with `doc` (meaning, units).
    pub fn state(&mut self, name: &str, doc: &str) -> Result<Expr<'g>, GenError> {
        let s = self.declare(name, SymKind::Var, doc)?;
        self.states.push(s);
        Ok(s)
    }

    /// Declares the parameter `name` (component of the parameter vector
    /// `p`, in declaration order), with `doc` (meaning, units).
    pub fn parameter(&mut self, name: &str, doc: &str) -> Result<Expr<'g>, GenError> {
        let p = self.declare(name, SymKind::Param, doc)?;
        self.params.push(p);
        Ok(p)
    }

    /// Names the parameter vector input `name` instead of `p` (in every
    /// function's signature and in `<NAME>_NAMES`).
    ///
    /// # Errors
    /// [`GenError::Model`] for a name that is not an ASCII identifier.
    pub fn parameters_named(&mut self, name: &str) -> Result<(), GenError> {
        if !is_ident(name) {
            return Err(self.error("declaration", name, "not an ASCII identifier"));
        }
        self.param_input = name.to_owned();
        Ok(())
    }

    /// The declared parameters, in the order of the parameter vector: to
    /// place the vector explicitly among a [`ModelBuilder::function`]'s
    /// inputs.
    pub fn parameters(&self) -> Vec<Expr<'g>> {
        self.params.clone()
    }

    /// The name of the parameter vector input (`p` unless renamed with
    /// [`ModelBuilder::parameters_named`]).
    pub fn parameter_input(&self) -> &str {
        &self.param_input
    }

    /// Declares a parameter-like input symbol `name` that is not part of the
    /// parameter vector: a value constant during a call that a function
    /// takes in an input of its own (an applied load, a given friction
    /// direction), with `doc` (meaning, units). Like a parameter it is
    /// treated as constant by the simplifier.
    pub fn input_parameter(&mut self, name: &str, doc: &str) -> Result<Expr<'g>, GenError> {
        self.declare(name, SymKind::Param, doc)
    }

    /// The time `t` (s). Using it makes the model explicitly time-dependent:
    /// every function then takes `t: &SVector<T, 1>` after `p`, and the
    /// adapter's `time_derivative` is exact instead of zero.
    pub fn time(&mut self) -> Expr<'g> {
        *self.time.get_or_insert_with(|| self.g.time())
    }

    /// Gives the model by Lagrange's equations: kinetic energy `t`, potential
    /// `v` and one generalized force per coordinate (a non-conservative
    /// force, e.g. friction or damping; zero for a conservative model):
    /// `d/dt ∂T/∂q̇ − ∂T/∂q + ∂V/∂q = Q`, so M(q) q̈ = f(q, q̇).
    pub fn lagrange(&mut self, t: Expr<'g>, v: Expr<'g>, forces: &[Expr<'g>]) {
        self.dynamics = Some(Dynamics::Lagrange {
            t,
            v,
            forces: forces.to_vec(),
        });
    }

    /// Gives the model explicitly as ẋ = f(x, p[, t]), one expression per
    /// state component declared with [`ModelBuilder::state`].
    pub fn explicit(&mut self, rhs: &[Expr<'g>]) {
        self.dynamics = Some(Dynamics::Explicit(rhs.to_vec()));
    }

    /// The energy emitted as `energy(x, p)` for an explicit model (a
    /// Lagrangian model uses T + V).
    pub fn energy(&mut self, e: Expr<'g>) {
        self.energy = Some(e);
    }

    /// Chooses the generated functions (default: all).
    pub fn outputs(&mut self, outputs: Outputs) {
        self.outputs = outputs;
    }

    /// A reference (book, paper, equation numbers) appended to the doc
    /// comment of every generated function of the dynamics and of
    /// [`ModelBuilder::output`].
    pub fn reference(&mut self, text: &str) {
        self.reference = text.to_owned();
    }

    /// A named extra function `name(x, p[, t]) -> output` (for example a
    /// contact force or a penetration), documented by `doc`.
    pub fn output(&mut self, name: &str, doc: &str, output: Output) {
        self.functions.push(Function {
            name: name.to_owned(),
            doc: doc.to_owned(),
            inputs: Vec::new(),
            outputs: vec![(name.to_owned(), doc.to_owned(), output)],
            of_state: true,
        });
    }

    /// Declares the input symbol `name` that is neither a state component
    /// nor a parameter (an angle a function is evaluated at, a force given
    /// from outside), with `doc` (meaning, units); it is used in the inputs
    /// of [`ModelBuilder::function`].
    pub fn symbol(&mut self, name: &str, doc: &str) -> Result<Expr<'g>, GenError> {
        self.declare(name, SymKind::Var, doc)
    }

    /// A named function `name(inputs..) -> outputs` with its own inputs
    /// (each a name and its symbols, declared with [`ModelBuilder::state`],
    /// [`ModelBuilder::symbol`], [`ModelBuilder::parameter`] or
    /// [`ModelBuilder::input_parameter`]) and several named outputs, each
    /// `(name, doc with units, value)`; documented by `doc`.
    ///
    /// The parameter vector `p` (and the time, when the model uses it) is
    /// appended to the inputs unless one of them is made of parameters only
    /// (the vector itself, [`ModelBuilder::parameters`], placed where the
    /// signature needs it, or a group of parameter-like inputs). Functions
    /// are emitted after the dynamics' functions, in declaration order. A
    /// model made only of such functions needs no dynamics when its adapter
    /// is off ([`Outputs::adapter`]): its right-hand side can then take an
    /// input besides the state, such as a wrench summed at run time.
    ///
    /// # Errors
    /// [`GenError::Model`] for a function or input name that is not an
    /// ASCII identifier, or a function declared twice.
    pub fn function(
        &mut self,
        name: &str,
        doc: &str,
        inputs: &[(&str, &[Expr<'g>])],
        outputs: Vec<(&str, &str, Output)>,
    ) -> Result<(), GenError> {
        if !is_ident(name) || self.functions.iter().any(|f| f.name == name) {
            return Err(self.error(name, name, "not an identifier, or declared twice"));
        }
        if let Some((bad, _)) = inputs.iter().find(|(n, _)| !is_ident(n)) {
            return Err(self.error(name, bad, "input name not an identifier"));
        }
        self.functions.push(Function {
            name: name.to_owned(),
            doc: doc.to_owned(),
            inputs: inputs
                .iter()
                .map(|(n, e)| ((*n).to_owned(), e.to_vec()))
                .collect(),
            outputs: outputs
                .into_iter()
                .map(|(n, d, o)| (n.to_owned(), d.to_owned(), o))
                .collect(),
            of_state: false,
        });
        Ok(())
    }

    /// The state symbols, in order.
    pub(super) fn state_exprs(&self) -> Vec<Expr<'g>> {
        if self.coords.is_empty() {
            return self.states.clone();
        }
        let q = self.coords.iter().map(|c| c.q);
        q.chain(self.coords.iter().map(|c| c.v)).collect()
    }

    /// The declared doc of `e` (empty for an undeclared symbol).
    pub(super) fn doc_of(&self, e: Expr<'g>) -> String {
        self.doc_of_sym(sym_of(e))
    }

    /// The declared doc of symbol `s` (empty for an undeclared symbol).
    pub(super) fn doc_of_sym(&self, s: Sym) -> String {
        self.docs
            .iter()
            .find(|(d, _)| *d == s)
            .map(|(_, d)| d.clone())
            .unwrap_or_default()
    }
}
