//! Sweeps and Monte Carlo behind `eulerdyn sweep`: many runs of one base scene, each with some numeric keys set
//! from a grid or drawn at random, run in parallel, each reduced to one row of a results table.
//!
//! Runs are numbered from 0: the Cartesian product of the grid axes (in the order written, the last varying
//! fastest), each grid point repeated `runs` times, its repeats consecutive, so run i is grid point i / runs. Run
//! i's draws depend on (seed, i) only ([`axis::run_rng`]); a run is computed the same way whichever thread or shard
//! runs it, so the table never depends on `--jobs` or `--shard` (but for `wall_s`).
//!
//! - this module: [`Sweep`] (load, plan, run one, run all);
//! - `file`: the sweep file and its messages; `axis`: grids and distributions;
//! - `outcome`: one run's status and summary; `table`: the results CSV.

mod axis;
mod file;
mod outcome;
mod table;

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use rayon::prelude::*;

use crate::sample::{ColumnSet, Sample};
use crate::scene::source_map::KeyPath;
use crate::scene::{self, ConditionSpec, MotionSpec, Scene, SceneError, SceneSpec, SceneTemplate};
use crate::simulate;

pub use axis::{Axis, run_rng};
pub use outcome::{RunOutcome, RunSummary, Status, Summarizer};
pub use table::{TableLayout, TableWriter};

use file::{Blame, SweepFile};

/// The most runs one sweep may have.
pub const MAX_RUNS: u64 = 1 << 40;

/// One varied key: as written, as a path, and its axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Varied {
    /// The key as written in the sweep file.
    pub name: String,
    /// Its path in the scene.
    pub key: KeyPath,
    /// Its values: a grid or a distribution.
    pub axis: Axis,
}

/// A loaded, checked sweep: the base scene as a template, the varied keys, and the plan of runs.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// The sweep file.
    pub file: PathBuf,
    /// The base scene file.
    pub scene_file: PathBuf,
    template: SceneTemplate,
    varied: Vec<Varied>,
    seed: u64,
    runs_per_point: u64,
    total: u64,
    layout: TableLayout,
    warnings: Vec<String>,
    /// What each run's scene gets after it is built (a user's moment or wheel law, [`Sweep::with_prepare`]).
    prepare: Option<Prepare>,
}

/// A step applied to each run's built scene.
#[derive(Clone)]
pub struct Prepare(pub std::sync::Arc<dyn Fn(Scene) -> Result<Scene, String> + Send + Sync>);

impl std::fmt::Debug for Prepare {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Prepare(..)")
    }
}

/// Which runs this process runs: those with `run % count == index − 1` (`--shard index/count`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// This shard, from 1.
    pub index: u64,
    /// How many shards.
    pub count: u64,
}

impl Shard {
    /// All runs.
    pub const ALL: Shard = Shard { index: 1, count: 1 };

    /// `K/N` with 1 ≤ K ≤ N.
    ///
    /// ```
    /// use eulerdyn::analysis::sweep::Shard;
    /// assert_eq!(Shard::parse("2/3"), Ok(Shard { index: 2, count: 3 }));
    /// assert!(Shard::parse("0/3").is_err());
    /// assert!(Shard::parse("4/3").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Self, String> {
        let bad =
            || format!("--shard {text}: expected K/N with whole numbers 1 <= K <= N, e.g. 2/8");
        let (k, n) = text.split_once('/').ok_or_else(bad)?;
        let (index, count) = (k.trim().parse::<u64>(), n.trim().parse::<u64>());
        match (index, count) {
            (Ok(index), Ok(count)) if 1 <= index && index <= count => Ok(Self { index, count }),
            _ => Err(bad()),
        }
    }

    /// The runs of `0..total` in this shard, in order.
    pub fn runs(self, total: u64) -> impl Iterator<Item = u64> + Clone {
        (self.index - 1..total).step_by(self.count as usize)
    }
}

