//! The torque-free rigid body (Euler–Poinsot motion) in closed form.
//!
//! Landau & Lifshitz, *Mechanics* (3rd ed.), §37; the attitude construction follows the same
//! section and Celledoni, Fassò, Säfström & Zanna (2008), "The exact computation of the free
//! rigid body motion and its use in splitting methods", SIAM J. Sci. Comput. 30(4), 2084–2112.
//!
//! # Conventions
//!
//! `moments_p` are the principal moments in the user's principal axes, in any order. The
//! solver works in a *canonical* principal frame, obtained from the user's by a signed
//! permutation with determinant +1 (so it is a proper rotation and Euler's equations keep
//! their form), in which
//!
//! * axis 3 is the axis that ω circulates around (the largest moment if `M² > 2E·I₂`, the
//!   smallest if `M² < 2E·I₂`; the largest on the separatrix), axis 2 the intermediate one;
//! * `ω₃(0) > 0` and `ω₁(0) ≥ 0` (a half-turn about a principal axis fixes these signs).
//!
//! Results are mapped back to the user's axes. With `a, b, c > 0`, `ε = sign(I₃ − I₁)` and
//! `τ = λt + τ₀` the solution is (L&L §37, with the signs fixed by substitution into Euler's
//! equations)
//!
//! ```text
//!   ω₁ = a cn(τ|m),   ω₂ = ε b sn(τ|m),   ω₃ = c dn(τ|m)
//!   a² = ω₁² + I₂(I₃−I₂)/(I₁(I₃−I₁)) ω₂²        [= (2E I₃ − M²)/(I₁(I₃ − I₁))]
//!   b² = I₁(I₃−I₁)/(I₂(I₃−I₂)) ω₁² + ω₂²        [= (2E I₃ − M²)/(I₂(I₃ − I₂))]
//!   c² = I₂(I₂−I₁)/(I₃(I₃−I₁)) ω₂² + ω₃²        [= (M² − 2E I₁)/(I₃(I₃ − I₁))]
//!   λ  = c √((I₃−I₁)(I₃−I₂)/(I₁I₂)),   m = I₁(I₂−I₁)a² / (I₃(I₃−I₂)c²)
//!   1 − m = (I₃(I₃−I₂)ω₃² − I₁(I₂−I₁)ω₁²) / (I₃(I₃−I₂)c²)   [∝ M² − 2E I₂]
//! ```
//!
//! every quantity formed from the initial ω without cancellation except `1 − m`, whose
//! cancellation is the physical sensitivity near the separatrix. The initial phase is
//! `τ₀ = F(φ₀|m)` with `(cos φ₀, sin φ₀) ∝ (ω₁/a, ε ω₂/b)`, `|φ₀| ≤ π/2`, so `omega_p(0)`
//! reproduces `omega0_p` to rounding, signs included.
//!
//! On the separatrix (`m = 1`) the same formulas hold with `sn = tanh`, `cn = dn = sech`
//! (L&L §37, the limiting case `M² = 2E I₂`). The symmetric cases `I₁ = I₂` and `I₂ = I₃`
//! come out with `m = 0` (uniform precession of ω about the symmetry axis at
//! `(I₃ − I₁)ω₃/I₁` in the body); the near-symmetric case uses the elliptic formulas with
//! small `m` (no switch to the symmetric formula unless the moments are exactly equal), which
//! stay accurate because [`crate::exact::jacobi`] is accurate as `m → 0`.
//!
//! The attitude uses the closed-form third-kind integral (Carlson `R_J`), not quadrature; see
//! [`TorqueFreeBody::attitude`].
//!
//! Stationary rotations (ω = 0, ω along a principal axis or in a degenerate principal plane,
//! a spherical body) have constant `ω_p` and `q(t) = q₀ ⊗ exp(½ ω_p t)`.

use ellip::elliprj;
use nalgebra::{Matrix3, Quaternion, Rotation3, UnitQuaternion, Vector3};

use super::double_double::{Dd, FOUR_PI, complete_k_pi, nearest_integer};
use super::jacobi::JacobiElliptic;
use super::{ExactError, axis_angle_quat, check_moments};

/// Which kind of Euler–Poinsot motion a [`TorqueFreeBody`] performs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TorqueFreeCase {
    /// ω is constant in the body (and in space): ω = 0, ω along a principal axis (including
    /// the intermediate one, an unstable equilibrium), ω in a degenerate principal plane of a
    /// symmetric body, or a spherical body.
    Stationary,
    /// ω circulates around the user principal axis with index `axis` (0, 1 or 2): the largest
    /// moment if `M² > 2E·I₂`, the smallest if `M² < 2E·I₂`. Includes the symmetric cases
    /// (elliptic parameter m = 0).
    Circulating {
        /// Index of the user principal axis whose ω component never changes sign.
        axis: usize,
    },
    /// `M² = 2E·I₂` (up to rounding) with ω not along the intermediate axis: the motion
    /// approaches the intermediate axis asymptotically (tanh/sech, not periodic).
    Separatrix,
}

