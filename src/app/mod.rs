//! The command-line program: argument parsing, the progress bar and Ctrl-C. Not a library
//! interface: everything it does is reachable through the library's own functions.

pub mod accuracy;
pub mod balance;
pub mod cli;
pub mod interrupt;
pub mod progress;
pub mod sweep;
pub mod view;
