//! The errors of one run against the reference, accumulated row by row while the run streams: the largest
//! |ω_b − ω_b,ref|, attitude angle, |E − E_ref|, ||H| − |H|_ref| and |H_s − H_s,ref| over the rows.

use crate::analysis::compare::attitude_angle;
use crate::sample::Sample;

use super::reference::RefRow;

/// The quantity the summary and the plot rank runs by.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Measure {
    /// `err_omega` (free motion).
    Omega,
    /// `err_H_s`: H_s integrated from Ḣ_s = M_s against the closed form (prescribed fixed-axis motion, whose ω
    /// is the closed form itself).
    HSpace,
}

impl Measure {
    /// The table column.
    pub fn column(&self) -> &'static str {
        match self {
            Measure::Omega => "err_omega",
            Measure::HSpace => "err_H_s",
        }
    }

    /// What it is, for people.
    pub fn describe(&self) -> &'static str {
        match self {
            Measure::Omega => "largest |omega_b - omega_ref| over the rows (rad/s)",
            Measure::HSpace => {
                "largest |H_s integrated - I_s(theta) omega_s| over the rows (kg*m^2/s)"
            }
        }
    }
}

/// The largest differences of one run, accumulated row by row.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Errors {
    pub omega: f64,
    pub attitude: Option<f64>,
    energy: f64,
    energy_scale: f64,
    h_norm: f64,
    h_scale: f64,
    pub h_s: Option<f64>,
}

impl Errors {
    fn max_into(slot: &mut Option<f64>, v: f64) {
        *slot = Some(slot.map_or(v, |old| old.max(v)));
    }

    /// Adds a row against its reference row.
    pub fn add(&mut self, s: &Sample, r: &RefRow) {
        self.omega = self.omega.max((*s.omega_b - r.omega_b).norm());
        if let Some(q) = &r.q {
            Self::max_into(&mut self.attitude, attitude_angle(&s.q, q));
        }
        self.energy = self.energy.max((s.energy - r.energy).abs());
        self.energy_scale = self.energy_scale.max(r.energy.abs());
        self.h_norm = self.h_norm.max((s.h_o_s.norm() - r.h_norm).abs());
        self.h_scale = self.h_scale.max(r.h_norm.abs());
        if let Some(h_s) = &r.h_s {
            Self::max_into(&mut self.h_s, (*s.h_o_s - h_s).norm());
        }
    }

    /// Adds a row of prescribed fixed-axis motion: its integrated H_s against its closed-form H_s.
    pub fn add_fixed_axis(&mut self, s: &Sample) {
        self.attitude = Some(0.0);
        if let Some(h_int) = &s.h_o_s_integrated {
            Self::max_into(&mut self.h_s, (*h_int - s.h_o_s).norm());
        }
        self.energy_scale = self.energy_scale.max(s.energy.abs());
        self.h_scale = self.h_scale.max(s.h_o_s.norm());
    }

    fn relative(abs: f64, scale: f64) -> f64 {
        if scale > 0.0 { abs / scale } else { abs }
    }

    /// Largest |E − E_ref| relative to the largest |E_ref|.
    pub fn energy_drift(&self) -> f64 {
        Self::relative(self.energy, self.energy_scale)
    }

    /// Largest ||H| − |H|_ref| relative to the largest |H|_ref.
    pub fn h_drift(&self) -> f64 {
        Self::relative(self.h_norm, self.h_scale)
    }
}

/// A run's row does not match the reference's (never expected: both follow the scene's schedule).
#[derive(Debug, thiserror::Error)]
#[error("row {row} at t = {t} has no reference row")]
pub(super) struct RowMismatch {
    pub row: usize,
    pub t: f64,
}
