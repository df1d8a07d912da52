//! The `eulerdyn` command: a thin shell over the library's [`eulerdyn::cli`].

fn main() -> std::process::ExitCode {
    eulerdyn::cli::main()
}