impl Sweep {
    /// Reads and checks a sweep file and its base scene. Every problem is found here, before any run: a missing
    /// base scene, an unknown or non-numeric key, an empty grid, an unknown `[summary]` column.
    pub fn load(path: &Path) -> Result<Self, SceneError> {
        let text = scene::read(path)?;
        let spec: SweepFile = scene::parse_toml(path, &text)?;
        let blame = Blame { path, text: &text };
        let root = KeyPath::root();
        let scene_file = path.parent().unwrap_or(Path::new("")).join(&spec.scene);
        if !scene_file.is_file() {
            return Err(blame.at(
                root.key("scene"),
                format!("the base scene {} is not a file", scene_file.display()),
            ));
        }
        let base = scene::load_spec(&scene_file)?;
        let template = SceneTemplate::load(&scene_file)?;
        if spec.vary.is_empty() {
            return Err(blame.at(root, "nothing is varied: give at least one [[vary]]".into()));
        }
        if spec.runs == 0 {
            return Err(blame.at(root.key("runs"), "must be at least 1".into()));
        }
        let mut varied = Vec::with_capacity(spec.vary.len());
        let warnings = (spec.vary.iter().enumerate())
            .filter_map(|(i, v)| v.logspace_warning(i))
            .collect();
        for (i, v) in spec.vary.iter().enumerate() {
            let at = || root.clone().key("vary").index(i).key("key");
            let axis = v.axis(i, &blame)?;
            let key = KeyPath::dotted(&v.key)
                .ok_or_else(|| blame.at(at(), format!("`{}` is not a dotted key path", v.key)))?;
            if varied.iter().any(|w: &Varied| w.key == key) {
                return Err(blame.at(at(), format!("`{}` is varied twice", v.key)));
            }
            template
                .check_numeric_key(&key, axis.probe())
                .map_err(|problem| blame.at(at(), problem))?;
            varied.push(Varied {
                name: v.key.clone(),
                key,
                axis,
            });
        }
        let total = plan_total(&varied, spec.runs)
            .ok_or_else(|| blame.at(root.clone(), format!("more than {MAX_RUNS} runs")))?;
        let layout = layout(&base, &template, &varied, spec.summary.columns)
            .map_err(|problem| blame.at(root.key("summary").key("columns"), problem))?;
        Ok(Self {
            file: path.to_path_buf(),
            scene_file,
            template,
            varied,
            seed: spec.seed,
            runs_per_point: spec.runs,
            total,
            layout,
            warnings,
            prepare: None,
        })
    }

    /// What the sweep file may mean otherwise than it says (a `logspace`'s end values), for the user to read.
    pub fn warnings(&self) -> &[String] {
        &self.warnings
    }

    /// The number of runs.
    pub fn len(&self) -> u64 {
        self.total
    }

    /// Whether the sweep has no run (never, once loaded).
    pub fn is_empty(&self) -> bool {
        self.total == 0
    }

    /// The varied keys, in the sweep file's order.
    pub fn varied(&self) -> &[Varied] {
        &self.varied
    }

    /// The layout of the results table.
    pub fn layout(&self) -> &TableLayout {
        &self.layout
    }

    /// Run `run`'s values of the varied keys, in order: grid values by its grid point, draws from (seed, run).
    pub fn values(&self, run: u64) -> Vec<f64> {
        let mut point = run / self.runs_per_point;
        let mut indices = vec![0; self.varied.len()];
        for (slot, v) in indices.iter_mut().zip(&self.varied).rev() {
            if let Some(n) = v.axis.grid_len() {
                *slot = (point % n as u64) as usize;
                point /= n as u64;
            }
        }
        let mut rng = run_rng(self.seed, run);
        self.varied
            .iter()
            .zip(indices)
            .map(|(v, i)| v.axis.value(i, &mut rng))
            .collect()
    }

    /// The base scene with the varied keys set to `values`, validated; the error names the key at fault.
    pub fn scene(&self, values: &[f64]) -> Result<Scene, String> {
        let keyed: Vec<(KeyPath, f64)> = self
            .varied
            .iter()
            .map(|v| v.key.clone())
            .zip(values.iter().copied())
            .collect();
        let spec: SceneSpec = self.template.spec_with(&keyed)?;
        let scene = spec.build().map_err(|e| e.to_string())?;
        match &self.prepare {
            Some(Prepare(prepare)) => prepare(scene),
            None => Ok(scene),
        }
    }

