//! Scene files: the TOML schema (unknown keys are errors) and its validation into a [`Scene`].
//!
//! Every error names the file, the key (with line and column where the parser knows them) and what is wrong.

use std::fmt;
use std::path::{Path, PathBuf};

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};
use serde::de::Error as _;
use serde::{Deserialize, Deserializer};

use crate::body::{InvalidBody, RigidBody, Shape};
use crate::effects::{Effect, TorqueProfile};
use crate::frames::{Axes, Form};
use crate::integrate::Schedule;
use crate::method::{Backend, Method};
use crate::motion::fixed_axis::FixedAxis;
use crate::motion::free::FreeBody;
use crate::scene::source_map::{KeyPath, SourceMap};
use crate::scene::{MotionSpec, Scene, SolverConfig};

/// Most rows a run may write (a CSV of about 10 GB).
pub const MAX_ROWS: f64 = 5e7;
/// Most fixed steps a run may take (minutes of computing at ~100 ns per step).
pub const MAX_FIXED_STEPS: f64 = 1e10;

/// A scene that could not be read or is not valid.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError {
    /// The scene file.
    pub file: PathBuf,
    /// The key at fault, e.g. `body.mass` or `effect[1].c`.
    pub key: Option<String>,
    /// Line and column (1-based) where the parser knows them.
    pub location: Option<(usize, usize)>,
    /// What is wrong and what would be valid.
    pub problem: String,
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file.display())?;
        if let Some((line, col)) = self.location {
            write!(f, ":{line}:{col}")?;
        }
        if let Some(key) = &self.key {
            write!(f, ": key `{key}`")?;
        }
        write!(f, ": {}", self.problem)
    }
}

impl std::error::Error for SceneError {}

/// Values from the command line that replace the scene's `[solver]` and `[output]` values.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Overrides {
    pub method: Option<String>,
    pub frame: Option<String>,
    pub backend: Option<String>,
    pub rtol: Option<f64>,
    pub atol: Option<f64>,
    pub dt: Option<f64>,
    pub t_end: Option<f64>,
    pub every: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneDoc {
    name: Option<String>,
    description: Option<String>,
    body: BodyDoc,
    motion: Option<MotionDoc>,
    initial: Option<InitialDoc>,
    #[serde(default)]
    effect: Vec<EffectDoc>,
    solver: SolverDoc,
    output: OutputDoc,
    compare: Option<CompareDoc>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct BodyDoc {
    mass: f64,
    shape: Option<ShapeDoc>,
    inertia: Option<InertiaDoc>,
}

/// An array of exactly `N` numbers. (serde's `[f64; N]` ignores extra elements when TOML drives it, so
/// `omega = [1, 2, 3, 4]` would pass silently.)
#[derive(Debug, Clone, Copy)]
struct Numbers<const N: usize>([f64; N]);

impl<'de, const N: usize> Deserialize<'de> for Numbers<N> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let items = Vec::<f64>::deserialize(deserializer)?;
        <[f64; N]>::try_from(items.as_slice())
            .map(Numbers)
            .map_err(|_| {
                D::Error::invalid_length(items.len(), &format!("an array of {N} numbers").as_str())
            })
    }
}

/// The `type` of a shape.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(rename_all = "snake_case")]
enum ShapeKind {
    ThinDisk,
    Disk,
    ThinRod,
    Sphere,
    Box,
    Cylinder,
}

/// `body.shape`: one flat table for every shape type, so that the TOML parser can point at the exact key of an
/// error (an internally tagged enum buffers the table and loses the positions); which keys a type takes is
/// checked in [`validate_shape`].
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ShapeDoc {
    #[serde(rename = "type")]
    kind: Option<ShapeKind>,
    radius: Option<f64>,
    thickness: Option<f64>,
    length: Option<f64>,
    size: Option<Numbers<3>>,
    height: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(
    untagged,
    expecting = "principal moments [I1, I2, I3] or a full tensor [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] (kg*m^2)"
)]
enum InertiaDoc {
    Principal([f64; 3]),
    Full([[f64; 3]; 3]),
}

/// The `type` of a motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
enum MotionKind {
    Free,
    FixedAxis,
}