/// A torque-free rigid body with given principal moments and initial state, solved in closed
/// form (Landau & Lifshitz, *Mechanics*, §37). See the module documentation for the formulas.
#[derive(Debug, Clone, PartialEq)]
pub struct TorqueFreeBody {
    moments_p: Vector3<f64>,
    omega0_p: Vector3<f64>,
    q0: UnitQuaternion<f64>,
    h_s: Vector3<f64>,
    energy: f64,
    /// |ω₀| in double-double (stationary motion: the angle |ω₀|·t of the rotation, reduced modulo 4π).
    omega0_norm: Dd,
    pub(super) regime: Regime,
}

/// Whether ω stays put (a principal-axis spin) or moves on its polhode.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Regime {
    Stationary,
    Elliptic(Box<Elliptic>),
}

/// The non-stationary solution in the canonical frame (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Elliptic {
    /// User → canonical: `v_c = perm · v_u` (signed permutation, det +1).
    pub(super) perm: Matrix3<f64>,
    /// Canonical user-axis index of canonical axis 3 (for [`TorqueFreeCase`]).
    pub(super) axis3_user: usize,
    pub(super) inertia: [f64; 3],
    /// `(I₁a, I₂b, I₃c)`, the amplitudes of H_p's components, times a power of two that brings the largest into
    /// [1, 2) (exact; the squares of [`Elliptic::half_angles`] neither overflow nor lose bits below `2⁻⁹⁶⁰`).
    pub(super) h_amp: [f64; 3],
    pub(super) a: f64,
    pub(super) b: f64,
    pub(super) c: f64,
    pub(super) eps: f64,
    pub(super) lambda: f64,
    /// λ and the half period 2K(m) of sn, cn in double-double, for `τ = λt + τ₀` and its reduction `τ − 2jK`.
    pub(super) lambda_dd: Dd,
    pub(super) two_k: Dd,
    pub(super) tau0: f64,
    pub(super) separatrix: bool,
    pub(super) jac: JacobiElliptic,
    /// `n = −I₃(I₂−I₁)/(I₁(I₃−I₂)) ≤ 0`, the characteristic of Π (A&S 17.2.15 sign
    /// convention: `Π(φ, n|m) = ∫ dθ / ((1 − n sin²θ) √(1 − m sin²θ))`).
    pub(super) n: f64,
    /// The secular part of φ in double-double, `phi_rate · t + phi_per_half_period · j` (j the half-period count of
    /// τ): `M/I₁` and `2κ R_J(0, m′, 1, 1−n) = 2 M(I₃ − I₁)/(I₁I₃λ) · (Π(n|m) − K(m))` (elliptic); on the separatrix
    /// `sep_lin` and 0. The rest of φ is bounded (see [`TorqueFreeBody::attitude`]).
    pub(super) phi_rate: Dd,
    pub(super) phi_per_half_period: Dd,
    /// Coefficient of `2j R_J(0, m′, 1, 1−n) + s³ R_J(c², d², 1, 1 − n s²)` in φ (elliptic).
    pub(super) kappa: f64,
    /// `R_J(0, m′, 1, 1 − n)` (elliptic case).
    pub(super) rj_complete: f64,
    /// The φ-integral's value at τ₀ (subtracted so that φ(0) = 0).
    pub(super) g0: f64,
    /// Separatrix: `φ = sep_lin · t + sep_atan · (atan(√ν tanh τ) − atan(√ν tanh τ₀))`, `sep_lin` = `phi_rate`.
    pub(super) sep_atan: f64,
    pub(super) sqrt_nu: f64,
    /// `q0 ⊗ perm⁻¹ ⊗ q_H(0)⁻¹`: maps the "H frame" (space frame rotated so that H ∥ z) to
    /// space; `attitude(t) = q_fixed ⊗ q_H(t) ⊗ q_perm`.
    pub(super) q_fixed: UnitQuaternion<f64>,
    pub(super) q_perm: UnitQuaternion<f64>,
}

impl TorqueFreeBody {
    /// Set up the motion of a torque-free body with principal moments `moments_p` (any order),
    /// initial angular velocity `omega0_p` in those principal axes, and initial attitude `q0`
    /// (principal → space, `v_s = q0 * v_p`).
    ///
    /// Classifies the motion by the sign of `M² − 2E·I₂ = I₁(I₁−I₂)ω₁² + I₃(I₃−I₂)ω₃²`
    /// (moments sorted `I₁ ≤ I₂ ≤ I₃`; L&L §37): a value within 4ε of the magnitude of its two
    /// terms is treated as the separatrix. Errors on non-finite input, non-positive moments or
    /// moments violating the triangle inequality.
    pub fn new(
        moments_p: Vector3<f64>,
        omega0_p: Vector3<f64>,
        q0: UnitQuaternion<f64>,
    ) -> Result<Self, ExactError> {
        check_moments(&[moments_p.x, moments_p.y, moments_p.z])?;
        if omega0_p.iter().any(|x| !x.is_finite()) {
            return Err(ExactError::NonFinite("initial angular velocity omega0_p"));
        }
        if q0.coords.iter().any(|x| !x.is_finite()) {
            return Err(ExactError::NonFinite("initial attitude q0"));
        }
        let h0_p = moments_p.component_mul(&omega0_p);
        let h_s = q0 * h0_p;
        let energy = 0.5 * omega0_p.dot(&h0_p);
        // Work with ω scaled by a power of two to 1 ≤ max |ω_i| < 2 (exactly) so that squares neither underflow nor
        // overflow; every rate scales linearly with |ω|.
        let scale = pow2_floor(omega0_p.amax());
        let unit = if scale == 0.0 {
            Vector3::zeros()
        } else {
            omega0_p / scale
        };
        let omega0_norm = unit
            .iter()
            .fold(Dd::ZERO, |sum, &x| sum + Dd::from(x) * x)
            .sqrt()
            * scale;
        let regime = if scale == 0.0 {
            Regime::Stationary
        } else {
            match classify(&moments_p, &unit) {
                None => Regime::Stationary,
                Some((perm, axis3_user, separatrix)) => Regime::Elliptic(Box::new(Elliptic::new(
                    &moments_p, &unit, scale, &q0, perm, axis3_user, separatrix,
                )?)),
            }
        };
        Ok(Self {
            moments_p,
            omega0_p,
            q0,
            h_s,
            energy,
            omega0_norm,
            regime,
        })
    }

