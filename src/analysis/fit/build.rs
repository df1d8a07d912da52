//! The scene at a parameter point: the scene's own file with the inertia, ω₀ and q₀ replaced, validated as `run`
//! validates it (the user's laws and the wheels' law added back), so that its effects (a pivot's gravity, an orbit's
//! gradient, a law) and wheels act on the fitted body as they would in a run. Also the fitted scene `-o` writes.

use nalgebra::{DVector, Matrix3, UnitQuaternion, Vector3};

use super::FitError;
use super::model::{Column, Model, Moments, Point};
use super::params::Parameters;
use super::wheels::{GyrostatModel, GyrostatSystem, inertia_step};
use crate::effects::{Effect, EffectMoments};
use crate::method::Method;
use crate::scene::{
    AttitudeSpec, Distribution, InertiaSpec, InitialSpec, Overrides, Scene, SceneSpec,
};
use crate::wheels::gyrostat::Gyrostat;

/// The relative size of the inertia's step across which a moment that depends on the inertia is differenced.
const STEP: f64 = 6e-6;

/// The model at a parameter point: the free body's ([`Model`]), or its wheels' ([`GyrostatModel`]) with its start
/// and columns.
#[derive(Debug, Clone)]
pub struct Dynamics {
    /// The free body, its start and the parameters' columns.
    pub model: Model,
    /// The body's wheels, when it has any: then the motion is theirs.
    pub wheels: Option<GyrostatModel>,
}

impl Dynamics {
    /// The motion and its sensitivities at `times` ([`Model::solve`], [`GyrostatModel::solve`]).
    pub fn solve(&self, times: &[f64]) -> Result<Vec<Point>, String> {
        match &self.wheels {
            Some(wheels) => wheels.solve(&self.model, times),
            None => self.model.solve(times),
        }
    }
}

/// Builds the model at any x from the scene's file.
#[derive(Debug, Clone)]
pub struct Builder {
    spec: SceneSpec,
    /// The user's laws ([`Scene::with_moment`]), which no scene file holds: added to every scene built.
    laws: Vec<Effect>,
    /// Whether an effect's moment depends on the inertia (the gravity gradient).
    uses_inertia: bool,
    /// The scene's body with its wheels, when it has any, with their law ([`Scene::with_wheel_law`]), which no
    /// scene file holds either.
    gyrostat: Option<Gyrostat>,
}

impl Builder {
    /// The builder of `scene`: a free body (with wheels or not), not changing shape (what the models integrate).
    pub fn new(scene: &Scene) -> Result<Self, FitError> {
        let refuse = |what: &str| {
            Err(FitError::Input(format!(
                "{}: fit models a free body (with or without wheels); this scene {what}",
                scene_name(scene)
            )))
        };
        let Some(free) = scene.motion.free() else {
            return refuse("prescribes a motion about an axis ([motion] type)");
        };
        if free.attribute.is_some() && free.gyrostat.is_none() {
            return refuse("changes shape ([[body.moving_mass]] or inertia_table)");
        }
        Ok(Self {
            spec: scene.spec.clone(),
            laws: scene
                .effects
                .iter()
                .filter(|e| e.is_user())
                .cloned()
                .collect(),
            uses_inertia: scene.effects.iter().any(|e| e.uses_mass_distribution()),
            gyrostat: free.gyrostat.cloned(),
        })
    }

    /// The scene's file with I about C, ω₀ (body axes) and q₀ replaced.
    pub fn spec_at(
        &self,
        inertia: &Matrix3<f64>,
        omega0: &Vector3<f64>,
        q0: &UnitQuaternion<f64>,
    ) -> SceneSpec {
        let mut spec = self.spec.clone();
        let diagonal = (0..3).all(|r| (0..3).all(|c| r == c || inertia[(r, c)] == 0.0));
        spec.body.distribution = Distribution::Inertia(if diagonal {
            InertiaSpec::Principal([inertia[(0, 0)], inertia[(1, 1)], inertia[(2, 2)]])
        } else {
            InertiaSpec::Full(std::array::from_fn(|r| {
                std::array::from_fn(|c| inertia[(r, c)])
            }))
        });
        spec.initial = Some(InitialSpec {
            omega: Some((*omega0).into()),
            attitude: Some(AttitudeSpec::Quaternion([q0.w, q0.i, q0.j, q0.k])),
            omega_lvlh: None,
        });
        spec
    }

    /// The validated scene at (I, ω₀, q₀), run by dop853 (the scene's own method does not matter here).
    fn scene_at(
        &self,
        inertia: &Matrix3<f64>,
        omega0: &Vector3<f64>,
        q0: &UnitQuaternion<f64>,
    ) -> Result<Scene, String> {
        let overrides = Overrides {
            method: Some(Method::Dop853),
            ..Overrides::default()
        };
        let mut scene = (self.spec_at(inertia, omega0, q0).build_with(&overrides))
            .map_err(|e| e.to_string())?;
        scene.effects.extend(self.laws.iter().cloned());
        Ok(scene)
    }

