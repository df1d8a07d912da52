//! `eulerdyn plot`: a run's CSV time series drawn as an SVG figure, one panel per quantity.
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
//! the viewer renders the text).

use std::fmt;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::str::FromStr;

use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::run_csv::{CsvInputError, RunCsvReader, sidecar_path};
use super::ticks::LinearTicks;

/// The smallest drift drawn on the log scale; smaller values (an exact zero, typically) are drawn at it, and the
/// legend says so.
pub const DRIFT_FLOOR: f64 = 1e-17;

/// Most points per curve (about; see the module documentation).
pub const MAX_POINTS: usize = 4096;

/// Figure width and the height of one panel (SVG pixels).
const WIDTH: u32 = 1200;
const PANEL_HEIGHT: u32 = 320;
/// Height of the figure's title band.
const TITLE_HEIGHT: u32 = 44;
/// Width of the legend column at the right of each panel.
const LEGEND_WIDTH: i32 = 270;

/// The font family the SVG names (the viewer renders the text).
pub(crate) const FONT: &str = "sans-serif";

/// One panel of the figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Panel {
    /// H in body axes (and |H|).
    HBody,
    /// H in space axes (and |H|).
    HSpace,
    /// The moment M about the moment center, body axes (solid) and space axes (dashed).
    Moment,
    /// The angular velocity ω, body axes (solid) and space axes (dashed).
    Omega,
    /// The kinetic energy.
    Energy,
    /// |x(t) − x(0)| / |x(0)| of |H| and of the energy, on a log scale.
    Drift,
    /// The bearings' forces on the body: |R_A|, |R_B| and their components in body axes (A solid, B dashed).
    /// Drawn when asked for (`--panels …,bearings`): only runs with bearings have its columns.
    Bearings,
}

impl Panel {
    /// Every panel, in the order they are drawn by default.
    pub const ALL: [Panel; 6] = [
        Panel::HBody,
        Panel::HSpace,
        Panel::Moment,
        Panel::Omega,
        Panel::Energy,
        Panel::Drift,
    ];

    /// The name used with `--panels`.
    pub fn name(self) -> &'static str {
        match self {
            Panel::HBody => "h_body",
            Panel::HSpace => "h_space",
            Panel::Moment => "moment",
            Panel::Omega => "omega",
            Panel::Energy => "energy",
            Panel::Drift => "drift",
            Panel::Bearings => "bearings",
        }
    }

    /// The CSV columns the panel needs (besides `t`).
    pub fn columns(self) -> &'static [&'static str] {
        match self {
            Panel::HBody => &["H_b_x", "H_b_y", "H_b_z", "H_norm"],
            Panel::HSpace => &["H_s_x", "H_s_y", "H_s_z", "H_norm"],
            Panel::Moment => &["M_b_x", "M_b_y", "M_b_z", "M_s_x", "M_s_y", "M_s_z"],
            Panel::Omega => &[
                "omega_b_x",
                "omega_b_y",
                "omega_b_z",
                "omega_s_x",
                "omega_s_y",
                "omega_s_z",
            ],
            Panel::Energy => &["energy"],
            Panel::Drift => &["H_norm", "energy"],
            Panel::Bearings => &BEARING_COLUMNS,
        }
    }

    /// A comma-separated list of panel names (`h_body,h_space`), in the order given; a name given twice is drawn
    /// once. `all` stands for every panel.
    pub fn parse_list(text: &str) -> Result<Vec<Panel>, String> {
        let mut panels = Vec::new();
        for name in text.split(',').map(str::trim) {
            if name.is_empty() {
                return Err(format!(
                    "empty panel name in \"{text}\"; give names separated by commas, e.g. h_body,h_space (panels: {})",
                    Self::names()
                ));
            }
            let chosen = if name == "all" {
                Panel::ALL.to_vec()
            } else {
                vec![name.parse::<Panel>()?]
            };
            for panel in chosen {
                if !panels.contains(&panel) {
                    panels.push(panel);
                }
            }
        }
        Ok(panels)
    }

    /// Every panel name, comma-separated.
    pub fn names() -> String {
        Panel::ALL.map(Panel::name).join(", ") + ", bearings (with bearings only)"
    }
}

