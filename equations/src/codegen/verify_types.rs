//! Verification of a module's typed boundary: every typed input names an
//! input and documents each of its components, whose symbol names are
//! field names; every output struct is returned by functions with the same
//! outputs; struct names are unique; a struct shared with an earlier
//! module has that module's components and docs.

use std::collections::BTreeSet;

use crate::error::GenError;
use crate::graph::Graph;
use crate::model::{FnSpec, Input, Module, default_out_name};

fn error(m: &Module, item: &str, reason: impl Into<String>) -> GenError {
    GenError::Struct {
        module: m.name.clone(),
        item: item.to_owned(),
        reason: reason.into(),
    }
}

/// A CamelCase type name (`Params`, `LinearSystem`).
fn is_type_name(n: &str) -> bool {
    n.len() > 1
        && n.chars().all(|c| c.is_ascii_alphanumeric())
        && n.starts_with(|c: char| c.is_ascii_uppercase())
}

/// A field name: an ASCII identifier that is not a keyword (upper case
/// allowed: parameters keep their paper names, `J`, `D_hole`).
fn is_field_name(n: &str) -> bool {
    n.starts_with(|c: char| c.is_ascii_alphabetic())
        && n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !super::names::KEYWORDS.contains(&n)
}

/// The input `name` of the module's functions.
fn input<'m>(m: &'m Module, name: &str) -> Option<&'m Input> {
    m.functions
        .iter()
        .flat_map(|f| &f.inputs)
        .find(|i| i.name == name)
}

/// Verifies the records and output structs of `m` on their own.
pub fn verify_types(g: &Graph, m: &Module) -> Result<(), GenError> {
    let mut names = BTreeSet::new();
    for r in &m.records {
        if !is_type_name(&r.name) || !names.insert(r.name.clone()) {
            return Err(error(m, &r.name, "not a unique CamelCase name"));
        }
        let Some(i) = input(m, &r.input) else {
            return Err(error(
                m,
                &r.name,
                format!("no function takes `{}`", r.input),
            ));
        };
        if r.fields.len() != i.syms.len() || r.fields.iter().any(String::is_empty) {
            return Err(error(
                m,
                &r.name,
                "one non-empty doc per component required",
            ));
        }
        if let Some(s) = i
            .syms
            .iter()
            .find(|&&s| !is_field_name(&g.sym_info(s).name))
        {
            let name = g.sym_info(*s).name;
            return Err(error(m, &r.name, format!("`{name}` cannot name a field")));
        }
    }
    let mut returned = BTreeSet::new();
    for o in &m.out_types {
        if !is_type_name(&o.name) || !names.insert(o.name.clone()) {
            return Err(error(m, &o.name, "not a unique CamelCase name"));
        }
        let fns: Vec<&FnSpec> = o
            .functions
            .iter()
            .map(|n| m.functions.iter().find(|f| f.name == *n))
            .collect::<Option<_>>()
            .ok_or_else(|| error(m, &o.name, "returned by a function that does not exist"))?;
        let Some(first) = fns.first() else {
            return Err(error(m, &o.name, "returned by no function"));
        };
        let shape = |f: &FnSpec| -> Vec<(String, (usize, usize))> {
            f.outputs
                .iter()
                .map(|(n, o)| (n.clone(), o.shape()))
                .collect()
        };
        if first.outputs.len() < 2 || fns.iter().any(|f| shape(f) != shape(first)) {
            return Err(error(
                m,
                &o.name,
                "its functions need the same two or more output names and shapes",
            ));
        }
        if !(o.fields.is_empty() || o.fields.len() == first.outputs.len()) {
            return Err(error(m, &o.name, "one doc per output required"));
        }
        if let Some(f) = o.functions.iter().find(|f| !returned.insert(f.as_str())) {
            return Err(error(m, &o.name, format!("`{f}` returns two structs")));
        }
    }
    for f in &m.functions {
        let name = default_out_name(&f.name);
        if f.outputs.len() > 1 && !returned.contains(f.name.as_str()) && !names.insert(name.clone())
        {
            return Err(error(m, &name, "the name of another struct"));
        }
    }
    Ok(())
}

/// Verifies that every struct of `m` shared with an earlier module (of
/// `earlier`) has the same components (fields, shapes) and docs as that
/// module's.
pub fn verify_shared(g: &Graph, m: &Module, earlier: &[(&Graph, &Module)]) -> Result<(), GenError> {
    for o in &m.out_types {
        let Some(other) = &o.shared_with else {
            continue;
        };
        let Some((_, om)) = earlier.iter().find(|(_, e)| e.name == *other) else {
            return Err(error(m, &o.name, format!("no earlier module `{other}`")));
        };
        let outputs = |m: &Module, f: &str| -> Option<Vec<(String, (usize, usize))>> {
            let f = m.functions.iter().find(|x| x.name == f)?;
            Some(
                f.outputs
                    .iter()
                    .map(|(n, o)| (n.clone(), o.shape()))
                    .collect(),
            )
        };
        let theirs = om.out_types.iter().find(|t| t.name == o.name);
        let same = theirs.is_some_and(|t| {
            t.shared_with.is_none()
                && t.fields == o.fields
                && t.functions.first().and_then(|f| outputs(om, f))
                    == o.functions.first().and_then(|f| outputs(m, f))
        });
        if !same {
            return Err(error(
                m,
                &o.name,
                format!(
                    "differs from `{other}::{}` (fields, docs or shapes)",
                    o.name
                ),
            ));
        }
    }
    for r in &m.records {
        let Some(other) = &r.shared_with else {
            continue;
        };
        let Some((og, om)) = earlier.iter().find(|(_, e)| e.name == *other) else {
            return Err(error(m, &r.name, format!("no earlier module `{other}`")));
        };
        let theirs = om.records.iter().find(|o| o.name == r.name);
        let names = |g: &Graph, i: Option<&Input>| -> Option<Vec<String>> {
            i.map(|i| i.syms.iter().map(|&s| g.sym_info(s).name).collect())
        };
        let same = theirs.is_some_and(|o| {
            o.shared_with.is_none()
                && o.fields == r.fields
                && names(og, input(om, &o.input)) == names(g, input(m, &r.input))
        });
        if !same {
            return Err(error(
                m,
                &r.name,
                format!("differs from `{other}::{}` (components or docs)", r.name),
            ));
        }
    }
    Ok(())
}
