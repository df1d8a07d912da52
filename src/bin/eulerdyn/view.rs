//! `eulerdyn view`: a run's CSV (and its sidecar) written as one self-contained HTML page that shows the motion
//! in 3D.

use std::path::PathBuf;

use clap::Args;

use eulerdyn::output::view::{ViewError, ViewSummary, view_file};

#[derive(Debug, Args)]
pub struct ViewArgs {
    /// CSV written by `eulerdyn run -o RUN.csv`; its sidecar RUN.csv.meta.json gives the body's shape.
    #[arg(value_name = "RUN.csv")]
    pub csv: PathBuf,
    /// The HTML page to write (atomically): one file, everything inline, no network request.
    #[arg(short = 'o', long = "output", value_name = "VIEW.html")]
    pub output: PathBuf,
}

/// Writes the page; on success, the lines to print on stderr: a warning per thing that could not be drawn, and
/// what was written.
pub fn view_command(args: &ViewArgs) -> Result<Vec<String>, ViewError> {
    let (csv, out) = (&args.csv, &args.output);
    if let (Ok(a), Ok(b)) = (csv.canonicalize(), out.canonicalize())
        && a == b
    {
        return Err(ViewError::Input {
            file: out.clone(),
            problem: "the page would overwrite the CSV it shows; give another -o path".into(),
        });
    }
    let summary = view_file(csv, out)?;
    Ok(messages(&summary, out))
}

/// The warnings and the `wrote …` line for `summary`.
fn messages(summary: &ViewSummary, out: &std::path::Path) -> Vec<String> {
    let mut lines: Vec<String> = summary
        .notes
        .iter()
        .map(|n| format!("warning: {n}"))
        .collect();
    let rows = if summary.stride == 1 {
        format!("{} rows", summary.rows_in_run)
    } else {
        format!(
            "{} of {} rows: every {}th from the first, and the last",
            summary.rows_drawn, summary.rows_in_run, summary.stride
        )
    };
    lines.push(format!(
        "wrote {} ({rows}; {:.1} MB)",
        out.display(),
        summary.bytes as f64 / 1e6
    ));
    lines
}
