//! Warnings about input that would make a balancing verdict wrong with confidence, most often a unit slip: trial
//! masses written in kg in the table's `trial_mass_g` column, planes or a radius given in mm. Each warning names
//! the likely slip; after any, the grade's verdicts read `unverified`.
//!
//! - The fitted influence coefficients against the rigid-rotor model's (readings that are bearing forces in N,
//!   `--readings force`): for each plane j the column α_j is compared with the model's α̂_j
//!   ([`rigid_rotor_coefficients`](super::influence::rigid_rotor_coefficients) at the runs' speed) by the amplitude
//!   ratio |α_j|/|α̂_j| and the phase arg(α̂_jᴴ α_j); beyond a factor [`AMPLITUDE_LIMIT`] or [`PHASE_LIMIT_DEG`]
//!   they disagree. A trial mass in kg makes α 1000 × too large (α = ΔV/T).
//! - The initial unbalance outside every grade ISO 21940-11 lists (finer than G 0.4 or coarser than G 4000 at the
//!   service speed, 6.3.1 Table 1), whatever the readings are.
//! - A correction plane outside the bearings by more than their span, or a radius beyond the rotor's reach from
//!   the axis.
//! - A grade asked for with a measured table but no `--service-rpm`: the grade was judged at the scene's rate, and a
//!   rotor measured at one speed (often a balancing machine's) is graded at its maximum service speed. U_per ∝ 1/Ω
//!   (ISO 21940-11, 6.3.3), so at ten times the speed the same unbalance meets a grade ten times coarser.

use nalgebra::{Matrix2, Vector3};

use crate::body::Shape;
use crate::scene::Distribution;

use super::format::{angle_text, sig};
use super::influence::{self, Phasor};
use super::iso::{Assessment, STANDARD_GRADES};
use super::model::Rotor;
use super::{Influence, Request, Source};

/// What the table's readings are (`--readings`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Readings {
    /// The 1× forces on the bearings in N: the fitted coefficients are compared with the model's.
    #[default]
    Force,
    /// Vibration in any unit: no comparison with the model.
    Other,
}

impl Readings {
    /// The word of `--readings` and of the JSON.
    pub fn name(self) -> &'static str {
        match self {
            Self::Force => "force",
            Self::Other => "other",
        }
    }
}

impl crate::named::Named for Readings {
    const ALL: &'static [Self] = &[Self::Force, Self::Other];

    fn name(&self) -> &'static str {
        Readings::name(*self)
    }
}

/// A fitted coefficient column more than this factor above or below the model's is a warning.
pub const AMPLITUDE_LIMIT: f64 = 3.0;

/// A fitted coefficient column more than this many degrees from the model's phase is a warning.
pub const PHASE_LIMIT_DEG: f64 = 45.0;

/// The warnings of `eulerdyn balance` for `request` on `rotor` (module doc): the planes and radius, the fitted
/// coefficients against the model's at the runs' speed `runs_omega`, and the initial grade in `grade`.
pub(crate) fn warnings(
    rotor: &Rotor,
    request: &Request,
    found: Option<&Influence>,
    runs_omega: Option<f64>,
    grade: Option<&Assessment>,
) -> Vec<String> {
    let mut out = geometry(rotor);
    let bearings = rotor.axis.bearings();
    if let (Some(found), Some(b), Some(omega)) = (found, bearings, runs_omega)
        && found.source == Source::Measured
        && request.readings == Readings::Force
    {
        let planes = [rotor.planes.a, rotor.planes.b];
        let model =
            influence::rigid_rotor_coefficients([b.a, b.b], planes, rotor.planes.radius, omega);
        out.extend(coefficient_slip(&found.alpha, &model, omega));
    }
    if let (Some(_), Some(grade)) = (found, grade) {
        out.extend(grade_slip(grade));
        out.extend(service_speed_slip(request, grade));
    }
    out
}

/// The warning when a grade asked for with a measured table was judged at the scene's rate (module doc).
fn service_speed_slip(request: &Request, grade: &Assessment) -> Option<String> {
    if grade.from_service_rpm || request.grade.is_none() || request.measured.is_none() {
        return None;
    }
    Some(format!(
        "the grade was judged at the scene's rate, {} rpm, for want of --service-rpm: a rotor measured at one speed \
         is graded at its maximum service speed, and at ten times the speed the same unbalance meets a grade ten \
         times coarser; give --service-rpm N for a verdict",
        sig(grade.omega * 30.0 / std::f64::consts::PI, 6)
    ))
}

/// Per plane, the fitted column against the model's: the amplitude ratio |α_j|/|α̂_j| and the phase
/// arg(α̂_jᴴ α_j) in degrees, in (−180, 180].
pub fn compare_columns(fitted: &Matrix2<Phasor>, model: &Matrix2<Phasor>) -> [(f64, f64); 2] {
    [0, 1].map(|j| {
        let (f, m) = (fitted.column(j), model.column(j));
        let projection: Phasor = m.iter().zip(f.iter()).map(|(m, f)| m.conj() * f).sum();
        (f.norm() / m.norm(), projection.arg().to_degrees())
    })
}