/// `[motion]`: one flat table for every motion type (see [`ShapeDoc`]); checked in [`validate_motion`].
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct MotionDoc {
    #[serde(rename = "type")]
    kind: Option<MotionKind>,
    axis: Option<Numbers<3>>,
    tilt_deg: Option<f64>,
    rate: Option<f64>,
    accel: Option<f64>,
    point: Option<Numbers<3>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct InitialDoc {
    omega: Option<Numbers<3>>,
    attitude: Option<Numbers<4>>,
}

#[derive(Debug, Deserialize)]
#[serde(rename_all = "snake_case")]
enum FrameDoc {
    Body,
    Space,
}

#[derive(Debug, Deserialize)]
#[serde(rename_all = "snake_case")]
enum ProfileDoc {
    Constant,
    Sine,
    Step,
}

/// The `type` of an effect.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
enum EffectKind {
    Torque,
    Gravity,
    Damping,
}

/// One `[[effect]]`: one flat table for every effect type (see [`ShapeDoc`]); checked in [`validate_effect`].
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct EffectDoc {
    #[serde(rename = "type")]
    kind: Option<EffectKind>,
    frame: Option<FrameDoc>,
    value: Option<Numbers<3>>,
    profile: Option<ProfileDoc>,
    freq_hz: Option<f64>,
    phase_deg: Option<f64>,
    t_on: Option<f64>,
    t_off: Option<f64>,
    g: Option<Numbers<3>>,
    pivot: Option<Numbers<3>>,
    c: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SolverDoc {
    method: Option<String>,
    frame: Option<String>,
    backend: Option<String>,
    rtol: Option<f64>,
    atol: Option<f64>,
    dt: Option<f64>,
    t_end: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct OutputDoc {
    every: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct CompareDoc {
    tolerance: f64,
}

/// A validation failure before it is given a file and a location.
struct Invalid {
    key: KeyPath,
    problem: String,
}

type Checked<T> = Result<T, Invalid>;

fn invalid<T>(key: KeyPath, problem: impl Into<String>) -> Checked<T> {
    Err(Invalid {
        key,
        problem: problem.into(),
    })
}

/// Reads and validates a scene file, applying command-line overrides.
pub fn load(path: &Path, overrides: &Overrides) -> Result<Scene, SceneError> {
    let error = |problem: String| SceneError {
        file: path.to_path_buf(),
        key: None,
        location: None,
        problem,
    };
    if path.is_dir() {
        return Err(error(
            "is a directory; give the path of a scene file (.toml)".into(),
        ));
    }
    let bytes = std::fs::read(path).map_err(|e| error(format!("cannot read the file: {e}")))?;
    let text = String::from_utf8(bytes).map_err(|e| {
        let offset = e.utf8_error().valid_up_to();
        let before = String::from_utf8_lossy(&e.as_bytes()[..offset]).into_owned();
        let map = SourceMap::new(&before);
        SceneError {
            location: Some(map.line_col(offset.min(before.len()))),
            ..error("the file is not valid UTF-8 text; a scene file is TOML".into())
        }
    })?;
    parse(path, &text, overrides)
}

/// Parses and validates scene text; `path` is used in messages only.
pub fn parse(path: &Path, text: &str, overrides: &Overrides) -> Result<Scene, SceneError> {
    let map = SourceMap::new(text);
    if text.trim().is_empty() {
        return Err(SceneError {
            file: path.to_path_buf(),
            key: None,
            location: None,
            problem:
                "the file is empty; a scene needs at least [body], solver.t_end and output.every"
                    .into(),
        });
    }
    let doc: SceneDoc = toml::from_str(text).map_err(|e| {
        let span = e.span();
        let problem = e.message().trim().to_string();
        let file = path.to_path_buf();
        // serde names a missing key in its message; the span is then that of its table (empty for the root).
        let missing = problem
            .strip_prefix("missing field `")
            .and_then(|rest| rest.split('`').next());
        if let Some(name) = missing {
            let table = span
                .as_ref()
                .map_or_else(KeyPath::root, |s| map.table_at(s));
            return SceneError {
                file,
                location: if table.is_root() {
                    None
                } else {
                    span.map(|s| map.line_col(s.start))
                },
                key: Some(table.key(name).to_string()),
                problem: format!("missing: this key is required ({problem})"),
            };
        }
        // The parser's "duplicate key" does not say which; its span does.
        let duplicate = span
            .as_ref()
            .and_then(|s| text.get(s.clone()))
            .map(str::trim)
            .filter(|name| problem == "duplicate key" && !name.is_empty() && !name.contains('\n'));
        let problem = match duplicate {
            Some(name) => {
                format!("duplicate key `{name}`: each key and table may be given only once")
            }
            None => problem,
        };
        let key = span
            .as_ref()
            .and_then(|s| map.key_at(s.start).or_else(|| map.key_near(s.start)));
        // Text that names no key at all: quote the line, so the message still says where.
        let problem = match (&key, &span) {
            (None, Some(s)) => format!("{problem}, in the line `{}`", map.line_text(s.start)),
            _ => problem,
        };
        SceneError {
            file,
            key: key.map(|k| k.to_string()),
            location: span.map(|s| map.line_col(s.start)),
            problem,
        }
    })?;
    validate(doc, overrides).map_err(|inv| SceneError {
        file: path.to_path_buf(),
        location: map.locate(&inv.key),
        key: Some(inv.key.to_string()),
        problem: inv.problem,
    })
}

/// The value of a key that `kind` requires.
fn required<T>(key: KeyPath, value: Option<T>, kind: &str) -> Checked<T> {
    value.ok_or_else(|| Invalid {
        problem: format!("missing: {kind} needs `{}`", key.last_key()),
        key,
    })
}

/// Refuses the keys of `table` that are given (`given`: every optional key and whether it is present) but that
/// `kind` does not take (`takes`).
fn only_keys(table: &KeyPath, kind: &str, takes: &[&str], given: &[(&str, bool)]) -> Checked<()> {
    match given
        .iter()
        .find(|(name, present)| *present && !takes.contains(name))
    {
        None => Ok(()),
        Some((name, _)) => invalid(
            table.clone().key(name),
            if takes.is_empty() {
                format!("{kind} takes no `{name}`")
            } else {
                format!(
                    "{kind} takes no `{name}`; its keys are: {}",
                    takes.join(", ")
                )
            },
        ),
    }
}

fn finite(key: KeyPath, v: f64, unit: &str) -> Checked<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        invalid(key, format!("must be a finite number ({unit}), got {v}"))
    }
}

fn positive(key: KeyPath, v: f64, unit: &str) -> Checked<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        invalid(
            key,
            format!("must be a finite number > 0 ({unit}), got {v}"),
        )
    }
}

