//! The integration tests: one test crate (one binary to link, built once by `cargo test --release` on top of
//! the release build), a module per topic. `common` holds the helpers they share.

mod balance_grade;
mod body;
mod book;
mod carriers;
mod cli_end_to_end;
mod cli_usability;
mod common;
mod events;
mod exact_closed_forms;
mod exact_grid;
mod fixed_axis;
mod free_rotation;
mod gallery;
mod geometric_methods;
mod hard_cases;
mod integrate_methods;
mod invariant_axis;
mod messages;
mod output_paths;
mod output_safety;
mod plot;
mod properties;
mod readme;
mod rotors;
mod scene_errors;
mod scene_fuzz;
mod sidecar;
mod study;
mod sweep;
mod user_moments;
mod view;
