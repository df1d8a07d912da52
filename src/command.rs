//! The commands that live in a capability's folder (feature `cli`): each declares its clap arguments and what it
//! does next to the rest of the capability, and joins the `eulerdyn` program by one line in [`Capabilities`].

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

/// The registry: one line per capability, `Variant(its clap Subcommand enum)`.
macro_rules! capabilities {
    ($($variant:ident($commands:ty),)*) => {
        /// The commands of the capabilities (flattened into the program's subcommands, in this order).
        #[derive(Debug, clap::Subcommand)]
        pub enum Capabilities {
            $(
                #[command(flatten)]
                #[allow(missing_docs)]
                $variant($commands),
            )*
        }

        impl Command for Capabilities {
            fn run(&self, quiet: bool) -> Result<(), CommandError> {
                match self {
                    $(Capabilities::$variant(c) => c.run(quiet),)*
                }
            }
        }
    };
}

capabilities! {
    Score(crate::analysis::score::command::Commands),
}
