//! Verification before emission: a module that passes emits code that
//! compiles and computes what the interpreter computes.
//!
//! Checked: names are unique snake_case identifiers; every function has
//! outputs and every input has components; matrix shapes match their entry
//! counts; matrices declared symmetric are (entry (i, j) is the same node as
//! (j, i) — hash-consing makes that structural equality); every symbol the
//! outputs use is bound by exactly one input component; no constant is
//! infinite (NaN cannot be stored); an input name means the same components
//! in every function of the module.

use std::collections::{BTreeMap, BTreeSet};

use super::names::is_snake_ident;
use crate::error::GenError;
use crate::graph::{Graph, Id, Node, Sym};
use crate::model::{FnSpec, Module, Output};
use crate::schedule::Schedule;

fn check_names<'a>(
    what: &'static str,
    names: impl IntoIterator<Item = &'a str>,
) -> Result<(), GenError> {
    let mut seen = BTreeSet::new();
    for n in names {
        if !is_snake_ident(n) || !seen.insert(n) {
            return Err(GenError::InvalidName {
                what,
                name: n.to_owned(),
            });
        }
    }
    Ok(())
}

/// Verifies every module (and that module names are unique), and that
/// each struct shared with an earlier module matches that module's.
pub fn verify_all(modules: &[(&Graph, &Module)]) -> Result<(), GenError> {
    check_names("module", modules.iter().map(|(_, m)| m.name.as_str()))?;
    for (k, (g, m)) in modules.iter().enumerate() {
        verify_module(g, m)?;
        super::verify_types::verify_shared(g, m, &modules[..k])?;
    }
    Ok(())
}

/// Verifies one module.
pub fn verify_module(g: &Graph, m: &Module) -> Result<(), GenError> {
    check_names("function", m.functions.iter().map(|f| f.name.as_str()))?;
    super::verify_types::verify_types(g, m)?;
    let mut inputs: BTreeMap<&str, &[Sym]> = BTreeMap::new();
    for f in &m.functions {
        verify_fn(g, &m.name, f)?;
        for i in &f.inputs {
            if *inputs.entry(&i.name).or_insert(&i.syms) != i.syms.as_slice() {
                return Err(GenError::InconsistentInput {
                    module: m.name.clone(),
                    input: i.name.clone(),
                });
            }
        }
    }
    Ok(())
}

fn verify_fn(g: &Graph, module: &str, f: &FnSpec) -> Result<(), GenError> {
    let empty = |reason| GenError::Empty {
        module: module.to_owned(),
        function: f.name.clone(),
        reason,
    };
    check_names("input", f.inputs.iter().map(|i| i.name.as_str()))?;
    check_names(
        "output",
        f.outputs
            .iter()
            .map(|(n, _)| n.as_str())
            .chain(f.inputs.iter().map(|i| i.name.as_str())),
    )?;
    if f.outputs.is_empty() {
        return Err(empty("no outputs"));
    }
    if f.inputs.iter().any(|i| i.syms.is_empty()) {
        return Err(empty("an input has no components"));
    }
    for (name, out) in &f.outputs {
        verify_output(g, module, &f.name, name, out)?;
    }
    let mut bound = BTreeSet::new();
    for s in f.inputs.iter().flat_map(|i| &i.syms) {
        if !bound.insert(*s) {
            return Err(GenError::SymbolBoundTwice {
                module: module.to_owned(),
                function: f.name.clone(),
                symbol: g.sym_info(*s).name,
            });
        }
    }
    let roots: Vec<Id> = f
        .outputs
        .iter()
        .flat_map(|(_, o)| o.ids().iter().copied())
        .collect();
    let sched = Schedule::new(g, &roots);
    if let Some(s) = sched.syms.iter().find(|s| !bound.contains(s)) {
        return Err(GenError::UnboundSymbol {
            module: module.to_owned(),
            function: f.name.clone(),
            symbol: g.sym_info(*s).name,
        });
    }
    Ok(())
}

fn verify_output(
    g: &Graph,
    module: &str,
    function: &str,
    name: &str,
    out: &Output,
) -> Result<(), GenError> {
    let (rows, cols) = out.shape();
    let entries = out.ids().len();
    if entries != rows * cols || entries == 0 {
        return Err(GenError::Shape {
            module: module.to_owned(),
            function: function.to_owned(),
            output: name.to_owned(),
            rows,
            cols,
            entries,
        });
    }
    if let Output::Symmetric { n, entries } = out {
        for i in 0..*n {
            for j in 0..i {
                if entries[i * n + j] != entries[j * n + i] {
                    return Err(GenError::NotSymmetric {
                        module: module.to_owned(),
                        function: function.to_owned(),
                        output: name.to_owned(),
                        row: i,
                        col: j,
                    });
                }
            }
        }
    }
    let sched = Schedule::new(g, out.ids());
    for (i, _) in sched.live.iter().enumerate().filter(|(_, l)| **l) {
        if let Node::Const(c) = g.node(Id(i as u32))
            && !c.value().is_finite()
        {
            return Err(GenError::NonFiniteConstant {
                module: module.to_owned(),
                function: function.to_owned(),
                output: name.to_owned(),
                value: c.value(),
            });
        }
    }
    Ok(())
}
