//! The integration methods and the two implementations of the Runge–Kutta ones: one type each, used by the scene,
//! the integrators, the study and the command line alike.

use crate::named::{Named, serde_by_name};

/// An integration method, by its scene-file name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Method {
    /// Classical Runge–Kutta of order 4 (HNW I §II.1, Table 1.2), fixed step h ≤ `dt`: between consecutive rows
    /// t_a < t_b it takes n = ⌈(t_b − t_a)/dt⌉ equal steps h = (t_b − t_a)/n at times t_a + i·h.
    Rk4,
    /// Dormand–Prince 5(4) (HNW I §II.5, Table 5.2) with FSAL (6 evaluations per step), local extrapolation, the
    /// error norm of HNW I eq. (4.11) and Hairer's `dopri5.f` controller: safety 0.9, 0.2 ≤ h_new/h ≤ 10, PI (Lund)
    /// stabilisation β = 0.04 (HNW II §IV.2), exponent 1/5 − 0.75β.
    Dopri5,
    /// Dormand–Prince 8(5,3) with Hairer's `dop853.f` coefficients and error estimator (12 stages, 12 evaluations
    /// per accepted step, HNW I §II.5), controller safety 0.9, 1/3 ≤ h_new/h ≤ 6, β = 0, exponent 1/8.
    Dop853,
    /// Lie–Poisson splitting of the free body into exact planar rotations, Strang composition, order 2
    /// (McLachlan 1993; Touma & Wisdom 1994), fixed step `dt`; effects applied as kicks. Preserves |H| exactly and
    /// H_s to round-off when torque-free; energy error bounded. See [`crate::motion::lie_poisson`].
    Split2,
    /// An order-4 composition of `split2`: Suzuki's fractal S(ph)S(ph)S((1−4p)h)S(ph)S(ph), p = 1/(4 − 4^{1/3})
    /// (Suzuki 1990, Phys. Lett. A 146, 319), fixed step `dt`.
    Split4,
    /// The torque-free flow in closed form (Landau & Lifshitz §37; Celledoni, Fassò, Säfström & Zanna 2008), no
    /// stepping: the rows of the equal grid advanced by the addition theorems of the closed form (DLMF 22.8) and
    /// re-anchored to its direct evaluation every 256 rows, the last row evaluated directly. Torque-free scenes only.
    /// See [`crate::motion::exact_flow`].
    Exact,
}

impl Method {
    /// Every method, in the order they are listed to users.
    pub const ALL: [Method; 6] = [
        Method::Rk4,
        Method::Dopri5,
        Method::Dop853,
        Method::Split2,
        Method::Split4,
        Method::Exact,
    ];

    /// The method a scene gets when it names none.
    pub const DEFAULT: Method = Method::Dop853;

    /// The name used in scene files and on the command line.
    ///
    /// ```
    /// use eulerdyn::Method;
    /// assert_eq!(Method::Dop853.name(), "dop853");
    /// ```
    pub fn name(&self) -> &'static str {
        match self {
            Method::Rk4 => "rk4",
            Method::Dopri5 => "dopri5",
            Method::Dop853 => "dop853",
            Method::Split2 => "split2",
            Method::Split4 => "split4",
            Method::Exact => "exact",
        }
    }

    /// Whether the method takes steps of the fixed size `dt` (rk4, split2, split4). The adaptive methods adapt
    /// their step to `rtol`/`atol`; `exact` takes no steps.
    pub fn is_fixed_step(&self) -> bool {
        matches!(self, Method::Rk4 | Method::Split2 | Method::Split4)
    }

    /// Whether the method adapts its step to `rtol`/`atol` (dopri5, dop853).
    pub fn is_adaptive(&self) -> bool {
        matches!(self, Method::Dopri5 | Method::Dop853)
    }

    /// Whether the method is a Runge–Kutta method, run by either backend (`own` or `ode_solvers`). The splitting
    /// methods and `exact` are the project's own only.
    pub fn is_runge_kutta(&self) -> bool {
        matches!(self, Method::Rk4 | Method::Dopri5 | Method::Dop853)
    }

    /// The order p of the method: its global error is O(dt^p) for the fixed-step methods; for the adaptive ones
    /// the order of the propagated solution. `None` for `exact` (round-off only).
    pub fn order(&self) -> Option<u32> {
        match self {
            Method::Rk4 | Method::Split4 => Some(4),
            Method::Split2 => Some(2),
            Method::Dopri5 => Some(5),
            Method::Dop853 => Some(8),
            Method::Exact => None,
        }
    }
}

impl Named for Method {
    const ALL: &'static [Self] = &Method::ALL;

    fn name(&self) -> &'static str {
        Method::name(self)
    }
}

serde_by_name!(Method);

/// Which implementation runs the Runge–Kutta methods.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Backend {
    /// The project's own tableaus (streaming, exact row times, projection after every step, no heap allocation
    /// per step). The default.
    #[default]
    Own,
    /// The same method through the ode_solvers 0.6.2 crate, with its known defects worked around (a cross-check;
    /// see [`crate::integrate::ode_solvers_path`]).
    OdeSolvers,
}

impl Backend {
    /// Both backends, the default first.
    pub const ALL: [Backend; 2] = [Backend::Own, Backend::OdeSolvers];

    /// The name used in scene files and on the command line.
    ///
    /// ```
    /// assert_eq!(eulerdyn::Backend::OdeSolvers.name(), "ode_solvers");
    /// ```
    pub fn name(&self) -> &'static str {
        match self {
            Backend::Own => "own",
            Backend::OdeSolvers => "ode_solvers",
        }
    }
}

impl Named for Backend {
    const ALL: &'static [Self] = &Backend::ALL;

    fn name(&self) -> &'static str {
        Backend::name(self)
    }
}

serde_by_name!(Backend);

/// The solver settings a scene gets for what it leaves out: `method` [`Method::DEFAULT`], body form, own
/// backend, and these tolerances and step.
pub mod defaults {
    /// Relative tolerance of the adaptive methods.
    pub const RTOL: f64 = 1e-10;
    /// Absolute tolerance of the adaptive methods.
    pub const ATOL: f64 = 1e-12;
    /// Largest step of the fixed-step methods (s).
    pub const DT: f64 = 1e-3;
    /// Most attempted steps of one run.
    pub const MAX_STEPS: u64 = 100_000_000;
    /// Largest allowed difference for `eulerdyn compare`.
    pub const COMPARE_TOLERANCE: f64 = 1e-8;
}
