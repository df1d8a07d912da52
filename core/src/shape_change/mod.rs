//! A body that changes shape, one capability in one folder: point masses moved inside a freely turning body
//! (`[[body.moving_mass]]`: booms that deploy, a mass on a rail, a skater's arms) or an inertia history
//! (`[body] inertia_table`), and Euler's equation in its full form, M = d/dt(I·ω), about the system's
//! instantaneous centre of mass ([`system`], and split by [`splitting`]): its distribution in time
//! ([`history`]), the masses' paths ([`path`]), its keys (`keys.rs`) and validation (`validate.rs`), its columns (`columns.rs`) and `check` lines
//! (`describe.rs`). Without external moment H_s is constant; the kinetic energy is not — the internal drives put
//! in `P_internal`.

mod attribute;
mod columns;
mod describe;
pub mod history;
mod keys;
mod mount;
pub mod path;
pub mod splitting;
pub mod system;
mod validate;

pub use history::{Distribution, InertiaHistory, MassState, MovingMass};
pub(crate) use keys::ShapeChangeKeys;
pub use keys::{MovingMassSpec, PathSpec, ShapeChangeSpec};
pub use path::{Kinematics, MassPath, Profile, Side};
pub(crate) use validate::validate_shape_change;
pub use validate::{INERTIA_TABLE_HEADER, PATH_TABLE_HEADER};

/// A body's mass distribution in time, validated: what [`system`] integrates.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapeChange {
    distribution: Distribution,
    /// Every time a rate jumps, sorted.
    corners: Vec<f64>,
    center_moves: bool,
}

impl ShapeChange {
    /// The shape change of `distribution`.
    pub fn new(distribution: Distribution) -> Self {
        let corners = distribution.corners();
        let center_moves = match &distribution {
            Distribution::Table { .. } => false,
            Distribution::Masses { masses, .. } => center_moves(masses),
        };
        Self {
            distribution,
            corners,
            center_moves,
        }
    }

    /// The distribution at t ([`history`]), one-sided at a corner.
    pub fn at(&self, t: f64, side: Side) -> MassState {
        self.distribution.at(t, side)
    }

    /// What changes the shape.
    pub fn distribution(&self) -> &Distribution {
        &self.distribution
    }

    /// The moving masses (none for an inertia table).
    pub fn masses(&self) -> &[MovingMass] {
        match &self.distribution {
            Distribution::Masses { masses, .. } => masses,
            Distribution::Table { .. } => &[],
        }
    }

    /// The first corner later than `t`, where an adaptive method ends a step.
    pub fn corner_after(&self, t: f64) -> Option<f64> {
        self.corners
            .get(self.corners.partition_point(|c| *c <= t))
            .copied()
    }

    /// The time from which nothing moves any more (the last corner, s).
    pub fn end(&self) -> f64 {
        self.corners.last().copied().unwrap_or(0.0)
    }

    /// Whether the system's centre of mass moves in the body (then its columns are written).
    pub fn center_moves(&self) -> bool {
        self.center_moves
    }
}

/// Whether Σ m_i r_i(t) changes: a mass on a table, or moves that do not cancel (masses moved together, with the
/// same start, duration and profile, whose Σ m_i (to_i − from_i) is zero keep C in place: a symmetric pair).
fn center_moves(masses: &[MovingMass]) -> bool {
    // Per timing (start, duration, profile): Σ m_i (to_i − from_i) and the scale Σ m_i (|to_i| + |from_i|).
    type Timing = (f64, f64, Profile);
    let mut groups: Vec<(Timing, nalgebra::Vector3<f64>, f64)> = Vec::new();
    for m in masses {
        match &m.path {
            MassPath::Table { .. } => return true,
            MassPath::Move {
                from,
                to,
                start,
                duration,
                profile,
            } => {
                let timing = (*start, *duration, *profile);
                let moment = (to - from) * m.mass;
                let scale = (to.norm() + from.norm()) * m.mass;
                match groups.iter_mut().find(|(t, ..)| *t == timing) {
                    Some((_, sum, size)) => (*sum, *size) = (*sum + moment, *size + scale),
                    None => groups.push((timing, moment, scale)),
                }
            }
        }
    }
    groups
        .iter()
        .any(|(_, sum, scale)| sum.norm() > 1e-12 * scale)
}
