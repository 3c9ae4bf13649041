//! pegdyn
pub mod compliant;
pub mod error;
pub mod generated;
pub mod hertz;
pub mod integrate;
pub mod jamming;
pub mod output;
pub mod reference_problems;
pub mod rigid;
pub mod scene;
pub mod system;
