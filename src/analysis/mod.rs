//! What is computed from runs: the comparison of forms and closed forms (`compare`), the work-precision study
//! (`accuracy`), balancing (`balance`), and sweeps and Monte Carlo over many scenes (`sweep`).

pub mod balance;
pub mod compare;
pub mod study;
pub mod sweep;
