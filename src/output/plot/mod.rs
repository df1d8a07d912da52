//! `eulerdyn plot`: a run's CSV time series drawn as a figure, one panel per quantity, laid out in a grid at a
//! size that prints (see [`layout`]): SVG, or PNG when the output's name ends in `.png`.
//!
//! The CSV is read by its header names (the column order does not matter and extra columns are ignored), so any
//! CSV that `eulerdyn run` writes can be plotted, as can one re-saved by pandas with the same column names. Only
//! the columns the chosen panels need are read. A file that cannot be used (empty, no data rows, a missing
//! column, a cell that is not a finite number, a row of the wrong length) is refused with a [`PlotError`] that
//! names the file, the row and the column.
//!
//! Reading streams: memory does not grow with the number of rows. Long runs are reduced to at most about
//! [`MAX_POINTS`] points per curve by keeping, for each run of consecutive rows, its smallest and its largest
//! value (in time order), so that peaks, flips and spikes stay visible.
//!
//! The figure is drawn with plotters' SVG backend (pure Rust, no font libraries: the SVG names the font family and
//! the viewer renders the text). PNG is that SVG, its text set as outlines of the font embedded in the program
//! (DejaVu Sans, `assets/fonts/`), rasterised by resvg (pure Rust), so it needs no system fonts.
//!
//! Files: `series` reads the CSV and sidecar, `decimator` bounds the points, `panels` says what each panel
//! shows, `layout` sizes the figure and its grid, `draw` draws the SVG, `glyphs` sets its text as
//! outlines, `png` rasterises it.

mod decimator;
mod draw;
mod glyphs;
pub mod layout;
mod panels;
pub mod png;
mod series;

use std::path::{Path, PathBuf};

use super::run_csv::CsvInputError;
use super::ticks;

pub use crate::panel::Panel;
pub(crate) use draw::{
    Area, DrawResult, PALETTE, decade_label, decade_range, draw_curve, draw_legend_entry, svg_text,
};
pub use layout::FigureSize;
pub(crate) use panels::Curve;
pub use panels::DRIFT_FLOOR;
pub use png::parse_dpi;
pub use series::{RunSeries, read_run, read_run_from};

/// Most points per curve (about; see the module documentation).
pub const MAX_POINTS: usize = 4096;

/// The font family the SVG names (the viewer renders the text; the PNG uses the embedded font).
pub(crate) const FONT: &str = "sans-serif";

/// Why a CSV could not be plotted, or the figure not written.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// The CSV cannot be used (bad input).
    #[error("{}: {problem}", file.display())]
    Input {
        /// The file.
        file: PathBuf,
        /// What is wrong.
        problem: String,
    },
    /// A figure option (`--size`, `--title`, `--dpi`) cannot be used; the message names it (bad input).
    #[error("{0}")]
    Option(String),
    /// The figure could not be drawn or written.
    #[error("{}: {problem}", file.display())]
    Output {
        /// The file.
        file: PathBuf,
        /// What failed.
        problem: String,
    },
}

impl From<CsvInputError> for PlotError {
    fn from(e: CsvInputError) -> Self {
        PlotError::Input {
            file: e.file,
            problem: e.problem,
        }
    }
}

impl PlotError {
    fn input(file: &Path, problem: impl Into<String>) -> Self {
        PlotError::Input {
            file: file.to_path_buf(),
            problem: problem.into(),
        }
    }
}

/// How the figure is drawn: its size (default: [`layout::Grid::figure_size`]), its title (default: the scene,
/// method and rows; `Some("")`: none), and the resolution of a PNG.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FigureOptions {
    /// The figure's size.
    pub size: Option<FigureSize>,
    /// Its title.
    pub title: Option<String>,
    /// Pixels per inch of a PNG (default [`png::DEFAULT_DPI`]); an SVG has none, and is refused one.
    pub dpi: Option<f64>,
}

/// The file format of a figure, by the output's extension: `.png` (any case) is PNG, anything else SVG.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FigureFormat {
    /// SVG.
    Svg,
    /// PNG.
    Png,
}

impl FigureFormat {
    /// The format `out`'s name asks for.
    pub fn of(out: &Path) -> Self {
        match out.extension() {
            Some(e) if e.eq_ignore_ascii_case("png") => FigureFormat::Png,
            _ => FigureFormat::Svg,
        }
    }
}

/// The bytes of the figure `svg`, drawn `pixels` wide and high (1/96 inch each), in the format `out`'s name asks
/// for: the SVG text, or its PNG at [`png::DEFAULT_DPI`] (for figures without a `--dpi` of their own).
pub fn figure_bytes(svg: String, pixels: (u32, u32), out: &Path) -> Result<Vec<u8>, String> {
    match FigureFormat::of(out) {
        FigureFormat::Svg => Ok(svg.into_bytes()),
        FigureFormat::Png => {
            let scale = png::DEFAULT_DPI / 96.0;
            let px = |p: u32| (f64::from(p) * scale).round() as u32;
            png::rasterise(&svg, (px(pixels.0), px(pixels.1))).map(|image| image.bytes)
        }
    }
}

