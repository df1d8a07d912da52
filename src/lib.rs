//! eulerdyn — Euler's equation of rigid-body rotation, M = d/dt(I·ω), integrated in body and in space axes.
//!
//! Layers point down: vocabulary ([`frames`], [`method`], [`sample`], [`body`], [`kinetics`], [`effects`]) →
//! closed forms ([`exact`]) and integrators ([`integrate`]) → motions ([`motion`]) → the validated [`scene`] →
//! [`simulate`] → [`analysis`] and [`output`] → the command line.

pub mod analysis;
#[doc(hidden)]
pub mod app;
pub mod body;
pub mod effects;
pub mod exact;
pub mod frames;
pub mod integrate;
pub mod kinetics;
pub mod method;
pub mod motion;
pub mod named;
pub mod output;
pub mod sample;
pub mod scene;
pub mod simulate;
pub mod trig;

pub use frames::{Axes, Form};
pub use method::{Backend, Method};
pub use sample::Sample;
pub use scene::Scene;
