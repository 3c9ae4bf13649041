//! Parameter Jacobians `∂f/∂p`: which functions of a model get one
//! ([`ModelBuilder::parameter_jacobian`],
//! [`ModelBuilder::solution_parameter_jacobian`]), and the functions
//! derived from them when the generator's
//! [`Options::parameter_jacobians`](crate::Options::parameter_jacobians)
//! names the model.
//!
//! Each is straight-line code through the same pipeline as `∂f/∂x`; the
//! columns are the parameters in the order of the parameter vector
//! (`P_NAMES`).

use super::model::{Mark, ModelBuilder};
use crate::GenError;
use crate::diff;
use crate::expr::Expr;
use crate::graph::{Id, Node, Sym};
use crate::lagrange::Lagrange;
use crate::model::{FnSpec, Input, Output, sym_of};

impl<'g> ModelBuilder<'g> {
    /// Asks for the parameter Jacobian of the declared function `function`
    /// (scalar and vector outputs): `<function>_p`, with the same inputs
    /// and, per output `o`, the output `d<o>_dp` with entry
    /// `(i, k) = ∂oᵢ/∂p_k` (a vector for a scalar output). Generated only
    /// when the generator's options name this model
    /// ([`Options::parameter_jacobians`](crate::Options::parameter_jacobians)).
    ///
    /// # Errors
    /// [`GenError::Model`] for a name that is not an ASCII identifier.
    pub fn parameter_jacobian(&mut self, function: &str) -> Result<(), GenError> {
        self.mark(function, None)
    }

    /// Asks for the parameter Jacobian of the solution `u` of the linear
    /// system `A u = b` the declared function `function` returns (outputs
    /// `A` then `b`, `A` with one column per element of `unknowns`):
    /// `<function>_p`, whose inputs are the function's with `u` (the
    /// unknowns' symbols) inserted after the first, returns
    /// `∂(b − A u)/∂p` at the given `u`, so that
    /// `A ∂u/∂p = ∂(b − A u)/∂p` (one more solve with the same `A`).
    /// Generated only when the options name this model.
    ///
    /// # Errors
    /// [`GenError::Model`] for a name that is not an ASCII identifier or an
    /// unknown that is not a symbol.
    pub fn solution_parameter_jacobian(
        &mut self,
        function: &str,
        unknowns: &[Expr<'g>],
    ) -> Result<(), GenError> {
        if let Some(u) = unknowns.iter().find(|u| !matches!(u.node(), Node::Sym(_))) {
            return Err(self.error(function, &u.to_string(), "an unknown that is not a symbol"));
        }
        self.mark(function, Some(unknowns.to_vec()))
    }

    fn mark(&mut self, function: &str, unknowns: Option<Vec<Expr<'g>>>) -> Result<(), GenError> {
        if !super::model::is_ident(function) {
            return Err(self.error("parameter_jacobian", function, "not an ASCII identifier"));
        }
        self.param_marks.push(Mark {
            function: function.to_owned(),
            unknowns,
        });
        Ok(())
    }

    /// The parameter symbols.
    fn param_syms(&self) -> Vec<Sym> {
        self.params.iter().map(|&p| sym_of(p)).collect()
    }

    /// `∂e/∂p_k` for every parameter, in vector order.
    fn param_row(&self, e: Id) -> Vec<Expr<'g>> {
        self.param_syms()
            .into_iter()
            .map(|s| self.g.expr(diff::diff(self.g, e, s)))
            .collect()
    }