    /// The sweep with `prepare` applied to each run's built scene, e.g. `|s| s.with_wheel_law(…)` (its error makes
    /// the run invalid).
    ///
    /// ```
    /// use eulerdyn::analysis::sweep::{Status, Sweep};
    /// let dir = tempfile::tempdir()?;
    /// let scene = "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.0, 0.0, 2.0]\n\
    ///              [solver]\nt_end = 1.0\n[output]\nevery = 0.5\n";
    /// std::fs::write(dir.path().join("box.toml"), scene)?;
    /// let sweep = "scene = \"box.toml\"\n[[vary]]\nkey = \"initial.omega.2\"\nvalues = [1.0, 2.0]\n";
    /// std::fs::write(dir.path().join("sweep.toml"), sweep)?;
    /// let sweep = Sweep::load(&dir.path().join("sweep.toml"))?;
    /// let named = sweep.clone().with_prepare(|mut scene| {
    ///     scene.name = "prepared".into();
    ///     Ok(scene)
    /// });
    /// assert_eq!(named.scene(&named.values(1))?.name, "prepared");
    /// // Its error makes the run invalid.
    /// let refused = sweep.with_prepare(|_| Err("no wheel law".into()));
    /// let outcome = refused.run_one(0, None);
    /// assert_eq!((outcome.status, outcome.message.as_str()), (Status::Invalid, "no wheel law"));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_prepare(
        mut self,
        prepare: impl Fn(Scene) -> Result<Scene, String> + Send + Sync + 'static,
    ) -> Self {
        self.prepare = Some(Prepare(std::sync::Arc::new(prepare)));
        self
    }

    /// Runs run `run` and summarises it. With `series`, the run's rows are handed to it after the run (to write
    /// its time series); its error makes the run failed.
    pub fn run_one(&self, run: u64, series: Option<&SeriesSink<'_>>) -> RunOutcome {
        let start = Instant::now();
        let values = self.values(run);
        let outcome = |status, message: String, summary, (steps, evals)| RunOutcome {
            run,
            values: values.clone(),
            status,
            message,
            summary,
            steps,
            evals,
            wall_s: start.elapsed().as_secs_f64(),
        };
        let scene = match self.scene(&values) {
            Ok(scene) => scene,
            Err(message) => return outcome(Status::Invalid, message, None, (0, 0)),
        };
        let columns = scene.facts().columns();
        let mut summarizer = Summarizer::new(columns, &self.layout.summary);
        let mut rows: Vec<Sample> = Vec::new();
        let result = simulate::run_with_events(&scene, |s: &Sample| {
            summarizer.add(s);
            if series.is_some() {
                rows.push(*s);
            }
            Ok::<(), std::convert::Infallible>(())
        });
        let report = match result {
            Ok((report, events)) => {
                summarizer.add_events(&scene.events, &events);
                report
            }
            Err(e) => return outcome(Status::Failed, e.to_string(), None, (0, 0)),
        };
        if let Some(write) = series
            && let Err(e) = write(run, columns.clone(), &rows)
        {
            return outcome(Status::Failed, format!("time series: {e}"), None, (0, 0));
        }
        let counts = (report.stats.steps, report.stats.evals);
        outcome(Status::Ok, String::new(), Some(summarizer.finish()), counts)
    }

    /// Runs the runs of `shard` on `jobs` threads (0: all cores) and hands each outcome to `deliver` in run
    /// order. Runs go in batches (the first small, growing while a batch takes under a quarter second), so that
    /// memory holds two batches of outcomes and progress comes often; while the pool runs a batch, the calling
    /// thread delivers the one before (so the table and the progress bar never leave the pool idle); `deliver`'s
    /// error stops the sweep (the runs of the batch in flight not yet started are skipped, its others dropped).
    pub fn run_all<E: std::fmt::Display>(
        &self,
        jobs: usize,
        shard: Shard,
        series: Option<&SeriesSink<'_>>,
        mut deliver: impl FnMut(&RunOutcome) -> Result<(), E>,
    ) -> Result<(), SweepError<E>> {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(jobs)
            .build()
            .map_err(|e| SweepError::Threads(e.to_string()))?;
        let threads = pool.current_num_threads() as u64;
        let mut runs = shard.runs(self.total);
        let mut batch_len = 2 * threads;
        // Set when `deliver` fails: the runs of the batch in flight not yet started are skipped.
        let stop = AtomicBool::new(false);
        std::thread::scope(|scope| {
            let run_batch = |batch: Vec<u64>| {
                let (pool, stop) = (&pool, &stop);
                scope.spawn(move || {
                    let started = Instant::now();
                    let run =
                        |&i: &u64| (!stop.load(Ordering::Relaxed)).then(|| self.run_one(i, series));
                    let outcomes: Vec<Option<RunOutcome>> =
                        pool.install(|| batch.par_iter().map(run).collect());
                    (outcomes, started.elapsed().as_secs_f64())
                })
            };
            let mut running = Some(run_batch(runs.by_ref().take(batch_len as usize).collect()));
            while let Some(handle) = running.take() {
                let next: Vec<u64> = runs.by_ref().take(batch_len as usize).collect();
                running = (!next.is_empty()).then(|| run_batch(next));
                let (outcomes, seconds) = handle
                    .join()
                    .unwrap_or_else(|panic| std::panic::resume_unwind(panic));
                for o in outcomes.iter().flatten() {
                    if let Err(e) = deliver(o) {
                        stop.store(true, Ordering::Relaxed);
                        return Err(SweepError::Deliver(e));
                    }
                }
                if seconds < 0.25 {
                    batch_len = (batch_len * 2).min(MAX_BATCH);
                }
            }
            Ok(())
        })
    }
}

