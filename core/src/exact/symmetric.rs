//! Symmetric bodies (`I₁ = I₂ = I_t` transverse, `I₃ = I_a` axial) in closed form.
//!
//! **Convention: the symmetry axis is principal (body) axis 3, the body z axis.** Inputs
//! and outputs in principal axes (`_p`) are ordered (transverse x, transverse y, axial z).
//! For a symmetric body with the symmetry axis elsewhere, relabel the axes (or use
//! [`crate::exact::TorqueFreeBody`], which accepts moments in any order).
//!
//! - [`SymmetricTorqueFree`]: torque-free precession (Goldstein, Poole & Safko, *Classical
//!   Mechanics*, 3rd ed., §5.6; Landau & Lifshitz, *Mechanics*, §33 and §37).
//! - [`AxialTorqueSymmetric`]: constant torque about the symmetry axis (Euler's equations
//!   integrated directly).
//! - [`HeavySymmetricTop`] / [`SteadyPrecession`]: the heavy symmetric top on a fixed pivot
//!   in steady precession (Goldstein §5.7).

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::{ExactError, axis_angle_quat, check_moments};

fn check_finite(values: &[f64], what: &'static str) -> Result<(), ExactError> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(ExactError::NonFinite(what))
    }
}

/// Rotate the transverse part `(x, y)` of `v` by `angle` about z.
fn rotate_z(v: &Vector3<f64>, angle: f64) -> Vector3<f64> {
    let (s, c) = angle.sin_cos();
    Vector3::new(c * v.x - s * v.y, s * v.x + c * v.y, v.z)
}

/// A torque-free symmetric body (`I₁ = I₂ = i_t`, `I₃ = i_a`, symmetry axis = body z).
///
/// Goldstein, Poole & Safko 3rd ed. §5.6 (torque-free motion; the symmetric case): `ω₃` is
/// constant and the transverse part of `ω_p` rotates in the body
/// about the symmetry axis at `Ω_b = (I₃ − I₁)/I₁ · ω₃`; in space, ω and the symmetry axis
/// precess uniformly about the fixed `H_s` at `|H|/I₁` (L&L §33). Writing
/// `ω_p = H_p/I₁ − Ω_b e₃`, the attitude is the composition of two uniform rotations,
///
/// ```text
///   q(t) = Rot(Ĥ_s, |H| t / I₁) ⊗ q₀ ⊗ Rot(e₃, −Ω_b t).
/// ```
///
/// With rotors on the symmetry axis holding a constant relative momentum h = Σ J_k Ω_k (a symmetric gyrostat,
/// [`SymmetricTorqueFree::gyrostat`]), H_p = (I₁ω₁, I₁ω₂, I₃ω₃ + h): ω₃ stays constant and the transverse ω turns at
/// λ = ((I₃ − I₁)ω₃ + h)/I₁ (Hughes, *Spacecraft Attitude Dynamics*, 1986, §3.5, the axisymmetric gyrostat), and
/// `ω_p = H_p/I₁ − λ e₃` gives the attitude in the same form with λ for Ω_b.
#[derive(Debug, Clone, PartialEq)]
pub struct SymmetricTorqueFree {
    i_t: f64,
    i_a: f64,
    /// h, the rotors' axial momentum relative to the body (0 for a rigid body).
    h_rotor: f64,
    omega0_p: Vector3<f64>,
    q0: UnitQuaternion<f64>,
    h_s: Vector3<f64>,
}

impl SymmetricTorqueFree {
    /// `i_t` transverse moment (axes 1, 2), `i_a` axial moment (axis 3), `omega0_p` initial
    /// angular velocity in principal axes, `q0` initial attitude (principal → space).
    /// Errors on non-finite input, non-positive moments, or `i_a > 2 i_t` (triangle
    /// inequality).
    pub fn new(
        i_t: f64,
        i_a: f64,
        omega0_p: Vector3<f64>,
        q0: UnitQuaternion<f64>,
    ) -> Result<Self, ExactError> {
        check_moments(&[i_t, i_t, i_a])?;
        check_finite(omega0_p.as_slice(), "initial angular velocity omega0_p")?;
        check_finite(q0.coords.as_slice(), "initial attitude q0")?;
        let h_s = q0 * Vector3::new(i_t * omega0_p.x, i_t * omega0_p.y, i_a * omega0_p.z);
        Ok(Self {
            i_t,
            i_a,
            h_rotor: 0.0,
            omega0_p,
            q0,
            h_s,
        })
    }