impl fmt::Display for Panel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Panel {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Panel::ALL
            .into_iter()
            .chain([Panel::Bearings])
            .find(|p| p.name() == s)
            .ok_or_else(|| format!("unknown panel \"{s}\"; panels: {}, or all", Panel::names()))
    }
}

/// Why a CSV could not be plotted, or the figure not written.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// The CSV cannot be used (bad input).
    #[error("{}: {problem}", file.display())]
    Input { file: PathBuf, problem: String },
    /// The figure could not be drawn or written.
    #[error("{}: {problem}", file.display())]
    Output { file: PathBuf, problem: String },
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

/// A curve's points reduced to bounded memory: consecutive rows are grouped in buckets, and each bucket keeps its
/// smallest and largest value. Buckets start at one row each; when there are too many, neighbours merge.
#[derive(Debug, Clone, Default)]
struct Decimator {
    /// (lowest point, highest point) of each bucket.
    buckets: Vec<((f64, f64), (f64, f64))>,
    /// Rows per full bucket.
    per_bucket: usize,
    /// Rows in the last bucket.
    in_last: usize,
}

impl Decimator {
    fn new() -> Self {
        Self {
            buckets: Vec::new(),
            per_bucket: 1,
            in_last: 0,
        }
    }

    fn push(&mut self, t: f64, y: f64) {
        let point = (t, y);
        if let Some(last) = self.buckets.last_mut()
            && self.in_last < self.per_bucket
        {
            if y < last.0.1 {
                last.0 = point;
            }
            if y > last.1.1 {
                last.1 = point;
            }
            self.in_last += 1;
            return;
        }
        if self.buckets.len() >= MAX_POINTS / 2 {
            // Every bucket is full: merge neighbours, halving their number.
            self.buckets = self
                .buckets
                .chunks(2)
                .map(|pair| {
                    let lo = pair
                        .iter()
                        .map(|b| b.0)
                        .fold(pair[0].0, |a, b| if b.1 < a.1 { b } else { a });
                    let hi = pair
                        .iter()
                        .map(|b| b.1)
                        .fold(pair[0].1, |a, b| if b.1 > a.1 { b } else { a });
                    (lo, hi)
                })
                .collect();
            self.per_bucket *= 2;
        }
        self.buckets.push((point, point));
        self.in_last = 1;
    }

    /// The kept points, in time order.
    fn points(&self) -> Vec<(f64, f64)> {
        let mut out = Vec::with_capacity(2 * self.buckets.len());
        for &(lo, hi) in &self.buckets {
            if lo == hi {
                out.push(lo);
            } else if lo.0 <= hi.0 {
                out.extend([lo, hi]);
            } else {
                out.extend([hi, lo]);
            }
        }
        out
    }
}

/// A derived curve of the drift panel: |x(t) − x(0)| / |x(0)| (or |x(t) − x(0)| when x(0) = 0).
#[derive(Debug, Clone)]
struct Drift {
    /// The CSV column x.
    column: &'static str,
    /// x(0), the first row's value.
    x0: Option<f64>,
    points: Decimator,
}

