//! The divergence guard: a free-motion run whose energy or moment of momentum leaves what the scene's effects can
//! supply is stopped before the row that shows it reaches the sink.

use std::fmt;

use nalgebra::Vector3;

use crate::effects::{Effect, EffectMoments};
use crate::method::Method;
use crate::sample::Sample;
use crate::scene::{Invariant, Scene};

/// The quantity a [`DivergenceGuard`] found out of bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GuardedQuantity {
    /// Kinetic energy ½ ω·H (J).
    Energy,
    /// |H| about the moment center (kg·m²/s).
    HNorm,
    /// H_s, the moment of momentum in space axes (kg·m²/s): |H_s(t) − H_s(0)|.
    HSpace,
}

impl GuardedQuantity {
    /// A name for messages.
    pub fn describe(&self) -> &'static str {
        match self {
            GuardedQuantity::Energy => "the kinetic energy",
            GuardedQuantity::HNorm => "|H|",
            GuardedQuantity::HSpace => "H_s (moment of momentum in space axes)",
        }
    }
}

/// A run stopped by the [`DivergenceGuard`]: at row time `t`, `quantity` was `value` where the bound was `bound`
/// (for [`GuardedQuantity::HSpace`], `value` is |H_s(t) − H_s(0)|).
#[derive(Debug, Clone, PartialEq)]
pub struct Divergence {
    /// Row time (s) at which the bound was exceeded; the rows before it were delivered, this one was not.
    pub t: f64,
    /// What left its bound.
    pub quantity: GuardedQuantity,
    /// Its value at t.
    pub value: f64,
    /// Its value at t = 0.
    pub initial: f64,
    /// The bound it exceeded (for a conserved quantity: the largest allowed |change|).
    pub bound: f64,
    /// Whether the quantity is conserved (torque-free), so the bound is on its change in either direction.
    pub conserved: bool,
    /// What to do about it.
    pub hint: &'static str,
}

impl fmt::Display for Divergence {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let what = self.quantity.describe();
        match (self.conserved, self.quantity) {
            (_, GuardedQuantity::HSpace) => write!(
                f,
                "the run diverged at t = {} s: {what} moved by {:e} from its initial value (|H(0)| = {:e}), more \
                 than the {:e} the scene's effects and the method's accuracy allow",
                self.t, self.value, self.initial, self.bound
            )?,
            (true, _) => write!(
                f,
                "the run diverged at t = {} s: {what} changed from {:e} to {:e}; a torque-free body conserves it, \
                 and the method's accuracy allows a change of at most {:e}",
                self.t, self.initial, self.value, self.bound
            )?,
            (false, _) => write!(
                f,
                "the run diverged at t = {} s: {what} grew to {:e}, beyond {:e}, the most its initial value {:e} \
                 plus the work the scene's effects can do by then allows",
                self.t, self.value, self.bound, self.initial
            )?,
        }
        write!(f, " — {}", self.hint)
    }
}

impl std::error::Error for Divergence {}

/// How accurate the method is, for the [`DivergenceGuard`]'s allowance.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Accuracy {
    /// Adaptive: rtol + atol / (scale of the state).
    Tolerance(f64),
    /// Fixed step h of order p: (Ω h)^p, h the step taken ([`super::fixed_step`]).
    Step { dt: f64, order: i32 },
    /// The closed form: round-off.
    RoundOff,
}

/// Stops a free-motion run whose rows leave what physics allows, before such a row reaches the sink.
///
/// With Ω(t) = √(2 E_max(t)/I_min), the largest |ω| the energy allows (E ≥ ½ I_min |ω|²), and the method's
/// accuracy a (rtol + atol/scale for dopri5/dop853, (Ω dt)^p for rk4/split2/split4 with p = 4, 2, 4, ε for
/// exact), the allowance is
///
/// ```text
///   δ(t) = min(0.5, max(1e-6, 1e3 · a · (1 + Ω t)))
/// ```
///
/// — a thousand times the global error of a method honouring its accuracy over Ω t radians (measured constants
/// are ≤ 0.15, see tests/it/free_rotation.rs), never below 1e-6 (round-off over long runs), never above 50 % (a
/// conserved quantity off by half is garbage whatever the settings).
///
/// * Torque-free, E, |H| and H_s are conserved: |E − E₀| ≤ δ E₀, ||H| − |H₀|| ≤ δ |H₀|,
///   |H_s − H_s₀| ≤ δ |H₀|. A body-form run whose attitude is garbage (a too-large step that stays bounded) moves
///   H_s = q·H_b and is caught by the last check.
/// * With effects, M = M_rest(t, q) − c ω with |M_rest| ≤ M_max (Σ |torque| + m|g||ρ_C|; damping does no positive
///   work): dE/dt = M·ω ≤ M_max |ω| ≤ M_max √(2E/I_min), so d√E/dt ≤ M_max/√(2 I_min) and
///   `E ≤ E_max(t) = (√E₀ + M_max t/√(2 I_min))²`; and |H_s(t) − H_s₀| ≤ ∫|M| ≤ (M_max + c Ω(t)) t =: ΔH(t).
///   Checks: E ≤ (1 + δ) E_max(t), |H_s − H_s₀| ≤ ΔH(t) + δ (|H₀| + ΔH(t)).
///
/// A method that blows up grows exponentially and crosses these polynomial bounds within a few steps; one that is
/// merely inaccurate within its allowance is left alone. Prescribed (fixed-axis) motion is not guarded: its rows
/// are the closed form.
#[derive(Debug, Clone, PartialEq)]
pub struct DivergenceGuard {
    e0: f64,
    h0_s: Vector3<f64>,
    h0_norm: f64,
    m_max: f64,
    damping_c: f64,
    i_min: f64,
    /// T and H_s are conserved (the scene's [`crate::scene::Facts`]: torque-free).
    conserved: bool,
    accuracy: Accuracy,
    hint: &'static str,
}

