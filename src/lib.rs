//! pegdyn
pub mod compliant;
pub mod hertz;