/// The curves read from a run's CSV, ready to draw.
#[derive(Debug, Clone)]
pub struct RunSeries {
    /// The file, for titles and messages.
    pub file: PathBuf,
    /// Data rows read.
    pub rows: u64,
    /// Smallest and largest t.
    t_range: (f64, f64),
    /// Curves by column name.
    columns: Vec<(&'static str, Decimator)>,
    drifts: Vec<Drift>,
    /// |R_A| and |R_B| per row (bearings panel): the index in a row's values of the bearing's first body
    /// component, and the curve.
    bearing_norms: Vec<(usize, Decimator)>,
    /// Scene and method from the run's sidecar, when there is one.
    subtitle: Option<String>,
}

impl RunSeries {
    /// No rows yet: a curve for each wanted column after t, and the drift curves when `panels` draw them.
    fn new(file: &Path, wanted: &[&'static str], panels: &[Panel]) -> Self {
        let drifts = if panels.contains(&Panel::Drift) {
            Panel::Drift
                .columns()
                .iter()
                .map(|&column| Drift {
                    column,
                    x0: None,
                    points: Decimator::new(),
                })
                .collect()
        } else {
            Vec::new()
        };
        Self {
            file: file.to_path_buf(),
            rows: 0,
            t_range: (f64::INFINITY, f64::NEG_INFINITY),
            columns: wanted[1..].iter().map(|&c| (c, Decimator::new())).collect(),
            drifts,
            bearing_norms: if panels.contains(&Panel::Bearings) {
                ["R_A_b_x", "R_B_b_x"]
                    .iter()
                    .filter_map(|x| wanted.iter().position(|c| c == x))
                    .map(|index| (index, Decimator::new()))
                    .collect()
            } else {
                Vec::new()
            },
            subtitle: None,
        }
    }

    /// Adds a row's `values` (t first, then the wanted columns); `drift_index[k]` is the value of drift k.
    fn push(&mut self, values: &[f64], drift_index: &[usize]) {
        let t = values[0];
        self.t_range = (self.t_range.0.min(t), self.t_range.1.max(t));
        for (k, (_, d)) in self.columns.iter_mut().enumerate() {
            d.push(t, values[k + 1]);
        }
        for (index, norm) in &mut self.bearing_norms {
            let r = &values[*index..*index + 3];
            norm.push(t, (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]).sqrt());
        }
        for (drift, &k) in self.drifts.iter_mut().zip(drift_index) {
            let x = values[k];
            match drift.x0 {
                None => drift.x0 = Some(x),
                Some(x0) => {
                    let change = (x - x0).abs();
                    let value = if x0 == 0.0 { change } else { change / x0.abs() };
                    drift.points.push(t, value);
                }
            }
        }
    }

    fn points(&self, column: &str) -> Vec<(f64, f64)> {
        self.columns
            .iter()
            .find(|(name, _)| *name == column)
            .map(|(_, d)| d.points())
            .unwrap_or_default()
    }
}

/// Reads the CSV file `path` (or stdin when `path` is `-`) for `panels`.
pub fn read_run(path: &Path, panels: &[Panel]) -> Result<RunSeries, PlotError> {
    if path.as_os_str() == "-" {
        let reader = RunCsvReader::new(Path::new("stdin"), std::io::stdin().lock())?;
        return read_rows(reader, panels);
    }
    let mut series = read_rows(RunCsvReader::open(path)?, panels)?;
    series.subtitle = sidecar_subtitle(path);
    Ok(series)
}

/// Reads a run's CSV from `reader`; `file` names it in messages.
pub fn read_run_from(
    file: &Path,
    reader: impl Read,
    panels: &[Panel],
) -> Result<RunSeries, PlotError> {
    read_rows(RunCsvReader::new(file, reader)?, panels)
}

/// Reads the data rows of `csv` (its header read) into the curves of `panels`.
fn read_rows(mut csv: RunCsvReader<impl Read>, panels: &[Panel]) -> Result<RunSeries, PlotError> {
    let file = csv.file().to_path_buf();
    let wanted = wanted_columns(panels);
    let index = column_indices(&csv, &wanted, panels)?;
    let mut series = RunSeries::new(&file, &wanted, panels);
    let drift_index: Vec<usize> = series
        .drifts
        .iter()
        .map(|d| wanted.iter().position(|&w| w == d.column).unwrap_or(0))
        .collect();
    let mut values = vec![0.0; wanted.len()];
    while csv.next_row(&index, &wanted, &mut values)? {
        series.rows += 1;
        series.push(&values, &drift_index);
    }
    if series.rows == 0 {
        return Err(PlotError::input(
            &file,
            "the file has a header but no data rows; nothing to plot",
        ));
    }
    Ok(series)
}

/// The columns to read: t, then those of every panel, each once.
fn wanted_columns(panels: &[Panel]) -> Vec<&'static str> {
    let mut wanted: Vec<&'static str> = vec!["t"];
    for panel in panels {
        for &c in panel.columns() {
            if !wanted.contains(&c) {
                wanted.push(c);
            }
        }
    }
    wanted
}

