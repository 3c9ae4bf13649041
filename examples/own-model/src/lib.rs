//! A model pegdyn does not ship — a spherical pendulum over a Hertz floor
//! (see `model.rs`) — generated at build time by `pegdyn-equations` and
//! integrated with pegdyn's integrators.
//!
//! ```
//! use own_model::{generated::spherical_pendulum as sp, initial_state, parameters};
//! use pegdyn::integrate::{Method, Options, solve};
//!
//! let system = sp::System::new(parameters());
//! let x0 = initial_state();
//! let sol = solve(&system, Method::Dopri5, (0.0, x0), 1.0, &Options::with_tolerances(1e-9, 1e-12)).unwrap();
//! let x1 = sol.x.last().unwrap();
//! let p = parameters().into(); // the vector the generated functions take
//! let drift = sp::energy(x1, &p) - sp::energy(&x0, &p);
//! assert!(drift.abs() < 1e-6);
//! ```

use nalgebra::SVector;

/// The generated code: `generated::spherical_pendulum` with the model's
/// functions (`dynamics`, `rhs`, `jacobian_terms`, `energy`, `penetration`,
/// `floor_load`, `angular_momentum`), its layout constants and `System`;
/// `generated::forced_oscillator` (explicit, time-dependent); then
/// `generated::registry` (every function at `f64` and double-double).
#[allow(
    clippy::all,
    clippy::pedantic,
    unused_parens,
    unused_variables,
    non_snake_case,
    missing_docs
)]
pub mod generated {
    include!(concat!(env!("OUT_DIR"), "/own_model.rs"));
}

use generated::spherical_pendulum as sp;

/// Operation counts of the generated functions.
pub const REPORT: &str = include_str!(concat!(env!("OUT_DIR"), "/own_model_report.txt"));

/// The example's parameters: 1 kg on a 1 m rod, g = 9.81 m/s², the floor
/// 0.95 m below the hinge, Hertz stiffness 1e6 N/m^1.5.
pub fn parameters() -> sp::Params<f64> {
    sp::Params {
        m: 1.0,
        l: 1.0,
        g: 9.81,
        h: 0.95,
        k: 1.0e6,
    }
}

/// Released at θ = 1 rad, swinging down with θ̇ = −1 rad/s while turning at
/// φ̇ = 0.5 rad/s: the bob dips into the floor near the bottom of each swing.
pub fn initial_state() -> SVector<f64, { sp::STATE_DIM }> {
    let mut x = SVector::zeros();
    x[sp::X_THETA] = 1.0;
    x[sp::X_THETA_DOT] = -1.0;
    x[sp::X_PHI_DOT] = 0.5;
    x
}
