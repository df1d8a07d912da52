//! The motions eulerdyn simulates: prescribed rotation about a fixed axis, and free rotation.

pub mod fixed_axis;
pub mod free;
