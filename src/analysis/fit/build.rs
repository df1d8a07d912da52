//! The scene at a parameter point: the scene's own file with the inertia, ω₀ and q₀ replaced, validated as `run`
//! validates it (with the user's laws added back), so that its effects (a pivot's gravity, an orbit's gradient, a law) act on the fitted body as
//! they would in a run. Also the fitted scene `-o` writes.

use nalgebra::{DVector, Matrix3, UnitQuaternion, Vector3};

use super::FitError;
use super::model::{Column, Model, Moments};
use super::params::Parameters;
use crate::effects::{Effect, EffectMoments};
use crate::method::Method;
use crate::scene::{
    AttitudeSpec, Distribution, InertiaSpec, InitialSpec, Overrides, Scene, SceneSpec,
};

/// The relative size of the inertia's step across which a moment that depends on the inertia is differenced.
const STEP: f64 = 6e-6;

/// Builds the model at any x from the scene's file.
#[derive(Debug, Clone)]
pub struct Builder {
    spec: SceneSpec,
    /// The user's laws ([`Scene::with_moment`]), which no scene file holds: added to every scene built.
    laws: Vec<Effect>,
    /// Whether an effect's moment depends on the inertia (the gravity gradient).
    uses_inertia: bool,
}

impl Builder {
    /// The builder of `scene`: a free rigid body, without rotors or a changing shape (what the model integrates).
    pub fn new(scene: &Scene) -> Result<Self, FitError> {
        let refuse = |what: &str| {
            Err(FitError::Input(format!(
                "{}: fit models a free rigid body; this scene {what}",
                scene_name(scene)
            )))
        };
        let Some(free) = scene.motion.free() else {
            return refuse("prescribes a motion about an axis ([motion] type)");
        };
        if free.gyrostat.is_some() {
            return refuse("has rotors ([[body.rotor]]), which fit does not model yet");
        }
        if free.shape_change.is_some() {
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

    /// The model at x; `Err` when its inertia is not positive definite. An inertia that no mass distribution has
    /// (the triangle inequality broken) is still a model: the scene's effects are then those at the scene's own
    /// inertia, unless one depends on the inertia (then `Err`); whether the fit's end is a body is judged apart.
    pub fn model(&self, params: &Parameters, x: &DVector<f64>) -> Result<Model, String> {
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
        Ok(Model {
            body,
            moments,
            omega0_b: omega0,
            q0,
            columns,
        })
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
}

/// The scene's file, or its name, for messages.
pub fn scene_name(scene: &Scene) -> String {
    match &scene.source {
        Some(source) => source.path.display().to_string(),
        None if !scene.name.is_empty() => scene.name.clone(),
        None => "the scene".into(),
    }
}
