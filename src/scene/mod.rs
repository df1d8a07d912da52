//! Scenes: the validated [`Scene`] a run needs, and its TOML front end ([`load`], [`parse`]).

mod file;
mod model;
pub mod source_map;

pub use file::{MAX_FIXED_STEPS, MAX_ROWS, Overrides, SceneError, load, parse};
pub use model::{MotionSpec, Scene, SolverConfig};