    /// The principal moments as given (user order).
    pub fn moments_p(&self) -> Vector3<f64> {
        self.moments_p
    }

    /// Which kind of motion this is.
    pub fn case(&self) -> TorqueFreeCase {
        match &self.regime {
            Regime::Stationary => TorqueFreeCase::Stationary,
            Regime::Elliptic(e) if e.separatrix => TorqueFreeCase::Separatrix,
            Regime::Elliptic(e) => TorqueFreeCase::Circulating { axis: e.axis3_user },
        }
    }

    /// The elliptic parameter `m = k²` of the Jacobi functions (L&L §37, `k²` for `M² > 2EI₂`,
    /// indices 1 ↔ 3 exchanged otherwise): `Some(1.0)` on the separatrix, `None` when
    /// stationary.
    pub fn elliptic_parameter(&self) -> Option<f64> {
        match &self.regime {
            Regime::Stationary => None,
            Regime::Elliptic(e) => Some(e.jac.m()),
        }
    }

    /// Angular velocity in principal axes at time `t` (L&L §37, see the module
    /// docs): `ω₁ = a cn τ`, `ω₂ = ε b sn τ`, `ω₃ = c dn τ` in the canonical frame, `τ = λt + τ₀`.
    pub fn omega_p(&self, t: f64) -> Vector3<f64> {
        match &self.regime {
            Regime::Stationary => self.omega0_p,
            Regime::Elliptic(e) => {
                let (s, c, d, _) = e.functions(t);
                e.perm.transpose() * Vector3::new(e.a * c, e.eps * e.b * s, e.c * d)
            }
        }
    }

    /// Angular velocity in space axes, `ω_s(t) = q(t) * ω_p(t)`.
    pub fn omega_s(&self, t: f64) -> Vector3<f64> {
        self.attitude(t) * self.omega_p(t)
    }

    /// Moment of momentum in principal axes, `H_p(t) = I · ω_p(t)`.
    pub fn h_p(&self, t: f64) -> Vector3<f64> {
        self.moments_p.component_mul(&self.omega_p(t))
    }

    /// Moment of momentum in space axes, `H_s = q0 * (I · ω0_p)`; constant (no torque).
    pub fn h_s(&self) -> Vector3<f64> {
        self.h_s
    }

    /// Kinetic energy `E = ½ ω_p · I ω_p` (constant).
    pub fn energy(&self) -> f64 {
        self.energy
    }

    /// Period of `ω_p(t)`: `4K(m)/λ` (L&L §37: "the period of the functions sn, cn is 4K").
    /// For the symmetric cases (`m = 0`) this is `2π/|Ω_b|`, `Ω_b = (I₃ − I₁)ω₃/I₁`.
    /// `None` on the separatrix (not periodic) and for stationary motion (ω constant).
    pub fn period_omega(&self) -> Option<f64> {
        match &self.regime {
            Regime::Elliptic(e) if !e.separatrix => Some(4.0 * e.jac.quarter_period() / e.lambda),
            _ => None,
        }
    }

    /// `2K(m)/λ`: the time between successive sign changes of each of the two components of
    /// `ω_p` transverse to the axis ω circulates around (see [`TorqueFreeCase::Circulating`];
    /// the circulation-axis component never changes sign). One of the two is always the
    /// intermediate axis, whose component ∝ `sn τ` vanishes at `τ = 2jK`; the other ∝ `cn τ`
    /// vanishes at `τ = (2j+1)K`. Near the separatrix (tennis-racket / Dzhanibekov regime)
    /// the intermediate-axis component is nearly a square wave that flips sign every
    /// `flip_interval`. `None` where [`Self::period_omega`] is `None`.
    pub fn flip_interval(&self) -> Option<f64> {
        self.period_omega().map(|p| 0.5 * p)
    }

