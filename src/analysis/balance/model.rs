//! Two-plane balancing of a rigid rotor: the two correction masses that put the mass center on the axis and make
//! the axis a principal axis of inertia at the axis point A, so that the rotating bearing reactions vanish at
//! every rate.
//!
//! With u the axis, s = m ρ_C⊥ the static imbalance (ρ_C from A) and d = I_A u − (u·I_A u) u the dynamic one
//! (the product of inertia about the axis), a point mass m_i at z_i u + r_i (r_i ⊥ u, |r_i| = R) adds m_i r_i to
//! s and −m_i z_i r_i to d (parallel-axis theorem, eq. 8.4). Both vanish for v_i = m_i r_i with
//!
//! ```text
//!   v_1 + v_2 = −s,   z_1 v_1 + z_2 v_2 = d   ⇒   v_2 = (d + z_1 s)/(z_2 − z_1),   v_1 = −s − v_2,
//! ```
//!
//! m_i = |v_i|/R. For the notes' skewed disk (s = 0, |d| = ¼ m R² sin θ cos θ) this is two equal masses
//! ¼ m R² sin θ cos θ / (R_c (z_2 − z_1)) on opposite sides.

use nalgebra::{Unit, Vector3};

use crate::motion::fixed_axis::FixedAxis;
use crate::motion::support::Bearings;
use crate::scene::{BodySpec, InvalidScene, PointMassSpec, SceneSpec};

/// The correction planes: axial positions `a` and `b` from the axis point, and the radius of the masses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Planes {
    /// Axial position of plane A (m).
    pub a: f64,
    /// Axial position of plane B (m), ≠ a.
    pub b: f64,
    /// Distance of the correction masses from the axis (m), > 0.
    pub radius: f64,
}

/// One correction mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Correction {
    /// Axial position of its plane (m).
    pub z: f64,
    /// Mass (kg); 0 when the plane needs none.
    pub mass: f64,
    /// Angle about the axis from the reference direction (degrees in [0, 360), right-handed about the axis).
    pub angle_deg: f64,
    /// Position from the reference origin, body axes (m) — the scene file's `at`.
    pub at_b: Vector3<f64>,
}

/// The balance of a scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Balance {
    /// The masses for planes A and B.
    pub corrections: [Correction; 2],
    /// The body direction angles are measured from: the body axis most nearly across the rotation axis, made
    /// perpendicular to it.
    pub reference_b: Vector3<f64>,
    /// Its name, e.g. "body x".
    pub reference_name: &'static str,
    /// The rate the reactions below are computed at (rad/s): the scene's initial rate, or 1 when that is 0.
    pub rate: f64,
    /// The largest rotating bearing reaction (N) before and after balancing, at `rate` without effects.
    pub largest_reaction: [f64; 2],
    /// The scene with the correction masses added.
    pub balanced: SceneSpec,
}

/// Why a scene cannot be balanced.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BalanceError {
    /// The scene itself is invalid.
    #[error(transparent)]
    Scene(#[from] InvalidScene),
    /// The scene or the planes do not allow balancing.
    #[error("{0}")]
    Unbalanceable(String),
}

impl Balance {
    /// What `eulerdyn balance` prints: the reference direction, each plane's mass (g) and angle (deg, in
    /// [0, 360)) and where it goes, and the largest rotating bearing reaction before and after.
    pub fn report(&self) -> String {
        let mut text = String::new();
        let r = &self.reference_b;
        text += &format!(
            "angles about the axis from {} across it: ({:.6}, {:.6}, {:.6}) in body axes\n",
            self.reference_name, r.x, r.y, r.z
        );
        for (name, c) in ["A", "B"].iter().zip(&self.corrections) {
            text += &super::format::correction_line(name, c.z, (c.mass, c.angle_deg), &c.at_b);
        }
        text += &format!(
            "largest rotating bearing reaction at {} rad/s without effects: {:.6e} N before, {:.6e} N after\n",
            self.rate, self.largest_reaction[0], self.largest_reaction[1]
        );
        text
    }

