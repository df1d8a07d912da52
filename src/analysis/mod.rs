//! What is computed from runs: the comparison of forms and closed forms (`compare`) and the work-precision study
//! (`accuracy`).

pub mod balance;
pub mod compare;
pub mod study;