    /// The attitude `q(t)` (principal → space), satisfying `q̇ = ½ q ⊗ (0, ω_p)`.
    ///
    /// Construction (L&L §37; Celledoni et al. 2008): `q(t) = Q ⊗ R_z(φ) R_x(θ) R_z(ψ) ⊗ P`
    /// with `P` the user → canonical permutation, `Q` a constant rotation taking the space
    /// direction of H to `Q e_z` (fixed by `q(0) = q0`), and z-x-z Euler angles of the canonical
    /// body relative to the frame whose z axis is H:
    ///
    /// ```text
    ///   M sinθ sinψ = I₁ω₁,   M sinθ cosψ = I₂ω₂,   M cosθ = I₃ω₃          (L&L §37)
    ///   dφ/dt = M (I₁ω₁² + I₂ω₂²)/(I₁²ω₁² + I₂²ω₂²)
    ///         = M/I₃ + M(I₃ − I₁)/(I₁I₃) · 1/(1 − n sn²τ),   n = −I₃(I₂−I₁)/(I₁(I₃−I₂)) ≤ 0
    ///   φ(t)  = (M/I₁) t + M(I₃−I₁)/(I₁I₃λ) · [Π(am τ, n|m) − Π(am τ₀, n|m) − (τ − τ₀)]
    /// ```
    ///
    /// `Π` is evaluated through Carlson's form (DLMF §19.25(i)–(ii))
    /// `Π(am r, n|m) = r + (n/3) s³ R_J(c², d², 1, 1 − n s²)` with `(s, c, d)` = sn, cn, dn of the
    /// reduced argument `r ∈ [−K, K]`, and continued across half periods by
    /// `Π(jπ + x) = 2jΠ(n|m) + Π(x)` with `Π(n|m) = K + (n/3) R_J(0, m′, 1, 1 − n)`; with
    /// `n ≤ 0` there is no pole. `ψ` is unwrapped the same way (it turns by `∓π` per half period
    /// of τ), so `q(t)` is continuous in `t` (no sign flips). On the separatrix the Π-integral is
    /// elementary: `∫₀^τ du/(1 + ν tanh²u) = (τ + √ν atan(√ν tanh τ))/(1 + ν)`, `ν = −n`.
    ///
    /// Accuracy: φ grows without bound (≈ 600 rad after 100 s for the benchmark body), so in binary64 its rounding
    /// alone would be ε·φ. It is split into a secular part, `(M/I₁)·t + 2j·κR_J(0, m′, 1, 1−n)` (j the half-period
    /// count of τ), and a bounded periodic rest. The secular rates come from the exact inputs in double-double
    /// (K and Π by the AGM, DLMF 19.8.5–19.8.7; Dekker 1971), the secular angle is formed and reduced modulo 4π
    /// in double-double, and only then rounded; likewise `τ = λt + τ₀` and its reduction `τ − 2jK`. What is left
    /// is bounded: a few ε times `4π + |κ| R_J`, independent of t while the double-double's own `2⁻¹⁰⁶·φ` stays below
    /// that (φ up to ~1e16 rad). Stationary rotations take the angle `|ω₀|·t` the same way.
    pub fn attitude(&self, t: f64) -> UnitQuaternion<f64> {
        match &self.regime {
            Regime::Stationary => {
                let w = self.omega0_norm.hi;
                if w == 0.0 {
                    self.q0
                } else {
                    // The angle |ω₀|·t in double-double, reduced modulo 4π (the quaternion's period).
                    let angle = (self.omega0_norm * t).reduce(FOUR_PI).hi;
                    self.q0 * axis_angle_quat(&(self.omega0_p / w), angle)
                }
            }
            Regime::Elliptic(e) => e.q_fixed * e.q_h(t) * e.q_perm,
        }
    }
}

/// `(−1)^j`: sn and cn change sign with each half period 2K (DLMF §22.4(iii)).
pub(super) fn half_period_sign(j: f64) -> f64 {
    if (j as i64) & 1 == 1 { -1.0 } else { 1.0 }
}

/// The largest power of two ≤ x (x ≥ 0 finite; 0 for 0): dividing by it is exact.
fn pow2_floor(x: f64) -> f64 {
    let bits = x.to_bits();
    if bits >> 52 == 0 {
        // Zero or subnormal: keep the leading bit.
        if bits == 0 {
            0.0
        } else {
            f64::from_bits(1 << (63 - bits.leading_zeros()))
        }
    } else {
        f64::from_bits(bits & (0x7ff << 52))
    }
}