/// The warning when the fitted coefficients `fitted` are not the model's `model` (at `omega`, rad/s).
fn coefficient_slip(
    fitted: &Matrix2<Phasor>,
    model: &Matrix2<Phasor>,
    omega: f64,
) -> Option<String> {
    let columns = compare_columns(fitted, model);
    let agree = |(ratio, phase): (f64, f64)| {
        (1.0 / AMPLITUDE_LIMIT..=AMPLITUDE_LIMIT).contains(&ratio) && phase.abs() <= PHASE_LIMIT_DEG
    };
    if columns.iter().all(|&c| agree(c)) {
        return None;
    }
    let ratio = (columns[0].0 * columns[1].0).sqrt();
    let likely = if (300.0..3000.0).contains(&ratio) {
        "the trial masses are likely in kg instead of g (the column is trial_mass_g)"
    } else if (1.0 / 3000.0..1.0 / 300.0).contains(&ratio) {
        "the radius is likely in mm instead of m (--radius), or the trial masses in mg instead of g"
    } else {
        "the planes (--planes, m) or the radius (--radius, m) are likely in another unit, or the readings are not \
         bearing forces in N at that speed: give the runs' speed with --rpm, or --readings other for vibration"
    };
    let each: Vec<String> = columns
        .iter()
        .zip(["A", "B"])
        .map(|(&(r, p), name)| format!("plane {name} {} × at {} deg", sig(r, 3), angle_text(p)))
        .collect();
    Some(format!(
        "the influence coefficients fitted to the table are not the rigid-rotor model's for bearing forces in N at \
         {} rpm ({}; beyond {AMPLITUDE_LIMIT} × or {PHASE_LIMIT_DEG} deg): {likely}",
        sig(omega * 30.0 / std::f64::consts::PI, 6),
        each.join(", ")
    ))
}

/// The warning when the initial unbalance is outside every grade of the standard (G 0.4 to G 4000).
fn grade_slip(grade: &Assessment) -> Option<String> {
    let met = grade.met[0];
    let (finest, coarsest) = (
        STANDARD_GRADES[0],
        STANDARD_GRADES[STANDARD_GRADES.len() - 1],
    );
    let (side, likely) = if met < finest {
        (
            format!("finer than G {finest}"),
            "the trial masses are likely in kg instead of g (trial_mass_g)",
        )
    } else if met > coarsest {
        (
            format!("coarser than G {coarsest}"),
            "the radius is likely in mm instead of m (--radius), or the trial masses in mg instead of g",
        )
    } else {
        return None;
    };
    Some(format!(
        "the initial unbalance meets G {} at the service speed, {side}, outside every grade of ISO 21940-11: {likely}",
        sig(met, 3)
    ))
}

/// The warnings on the planes and the radius: a correction plane outside the bearings by more than their span
/// (likely mm for m), a radius beyond the rotor's reach from the axis.
fn geometry(rotor: &Rotor) -> Vec<String> {
    let mut out = Vec::new();
    let planes = rotor.planes;
    if let Some(b) = rotor.axis.bearings() {
        let (low, high) = (b.a.min(b.b), b.a.max(b.b));
        let span = high - low;
        for (name, z) in [("A", planes.a), ("B", planes.b)] {
            let outside = (low - z).max(z - high);
            if outside > span {
                out.push(format!(
                    "correction plane {name} at {z} m is {} m outside the bearings ({low} m to {high} m), more than \
                     their span {} m: the planes are likely in mm instead of m (--planes)",
                    sig(outside, 4),
                    sig(span, 4)
                ));
            }
        }
    }
    if let Some(reach) = reach(rotor).filter(|r| planes.radius > *r) {
        out.push(format!(
            "the correction radius {} m is beyond the rotor, which reaches {} m from the axis: the radius is likely \
             in mm instead of m (--radius)",
            planes.radius,
            sig(reach, 4)
        ));
    }
    out
}

/// How far the rotor reaches from the axis (m): its shape's bounding sphere about the shape's centre plus that
/// centre's distance from the axis, and its point masses' distances; `None` for a body given by its inertia
/// without point masses (it has no size).
fn reach(rotor: &Rotor) -> Option<f64> {
    let across = |p: Vector3<f64>| {
        let d = p - rotor.origin_b;
        (d - rotor.u_b * d.dot(&rotor.u_b)).norm()
    };
    let body = &rotor.body;
    let shape = match &body.distribution {
        Distribution::Shape(shape) => Some(bounding_radius(shape) + across(Vector3::zeros())),
        Distribution::Inertia(_) => None,
    };
    let masses = body.point_mass.iter().map(|p| across(Vector3::from(p.at)));
    shape.into_iter().chain(masses).reduce(f64::max)
}

/// The radius of the sphere about a shape's centre that holds it.
fn bounding_radius(shape: &Shape) -> f64 {
    match *shape {
        Shape::ThinDisk { radius } | Shape::Sphere { radius } => radius,
        Shape::Disk { radius, thickness } => radius.hypot(thickness / 2.0),
        Shape::Cylinder { radius, height } => radius.hypot(height / 2.0),
        Shape::ThinRod { length } => length / 2.0,
        Shape::Box { size } => Vector3::from(size).norm() / 2.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_column_1000_times_the_models_is_a_kg_for_g_slip() {
        let model = influence::rigid_rotor_coefficients([-0.4, 0.3], [-0.1, 0.08], 0.25, 157.0);
        let fitted = model * Phasor::new(1000.0, 0.0);
        let columns = compare_columns(&fitted, &model);
        for (ratio, phase) in columns {
            assert!((ratio - 1000.0).abs() < 1e-9 && phase.abs() < 1e-9);
        }
        let warning = coefficient_slip(&fitted, &model, 157.0).unwrap();
        assert!(warning.contains("in kg instead of g"), "{warning}");
        assert!(coefficient_slip(&model, &model, 157.0).is_none());
    }
}
