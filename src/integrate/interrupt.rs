//! Cooperative cancellation: an [`Interrupt`] is a flag shared between the
//! code that runs an integration and whoever may want it stopped (a signal
//! handler of the command line, Python's Ctrl-C). A solver given one
//! ([`super::Solver::with_interrupt`]) looks at it before every attempted
//! step and stops with [`super::StopReason::Interrupted`] once it is set;
//! loops over many runs look at it between runs.
//!
//! ```
//! use nalgebra::Vector1;
//! use pegdyn::integrate::{Interrupt, Method, Options, Solver, StopReason};
//! use pegdyn::system::FnSystem;
//!
//! let decay = FnSystem(|_t: f64, x: &Vector1<f64>| -x);
//! let stop = Interrupt::new();
//! stop.request();
//! let sol = Solver::new(Method::Dopri5, Options::default())
//!     .with_interrupt(&stop)
//!     .solve(&decay, 0.0, Vector1::new(1.0), 10.0)
//!     .unwrap();
//! assert_eq!(sol.stop, StopReason::Interrupted { t: 0.0 });
//! ```

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// A shared stop request (cheap to clone; clones share the flag).
#[derive(Debug, Clone, Default)]
pub struct Interrupt(Arc<AtomicBool>);

impl Interrupt {
    /// A flag not yet set.
    pub fn new() -> Self {
        Interrupt::default()
    }

    /// An interrupt reading `flag`, e.g. one a signal handler sets.
    pub fn from_flag(flag: Arc<AtomicBool>) -> Self {
        Interrupt(flag)
    }

    /// The shared flag (to hand to a signal handler).
    pub fn flag(&self) -> Arc<AtomicBool> {
        Arc::clone(&self.0)
    }

    /// Asks every holder to stop.
    pub fn request(&self) {
        self.0.store(true, Ordering::Relaxed);
    }

    /// Whether a stop was asked for.
    pub fn is_requested(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }
}