/// The index in the header of each wanted column; a missing column is refused with the panels that need it.
fn column_indices(
    csv: &RunCsvReader<impl Read>,
    wanted: &[&'static str],
    panels: &[Panel],
) -> Result<Vec<usize>, PlotError> {
    let mut missing: Vec<(&str, Vec<&str>)> = Vec::new();
    let mut index = Vec::with_capacity(wanted.len());
    for &name in wanted {
        match csv.index_of(name) {
            Some(i) => index.push(i),
            None => {
                let users: Vec<&str> = if name == "t" {
                    vec!["every panel"]
                } else {
                    panels
                        .iter()
                        .filter(|p| p.columns().contains(&name))
                        .map(|p| p.name())
                        .collect()
                };
                missing.push((name, users));
            }
        }
    }
    if missing.is_empty() {
        return Ok(index);
    }
    let list: Vec<String> = missing
        .iter()
        .map(|(name, users)| format!("`{name}` (needed by {})", users.join(", ")))
        .collect();
    let shown = csv.header_shown();
    let hint = if csv.header().len() == 1 && (shown.contains(';') || shown.contains('\t')) {
        " (the columns must be separated by commas)"
    } else {
        ""
    };
    Err(PlotError::input(
        csv.file(),
        format!(
            "no column {}; is it a CSV written by `eulerdyn run`? Its header is: {shown}{hint}. Choose other panels with --panels ({})",
            list.join(", "),
            Panel::names()
        ),
    ))
}

/// "scene tilted-disk, dop853 (space form)" from `FILE.meta.json`, if the run left one next to the CSV.
fn sidecar_subtitle(csv: &Path) -> Option<String> {
    let text = std::fs::read_to_string(sidecar_path(csv)).ok()?;
    let doc: serde_json::Value = serde_json::from_str(&text).ok()?;
    let name = doc.pointer("/scene/name")?.as_str()?;
    let method = doc.pointer("/solver/method")?.as_str()?;
    let frame = doc.pointer("/solver/frame")?.as_str()?;
    let version = doc
        .pointer("/eulerdyn_version")
        .and_then(|v| v.as_str())
        .map(|v| format!(", eulerdyn {v}"))
        .unwrap_or_default();
    Some(format!("scene {name}, {method} ({frame} form){version}"))
}

/// A curve to draw: its legend label, colour, line style and points (x, y) in drawing order.
pub(crate) struct Curve {
    pub label: String,
    pub color: RGBColor,
    pub dashed: bool,
    pub points: Vec<(f64, f64)>,
}

/// The columns of the bearings panel.
const BEARING_COLUMNS: [&str; 6] = [
    "R_A_b_x", "R_A_b_y", "R_A_b_z", "R_B_b_x", "R_B_b_y", "R_B_b_z",
];

const RED: RGBColor = RGBColor(0xd6, 0x27, 0x28);
const GREEN: RGBColor = RGBColor(0x2c, 0xa0, 0x2c);
const BLUE: RGBColor = RGBColor(0x1f, 0x77, 0xb4);
const GREY: RGBColor = RGBColor(0x55, 0x55, 0x55);
const PURPLE: RGBColor = RGBColor(0x94, 0x67, 0xbd);
const ORANGE: RGBColor = RGBColor(0xff, 0x7f, 0x0e);
const XYZ: [RGBColor; 3] = [RED, GREEN, BLUE];

/// What one panel shows.
struct PanelPlot {
    title: String,
    y_label: String,
    curves: Vec<Curve>,
    /// Log scale (the drift panel).
    log: bool,
    /// Legend lines that are text only.
    notes: Vec<String>,
}

/// A vector's three components as curves: `{prefix}_x` etc., colored x red, y green, z blue.
fn components(run: &RunSeries, prefix: &str, suffix: &str, dashed: bool) -> Vec<Curve> {
    ["x", "y", "z"]
        .iter()
        .zip(XYZ)
        .map(|(axis, color)| {
            let column = format!("{prefix}_{axis}");
            Curve {
                label: format!("{column}{suffix}"),
                color,
                dashed,
                points: run.points(&column),
            }
        })
        .collect()
}

/// What `panel` shows of `run`.
fn panel_plot(run: &RunSeries, panel: Panel) -> PanelPlot {
    match panel {
        Panel::HBody => h_panel(run, "H_b", "body"),
        Panel::HSpace => h_panel(run, "H_s", "space"),
        Panel::Moment => body_and_space_panel(
            run,
            "Moment M about the moment center: body axes (solid), space axes (dashed)",
            "M (N·m)",
            "M",
        ),
        Panel::Omega => body_and_space_panel(
            run,
            "Angular velocity ω: body axes (solid), space axes (dashed)",
            "ω (rad/s)",
            "omega",
        ),
        Panel::Energy => PanelPlot {
            title: "Kinetic energy ½ ω·H".into(),
            y_label: "energy (J)".into(),
            curves: vec![Curve {
                label: "energy".into(),
                color: PURPLE,
                dashed: false,
                points: run.points("energy"),
            }],
            log: false,
            notes: Vec::new(),
        },
        Panel::Drift => drift_panel(run),
        Panel::Bearings => bearings_panel(run),
    }
}

/// The components of the bearings' forces on the body, body axes (A solid, B dashed), and their magnitudes.
fn bearings_panel(run: &RunSeries) -> PanelPlot {
    let norms = run
        .bearing_norms
        .iter()
        .zip([("|R_A|", false), ("|R_B|", true)])
        .map(|((_, norm), (label, dashed))| Curve {
            label: label.into(),
            color: GREY,
            dashed,
            points: norm.points(),
        });
    PanelPlot {
        title: "Forces of bearings A (solid) and B (dashed) on the body, body axes".into(),
        y_label: "R (N)".into(),
        curves: components(run, "R_A_b", " (A)", false)
            .into_iter()
            .chain(components(run, "R_B_b", " (B)", true))
            .chain(norms)
            .collect(),
        log: false,
        notes: Vec::new(),
    }
}

/// H in one set of axes (columns `{columns}_x` …), with |H| dashed.
fn h_panel(run: &RunSeries, columns: &str, axes: &str) -> PanelPlot {
    let norm = Curve {
        label: "|H| = H_norm".into(),
        color: GREY,
        dashed: true,
        points: run.points("H_norm"),
    };
    PanelPlot {
        title: format!("Moment of momentum H about the moment center, in {axes} axes"),
        y_label: "H (kg·m²/s)".into(),
        curves: components(run, columns, "", false)
            .into_iter()
            .chain([norm])
            .collect(),
        log: false,
        notes: Vec::new(),
    }
}

/// A vector in body axes (`{quantity}_b_x` …, solid) and in space axes (`{quantity}_s_x` …, dashed).
fn body_and_space_panel(run: &RunSeries, title: &str, y_label: &str, quantity: &str) -> PanelPlot {
    PanelPlot {
        title: title.into(),
        y_label: y_label.into(),
        curves: components(run, &format!("{quantity}_b"), " body", false)
            .into_iter()
            .chain(components(run, &format!("{quantity}_s"), " space", true))
            .collect(),
        log: false,
        notes: Vec::new(),
    }
}

/// The drift of |H| and of the energy on a log scale, values below [`DRIFT_FLOOR`] drawn at it.
fn drift_panel(run: &RunSeries) -> PanelPlot {
    let mut notes = Vec::new();
    let mut clamped = false;
    let curves = run
        .drifts
        .iter()
        .map(|d| {
            let (name, color, unit) = match d.column {
                "H_norm" => ("|H|", ORANGE, "kg·m²/s"),
                _ => ("energy", PURPLE, "J"),
            };
            let absolute = d.x0 == Some(0.0);
            let label = if absolute {
                format!("{name}: absolute ({unit}), as {name}(0) = 0")
            } else {
                format!("{name}: relative")
            };
            let points = d
                .points
                .points()
                .into_iter()
                .map(|(t, v)| {
                    if v < DRIFT_FLOOR {
                        clamped = true;
                        (t, DRIFT_FLOOR)
                    } else {
                        (t, v)
                    }
                })
                .collect();
            Curve {
                label,
                color,
                dashed: false,
                points,
            }
        })
        .collect();
    if clamped {
        notes.push(format!("drift < {DRIFT_FLOOR:.0e} (e.g. 0)"));
        notes.push(format!("is drawn at {DRIFT_FLOOR:.0e}"));
    }
    PanelPlot {
        title: "Change of |H| and energy since t = 0 (their drift where they are invariants)"
            .into(),
        y_label: "|x(t) − x(0)| / |x(0)|".into(),
        curves,
        log: true,
        notes,
    }
}

/// The smallest and largest y of the curves, or `None` when they have no points.
fn y_extent(curves: &[Curve]) -> Option<(f64, f64)> {
    curves
        .iter()
        .flat_map(|c| c.points.iter().map(|p| p.1))
        .fold(None, |acc, y| match acc {
            None => Some((y, y)),
            Some((lo, hi)) => Some((lo.min(y), hi.max(y))),
        })
}

/// A linear axis range around [lo, hi]: 5 % margins; a constant (or constant to 1e-9 relative) gets ±5 % of its
/// value (±1 around 0), so that a constant reads as a flat line at its value instead of magnified round-off.
fn linear_range(lo: f64, hi: f64) -> (f64, f64) {
    let scale = lo.abs().max(hi.abs());
    let span = hi - lo;
    if span <= 1e-9 * scale || scale == 0.0 {
        let mid = 0.5 * (lo + hi);
        let half = if mid == 0.0 { 1.0 } else { 0.05 * mid.abs() };
        (mid - half, mid + half)
    } else {
        (lo - 0.05 * span, hi + 0.05 * span)
    }
}

/// The range of a log axis drawn as exponents: [lo, hi] (log10 of the values) widened to whole decades.
pub(crate) fn decade_range(lo: f64, hi: f64) -> (f64, f64) {
    let (lo, hi) = (lo.floor(), hi.ceil());
    if hi <= lo { (lo, lo + 1.0) } else { (lo, hi) }
}

/// The label of the exponent `v` on a log axis: `1e-12` at a whole decade, else the value.
pub(crate) fn decade_label(v: f64) -> String {
    if (v - v.round()).abs() < 1e-9 {
        format!("1e{}", v.round() as i32)
    } else {
        format!("{:.1e}", 10f64.powf(v))
    }
}

/// A region of an SVG figure.
pub(crate) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

fn draw_error(file: &Path, e: impl fmt::Display) -> PlotError {
    PlotError::Output {
        file: file.to_path_buf(),
        problem: format!("cannot draw the figure: {e}"),
    }
}

/// The figure for `panels` of `run`, as SVG text.
pub fn render_svg(run: &RunSeries, panels: &[Panel], out_name: &Path) -> Result<String, PlotError> {
    let panels: Vec<Panel> = if panels.is_empty() {
        Panel::ALL.to_vec()
    } else {
        panels.to_vec()
    };
    let height = TITLE_HEIGHT + PANEL_HEIGHT * panels.len() as u32;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| draw_error(out_name, e))?;
        let file_name = run.file.file_name().map_or_else(
            || run.file.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        );
        let title = match &run.subtitle {
            Some(sub) => format!("{file_name}: {sub}, {} rows", run.rows),
            None => format!("{file_name}: {} rows", run.rows),
        };
        let body = root
            .titled(&title, (FONT, 22).into_font().color(&BLACK))
            .map_err(|e| draw_error(out_name, e))?;
        for (area, &panel) in body.split_evenly((panels.len(), 1)).iter().zip(&panels) {
            draw_panel(area, run, &panel_plot(run, panel)).map_err(|e| draw_error(out_name, e))?;
        }
        root.present().map_err(|e| draw_error(out_name, e))?;
    }
    Ok(svg)
}