/// Decide the motion type. Returns `None` for stationary motion, else the user → canonical
/// signed permutation, the user index of canonical axis 3, and whether it is the separatrix.
fn classify(moments: &Vector3<f64>, omega: &Vector3<f64>) -> Option<(Matrix3<f64>, usize, bool)> {
    if omega.iter().all(|&w| w == 0.0) {
        return None;
    }
    let mut idx = [0usize, 1, 2];
    idx.sort_by(|&i, &j| moments[i].total_cmp(&moments[j]));
    let mut perm = Matrix3::zeros();
    for (row, &col) in idx.iter().enumerate() {
        perm[(row, col)] = 1.0;
    }
    if perm.determinant() < 0.0 {
        perm.row_mut(2).neg_mut();
    }
    let j = Vector3::new(moments[idx[0]], moments[idx[1]], moments[idx[2]]);
    let w = perm * omega;
    if j.x == j.z {
        return None; // spherical
    }
    let t3 = j.z * (j.z - j.y) * w.z * w.z;
    let t1 = j.x * (j.y - j.x) * w.x * w.x;
    let delta = t3 - t1; // M² − 2E·I₂
    let tol = 4.0 * f64::EPSILON * (t3 + t1);
    let (mut perm, axis3_user, separatrix) = if delta > tol {
        if w.x == 0.0 && w.y == 0.0 {
            return None; // pure rotation about the largest axis
        }
        (perm, idx[2], false)
    } else if delta < -tol {
        if w.z == 0.0 && w.y == 0.0 {
            return None; // pure rotation about the smallest axis
        }
        // (x, y, z) → (z, y, −x): a proper rotation putting the smallest axis third.
        let swap = Matrix3::new(0.0, 0.0, 1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0);
        (swap * perm, idx[0], false)
    } else {
        // |M² − 2E·I₂| at rounding level: ω in a degenerate plane of a symmetric body,
        // along the intermediate axis, or on the separatrix.
        if j.x == j.y || j.y == j.z || w.x == 0.0 || w.z == 0.0 {
            return None;
        }
        (perm, idx[2], true)
    };
    // Half-turns about canonical axes 1 and 3 to make ω₃ > 0 and ω₁ ≥ 0.
    let wc = perm * omega;
    if wc.z < 0.0 {
        perm = Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, -1.0)) * perm;
    }
    let wc = perm * omega;
    if wc.x < 0.0 {
        perm = Matrix3::from_diagonal(&Vector3::new(-1.0, -1.0, 1.0)) * perm;
    }
    Some((perm, axis3_user, separatrix))
}

/// The initial phase τ₀ of the elliptic functions from (cn τ₀, sn τ₀) ∝ (`x`, `y`) = (ω₁/a, ε ω₂/b), cn τ₀ ≥ 0:
/// τ₀ = F(φ₀|m) = sin φ₀ R_F(cos²φ₀, cos²φ₀ + m′ sin²φ₀, 1) (DLMF 19.25.5, homogeneous form), atanh(sin φ₀) on
/// the separatrix (m = 1).
fn initial_phase(x: f64, y: f64, mc: f64, separatrix: bool) -> Result<f64, ExactError> {
    let r = x.hypot(y);
    let (s0, c0) = (y / r, x / r);
    Ok(if separatrix {
        s0.atanh()
    } else if s0 == 0.0 {
        0.0
    } else {
        s0 * ellip::elliprf(c0 * c0, c0 * c0 + mc * s0 * s0, 1.0).map_err(ExactError::Numerical)?
    })
}

/// The constants of the motion in double-double (module docs; L&L §37), from the canonical moments and
/// `w = ω₀/scale` — exact, `scale` being a power of two — so that the secular rates are good to ~1e-30 relative
/// and `λt`, `j·2K` and the precession angle's secular part stay exact to ~1e-30·t: amplitudes, λ and |H| in
/// physical units (they scale with |ω|; m, m′, n do not).
struct Constants {
    a: Dd,
    b: Dd,
    c: Dd,
    lambda: Dd,
    m: Dd,
    mc: Dd,
    n: Dd,
    h_norm: Dd,
    /// `M(I₃ − I₁)/(I₁I₃λ)`, the coefficient of `∫dτ/(1 − n sn²τ)` in φ.
    coef_pi: Dd,
}

impl Constants {
    fn new(i: [f64; 3], w: [f64; 3], scale: f64, separatrix: bool) -> Self {
        let [i1, i2, i3] = i.map(Dd::from);
        let [w1, w2, w3] = w.map(|x| Dd::from(x) * x);
        let (d21, d31, d32) = (i2 - i1, i3 - i1, i3 - i2);
        let a2 = w1 + i2 * d32 / (i1 * d31) * w2;
        let b2 = i1 * d31 / (i2 * d32) * w1 + w2;
        let c2 = i2 * d21 / (i3 * d31) * w2 + w3;
        let denom = i3 * d32 * c2;
        let (m, mc) = if separatrix {
            (Dd::ONE, Dd::ZERO)
        } else {
            let m = i1 * d21 * a2 / denom;
            let mc = (i3 * d32 * w3 - i1 * d21 * w1) / denom;
            (m.clamp(0.0, 1.0), mc.clamp(0.0, 1.0))
        };
        let n = if d21.hi == 0.0 {
            Dd::ZERO
        } else {
            -(i3 * d21 / (i1 * d32))
        };
        let lambda = (c2 * d31 * d32 / (i1 * i2)).sqrt() * scale;
        let h_norm = (i1 * i1 * w1 + i2 * i2 * w2 + i3 * i3 * w3).sqrt() * scale;
        Self {
            a: a2.sqrt() * scale,
            b: b2.sqrt() * scale,
            c: c2.sqrt() * scale,
            lambda,
            m,
            mc,
            n,
            h_norm,
            coef_pi: h_norm * d31 / (i1 * i3 * lambda),
        }
    }
}