    /// A symmetric gyrostat: the body as in [`Self::new`] (with its rotors locked) and rotors on the symmetry axis
    /// whose relative momentum `h_rotor` = Σ J_k Ω_k (N·m·s) stays constant (see the type docs).
    ///
    /// ```
    /// use eulerdyn::exact::SymmetricTorqueFree;
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// let g = SymmetricTorqueFree::gyrostat(2.0, 3.0, 0.5, Vector3::new(0.1, 0.0, 1.0), UnitQuaternion::identity())
    ///     .unwrap();
    /// assert_eq!(g.body_precession_rate(), ((3.0 - 2.0) * 1.0 + 0.5) / 2.0);
    /// ```
    pub fn gyrostat(
        i_t: f64,
        i_a: f64,
        h_rotor: f64,
        omega0_p: Vector3<f64>,
        q0: UnitQuaternion<f64>,
    ) -> Result<Self, ExactError> {
        check_finite(&[h_rotor], "rotor momentum h")?;
        let body = Self::new(i_t, i_a, omega0_p, q0)?;
        Ok(Self {
            h_rotor,
            h_s: body.h_s + q0 * Vector3::new(0.0, 0.0, h_rotor),
            ..body
        })
    }

    /// Body-frame precession rate of ω about the symmetry axis,
    /// `Ω_b = (I₃ − I₁)/I₁ · ω₃` (Goldstein 3rd ed. §5.6, the Ω of the symmetric torque-free
    /// solution).
    pub fn body_precession_rate(&self) -> f64 {
        if self.h_rotor == 0.0 {
            (self.i_a - self.i_t) / self.i_t * self.omega0_p.z
        } else {
            ((self.i_a - self.i_t) * self.omega0_p.z + self.h_rotor) / self.i_t
        }
    }

    /// Space-frame precession rate of ω and of the symmetry axis about `H_s`, `|H|/I₁`
    /// (L&L §33; the "space cone" rate).
    pub fn space_precession_rate(&self) -> f64 {
        self.h_s.norm() / self.i_t
    }

    /// Half-angle of the body cone: the angle between ω and the symmetry axis,
    /// `atan2(|ω⊥|, ω₃)` (Goldstein §5.6).
    pub fn body_cone_half_angle(&self) -> f64 {
        self.omega0_p.xy().norm().atan2(self.omega0_p.z)
    }

    /// `H_p` at t = 0: (I₁ω₁, I₁ω₂, I₃ω₃ + h).
    fn h0_p(&self) -> Vector3<f64> {
        let w = self.omega0_p;
        Vector3::new(
            self.i_t * w.x,
            self.i_t * w.y,
            self.i_a * w.z + self.h_rotor,
        )
    }

    /// Half-angle of the space cone: the angle between ω and `H_s`, i.e. between ω and `H_p`.
    pub fn space_cone_half_angle(&self) -> f64 {
        let (w, h) = (self.omega0_p, self.h0_p());
        w.cross(&h).norm().atan2(w.dot(&h))
    }

    /// Nutation angle: the constant angle between the symmetry axis and `H_s`,
    /// `atan2(I₁|ω⊥|, I₃ω₃ + h)`.
    pub fn nutation_angle(&self) -> f64 {
        let h = self.h0_p();
        h.xy().norm().atan2(h.z)
    }

    /// `ω_p(t)`: `ω₃` constant, `(ω₁ + iω₂)(t) = (ω₁ + iω₂)(0) e^{iΩ_b t}` (Goldstein §5.6).
    pub fn omega_p(&self, t: f64) -> Vector3<f64> {
        rotate_z(&self.omega0_p, self.body_precession_rate() * t)
    }

    /// `ω_s(t) = q(t) * ω_p(t)`: precesses about `H_s` at [`Self::space_precession_rate`].
    pub fn omega_s(&self, t: f64) -> Vector3<f64> {
        self.attitude(t) * self.omega_p(t)
    }

    /// `H_s = q₀ * (I ω₀_p + h e₃)` (constant).
    pub fn h_s(&self) -> Vector3<f64> {
        self.h_s
    }

    /// Kinetic energy `½ ω·Iω` (constant), the rigid body's: a gyrostat's wheels add `h ω₃ + ½ Σ J_k Ω_k²`.
    pub fn energy(&self) -> f64 {
        let w = self.omega0_p;
        0.5 * (self.i_t * (w.x * w.x + w.y * w.y) + self.i_a * w.z * w.z)
    }

