//! Interrupts (Ctrl-C, SIGTERM): the process stops at once with exit code 130, after removing the temporary files
//! of outputs still being written, so an interrupted run leaves no partial file and an existing output untouched.

/// Exit code of an interrupted run (128 + SIGINT, as shells report it).
pub const EXIT_INTERRUPTED: i32 = 130;

/// Installs the handler: on SIGINT or SIGTERM, remove the pending temporary files, say so, exit 130.
/// Fails only if a handler is already installed (then the default behaviour stays).
pub fn install() -> Result<(), String> {
    ctrlc::set_handler(|| {
        eulerdyn::output::pending::remove_all();
        crate::progress::clear();
        eprintln!("error: interrupted; no output file was written or changed");
        std::process::exit(EXIT_INTERRUPTED);
    })
    .map_err(|e| e.to_string())
}