fn vector(key: KeyPath, v: [f64; 3], unit: &str) -> Checked<Vector3<f64>> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(Vector3::from(v))
    } else {
        invalid(
            key,
            format!("every component must be a finite number ({unit}), got {v:?}"),
        )
    }
}

/// The key of an overridable value: `solver.dt`, or `solver.dt (from --dt)` when the command line set it.
fn key_of(section: &str, name: &str, overridden: bool) -> KeyPath {
    let key = KeyPath::root().key(section).key(name);
    if overridden {
        key.from_flag(&format!("--{}", name.replace('_', "-")))
    } else {
        key
    }
}

fn validate(doc: SceneDoc, overrides: &Overrides) -> Checked<Scene> {
    let body = validate_body(&doc.body)?;
    let attitude0 = match doc.initial.as_ref().and_then(|i| i.attitude) {
        None => UnitQuaternion::identity(),
        Some(Numbers(q)) => {
            let key = KeyPath::root().key("initial").key("attitude");
            if !q.iter().all(|x| x.is_finite()) {
                return invalid(key, format!("every component must be finite, got {q:?}"));
            }
            let quat = Quaternion::new(q[0], q[1], q[2], q[3]);
            if quat.norm() < 1e-12 {
                return invalid(
                    key,
                    "the zero quaternion is not an attitude; give [w, x, y, z] with a nonzero norm (identity: [1, 0, 0, 0])",
                );
            }
            UnitQuaternion::from_quaternion(quat)
        }
    };
    let effects = doc
        .effect
        .iter()
        .enumerate()
        .map(|(i, e)| validate_effect(i, e))
        .collect::<Checked<Vec<_>>>()?;
    let fixed_axis = doc
        .motion
        .as_ref()
        .is_some_and(|m| m.kind == Some(MotionKind::FixedAxis));
    if fixed_axis && !effects.is_empty() {
        return invalid(
            KeyPath::root().key("effect").index(0),
            "a fixed-axis motion is prescribed: its moment is computed from the motion (M = dH/dt), so it takes no effects; remove the [[effect]] tables or use free motion",
        );
    }
    let gravity_count = effects
        .iter()
        .filter(|e| matches!(e, Effect::Gravity { .. }))
        .count();
    if gravity_count > 1 {
        let second = doc
            .effect
            .iter()
            .enumerate()
            .filter(|(_, e)| e.kind == Some(EffectKind::Gravity))
            .nth(1)
            .map_or(0, |(i, _)| i);
        return invalid(
            KeyPath::root().key("effect").index(second),
            "only one gravity effect is allowed: its pivot is the single fixed point of the body",
        );
    }
    effect_moments_in_range(&effects, body.mass())?;
    let motion = validate_motion(&doc, &body, &attitude0, &effects)?;
    let solver = validate_solver(&doc.solver, overrides)?;
    validate_method(&solver, &motion, &effects, &attitude0, overrides)?;
    let every_key = key_of("output", "every", overrides.every.is_some());
    let every = positive(
        every_key.clone(),
        overrides.every.unwrap_or(doc.output.every),
        "s",
    )?;
    if solver.t_end > 0.0 && every > solver.t_end {
        return invalid(
            every_key,
            format!(
                "every = {every} s is longer than t_end = {} s: the run would have no rows between its ends; use every <= t_end",
                solver.t_end
            ),
        );
    }
    let schedule = Schedule::new(every, solver.t_end).map_err(|e| Invalid {
        key: every_key.clone(),
        problem: e.to_string(),
    })?;
    let rows = schedule.len() as f64;
    if rows > MAX_ROWS {
        return invalid(
            every_key,
            format!(
                "t_end / every would write {rows:.3e} rows, more than the limit of {MAX_ROWS:.0e}; use a larger every"
            ),
        );
    }
    if solver.method.is_fixed_step() {
        let steps = (solver.t_end / solver.dt).ceil();
        if steps > MAX_FIXED_STEPS {
            return invalid(
                key_of("solver", "dt", overrides.dt.is_some()),
                format!(
                    "t_end / dt would take {steps:.3e} steps, more than the limit of {MAX_FIXED_STEPS:.0e}; use a larger dt or an adaptive method"
                ),
            );
        }
    }
    let compare_tolerance = match &doc.compare {
        None => 1e-8,
        Some(c) => positive(
            KeyPath::root().key("compare").key("tolerance"),
            c.tolerance,
            "largest allowed difference",
        )?,
    };
    Ok(Scene {
        name: doc.name.clone().unwrap_or_default(),
        description: doc.description.clone().unwrap_or_default(),
        body,
        motion,
        attitude0,
        effects,
        solver,
        schedule,
        compare_tolerance,
    })
}

