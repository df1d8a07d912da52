//! eulerdyn — Euler's equation of rigid-body rotation, M = d/dt(I·ω), integrated in body axes and in space axes,
//! where the inertia depends on the coordinates, I_s(θ) (eqs. 8.9 and 8.10 of *Rigid-body dynamics*, the lecture
//! notes this crate implements).
//!
//! A scene is a typed value ([`SceneSpec`]): built in code as below, or read from a TOML scene file
//! ([`scene::load`]). [`SceneSpec::build`] validates it into a [`Scene`]; [`simulate::run`] streams its
//! [`Sample`]s to a sink, [`simulate::samples`] collects them.
//!
//! # Example: the notes' disk on a tilted axis
//!
//! A thin disk (m = 2 kg, R = 0.3 m) spins at ω = 10 rad/s about an axis through C tilted θ = 30° from its
//! symmetry axis. H is constant in body axes but turns about the spin axis in space; the moment that turns it —
//! what the bearings must supply — has the magnitude ¼ m R² ω² sin θ cos θ.
//!
//! ```
//! use eulerdyn::scene::{BodySpec, FixedAxisSpec, SceneSpec, ShapeSpec};
//! use eulerdyn::Form;
//!
//! let (m, r, omega, tilt) = (2.0, 0.3, 10.0, 30f64.to_radians());
//! let scene = SceneSpec::new(BodySpec::shape(m, ShapeSpec::thin_disk(r)), 1.0, 0.01)
//!     .with_motion(FixedAxisSpec::tilted(30.0, omega))
//!     // The spin axis along space z: body → space is a rotation of −θ about x.
//!     .with_attitude([(tilt / 2.0).cos(), -(tilt / 2.0).sin(), 0.0, 0.0])
//!     .with_form(Form::Space)
//!     .build()?;
//! let (samples, _report) = eulerdyn::simulate::samples(&scene)?;
//!
//! // H_s along the spin axis stays ¼ m R² ω (1 + cos²θ); its part across the axis turns at ω.
//! let h_axial = 0.25 * m * r * r * omega * (1.0 + tilt.cos().powi(2));
//! assert!(samples.iter().all(|s| (s.h_o_s.z - h_axial).abs() < 1e-12));
//! // The bearings' moment: |M| = ¼ m R² ω² sin θ cos θ = 1.9486 N·m.
//! let moment = 0.25 * m * r * r * omega * omega * tilt.sin() * tilt.cos();
//! assert!((samples[0].m_o_s.norm() - moment).abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Layers
//!
//! Modules point down only: vocabulary ([`frames`], [`method`], [`named`], [`sample`], [`panel`], [`body`], [`kinetics`],
//! [`effects`], [`events`], [`trig`]) → closed forms ([`exact`]) and integrators ([`integrate`]) → motions
//! ([`motion`]), the body's wheels ([`wheels`]) and its changing shape ([`shape_change`]) → the validated [`scene`] → [`simulate`] → [`analysis`] and
//! [`output`]. The command line is a binary over the library (feature `cli`, on by default). The modules from
//! [`simulate`] down are the workspace's crate `eulerdyn-core` (core/src/), re-exported here under the same paths:
//! cargo compiles it as one code-generation unit, which its run-time figures need, while analysis and output
//! compile beside it.
//!
//! # Features
//!
//! All on by default; with `default-features = false` only the core compiles (no clap, indicatif, ctrlc, plotters,
//! resvg, rayon or rand, and no embedded assets):
//! - `plot`: figures of a run's CSV (`output::plot`) and the work-precision figure (`analysis::study::figure`);
//! - `view`: the 3D page (`output::view`, with the embedded three.js);
//! - `sweep`: sweeps and Monte Carlo over many scenes (`analysis::sweep`, every core through rayon);
//! - `cli`: the command line (needs the three above).
//!
//! ARCHITECTURE.md draws them and says where a new motion, effect, method or command goes.

#![warn(missing_docs)]

/// The book's Rust examples (docs/book), run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../docs/book/src/reference/rust.md")]
pub struct BookRustExamples;

pub mod analysis;
#[cfg(feature = "cli")]
pub mod command;
pub mod output;

// The numerical core (core/src/, the crate eulerdyn-core), under the same paths.
#[doc(inline)]
pub use eulerdyn_core::{
    body, effects, events, exact, frames, integrate, keys, kinetics, method, motion, named, orbit,
    panel, profile, sample, scene, shape_change, simulate, text, trig, wheels,
};

pub use frames::{Axes, Form};
pub use method::{Backend, Method};
pub use sample::Sample;
pub use scene::{
    BodySpec, EffectSpec, FixedAxisSpec, HingeSpec, MotionSpec, Scene, SceneSpec, ShapeSpec,
    TorqueSpec,
};

/// The crate's version (`Cargo.toml`), as the sidecar's `eulerdyn_version` and Python's `eulerdyn.__version__`
/// give it.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");
