//! Reading a run's CSV into the curves the chosen panels draw: by header names (the column order does not matter
//! and extra columns are ignored), streaming (memory does not grow with the rows), each curve reduced by a
//! [`Decimator`]. A panel's optional columns (`potential` and `energy_total` for the energy panel) are read when the
//! file has them. What the run's sidecar says of the scene (name, method, motion, effects) is kept for the title
//! and for the drift panel, which shows only the scene's invariants; the run's located events (its events file) for
//! the markers of the panels that draw their quantities.

use std::io::Read;
use std::path::{Path, PathBuf};

use super::decimator::Decimator;
use super::{Panel, PlotError};
use crate::output::events_file::{EventRow, run_events};
use crate::output::run_csv::RunCsvReader;
use crate::output::sidecar::Sidecar;
use crate::scene::{Facts, MotionKind};
use crate::wheels::rotor_columns;

/// A derived curve of the drift panel: |x(t) − x(0)| / |x(0)| (or |x(t) − x(0)| when x(0) = 0).
#[derive(Debug, Clone)]
pub(super) struct Drift {
    /// The CSV column x.
    pub(super) column: &'static str,
    /// x(0), the first row's value.
    pub(super) x0: Option<f64>,
    pub(super) points: Decimator,
}

/// A derived curve: the magnitude of a vector whose components are three consecutive wanted columns.
#[derive(Debug, Clone)]
pub(super) struct Norm {
    /// The columns' common prefix (`R_A_b` for `R_A_b_x` …).
    pub(super) prefix: &'static str,
    /// The index in a row's values of the x component.
    index: usize,
    pub(super) points: Decimator,
}

/// What the run's sidecar (`RUN.csv.meta.json`) says of the scene that was run.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct SceneFacts {
    pub(super) name: String,
    pub(super) method: String,
    pub(super) frame: String,
    pub(super) motion: MotionKind,
    /// What the scene conserves (the sidecar's `facts`), `None` in a sidecar written before 0.2.
    pub(super) facts: Option<Facts>,
}

/// The curves read from a run's CSV, ready to draw.
#[derive(Debug, Clone)]
pub struct RunSeries {
    /// The file, for titles and messages.
    pub file: PathBuf,
    /// Data rows read.
    pub rows: u64,
    /// Smallest and largest t.
    pub(super) t_range: (f64, f64),
    /// Curves by column name.
    columns: Vec<(String, Decimator)>,
    pub(super) drifts: Vec<Drift>,
    /// |R_A|, |R_B| (bearings panel) and |F_sup| (support panel).
    pub(super) norms: Vec<Norm>,
    /// The scene, from the run's sidecar, when there is one.
    pub(super) scene: Option<SceneFacts>,
    /// The run's located events ([`run_events`]: its events file or sidecar), none for a CSV from stdin.
    pub(super) events: Vec<EventRow>,
    /// The panels read for: those asked for or, when none were, the panels the run has ([`Panel::of_run`]).
    pub panels: Vec<Panel>,
    /// The largest |T| and |ω_b| over the rows, when the H panels read `energy` and `omega_b_*` (else 0), for
    /// [`RunSeries::momentum_scale`].
    extremes: (f64, f64),
    /// The indices in a row's values of `energy` and `omega_b_x`.
    scale_index: Option<(usize, usize)>,
    /// The wheels whose columns the run has (`<name>_spin`, `<name>_h`, `<name>_torque`), in order.
    wheels: Vec<String>,
}

/// The vectors whose magnitude a panel draws, by column prefix.
fn norm_prefixes(panel: Panel) -> &'static [&'static str] {
    match panel {
        Panel::Bearings => &["R_A_b", "R_B_b"],
        Panel::BearingsSpace => &["R_A_s", "R_B_s"],
        Panel::Support => &["F_sup_s"],
        _ => &[],
    }
}

