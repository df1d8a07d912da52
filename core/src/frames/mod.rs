//! Two words for two things that are easily spelled alike: the axes a vector is expressed in, and the form of Euler's
//! equation that is integrated. A vector `v_b` is in [`Axes::Body`], `v_s` in [`Axes::Space`]; the attitude
//! `r_sb` (the quaternion q) maps body to space, `v_s = r_sb · v_b`. A [`Vector`] carries its axes in its type
//! (`Vector<BodyAxes>`, `Vector<SpaceAxes>`, `Vector<SupportAxes>`).

mod vector;

use nalgebra::{Matrix3, Quaternion, Vector3};

use crate::named::{Named, serde_by_name};

pub use vector::{BodyAxes, Frame, SpaceAxes, SupportAxes, Vector};

/// The axes a vector is expressed in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Axes {
    /// Axes fixed in the body: the axes the scene's inertia is given in, origin at the mass center C.
    Body,
    /// The inertial frame.
    Space,
}

impl Axes {
    /// The name used in scene files (`frame = "body"`).
    ///
    /// ```
    /// assert_eq!(eulerdyn::Axes::Space.name(), "space");
    /// ```
    pub fn name(&self) -> &'static str {
        match self {
            Axes::Body => "body",
            Axes::Space => "space",
        }
    }
}

impl Named for Axes {
    const ALL: &'static [Self] = &[Axes::Body, Axes::Space];

    fn name(&self) -> &'static str {
        Axes::name(self)
    }
}

serde_by_name!(Axes);

/// The form of Euler's equation that is integrated (or, for prescribed motion, that computes the moment).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Form {
    /// In body axes, state (ω_b, q): I ω̇ + ω × I ω = M_b, q̇ = ½ q ⊗ (0, ω_b).
    Body,
    /// In space axes, state (H_s, q): Ḣ_s = M_s with ω_s = R I⁻¹ Rᵀ H_s, i.e. M = d/dt(I_s(θ) ω_s) (eq. 8.10).
    Space,
}

impl Form {
    /// Both forms, body first.
    pub const ALL: [Form; 2] = [Form::Body, Form::Space];

    /// The first three states of this form: ω_b, or H_s = `h_s()` (computed only for the space form).
    ///
    /// ```
    /// use eulerdyn::Form;
    /// use nalgebra::Vector3;
    /// let omega_b = Vector3::new(1.0, 0.0, 0.0);
    /// assert_eq!(Form::Body.first_states(&omega_b, || unreachable!()), omega_b);
    /// assert_eq!(Form::Space.first_states(&omega_b, || omega_b * 2.0), omega_b * 2.0);
    /// ```
    pub fn first_states(
        self,
        omega_b: &Vector3<f64>,
        h_s: impl FnOnce() -> Vector3<f64>,
    ) -> Vector3<f64> {
        match self {
            Form::Body => *omega_b,
            Form::Space => h_s(),
        }
    }

    /// The name used in scene files and on the command line (`solver.frame`, `--frame`).
    ///
    /// ```
    /// assert_eq!(eulerdyn::Form::Body.name(), "body");
    /// ```
    pub fn name(&self) -> &'static str {
        match self {
            Form::Body => "body",
            Form::Space => "space",
        }
    }
}

impl Named for Form {
    const ALL: &'static [Self] = &Form::ALL;

    fn name(&self) -> &'static str {
        Form::name(self)
    }
}

serde_by_name!(Form);

/// The rotation R of the attitude held in a state, q = (w, x, y, z) of norm near but not exactly 1, without
/// normalising q first: R(q/|q|) = A(q) / |q|², with A(q) the quadratic form
///
/// A = [w²+x²−y²−z², 2(xy−wz), 2(xz+wy); 2(xy+wz), w²−x²+y²−z², 2(yz−wx); 2(xz−wy), 2(yz+wx), w²−x²−y²+z²].
///
/// The square root and divisions of a normalisation would sit on the path from one stage to the next; here the
/// one division, 1/|q|², is computed alongside the products.
#[derive(Debug, Clone, Copy)]
pub struct StateRotation {
    a: Matrix3<f64>,
    inv_norm2: f64,
}

impl StateRotation {
    /// The rotation of a state's quaternion part q_state = (w, x, y, z).
    #[inline(always)]
    pub fn of(q_state: &Quaternion<f64>) -> Self {
        let (w, x, y, z) = (q_state.w, q_state.i, q_state.j, q_state.k);
        let (ww, xx, yy, zz) = (w * w, x * x, y * y, z * z);
        let (xy, xz, yz) = (x * y, x * z, y * z);
        let (wx, wy, wz) = (w * x, w * y, w * z);
        Self {
            a: Matrix3::new(
                ww + xx - yy - zz,
                2.0 * (xy - wz),
                2.0 * (xz + wy),
                2.0 * (xy + wz),
                ww - xx + yy - zz,
                2.0 * (yz - wx),
                2.0 * (xz - wy),
                2.0 * (yz + wx),
                ww - xx - yy + zz,
            ),
            inv_norm2: 1.0 / ((ww + xx) + (yy + zz)),
        }
    }

    /// v_b = Rᵀ v_s.
    #[inline(always)]
    pub fn to_body(&self, v_s: &Vector3<f64>) -> Vector3<f64> {
        self.a.tr_mul(v_s) * self.inv_norm2
    }

    /// v_s = R v_b.
    #[inline(always)]
    pub fn to_space(&self, v_b: &Vector3<f64>) -> Vector3<f64> {
        (self.a * v_b) * self.inv_norm2
    }
}