    /// The balanced scene as a scene file (TOML), with a header line saying where it came from.
    pub fn balanced_toml(&self) -> Result<String, String> {
        let text =
            toml::to_string(&self.balanced).map_err(|e| format!("cannot write the scene: {e}"))?;
        Ok(format!(
            "# Written by `eulerdyn balance`: the scene with its two correction masses ([[body.point_mass]]).\n{text}"
        ))
    }
}

/// The correction masses of `spec` (a fixed-axis or hinge scene) in `planes`.
///
/// ```
/// use eulerdyn::analysis::balance::{Planes, balance};
/// use eulerdyn::scene::{BodySpec, FixedAxisSpec, SceneSpec, ShapeSpec};
/// let disk = SceneSpec::new(BodySpec::shape(2.0, ShapeSpec::thin_disk(0.3)), 1.0, 0.1)
///     .with_motion(FixedAxisSpec::tilted(30.0, 10.0).with_bearings(-0.1, 0.15));
/// let result = balance(&disk, &Planes { a: -0.1, b: 0.1, radius: 0.2 }).unwrap();
/// // The notes' skewed disk: two equal masses ¼ m R² sin θ cos θ / (R_c (b − a)) on opposite sides.
/// let expected = 0.25 * 2.0 * 0.09 * 0.5 * 0.75f64.sqrt() / (0.2 * 0.2);
/// assert!((result.corrections[0].mass - expected).abs() < 1e-12);
/// assert!(result.largest_reaction[1] < 1e-9 * result.largest_reaction[0]);
/// ```
pub fn balance(spec: &SceneSpec, planes: &Planes) -> Result<Balance, BalanceError> {
    let rotor = Rotor::new(spec, planes)?;
    let [v_a, v_b] = rotor.plane_vectors();
    let corrections = [
        rotor.correction(planes.a, v_a),
        rotor.correction(planes.b, v_b),
    ];
    rotor.apply(spec, corrections)
}

/// A fixed-axis or hinge scene with its correction planes: where the masses go and how their angles are measured.
#[derive(Debug, Clone)]
pub(crate) struct Rotor {
    /// The scene's axis (its motion, at the scene's rate).
    pub axis: FixedAxis,
    /// The correction planes and radius, checked.
    pub planes: Planes,
    /// The unit axis, body axes.
    pub u_b: Vector3<f64>,
    /// The body direction angles are measured from, across the axis, and its name.
    pub reference_b: Vector3<f64>,
    pub reference_name: &'static str,
    /// The axis point from the reference origin, body axes: the origin of the planes' positions.
    pub origin_b: Vector3<f64>,
    /// The scene's body (its shape and point masses: how far the rotor reaches).
    pub body: BodySpec,
}

impl Rotor {
    /// Checks the planes (A ≠ B, finite; R > 0) and that the scene turns about an axis.
    pub fn new(spec: &SceneSpec, planes: &Planes) -> Result<Self, BalanceError> {
        let refuse = |why: &str| Err(BalanceError::Unbalanceable(why.to_string()));
        if !(planes.a.is_finite() && planes.b.is_finite()) || planes.a == planes.b {
            return refuse(
                "the planes must be two different finite positions along the axis (A != B)",
            );
        }
        if !(planes.radius.is_finite() && planes.radius > 0.0) {
            return refuse("the radius must be a finite number > 0 (m)");
        }
        let scene = spec.build()?;
        let Some(axis) = scene.motion.axis() else {
            return refuse(
                "balancing needs an axis: the scene's motion must be a fixed_axis or a hinge (a free body has no bearings)",
            );
        };
        let u_b = axis.axis_b().into_inner();
        let (reference_b, reference_name) = reference_direction(&u_b);
        Ok(Self {
            axis: axis.clone(),
            planes: *planes,
            u_b,
            reference_b,
            reference_name,
            origin_b: *axis.point_b() + scene.center_b,
            body: spec.body.clone(),
        })
    }

