//! `score --diagnose`: what an engine's error is consistent with. The trajectory is made again by eulerdyn's own
//! fixed-step models of what game and robotics engines do, at its row step Δt and at 2, 4 and 8 substeps a row, from
//! the scene's initial state; the model whose attitude comes closest (the largest angle over the rows) is named, a
//! `match` within [`MATCH_RAD`]. The faults the models cover are those of the bug reports behind `score`: the
//! gyroscopic term left out or its sign flipped, ω held in the wrong axes, an explicit step where a semi-implicit one
//! was meant. With f(ω_b) = I⁻¹ (M_b − g ω_b × I ω_b), g = 1 (`full`), 0 (`none`), −1 (`flipped`), R = R(q):
//!
//! ```text
//!   explicit_euler       ω⁺ = ω + h ω̇;   q⁺ = normalise(q + h/2 (0, R ω_b) ⊗ q)    with the old ω
//!   semi_implicit_euler  ω⁺ = ω + h ω̇;   q⁺ = normalise(q + h/2 (0, R ω⁺_b) ⊗ q)   with the new ω
//!   rk4                  (q, ω) as one system, q̇ = ½ q ⊗ (0, ω_b), q normalised after each step only
//!   axes                 body: ω_b held, ω̇_b = f(ω_b);   world: ω_w held, ω̇_w = R f(Rᵀ ω_w)
//! ```
//!
//! The Euler models also turn q by the exponential map, q⁺ = exp(h/2 (0, ω_w)) ⊗ q (the turn by |ω| h about ω, as
//! MuJoCo's `mju_quatIntegrate` does), which the contract's normalised update approximates to O((|ω| h)³) a step.
//! (0, ω_w) ⊗ q = q ⊗ (0, ω_b). Semi-implicit Euler takes the same steps in both axes: q turns about the new ω, which
//! the turn leaves unchanged; either may be named for it.

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};

use super::ScoreError;
use super::reader::TheirRow;
use crate::analysis::compare::attitude_angle;
use crate::effects::{AppliedMoment, EffectMoments};
use crate::scene::Scene;

/// A model within this largest attitude angle (rad) over the run is a `match`: far above the round-off of a few
/// thousand steps (1e-13), far below any difference between two models of the family.
pub const MATCH_RAD: f64 = 1e-6;

/// The substeps a row the models take.
pub const SUBSTEPS: [u32; 4] = [1, 2, 4, 8];

/// How a model steps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stepper {
    /// ω and q both from step n.
    ExplicitEuler,
    /// ω first, then q with the new ω.
    SemiImplicitEuler,
    /// Classical Runge–Kutta on (q, ω).
    Rk4,
}

/// The axes a model holds ω in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum HeldAxes {
    /// ω in space axes.
    World,
    /// ω in body axes.
    Body,
}

/// The gyroscopic term ω × Iω of a model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Gyroscopic {
    /// As Euler's equation has it.
    Full,
    /// Left out.
    None,
    /// Its sign changed.
    Flipped,
}

/// How an Euler model turns its attitude by ω over a step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AttitudeUpdate {
    /// q ← normalise(q + h/2 (0, ω_w) ⊗ q), the contract's (and RK4's: q normalised after its step).
    Normalised,
    /// q ← exp(h/2 (0, ω_w)) ⊗ q: the turn by the angle |ω| h about ω (MuJoCo's `mju_quatIntegrate`).
    Exponential,
}

/// One model of an engine's step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub struct Model {
    /// How it steps.
    pub method: Stepper,
    /// The axes ω is held in.
    pub axes: HeldAxes,
    /// Its gyroscopic term.
    pub gyroscopic: Gyroscopic,
    /// Steps a row.
    pub substeps: u32,
    /// How the attitude turns (an Euler model's; RK4's is `normalised`).
    pub attitude_update: AttitudeUpdate,
}

impl Model {
    /// Every model of the family: 3 methods × 2 axes × 3 gyroscopic terms × [`SUBSTEPS`], the two Euler methods
    /// with either attitude update.
    ///
    /// ```
    /// assert_eq!(eulerdyn::analysis::score::diagnose::Model::all().len(), 120);
    /// ```
    pub fn all() -> Vec<Model> {
        let methods = [
            Stepper::ExplicitEuler,
            Stepper::SemiImplicitEuler,
            Stepper::Rk4,
        ];
        let terms = [Gyroscopic::Full, Gyroscopic::None, Gyroscopic::Flipped];
        let mut all = Vec::new();
        for method in methods {
            for axes in [HeldAxes::World, HeldAxes::Body] {
                for gyroscopic in terms {
                    for substeps in SUBSTEPS {
                        let updates: &[AttitudeUpdate] = match method {
                            Stepper::Rk4 => &[AttitudeUpdate::Normalised],
                            _ => &[AttitudeUpdate::Normalised, AttitudeUpdate::Exponential],
                        };
                        all.extend(updates.iter().map(|&attitude_update| Model {
                            method,
                            axes,
                            gyroscopic,
                            substeps,
                            attitude_update,
                        }));
                    }
                }
            }
        }
        all
    }

