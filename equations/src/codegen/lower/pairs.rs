//! Pass 2: sub-products shared by several products bound once (greedy
//! pair extraction), then the rebuild with the shared products in place.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap};

use super::{factors_of, live_nodes, rebuild, term_node};
use crate::graph::{Graph, Id, Node};

/// A factor of pass 2: a node, or the product of two earlier factors.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
enum Factor {
    Node(Id),
    Pair(usize),
}

/// Pass 2: greedy pair extraction over every product reachable from
/// `roots`, then the rebuild with the shared products in place.
pub(super) fn share_products(g: &Graph, roots: &[Id]) -> Vec<Id> {
    let live = live_nodes(g, roots);
    let mut products: Vec<(Id, f64, Vec<Factor>)> = Vec::new();
    for &id in &live {
        if matches!(g.node(id), Node::Mul(_)) {
            let (c, fs) = factors_of(g, id);
            products.push((id, c, fs.into_iter().map(Factor::Node).collect()));
        }
    }
    let pairs = extract_pairs(products.iter_mut().map(|(_, _, fs)| fs).collect());
    let by_id: HashMap<Id, usize> = products
        .iter()
        .enumerate()
        .map(|(k, (id, _, _))| (*id, k))
        .collect();
    let mut pair_nodes: HashMap<usize, Id> = HashMap::new();
    rebuild(g, roots, |g, old, node, map| {
        let Some(&k) = by_id.get(&old) else {
            return g.intern(node);
        };
        // The leaf factors of product `k` come before it in the arena, so
        // they are already in `map` (merged powers aside, see `factor_node`).
        let (_, c, fs) = &products[k];
        let fs: Vec<Id> = fs
            .iter()
            .map(|&f| factor_node(g, f, &pairs, &mut pair_nodes, map))
            .collect();
        term_node(g, (*c, fs))
    })
}

/// The node of pass-2 factor `f`, leaves mapped through `map`; a pair's
/// product is built once and shared by every product that holds it.
fn factor_node(
    g: &Graph,
    f: Factor,
    pairs: &[(Factor, Factor)],
    built: &mut HashMap<usize, Id>,
    map: &HashMap<Id, Id>,
) -> Id {
    match f {
        // A power that `factors_of` merged from repeated bases is a new
        // node, not in `map`: it stands for itself.
        Factor::Node(id) => map.get(&id).copied().unwrap_or(id),
        Factor::Pair(k) => {
            if let Some(&id) = built.get(&k) {
                return id;
            }
            let (a, b) = pairs[k];
            let a = factor_node(g, a, pairs, built, map);
            let b = factor_node(g, b, pairs, built, map);
            let id = term_node(g, (1.0, vec![a, b]));
            built.insert(k, id);
            id
        }
    }
}

/// Greedy pair extraction: while some pair of factors occurs together in
/// two or more of `products`, replace it by a new factor (returned as the
/// table of pairs, indexed by `Factor::Pair`). Most frequent pair first;
/// ties to the smallest pair (deterministic).
fn extract_pairs(mut products: Vec<&mut Vec<Factor>>) -> Vec<(Factor, Factor)> {
    let mut counts: HashMap<(Factor, Factor), usize> = HashMap::new();
    let mut holders: HashMap<(Factor, Factor), Vec<usize>> = HashMap::new();
    for (k, fs) in products.iter().enumerate() {
        for p in pairs_of(fs) {
            *counts.entry(p).or_default() += 1;
            holders.entry(p).or_default().push(k);
        }
    }
    let mut heap: BinaryHeap<(usize, Reverse<(Factor, Factor)>)> = counts
        .iter()
        .filter(|(_, n)| **n >= 2)
        .map(|(p, n)| (*n, Reverse(*p)))
        .collect();
    let mut table = Vec::new();
    while let Some((n, Reverse(p))) = heap.pop() {
        if counts.get(&p) != Some(&n) || n < 2 {
            continue; // stale entry
        }
        let new = Factor::Pair(table.len());
        table.push(p);
        let ks = holders.remove(&p).unwrap_or_default();
        for k in ks {
            let fs = &mut *products[k];
            if !(fs.contains(&p.0) && fs.contains(&p.1)) {
                continue;
            }
            for q in pairs_of(fs) {
                if let Some(c) = counts.get_mut(&q) {
                    *c -= 1;
                }
            }
            // One occurrence of each (a flattened product may repeat a factor).
            for x in [p.0, p.1] {
                if let Some(i) = fs.iter().position(|&f| f == x) {
                    fs.remove(i);
                }
            }
            fs.insert(0, new);
            for q in pairs_of(fs) {
                let c = counts.entry(q).or_default();
                *c += 1;
                holders.entry(q).or_default().push(k);
                if *c >= 2 {
                    heap.push((*c, Reverse(q)));
                }
            }
        }
        counts.remove(&p);
    }
    table
}

/// The unordered pairs of distinct factors of one product, each as
/// (smaller, larger), each pair once even where a factor repeats.
fn pairs_of(fs: &[Factor]) -> Vec<(Factor, Factor)> {
    let mut out = Vec::with_capacity(fs.len() * fs.len().saturating_sub(1) / 2);
    for (i, &a) in fs.iter().enumerate() {
        for &b in &fs[i + 1..] {
            if a != b {
                out.push(if a < b { (a, b) } else { (b, a) });
            }
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}
