//! The `eulerdyn` command: argument parsing, the progress bar and Ctrl-C over the library. Not a library interface:
//! everything it does is a library call ([`eulerdyn`]'s own functions); this binary adds only clap, indicatif and
//! ctrlc, which a crate using the library with `default-features = false` never compiles.

mod balance;
mod capabilities;
mod cli;
mod interrupt;
mod progress;
mod sweep;
mod view;

fn main() -> std::process::ExitCode {
    cli::main()
}
