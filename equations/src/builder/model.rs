//! [`ModelBuilder`]: one model declared by name — coordinates, parameters,
//! dynamics, outputs — and turned into a [`Module`] of functions plus the
//! layout its ODE adapter needs.

use crate::GenError;
use crate::diff;
use crate::expr::Expr;
use crate::graph::{Graph, Sym};
use crate::lagrange;
use crate::model::{FnSpec, Input, Module, Output, sym_of};

/// One generalized coordinate `q` with its velocity `q̇` (both state
/// symbols) and acceleration `q̈` (used inside the Jacobian terms only).
#[derive(Clone, Copy, Debug)]
pub struct Coordinate<'g> {
    /// The coordinate `q`.
    pub q: Expr<'g>,
    /// Its velocity `q̇`, named `<q>_dot`.
    pub v: Expr<'g>,
    accel: Expr<'g>,
}

/// Which functions a model's generated module contains.
///
/// With [`Outputs::adapter`] on, the functions the adapter needs are
/// generated whatever the other flags say.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Outputs {
    /// `rhs(x, p) -> xdot`: the first-order right-hand side ẋ = f(x, p).
    /// For a Lagrangian model it is emitted in closed form (Cramer's rule)
    /// for up to three degrees of freedom; beyond, the adapter solves
    /// M q̈ = f by LU at run time.
    pub rhs: bool,
    /// `dynamics(x, p) -> (mass, forcing)`: M and f of M q̈ = f (Lagrangian
    /// models only).
    pub mass_forcing: bool,
    /// The exact Jacobian: `jacobian_terms(x, qdd, p)` (G with
    /// ∂ẋ/∂x = [[0, I], [M⁻¹G]]) for a Lagrangian model, `jacobian(x, p)`
    /// (∂f/∂x) for an explicit one.
    pub jacobian: bool,
    /// `energy(x, p) -> energy`: T + V for a Lagrangian model, the
    /// expression given to [`ModelBuilder::energy`] for an explicit one
    /// (none when it was not given).
    pub energy: bool,
    /// The ODE adapter `System` implementing `pegdyn::system::OdeSystem`
    /// and the layout constants (`X_<NAME>`, `P_<NAME>`, `X_DOCS`, ...).
    pub adapter: bool,
}

impl Outputs {
    /// Everything off: the model emits only the functions given to
    /// [`ModelBuilder::function`].
    pub const NONE: Outputs = Outputs {
        rhs: false,
        mass_forcing: false,
        jacobian: false,
        energy: false,
        adapter: false,
    };
}

impl Default for Outputs {
    /// Everything on.
    fn default() -> Outputs {
        Outputs {
            rhs: true,
            mass_forcing: true,
            jacobian: true,
            energy: true,
            adapter: true,
        }
    }
}

/// How the model's motion is given.
#[derive(Clone, Debug)]
enum Dynamics<'g> {
    /// T, V and one generalized force per coordinate.
    Lagrange {
        t: Expr<'g>,
        v: Expr<'g>,
        forces: Vec<Expr<'g>>,
    },
    /// ẋ = f(x, p[, t]) component by component.
    Explicit(Vec<Expr<'g>>),
}

/// What the ODE adapter of a model needs to know, besides its functions.
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