    /// The vectors v_A, v_B = m_i r_i (kg·m, body axes) of the two masses that cancel the static imbalance s
    /// and the dynamic imbalance d: v_B = (d + z_A s)/(z_B − z_A), v_A = −s − v_B (module doc).
    pub fn plane_vectors(&self) -> [Vector3<f64>; 2] {
        let (s, d) = self.axis.imbalance();
        let (s, d) = (s.into_inner(), d.into_inner());
        let Planes { a, b, .. } = self.planes;
        let v_b = (d + s * a) / (b - a);
        let v_a = -s - v_b;
        // Tiny vectors are round-off of a balanced rotor.
        let negligible = 1e-14 * (s.norm() + d.norm() / a.abs().max(b.abs()));
        [v_a, v_b].map(|v| {
            if v.norm() <= negligible {
                Vector3::zeros()
            } else {
                v
            }
        })
    }

    /// The correction m r = `v` (kg·m) in the plane at `z`: mass |v|/R at R along v (0 for a zero `v`).
    pub fn correction(&self, z: f64, v: Vector3<f64>) -> Correction {
        let radius = self.planes.radius;
        if v.norm() == 0.0 {
            return self.correction_at(z, 0.0, 0.0);
        }
        let r_b = v.normalize() * radius;
        self.correction_at(z, v.norm() / radius, self.angle_of(&r_b))
    }

    /// A mass `mass` (kg) in the plane at `z`, at the radius R and `angle` (rad) about the axis from the
    /// reference direction.
    pub fn correction_at(&self, z: f64, mass: f64, angle: f64) -> Correction {
        let across =
            self.reference_b * angle.cos() + self.u_b.cross(&self.reference_b) * angle.sin();
        Correction {
            z,
            mass,
            angle_deg: super::format::wrap_deg(angle.to_degrees()),
            at_b: self.origin_b + self.u_b * z + across * self.planes.radius,
        }
    }

    /// The angle (rad) of a vector `r_b` across the axis, right-handed about it from the reference direction.
    pub fn angle_of(&self, r_b: &Vector3<f64>) -> f64 {
        self.u_b
            .dot(&self.reference_b.cross(r_b))
            .atan2(self.reference_b.dot(r_b))
    }

    /// `spec` with the `corrections` added as point masses (those with a mass), and the largest rotating bearing
    /// reaction before and after.
    pub fn apply(
        &self,
        spec: &SceneSpec,
        corrections: [Correction; 2],
    ) -> Result<Balance, BalanceError> {
        let mut balanced = spec.clone();
        for c in corrections.iter().filter(|c| c.mass > 0.0) {
            (balanced.body.point_mass).push(PointMassSpec::of(c.mass, c.at_b.into()));
        }
        let bearings = self.axis.bearings().copied().unwrap_or(Bearings {
            a: self.planes.a,
            b: self.planes.b,
        });
        let rate = if self.axis.rate() == 0.0 {
            1.0
        } else {
            self.axis.rate()
        };
        let after = Rotor::new(&balanced, &self.planes)?;
        Ok(Balance {
            corrections,
            reference_b: self.reference_b,
            reference_name: self.reference_name,
            rate,
            largest_reaction: [
                rotating_reaction(&self.axis, &bearings, rate),
                rotating_reaction(&after.axis, &bearings, rate),
            ],
            balanced,
        })
    }
}

/// The body axis most nearly across `u_b`, made perpendicular to it, and its name.
fn reference_direction(u_b: &Vector3<f64>) -> (Vector3<f64>, &'static str) {
    let names = ["body x", "body y", "body z"];
    let k = (0..3)
        .min_by(|&i, &j| u_b[i].abs().total_cmp(&u_b[j].abs()))
        .unwrap_or(0);
    let e = Vector3::ith(k, 1.0);
    let across = Unit::new_normalize(e - u_b * e.dot(u_b));
    (across.into_inner(), names[k])
}

/// The larger of |R_A|, |R_B| for rotation at the constant `rate` (rad/s) about the axis, without effects: the
/// rotating (speed-dependent) reaction.
fn rotating_reaction(axis: &FixedAxis, bearings: &Bearings, rate: f64) -> f64 {
    let spin = FixedAxis::new_like(axis, rate).with_bearings(*bearings);
    let loads = spin.sample(0.0, crate::Form::Body).support;
    loads
        .and_then(|l| l.bearings)
        .map_or(0.0, |b| b.r_a_s.norm().max(b.r_b_s.norm()))
}
