//! pegdyn
pub mod compliant;
pub mod hertz;
pub mod error;
pub mod output;
pub mod scene;
