//! The doors each effect kind goes through: what the library asks of a validated effect ([`EffectKind`]), and how
//! a scene's table becomes one ([`KindSpec`]: read, written, validated onto the body, [`Placement`]). Each kind
//! answers in its own folder; `kinds.rs` registers it by one line.

use std::path::Path;

use nalgebra::{Matrix3, UnitQuaternion, Vector3};

use super::compiling::Compiling;
use crate::frames::Axes;
use crate::keys::{Checked, KeyPath, Keys};
use crate::orbit::{CircularOrbit, DipoleField, FieldKeys};
use crate::sample::ColumnGroup;

/// An effect kind as a scene gives it: its spec, read from its own keys of the `[[effect]]` table and those kinds
/// share, written back to them, and validated onto the body into its [`EffectKind`].
pub(crate) trait KindSpec: Sized {
    /// Its own keys of the `[[effect]]` table, a `#[derive(Keys)]` group ([`NoKeys`] for a kind without any).
    type Keys: Keys + Default;
    /// Its validated form.
    type Effect: EffectKind;

    /// The spec its keys give (its table at `at`; `kind_text` names the table in messages).
    fn read(keys: &Self::Keys, shared: &SharedKeys, at: &KeyPath, kind_text: &str)
    -> Checked<Self>;

    /// Its own keys, and in `shared` those it shares with other kinds.
    fn write(&self, shared: &mut SharedKeys) -> Self::Keys;

    /// The spec validated `on` the body, its table at `at`.
    fn validate(&self, at: &KeyPath, on: &Placement) -> Checked<Self::Effect>;

    /// The files it names taken relative to `dir` (a scene file's directory).
    fn take_files_in(&mut self, _dir: &Path) {}
}

/// The keys of `[[effect]]` that more than one kind takes: `frame` (a torque's, a torque table's) and the Earth's
/// field (`magnetic`'s, `b_dot`'s).
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct SharedKeys {
    /// `frame`: the axes of the moment.
    pub frame: Option<Axes>,
    /// `field_tilt_deg`, `field_lon_deg`, `field_b0`.
    pub field: FieldKeys,
}

/// The keys of a kind that has none of its own (`gravity_gradient`).
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
pub(crate) struct NoKeys {}

/// A validated effect, as the rest of the library reads it: its name and words, the bound of its moment, what it
/// adds to the right-hand side, its columns, and the queries the facts, the closed forms and the 3D page ask (each
/// `None` unless the kind is the one asked about).
pub trait EffectKind {
    /// The `type` in scene files.
    fn kind(&self) -> &'static str;

    /// What `check` and the sidecar call the effect (its [`kind`](Self::kind) unless the kind names itself).
    fn label(&self) -> String {
        self.kind().to_string()
    }

    /// The effect in words, as `eulerdyn check` prints it.
    fn describe(&self) -> String;

    /// An upper bound of |M| over all times, attitudes and rates on a body of mass `mass` (kg), N·m; `None` when
    /// the moment has no such bound (viscous damping, whose power −c|ω|² is never positive, and the user's law).
    fn largest_moment(&self, mass: f64) -> Option<f64>;

    /// The key whose value sets [`largest_moment`](Self::largest_moment), named when that bound is out of range.
    fn size_key(&self) -> &'static str {
        "value"
    }

    /// Adds the effect to the scene's compiled moments.
    fn compile(&self, into: &mut Compiling);

    /// Whether the moment depends on ω other than as viscous damping, which the splitting methods cannot apply.
    fn depends_on_rate(&self) -> bool {
        false
    }

    /// Whether the moment depends on the body's mass distribution (its centre of mass or inertia, fixed when the
    /// effect is validated): a body that changes shape refuses it.
    fn uses_mass_distribution(&self) -> bool {
        false
    }

    /// Whether the work of the moment has no known bound (the user's law): the divergence guard then stands down.
    fn unbounded_work(&self) -> bool {
        false
    }

    /// Whether this is the orbit's gravity (its gradient), which uniform gravity does not join.
    fn is_orbit_gravity(&self) -> bool {
        false
    }

    /// The effect's own columns, after the orbit's and the field's.
    fn columns(&self) -> Option<ColumnGroup> {
        None
    }

    /// Gravity's g (space axes, m/s²) and the pivot from C (body axes, m).
    fn gravity(&self) -> Option<(Vector3<f64>, Vector3<f64>)> {
        None
    }

    /// c (N·m·s) of viscous damping M = −c ω.
    fn damping(&self) -> Option<f64> {
        None
    }

    /// The orbit and the Earth's field the effect acts in.
    fn field(&self) -> Option<(CircularOrbit, DipoleField)> {
        None
    }

    /// The potential energy of the moment on a body of mass `mass` at the attitude `q` (J).
    fn potential(&self, _mass: f64, _q: &UnitQuaternion<f64>) -> Option<f64> {
        None
    }
}

/// Where the effects act: an axis motion's axis point from C (gravity's moment center there), the mass center from
/// the reference origin, the body's mass and inertia about C, and the orbit.
pub(crate) struct Placement<'a> {
    /// An axis motion's axis point from C (body axes, m).
    pub axis_point_b: Option<&'a Vector3<f64>>,
    /// The mass center from the reference origin (body axes, m).
    pub center_b: &'a Vector3<f64>,
    /// The inertia about C (body axes, kg·m²).
    pub inertia_c_b: &'a Matrix3<f64>,
    /// The scene's `[orbit]`.
    pub orbit: Option<&'a CircularOrbit>,
}

impl Placement<'_> {
    /// The orbit of an environment effect `kind` (its table at `at`): it needs an `[orbit]` and a free body.
    pub fn in_orbit(&self, at: &KeyPath, kind: &str) -> Checked<CircularOrbit> {
        let key = at.clone().key("type");
        match (self.orbit, self.axis_point_b) {
            (None, _) => crate::keys::invalid(
                key,
                format!(
                    "effect type = \"{kind}\" needs an `[orbit]` (altitude_km or radius_km): it acts along the orbit"
                ),
            ),
            (Some(_), Some(_)) => crate::keys::invalid(
                key,
                format!(
                    "effect type = \"{kind}\" acts on a free body in orbit; a fixed axis or hinge is not in orbit"
                ),
            ),
            (Some(orbit), None) => Ok(*orbit),
        }
    }
}
