//! The `eulerdyn` command: a thin shell over the library's [`eulerdyn::app::cli`].

fn main() -> std::process::ExitCode {
    eulerdyn::app::cli::main()
}