    /// Exact attitude `q(t) = Rot(Ĥ_s, |H|t/I₁) ⊗ q₀ ⊗ Rot(e₃, −Ω_b t)` (see the type docs;
    /// follows from `ω_p = H_p/I₁ − Ω_b e₃`, L&L §33).
    pub fn attitude(&self, t: f64) -> UnitQuaternion<f64> {
        let h = self.h_s.norm();
        let body = axis_angle_quat(&Vector3::z(), -self.body_precession_rate() * t);
        if h == 0.0 {
            return self.q0;
        }
        axis_angle_quat(&(self.h_s / h), h / self.i_t * t) * self.q0 * body
    }
}

/// A symmetric body (`I₁ = I₂ = i_t`, `I₃ = i_a`, symmetry axis = body z) under a constant
/// torque `M₃` about its symmetry axis (torque fixed in the body).
///
/// Euler's equations `I₁ω̇₁ = (I₁ − I₃)ω₂ω₃`, `I₁ω̇₂ = (I₃ − I₁)ω₃ω₁`, `I₃ω̇₃ = M₃`
/// (Goldstein 3rd ed. §5.5, Euler's equations, with `N₁ = N₂ = 0`) integrate to
///
/// ```text
///   ω₃(t) = ω₃(0) + M₃ t / I₃,
///   (ω₁ + iω₂)(t) = (ω₁ + iω₂)(0) e^{iα(t)},   α(t) = (I₃ − I₁)/I₁ · (ω₃(0) t + M₃ t²/(2 I₃)).
/// ```
///
/// No attitude is provided: with ω₃ linear in time the attitude problem is a linearly swept
/// two-level (Landau–Zener) problem whose solution needs parabolic-cylinder functions.
#[derive(Debug, Clone, PartialEq)]
pub struct AxialTorqueSymmetric {
    i_t: f64,
    i_a: f64,
    torque3: f64,
    omega0_p: Vector3<f64>,
}

impl AxialTorqueSymmetric {
    /// `torque3` is the constant axial torque `M₃` (body axis 3). Errors as
    /// [`SymmetricTorqueFree::new`].
    pub fn new(
        i_t: f64,
        i_a: f64,
        torque3: f64,
        omega0_p: Vector3<f64>,
    ) -> Result<Self, ExactError> {
        check_moments(&[i_t, i_t, i_a])?;
        check_finite(&[torque3], "axial torque")?;
        check_finite(omega0_p.as_slice(), "initial angular velocity omega0_p")?;
        Ok(Self {
            i_t,
            i_a,
            torque3,
            omega0_p,
        })
    }

    /// The applied torque in principal axes, `(0, 0, M₃)`.
    pub fn torque_p(&self) -> Vector3<f64> {
        Vector3::new(0.0, 0.0, self.torque3)
    }

    /// The body-frame rotation angle of the transverse part of ω,
    /// `α(t) = (I₃ − I₁)/I₁ · ∫₀ᵗ ω₃ dt = (I₃ − I₁)/I₁ · (ω₃(0) t + M₃ t²/(2I₃))`.
    pub fn transverse_angle(&self, t: f64) -> f64 {
        let integral = t * (self.omega0_p.z + 0.5 * self.torque3 * t / self.i_a);
        (self.i_a - self.i_t) / self.i_t * integral
    }

    /// `ω_p(t)` (see the type docs).
    pub fn omega_p(&self, t: f64) -> Vector3<f64> {
        let mut w = rotate_z(&self.omega0_p, self.transverse_angle(t));
        w.z = self.omega0_p.z + self.torque3 * t / self.i_a;
        w
    }
}

/// A heavy symmetric top on a fixed, frictionless pivot on its symmetry axis.
///
/// Body axis 3 is the symmetry axis, pointing from the pivot O to the mass centre C, which
/// lies at `r_C = l e₃` (`l` may be negative: C below the pivot along −e₃). `i_t` is the
/// transverse moment *about the pivot* (`I_t = I_t,C + m l²`), `i_a` the axial moment.
/// Space axes: z up, gravity `(0, 0, −g)`. The torque about O is `r_C × m g`, in body axes
/// `τ_p = l e₃ × (−m g R(t)ᵀ e_z)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeavySymmetricTop {
    i_t: f64,
    i_a: f64,
    mass: f64,
    gravity: f64,
    l: f64,
}

/// Roots of the steady-precession condition `m g l = Ω (I₃ω₃ − I_t Ω cos θ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PrecessionRoots {
    /// No real root (discriminant negative: spin too slow for steady precession at this tilt).
    None,
    /// A single root (`cos θ = 0`, or a double root).
    One(f64),
    /// Two roots, ordered by magnitude: `slow` (≈ `m g l/(I₃ω₃)` for a fast top) and `fast`
    /// (≈ `I₃ω₃/(I_t cos θ)`).
    Two {
        /// The smaller |Ω|.
        slow: f64,
        /// The larger |Ω|.
        fast: f64,
    },
}

