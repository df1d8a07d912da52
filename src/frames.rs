//! Two words for two things that are easily spelled alike: the axes a vector is expressed in, and the form of Euler's
//! equation that is integrated. A vector `v_b` is in [`Axes::Body`], `v_s` in [`Axes::Space`]; the attitude
//! `r_sb` (the quaternion q) maps body to space, `v_s = r_sb · v_b`.

use crate::named::{Named, serde_by_name};

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
