//! Seeded inputs and interpreter tapes for every generated function.
//!
//! [`Cases::new`] builds every registered model (`models::ALL`) in its own
//! graph and, for each function, draws seeded inputs (SplitMix64, seed 0:
//! states in [−2, 2], parameters in [0.5, 2], time in [0, 10], as
//! `tests/generator/vs_interpreter.rs`), then replaces them with physical
//! values where the model needs them ([`physical_inputs`]). The interpreter
//! [`Tape`] of the function's outputs is compiled here, once, outside any
//! timed loop; only [`Case::interpret`] is timed.

use nalgebra::{Dim, Matrix, RawStorage, SVector};
use pegdyn::compliant_peg::{CompliantParams, Load, PegState};
use pegdyn_equations::eval::Tape;
use pegdyn_equations::graph::SymKind;
use pegdyn_equations::{Graph, models};

#[path = "../tests/common/rng.rs"]
mod rng;
pub use rng::Rng;

/// One generated function: its inputs and its interpreter program.
pub struct Case {
    /// Module (model) name.
    pub module: String,
    /// Function name.
    pub function: String,
    /// One vector per input, in the function's argument order.
    pub inputs: Vec<Vec<f64>>,
    tape: Tape,
    /// Symbol values (by symbol index) the tape reads.
    values: Vec<f64>,
    scratch: Vec<f64>,
    out: Vec<f64>,
}

impl Case {
    /// Input `k` as a fixed-size vector (its length fixed by the caller).
    pub fn input<const N: usize>(&self, k: usize) -> SVector<f64, N> {
        SVector::from_column_slice(&self.inputs[k])
    }

    /// Evaluates the function with the interpreter (no allocation once the
    /// scratch buffer has grown); outputs flattened as in
    /// `FnSpec::interpret` (matrices row-major).
    pub fn interpret(&mut self) -> &[f64] {
        self.tape
            .eval_into(&self.values, &mut self.scratch, &mut self.out);
        &self.out
    }
}

/// Every generated function of every registered model.
pub struct Cases {
    cases: Vec<Case>,
}

impl Cases {
    /// Builds the cases with seed `seed`.
    pub fn new(seed: u64) -> Cases {
        let mut rng = Rng(seed);
        let mut cases = Vec::new();
        for build in models::ALL {
            let g = Graph::new();
            let m = build.module(&g);
            for f in &m.functions {
                let mut inputs: Vec<Vec<f64>> = f
                    .inputs
                    .iter()
                    .map(|i| {
                        i.syms
                            .iter()
                            .map(|&s| match g.sym_info(s).kind {
                                SymKind::Var => rng.uniform(-2.0, 2.0),
                                SymKind::Param => rng.uniform(0.5, 2.0),
                                SymKind::Time => rng.uniform(0.0, 10.0),
                            })
                            .collect()
                    })
                    .collect();
                for (input, values) in f.inputs.iter().zip(inputs.iter_mut()) {
                    if let Some(v) = physical_inputs(&m.name, &input.name) {
                        *values = v;
                    }
                }
                let mut values = vec![f64::NAN; g.symbols().len()];
                for (input, vals) in f.inputs.iter().zip(&inputs) {
                    for (s, &v) in input.syms.iter().zip(vals) {
                        values[s.index()] = v;
                    }
                }
                let roots: Vec<_> = f
                    .outputs
                    .iter()
                    .flat_map(|(_, o)| o.ids().iter().copied())
                    .collect();
                let out = vec![0.0; roots.len()];
                cases.push(Case {
                    module: m.name.clone(),
                    function: f.name.clone(),
                    inputs,
                    tape: Tape::new(&g, &roots),
                    values,
                    scratch: Vec::new(),
                    out,
                });
            }
        }
        Cases { cases }
    }

    /// Removes and returns the case of `module::function`.
    ///
    /// # Panics
    /// If there is no such generated function (a stale bench entry).
    pub fn take(&mut self, module: &str, function: &str) -> Case {
        let k = self
            .cases
            .iter()
            .position(|c| c.module == module && c.function == function)
            .unwrap_or_else(|| panic!("no generated function {module}::{function}"));
        self.cases.remove(k)
    }

    /// `module::function` of the cases not taken yet.
    pub fn remaining(&self) -> Vec<String> {
        self.cases
            .iter()
            .map(|c| format!("{}::{}", c.module, c.function))
            .collect()
    }
}

/// The compliant insertion scene, read from `scenes/insert_compliant.toml`
/// so that the benches follow it (steel peg, D = 50 mm, c = 0.002,
/// μ = 0.1, f₁ = 5 N, M = −0.002 N·m, tilted 0.01 rad in two-point contact).
pub fn insertion_scene() -> (CompliantParams, Load, PegState) {
    let text = include_str!("../scenes/insert_compliant.toml");
    let scene: pegdyn::scene::kinds::insert_compliant::InsertCompliantScene =
        pegdyn::scene::document::Document::parse(text)
            .and_then(|d| d.body())
            .expect("shipped scene parses");
    let built = scene.build().expect("shipped scene is valid");
    (built.params, built.load, built.initial)
}