/// Checks that the method can run the scene: the splitting methods and `exact` are the project's own (no
/// ode_solvers backend); `exact` is the torque-free closed form, so it refuses effects, and its closed form must
/// accept the body.
fn validate_method(
    solver: &SolverConfig,
    motion: &MotionSpec,
    effects: &[Effect],
    attitude0: &UnitQuaternion<f64>,
    o: &Overrides,
) -> Checked<()> {
    let method = solver.method;
    if solver.backend != Backend::Own && !method.is_runge_kutta() {
        return invalid(
            key_of("solver", "backend", o.backend.is_some()),
            format!(
                "backend \"{}\" runs only rk4, dopri5 and dop853; method \"{}\" is the project's own: remove the backend or use backend = \"own\"",
                solver.backend.name(),
                method.name()
            ),
        );
    }
    if method != Method::Exact {
        return Ok(());
    }
    let method_key = key_of("solver", "method", o.method.is_some());
    if let Some((index, effect)) = effects.iter().enumerate().next() {
        let others: Vec<&str> = Method::ALL
            .iter()
            .filter(|m| **m != Method::Exact)
            .map(|m| m.name())
            .collect();
        let (last, first) = others.split_last().map_or((&"", &[][..]), |(l, f)| (l, f));
        return invalid(
            method_key,
            format!(
                "method \"exact\" is the torque-free closed form; the scene's effect[{index}] ({}) needs {} or {last}",
                effect.kind(),
                first.join(", "),
            ),
        );
    }
    if let MotionSpec::Free { omega0_b, body } = motion {
        crate::motion::exact_flow::ExactFlow::new(body, omega0_b, attitude0).map_err(|e| {
            Invalid {
                key: method_key,
                problem: format!("method \"exact\" cannot solve this body in closed form: {e}"),
            }
        })?;
    }
    Ok(())
}