/// What drawing into an [`Area`] gives.
pub(crate) type DrawResult = Result<(), DrawingAreaErrorKind<std::io::Error>>;

fn draw_panel(area: &Area<'_>, run: &RunSeries, plot: &PanelPlot) -> DrawResult {
    let (w, _) = area.dim_in_pixel();
    let (chart_area, legend_area) = area.split_horizontally(w as i32 - LEGEND_WIDTH);
    let (t0, t1) = if run.t_range.0 < run.t_range.1 {
        run.t_range
    } else {
        (run.t_range.0 - 0.5, run.t_range.0 + 0.5)
    };
    // The log scale is drawn as log10 of the values on a linear axis, with a tick at every decade.
    let curves: Vec<Curve> = if plot.log {
        plot.curves
            .iter()
            .map(|c| Curve {
                label: c.label.clone(),
                color: c.color,
                dashed: c.dashed,
                points: c
                    .points
                    .iter()
                    .map(|&(t, v)| (t, v.max(DRIFT_FLOOR).log10()))
                    .collect(),
            })
            .collect()
    } else {
        Vec::new()
    };
    let curves = if plot.log { &curves } else { &plot.curves };
    let (lo, hi) = if plot.log {
        let (lo, hi) = y_extent(curves).unwrap_or((DRIFT_FLOOR.log10(), DRIFT_FLOOR.log10()));
        decade_range(lo, hi)
    } else {
        let (lo, hi) = y_extent(curves).unwrap_or((-1.0, 1.0));
        linear_range(lo, hi)
    };
    let x_ticks = LinearTicks::new(t0, t1);
    let y_ticks = LinearTicks::new(lo, hi);
    let x_fmt = |v: &f64| x_ticks.label(*v);
    let y_fmt = |v: &f64| {
        if plot.log {
            decade_label(*v)
        } else {
            y_ticks.label(*v)
        }
    };
    let y_desc = if plot.log {
        plot.y_label.clone()
    } else {
        y_ticks.title(&plot.y_label)
    };
    let mut chart = ChartBuilder::on(&chart_area)
        .caption(&plot.title, (FONT, 18).into_font())
        .margin(10)
        .margin_right(20)
        .x_label_area_size(42)
        .y_label_area_size(80)
        .build_cartesian_2d(t0..t1, lo..hi)?;
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(x_ticks.title("t (s)"))
        .y_desc(y_desc)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .bold_line_style(BLACK.mix(0.15))
        .light_line_style(BLACK.mix(0.04))
        .max_light_lines(4)
        .axis_desc_style((FONT, 15))
        .label_style((FONT, 13));
    if plot.log {
        // A label at every decade (at most 13 of them), and no minor lines: they would be linear in the exponent.
        let decades = (hi - lo).round().clamp(1.0, 12.0) as usize;
        mesh.y_labels(decades + 1).y_max_light_lines(0);
    }
    mesh.draw()?;
    for curve in curves {
        draw_curve(&mut chart, curve, 7)?;
    }
    draw_legend(&legend_area, plot)
}