/// `scenes/align_forward.toml` (the shipped rigid forward scene, read from
/// the file so that the benches follow it) and its forward model.
pub fn align_forward_scene() -> (
    pegdyn::scene::kinds::align_forward::AlignForwardScene,
    pegdyn::rigid_peg::forward::ForwardModel,
) {
    let text = include_str!("../scenes/align_forward.toml");
    let scene: pegdyn::scene::kinds::align_forward::AlignForwardScene =
        pegdyn::scene::document::Document::parse(text)
            .and_then(|d| d.body())
            .expect("shipped scene parses");
    let model = scene.forward_model().expect("shipped scene is valid");
    (scene, model)
}

/// Physical values for inputs whose random values would be meaningless:
/// the compliant models at the insertion scene's start (contacts active),
/// positive Hertz loads.
pub fn physical_inputs(module: &str, input: &str) -> Option<Vec<f64>> {
    match (module, input) {
        ("compliant_peg" | "compliant_peg_lean", "y") => {
            Some(insertion_scene().2.to_vector().as_slice().to_vec())
        }
        ("compliant_peg" | "compliant_peg_lean", "p") => {
            let (params, load, _) = insertion_scene();
            Some(params.vector(&load).as_slice().to_vec())
        }
        ("hertz", "load") => Some(vec![12.5]),
        (m, input) if m.starts_with("rigid_peg") => rigid_inputs(m.contains("planar"), input),
        _ => None,
    }
}

/// The rigid peg of Fig. 9 at γ = 0.3 rad, ψ = 0, (γ̇, ψ̇) = (−2, 10) 1/s
/// (planar: ψ̇ = 0), small applied loads, friction opposing the sliding.
fn rigid_inputs(planar: bool, input: &str) -> Option<Vec<f64>> {
    use nalgebra::Vector2;
    use pegdyn::rigid_peg::dynamics::friction_directions;
    use pegdyn::rigid_peg::kinematics::Pose;
    use pegdyn::rigid_peg::{Loads, PegParams};
    let p = PegParams::fig9();
    let (gamma, qd) = (0.3, Vector2::new(-2.0, if planar { 0.0 } else { 10.0 }));
    let loads = Loads {
        m_gamma: 0.02,
        m_psi: 0.0,
        force: [0.3, 0.0, 1.5],
    };
    let pose = Pose::try_new(&p, gamma, 0.0).ok()?;
    let t = friction_directions(&pose.kinematics(qd)).ok()?;
    let v = match (planar, input) {
        (_, "p") => p.to_vector().as_slice().to_vec(),
        (false, "x") => vec![gamma, 0.0, qd[0], qd[1]],
        (true, "x") => vec![gamma, qd[0]],
        (false, "loads") => loads.to_vector().as_slice().to_vec(),
        (true, "loads") => vec![loads.m_gamma, loads.force[0], loads.force[2]],
        (false, "t") => t.iter().flat_map(|v| v.iter().copied()).collect(),
        (true, "t") => vec![t[0][0], t[0][2], t[1][0], t[1][2]],
        (false, "qdd") => vec![3.0, -40.0],
        (true, "qdd") => vec![3.0],
        _ => return None,
    };
    Some(v)
}

/// Outputs of a generated function flattened like `FnSpec::interpret`
/// (outputs in order, matrices row-major).
pub trait Flat {
    /// Appends the values to `out`.
    fn flat(&self, out: &mut Vec<f64>);
}

impl Flat for f64 {
    fn flat(&self, out: &mut Vec<f64>) {
        out.push(*self);
    }
}

impl<R: Dim, C: Dim, S: RawStorage<f64, R, C>> Flat for Matrix<f64, R, C, S> {
    fn flat(&self, out: &mut Vec<f64>) {
        for i in 0..self.nrows() {
            for j in 0..self.ncols() {
                out.push(self[(i, j)]);
            }
        }
    }
}

macro_rules! flat_tuple {
    ($($t:ident $k:tt),*) => {
        impl<$($t: Flat),*> Flat for ($($t,)*) {
            fn flat(&self, out: &mut Vec<f64>) {
                $(self.$k.flat(out);)*
            }
        }
    };
}
flat_tuple!(A 0, B 1);
flat_tuple!(A 0, B 1, C 2);
flat_tuple!(A 0, B 1, C 2, D 3);
flat_tuple!(A 0, B 1, C 2, D 3, E 4);
flat_tuple!(A 0, B 1, C 2, D 3, E 4, F 5);
flat_tuple!(A 0, B 1, C 2, D 3, E 4, F 5, G 6);

/// All outputs of `r`, flattened.
pub fn flatten<R: Flat>(r: &R) -> Vec<f64> {
    let mut out = Vec::new();
    r.flat(&mut out);
    out
}

/// Largest difference of `a` and `b` relative to `max(1, |b|)`, NaN in the
/// same places counting as equal; infinite for different lengths.
pub fn max_rel_diff(a: &[f64], b: &[f64]) -> f64 {
    if a.len() != b.len() {
        return f64::INFINITY;
    }
    a.iter()
        .zip(b)
        .map(|(&x, &y)| {
            if (x.is_nan() && y.is_nan()) || x == y {
                0.0
            } else {
                (x - y).abs() / y.abs().max(1.0)
            }
        })
        .fold(
            0.0,
            |m, d| if d.is_nan() { f64::INFINITY } else { m.max(d) },
        )
}