fn validate_body(doc: &BodyDoc) -> Checked<RigidBody> {
    let body_key = || KeyPath::root().key("body");
    let located = |e: InvalidBody| {
        let mut key = body_key();
        for part in e.key.split('.') {
            key = key.key(part);
        }
        Invalid {
            key,
            problem: e.problem,
        }
    };
    match (&doc.shape, &doc.inertia) {
        (Some(_), Some(_)) => invalid(
            body_key().key("inertia"),
            "give either `shape` or `inertia`, not both",
        ),
        (None, None) => invalid(
            body_key(),
            "the body needs `shape` (e.g. { type = \"thin_disk\", radius = 0.3 }) or `inertia` ([I1, I2, I3] or a 3x3 tensor)",
        ),
        (Some(shape), None) => {
            RigidBody::from_shape(doc.mass, validate_shape(shape)?).map_err(located)
        }
        (None, Some(inertia)) => {
            let tensor = match inertia {
                InertiaDoc::Principal(m) => Matrix3::from_diagonal(&Vector3::from(*m)),
                InertiaDoc::Full(rows) => Matrix3::from_fn(|r, c| rows[r][c]),
            };
            RigidBody::new(doc.mass, tensor).map_err(located)
        }
    }
}

/// The shape a `body.shape` table describes: its `type` and the keys that type takes.
fn validate_shape(doc: &ShapeDoc) -> Checked<Shape> {
    let table = KeyPath::root().key("body").key("shape");
    let Some(kind) = doc.kind else {
        return invalid(
            table.key("type"),
            "missing: the shape needs `type` = \"thin_disk\" | \"disk\" | \"thin_rod\" | \"sphere\" | \"box\" | \"cylinder\"",
        );
    };
    let (name, takes): (&str, &[&str]) = match kind {
        ShapeKind::ThinDisk => ("thin_disk", &["radius"]),
        ShapeKind::Disk => ("disk", &["radius", "thickness"]),
        ShapeKind::ThinRod => ("thin_rod", &["length"]),
        ShapeKind::Sphere => ("sphere", &["radius"]),
        ShapeKind::Box => ("box", &["size"]),
        ShapeKind::Cylinder => ("cylinder", &["radius", "height"]),
    };
    let kind_text = format!("shape type = \"{name}\"");
    only_keys(
        &table,
        &kind_text,
        takes,
        &[
            ("radius", doc.radius.is_some()),
            ("thickness", doc.thickness.is_some()),
            ("length", doc.length.is_some()),
            ("size", doc.size.is_some()),
            ("height", doc.height.is_some()),
        ],
    )?;
    let need = |name: &str, v: Option<f64>| required(table.clone().key(name), v, &kind_text);
    Ok(match kind {
        ShapeKind::ThinDisk => Shape::ThinDisk {
            radius: need("radius", doc.radius)?,
        },
        ShapeKind::Disk => Shape::Disk {
            radius: need("radius", doc.radius)?,
            thickness: need("thickness", doc.thickness)?,
        },
        ShapeKind::ThinRod => Shape::ThinRod {
            length: need("length", doc.length)?,
        },
        ShapeKind::Sphere => Shape::Sphere {
            radius: need("radius", doc.radius)?,
        },
        ShapeKind::Box => Shape::Box {
            size: required(table.clone().key("size"), doc.size, &kind_text)?.0,
        },
        ShapeKind::Cylinder => Shape::Cylinder {
            radius: need("radius", doc.radius)?,
            height: need("height", doc.height)?,
        },
    })
}