    /// The dynamics at x; `Err` when its inertia is not positive definite. An inertia that no mass distribution has
    /// (the triangle inequality broken) is still a model: the scene's effects are then those at the scene's own
    /// inertia, unless one depends on the inertia (then `Err`); whether the fit's end is a body is judged apart.
    pub fn model(&self, params: &Parameters, x: &DVector<f64>) -> Result<Dynamics, String> {
        let inertia = params.inertia(x);
        let (omega0, q0) = (params.omega0(x), params.q0(x));
        let scene = match self.scene_at(&inertia, &omega0, &q0) {
            Ok(scene) => scene,
            Err(e) if self.uses_inertia => return Err(e),
            Err(_) => self.scene_at(&params.inertia0, &omega0, &q0)?,
        };
        let free = scene.motion.free().expect("checked free");
        let body = (free.body.with_inertia_c(&inertia)).map_err(|e| e.to_string())?;
        let (columns, _) = params.columns(x);
        let wheels = match free.gyrostat {
            None => None,
            Some(_) => Some(self.wheels(&scene, &inertia, &columns, (&omega0, &q0))?),
        };
        let moments = match scene.effects.is_empty() {
            true => None,
            false => Some(Moments {
                at: EffectMoments::new(&scene.effects, scene.body.mass()),
                across: (columns.iter())
                    .map(|c| match c {
                        Column::Inertia(e) if self.uses_inertia => {
                            self.across(&inertia, e, &omega0, &q0).map(Some)
                        }
                        _ => Ok(None),
                    })
                    .collect::<Result<_, _>>()?,
            }),
        };
        let model = Model {
            body,
            moments,
            omega0_b: omega0,
            q0,
            columns,
        };
        Ok(Dynamics { model, wheels })
    }

    /// The moments at I ± δE and 2δ.
    fn across(
        &self,
        inertia: &Matrix3<f64>,
        e: &Matrix3<f64>,
        omega0: &Vector3<f64>,
        q0: &UnitQuaternion<f64>,
    ) -> Result<(EffectMoments, EffectMoments, f64), String> {
        let delta = STEP * inertia.norm() / e.norm();
        let at = |i: Matrix3<f64>| {
            self.scene_at(&i, omega0, q0)
                .map(|s| EffectMoments::new(&s.effects, s.body.mass()))
        };
        Ok((
            at(inertia + e * delta)?,
            at(inertia - e * delta)?,
            2.0 * delta,
        ))
    }

    /// The scene's wheels on its body with the inertia about C replaced by `inertia` (positive definite, a
    /// body's or not), their law put back, and the moments: `scene`'s, or for a moment that depends on the inertia
    /// those of the scene built at `inertia`.
    fn wheel_system(
        &self,
        scene: &Scene,
        inertia: &Matrix3<f64>,
        (omega0, q0): (&Vector3<f64>, &UnitQuaternion<f64>),
    ) -> Result<GyrostatSystem, String> {
        let wheels = self.gyrostat.as_ref().expect("a body with wheels");
        let body = (wheels.body().with_inertia_c(inertia)).map_err(|e| e.to_string())?;
        let gyrostat = Gyrostat::new(body, wheels.rotors().to_vec()).map_err(|e| e.to_string())?;
        let gyrostat = match wheels.law() {
            Some(law) => gyrostat.with_law(law.clone()).map_err(|e| e.to_string())?,
            None => gyrostat,
        };
        let moments = match self.uses_inertia {
            false => EffectMoments::new(&scene.effects, scene.body.mass()),
            true => {
                let at = self.scene_at(inertia, omega0, q0)?;
                EffectMoments::new(&at.effects, at.body.mass())
            }
        };
        Ok(GyrostatSystem { gyrostat, moments })
    }

    /// The wheels' model at (I, ω₀, q₀) on `scene`'s wheels, and at I ± δE for each column that moves the inertia.
    fn wheels(
        &self,
        scene: &Scene,
        inertia: &Matrix3<f64>,
        columns: &[Column],
        start: (&Vector3<f64>, &UnitQuaternion<f64>),
    ) -> Result<GyrostatModel, String> {
        let at = |i: Matrix3<f64>| self.wheel_system(scene, &i, start);
        let across = (columns.iter())
            .map(|c| match c {
                Column::Inertia(e) => {
                    let delta = inertia_step(inertia, e);
                    Ok(Some((
                        at(inertia + e * delta)?,
                        at(inertia - e * delta)?,
                        2.0 * delta,
                    )))
                }
                _ => Ok(None),
            })
            .collect::<Result<_, String>>()?;
        Ok(GyrostatModel {
            at: at(*inertia)?,
            across,
        })
    }
}

/// The scene's file, or its name, for messages.
pub fn scene_name(scene: &Scene) -> String {
    match &scene.source {
        Some(source) => source.path.display().to_string(),
        None if !scene.name.is_empty() => scene.name.clone(),
        None => "the scene".into(),
    }
}
