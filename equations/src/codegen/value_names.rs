//! Model names found by value: a `let` whose value is a value the model
//! named (or its negation, half or double) gets that name even when the
//! expansion and lowering built it from other nodes (the model's `a₂ − a₁
//! cos γ` reaches the code as a factored sum with no node of its own).
//!
//! Two values are taken to be the same when they agree at two fixed
//! pseudo-random points of the symbols (relative difference below 1e-9,
//! both away from zero): values of different expressions do not agree
//! there unless they are equal as functions. Names only: the code and its
//! operation counts do not change.

use std::collections::HashMap;

use super::names::snake_case;
use crate::eval::Tape;
use crate::graph::{Graph, Id, Node};

/// Points at which values are compared (symbol values in [0.2, 1.2)).
const POINTS: usize = 2;

/// Names by value for the `lets` of one function.
pub(crate) struct ValueNames {
    /// `let` id → (scale prefix, model name).
    found: HashMap<Id, String>,
}

impl ValueNames {
    /// Compares every `let` of `lets` with every value the model named.
    pub(crate) fn new(g: &Graph, lets: &[Id]) -> ValueNames {
        let labels: Vec<(Id, String)> = g
            .labels()
            .into_iter()
            .filter(|(id, _)| !matches!(g.node(*id), Node::Const(_) | Node::Sym(_)))
            .collect();
        let unnamed: Vec<Id> = lets
            .iter()
            .copied()
            .filter(|&id| g.label(id).is_none())
            .collect();
        let mut found = HashMap::new();
        if labels.is_empty() || unnamed.is_empty() {
            return ValueNames { found };
        }
        let roots: Vec<Id> = labels
            .iter()
            .map(|(id, _)| *id)
            .chain(unnamed.iter().copied())
            .collect();
        let tape = Tape::new(g, &roots);
        let values: Vec<Vec<f64>> = (0..POINTS)
            .map(|k| tape.eval(&point(tape.n_syms(), k as u64)))
            .collect();
        let at = |k: usize| -> [f64; POINTS] { std::array::from_fn(|p| values[p][k]) };
        let usable = |v: &[f64; POINTS]| v.iter().all(|x| x.is_finite() && x.abs() > 1e-9);
        for (j, &id) in unnamed.iter().enumerate() {
            let w = at(labels.len() + j);
            if !usable(&w) {
                continue;
            }
            let hit = labels.iter().enumerate().find_map(|(i, (_, name))| {
                let v = at(i);
                if !usable(&v) {
                    return None;
                }
                let r = w[0] / v[0];
                let same = w
                    .iter()
                    .zip(&v)
                    .all(|(a, b)| (a - r * b).abs() <= 1e-9 * a.abs());
                let prefix = scale_prefix(snap(r)?)?;
                same.then(|| format!("{prefix}{}", snake_case(name)))
            });
            if let Some(name) = hit {
                found.insert(id, name);
            }
        }
        ValueNames { found }
    }

    /// The name found for `id`, if any.
    pub(crate) fn get(&self, id: Id) -> Option<&str> {
        self.found.get(&id).map(String::as_str)
    }
}

/// `r` rounded to the scale it is within 1e-9 of (±1, ±½, ±2), if any.
fn snap(r: f64) -> Option<f64> {
    [1.0, -1.0, 0.5, -0.5, 2.0, -2.0]
        .into_iter()
        .find(|s: &f64| (r - s).abs() <= 1e-9 * s.abs())
}

/// Symbol values of point `k`: a fixed sequence in [0.2, 1.2) (SplitMix64).
fn point(n: usize, k: u64) -> Vec<f64> {
    let mut state = 0x9E37_79B9_7F4A_7C15_u64.wrapping_mul(k + 1);
    (0..n)
        .map(|_| {
            state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^= z >> 31;
            0.2 + (z >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect()
}

/// How a value relates to a named product with the same leaves, as a name
/// prefix: the ratio of the coefficients (`−x` is `neg_x`, `x/2` is
/// `half_x`); `None` for other ratios.
pub(crate) fn scale_prefix(ratio: f64) -> Option<&'static str> {
    Some(match ratio {
        1.0 => "",
        -1.0 => "neg_",
        0.5 => "half_",
        -0.5 => "neg_half_",
        2.0 => "twice_",
        -2.0 => "neg_twice_",
        _ => return None,
    })
}
