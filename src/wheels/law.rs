//! A wheel law: the commanded motor torques of a body's wheels from (t, q, ω_b, the wheels' spins) — the same kind
//! of law as a user moment ([`crate::effects::MomentLaw`]).

use std::fmt;
use std::sync::Arc;

use nalgebra::{UnitQuaternion, Vector3};

/// τ_cmd,k(t, q, ω_b, Ω_1 … Ω_n) (N·m), one per wheel in the scene's order: t in s, q the attitude (body →
/// space), ω_b in body axes (rad/s), Ω_k the wheels' spins relative to the body (rad/s). Called at every
/// right-hand-side evaluation; a law that cannot give its torques returns non-finite ones (or a wrong number of
/// them), and the run stops there.
///
/// A closure `Fn(f64, &UnitQuaternion<f64>, &Vector3<f64>, &[f64]) -> Vec<f64>` that is `Send + Sync` is a law.
pub trait WheelLaw: Send + Sync {
    /// The commanded torques at time `t`, attitude `q`, angular velocity `omega_b` and relative spins `spins`.
    fn torques(
        &self,
        t: f64,
        q: &UnitQuaternion<f64>,
        omega_b: &Vector3<f64>,
        spins: &[f64],
    ) -> Vec<f64>;
}

impl<F> WheelLaw for F
where
    F: Fn(f64, &UnitQuaternion<f64>, &Vector3<f64>, &[f64]) -> Vec<f64> + Send + Sync,
{
    fn torques(
        &self,
        t: f64,
        q: &UnitQuaternion<f64>,
        omega_b: &Vector3<f64>,
        spins: &[f64],
    ) -> Vec<f64> {
        self(t, q, omega_b, spins)
    }
}

/// A named wheel law. Two are equal when they have the same name and share the same law (the same `Arc`).
#[derive(Clone)]
pub struct WheelTorqueLaw {
    /// What `check` and the sidecar call it.
    pub name: String,
    /// The law.
    pub law: Arc<dyn WheelLaw>,
}

impl WheelTorqueLaw {
    /// The law `law` called `name`.
    pub fn new(name: &str, law: impl WheelLaw + 'static) -> Self {
        Self {
            name: name.to_string(),
            law: Arc::new(law),
        }
    }

    /// The commands of `n` wheels; NaN for every wheel when the law gives another number of torques.
    pub fn commands(
        &self,
        n: usize,
        t: f64,
        q: &UnitQuaternion<f64>,
        omega_b: &Vector3<f64>,
        spins: &[f64],
    ) -> Vec<f64> {
        let torques = self.law.torques(t, q, omega_b, spins);
        match torques.len() == n {
            true => torques,
            false => vec![f64::NAN; n],
        }
    }
}

impl fmt::Debug for WheelTorqueLaw {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("WheelTorqueLaw")
            .field("name", &self.name)
            .finish_non_exhaustive()
    }
}

impl PartialEq for WheelTorqueLaw {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name && Arc::ptr_eq(&self.law, &other.law)
    }
}