fn validate_motion(
    doc: &SceneDoc,
    body: &RigidBody,
    attitude0: &UnitQuaternion<f64>,
    effects: &[Effect],
) -> Checked<MotionSpec> {
    let initial_omega = doc.initial.as_ref().and_then(|i| i.omega);
    let motion = || KeyPath::root().key("motion");
    // The fixed-axis table, or `None` for free motion (no [motion] table, or type = "free").
    let fixed_axis = match &doc.motion {
        None => None,
        Some(m) => match m.kind {
            None => {
                return invalid(
                    motion().key("type"),
                    "missing: the motion needs `type` = \"free\" or \"fixed_axis\"",
                );
            }
            Some(MotionKind::Free) => {
                only_keys(
                    &motion(),
                    "motion type = \"free\"",
                    &[],
                    &[
                        ("axis", m.axis.is_some()),
                        ("tilt_deg", m.tilt_deg.is_some()),
                        ("rate", m.rate.is_some()),
                        ("accel", m.accel.is_some()),
                        ("point", m.point.is_some()),
                    ],
                )?;
                None
            }
            Some(MotionKind::FixedAxis) => Some(m),
        },
    };
    match fixed_axis {
        None => {
            let omega0_b = match initial_omega {
                None => Vector3::zeros(),
                Some(Numbers(w)) => {
                    vector(KeyPath::root().key("initial").key("omega"), w, "rad/s")?
                }
            };
            let center_b = effects
                .iter()
                .find_map(|e| match e {
                    Effect::Gravity { pivot_b, .. } => Some(*pivot_b),
                    _ => None,
                })
                .unwrap_or_else(Vector3::zeros);
            let body_key = if doc.body.shape.is_some() {
                "shape"
            } else {
                "inertia"
            };
            let free_body = FreeBody::new(body, &center_b).map_err(|e| Invalid {
                key: KeyPath::root().key("body").key(body_key),
                problem: e.to_string(),
            })?;
            // H = I_A ω₀ and T = ½ ω₀·H must be numbers: every row reports them, and the divergence guard measures
            // the run by T.
            let h0_b = free_body.inertia_b() * omega0_b;
            let energy0 = 0.5 * omega0_b.dot(&h0_b);
            if !(energy0.is_finite() && h0_b.norm().is_finite()) {
                return invalid(
                    KeyPath::root().key("initial").key("omega"),
                    format!(
                        "ω₀ = ({:e}, {:e}, {:e}) rad/s is too large: the moment of momentum I·ω₀ or the kinetic \
                         energy ½ ω₀·I·ω₀ is beyond the range of double precision",
                        omega0_b.x, omega0_b.y, omega0_b.z
                    ),
                );
            }
            Ok(MotionSpec::Free {
                omega0_b,
                body: free_body,
            })
        }
        Some(m) => {
            if initial_omega.is_some() {
                return invalid(
                    KeyPath::root().key("initial").key("omega"),
                    "a fixed-axis motion sets ω from `motion.rate`; remove initial.omega",
                );
            }
            let axis_b = match (m.axis, m.tilt_deg) {
                (Some(_), Some(_)) => {
                    return invalid(
                        motion().key("tilt_deg"),
                        "give either `axis` or `tilt_deg`, not both",
                    );
                }
                (None, None) => {
                    return invalid(
                        motion(),
                        "a fixed-axis motion needs `axis = [x, y, z]` (body axes) or `tilt_deg`",
                    );
                }
                (Some(Numbers(a)), None) => {
                    let a = vector(motion().key("axis"), a, "direction")?;
                    let norm = a.norm();
                    if !(norm > 1e-300 && norm.is_finite()) {
                        return invalid(
                            motion().key("axis"),
                            "the axis is the zero vector; give a nonzero direction in body axes",
                        );
                    }
                    a / norm
                }
                (None, Some(tilt)) => {
                    let tilt = finite(motion().key("tilt_deg"), tilt, "degrees")?.to_radians();
                    Vector3::new(0.0, -tilt.sin(), tilt.cos())
                }
            };
            let rate = finite(motion().key("rate"), m.rate.unwrap_or(0.0), "rad/s")?;
            let accel = finite(motion().key("accel"), m.accel.unwrap_or(0.0), "rad/s^2")?;
            // The required moment M = I α + ω × I ω is of order I_max (ω² + |α|): it must be a number at t = 0.
            let inertia_max = body.inertia_c().abs().max();
            if !(inertia_max * (rate * rate + accel.abs())).is_finite() {
                return invalid(
                    motion().key("rate"),
                    format!(
                        "rate {rate:e} rad/s with accel {accel:e} rad/s^2 is too large: the moment that keeps the \
                         body on its axis, of order I·(ω² + |α|), is beyond the range of double precision"
                    ),
                );
            }
            Ok(MotionSpec::FixedAxis(FixedAxis::new(
                body,
                axis_b,
                rate,
                accel,
                match m.point {
                    None => Vector3::zeros(),
                    Some(Numbers(p)) => vector(motion().key("point"), p, "m")?,
                },
                *attitude0,
            )))
        }
    }
}

