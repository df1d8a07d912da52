//! The commands that live in a capability's folder ([`eulerdyn::command`]): one line each in `capabilities!`.

use eulerdyn::command::{Command, CommandError};

/// The registry: one line per capability, `Variant(its clap Subcommand enum)`.
macro_rules! capabilities {
    ($($variant:ident($commands:ty),)*) => {
        /// The commands of the capabilities (flattened into the program's subcommands, in this order).
        #[derive(Debug, clap::Subcommand)]
        pub enum Capabilities {
            $(
                #[command(flatten)]
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
    Score(eulerdyn::analysis::score::command::Commands),
    Fit(eulerdyn::analysis::fit::command::Commands),
}
