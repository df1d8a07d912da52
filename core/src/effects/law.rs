//! A moment law of (t, q, ω_b): a Rust type or closure that gives the moment, named so that `check` and the run's
//! sidecar say what acted — the user's own, or an effect's that depends on ω (B-dot).

use std::fmt;
use std::sync::Arc;

use nalgebra::{UnitQuaternion, Vector3};

use crate::frames::Axes;

/// A moment law M(t, q, ω_b) (N·m), in the axes its [`UserMoment`] names: t in s, q the attitude (body → space),
/// ω_b the angular velocity in body axes (rad/s). Called at every right-hand-side evaluation of the run; a law that
/// cannot give a moment returns a non-finite vector, and the run stops there (a non-finite state).
///
/// A closure `Fn(f64, &UnitQuaternion<f64>, &Vector3<f64>) -> Vector3<f64>` that is `Send + Sync` is a law.
pub trait MomentLaw: Send + Sync {
    /// The moment at time `t`, attitude `q` and angular velocity `omega_b`.
    fn moment(&self, t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>) -> Vector3<f64>;
}

impl<F> MomentLaw for F
where
    F: Fn(f64, &UnitQuaternion<f64>, &Vector3<f64>) -> Vector3<f64> + Send + Sync,
{
    fn moment(&self, t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>) -> Vector3<f64> {
        self(t, q, omega_b)
    }
}

/// A named law and the axes its moment is given in. Two are equal when they have the same name and axes and share
/// the same law (the same `Arc`).
#[derive(Clone)]
pub struct UserMoment {
    /// What `check` and the sidecar call it.
    pub name: String,
    /// The axes of the law's moment.
    pub frame: Axes,
    /// The law.
    pub law: Arc<dyn MomentLaw>,
}

impl UserMoment {
    /// The law `law` called `name`, its moment in `frame` axes.
    pub fn new(name: &str, frame: Axes, law: impl MomentLaw + 'static) -> Self {
        Self {
            name: name.to_string(),
            frame,
            law: Arc::new(law),
        }
    }

    /// The moment in body axes: the law's, rotated by qᵀ when it is given in space axes.
    #[inline]
    pub fn moment_b(
        &self,
        t: f64,
        q: &UnitQuaternion<f64>,
        omega_b: &Vector3<f64>,
    ) -> Vector3<f64> {
        let m = self.law.moment(t, q, omega_b);
        match self.frame {
            Axes::Body => m,
            Axes::Space => q.inverse_transform_vector(&m),
        }
    }
}

impl fmt::Debug for UserMoment {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("UserMoment")
            .field("name", &self.name)
            .field("frame", &self.frame)
            .finish_non_exhaustive()
    }
}

impl PartialEq for UserMoment {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name && self.frame == other.frame && Arc::ptr_eq(&self.law, &other.law)
    }
}