    /// The model in words: "semi-implicit Euler in world axes, gyroscopic term left out, 1 substep".
    pub fn describe(&self) -> String {
        let method = match self.method {
            Stepper::ExplicitEuler => "explicit Euler",
            Stepper::SemiImplicitEuler => "semi-implicit Euler",
            Stepper::Rk4 => "RK4",
        };
        let axes = match self.axes {
            HeldAxes::World => "world",
            HeldAxes::Body => "body",
        };
        let term = match self.gyroscopic {
            Gyroscopic::Full => "full gyroscopic term",
            Gyroscopic::None => "gyroscopic term left out",
            Gyroscopic::Flipped => "gyroscopic term with its sign flipped",
        };
        let plural = if self.substeps == 1 { "" } else { "s" };
        let update = match self.attitude_update {
            AttitudeUpdate::Normalised => "",
            AttitudeUpdate::Exponential => ", attitude turned by the exponential map",
        };
        format!(
            "{method} in {axes} axes, {term}, {} substep{plural}{update}",
            self.substeps
        )
    }
}

/// A model and how far its attitude comes from the trajectory's.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Candidate {
    /// The model.
    #[serde(flatten)]
    pub model: Model,
    /// The largest attitude angle between the model and the trajectory over the rows (rad; +∞ when the model
    /// diverged).
    pub distance_rad: f64,
}

/// Whether the closest model reproduces the trajectory.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// Within [`MATCH_RAD`].
    Match,
    /// The closest of the family, farther than [`MATCH_RAD`].
    Nearest,
}

/// What the trajectory is consistent with.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Diagnosis {
    /// The closest model.
    pub closest: Model,
    /// Its distance (rad).
    pub distance_rad: f64,
    /// `match` or `nearest`.
    pub verdict: Verdict,
    /// Every model, closest first.
    pub candidates: Vec<Candidate>,
}

impl Diagnosis {
    /// The diagnosis in a line; a match says how many other models are within [`MATCH_RAD`] too (without the
    /// gyroscopic term, explicit and semi-implicit Euler move a torque-free body alike).
    pub fn line(&self) -> String {
        let others = (self.candidates.iter().skip(1))
            .filter(|c| c.distance_rad <= MATCH_RAD)
            .count();
        let also = match others {
            0 => String::new(),
            1 => format!("; 1 other model within {MATCH_RAD:e} rad too"),
            n => format!("; {n} other models within {MATCH_RAD:e} rad too"),
        };
        match self.verdict {
            Verdict::Match => format!(
                "diagnosis: consistent with {} (largest attitude difference {:.1e} rad: match{also})",
                self.closest.describe(),
                self.distance_rad
            ),
            Verdict::Nearest => format!(
                "diagnosis: nearest model {}, {:.2e} rad from the trajectory (none within {MATCH_RAD:e} rad)",
                self.closest.describe(),
                self.distance_rad
            ),
        }
    }
}

/// The models' body: its inertia about the moment center and the scene's applied moment.
struct Body {
    inertia_b: Matrix3<f64>,
    inverse_b: Matrix3<f64>,
    moments: EffectMoments,
}

/// A model's state: the attitude and ω in the model's axes.
#[derive(Debug, Clone, Copy)]
struct State {
    q: Quaternion<f64>,
    omega: Vector3<f64>,
}

impl Body {
    /// ω_b of ω held in `axes` at the attitude q.
    fn omega_b(axes: HeldAxes, q: &UnitQuaternion<f64>, omega: &Vector3<f64>) -> Vector3<f64> {
        match axes {
            HeldAxes::Body => *omega,
            HeldAxes::World => q.inverse_transform_vector(omega),
        }
    }

    /// The rate of ω held in the model's axes: f(ω_b), or R f(Rᵀ ω_w).
    fn omega_rate(
        &self,
        model: &Model,
        t: f64,
        q: &UnitQuaternion<f64>,
        omega: &Vector3<f64>,
    ) -> Vector3<f64> {
        let g = match model.gyroscopic {
            Gyroscopic::Full => 1.0,
            Gyroscopic::None => 0.0,
            Gyroscopic::Flipped => -1.0,
        };
        let omega_b = Self::omega_b(model.axes, q, omega);
        let m_b = self.moments.moment_b(t, q, &omega_b);
        let rate_b = self.inverse_b * (m_b - g * omega_b.cross(&(self.inertia_b * omega_b)));
        match model.axes {
            HeldAxes::Body => rate_b,
            HeldAxes::World => q.transform_vector(&rate_b),
        }
    }

    /// (q̇, ω̇) of the system RK4 integrates: q̇ = ½ q ⊗ (0, ω_b) with q as it is, the rotation from q normalised.
    fn rates(&self, model: &Model, t: f64, y: &State) -> State {
        let unit = UnitQuaternion::new_normalize(y.q);
        let omega_b = Self::omega_b(model.axes, &unit, &y.omega);
        State {
            q: y.q * Quaternion::from_imag(omega_b) * 0.5,
            omega: self.omega_rate(model, t, &unit, &y.omega),
        }
    }