/// A chart of an SVG figure, both axes linear in f64 (log scales are drawn as log10 of the values).
pub(crate) type Chart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Draws `curve` as a line 2 px wide, solid or dashed (dashes of `dash` px, 5 px apart).
pub(crate) fn draw_curve(chart: &mut Chart<'_, '_>, curve: &Curve, dash: u32) -> DrawResult {
    let style = ShapeStyle::from(&curve.color).stroke_width(2);
    let points = curve.points.iter().copied();
    if curve.dashed {
        chart.draw_series(DashedLineSeries::new(points, dash, 5, style))?;
    } else {
        chart.draw_series(LineSeries::new(points, style))?;
    }
    Ok(())
}

/// One line of a legend at height `y`: a sample of the curve's line (three dashes when dashed) and its label.
pub(crate) fn draw_legend_entry(
    area: &Area<'_>,
    curve: &Curve,
    y: i32,
    text: &TextStyle<'_>,
) -> DrawResult {
    let style = ShapeStyle::from(&curve.color).stroke_width(2);
    if curve.dashed {
        for x in [6, 18, 30] {
            area.draw(&PathElement::new(vec![(x, y), (x + 7, y)], style))?;
        }
    } else {
        area.draw(&PathElement::new(vec![(6, y), (37, y)], style))?;
    }
    area.draw(&Text::new(curve.label.clone(), (46, y), text.clone()))
}

