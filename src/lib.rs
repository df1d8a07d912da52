//! eulerdyn — Euler's equation of rigid-body rotation, M = d/dt(I·ω), integrated in body and in space axes.
//!
//! Data flows one way: scene → model → simulation → samples → sinks.
//!
//! - [`body`]: rigid bodies, inertia tensors, principal axes, the parallel-axis theorem.
//! - [`kinetics`]: kinetic states P, H_C, H_A and kinetic energy (Theorems 23–25, eqs. 8.1–8.6).
//! - [`scene`]: the TOML scene schema and its validation into a [`model::Model`].
//! - [`motion`]: prescribed fixed-axis rotation (inverse dynamics, eq. 8.10) and free rotation.
//! - [`integrate`]: the integration methods and the streaming driver.
//! - [`exact`]: closed-form solutions used as oracles and by `compare`.
//! - [`output`]: CSV rows, the atomic file writer, the metadata sidecar, SVG plots of a run.
//! - [`progress`]: the progress bar on stderr.

pub mod body;
pub mod cli;
pub mod compare;
pub mod effects;
pub mod exact;
pub mod integrate;
pub mod interrupt;
pub mod kinetics;
pub mod model;
pub mod motion;
pub mod output;
pub mod progress;
pub mod report;
pub mod scene;
pub mod simulate;
pub mod source_map;
pub mod study;
pub mod trig;
