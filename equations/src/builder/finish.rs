//! The steps that turn a [`ModelBuilder`] declaration into a [`Module`]:
//! check the dynamics, derive the functions of the dynamics (Lagrange's
//! equations or the explicit right-hand side), add the declared functions,
//! and describe the adapter's layout.

use super::model::{Dynamics, Function, ModelBuilder};
use super::outputs::Outputs;
use crate::GenError;
use crate::diff;
use crate::expr::Expr;
use crate::graph::{Sym, SymKind};
use crate::lagrange::{self, Lagrange};
use crate::model::{FnSpec, Input, Layout, Module, Output, sym_of};

/// The standard inputs of the model's functions: the state `x`, the
/// parameter vector and the time (when the model uses it).
struct Signature {
    x: Input,
    p: Input,
    t: Option<Input>,
}

impl Signature {
    /// `x`, then `extra` (the accelerations of the Jacobian terms), then
    /// the parameters and the time; empty inputs dropped.
    fn inputs(&self, extra: Option<&Input>) -> Vec<Input> {
        let mut v = vec![self.x.clone()];
        v.extend(extra.cloned());
        v.push(self.p.clone());
        v.extend(self.t.clone());
        v.retain(|i| !i.syms.is_empty());
        v
    }
}

/// What the dynamics step produced besides its functions.
struct Derived {
    /// `Some(n)` for a Lagrangian model with `n` degrees of freedom.
    dof: Option<usize>,
    /// Whether a closed-form `rhs` was generated.
    closed_rhs: bool,
}

impl<'g> ModelBuilder<'g> {
    /// Builds the module (with the adapter's layout), in named steps.
    pub(crate) fn finish(self) -> Result<Module, GenError> {
        let dynamics = self.checked_dynamics()?;
        let sig = self.signature();
        let mut outputs = self.outputs;
        let mut functions = Vec::new();
        let derived = match dynamics {
            None => Derived {
                dof: None,
                closed_rhs: false,
            },
            Some(Dynamics::Lagrange { t, v, forces }) => {
                self.lagrange_functions(t, v, &forces, &sig, &mut outputs, &mut functions)?
            }
            Some(Dynamics::Explicit(rhs)) => {
                self.explicit_functions(&rhs, &sig, &mut outputs, &mut functions)?
            }
        };
        functions.extend(self.functions.iter().map(|f| self.declared(f, &sig)));
        let functions = self.with_parameter_jacobians(functions)?;
        let records = self.records(&functions)?;
        let out_types = self.out_types(&functions)?;
        let layout = self.layout(&derived, outputs);
        let module = Module {
            name: self.name,
            doc: self.doc,
            functions,
            records,
            out_types,
            adapter: Some(layout),
        };
        Ok(module)
    }