/// A `--title` that is one line of printable text.
fn check_title(title: &str) -> Result<(), PlotError> {
    if title.chars().any(char::is_control) {
        return Err(PlotError::Option(
            "--title: give one line of text (no line breaks or control characters)".into(),
        ));
    }
    Ok(())
}

/// The figure for `panels` of `run` (when empty, the panels `run` was read for: [`RunSeries::panels`]), as SVG
/// text.
pub fn render_svg(
    run: &RunSeries,
    panels: &[Panel],
    options: &FigureOptions,
    out_name: &Path,
) -> Result<String, PlotError> {
    let panels = if panels.is_empty() {
        &run.panels
    } else {
        panels
    };
    let title = match &options.title {
        Some(t) => {
            check_title(t)?;
            t.clone()
        }
        None => draw::default_title(run),
    };
    let size = figure_size(panels, options)?;
    draw::render_svg(run, panels, size, &title, out_name)
}

/// What [`plot_file`] drew.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotSummary {
    /// Data rows read from the CSV.
    pub rows: u64,
    /// Panels drawn.
    pub panels: Vec<Panel>,
    /// The file's format.
    pub format: FigureFormat,
    /// Its size in pixels (of the SVG: 1/96 inch; of the PNG: at its dpi).
    pub pixels: (u32, u32),
}

/// Reads the run's CSV `csv` (`-`: stdin), draws `panels` (when empty, the panels the run has:
/// [`Panel::of_run`]) and writes the figure to `out` through [`super::AtomicFile`] (atomically, or written
/// through to a device or FIFO), as PNG when its name ends in `.png`, else SVG: on any error an existing regular
/// `out` is left untouched.
pub fn plot_file(
    csv: &Path,
    out: &Path,
    panels: &[Panel],
    options: &FigureOptions,
) -> Result<PlotSummary, PlotError> {
    let format = FigureFormat::of(out);
    if format == FigureFormat::Svg && options.dpi.is_some() {
        return Err(PlotError::Option(
            "--dpi: only a PNG has a resolution; name the output FIG.png, or leave out --dpi"
                .into(),
        ));
    }
    let run = read_run(csv, panels)?;
    let panels = run.panels.clone();
    let svg = render_svg(&run, &panels, options, out)?;
    let size = figure_size(&panels, options)?;
    let (bytes, pixels) = match format {
        FigureFormat::Svg => (svg.into_bytes(), size.pixels()),
        FigureFormat::Png => {
            let pixels = png::png_pixels(size, options.dpi.unwrap_or(png::DEFAULT_DPI));
            let image = png::rasterise(&svg, pixels).map_err(|problem| PlotError::Output {
                file: out.to_path_buf(),
                problem,
            })?;
            (image.bytes, image.pixels)
        }
    };
    write_atomically(out, &bytes)?;
    Ok(PlotSummary {
        rows: run.rows,
        panels,
        format,
        pixels,
    })
}

/// The figure's size (cm) for `panels` and `options`.
fn figure_size(panels: &[Panel], options: &FigureOptions) -> Result<FigureSize, PlotError> {
    let titled = options.title.as_ref().is_none_or(|t| !t.is_empty());
    layout::Grid::for_panels(panels.len())
        .figure_size(options.size, titled)
        .map_err(|e| PlotError::Option(format!("--size: {e}")))
}

/// Writes `bytes` to `out` through [`super::AtomicFile`]: a temporary file renamed over it (or, for a device or
/// FIFO, written through).
fn write_atomically(out: &Path, bytes: &[u8]) -> Result<(), PlotError> {
    let file = super::AtomicFile::create(out).map_err(|e| PlotError::Input {
        file: out.to_path_buf(),
        problem: format!("cannot create the output file: {e}"),
    })?;
    file.write_and_commit(bytes).map_err(|e| PlotError::Output {
        file: out.to_path_buf(),
        problem: e.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn panel_lists_parse_dedupe_and_refuse_unknown_names() {
        assert_eq!(
            Panel::parse_list("h_body, h_space,h_body").unwrap(),
            vec![Panel::HBody, Panel::HSpace]
        );
        // `all`: every panel the run has, as when no list is given.
        assert_eq!(Panel::parse_list(" all ").unwrap(), Vec::new());
        let e = Panel::parse_list("all,bearings_space").unwrap_err();
        assert!(e.contains("stands alone"), "{e}");
        assert_eq!(
            Panel::parse_list("theta,support").unwrap(),
            vec![Panel::Theta, Panel::Support]
        );
        let e = Panel::parse_list("h_body,torque").unwrap_err();
        assert!(
            e.contains("unknown panel \"torque\"") && e.contains("h_space"),
            "{e}"
        );
        assert!(Panel::parse_list("h_body,").is_err());
    }

    #[test]
    fn the_format_is_chosen_by_the_extension() {
        assert_eq!(FigureFormat::of(Path::new("a/fig.png")), FigureFormat::Png);
        assert_eq!(FigureFormat::of(Path::new("FIG.PNG")), FigureFormat::Png);
        assert_eq!(FigureFormat::of(Path::new("fig.svg")), FigureFormat::Svg);
        assert_eq!(FigureFormat::of(Path::new("fig")), FigureFormat::Svg);
    }
}