impl RunSeries {
    /// No rows yet: a curve for each wanted column after t, and the derived curves of `panels`.
    fn new(file: &Path, wanted: &[&str], panels: &[Panel]) -> Self {
        let drifts = if panels.contains(&Panel::Drift) {
            ["H_norm", "energy", "energy_total", "H_s_z"]
                .into_iter()
                .filter(|c| wanted.contains(c))
                .map(|column| Drift {
                    column,
                    x0: None,
                    points: Decimator::new(),
                })
                .collect()
        } else {
            Vec::new()
        };
        let norms = panels
            .iter()
            .flat_map(|&p| norm_prefixes(p))
            .filter_map(|&prefix| {
                let x = format!("{prefix}_x");
                let index = wanted.iter().position(|c| *c == x)?;
                Some(Norm {
                    prefix,
                    index,
                    points: Decimator::new(),
                })
            })
            .collect();
        let at = |c: &str| wanted.iter().position(|w| *w == c);
        let reads_scale = panels
            .iter()
            .any(|p| matches!(p, Panel::HBody | Panel::HSpace));
        let scale_index = match (at("energy"), at("omega_b_x")) {
            (Some(energy), Some(omega)) if reads_scale => Some((energy, omega)),
            _ => None,
        };
        Self {
            file: file.to_path_buf(),
            rows: 0,
            t_range: (f64::INFINITY, f64::NEG_INFINITY),
            columns: wanted[1..]
                .iter()
                .map(|&c| (c.to_string(), Decimator::new()))
                .collect(),
            drifts,
            norms,
            scene: None,
            events: Vec::new(),
            panels: panels.to_vec(),
            extremes: (0.0, 0.0),
            scale_index,
            wheels: Vec::new(),
        }
    }

    /// The wheels whose columns the run has, in order (read for the wheel panels only).
    pub(super) fn wheel_names(&self) -> &[String] {
        &self.wheels
    }