impl Elliptic {
    /// `omega_unit` is the initial ω divided by `scale` (a power of two, so the division is exact).
    fn new(
        moments: &Vector3<f64>,
        omega_unit: &Vector3<f64>,
        scale: f64,
        q0: &UnitQuaternion<f64>,
        perm: Matrix3<f64>,
        axis3_user: usize,
        separatrix: bool,
    ) -> Result<Self, ExactError> {
        let ic = perm.abs() * moments;
        let (i1, i2, i3) = (ic.x, ic.y, ic.z);
        let w = perm * omega_unit;
        let k = Constants::new([i1, i2, i3], [w.x, w.y, w.z], scale, separatrix);
        let eps = (i3 - i1).signum();
        let (m, mc) = (k.m.hi, k.mc.hi);
        let jac = JacobiElliptic::with_complement(m, mc)
            .or_else(|| JacobiElliptic::new(m))
            .ok_or(ExactError::Numerical("elliptic parameter out of [0, 1]"))?;
        let (a, b) = (k.a.hi, k.b.hi);
        let tau0 = initial_phase(w.x * scale / a, eps * w.y * scale / b, mc, separatrix)?;
        let amp = [i1 * a, i2 * b, i3 * k.c.hi];
        let unit = 1.0 / pow2_floor(amp[0].max(amp[1]).max(amp[2]));
        let unit = if unit.is_finite() { unit } else { 1.0 };
        let mut e = Self {
            perm,
            axis3_user,
            inertia: [i1, i2, i3],
            h_amp: amp.map(|v| v * unit),
            a,
            b,
            c: k.c.hi,
            eps,
            lambda: k.lambda.hi,
            lambda_dd: k.lambda,
            two_k: Dd::ZERO,
            tau0,
            separatrix,
            jac,
            n: k.n.hi,
            phi_rate: k.h_norm / Dd::from(i1),
            phi_per_half_period: Dd::ZERO,
            kappa: (k.coef_pi * k.n).hi / 3.0,
            rj_complete: 0.0,
            g0: 0.0,
            sep_atan: 0.0,
            sqrt_nu: 0.0,
            q_fixed: UnitQuaternion::identity(),
            q_perm: UnitQuaternion::identity(),
        };
        e.init_precession(&k);
        let q_perm = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(perm));
        let q_h0 = e.q_h(0.0);
        e.q_fixed = q0 * q_perm.inverse() * q_h0.inverse();
        e.q_perm = q_perm;
        Ok(e)
    }

    /// The constants of the precession angle's integral ∫dτ/(1 − n sn²): on the separatrix (sn = tanh, n = −ν)
    /// its closed form in atan, `φ = sep_lin·t + sep_atan·(atan(√ν tanh τ) − g₀)` with
    /// `sep_lin = M/I₃ + M(I₃ − I₁)/(I₁I₃(1 + ν))`; elsewhere the half period 2K, Π(n|m) − K = (n/3) R_J(0, m′, 1, 1 − n)
    /// (DLMF §19.25(i)) and the integral's value at τ₀, with K and Π by the AGM in double-double.
    fn init_precession(&mut self, k: &Constants) {
        let tau0 = self.tau0;
        let i3 = self.inertia[2];
        if self.separatrix {
            let nu = -self.n;
            self.sqrt_nu = nu.sqrt();
            self.phi_rate = k.h_norm / Dd::from(i3) + k.coef_pi * k.lambda / (Dd::ONE - k.n);
            self.sep_atan = k.coef_pi.hi * self.sqrt_nu / (1.0 + nu);
            self.g0 = (self.sqrt_nu * tau0.tanh()).atan();
            return;
        }
        let (quarter, pi_n) = complete_k_pi(k.mc, k.n);
        self.two_k = quarter * 2.0;
        if self.n != 0.0 {
            let pi_minus_k = pi_n - quarter;
            self.phi_per_half_period = k.coef_pi * pi_minus_k * 2.0;
            self.rj_complete = (pi_minus_k * 3.0 / k.n).hi;
            let (s, c, d, _) = self.reduced(tau0);
            self.g0 = self.g_integral(s, c, d, 0.0);
        }
    }

    /// τ(t) = λt + τ₀ in double-double (`t` exact).
    fn tau_dd(&self, t: f64) -> Dd {
        self.lambda_dd * t + self.tau0
    }

    /// τ(t) rounded, and sn, cn ≥ 0, dn of its reduced argument `r = τ − 2jK` with the half-period count j, τ and
    /// `j·2K` in double-double: `r` carries no error growing with t (binary64 would add ~ε·τ from λt and
    /// ~j·ulp(2K) from the reduction). On the separatrix nothing is reduced (j = 0).
    pub(super) fn phase(&self, t: f64) -> (f64, (f64, f64, f64, f64)) {
        let tau = self.tau_dd(t);
        (tau.hi, self.reduce_tau(tau).0)
    }

    /// sn, cn ≥ 0, dn of the reduced argument `r = τ − 2jK` of a double-double τ, with j; and the part of r below
    /// binary64 (its rounding, which the functions do not see).
    pub(super) fn reduce_tau(&self, tau: Dd) -> ((f64, f64, f64, f64), f64) {
        if self.separatrix {
            return (self.reduced(tau.hi), tau.lo);
        }
        let j = if tau.hi.abs() <= self.jac.quarter_period() {
            0.0
        } else {
            nearest_integer(tau.hi / self.two_k.hi)
        };
        let r = tau - self.two_k * j;
        let red = self.jac.at_reduced(j, r.hi);
        ((red.sn, red.cn, red.dn, red.j), r.lo)
    }

    /// sn, cn, dn of τ(t) (unreduced) and the half-period count j.
    fn functions(&self, t: f64) -> (f64, f64, f64, f64) {
        let (_, (s, c, d, j)) = self.phase(t);
        let sign = half_period_sign(j);
        (sign * s, sign * c, d, j)
    }

    /// sn, cn ≥ 0, dn of the reduced argument r (τ = 2jK + r) and j, τ in binary64 (for |τ| ≲ K or the separatrix).
    pub(super) fn reduced(&self, tau: f64) -> (f64, f64, f64, f64) {
        if self.separatrix {
            let sech = 1.0 / tau.cosh();
            (tau.tanh(), sech, sech, 0.0)
        } else {
            let red = self.jac.reduce(tau);
            (red.sn, red.cn, red.dn, red.j)
        }
    }

    /// `2j R_J(0, m′, 1, 1−n) + s³ R_J(c², d², 1, 1 − n s²)`, i.e. `(3/n)(Π(am τ, n|m) − τ)`.
    pub(super) fn g_integral(&self, s: f64, c: f64, d: f64, j: f64) -> f64 {
        let partial = if s == 0.0 {
            0.0
        } else {
            // Arguments are valid by construction (c², d² ≥ 0, d > 0 for m < 1, p ≥ 1).
            s * s * s * elliprj(c * c, d * d, 1.0, 1.0 - self.n * s * s).unwrap_or(f64::NAN)
        };
        2.0 * j * self.rj_complete + partial
    }

    /// The precession angle φ(t) about H, with φ(0) = 0, reduced modulo 4π (the period of `R_z(φ)`'s quaternion):
    /// the secular part `phi_rate·t + phi_per_half_period·j` (which grows with t) formed and reduced in
    /// double-double, then the bounded rest in binary64 — `κ(s³R_J(c², d², 1, 1 − n s²) − g₀)` (that part of
    /// `κ(g(τ) − g(τ₀))` which does not grow), or on the separatrix `sep_atan·(atan(√ν tanh τ) − g₀)`. So φ's error
    /// is a few ε·(4π + |κ| R_J), not ε·φ. `(s, c, d, j)` from [`Self::phase`].
    pub(super) fn phi(&self, t: f64, tau: f64, s: f64, c: f64, d: f64, j: f64) -> f64 {
        let secular = (self.phi_rate * t + self.phi_per_half_period * j)
            .reduce(FOUR_PI)
            .hi;
        if self.separatrix {
            let at = (self.sqrt_nu * tau.tanh()).atan();
            secular + self.sep_atan * (at - self.g0)
        } else if self.n == 0.0 {
            secular
        } else {
            secular + self.kappa * (self.g_integral(s, c, d, 0.0) - self.g0)
        }
    }

    /// `q_H(t) = R_z(φ) R_x(θ) R_z(ψ)`: canonical body → H frame, θ and ψ by [`Self::half_angles`] (no
    /// arctangent, no sine), φ's half-angle by one sine–cosine pair; normalised (the half-angle formulas leave the
    /// norm a few ε off 1, and the attitude's contract is a unit quaternion to 1e-15).
    fn q_h(&self, t: f64) -> UnitQuaternion<f64> {
        let (tau, (s, c, d, j)) = self.phase(t);
        let phi = self.phi(t, tau, s, c, d, j);
        let (sin_f, cos_f) = (0.5 * phi).sin_cos();
        let half = self.half_angles(c, s, d, j as i64);
        UnitQuaternion::new_normalize(precession_nutation_spin(cos_f, sin_f, half))
    }

    /// cos, sin of θ/2 and of ψ/2 for the Euler angles of [`TorqueFreeBody::attitude`] from `H_p`'s components
    /// `(x, y, z) = (I₁ω₁, I₂ω₂, I₃ω₃)` of the reduced argument, `(cn r, sn r, dn r)` times [`Self::h_amp`]
    /// (cn r ≥ 0 up to rounding), and the half-period count j (L&L §37: `M sinθ sinψ = I₁ω₁`,
    /// `M sinθ cosψ = I₂ω₂`, `M cosθ = I₃ω₃`): θ = atan2(√(x² + y²), z) ∈ [0, π/2), ψ = π/2 − ε(j·π + α),
    /// α = atan2(y, x) ∈ [−π/2, π/2]; cos(θ/2) = √((1 + cos θ)/2), sin(θ/2) = sin θ / (2 cos(θ/2)), and the same for
    /// α/2 (x ≤ 0 only where cn ≈ 0, and then |y| ≈ ρ, so √(2ρ(ρ + x)) > 0), then ψ/2 by the angle sum with
    /// π/4 − ε (j mod 4) π/2 (a multiple of π/2 plus π/4, whose cosine and sine are ±√½). x² + y² below 2⁻⁹⁶⁰ (ω
    /// within ~1e-144 of the axis it circulates around, relative) takes ρ by `hypot` and α/2 from (x, y)/ρ.
    #[inline]
    pub(super) fn half_angles(&self, cn: f64, sn: f64, dn: f64, j: i64) -> [f64; 4] {
        let [hx, hy, hz] = self.h_amp;
        let (x, y, z) = (hx * cn, hy * sn, hz * dn);
        let r2 = x * x + y * y;
        let (cos_t, sin_t, cos_a, sin_a) = if r2 >= TINY_SQUARE {
            let rho = r2.sqrt();
            let m_tot = (z * z + r2).sqrt();
            // cos(θ/2) = (M + z)/√(2M(M + z)), sin(θ/2) = ρ/√(2M(M + z)); the same for α/2 with (ρ, x): one division.
            let (p_t, p_a) = (m_tot + z, (rho + x).max(0.0));
            let (root_t, root_a) = ((2.0 * m_tot * p_t).sqrt(), (2.0 * rho * p_a).sqrt());
            let inv = 1.0 / (root_t * root_a);
            let (inv_t, inv_a) = (inv * root_a, inv * root_t);
            (p_t * inv_t, rho * inv_t, p_a * inv_a, y * inv_a)
        } else {
            tiny_half_angles(x, y, z)
        };
        // π/4 + q·π/2 with q = −ε·j mod 4: (cos, sin) = √½ (±1, ±1).
        let eps = self.eps;
        let q = if eps > 0.0 { (4 - (j & 3)) & 3 } else { j & 3 };
        let r = std::f64::consts::FRAC_1_SQRT_2;
        let (cos_g, sin_g) = match q {
            0 => (r, r),
            1 => (-r, r),
            2 => (-r, -r),
            _ => (r, -r),
        };
        let cos_p = cos_g * cos_a + eps * sin_g * sin_a;
        let sin_p = sin_g * cos_a - eps * cos_g * sin_a;
        [cos_t, sin_t, cos_p, sin_p]
    }
}