    /// The dynamics, or `None` for a model made only of its own functions
    /// without an adapter.
    fn checked_dynamics(&self) -> Result<Option<Dynamics<'g>>, GenError> {
        let functions_only = !self.functions.is_empty() && !self.outputs.adapter;
        match self.dynamics.clone() {
            Some(d) => {
                if self.state_exprs().is_empty() {
                    return Err(self.error("state", &self.name, "no coordinate or state declared"));
                }
                Ok(Some(d))
            }
            None if functions_only => Ok(None),
            None => Err(self.error(
                "dynamics",
                &self.name,
                "no dynamics: call `lagrange` or `explicit`",
            )),
        }
    }

    fn signature(&self) -> Signature {
        Signature {
            x: Input::new("x", &self.state_exprs()),
            p: Input::new(&self.param_input, &self.params),
            t: self.time.map(|t| Input::new("t", &[t])),
        }
    }

    /// `text` with the model's reference appended.
    pub(super) fn with_reference(&self, text: &str) -> String {
        if self.reference.is_empty() {
            text.to_owned()
        } else {
            format!("{text}\n\n{}", self.reference)
        }
    }

    /// Lagrange's equations: `dynamics`, `rhs` (closed form up to three
    /// degrees of freedom), `jacobian_terms` (and `time_terms` for a
    /// time-dependent model), `energy`.
    fn lagrange_functions(
        &self,
        t: Expr<'g>,
        v: Expr<'g>,
        forces: &[Expr<'g>],
        sig: &Signature,
        o: &mut Outputs,
        fns: &mut Vec<FnSpec>,
    ) -> Result<Derived, GenError> {
        if let Some(s) = self.states.first() {
            return Err(self.error(
                "lagrange",
                &s.to_string(),
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
        let coords: Vec<lagrange::Coord<'g>> =
            self.coords.iter().map(|c| (c.q, c.v, c.accel)).collect();
        let lag = lagrange::derive(self.g, &coords, t, v, forces);
        let qdd = Input::new("qdd", &lag.accelerations());
        if o.adapter {
            o.mass_forcing = true;
            o.jacobian = true;
        }
        if o.mass_forcing {
            fns.push(FnSpec::new(
                "dynamics",
                self.with_reference("Mass matrix M(q) and forcing f(q, q̇) of M q̈ = f (Lagrange's equations, derived symbolically)."),
                sig.inputs(None),
                vec![("mass", Output::symmetric(&lag.mass)), ("forcing", Output::vector(&lag.forcing))],
            ));
        }
        let rhs = if o.rhs { lag.rhs() } else { None };
        let closed_rhs = rhs.is_some();
        if let Some(rhs) = rhs {
            fns.push(FnSpec::new(
                "rhs",
                self.with_reference(
                    "First-order right-hand side ẋ = (q̇, M⁻¹f), M⁻¹f by Cramer's rule.",
                ),
                sig.inputs(None),
                vec![("xdot", Output::vector(&rhs))],
            ));
        }
        if self.parameter_jacobians && !self.params.is_empty() {
            fns.push(self.lagrange_parameter_terms(&lag, sig.inputs(Some(&qdd))));
        }
        if o.jacobian {
            fns.push(FnSpec::new(
                "jacobian_terms",
                self.with_reference(
                    "G = ∂f/∂x − Σ_j (∂M_{·j}/∂x) q̈_j (n × 2n) at the accelerations `qdd`;\n\
                     the state Jacobian is ∂ẋ/∂x = [[0, I], [M⁻¹G]] (one LU solve of M).",
                ),
                sig.inputs(Some(&qdd)),
                vec![("terms", Output::matrix(&lag.accel_jacobian_terms()))],
            ));
            if let Some(ts) = self.time.map(sym_of) {
                fns.push(FnSpec::new(
                    "time_terms",
                    self.with_reference("∂f/∂t − Σ_j (∂M_{·j}/∂t) q̈_j at the accelerations `qdd`; ∂q̈/∂t = M⁻¹ times it."),
                    sig.inputs(Some(&qdd)),
                    vec![("terms", Output::vector(&self.time_terms(&lag, ts)))],
                ));
            }
        }
        if o.energy {
            fns.push(FnSpec::new(
                "energy",
                self.with_reference(
                    "Total mechanical energy T + V (conserved without generalized forces).",
                ),
                sig.inputs(None),
                vec![("energy", Output::scalar(lag.energy))],
            ));
        }
        Ok(Derived {
            dof: Some(n),
            closed_rhs,
        })
    }

    /// ∂f/∂t − Σ_j (∂M_{·j}/∂t) q̈_j, one entry per coordinate.
    fn time_terms(&self, lag: &Lagrange<'g>, ts: Sym) -> Vec<Expr<'g>> {
        let g = self.g;
        (0..lag.dof())
            .map(|i| {
                let dm = g.sum(
                    lag.accelerations()
                        .iter()
                        .zip(&lag.mass[i])
                        .map(|(&a, &m)| g.expr(diff::diff(g, m.id(), ts)) * a),
                );
                g.expr(diff::diff(g, lag.forcing[i].id(), ts)) - dm
            })
            .collect()
    }

    /// The explicit model: `rhs`, `jacobian` (and `rhs_t` for a
    /// time-dependent model), `energy` when one was given.
    fn explicit_functions(
        &self,
        rhs: &[Expr<'g>],
        sig: &Signature,
        o: &mut Outputs,
        fns: &mut Vec<FnSpec>,
    ) -> Result<Derived, GenError> {
        let g = self.g;
        if let Some(c) = self.coords.first() {
            return Err(self.error(
                "explicit",
                &c.q.to_string(),
                "a `coordinate` in an explicit model (use `state`)",
            ));
        }
        let state = self.state_exprs();
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
                self.with_reference("First-order right-hand side ẋ = f(x, p)."),
                sig.inputs(None),
                vec![("xdot", Output::vector(rhs))],
            ));
            if self.parameter_jacobians && !self.params.is_empty() {
                fns.push(self.explicit_rhs_p(rhs, sig.inputs(None)));
            }
        }
        if o.jacobian {
            let rows: Vec<Vec<Expr<'g>>> = rhs
                .iter()
                .map(|f| state.iter().map(|&s| f.diff(s)).collect())
                .collect();
            fns.push(FnSpec::new(
                "jacobian",
                self.with_reference(
                    "Exact Jacobian ∂f/∂x of the right-hand side, entry (i, j) = ∂fᵢ/∂xⱼ.",
                ),
                sig.inputs(None),
                vec![("jacobian", Output::matrix(&rows))],
            ));
            if let Some(ts) = self.time.map(sym_of) {
                let dt: Vec<Expr<'g>> = rhs
                    .iter()
                    .map(|f| g.expr(diff::diff(g, f.id(), ts)))
                    .collect();
                fns.push(FnSpec::new(
                    "rhs_t",
                    self.with_reference("Partial time derivative ∂f/∂t of the right-hand side."),
                    sig.inputs(None),
                    vec![("rhs_t", Output::vector(&dt))],
                ));
            }
        }
        if let (true, Some(e)) = (o.energy, self.energy) {
            fns.push(FnSpec::new(
                "energy",
                self.with_reference("The model's energy (as given to the builder)."),
                sig.inputs(None),
                vec![("energy", Output::scalar(e))],
            ));
        }
        Ok(Derived {
            dof: None,
            closed_rhs: false,
        })
    }

    /// A function given to `function` or `output`: its inputs (the state
    /// for an `output`), then the parameter vector unless an input already
    /// carries parameters, then the time unless an input carries it.
    fn declared(&self, f: &Function<'g>, sig: &Signature) -> FnSpec {
        let mut ins: Vec<Input> = if f.of_state {
            vec![sig.x.clone()]
        } else {
            f.inputs.iter().map(|(n, e)| Input::new(n, e)).collect()
        };
        let params_only = |i: &Input| {
            !i.syms.is_empty()
                && i.syms
                    .iter()
                    .all(|&s| self.g.sym_info(s).kind == SymKind::Param)
        };
        if !ins.iter().any(params_only) {
            ins.push(sig.p.clone());
        }
        if let Some(t) = &sig.t
            && !ins.iter().any(|i| i.syms.contains(&t.syms[0]))
        {
            ins.push(t.clone());
        }
        ins.retain(|i| !i.syms.is_empty());
        FnSpec::new(
            &f.name,
            self.with_reference(&f.doc),
            ins,
            f.outputs
                .iter()
                .map(|(n, _, o)| (n.as_str(), o.clone()))
                .collect(),
        )
    }

    /// What the adapter needs: state and parameter names and docs, the
    /// degrees of freedom, whether `rhs` is closed-form and time is used.
    fn layout(&self, d: &Derived, o: Outputs) -> Layout {
        let state = self.state_exprs();
        Layout {
            model: self.name.clone(),
            state: state.iter().map(|s| s.to_string()).collect(),
            state_docs: state.iter().map(|&s| self.doc_of(s)).collect(),
            params: self.params.iter().map(|p| p.to_string()).collect(),
            param_docs: self.params.iter().map(|&p| self.doc_of(p)).collect(),
            dof: d.dof,
            closed_rhs: d.closed_rhs,
            time: self.time.is_some(),
            adapter: o.adapter,
        }
    }
}
