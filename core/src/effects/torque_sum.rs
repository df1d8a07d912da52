//! The torques of one frame summed and compiled: M(t) = Σ value_k · f_k(t), what the torque and torque-table
//! effects and a wheel's motor torque become for the right-hand side.

use std::sync::Arc;

use nalgebra::Vector3;

use super::table::TorqueTable;
use crate::profile::Profile;
use crate::trig;

/// The torques of one frame summed, compiled once so that every evaluation does only the time-dependent
/// arithmetic: M(t) = Σ value_k · f_k(t) with the profiles of [`Profile`]. The constant torques are summed
/// into one vector, each sine keeps its angular frequency ω = 2π f (computed once, rounded as 2π·f·t would round
/// it), each step keeps its interval, each table is interpolated ([`TorqueTable::at`]).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TorqueSum {
    constant: Vector3<f64>,
    sines: Vec<SineTorque>,
    steps: Vec<StepTorque>,
    /// A boxed slice, two words: the scene's `Motion` holds a hinge's compiled effects and stays small.
    tables: Box<[Arc<TorqueTable>]>,
}

/// value · sin(ω t + φ).
#[derive(Debug, Clone, Copy, PartialEq)]
struct SineTorque {
    value: Vector3<f64>,
    omega_rad_s: f64,
    phase_rad: f64,
}

/// value for t_on ≤ t < t_off, else 0.
#[derive(Debug, Clone, Copy, PartialEq)]
struct StepTorque {
    value: Vector3<f64>,
    t_on: f64,
    t_off: f64,
}

impl TorqueSum {
    /// Adds the torque `value · f(t)`.
    pub fn add(&mut self, value: &Vector3<f64>, profile: &Profile) {
        match *profile {
            Profile::Constant => self.constant += value,
            Profile::Sine { freq_hz, phase_deg } => self.sines.push(SineTorque {
                value: *value,
                omega_rad_s: 2.0 * std::f64::consts::PI * freq_hz,
                phase_rad: phase_deg.to_radians(),
            }),
            Profile::Step { t_on, t_off } => self.steps.push(StepTorque {
                value: *value,
                t_on,
                t_off,
            }),
        }
    }

    /// Adds the tabulated torque `table`.
    pub fn add_table(&mut self, table: &Arc<TorqueTable>) {
        let mut tables = std::mem::take(&mut self.tables).into_vec();
        tables.push(Arc::clone(table));
        self.tables = tables.into_boxed_slice();
    }

    /// Whether the sum is zero at every time: no torque added, or only constant torques summing to zero.
    pub fn is_zero(&self) -> bool {
        self.constant == Vector3::zeros()
            && self.sines.is_empty()
            && self.steps.is_empty()
            && self.tables.is_empty()
    }

    /// The first corner of a table's moment later than `t` (s), where an adaptive method should end a step.
    pub fn corner_after(&self, t: f64) -> Option<f64> {
        (self.tables.iter())
            .filter_map(|table| table.corner_after(t))
            .min_by(f64::total_cmp)
    }

    /// M(t) = Σ value_k · f_k(t). Always inlined: a call at every Runge–Kutta stage would spill the state.
    #[inline(always)]
    pub fn at(&self, t: f64) -> Vector3<f64> {
        let mut m = self.constant;
        for sine in &self.sines {
            m += sine.value * trig::sin(sine.omega_rad_s * t + sine.phase_rad);
        }
        for step in &self.steps {
            if step.t_on <= t && t < step.t_off {
                m += step.value;
            }
        }
        for table in &self.tables {
            m += table.at(t);
        }
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_torque_sum_is_the_sum_of_its_profiles() {
        let (a, b, c) = (
            Vector3::new(0.5, 0.0, -0.25),
            Vector3::new(0.0, 2.0, 1.0),
            Vector3::new(-1.0, 0.5, 0.0),
        );
        let mut sum = TorqueSum::default();
        assert!(sum.is_zero());
        sum.add(&a, &Profile::Constant);
        sum.add(&a, &Profile::Constant);
        sum.add(
            &b,
            &Profile::Sine {
                freq_hz: 0.5,
                phase_deg: 30.0,
            },
        );
        sum.add(
            &c,
            &Profile::Step {
                t_on: 1.0,
                t_off: 2.0,
            },
        );
        assert!(!sum.is_zero());
        for t in [0.0, 0.9, 1.0, 1.5, 2.0, 7.3] {
            // The sine as the profile defines it, by the crate's inline sine (tested against the library's in
            // `trig`).
            let sine = trig::sin(2.0 * std::f64::consts::PI * 0.5 * t + 30f64.to_radians());
            let step = if (1.0..2.0).contains(&t) { 1.0 } else { 0.0 };
            // Each term is computed as the profile defines it; only the order of the sum differs (exact here:
            // the constant part 2a is exact and the other terms are added one by one as before).
            assert_eq!(sum.at(t), a * 2.0 + b * sine + c * step, "t = {t}");
        }
    }

    #[test]
    fn constant_torques_that_cancel_sum_to_zero() {
        let mut sum = TorqueSum::default();
        let a = Vector3::new(0.5, -1.0, 2.0);
        sum.add(&a, &Profile::Constant);
        sum.add(&-a, &Profile::Constant);
        assert!(sum.is_zero());
        assert_eq!(sum.at(3.0), Vector3::zeros());
    }
}