impl HeavySymmetricTop {
    /// `i_t`: transverse moment about the pivot; `i_a`: axial moment; `mass`; `gravity` g
    /// (≥ 0); `l`: signed distance from the pivot to C along the symmetry axis.
    pub fn new(i_t: f64, i_a: f64, mass: f64, gravity: f64, l: f64) -> Result<Self, ExactError> {
        check_moments(&[i_t, i_t, i_a])?;
        check_finite(&[mass, gravity, l], "mass, gravity and pivot distance")?;
        if mass <= 0.0 {
            return Err(ExactError::NonPositive {
                what: "mass",
                value: mass,
            });
        }
        if gravity < 0.0 {
            return Err(ExactError::InvalidArgument("gravity must be >= 0"));
        }
        Ok(Self {
            i_t,
            i_a,
            mass,
            gravity,
            l,
        })
    }

    /// Transverse moment about the pivot.
    pub fn i_t(&self) -> f64 {
        self.i_t
    }

    /// Axial moment.
    pub fn i_a(&self) -> f64 {
        self.i_a
    }

    /// `m g l`.
    pub fn mgl(&self) -> f64 {
        self.mass * self.gravity * self.l
    }

    /// Mass centre in principal axes, `(0, 0, l)`.
    pub fn r_c_p(&self) -> Vector3<f64> {
        Vector3::new(0.0, 0.0, self.l)
    }

    /// Gravity torque about the pivot in principal axes for attitude `q` (principal → space):
    /// `τ_p = r_C,p × (m · qᵀ(0, 0, −g))`.
    pub fn torque_p(&self, q: &UnitQuaternion<f64>) -> Vector3<f64> {
        let g_p = q.inverse() * Vector3::new(0.0, 0.0, -self.gravity);
        self.r_c_p().cross(&(self.mass * g_p))
    }

    /// Steady-precession rates Ω for tilt `theta` (symmetry axis from the upward vertical)
    /// and axial spin `omega3` (component of ω along the symmetry axis).
    ///
    /// From the θ equation of motion of the Lagrangian
    /// `L = ½I_t(θ̇² + φ̇² sin²θ) + ½I₃(ψ̇ + φ̇ cos θ)² − m g l cos θ` (Goldstein 3rd ed. §5.7,
    /// the heavy symmetric top with one point fixed) with `θ̇ = θ̈ = 0`, `φ̇ = Ω`,
    /// `ω₃ = ψ̇ + φ̇ cos θ`:
    ///
    /// ```text
    ///   m g l = Ω (I₃ ω₃ − I_t Ω cos θ)   ⇔   I_t cos θ · Ω² − I₃ω₃ Ω + m g l = 0.
    /// ```
    ///
    /// Roots by the cancellation-free quadratic formula. `theta` must lie in `(0, π)`
    /// (at `sin θ = 0` every Ω is formally steady).
    pub fn steady_precession_rates(
        &self,
        theta: f64,
        omega3: f64,
    ) -> Result<PrecessionRoots, ExactError> {
        check_finite(&[theta, omega3], "tilt and spin")?;
        if !(theta > 0.0 && theta < std::f64::consts::PI) {
            return Err(ExactError::InvalidArgument(
                "tilt theta must lie in (0, pi)",
            ));
        }
        let a = self.i_t * theta.cos();
        let b = -self.i_a * omega3;
        let c = self.mgl();
        if a == 0.0 {
            return Ok(if b == 0.0 {
                PrecessionRoots::None
            } else {
                PrecessionRoots::One(-c / b)
            });
        }
        let disc = b * b - 4.0 * a * c;
        if disc < 0.0 {
            return Ok(PrecessionRoots::None);
        }
        if disc == 0.0 {
            return Ok(PrecessionRoots::One(-b / (2.0 * a)));
        }
        let sign_b = if b >= 0.0 { 1.0 } else { -1.0 };
        let q = -0.5 * (b + sign_b * disc.sqrt());
        let (r1, r2) = (q / a, c / q);
        let (slow, fast) = if r1.abs() <= r2.abs() {
            (r1, r2)
        } else {
            (r2, r1)
        };
        Ok(PrecessionRoots::Two { slow, fast })
    }

    /// Residual of the steady-precession condition, `Ω(I₃ω₃ − I_t Ω cos θ) − m g l`.
    pub fn steady_precession_residual(&self, theta: f64, omega3: f64, rate: f64) -> f64 {
        rate * (self.i_a * omega3 - self.i_t * rate * theta.cos()) - self.mgl()
    }
}

