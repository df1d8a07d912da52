//! The support of a body turning about an axis fixed in space: what the bearings and the drive must supply.
//!
//! With the effects' force and moment about the axis point A (F_eff, M_eff), Newton's and Euler's laws (eqs. 8.7,
//! 8.9) give the support's share:
//!
//! ```text
//!   F_sup = m a_C − F_eff,        M_sup = dH_A/dt − M_eff,
//! ```
//!
//! the drive supplies the axial part M_sup·u and the bearings the rest. Bearing A at r_A = a u and bearing B at
//! r_B = b u (a ≠ b, measured from A along u) carry
//!
//! ```text
//!   R_A + R_B = F_sup,            r_A × R_A + r_B × R_B = M_sup − (M_sup·u) u,
//! ```
//!
//! with the axial thrust F_sup·u taken by A. Crossing the second with u: a R_A⊥ + b R_B⊥ = M_sup × u =: W, so
//! R_B⊥ = (W − a F⊥)/(b − a) and R_A⊥ = (b F⊥ − W)/(b − a).

use nalgebra::Vector3;

/// Two bearings on the axis, at `a` (bearing A) and `b` (bearing B) metres from the axis point along the axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bearings {
    /// Axial position of bearing A (m).
    pub a: f64,
    /// Axial position of bearing B (m), ≠ a.
    pub b: f64,
}

impl Bearings {
    /// The forces (R_A, R_B) the bearings apply to the body, in the axes `f_sup`, `m_sup` and the unit axis `u`
    /// are given in, for the support force `f_sup` and the support moment `m_sup` about the axis point.
    ///
    /// ```
    /// use eulerdyn::motion::support::Bearings;
    /// use nalgebra::Vector3;
    /// // A weight of 10 N hanging at the axis point between bearings at −1 m and +3 m: the lever rule.
    /// let (r_a, r_b) = Bearings { a: -1.0, b: 3.0 }.split(
    ///     &Vector3::new(0.0, 0.0, 10.0),
    ///     &Vector3::zeros(),
    ///     &Vector3::x(),
    /// );
    /// assert!((r_a.z - 7.5).abs() < 1e-15 && (r_b.z - 2.5).abs() < 1e-15);
    /// ```
    pub fn split(
        &self,
        f_sup: &Vector3<f64>,
        m_sup: &Vector3<f64>,
        u: &Vector3<f64>,
    ) -> (Vector3<f64>, Vector3<f64>) {
        let thrust = u * f_sup.dot(u);
        let f_perp = f_sup - thrust;
        let w = m_sup.cross(u);
        let span = self.b - self.a;
        let r_b = (w - f_perp * self.a) / span;
        let r_a = (f_perp * self.b - w) / span + thrust;
        (r_a, r_b)
    }
}
