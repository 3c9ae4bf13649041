//! The typed boundary of a declared model: which inputs get a struct
//! (`Params` always, others on request), which functions share an output
//! struct, which structs are an earlier model's; and the finishing steps
//! that turn those declarations into the module's records and output
//! types.

use super::model::{ModelBuilder, is_ident};
use crate::GenError;
use crate::model::{FnSpec, OutType, Record, default_out_name};

/// What the outputs of the Lagrangian `dynamics` are.
const DYNAMICS_DOCS: [&str; 2] = ["mass matrix M(q), symmetric", "forcing f(q, q̇) of M q̈ = f"];

/// True for a CamelCase type name (`Params`, `LinearSystem`): ASCII
/// letters and digits, an upper-case letter first, more than one letter.
fn is_type_name(n: &str) -> bool {
    n.len() > 1
        && n.chars().all(|c| c.is_ascii_alphanumeric())
        && n.starts_with(|c: char| c.is_ascii_uppercase())
}

impl ModelBuilder<'_> {
    /// Gives the input `input` (as the functions that take it name it) a
    /// typed struct `type_name<T>`, documented by `doc`, with one field per
    /// component named as its symbol and documented as it was declared,
    /// and `From` conversions both ways with the input's `SVector`. The
    /// parameter vector gets its struct, `Params`, without asking.
    ///
    /// # Errors
    /// [`GenError::Model`] for a type name that is not CamelCase.
    pub fn typed_input(&mut self, input: &str, type_name: &str, doc: &str) -> Result<(), GenError> {
        if !is_type_name(type_name) || !is_ident(input) {
            return Err(self.error("typed_input", type_name, "not a CamelCase type name"));
        }
        self.typed
            .push((input.to_owned(), type_name.to_owned(), doc.to_owned()));
        Ok(())
    }

    /// Uses the struct of input `input` of the earlier model `module` (same
    /// components, names and docs, which the generator verifies) instead of
    /// a struct of this model's own: one value then serves both models'
    /// functions. For the parameter vector, `input` is its name (`p`).
    pub fn share_input_type(&mut self, input: &str, module: &str) {
        self.shared_types
            .push((input.to_owned(), module.to_owned()));
    }

    /// The functions `functions`, declared with the same output names and
    /// shapes, all return one struct `type_name<T>` (documented by `doc`, its
    /// fields by the first function's output docs) instead of one
    /// `<Function>Out` each.
    ///
    /// # Errors
    /// [`GenError::Model`] for a type name that is not CamelCase.
    pub fn shared_output(
        &mut self,
        type_name: &str,
        doc: &str,
        functions: &[&str],
    ) -> Result<(), GenError> {
        if !is_type_name(type_name) {
            return Err(self.error("shared_output", type_name, "not a CamelCase type name"));
        }
        self.shared_outputs.push((
            type_name.to_owned(),
            doc.to_owned(),
            functions.iter().map(|f| (*f).to_owned()).collect(),
        ));
        Ok(())
    }

    /// Uses the output struct `type_name` of the earlier model `module`
    /// (same fields, docs and shapes, which the generator verifies) for
    /// this model's functions that return a struct of that name (their
    /// `<Function>Out` or one declared with [`ModelBuilder::shared_output`]).
    pub fn share_output_type(&mut self, type_name: &str, module: &str) {
        self.shared_out_types
            .push((type_name.to_owned(), module.to_owned()));
    }
}

impl ModelBuilder<'_> {
    /// The typed inputs: `Params` for the parameter vector (when a function
    /// takes it), then those given to `typed_input`; fields documented as
    /// their symbols were declared.
    pub(super) fn records(&self, fns: &[FnSpec]) -> Result<Vec<Record>, GenError> {
        let input = |name: &str| fns.iter().flat_map(|f| &f.inputs).find(|i| i.name == name);
        let mut specs: Vec<(String, String, String)> = Vec::new();
        if !self.params.is_empty() && input(&self.param_input).is_some() {
            specs.push((
                self.param_input.clone(),
                "Params".to_owned(),
                format!(
                    "The parameters of `{}`: the input `{}` of its functions as a struct, one \
                     field per component in vector order (`From`/`Into` convert both ways).",
                    self.name, self.param_input
                ),
            ));
        }
        specs.extend(self.typed.iter().cloned());
        if let Some((bad, _)) = self
            .shared_types
            .iter()
            .find(|(i, _)| !specs.iter().any(|s| s.0 == *i))
        {
            return Err(self.error("share_input_type", bad, "no typed input of this name"));
        }
        specs
            .into_iter()
            .map(|(name, type_name, doc)| {
                let Some(i) = input(&name) else {
                    return Err(self.error("typed_input", &name, "no function takes this input"));
                };
                Ok(Record {
                    fields: i.syms.iter().map(|&s| self.doc_of_sym(s)).collect(),
                    shared_with: self
                        .shared_types
                        .iter()
                        .find(|(n, _)| *n == name)
                        .map(|(_, m)| m.clone()),
                    input: name,
                    name: type_name,
                    doc,
                })
            })
            .collect()
    }

    /// The output structs: the shared ones, then `<Function>Out` for every
    /// other function with several outputs; fields documented as the
    /// outputs were declared.
    pub(super) fn out_types(&self, fns: &[FnSpec]) -> Result<Vec<OutType>, GenError> {
        let docs = |function: &str| -> Vec<String> {
            match self.functions.iter().find(|f| f.name == function) {
                Some(f) => f.outputs.iter().map(|(_, d, _)| d.clone()).collect(),
                None if function == "dynamics" => {
                    DYNAMICS_DOCS.iter().map(|d| (*d).to_owned()).collect()
                }
                None => Vec::new(),
            }
        };
        let mut out: Vec<OutType> = self
            .shared_outputs
            .iter()
            .map(|(name, doc, functions)| OutType {
                name: name.clone(),
                doc: doc.clone(),
                fields: functions.first().map(|f| docs(f)).unwrap_or_default(),
                functions: functions.clone(),
                shared_with: None,
            })
            .collect();
        for f in fns {
            if f.outputs.len() > 1 && !out.iter().any(|o| o.functions.contains(&f.name)) {
                out.push(OutType {
                    name: default_out_name(&f.name),
                    doc: format!("The outputs of [`{}`].", f.name),
                    fields: docs(&f.name),
                    functions: vec![f.name.clone()],
                    shared_with: None,
                });
            }
        }
        for o in &mut out {
            o.shared_with = self
                .shared_out_types
                .iter()
                .find(|(n, _)| *n == o.name)
                .map(|(_, m)| m.clone());
        }
        if let Some((bad, _)) = self
            .shared_out_types
            .iter()
            .find(|(n, _)| !out.iter().any(|o| o.name == *n))
        {
            return Err(self.error("share_output_type", bad, "no output struct of this name"));
        }
        Ok(out)
    }
}
