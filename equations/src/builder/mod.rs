//! The generator as a build dependency: declare models by name in a
//! `build.rs`, write one `@generated` Rust file (and its operation-count
//! report) into `OUT_DIR`, include it, and integrate the models with
//! pegdyn's integrators through the generated `System` adapters.
//!
//! ```
//! use pegdyn_equations::{Generator, Options};
//!
//! let mut generator = Generator::new(Options::default());
//! generator.model("oscillator", "Mass on a linear spring.", |m| {
//!     let x = m.coordinate("x", "displacement, m")?;
//!     let mass = m.parameter("m", "mass, kg")?;
//!     let k = m.parameter("k", "spring stiffness, N/m")?;
//!     let zero = m.g().constant(0.0);
//!     m.lagrange(0.5 * mass * x.v.square(), 0.5 * k * x.q.square(), &[zero]);
//!     Ok(())
//! })?;
//! let out = generator.render()?;
//! assert!(out.source.starts_with("// @generated"));
//! assert!(out.source.contains("pub fn rhs<T: Real>"));
//! assert!(out.source.contains("impl pegdyn::system::OdeSystem<2> for System"));
//! assert!(out.source.contains("pub const X_X_DOT: usize = 1;"));
//! assert!(out.source.contains("pub struct Params<T>")); // System::new(Params { m, k })
//! # let dir = std::env::temp_dir().join(format!("pegdyn-builder-doc-{}", std::process::id()));
//! # std::fs::create_dir_all(&dir).unwrap();
//! let written = out.write(&dir)?; // generated.rs + codegen_report.txt
//! assert!(written.source_written);
//! assert!(!out.write(&dir)?.source_written); // unchanged bytes: not rewritten
//! # std::fs::remove_dir_all(&dir).unwrap();
//! # Ok::<(), pegdyn_equations::GenError>(())
//! ```

pub mod blocks;
mod finish;
mod model;
mod outputs;
mod param_jacobian;
mod types;

use std::path::Path;

pub use model::{Coordinate, ModelBuilder};
pub use outputs::Outputs;

use crate::GenError;
use crate::codegen::{Entry, Rendered, Written, render};
use crate::options::Options;

/// Collects the declared models; [`Generator::render`] hands them to the
/// generator's one pipeline ([`render`]).
pub struct Generator {
    options: Options,
    entries: Vec<Entry>,
}

impl Generator {
    /// A generator with no models.
    pub fn new(options: Options) -> Generator {
        Generator {
            options,
            entries: Vec::new(),
        }
    }

    /// The options this generator applies.
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// Declares the model `name` (a snake_case identifier: the generated
    /// `pub mod name`), documented by `doc`, built by `build` in a fresh
    /// expression arena.
    ///
    /// # Errors
    /// Whatever `build` returns, or [`GenError::Model`] for an incomplete
    /// model (no dynamics, a force count that does not match the
    /// coordinates, a name declared twice).
    pub fn model<F>(&mut self, name: &str, doc: &str, build: F) -> Result<&mut Generator, GenError>
    where
        F: for<'g> FnOnce(&mut ModelBuilder<'g>) -> Result<(), GenError>,
    {
        let graph = self.options.graph();
        let module = {
            let mut b = ModelBuilder::new(&graph, name, doc);
            b.parameter_jacobians = self.options.parameter_jacobians.iter().any(|m| m == name);
            build(&mut b)?;
            b.finish()?
        };
        self.entries.push(Entry { graph, module });
        Ok(self)
    }

    /// Verifies and emits every model: [`render`] of the declared models
    /// with the generator's options.
    ///
    /// # Errors
    /// [`GenError`] naming the module, function and symbol of a model that
    /// fails verification, or [`GenError::Model`] for a model named in
    /// [`Options::parameter_jacobians`] that was not declared.
    pub fn render(&self) -> Result<Rendered, GenError> {
        let declared = |m: &String| self.entries.iter().any(|e| e.module.name == *m);
        if let Some(m) = self
            .options
            .parameter_jacobians
            .iter()
            .find(|m| !declared(m))
        {
            return Err(GenError::Model {
                model: m.clone(),
                function: "parameter_jacobians".to_owned(),
                symbol: m.clone(),
                reason: "named in Options::parameter_jacobians but not declared".to_owned(),
            });
        }
        render(&self.entries, &self.options)
    }

    /// Evaluates `model::function` with the generator's interpreter (the
    /// oracle the generated code is checked against): `inputs[k]` gives the
    /// values of the function's `k`-th input (`x`, then `qdd` for
    /// `jacobian_terms`, `p`, and `t` for a time-dependent model). Returns
    /// one vector per output, matrices row-major.
    ///
    /// # Errors
    /// [`GenError::Model`] when the model or function does not exist or the
    /// inputs do not match it in number or length.
    pub fn interpret(
        &self,
        model: &str,
        function: &str,
        inputs: &[&[f64]],
    ) -> Result<Vec<Vec<f64>>, GenError> {
        let err = |symbol: &str, reason: String| GenError::Model {
            model: model.to_owned(),
            function: function.to_owned(),
            symbol: symbol.to_owned(),
            reason,
        };
        let entry = self
            .entries
            .iter()
            .find(|e| e.module.name == model)
            .ok_or_else(|| err(model, "no such model".to_owned()))?;
        let f = entry
            .module
            .functions
            .iter()
            .find(|f| f.name == function)
            .ok_or_else(|| err(function, "no such function".to_owned()))?;
        if f.inputs.len() != inputs.len() {
            return Err(err(
                "inputs",
                format!("{} inputs given, {} expected", inputs.len(), f.inputs.len()),
            ));
        }
        for (i, v) in f.inputs.iter().zip(inputs) {
            if i.syms.len() != v.len() {
                return Err(err(
                    &i.name,
                    format!("{} values given, {} expected", v.len(), i.syms.len()),
                ));
            }
        }
        Ok(f.interpret(&entry.graph, inputs))
    }

    /// [`Generator::render`] then [`Rendered::write`] into `dir`.
    ///
    /// # Errors
    /// As [`Generator::render`], or [`GenError::Io`] for a file that cannot
    /// be written.
    pub fn write(&self, dir: &Path) -> Result<Written, GenError> {
        self.render()?.write(dir)
    }
}
