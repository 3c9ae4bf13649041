#![doc = include_str!("../README.md")]
#![warn(missing_docs)]

// Generated code names the crate as `pegdyn::…` so that it reads the same
// inside this crate and in the test harness that includes it.
extern crate self as pegdyn;

pub mod accuracy;
pub mod compliant_peg;
pub mod compliant_peg_3d;
#[cfg(feature = "scenes")]
pub mod error;
pub mod generated;
pub mod hertz;
pub mod integrate;
#[doc(hidden)]
pub mod internals;
pub mod jamming;
#[cfg(feature = "scenes")]
pub mod output;
pub mod reference_problems;
#[cfg(feature = "scenes")]
pub mod replay;
pub mod rigid_peg;
pub mod scalar;
#[cfg(feature = "scenes")]
pub mod scene;
pub mod sensitivity;
pub mod system;
pub mod textbook;