/// The legend, in its own column beside the chart so that it never hides a curve.
fn draw_legend(area: &Area<'_>, plot: &PanelPlot) -> DrawResult {
    let text = TextStyle::from((FONT, 15).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let note = (FONT, 13)
        .into_font()
        .color(&GREY)
        .pos(Pos::new(HPos::Left, VPos::Center));
    let mut y = 52;
    for curve in &plot.curves {
        draw_legend_entry(area, curve, y, &text)?;
        y += 24;
    }
    for line in &plot.notes {
        area.draw(&Text::new(line.clone(), (6, y), note.clone()))?;
        y += 18;
    }
    Ok(())
}

/// What [`plot_file`] drew.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotSummary {
    /// Data rows read from the CSV.
    pub rows: u64,
    /// Panels drawn.
    pub panels: Vec<Panel>,
}

/// Reads the run's CSV `csv` (`-`: stdin), draws `panels` (all when empty) and writes the SVG to `out` atomically:
/// on any error an existing `out` is left untouched.
pub fn plot_file(csv: &Path, out: &Path, panels: &[Panel]) -> Result<PlotSummary, PlotError> {
    let panels: Vec<Panel> = if panels.is_empty() {
        Panel::ALL.to_vec()
    } else {
        panels.to_vec()
    };
    let run = read_run(csv, &panels)?;
    let svg = render_svg(&run, &panels, out)?;
    write_atomically(out, svg.as_bytes())?;
    Ok(PlotSummary {
        rows: run.rows,
        panels,
    })
}

