//! What is computed from scenes and runs: what a scene will simulate (`describe`), the comparison of forms and
//! closed forms (`compare`), the work-precision study (`accuracy`), balancing (`balance`), and sweeps and Monte
//! Carlo over many scenes (`sweep`, feature `sweep`).

pub mod balance;
pub mod compare;
pub mod describe;
pub mod facts;
pub mod fit;
pub mod score;
pub mod study;
#[cfg(feature = "sweep")]
pub mod sweep;
