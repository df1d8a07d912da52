//! The wheels' values in a row, carried by [`Sample::capability_values`] five to a wheel (Ω_k, h_k, τ_k, the
//! command, the friction) and read back as [`RotorRows`].

use super::MAX_ROTORS;
use crate::sample::{CapabilityValues, Sample};

/// The values each wheel adds to a row.
pub(super) const PER_WHEEL: usize = 5;

const _: () = assert!(PER_WHEEL * MAX_ROTORS <= CapabilityValues::CAPACITY);

/// The rotors' values in one row, the first `n` entries used: relative spin Ω_k (rad/s), the wheel's axial moment
/// of momentum J_k(a_k·ω + Ω_k) (N·m·s), the motor torque τ_k applied to the wheel (N·m), the torque commanded
/// (before the limits) and the friction torque on the wheel (N·m).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RotorRows {
    /// The number of wheels.
    pub n: usize,
    /// Ω_k (rad/s).
    pub spin: [f64; MAX_ROTORS],
    /// J_k(a_k·ω + Ω_k) (N·m·s).
    pub h: [f64; MAX_ROTORS],
    /// τ_k applied (N·m).
    pub torque: [f64; MAX_ROTORS],
    /// τ_k commanded (N·m).
    pub torque_cmd: [f64; MAX_ROTORS],
    /// Friction torque on the wheel (N·m).
    pub friction: [f64; MAX_ROTORS],
}

impl RotorRows {
    /// The wheels' values of the row `sample`, if it has wheels.
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, RotorSpec, SceneSpec};
    /// use eulerdyn::wheels::RotorRows;
    /// let body = BodySpec::principal(1.0, [1.0, 1.0, 2.0]).with_rotor(RotorSpec::new([0.0, 0.0, 1.0], 0.01, 100.0));
    /// let scene = SceneSpec::new(body, 0.1, 0.1).build()?;
    /// let (samples, _) = eulerdyn::simulate::samples(&scene)?;
    /// let wheels = RotorRows::of(&samples[0]).expect("a row with wheels");
    /// assert_eq!((wheels.n, wheels.spin[0]), (1, 100.0));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn of(sample: &Sample) -> Option<Self> {
        let values = sample.capability_values?;
        let values = values.as_slice();
        let mut rows = RotorRows {
            n: values.len() / PER_WHEEL,
            ..RotorRows::default()
        };
        for (k, wheel) in values.chunks_exact(PER_WHEEL).enumerate() {
            [
                rows.spin[k],
                rows.h[k],
                rows.torque[k],
                rows.torque_cmd[k],
                rows.friction[k],
            ] = [wheel[0], wheel[1], wheel[2], wheel[3], wheel[4]];
        }
        Some(rows)
    }

    /// The values a row carries, [`PER_WHEEL`] to a wheel.
    pub(super) fn values(&self) -> CapabilityValues {
        let mut values = [0.0; PER_WHEEL * MAX_ROTORS];
        for (k, wheel) in values.chunks_exact_mut(PER_WHEEL).take(self.n).enumerate() {
            wheel.copy_from_slice(&[
                self.spin[k],
                self.h[k],
                self.torque[k],
                self.torque_cmd[k],
                self.friction[k],
            ]);
        }
        CapabilityValues::new(&values[..PER_WHEEL * self.n]).expect("at most MAX_ROTORS wheels")
    }
}