    /// One step of `model` of length h from `y` at t (module doc).
    fn step(&self, model: &Model, t: f64, h: f64, y: &State) -> State {
        if model.method == Stepper::Rk4 {
            let at = |k: &State, scale: f64| State {
                q: y.q + k.q * scale,
                omega: y.omega + k.omega * scale,
            };
            let k1 = self.rates(model, t, y);
            let k2 = self.rates(model, t + h / 2.0, &at(&k1, h / 2.0));
            let k3 = self.rates(model, t + h / 2.0, &at(&k2, h / 2.0));
            let k4 = self.rates(model, t + h, &at(&k3, h));
            let q = y.q + (k1.q + (k2.q + k3.q) * 2.0 + k4.q) * (h / 6.0);
            let omega = y.omega + (k1.omega + (k2.omega + k3.omega) * 2.0 + k4.omega) * (h / 6.0);
            return State {
                q: q.normalize(),
                omega,
            };
        }
        let unit = UnitQuaternion::new_normalize(y.q);
        let omega = y.omega + self.omega_rate(model, t, &unit, &y.omega) * h;
        let turning = match model.method {
            Stepper::ExplicitEuler => y.omega,
            _ => omega,
        };
        let omega_w = match model.axes {
            HeldAxes::World => turning,
            HeldAxes::Body => unit.transform_vector(&turning),
        };
        let q = match model.attitude_update {
            AttitudeUpdate::Normalised => {
                (y.q + Quaternion::from_imag(omega_w) * y.q * (h / 2.0)).normalize()
            }
            AttitudeUpdate::Exponential => {
                *(UnitQuaternion::from_scaled_axis(omega_w * h) * unit).quaternion()
            }
        };
        State { q, omega }
    }

    /// The model's attitude at the rows k·Δt of `ks` (ascending), from q0 and ω0_b at t = 0.
    fn attitudes(
        &self,
        model: &Model,
        start: (&UnitQuaternion<f64>, &Vector3<f64>),
        dt: f64,
        ks: &[u64],
    ) -> Vec<Quaternion<f64>> {
        let (q0, omega0_b) = start;
        let omega = match model.axes {
            HeldAxes::Body => *omega0_b,
            HeldAxes::World => q0.transform_vector(omega0_b),
        };
        let mut y = State {
            q: *q0.quaternion(),
            omega,
        };
        let h = dt / f64::from(model.substeps);
        let mut k_now = 0;
        let mut out = Vec::with_capacity(ks.len());
        for &k in ks {
            while k_now < k {
                for j in 0..model.substeps {
                    let t = (k_now as f64) * dt + f64::from(j) * h;
                    y = self.step(model, t, h, &y);
                }
                k_now += 1;
            }
            out.push(y.q);
        }
        out
    }
}

/// The largest angle between the model's attitudes and the rows' (+∞ when the model diverged).
fn distance(model_q: &[Quaternion<f64>], rows: &[TheirRow]) -> f64 {
    let mut largest: f64 = 0.0;
    for (q, row) in model_q.iter().zip(rows) {
        let angle = attitude_angle(&UnitQuaternion::new_unchecked(*q), &row.q);
        if !angle.is_finite() {
            return f64::INFINITY;
        }
        largest = largest.max(angle);
    }
    largest
}

/// The diagnosis of their `rows` (times on the grid k·`dt`) against the scene: every model run from the scene's
/// initial state, the closest first. Only a free rigid body (no wheels) is modelled.
pub fn diagnose(scene: &Scene, rows: &[TheirRow], dt: f64) -> Result<Diagnosis, ScoreError> {
    let (omega0_b, body) = scene.motion.rigid_free().ok_or_else(|| {
        ScoreError::Input(format!(
            "--diagnose: scene \"{}\" is not a free rigid body; the engine models step a free body (with the \
             scene's effects) only",
            scene.name
        ))
    })?;
    let inertia_b = *body.inertia_b();
    let model_body = Body {
        inertia_b,
        inverse_b: *body.inertia_inv_b(),
        moments: EffectMoments::new(&scene.effects, scene.body.mass()),
    };
    let ks: Vec<u64> = rows.iter().map(|r| (r.t / dt).round() as u64).collect();
    let start = (&scene.attitude0, &**omega0_b);
    let mut candidates: Vec<Candidate> = (Model::all().into_iter())
        .map(|model| Candidate {
            model,
            distance_rad: distance(&model_body.attitudes(&model, start, dt, &ks), rows),
        })
        .collect();
    candidates.sort_by(|a, b| a.distance_rad.total_cmp(&b.distance_rad));
    let closest = candidates[0];
    Ok(Diagnosis {
        closest: closest.model,
        distance_rad: closest.distance_rad,
        verdict: if closest.distance_rad <= MATCH_RAD {
            Verdict::Match
        } else {
            Verdict::Nearest
        },
        candidates,
    })
}