/// The most runs in one batch of [`Sweep::run_all`].
const MAX_BATCH: u64 = 1 << 14;

/// What writes a run's time series: (run, its columns, its rows).
pub type SeriesSink<'a> = dyn Fn(u64, ColumnSet, &[Sample]) -> Result<(), String> + Sync + 'a;

/// Why a sweep stopped.
#[derive(Debug, thiserror::Error)]
pub enum SweepError<E: std::fmt::Display> {
    /// The thread pool could not be made.
    #[error("cannot start the threads: {0}")]
    Threads(String),
    /// The consumer of the outcomes failed (e.g. writing the table).
    #[error("{0}")]
    Deliver(E),
}

/// The number of runs: the grid's points times `runs`, or `None` past [`MAX_RUNS`].
fn plan_total(varied: &[Varied], runs: u64) -> Option<u64> {
    varied
        .iter()
        .filter_map(|v| v.axis.grid_len())
        .try_fold(runs, |n, len| n.checked_mul(len as u64))
        .filter(|&n| n <= MAX_RUNS)
}

/// The table's layout: the optional columns the base scene's motion has, and the `[summary]` columns, each a
/// column of the CSV of the scene with the varied keys at their probe values, or else of the base scene, or else
/// (neither is valid) one of the scene's own optional columns ([`Scene::all_own_columns`]).
fn layout(
    base: &SceneSpec,
    template: &SceneTemplate,
    varied: &[Varied],
    summary: Vec<String>,
) -> Result<TableLayout, String> {
    let axis = base.motion.as_ref().and_then(MotionSpec::axis);
    let support = axis.is_some();
    let bearings = axis.is_some_and(|a| a.bearings.is_some());
    let probe: Vec<(KeyPath, f64)> = varied
        .iter()
        .map(|v| (v.key.clone(), v.axis.probe()))
        .collect();
    let columns = template
        .spec_with(&probe)
        .ok()
        .and_then(|spec| spec.build().ok())
        .or_else(|| base.build().ok())
        .map_or_else(Scene::all_own_columns, |scene| {
            scene.facts().columns().clone()
        });
    let columns = columns.columns();
    let names: Vec<&str> = columns.iter().map(|c| c.name.as_ref()).collect();
    if let Some(unknown) = summary.iter().find(|c| !names.contains(&c.as_str())) {
        return Err(format!(
            "`{unknown}` is not a column of this scene's CSV; its columns are: {}",
            names.join(", ")
        ));
    }
    let events = (base.event.iter())
        .map(|e| match e.condition {
            ConditionSpec::Extremum(kind) => (e.name.clone(), Some(kind)),
            ConditionSpec::Crosses { .. } => (e.name.clone(), None),
        })
        .collect();
    Ok(TableLayout {
        keys: varied.iter().map(|v| v.name.clone()).collect(),
        support,
        bearings,
        summary,
        events,
    })
}
