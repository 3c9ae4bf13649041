//! The models pegdyn ships, one file or folder each, every one declared
//! through the public builder ([`ModelBuilder`]) exactly as a downstream
//! crate declares its own. Register a model in [`ALL`] (one line) to have
//! its code generated into `pegdyn::generated::<name>`.

use crate::builder::{Generator, ModelBuilder};
use crate::graph::Graph;
use crate::model::Module;
use crate::{GenError, Options};

pub mod cart_pole;
pub mod chamfer_capture;
pub mod compliant_peg;
pub mod compliant_peg_3d;
pub mod double_pendulum;
pub mod hertz;
pub mod jamming_design;
pub mod pendulum;
pub mod quasi_static;
pub mod rigid_peg;

/// Declares one model in a [`ModelBuilder`] (its doc comment included,
/// [`ModelBuilder::doc`]).
pub type Declare = fn(&mut ModelBuilder<'_>) -> Result<(), GenError>;

/// A built-in model: its module name and its declaration.
#[derive(Clone, Copy, Debug)]
pub struct Builtin {
    /// The generated module's name (`pegdyn::generated::<name>`).
    pub name: &'static str,
    /// The declaration, as a downstream build script would pass it to
    /// [`Generator::model`].
    pub declare: Declare,
}

impl Builtin {
    /// The model's module, declared in `g` as pegdyn's build declares it
    /// (with its parameter Jacobians when it is one of
    /// [`PARAMETER_JACOBIANS`]), for tools that evaluate the model's
    /// expressions, such as the interpreter benches.
    ///
    /// # Panics
    /// If the declaration fails: the built-in models are fixed, so that is
    /// a bug in pegdyn, which the build (`build.rs`) reports first.
    pub fn module(&self, g: &Graph) -> Module {
        let mut b = ModelBuilder::new(g, self.name, "");
        b.parameter_jacobians = PARAMETER_JACOBIANS.contains(&self.name);
        match (self.declare)(&mut b).and_then(|()| b.finish()) {
            Ok(module) => module,
            Err(e) => panic!("built-in model `{}` is inconsistent: {e}", self.name),
        }
    }
}

/// Every model the build generates code for, in emission order. One model
/// per line (kept by `rustfmt::skip`) so that registrations merge cleanly.
#[rustfmt::skip]
pub const ALL: &[Builtin] = &[
    Builtin { name: "pendulum", declare: pendulum::declare },
    Builtin { name: "double_pendulum", declare: double_pendulum::declare },
    Builtin { name: "cart_pole", declare: cart_pole::declare },
    Builtin { name: "hertz", declare: hertz::declare },
    Builtin { name: "compliant_peg", declare: compliant_peg::variants::declare_all_contacts },
    Builtin { name: "compliant_peg_lean", declare: compliant_peg::variants::declare_lean },
    Builtin { name: "compliant_peg_elastic", declare: compliant_peg::variants::declare_elastic },
    Builtin { name: "quasi_static", declare: quasi_static::declare },
    Builtin { name: "rigid_peg", declare: rigid_peg::declare::declare_full },
    Builtin { name: "rigid_peg_frictionless", declare: rigid_peg::declare::declare_frictionless },
    Builtin { name: "rigid_peg_planar", declare: rigid_peg::declare::declare_planar },
    Builtin { name: "rigid_peg_planar_frictionless", declare: rigid_peg::declare::declare_planar_frictionless },
    Builtin { name: compliant_peg_3d::NAME, declare: compliant_peg_3d::declare },
    Builtin { name: jamming_design::NAME, declare: jamming_design::declare },
    Builtin { name: chamfer_capture::NAME, declare: chamfer_capture::declare },
];

/// The built-in models whose parameter Jacobians pegdyn's build generates
/// ([`crate::Options::parameter_jacobians`]): those whose sensitivities it
/// integrates or evaluates (the quasi-static design quantities).
/// [`Builtin::module`] declares them the same way.
pub const PARAMETER_JACOBIANS: &[&str] = &[
    "compliant_peg",
    "rigid_peg",
    jamming_design::NAME,
    chamfer_capture::NAME,
];

/// The options of pegdyn's own build script, which decide which functions
/// exist: the stable forms as [`Options::from_env`] says, the registry of
/// every function, the function list (`generated_list.rs`, which the benches
/// include), the emitter-coverage test harness, and the parameter Jacobians
/// of [`PARAMETER_JACOBIANS`]. The benches' build script takes the same
/// options, so the functions it lists are the ones pegdyn generates.
pub fn build_options() -> Options {
    Options {
        registry: true,
        function_list: true,
        test_harness: true,
        parameter_jacobians: PARAMETER_JACOBIANS
            .iter()
            .map(|m| (*m).to_owned())
            .collect(),
        ..Options::from_env()
    }
}

/// Declares every built-in model ([`ALL`]) in `generator`, in order.
///
/// # Errors
/// The first declaration that fails (a bug in pegdyn's models).
pub fn declare_all(generator: &mut Generator) -> Result<(), GenError> {
    for b in ALL {
        generator.model(b.name, "", b.declare)?;
    }
    Ok(())
}
