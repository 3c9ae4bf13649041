//! The arena itself: nodes, the hash-consing memo and the symbol table.

use std::cell::RefCell;
use std::collections::HashMap;

use super::node::{Id, Node, Sym, SymKind};

/// A named symbol and what it stands for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SymInfo {
    /// The name the model gave it (unique in its arena).
    pub name: String,
    /// Variable, parameter or time.
    pub kind: SymKind,
}

#[derive(Default)]
struct Inner {
    nodes: Vec<Node>,
    memo: HashMap<Node, Id>,
    syms: Vec<SymInfo>,
    sym_by_name: HashMap<String, Sym>,
    labels: HashMap<Id, String>,
}

/// A hash-consed arena of expression nodes.
///
/// Invariant: a node's children have smaller ids than the node itself, so
/// `0..len()` is a topological order. Interning a node equal to a stored one
/// returns the stored id (structural sharing).
///
/// The arena uses interior mutability so that many [`Expr`](crate::Expr)
/// handles can build new nodes through `&Graph` with ordinary operators.
pub struct Graph {
    inner: RefCell<Inner>,
    /// Whether the simplifier applies the stable numerical forms (rows of
    /// `simplify::rules::RULES` with `stable: true`) in this arena.
    stable_rewrites: bool,
}

impl Default for Graph {
    fn default() -> Graph {
        Graph::with_stable_rewrites(true)
    }
}

impl Graph {
    /// An empty arena with the stable numerical rewrites on (the default).
    pub fn new() -> Graph {
        Graph::default()
    }

    /// An empty arena whose simplifier applies the stable numerical forms
    /// (`true`, the default) or leaves them out (`false`, the naive forms,
    /// for measuring what the stable forms buy). The choice belongs to the
    /// arena, so one graph never mixes both forms.
    ///
    /// ```
    /// use pegdyn_equations::Graph;
    /// let g = Graph::with_stable_rewrites(false);
    /// assert_eq!((1.0 - g.var("x").cos()).to_string(), "1 - cos(x)");
    /// ```
    pub fn with_stable_rewrites(on: bool) -> Graph {
        Graph {
            inner: RefCell::new(Inner::default()),
            stable_rewrites: on,
        }
    }

    /// Whether this arena applies the stable numerical forms.
    pub fn stable_rewrites(&self) -> bool {
        self.stable_rewrites
    }

    /// Stores `node` (or finds the equal node already stored) without any
    /// simplification. Use the [`Expr`](crate::Expr) operators instead unless
    /// you are the simplifier.
    ///
    /// # Panics
    /// If a child id is not already in the arena (that would break the
    /// children-first invariant).
    pub fn intern(&self, node: Node) -> Id {
        let mut inner = self.inner.borrow_mut();
        if let Some(&id) = inner.memo.get(&node) {
            return id;
        }
        let id = Id(u32::try_from(inner.nodes.len()).expect("more than 2^32 nodes"));
        node.for_each_child(|c| assert!(c < id, "child {c:?} not yet in the arena"));
        inner.nodes.push(node.clone());
        inner.memo.insert(node, id);
        id
    }

    /// `reachable[i]`: node `i` is reachable from one of `roots` (the
    /// vector covers ids up to the largest root). One backward sweep over
    /// the arena, which lists children before parents.
    pub fn reachable(&self, roots: &[Id]) -> Vec<bool> {
        let n = roots.iter().map(|r| r.index() + 1).max().unwrap_or(0);
        let mut live = vec![false; n];
        for r in roots {
            live[r.index()] = true;
        }
        for i in (0..n).rev() {
            if live[i] {
                self.with_node(Id(i as u32), |node| {
                    node.for_each_child(|c| live[c.index()] = true)
                });
            }
        }
        live
    }

    /// The id of `node` if an equal node is already stored. Unlike
    /// [`Graph::intern`] this never grows the arena, so rules can ask "does
    /// the partner term exist?" without leaving garbage behind.
    pub fn find(&self, node: &Node) -> Option<Id> {
        self.inner.borrow().memo.get(node).copied()
    }

    /// The node stored at `id` (cloned; the arena is append-only).
    pub fn node(&self, id: Id) -> Node {
        self.inner.borrow().nodes[id.index()].clone()
    }

    /// Runs `f` on the node stored at `id` without cloning it.
    pub fn with_node<R>(&self, id: Id, f: impl FnOnce(&Node) -> R) -> R {
        f(&self.inner.borrow().nodes[id.index()])
    }

    /// Number of nodes stored.
    pub fn len(&self) -> usize {
        self.inner.borrow().nodes.len()
    }

    /// True when no node is stored.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The symbol called `name`, created with `kind` if it does not exist.
    ///
    /// # Panics
    /// If `name` already exists with another kind: a model that uses one name
    /// for a variable and a parameter is a bug in the model.
    pub fn symbol(&self, name: &str, kind: SymKind) -> Sym {
        let mut inner = self.inner.borrow_mut();
        if let Some(&s) = inner.sym_by_name.get(name) {
            let have = inner.syms[s.index()].kind;
            assert_eq!(
                have, kind,
                "symbol `{name}` declared as {have:?} and as {kind:?}"
            );
            return s;
        }
        let s = Sym(u32::try_from(inner.syms.len()).expect("more than 2^32 symbols"));
        inner.syms.push(SymInfo {
            name: name.to_owned(),
            kind,
        });
        inner.sym_by_name.insert(name.to_owned(), s);
        s
    }

    /// The symbol called `name`, if any.
    pub fn lookup(&self, name: &str) -> Option<Sym> {
        self.inner.borrow().sym_by_name.get(name).copied()
    }

    /// Gives node `id` the name `label` for the generated code, unless it
    /// already has one (the first name wins). A label is a side note: it
    /// changes no node, no id and no simplification; the emitter uses it for
    /// the `let` that binds the value (see [`Expr::named`](crate::Expr::named)).
    /// Symbols and constants keep their own spelling.
    pub fn set_label(&self, id: Id, label: &str) {
        if self.with_node(id, |n| matches!(n, Node::Sym(_) | Node::Const(_))) {
            return;
        }
        self.inner
            .borrow_mut()
            .labels
            .entry(id)
            .or_insert_with(|| label.to_owned());
    }

    /// The name given to node `id`, if any ([`Graph::set_label`]).
    pub fn label(&self, id: Id) -> Option<String> {
        self.inner.borrow().labels.get(&id).cloned()
    }

    /// Every named node and its name, in arena order.
    pub fn labels(&self) -> Vec<(Id, String)> {
        let mut v: Vec<(Id, String)> = self
            .inner
            .borrow()
            .labels
            .iter()
            .map(|(&id, l)| (id, l.clone()))
            .collect();
        v.sort();
        v
    }

    /// Name and kind of a symbol.
    pub fn sym_info(&self, s: Sym) -> SymInfo {
        self.inner.borrow().syms[s.index()].clone()
    }

    /// All symbols, in creation order.
    pub fn symbols(&self) -> Vec<(Sym, SymInfo)> {
        let inner = self.inner.borrow();
        inner
            .syms
            .iter()
            .enumerate()
            .map(|(i, s)| (Sym(i as u32), s.clone()))
            .collect()
    }
}