/// A heavy symmetric top in steady precession: uniform precession about the vertical at Ω,
/// constant tilt θ, uniform spin `ψ̇ = ω₃ − Ω cos θ` (Goldstein 3rd ed. §5.7).
///
/// With z-x-z Euler angles (space z up; `q = R_z(φ) R_x(θ) R_z(ψ)`, the convention of
/// Goldstein 3rd ed. §4.4 and L&L §35):
///
/// ```text
///   φ(t) = φ₀ + Ω t,   θ(t) = θ,   ψ(t) = ψ₀ + (ω₃ − Ω cos θ) t
///   ω_p(t) = (Ω sin θ sin ψ, Ω sin θ cos ψ, ω₃)     (L&L §35 kinematic equations, θ̇ = 0)
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyPrecession {
    top: HeavySymmetricTop,
    theta: f64,
    omega3: f64,
    rate: f64,
    /// φ₀ and ψ₀.
    angles0: (f64, f64),
}

impl SteadyPrecession {
    /// Steady precession of `top` at tilt `theta`, spin `omega3`, precession rate `rate`
    /// (normally one of [`HeavySymmetricTop::steady_precession_rates`]), initial Euler angles
    /// `phi0`, `psi0`. Errors unless `rate` satisfies the steady-precession condition to a
    /// relative `1e-9` (of the largest term).
    pub fn new(
        top: HeavySymmetricTop,
        theta: f64,
        omega3: f64,
        rate: f64,
        phi0: f64,
        psi0: f64,
    ) -> Result<Self, ExactError> {
        check_finite(
            &[theta, omega3, rate, phi0, psi0],
            "steady precession state",
        )?;
        if !(theta > 0.0 && theta < std::f64::consts::PI) {
            return Err(ExactError::InvalidArgument(
                "tilt theta must lie in (0, pi)",
            ));
        }
        let scale = (rate * top.i_a * omega3)
            .abs()
            .max((top.i_t * rate * rate * theta.cos()).abs())
            .max(top.mgl().abs());
        let residual = top.steady_precession_residual(theta, omega3, rate);
        if residual.abs() > 1e-9 * scale {
            return Err(ExactError::InvalidArgument(
                "rate does not satisfy m g l = rate (I3 omega3 - It rate cos theta)",
            ));
        }
        Ok(Self {
            top,
            theta,
            omega3,
            rate,
            angles0: (phi0, psi0),
        })
    }

    /// The top.
    pub fn top(&self) -> &HeavySymmetricTop {
        &self.top
    }

    /// Spin rate relative to the precessing frame, `ψ̇ = ω₃ − Ω cos θ`.
    pub fn spin_rate(&self) -> f64 {
        self.omega3 - self.rate * self.theta.cos()
    }

    /// The Euler angles `(φ, θ, ψ)` at time `t` (unwrapped).
    pub fn euler_angles(&self, t: f64) -> (f64, f64, f64) {
        (
            self.angles0.0 + self.rate * t,
            self.theta,
            self.angles0.1 + self.spin_rate() * t,
        )
    }

    /// `ω_p(t) = (Ω sin θ sin ψ, Ω sin θ cos ψ, ω₃)`.
    pub fn omega_p(&self, t: f64) -> Vector3<f64> {
        let (_, theta, psi) = self.euler_angles(t);
        let (sp, cp) = psi.sin_cos();
        let wt = self.rate * theta.sin();
        Vector3::new(wt * sp, wt * cp, self.omega3)
    }

    /// The initial angular velocity that starts the steady motion, `ω_p(0)`.
    pub fn omega0_p(&self) -> Vector3<f64> {
        self.omega_p(0.0)
    }

    /// Exact attitude `q(t) = R_z(φ₀ + Ωt) R_x(θ) R_z(ψ₀ + ψ̇t)` (principal → space).
    pub fn attitude(&self, t: f64) -> UnitQuaternion<f64> {
        let (phi, theta, psi) = self.euler_angles(t);
        let qz = |a: f64| axis_angle_quat(&Vector3::z(), a);
        let qx = axis_angle_quat(&Vector3::x(), theta);
        let q: Quaternion<f64> = (qz(phi) * qx * qz(psi)).into_inner();
        UnitQuaternion::new_normalize(q)
    }

    /// Gravity torque about the pivot in principal axes at time `t`.
    pub fn torque_p(&self, t: f64) -> Vector3<f64> {
        self.top.torque_p(&self.attitude(t))
    }
}