/// Declares one model. Obtained inside [`super::Generator::model`]; every
/// expression it hands out lives in the model's own [`Graph`].
pub struct ModelBuilder<'g> {
    g: &'g Graph,
    name: String,
    doc: String,
    reference: String,
    coords: Vec<(Coordinate<'g>, String)>,
    states: Vec<(Expr<'g>, String)>,
    params: Vec<(Expr<'g>, String)>,
    time: Option<Expr<'g>>,
    dynamics: Option<Dynamics<'g>>,
    energy: Option<Expr<'g>>,
    outputs: Outputs,
    extras: Vec<(String, String, Output)>,
    functions: Vec<Function<'g>>,
    names: Vec<String>,
}

/// A function declared with [`ModelBuilder::function`]: its own inputs
/// (before the parameters) and several named outputs.
struct Function<'g> {
    name: String,
    doc: String,
    inputs: Vec<(String, Vec<Expr<'g>>)>,
    outputs: Vec<(String, Output)>,
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
            time: None,
            dynamics: None,
            energy: None,
            outputs: Outputs::default(),
            extras: Vec::new(),
            functions: Vec::new(),
            names: Vec::new(),
        }
    }

    /// The model's expression arena, for constants (`g().constant(2.0)`),
    /// sums and products.
    pub fn g(&self) -> &'g Graph {
        self.g
    }

    fn error(&self, function: &str, symbol: &str, reason: impl Into<String>) -> GenError {
        GenError::Model {
            model: self.name.clone(),
            function: function.to_owned(),
            symbol: symbol.to_owned(),
            reason: reason.into(),
        }
    }

    fn claim(&mut self, name: &str) -> Result<(), GenError> {
        let ok = !name.is_empty()
            && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
            && name.starts_with(|c: char| c.is_ascii_alphabetic());
        if !ok {
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

    /// Declares the generalized coordinate `name` and its velocity
    /// `<name>_dot`; `doc` says what it is, with units (it becomes the
    /// state's `X_DOCS` entry). Coordinates come first in the state
    /// `x = (q₁..qₙ, q̇₁..q̇ₙ)`, in declaration order.
    pub fn coordinate(&mut self, name: &str, doc: &str) -> Result<Coordinate<'g>, GenError> {
        self.claim(name)?;
        let vname = format!("{name}_dot");
        self.claim(&vname)?;
        let c = Coordinate {
            q: self.g.var(name),
            v: self.g.var(&vname),
            accel: self.g.var(&format!("{name}_ddot")),
        };
        self.coords.push((c, doc.to_owned()));
        Ok(c)
    }

    /// Declares the state component `name` of an explicit first-order
    /// model ([`ModelBuilder::explicit`]), with `doc` (meaning, units).
    pub fn state(&mut self, name: &str, doc: &str) -> Result<Expr<'g>, GenError> {
        self.claim(name)?;
        let s = self.g.var(name);
        self.states.push((s, doc.to_owned()));
        Ok(s)
    }

    /// Declares the parameter `name` (component of `p`, in declaration
    /// order), with `doc` (meaning, units).
    pub fn parameter(&mut self, name: &str, doc: &str) -> Result<Expr<'g>, GenError> {
        self.claim(name)?;
        let p = self.g.param(name);
        self.params.push((p, doc.to_owned()));
        Ok(p)
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
    /// comment of every generated function.
    pub fn reference(&mut self, text: &str) {
        self.reference = text.to_owned();
    }

    /// A named extra function `name(x, p[, t]) -> output` (for example a
    /// contact force or a penetration), documented by `doc`.
    pub fn output(&mut self, name: &str, doc: &str, output: Output) {
        self.extras.push((name.to_owned(), doc.to_owned(), output));
    }

    /// Declares the input symbol `name` that is neither a state component
    /// nor a parameter (an angle a function is evaluated at, a force given
    /// from outside), with `doc` (meaning, units); it is used in the inputs
    /// of [`ModelBuilder::function`].
    pub fn symbol(&mut self, name: &str, doc: &str) -> Result<Expr<'g>, GenError> {
        self.claim(name)?;
        let _ = doc;
        Ok(self.g.var(name))
    }

    /// A named function `name(inputs..., p[, t]) -> (outputs...)` with its
    /// own inputs (each a name and its symbols, declared with
    /// [`ModelBuilder::state`] or [`ModelBuilder::symbol`]) followed by the
    /// parameter vector `p` (and the time when the model uses it), and
    /// several named outputs; documented by `doc`. Functions are emitted
    /// after the dynamics' functions, in declaration order. A model made
    /// only of such functions needs no dynamics when its adapter is off
    /// ([`Outputs::adapter`]): its right-hand side can then take an input
    /// besides the state, such as a wrench summed at run time.
    ///
    /// # Errors
    /// [`GenError::Model`] for a function or input name that is not an
    /// ASCII identifier, or a function declared twice.
    pub fn function(
        &mut self,
        name: &str,
        doc: &str,
        inputs: &[(&str, &[Expr<'g>])],
        outputs: Vec<(&str, Output)>,
    ) -> Result<(), GenError> {
        let ident = |n: &str| {
            !n.is_empty()
                && n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
                && n.starts_with(|c: char| c.is_ascii_alphabetic())
        };
        if !ident(name) || self.functions.iter().any(|f| f.name == name) {
            return Err(self.error(name, name, "not an identifier, or declared twice"));
        }
        if let Some((bad, _)) = inputs.iter().find(|(n, _)| !ident(n) || *n == "p") {
            return Err(self.error(name, bad, "input name not an identifier (or `p`)"));
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
                .map(|(n, o)| (n.to_owned(), o))
                .collect(),
        });
        Ok(())
    }

    /// The state symbols, in order.
    fn state_exprs(&self) -> Vec<Expr<'g>> {
        if self.coords.is_empty() {
            return self.states.iter().map(|s| s.0).collect();
        }
        let q = self.coords.iter().map(|c| c.0.q);
        q.chain(self.coords.iter().map(|c| c.0.v)).collect()
    }

    /// Builds the module and the adapter layout.
    pub(crate) fn finish(self) -> Result<(Module, Layout), GenError> {
        let g = self.g;
        let functions_only = !self.functions.is_empty() && !self.outputs.adapter;
        let dynamics = match self.dynamics.clone() {
            Some(d) => Some(d),
            None if functions_only => None,
            None => {
                return Err(self.error(
                    "dynamics",
                    &self.name,
                    "no dynamics: call `lagrange` or `explicit`",
                ));
            }
        };
        let state = self.state_exprs();
        if state.is_empty() && !functions_only {
            return Err(self.error("state", &self.name, "no coordinate or state declared"));
        }
        let mut o = self.outputs;
        let x = Input::new("x", &state);
        let p = Input::new("p", &self.params.iter().map(|p| p.0).collect::<Vec<_>>());
        let t_in = self.time.map(|t| Input::new("t", &[t]));
        let inputs = |extra: Option<&Input>| {
            let mut v = vec![x.clone()];
            v.extend(extra.cloned());
            v.push(p.clone());
            v.extend(t_in.clone());
            v.retain(|i| !i.syms.is_empty());
            v
        };
        let doc = |text: &str| {
            if self.reference.is_empty() {
                text.to_owned()
            } else {
                format!("{text}\n\n{}", self.reference)
            }
        };
        let time_sym: Option<Sym> = self.time.map(sym_of);
        let mut fns = Vec::new();
        let (dof, closed_rhs) = match dynamics {
            None => (None, false),
            Some(Dynamics::Lagrange { t, v, forces }) => {
                if !self.states.is_empty() {
                    let name = self.states[0].0.to_string();
                    return Err(self.error(
                        "lagrange",
                        &name,
                        "a `state` in a Lagrangian model (use `coordinate`)",
                    ));
                }
                let n = self.coords.len();
                if forces.len() != n {
                    return Err(self.error(
                        "lagrange",
                        "forces",
                        format!("{} generalized forces for {n} coordinates", forces.len()),
                    ));
                }
                let coords: Vec<lagrange::Coord<'g>> = self
                    .coords
                    .iter()
                    .map(|(c, _)| (c.q, c.v, c.accel))
                    .collect();
                let lag = lagrange::derive(g, &coords, t, v, &forces);
                let qdd = Input::new("qdd", &lag.accelerations());
                if o.adapter {
                    o.mass_forcing = true;
                    o.jacobian = true;
                }
                if o.mass_forcing {
                    fns.push(FnSpec::new(
                        "dynamics",
                        doc("Mass matrix M(q) and forcing f(q, q̇) of M q̈ = f (Lagrange's equations, derived symbolically)."),
                        inputs(None),
                        vec![("mass", Output::symmetric(&lag.mass)), ("forcing", Output::vector(&lag.forcing))],
                    ));
                }
                let rhs = if o.rhs { lag.rhs() } else { None };
                let closed = rhs.is_some();
                if let Some(rhs) = rhs {
                    fns.push(FnSpec::new(
                        "rhs",
                        doc("First-order right-hand side ẋ = (q̇, M⁻¹f), M⁻¹f by Cramer's rule."),
                        inputs(None),
                        vec![("xdot", Output::vector(&rhs))],
                    ));
                }
                if o.jacobian {
                    fns.push(FnSpec::new(
                        "jacobian_terms",
                        doc("G = ∂f/∂x − Σ_j (∂M_{·j}/∂x) q̈_j (n × 2n) at the accelerations `qdd`;\n\
                             the state Jacobian is ∂ẋ/∂x = [[0, I], [M⁻¹G]] (one LU solve of M)."),
                        inputs(Some(&qdd)),
                        vec![("terms", Output::matrix(&lag.accel_jacobian_terms()))],
                    ));
                    if let Some(ts) = time_sym {
                        let terms: Vec<Expr<'g>> = (0..n)
                            .map(|i| {
                                let dm = g.sum(
                                    lag.accelerations()
                                        .iter()
                                        .zip(&lag.mass[i])
                                        .map(|(&a, &m)| g.expr(diff::diff(g, m.id(), ts)) * a),
                                );
                                g.expr(diff::diff(g, lag.forcing[i].id(), ts)) - dm
                            })
                            .collect();
                        fns.push(FnSpec::new(
                            "time_terms",
                            doc("∂f/∂t − Σ_j (∂M_{·j}/∂t) q̈_j at the accelerations `qdd`; ∂q̈/∂t = M⁻¹ times it."),
                            inputs(Some(&qdd)),
                            vec![("terms", Output::vector(&terms))],
                        ));
                    }
                }
                if o.energy {
                    fns.push(FnSpec::new(
                        "energy",
                        doc(
                            "Total mechanical energy T + V (conserved without generalized forces).",
                        ),
                        inputs(None),
                        vec![("energy", Output::scalar(lag.energy))],
                    ));
                }
                (Some(n), closed)
            }
            Some(Dynamics::Explicit(rhs)) => {
                if !self.coords.is_empty() {
                    let name = self.coords[0].0.q.to_string();
                    return Err(self.error(
                        "explicit",
                        &name,
                        "a `coordinate` in an explicit model (use `state`)",
                    ));
                }
                if rhs.len() != state.len() {
                    return Err(self.error(
                        "explicit",
                        "rhs",
                        format!("{} components for a state of {}", rhs.len(), state.len()),
                    ));
                }
                if o.adapter {
                    o.rhs = true;
                    o.jacobian = true;
                }
                if o.rhs {
                    fns.push(FnSpec::new(
                        "rhs",
                        doc("First-order right-hand side ẋ = f(x, p)."),
                        inputs(None),
                        vec![("xdot", Output::vector(&rhs))],
                    ));
                }
                if o.jacobian {
                    let rows: Vec<Vec<Expr<'g>>> = rhs
                        .iter()
                        .map(|f| state.iter().map(|&s| f.diff(s)).collect())
                        .collect();
                    fns.push(FnSpec::new(
                        "jacobian",
                        doc("Exact Jacobian ∂f/∂x of the right-hand side, entry (i, j) = ∂fᵢ/∂xⱼ."),
                        inputs(None),
                        vec![("jacobian", Output::matrix(&rows))],
                    ));
                    if let Some(ts) = time_sym {
                        let dt: Vec<Expr<'g>> = rhs
                            .iter()
                            .map(|f| g.expr(diff::diff(g, f.id(), ts)))
                            .collect();
                        fns.push(FnSpec::new(
                            "rhs_t",
                            doc("Partial time derivative ∂f/∂t of the right-hand side."),
                            inputs(None),
                            vec![("rhs_t", Output::vector(&dt))],
                        ));
                    }
                }
                if let (true, Some(e)) = (o.energy, self.energy) {
                    fns.push(FnSpec::new(
                        "energy",
                        doc("The model's energy (as given to the builder)."),
                        inputs(None),
                        vec![("energy", Output::scalar(e))],
                    ));
                }
                (None, false)
            }
        };
        for (name, text, output) in &self.extras {
            fns.push(FnSpec::new(
                name,
                doc(text),
                inputs(None),
                vec![(name.as_str(), output.clone())],
            ));
        }
        for f in &self.functions {
            let mut ins: Vec<Input> = f.inputs.iter().map(|(n, e)| Input::new(n, e)).collect();
            ins.push(p.clone());
            ins.extend(t_in.clone());
            ins.retain(|i| !i.syms.is_empty());
            fns.push(FnSpec::new(
                &f.name,
                doc(&f.doc),
                ins,
                f.outputs
                    .iter()
                    .map(|(n, o)| (n.as_str(), o.clone()))
                    .collect(),
            ));
        }
        let state_docs = match dof {
            Some(_) => {
                let q = self.coords.iter().map(|(_, d)| d.clone());
                q.chain(
                    self.coords
                        .iter()
                        .map(|(c, d)| format!("rate of `{}` ({d})", c.q)),
                )
                .collect()
            }
            None => self.states.iter().map(|(_, d)| d.clone()).collect(),
        };
        let layout = Layout {
            model: self.name.clone(),
            state: state.iter().map(|s| s.to_string()).collect(),
            state_docs,
            params: self.params.iter().map(|p| p.0.to_string()).collect(),
            param_docs: self.params.iter().map(|p| p.1.clone()).collect(),
            dof,
            closed_rhs,
            time: self.time.is_some(),
            adapter: o.adapter,
        };
        let module = Module {
            name: self.name,
            doc: self.doc,
            functions: fns,
        };
        Ok((module, layout))
    }
}
