//! The motions eulerdyn simulates: prescribed rotation about a fixed axis, and free rotation — by the Runge–Kutta
//! right-hand sides of both forms of Euler's equation ([`free`]), by Lie–Poisson splitting ([`lie_poisson`]), or in
//! closed form ([`exact_flow`]); a body with rotors inside it is [`crate::wheels`]'s gyrostat. An axis's support may move
//! ([`moving_support`]: a [`carrier`]).

pub mod attribute;
pub mod axis_columns;
pub mod carrier;
mod choices;
pub mod exact_flow;
pub mod fixed_axis;
pub mod free;
pub mod hinge;
pub(crate) mod keys;
pub mod lie_poisson;
pub mod moving_support;
mod part;
pub mod spec;
pub mod support;