    /// `rhs_p` of an explicit model: `∂f/∂p`, `n × n_p`.
    pub(super) fn explicit_rhs_p(&self, rhs: &[Expr<'g>], inputs: Vec<Input>) -> FnSpec {
        let rows: Vec<Vec<Expr<'g>>> = rhs.iter().map(|f| self.param_row(f.id())).collect();
        FnSpec::new(
            "rhs_p",
            self.with_reference(
                "Exact parameter Jacobian ∂f/∂p of the right-hand side, entry (i, k) = ∂fᵢ/∂p_k \
                 (columns in `P_NAMES` order).",
            ),
            inputs,
            vec![("rhs_p", Output::matrix(&rows))],
        )
    }

    /// `parameter_terms` of a Lagrangian model:
    /// `∂f/∂p − Σ_j (∂M_{·j}/∂p) q̈_j` (`n × n_p`) at the accelerations
    /// `qdd`, so that `∂q̈/∂p = M⁻¹` times it.
    pub(super) fn lagrange_parameter_terms(
        &self,
        lag: &Lagrange<'g>,
        inputs: Vec<Input>,
    ) -> FnSpec {
        let g = self.g;
        let rows: Vec<Vec<Expr<'g>>> = (0..lag.dof())
            .map(|i| {
                self.param_syms()
                    .into_iter()
                    .map(|s| {
                        let dm = g.sum(
                            lag.accelerations()
                                .iter()
                                .zip(&lag.mass[i])
                                .map(|(&a, &m)| g.expr(diff::diff(g, m.id(), s)) * a),
                        );
                        g.expr(diff::diff(g, lag.forcing[i].id(), s)) - dm
                    })
                    .collect()
            })
            .collect();
        FnSpec::new(
            "parameter_terms",
            self.with_reference(
                "∂f/∂p − Σ_j (∂M_{·j}/∂p) q̈_j at the accelerations `qdd` (n × n_p, columns in \
                 `P_NAMES` order); ∂q̈/∂p = M⁻¹ times it.",
            ),
            inputs,
            vec![("terms", Output::matrix(&rows))],
        )
    }

    /// `fns` with the parameter Jacobians last: those of the dynamics
    /// (`rhs_p`, `parameter_terms`), then `<function>_p` of every marked
    /// function.
    pub(super) fn with_parameter_jacobians(
        &self,
        fns: Vec<FnSpec>,
    ) -> Result<Vec<FnSpec>, GenError> {
        if let Some(m) = self
            .param_marks
            .iter()
            .find(|m| !fns.iter().any(|f| f.name == m.function))
        {
            return Err(self.error(
                "parameter_jacobian",
                &m.function,
                "no declared function of this name",
            ));
        }
        if !self.parameter_jacobians {
            return Ok(fns);
        }
        // After every other function, so that those are emitted exactly as
        // without the parameter Jacobians (lowering a function adds nodes to
        // the arena, which would reorder the intermediates of the next).
        let dynamics = ["rhs_p", "parameter_terms"];
        let (mut out, mut late): (Vec<FnSpec>, Vec<FnSpec>) = fns
            .into_iter()
            .partition(|f| !dynamics.contains(&f.name.as_str()));
        for m in &self.param_marks {
            if let Some(f) = out.iter().find(|f| f.name == m.function) {
                late.push(self.derived(f, m)?);
            }
        }
        out.extend(late);
        Ok(out)
    }

    /// `<f>_p` for the mark `m` of `f`.
    fn derived(&self, f: &FnSpec, m: &Mark<'g>) -> Result<FnSpec, GenError> {
        let name = format!("{}_p", f.name);
        if !f.inputs.iter().any(|i| i.name == self.param_input) {
            return Err(self.error(
                &f.name,
                &self.param_input,
                "a parameter Jacobian of a function that does not take the parameter vector",
            ));
        }
        let columns = "columns in `P_NAMES` order";
        match &m.unknowns {
            None => {
                let mut outputs = Vec::new();
                for (o, value) in &f.outputs {
                    let out = match value {
                        Output::Scalar(id) => Output::vector(&self.param_row(*id)),
                        Output::Vector(ids) => {
                            let rows: Vec<Vec<Expr<'g>>> =
                                ids.iter().map(|&id| self.param_row(id)).collect();
                            Output::matrix(&rows)
                        }
                        Output::Matrix { .. } | Output::Symmetric { .. } => {
                            return Err(self.error(
                                &f.name,
                                o,
                                "a parameter Jacobian of a matrix output (mark the function \
                                 with `solution_parameter_jacobian` if it is a linear system)",
                            ));
                        }
                    };
                    outputs.push((format!("d{o}_dp"), out));
                }
                let each: Vec<String> = f
                    .outputs
                    .iter()
                    .map(|(o, _)| format!("`d{o}_dp` with entry (i, k) = ∂{o}ᵢ/∂p_k"))
                    .collect();
                let doc = format!(
                    "Exact parameter Jacobian of [`{}`]: {} ({columns}).",
                    f.name,
                    each.join("; ")
                );
                Ok(FnSpec {
                    name,
                    doc: self.with_reference(&doc),
                    inputs: f.inputs.clone(),
                    outputs,
                })
            }
            Some(u) => self.solution_derived(f, name, u, columns),
        }
    }

    /// `<f>_p` of a linear-system function: `∂(b − A u)/∂p`.
    fn solution_derived(
        &self,
        f: &FnSpec,
        name: String,
        u: &[Expr<'g>],
        columns: &str,
    ) -> Result<FnSpec, GenError> {
        let g = self.g;
        let (a, b) = match f.outputs.as_slice() {
            [
                (
                    _,
                    Output::Matrix {
                        rows,
                        cols,
                        entries,
                    },
                ),
                (_, Output::Vector(b)),
            ] if *cols == u.len() && *rows == b.len() => (entries.clone(), b.clone()),
            _ => {
                return Err(self.error(
                    &f.name,
                    &f.name,
                    "not a linear system A u = b (outputs A then b) in the given unknowns",
                ));
            }
        };
        let cols = u.len();
        let residual: Vec<Expr<'g>> = b
            .iter()
            .enumerate()
            .map(|(i, &bi)| {
                let au = g.sum((0..cols).map(|j| g.expr(a[i * cols + j]) * u[j]));
                g.expr(bi) - au
            })
            .collect();
        let rows: Vec<Vec<Expr<'g>>> = residual.iter().map(|r| self.param_row(r.id())).collect();
        let mut inputs = f.inputs.clone();
        inputs.insert(1.min(inputs.len()), Input::new("u", u));
        let doc = format!(
            "Exact parameter Jacobian of the solution u of the linear system A u = b of \
             [`{}`]: ∂(b − A u)/∂p at the given u ({columns}), so that A ∂u/∂p equals it.",
            f.name
        );
        Ok(FnSpec::new(
            &name,
            self.with_reference(&doc),
            inputs,
            vec![("residual_p", Output::matrix(&rows))],
        ))
    }
}
