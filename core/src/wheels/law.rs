//! A wheel law: the commanded motor torques of a body's wheels from (t, q, ω_b, the wheels' spins) — the same kind
//! of law as a user moment ([`crate::effects::MomentLaw`]).

use std::fmt;
use std::sync::Arc;

use nalgebra::{UnitQuaternion, Vector3};

/// What a wheel law is told at one instant: t (s), the attitude q (body → space), ω_b in body axes (rad/s) and
/// Ω_k, the wheels' spins relative to the body (rad/s), in the scene's order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelInputs<'a> {
    /// Time (s).
    pub t: f64,
    /// Attitude, body → space.
    pub q: &'a UnitQuaternion<f64>,
    /// Angular velocity in body axes (rad/s).
    pub omega_b: &'a Vector3<f64>,
    /// The wheels' spins relative to the body (rad/s).
    pub spins: &'a [f64],
}

/// τ_cmd,k(t, q, ω_b, Ω_1 … Ω_n) (N·m), one per wheel in the scene's order ([`WheelInputs`]). Called at every
/// right-hand-side evaluation; a law that cannot give its torques returns non-finite ones (or a wrong number of
/// them), and the run stops there.
///
/// A closure `Fn(f64, &UnitQuaternion<f64>, &Vector3<f64>, &[f64]) -> Vec<f64>` that is `Send + Sync` is a law.
pub trait WheelLaw: Send + Sync {
    /// The commanded torques at the instant `now`.
    fn torques(&self, now: &WheelInputs<'_>) -> Vec<f64>;
}

impl<F> WheelLaw for F
where
    F: Fn(f64, &UnitQuaternion<f64>, &Vector3<f64>, &[f64]) -> Vec<f64> + Send + Sync,
{
    fn torques(&self, now: &WheelInputs<'_>) -> Vec<f64> {
        self(now.t, now.q, now.omega_b, now.spins)
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

    /// The commands of the wheels whose spins `now` gives, one each; NaN for every wheel when the law gives
    /// another number of torques.
    pub fn commands(&self, now: &WheelInputs<'_>) -> Vec<f64> {
        let n = now.spins.len();
        let torques = self.law.torques(now);
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

/// A quaternion-feedback regulator flown through the wheels (Wie, *Space Vehicle Dynamics and Control*, 2nd ed.,
/// §7.3, in its small-angle form): the body is asked for the control moment
///
/// ```text
///   u_b = k_p e_b − k_d ω_b,   e_b = R⁻¹ · (the rotation vector from q to the target, space axes)
///   τ_k = −u_b · a_k           (wheel k along a_k; the body feels −τ_k a_k)
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct AttitudePd {
    /// The attitude to reach (body → space).
    pub target: UnitQuaternion<f64>,
    /// The proportional gain k_p (N·m/rad).
    pub k_p: f64,
    /// The rate gain k_d (N·m·s/rad).
    pub k_d: f64,
    /// The wheels' unit axes a_k in body axes, in the scene's order.
    pub axes_b: Vec<Vector3<f64>>,
}

impl AttitudePd {
    /// The regulator to `target` with gains `k_p`, `k_d` through wheels along `axes_b`.
    ///
    /// ```
    /// use eulerdyn::wheels::{AttitudePd, WheelInputs, WheelLaw};
    /// use nalgebra::{UnitQuaternion, Vector3};
    ///
    /// let target = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.5);
    /// let pd = AttitudePd::new(target, 0.6, 3.0, vec![Vector3::x(), Vector3::y(), Vector3::z()]);
    /// // At rest and 0.5 rad short about z: u_b = (0, 0, 0.3), so the z wheel is told −0.3 N·m.
    /// let (q, omega_b) = (UnitQuaternion::identity(), Vector3::zeros());
    /// let tau = pd.torques(&WheelInputs { t: 0.0, q: &q, omega_b: &omega_b, spins: &[0.0; 3] });
    /// assert!((tau[2] + 0.3).abs() < 1e-15 && tau[0] == 0.0 && tau[1] == 0.0);
    /// ```
    pub fn new(target: UnitQuaternion<f64>, k_p: f64, k_d: f64, axes_b: Vec<Vector3<f64>>) -> Self {
        Self {
            target,
            k_p,
            k_d,
            axes_b,
        }
    }
}

impl WheelLaw for AttitudePd {
    fn torques(&self, now: &WheelInputs<'_>) -> Vec<f64> {
        let (q, omega_b) = (now.q, now.omega_b);
        let error_b = q.inverse_transform_vector(&q.rotation_to(&self.target).scaled_axis());
        let u_b = error_b * self.k_p - omega_b * self.k_d;
        self.axes_b.iter().map(|a| -u_b.dot(a)).collect()
    }
}
