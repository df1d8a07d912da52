//! eulerdyn's numerical core: the scene and its validation, the motions, effects and wheels, the closed forms,
//! the integrators and the drivers that stream a run's samples. The crate `eulerdyn` re-exports every module of it
//! under the same path (`eulerdyn::scene`, `eulerdyn::simulate`, …) and adds the analyses, the outputs and the
//! command line: depend on `eulerdyn`. It is a crate of its own so that cargo compiles it as one code-generation
//! unit, which its run-time figures need, while the rest of eulerdyn compiles beside it (the book's "Build time").

#![warn(missing_docs)]

pub mod body;
pub mod effects;
pub mod events;
pub mod exact;
pub mod frames;
pub mod integrate;
pub mod keys;
pub mod kinetics;
pub mod method;
pub mod motion;
pub mod named;
pub mod orbit;
pub mod panel;
pub mod profile;
pub mod sample;
pub mod scene;
pub mod shape_change;
pub mod simulate;
pub mod text;
pub mod trig;
pub mod wheels;

pub use frames::{Axes, Form};
pub use method::{Backend, Method};
pub use sample::Sample;
pub use scene::{
    BodySpec, EffectSpec, FixedAxisSpec, HingeSpec, MotionSpec, Scene, SceneSpec, ShapeSpec,
    TorqueSpec,
};