/// The largest moments of the effects ([`Effect::largest_moment`]) and their sum must be numbers: the divergence
/// guard bounds the work the effects can do by that sum ([`crate::motion::free::EffectMoments::rest_moment_bound`]).
fn effect_moments_in_range(effects: &[Effect], mass: f64) -> Checked<()> {
    let mut sum = 0.0;
    for (index, effect) in effects.iter().enumerate() {
        let Some(largest) = effect.largest_moment(mass) else {
            continue;
        };
        let name = match effect {
            Effect::Gravity { .. } => "g",
            _ => "value",
        };
        sum += largest;
        if !sum.is_finite() {
            let problem = if largest.is_finite() {
                format!(
                    "too large: the moment of this effect (up to {largest:e} N*m), added to the others', is beyond \
                     the range of double precision"
                )
            } else {
                "too large: the moment of this effect is beyond the range of double precision"
                    .to_string()
            };
            return invalid(
                KeyPath::root().key("effect").index(index).key(name),
                problem,
            );
        }
    }
    Ok(())
}

fn validate_effect(index: usize, doc: &EffectDoc) -> Checked<Effect> {
    let table = KeyPath::root().key("effect").index(index);
    let key = |name: &str| table.clone().key(name);
    let Some(kind) = doc.kind else {
        return invalid(
            key("type"),
            "missing: an effect needs `type` = \"torque\", \"gravity\" or \"damping\"",
        );
    };
    let (name, takes): (&str, &[&str]) = match kind {
        EffectKind::Torque => (
            "torque",
            &[
                "frame",
                "value",
                "profile",
                "freq_hz",
                "phase_deg",
                "t_on",
                "t_off",
            ],
        ),
        EffectKind::Gravity => ("gravity", &["g", "pivot"]),
        EffectKind::Damping => ("damping", &["c"]),
    };
    let kind_text = format!("effect type = \"{name}\"");
    only_keys(
        &table,
        &kind_text,
        takes,
        &[
            ("frame", doc.frame.is_some()),
            ("value", doc.value.is_some()),
            ("profile", doc.profile.is_some()),
            ("freq_hz", doc.freq_hz.is_some()),
            ("phase_deg", doc.phase_deg.is_some()),
            ("t_on", doc.t_on.is_some()),
            ("t_off", doc.t_off.is_some()),
            ("g", doc.g.is_some()),
            ("pivot", doc.pivot.is_some()),
            ("c", doc.c.is_some()),
        ],
    )?;
    Ok(match kind {
        EffectKind::Torque => {
            let misplaced = |name: &str, present: bool, kind: &str| -> Checked<()> {
                if present {
                    invalid(
                        key(name),
                        format!("`{name}` applies to profile = \"{kind}\" only"),
                    )
                } else {
                    Ok(())
                }
            };
            let profile = match doc.profile.as_ref().unwrap_or(&ProfileDoc::Constant) {
                ProfileDoc::Constant => {
                    misplaced("freq_hz", doc.freq_hz.is_some(), "sine")?;
                    misplaced("phase_deg", doc.phase_deg.is_some(), "sine")?;
                    misplaced("t_on", doc.t_on.is_some(), "step")?;
                    misplaced("t_off", doc.t_off.is_some(), "step")?;
                    TorqueProfile::Constant
                }
                ProfileDoc::Sine => {
                    misplaced("t_on", doc.t_on.is_some(), "step")?;
                    misplaced("t_off", doc.t_off.is_some(), "step")?;
                    let Some(f) = doc.freq_hz else {
                        return invalid(
                            key("freq_hz"),
                            "a sine torque needs `freq_hz` (Hz, finite, >= 0)",
                        );
                    };
                    let f = finite(key("freq_hz"), f, "Hz")?;
                    if f < 0.0 {
                        return invalid(key("freq_hz"), format!("must be >= 0 (Hz), got {f}"));
                    }
                    TorqueProfile::Sine {
                        freq_hz: f,
                        phase_rad: finite(
                            key("phase_deg"),
                            doc.phase_deg.unwrap_or(0.0),
                            "degrees",
                        )?
                        .to_radians(),
                    }
                }
                ProfileDoc::Step => {
                    misplaced("freq_hz", doc.freq_hz.is_some(), "sine")?;
                    misplaced("phase_deg", doc.phase_deg.is_some(), "sine")?;
                    let t_on = finite(key("t_on"), doc.t_on.unwrap_or(0.0), "s")?;
                    let t_off = doc.t_off.unwrap_or(f64::INFINITY);
                    if t_off.is_nan() || t_off <= t_on {
                        return invalid(
                            key("t_off"),
                            format!("must be later than t_on = {t_on} s, got {t_off}"),
                        );
                    }
                    TorqueProfile::Step { t_on, t_off }
                }
            };
            Effect::Torque {
                frame: match doc.frame {
                    None | Some(FrameDoc::Body) => Axes::Body,
                    Some(FrameDoc::Space) => Axes::Space,
                },
                value: vector(
                    key("value"),
                    required(key("value"), doc.value, &kind_text)?.0,
                    "N*m",
                )?,
                profile,
            }
        }
        EffectKind::Gravity => Effect::Gravity {
            g_s: vector(key("g"), doc.g.map_or([0.0, 0.0, -9.81], |g| g.0), "m/s^2")?,
            pivot_b: vector(
                key("pivot"),
                required(key("pivot"), doc.pivot, &kind_text)?.0,
                "m",
            )?,
        },
        EffectKind::Damping => {
            let c = finite(key("c"), required(key("c"), doc.c, &kind_text)?, "N*m*s")?;
            if c < 0.0 {
                return invalid(
                    key("c"),
                    format!("must be >= 0 (N*m*s): a negative damping adds energy, got {c}"),
                );
            }
            Effect::Damping { c }
        }
    })
}