/// Below this `x² + y²` [`Elliptic::half_angles`] takes the scale-safe path (2⁻⁹⁶⁰: the squares keep ~60 bits of
/// headroom above the subnormals).
const TINY_SQUARE: f64 = 1.026_134_200_324_594_1e-289;

/// [`Elliptic::half_angles`]'s `(cos θ/2, sin θ/2, cos α/2, sin α/2)` where `x² + y²` is below [`TINY_SQUARE`]:
/// ρ = hypot(x, y) (no underflow) and α/2 from the unit vector (x, y)/ρ (α = 0 where ρ underflowed to 0).
#[cold]
fn tiny_half_angles(x: f64, y: f64, z: f64) -> (f64, f64, f64, f64) {
    let rho = x.hypot(y);
    let m_tot = z.hypot(rho);
    let root_t = (2.0 * m_tot * (m_tot + z)).sqrt();
    let (xn, yn) = if rho > 0.0 {
        (x / rho, y / rho)
    } else {
        (1.0, 0.0)
    };
    let p_a = (1.0 + xn).max(0.0);
    let root_a = (2.0 * p_a).sqrt();
    (
        (m_tot + z) / root_t,
        rho / root_t,
        p_a / root_a,
        yn / root_a,
    )
}

/// `R_z(φ) R_x(θ) R_z(ψ)` from the cosines and sines of φ/2 and of `[θ/2, ψ/2]` (as `[cos, sin, cos, sin]`):
/// `R_x(θ) R_z(ψ) = (cθ cψ, sθ cψ, −sθ sψ, cθ sψ)`, then `R_z(φ)` on the left.
#[inline]
pub(super) fn precession_nutation_spin(cos_f: f64, sin_f: f64, half: [f64; 4]) -> Quaternion<f64> {
    let [cos_t, sin_t, cos_p, sin_p] = half;
    let (w, i, j, k) = (cos_t * cos_p, sin_t * cos_p, -sin_t * sin_p, cos_t * sin_p);
    Quaternion::new(
        cos_f * w - sin_f * k,
        cos_f * i - sin_f * j,
        cos_f * j + sin_f * i,
        cos_f * k + sin_f * w,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn omega_a_hair_off_a_principal_axis_keeps_a_finite_attitude() {
        // ω = (1e-160, 0, 1) rad/s about the largest axis: elliptic (circulating about axis 3), but H_p's transverse
        // components square below 2⁻⁹⁶⁰, the half-angle formulas' scale-safe path. To far below 1e-15 the motion is
        // the steady rotation about axis 3 (L&L §37 with a → 0): q(t) = q₀ ⊗ (cos(t/2), 0, 0, sin(t/2)).
        let q0 = UnitQuaternion::from_euler_angles(0.3, -1.1, 2.4);
        let body = TorqueFreeBody::new(
            Vector3::new(1.0, 2.0, 3.0),
            Vector3::new(1e-160, 0.0, 1.0),
            q0,
        )
        .expect("valid body");
        assert_eq!(body.case(), TorqueFreeCase::Circulating { axis: 2 });
        for t in [0.0, 0.7, 3.1, 10.0, 100.0] {
            let want = q0 * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), t);
            let got = body.attitude(t);
            assert!(
                got.angle_to(&want) <= 1e-14,
                "t = {t}: {got:?} against {want:?}"
            );
            assert!((got.norm() - 1.0).abs() <= 1e-15);
        }
    }
}
