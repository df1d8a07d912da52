//! The commands that live in a capability's folder (feature `cli`): each declares its clap arguments and what it
//! does next to the rest of the capability, implements [`Command`], and joins the `eulerdyn` program by one line in
//! the binary's `capabilities!` list (`src/bin/eulerdyn/capabilities.rs`), so that the library never points up
//! to the capabilities that use it.

/// Why a command failed, with the exit code it maps to.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum CommandError {
    /// Bad input: exit 2. The message names the file, key or argument.
    #[error("{0}")]
    Input(String),
    /// The run (or a verdict) failed: exit 1.
    #[error("{0}")]
    Run(String),
}

impl CommandError {
    /// The exit code: 2 for bad input, 1 for a failed run.
    pub fn exit_code(&self) -> u8 {
        match self {
            CommandError::Input(_) => 2,
            CommandError::Run(_) => 1,
        }
    }
}

/// A command of the `eulerdyn` program.
pub trait Command {
    /// Runs it: data to stdout, messages to stderr unless `quiet`.
    fn run(&self, quiet: bool) -> Result<(), CommandError>;
}