fn choice<T: Copy>(key: KeyPath, given: &str, options: &[(&str, T)]) -> Checked<T> {
    options
        .iter()
        .find(|(name, _)| *name == given)
        .map(|(_, v)| *v)
        .map_or_else(
            || {
                let names: Vec<&str> = options.iter().map(|(n, _)| *n).collect();
                invalid(
                    key,
                    format!(
                        "unknown value \"{given}\"; expected one of: {}",
                        names.join(", ")
                    ),
                )
            },
            Ok,
        )
}

fn validate_solver(doc: &SolverDoc, o: &Overrides) -> Checked<SolverConfig> {
    let methods: Vec<(&str, Method)> = Method::ALL.iter().map(|m| (m.name(), *m)).collect();
    let method = choice(
        key_of("solver", "method", o.method.is_some()),
        o.method
            .as_deref()
            .or(doc.method.as_deref())
            .unwrap_or("dop853"),
        &methods,
    )?;
    let frame = choice(
        key_of("solver", "frame", o.frame.is_some()),
        o.frame
            .as_deref()
            .or(doc.frame.as_deref())
            .unwrap_or("body"),
        &[("body", Form::Body), ("space", Form::Space)],
    )?;
    let backend = choice(
        key_of("solver", "backend", o.backend.is_some()),
        o.backend
            .as_deref()
            .or(doc.backend.as_deref())
            .unwrap_or("own"),
        &[("own", Backend::Own), ("ode_solvers", Backend::OdeSolvers)],
    )?;
    let rtol = o.rtol.or(doc.rtol).unwrap_or(1e-10);
    let rtol_key = key_of("solver", "rtol", o.rtol.is_some());
    if !(rtol.is_finite() && (1e-14..1.0).contains(&rtol)) {
        return invalid(
            rtol_key,
            format!(
                "must be a finite number in [1e-14, 1) (relative tolerance; 1e-14 is the limit of double precision), got {rtol}"
            ),
        );
    }
    let atol = o.atol.or(doc.atol).unwrap_or(1e-12);
    if !(atol.is_finite() && atol > 0.0) {
        return invalid(
            key_of("solver", "atol", o.atol.is_some()),
            format!("must be a finite number > 0 (absolute tolerance), got {atol}"),
        );
    }
    let dt = positive(
        key_of("solver", "dt", o.dt.is_some()),
        o.dt.or(doc.dt).unwrap_or(1e-3),
        "s",
    )?;
    let t_end_key = key_of("solver", "t_end", o.t_end.is_some());
    let t_end = finite(t_end_key.clone(), o.t_end.unwrap_or(doc.t_end), "s")?;
    if t_end < 0.0 {
        return invalid(t_end_key, format!("must be >= 0 (s), got {t_end}"));
    }
    Ok(SolverConfig {
        method,
        frame,
        backend,
        rtol,
        atol,
        dt,
        t_end,
    })
}