/// The hints of a run stopped by the guard, per kind of method.
const HINT_RK4: &str = "the step is too large for this motion: use a smaller dt, an adaptive method \
                        (dopri5/dop853) or split2/split4";
const HINT_SPLIT: &str = "the step is too large for this motion: use a smaller dt (the splitting keeps |H| \
                          exact at any step, but its energy error grows with |omega|*dt)";
const HINT_ADAPTIVE: &str = "use a tighter rtol/atol, or split2/split4, whose |H| is exact";
const HINT_EXACT: &str = "the closed form should not do this: please report the scene";

impl DivergenceGuard {
    /// The guard of a scene's run; `None` for a prescribed motion, a body with rotors (whose motors may add any
    /// energy), and a run with a user's moment law, whose work has no known bound.
    pub fn new(scene: &Scene) -> Option<Self> {
        let (omega0_b, body) = scene.motion.rigid_free()?;
        if scene.effects.iter().any(Effect::is_user) {
            return None;
        }
        let facts = scene.facts();
        let (h0_b, e0) = body.momentum_and_energy(omega0_b);
        let h0_s = *h0_b.in_space(&scene.attitude0);
        let moments = EffectMoments::new(&scene.effects, body.mass());
        let i_min = body.principal_moments().min();
        let s = &scene.solver;
        let accuracy = match s.method {
            Method::Dopri5 | Method::Dop853 => {
                let omega0 = (2.0 * e0 / i_min).sqrt();
                let scale = 1f64.min(omega0).min(h0_b.norm()).max(f64::MIN_POSITIVE);
                Accuracy::Tolerance(s.rtol + s.atol / scale)
            }
            Method::Rk4 | Method::Split2 | Method::Split4 => Accuracy::Step {
                dt: scene.fixed_step().unwrap_or(s.dt),
                order: s.method.order().map_or(1, |p| p as i32),
            },
            Method::Exact => Accuracy::RoundOff,
        };
        Some(Self {
            e0,
            h0_s,
            h0_norm: h0_b.norm(),
            m_max: moments.rest_moment_bound(),
            damping_c: moments.damping_c(),
            i_min,
            conserved: facts.conserves(Invariant::Energy) && facts.conserves(Invariant::HSpaceX),
            accuracy,
            hint: match s.method {
                Method::Rk4 => HINT_RK4,
                Method::Split2 | Method::Split4 => HINT_SPLIT,
                Method::Dopri5 | Method::Dop853 => HINT_ADAPTIVE,
                Method::Exact => HINT_EXACT,
            },
        })
    }

    /// E_max(t) = (√E₀ + M_max t/√(2 I_min))²: the most kinetic energy the effects can have supplied by t (J).
    pub fn energy_bound(&self, t: f64) -> f64 {
        let root = self.e0.sqrt() + self.m_max * t / (2.0 * self.i_min).sqrt();
        root * root
    }

    /// Ω(t) = √(2 E_max(t)/I_min): the largest |ω| the energy allows (rad/s).
    fn omega_bound(&self, t: f64) -> f64 {
        (2.0 * self.energy_bound(t) / self.i_min).sqrt()
    }

    /// The relative allowance δ(t) for the method's error (see the type's documentation).
    pub fn allowance(&self, t: f64) -> f64 {
        let omega = self.omega_bound(t);
        let a = match self.accuracy {
            Accuracy::Tolerance(tol) => tol,
            Accuracy::Step { dt, order } => (omega * dt).powi(order),
            Accuracy::RoundOff => f64::EPSILON,
        };
        (1e3 * a * (1.0 + omega * t)).clamp(1e-6, 0.5)
    }

    /// Checks one row; `Err` says what left its bound.
    pub fn check(&self, s: &Sample) -> Result<(), Divergence> {
        let t = s.t;
        let delta = self.allowance(t);
        let out = |quantity, value, initial, bound, conserved| Divergence {
            t,
            quantity,
            value,
            initial,
            bound,
            conserved,
            hint: self.hint,
        };
        let h_norm = s.h_o_s.norm();
        let h_moved = (*s.h_o_s - self.h0_s).norm();
        if self.conserved {
            let (de, dh) = (delta * self.e0, delta * self.h0_norm);
            if !within((s.energy - self.e0).abs(), de) {
                return Err(out(GuardedQuantity::Energy, s.energy, self.e0, de, true));
            }
            if !within((h_norm - self.h0_norm).abs(), dh) {
                return Err(out(GuardedQuantity::HNorm, h_norm, self.h0_norm, dh, true));
            }
            if !within(h_moved, dh) {
                return Err(out(
                    GuardedQuantity::HSpace,
                    h_moved,
                    self.h0_norm,
                    dh,
                    true,
                ));
            }
        } else {
            let e_max = (1.0 + delta) * self.energy_bound(t);
            if !within(s.energy, e_max) {
                return Err(out(
                    GuardedQuantity::Energy,
                    s.energy,
                    self.e0,
                    e_max,
                    false,
                ));
            }
            let dh = (self.m_max + self.damping_c * self.omega_bound(t)) * t;
            let bound = dh + delta * (self.h0_norm + dh);
            if !within(h_moved, bound) {
                return Err(out(
                    GuardedQuantity::HSpace,
                    h_moved,
                    self.h0_norm,
                    bound,
                    false,
                ));
            }
        }
        Ok(())
    }
}

/// x ≤ bound, false for a NaN x (so a NaN row, which the integrators never deliver, would be stopped too).
fn within(x: f64, bound: f64) -> bool {
    x <= bound
}
