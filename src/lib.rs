//! pegdyn
