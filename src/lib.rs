//! pegdyn
pub mod compliant;
pub mod generated;
pub mod hertz;
pub mod error;
pub mod output;
pub mod scene;
pub mod jamming;
pub mod integrate;
pub mod reference_problems;
pub mod system;