/// Writes `bytes` to `out` through a temporary file renamed over it.
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
    fn the_decimator_keeps_every_point_of_a_short_curve() {
        let mut d = Decimator::new();
        for k in 0..100 {
            d.push(f64::from(k), f64::from(k * k));
        }
        let points = d.points();
        assert_eq!(points.len(), 100);
        assert_eq!(points[99], (99.0, 9801.0));
    }

    #[test]
    fn the_decimator_bounds_memory_and_keeps_the_extremes_in_time_order() {
        let mut d = Decimator::new();
        let n = 1_000_003;
        for k in 0..n {
            let t = f64::from(k);
            // A single spike that must survive.
            let y = if k == 777_777 { 50.0 } else { (t * 1e-3).sin() };
            d.push(t, y);
        }
        let points = d.points();
        assert!(points.len() <= MAX_POINTS + 2, "{}", points.len());
        assert!(points.contains(&(777_777.0, 50.0)));
        assert!(points.windows(2).all(|w| w[0].0 < w[1].0));
        let lowest = points.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        assert!(lowest < -0.999_999);
        assert_eq!(points.last().map(|p| p.0), Some(f64::from(n - 1)));
    }

    #[test]
    fn panel_lists_parse_dedupe_and_refuse_unknown_names() {
        assert_eq!(
            Panel::parse_list("h_body, h_space,h_body").unwrap(),
            vec![Panel::HBody, Panel::HSpace]
        );
        assert_eq!(Panel::parse_list("all").unwrap(), Panel::ALL.to_vec());
        let e = Panel::parse_list("h_body,torque").unwrap_err();
        assert!(
            e.contains("unknown panel \"torque\"") && e.contains("h_space"),
            "{e}"
        );
        assert!(Panel::parse_list("h_body,").is_err());
    }

    #[test]
    fn ranges_of_constants_are_widened_around_the_value() {
        assert_eq!(linear_range(2.0, 2.0), (1.9, 2.1));
        assert_eq!(linear_range(0.0, 0.0), (-1.0, 1.0));
        let (lo, hi) = linear_range(0.0, 10.0);
        assert!(lo < 0.0 && hi > 10.0);
        assert_eq!(decade_range(-15.5, -12.7), (-16.0, -12.0));
        assert_eq!(decade_range(-17.0, -17.0), (-17.0, -16.0));
        assert_eq!(decade_label(-16.0), "1e-16");
        assert_eq!(decade_label(0.0), "1e0");
    }
}
