//! The sweep file (`SWEEP.toml`), key for key, and its checks: every error names the sweep file, the key and its
//! line, before any run.

use std::path::Path;

use serde::Deserialize;

use super::axis::Axis;
use crate::scene::SceneError;
use crate::scene::source_map::{KeyPath, SourceMap};

/// A sweep file as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SweepFile {
    /// The base scene, relative to the sweep file.
    pub scene: String,
    /// Seed of the random draws.
    #[serde(default)]
    pub seed: u64,
    /// Draws per grid point.
    #[serde(default = "one")]
    pub runs: u64,
    /// `[[vary]]`, in order.
    #[serde(default)]
    pub vary: Vec<VaryFile>,
    /// `[summary]`.
    #[serde(default)]
    pub summary: SummaryFile,
}

fn one() -> u64 {
    1
}

/// One `[[vary]]`: a key and exactly one of its ways to vary.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct VaryFile {
    pub key: String,
    values: Option<Vec<f64>>,
    linspace: Option<[f64; 3]>,
    logspace: Option<[f64; 3]>,
    geomspace: Option<[f64; 3]>,
    normal: Option<NormalFile>,
    uniform: Option<UniformFile>,
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
struct NormalFile {
    mean: f64,
    sd: f64,
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
struct UniformFile {
    low: f64,
    high: f64,
}

/// `[summary]`.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SummaryFile {
    /// CSV columns whose min, max and final value each run reports.
    #[serde(default)]
    pub columns: Vec<String>,
}

/// Errors of one sweep file: its path and text, to name the key and line at fault.
pub(super) struct Blame<'a> {
    pub path: &'a Path,
    pub text: &'a str,
}

impl Blame<'_> {
    /// The error at `key` of the sweep file (e.g. `vary[1].linspace`), located at its line.
    pub fn at(&self, key: KeyPath, problem: String) -> SceneError {
        SceneError {
            file: self.path.to_path_buf(),
            location: SourceMap::new(self.text).locate(&key),
            key: Some(key.to_string()),
            problem,
        }
    }
}

impl VaryFile {
    /// The axis this `[[vary]]` (number `index`) describes, checked.
    pub fn axis(&self, index: usize, blame: &Blame) -> Result<Axis, SceneError> {
        let mut ways: Vec<(&str, Result<Axis, String>)> = [
            ("values", self.values.clone().map(Axis::values)),
            (
                "linspace",
                self.linspace.map(|[a, b, n]| Axis::linspace(a, b, n)),
            ),
            (
                "logspace",
                self.logspace.map(|[a, b, n]| Axis::logspace(a, b, n)),
            ),
            (
                "geomspace",
                self.geomspace.map(|[a, b, n]| Axis::logspace(a, b, n)),
            ),
            ("normal", self.normal.map(|d| Axis::normal(d.mean, d.sd))),
            (
                "uniform",
                self.uniform.map(|d| Axis::uniform(d.low, d.high)),
            ),
        ]
        .into_iter()
        .filter_map(|(name, axis)| axis.map(|axis| (name, axis)))
        .collect();
        let vary = KeyPath::root().key("vary").index(index);
        if ways.len() != 1 {
            let given: Vec<&str> = ways.iter().map(|(name, _)| *name).collect();
            let given = if given.is_empty() {
                "none".to_string()
            } else {
                given.join(", ")
            };
            return Err(blame.at(
                vary,
                format!("give exactly one of values, linspace, geomspace, logspace, normal, uniform (given: {given})"),
            ));
        }
        let (name, axis) = ways.remove(0);
        axis.map_err(|problem| blame.at(vary.key(name), problem))
    }

    /// The warning of a `logspace`, whose end values are values, not numpy's powers of ten; `None` otherwise.
    pub fn logspace_warning(&self, index: usize) -> Option<String> {
        let [from, to, n] = self.logspace?;
        Some(format!(
            "vary[{index}].logspace = [{from}, {to}, {n}] runs from {from} to {to} (the end values themselves, \
             as numpy's geomspace), not from 10^{from} to 10^{to} as numpy's logspace would; write \
             `geomspace = [{from}, {to}, {n}]` to say so, or give the values 10^a and 10^b"
        ))
    }
}