    /// Adds a row's `values` (t first, then the wanted columns); `drift_index[k]` is the value of drift k.
    fn push(&mut self, values: &[f64], drift_index: &[usize]) {
        let t = values[0];
        self.t_range = (self.t_range.0.min(t), self.t_range.1.max(t));
        for (k, (_, d)) in self.columns.iter_mut().enumerate() {
            d.push(t, values[k + 1]);
        }
        for norm in &mut self.norms {
            let r = &values[norm.index..norm.index + 3];
            norm.points
                .push(t, (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]).sqrt());
        }
        if let Some((energy, omega)) = self.scale_index {
            let w = &values[omega..omega + 3];
            let omega_norm = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
            self.extremes = (
                self.extremes.0.max(values[energy].abs()),
                self.extremes.1.max(omega_norm),
            );
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

    /// The points of the CSV column `column` (none when it was not read).
    pub(super) fn points(&self, column: &str) -> Vec<(f64, f64)> {
        self.columns
            .iter()
            .find(|(name, _)| *name == column)
            .map(|(_, d)| d.points())
            .unwrap_or_default()
    }

    /// The run's scale of moment of momentum (kg·m²/s), 2 max T / max |ω_b| (0 when not read or at rest): for a
    /// rigid body 2T = ω·Iω ≤ |ω| |Iω| (Cauchy–Schwarz), so it is at most the largest |Iω|; a rotor's energy
    /// ½ J Ω² raises it by up to Ω/|ω_b|.
    pub(super) fn momentum_scale(&self) -> f64 {
        let (energy, omega) = self.extremes;
        if omega > 0.0 {
            2.0 * energy / omega
        } else {
            0.0
        }
    }

    /// Whether the CSV column `column` was read (an optional column the file has, or a required one).
    pub(super) fn has(&self, column: &str) -> bool {
        self.columns.iter().any(|(name, _)| *name == column)
    }
}

/// Reads the CSV file `path` (or stdin when `path` is `-`) for `panels` (when empty, the panels the run has).
pub fn read_run(path: &Path, panels: &[Panel]) -> Result<RunSeries, PlotError> {
    if path.as_os_str() == "-" {
        let reader = RunCsvReader::new(Path::new("stdin"), std::io::stdin().lock())?;
        return read_rows(reader, panels, None);
    }
    let sidecar = Sidecar::read(path).ok();
    let facts = sidecar.as_ref().map(scene_facts);
    let scene_facts = facts.as_ref().and_then(|f| f.facts.as_ref());
    let mut series = read_rows(RunCsvReader::open(path)?, panels, scene_facts)?;
    series.scene = facts;
    series.events = run_events(path, sidecar.as_ref())?;
    Ok(series)
}

/// Reads a run's CSV from `reader` for `panels` (when empty, the panels the run has); `file` names it in messages.
pub fn read_run_from(
    file: &Path,
    reader: impl Read,
    panels: &[Panel],
) -> Result<RunSeries, PlotError> {
    read_rows(RunCsvReader::new(file, reader)?, panels, None)
}

/// Reads the data rows of `csv` (its header read) into the curves of `panels`; when empty, the panels the run has:
/// those its sidecar's `facts` name, or for a file without them, those its header has ([`Panel::of_run`]; for a
/// run whose support moves, the bearing forces in space axes rather than in the spinning body's).
fn read_rows(
    mut csv: RunCsvReader<impl Read>,
    panels: &[Panel],
    facts: Option<&Facts>,
) -> Result<RunSeries, PlotError> {
    let file = csv.file().to_path_buf();
    if csv.index_of("t").is_none() && looks_like_a_scene(&csv) {
        return Err(PlotError::input(&file, scene_file_advice(&file)));
    }
    let wheels = csv.rotor_names();
    let panels = match (panels.is_empty(), facts) {
        (false, _) => panels.to_vec(),
        (true, Some(facts)) if !facts.panels.is_empty() => facts.panels.clone(),
        (true, _) => {
            let has = |c: &str| csv.index_of(c).is_some();
            let carried = facts.is_some_and(|f| f.moving_support);
            let space = carried && Panel::BearingsSpace.columns().iter().all(|c| has(c));
            Panel::of_run(has, space, &wheels)
        }
    };
    let wheel_panels = panels.iter().any(|p| p.is_wheel());
    if wheel_panels && wheels.is_empty() {
        return Err(PlotError::input(
            &file,
            "no wheels (only runs of scenes with [[body.rotor]] have the columns <name>_spin, <name>_h and \
             <name>_torque that the wheel panels draw)",
        ));
    }
    let controlled = (wheels.iter()).all(|n| csv.index_of(&format!("{n}_torque_cmd")).is_some());
    if panels.contains(&Panel::WheelFriction) && !controlled {
        return Err(PlotError::input(
            &file,
            "no wheel friction columns (<name>_friction): only runs whose wheels are under control (a law, a \
             table, mode = \"free\", a limit or friction) have them",
        ));
    }
    let wheel_columns = if wheel_panels {
        rotor_columns(&wheels, controlled)
    } else {
        Vec::new()
    };
    let mut wanted: Vec<&str> = wanted_columns(&panels, |c| csv.index_of(c).is_some());
    wanted.extend(wheel_columns.iter().map(|c| c.name.as_ref()));
    let index = column_indices(&csv, &wanted, &panels)?;
    let mut series = RunSeries::new(&file, &wanted, &panels);
    series.wheels = wheels;
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

/// The columns to read: t, then those of every panel, each once; a panel's optional columns when `present`.
fn wanted_columns(panels: &[Panel], present: impl Fn(&str) -> bool) -> Vec<&'static str> {
    let mut wanted: Vec<&'static str> = vec!["t"];
    for panel in panels {
        let optional = panel.optional_columns().iter().filter(|c| present(c));
        for &c in panel.columns().iter().chain(optional) {
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
    wanted: &[&str],
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
    if let Some(absent) = absent_axis_panels(csv, &missing, panels) {
        return Err(PlotError::input(csv.file(), absent));
    }
    let list: Vec<String> = missing
        .iter()
        .map(|(name, users)| format!("`{name}` (needed by {})", users.join(", ")))
        .collect();
    let runs_with: Vec<String> = panels
        .iter()
        .filter(|p| missing.iter().any(|(name, _)| p.columns().contains(name)))
        .filter_map(|p| p.which_runs().map(|runs| format!("{p}: {runs}")))
        .collect();
    let runs_with = if runs_with.is_empty() {
        String::new()
    } else {
        format!(" ({})", runs_with.join("; "))
    };
    let shown = csv.header_shown();
    let hint = if csv.header().len() == 1 && (shown.contains(';') || shown.contains('\t')) {
        " (the columns must be separated by commas)"
    } else {
        ""
    };
    Err(PlotError::input(
        csv.file(),
        format!(
            "no column {}{runs_with}; is it a CSV written by `eulerdyn run`? Its header is: {shown}{hint}. Choose other panels with --panels ({})",
            list.join(", "),
            Panel::names()
        ),
    ))
}

/// When `csv` is a run of `eulerdyn run` (it has every column of [`Panel::ALL`]) and the `missing` columns are
/// only those of fixed-axis panels asked for, what the run has not, in words: "this run has no bearings (…)".
fn absent_axis_panels(
    csv: &RunCsvReader<impl Read>,
    missing: &[(&str, Vec<&str>)],
    panels: &[Panel],
) -> Option<String> {
    let a_run = std::iter::once("t")
        .chain(Panel::ALL.iter().flat_map(|p| p.columns().iter().copied()))
        .all(|c| csv.index_of(c).is_some());
    if !a_run {
        return None;
    }
    let absent: Vec<&str> = panels
        .iter()
        .filter(|p| missing.iter().any(|(name, _)| p.columns().contains(name)))
        .map(|p| p.absence())
        .collect::<Option<_>>()?;
    let has: Vec<&str> = Panel::of_run(|c| csv.index_of(c).is_some(), false, &[])
        .iter()
        .map(|p| p.name())
        .collect();
    Some(format!(
        "this run has {}. Its panels (drawn without --panels): {}",
        absent.join("; and "),
        has.join(", ")
    ))
}

/// Whether the text read as a CSV looks like a scene file: named `*.toml`, or its first line a TOML comment,
/// table header or `key = value`.
fn looks_like_a_scene(csv: &RunCsvReader<impl Read>) -> bool {
    let toml_name = csv
        .file()
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("toml"));
    let first = csv.header().first().map_or("", |c| c.trim());
    let key = first.split('=').next().unwrap_or("").trim();
    let key_value = first.contains('=')
        && !key.is_empty()
        && key
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.' | '"'));
    toml_name || first.starts_with('#') || first.starts_with('[') || key_value
}

/// The message for a scene file given to `plot`: what it is and the commands that run it and plot its run.
fn scene_file_advice(file: &Path) -> String {
    let (scene, csv, figure) = if file == Path::new("stdin") {
        (
            "SCENE.toml".to_string(),
            "RUN.csv".to_string(),
            "FIG.svg".to_string(),
        )
    } else {
        let named = |ext: &str| file.with_extension(ext).display().to_string();
        (file.display().to_string(), named("csv"), named("svg"))
    };
    format!(
        "this is a scene file (TOML), not a run's CSV; run it, then plot the run: `eulerdyn run {scene} -o {csv}`, \
         then `eulerdyn plot {csv} -o {figure}`"
    )
}

/// The scene's name, method, motion and what it conserves, from the run's sidecar ([`Sidecar`]).
fn scene_facts(sidecar: &Sidecar) -> SceneFacts {
    SceneFacts {
        name: sidecar.scene.name.clone(),
        method: sidecar.solver.method.clone(),
        frame: sidecar.solver.frame.clone(),
        motion: sidecar.scene.motion,
        facts: sidecar.facts.clone(),
    }
}
