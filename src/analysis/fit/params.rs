//! What a fit estimates: the parameters `--estimate` names, the vector x the least squares move, the model at x,
//! and the reported values (the contract's names) with their derivatives in x.
//!
//! The inertia is I about C in body axes: its six entries (`inertia`), or the principal moments with the scene's
//! axes P held, I = P diag(I_k) Pᵀ (`principal`). The attitude at t = 0 is q₀ = q̂₀ ⊗ exp(δ/2), δ a turn in body
//! axes from the scene's q̂₀, whose derivative is q₀ ⊗ (0, J_r(δ) e_k)/2 with the right Jacobian of SO(3)
//! (Chirikjian, *Stochastic Models, Information Theory, and Lie Groups* II, §10.6; Solà, Deray & Atchuthan 2018,
//! eq. 143). When no moment fixes the inertia's scale, x holds one coordinate fewer: I_zz = trace − I_xx − I_yy,
//! or the largest principal moment kept.

use nalgebra::{DMatrix, DVector, Matrix3, UnitQuaternion, Vector3};

use super::model::Column;

/// A parameter group `--estimate` names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Estimate {
    /// The six entries of I about C in body axes.
    Inertia,
    /// The three principal moments, the scene's axes held.
    Principal,
    /// ω at t = 0, body axes.
    Omega0,
    /// The attitude at t = 0.
    Attitude0,
    /// A constant bias of the gyro, per body axis.
    GyroBias,
}

impl Estimate {
    /// The names `--estimate` takes, in order.
    pub const NAMES: [&'static str; 5] =
        ["inertia", "principal", "omega0", "attitude0", "gyro_bias"];

    /// The group named `name`.
    pub fn named(name: &str) -> Option<Self> {
        let all = [
            Self::Inertia,
            Self::Principal,
            Self::Omega0,
            Self::Attitude0,
            Self::GyroBias,
        ];
        (Self::NAMES.iter().position(|n| *n == name)).map(|k| all[k])
    }

    /// Its name in `--estimate`.
    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }
}

/// The entries of I in the contract's order, (row, column).
const ENTRIES: [(usize, usize); 6] = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)];
/// Their names.
const ENTRY_NAMES: [&str; 6] = ["I_xx", "I_yy", "I_zz", "I_xy", "I_xz", "I_yz"];
const AXES: [&str; 3] = ["x", "y", "z"];

/// One coordinate of x.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Coordinate {
    /// An entry of I (index into [`ENTRIES`]).
    Entry(usize),
    /// A principal moment.
    Moment(usize),
    /// ω₀ along a body axis.
    Omega0(usize),
    /// δ's component along a body axis.
    Turn(usize),
    /// The gyro's bias along a body axis.
    Bias(usize),
}

/// The parameters of one fit: what is estimated, where it starts, and the layout of x.
#[derive(Debug, Clone)]
pub struct Parameters {
    /// The groups estimated.
    pub estimates: Vec<Estimate>,
    /// The scene's I about C, body axes.
    pub inertia0: Matrix3<f64>,
    /// The scene's principal axes (columns, body axes) and moments.
    pub axes: Matrix3<f64>,
    moments0: Vector3<f64>,
    /// The scene's ω₀, body axes.
    pub omega0: Vector3<f64>,
    /// The scene's q₀.
    pub q0: UnitQuaternion<f64>,
    /// Whether the inertia's scale is held (no moment fixes it).
    pub scale_held: bool,
    coordinates: Vec<Coordinate>,
}

impl Parameters {
    /// The parameters of `estimates` starting at the scene's values; `scale_held` drops one inertia coordinate.
    pub fn new(
        estimates: &[Estimate],
        inertia0: Matrix3<f64>,
        omega0: Vector3<f64>,
        q0: UnitQuaternion<f64>,
        scale_held: bool,
    ) -> Self {
        let principal = crate::body::Principal::of(&inertia0);
        let moments0 = principal.moments;
        let largest = moments0.imax();
        let mut coordinates = Vec::new();
        for estimate in estimates {
            match estimate {
                Estimate::Inertia => coordinates.extend(
                    (0..6)
                        .filter(|&k| !(scale_held && k == 2))
                        .map(Coordinate::Entry),
                ),
                Estimate::Principal => coordinates.extend(
                    (0..3)
                        .filter(|&k| !(scale_held && k == largest))
                        .map(Coordinate::Moment),
                ),
                Estimate::Omega0 => coordinates.extend((0..3).map(Coordinate::Omega0)),
                Estimate::Attitude0 => coordinates.extend((0..3).map(Coordinate::Turn)),
                Estimate::GyroBias => coordinates.extend((0..3).map(Coordinate::Bias)),
            }
        }
        Self {
            estimates: estimates.to_vec(),
            inertia0,
            axes: *principal.axes_b.matrix(),
            moments0,
            omega0,
            q0,
            scale_held,
            coordinates,
        }
    }

    /// The same parameters with the scale held or not.
    pub fn with_scale_held(&self, scale_held: bool) -> Self {
        Self::new(
            &self.estimates,
            self.inertia0,
            self.omega0,
            self.q0,
            scale_held,
        )
    }

    /// Whether `estimate` is among the estimated.
    pub fn has(&self, estimate: Estimate) -> bool {
        self.estimates.contains(&estimate)
    }

    /// The length of x.
    pub fn len(&self) -> usize {
        self.coordinates.len()
    }

    /// Whether nothing is estimated.
    pub fn is_empty(&self) -> bool {
        self.coordinates.is_empty()
    }

    /// x at the scene's values.
    pub fn start(&self) -> DVector<f64> {
        DVector::from_iterator(
            self.len(),
            self.coordinates.iter().map(|c| match *c {
                Coordinate::Entry(k) => self.inertia0[ENTRIES[k]],
                Coordinate::Moment(k) => self.moments0[k],
                Coordinate::Omega0(k) => self.omega0[k],
                Coordinate::Turn(_) | Coordinate::Bias(_) => 0.0,
            }),
        )
    }

    /// I about C at x.
    pub fn inertia(&self, x: &DVector<f64>) -> Matrix3<f64> {
        let mut inertia = self.inertia0;
        if self.has(Estimate::Principal) {
            let mut moments = self.moments0;
            for (c, v) in self.coordinates.iter().zip(x.iter()) {
                if let Coordinate::Moment(k) = *c {
                    moments[k] = *v;
                }
            }
            inertia = self.axes * Matrix3::from_diagonal(&moments) * self.axes.transpose();
        }
        for (c, v) in self.coordinates.iter().zip(x.iter()) {
            if let Coordinate::Entry(k) = *c {
                let (r, s) = ENTRIES[k];
                inertia[(r, s)] = *v;
                inertia[(s, r)] = *v;
            }
        }
        if self.has(Estimate::Inertia) && self.scale_held {
            inertia[(2, 2)] = self.inertia0.trace() - inertia[(0, 0)] - inertia[(1, 1)];
        }
        inertia
    }

    /// ω₀ at x.
    pub fn omega0(&self, x: &DVector<f64>) -> Vector3<f64> {
        let mut omega = self.omega0;
        for (c, v) in self.coordinates.iter().zip(x.iter()) {
            if let Coordinate::Omega0(k) = *c {
                omega[k] = *v;
            }
        }
        omega
    }

    /// δ at x.
    fn turn(&self, x: &DVector<f64>) -> Vector3<f64> {
        let mut turn = Vector3::zeros();
        for (c, v) in self.coordinates.iter().zip(x.iter()) {
            if let Coordinate::Turn(k) = *c {
                turn[k] = *v;
            }
        }
        turn
    }

    /// q₀ = q̂₀ ⊗ exp(δ/2) at x.
    pub fn q0(&self, x: &DVector<f64>) -> UnitQuaternion<f64> {
        self.q0 * UnitQuaternion::from_scaled_axis(self.turn(x))
    }

    /// The gyro's bias at x (zero when it is not estimated).
    pub fn bias(&self, x: &DVector<f64>) -> Vector3<f64> {
        let mut bias = Vector3::zeros();
        for (c, v) in self.coordinates.iter().zip(x.iter()) {
            if let Coordinate::Bias(k) = *c {
                bias[k] = *v;
            }
        }
        bias
    }

    /// The variational equations' columns at x, one per coordinate that enters the dynamics (in x's order), and
    /// for each coordinate of x its column's index (`None` for a bias).
    pub fn columns(&self, x: &DVector<f64>) -> (Vec<Column>, Vec<Option<usize>>) {
        let jr = right_jacobian(&self.turn(x));
        let mut columns = Vec::new();
        let index = (self.coordinates.iter())
            .map(|c| {
                let column = match *c {
                    Coordinate::Entry(k) => Column::Inertia(self.entry_direction(k)),
                    Coordinate::Moment(k) => {
                        let p = self.axes.column(k);
                        Column::Inertia(p * p.transpose())
                    }
                    Coordinate::Omega0(k) => Column::Omega0(k),
                    Coordinate::Turn(k) => Column::Attitude0(jr.column(k).into()),
                    Coordinate::Bias(_) => return None,
                };
                columns.push(column);
                Some(columns.len() - 1)
            })
            .collect();
        (columns, index)
    }

    /// ∂I/∂x for the entry k (with I_zz following I_xx and I_yy when the trace is held).
    fn entry_direction(&self, k: usize) -> Matrix3<f64> {
        let (r, s) = ENTRIES[k];
        let mut e = Matrix3::zeros();
        e[(r, s)] = 1.0;
        e[(s, r)] = 1.0;
        if self.scale_held && r == s {
            e[(2, 2)] -= 1.0;
        }
        e
    }

    /// The index in x of the coordinate that is the gyro's bias along axis k.
    pub fn bias_index(&self, k: usize) -> Option<usize> {
        (self.coordinates.iter()).position(|c| *c == Coordinate::Bias(k))
    }

    /// The names of x's coordinates (a turn of q₀ as `turn0_x..z`).
    pub fn coordinate_names(&self) -> Vec<String> {
        (self.coordinates.iter())
            .map(|c| match *c {
                Coordinate::Entry(k) => ENTRY_NAMES[k].to_string(),
                Coordinate::Moment(k) => format!("I_{}", k + 1),
                Coordinate::Omega0(k) => format!("omega0_{}", AXES[k]),
                Coordinate::Turn(k) => format!("turn0_{}", AXES[k]),
                Coordinate::Bias(k) => format!("bias_{}", AXES[k]),
            })
            .collect()
    }

    /// The typical size of each coordinate of x: the inertia's entries and moments a third of its trace, ω₀
    /// and the bias |ω₀| (1e-3 rad/s at least), a turn of q₀ 1 rad.
    pub fn scales(&self) -> DVector<f64> {
        let inertia = self.inertia0.trace() / 3.0;
        let rate = self.omega0.norm().max(1e-3);
        DVector::from_iterator(
            self.len(),
            self.coordinates.iter().map(|c| match c {
                Coordinate::Entry(_) | Coordinate::Moment(_) => inertia,
                Coordinate::Omega0(_) | Coordinate::Bias(_) => rate,
                Coordinate::Turn(_) => 1.0,
            }),
        )
    }

    /// The index in x of coordinate `c`.
    fn at(&self, c: Coordinate) -> Option<usize> {
        self.coordinates.iter().position(|d| *d == c)
    }

    /// A gradient in x with the entries `pairs` (index, value).
    fn gradient(&self, pairs: &[(usize, f64)]) -> DVector<f64> {
        let mut r = DVector::zeros(self.len());
        for &(i, v) in pairs {
            r[i] += v;
        }
        r
    }

    /// The reported parameters (the contract's names) at x: names, values, and their derivatives in x.
    pub fn reported(&self, x: &DVector<f64>) -> Vec<Reported> {
        let mut out = Vec::new();
        if self.has(Estimate::Inertia) {
            let inertia = self.inertia(x);
            for (k, name) in ENTRY_NAMES.iter().enumerate() {
                let gradient = match self.at(Coordinate::Entry(k)) {
                    Some(i) => self.gradient(&[(i, 1.0)]),
                    None => {
                        let xx = self.at(Coordinate::Entry(0)).expect("I_xx is free");
                        let yy = self.at(Coordinate::Entry(1)).expect("I_yy is free");
                        self.gradient(&[(xx, -1.0), (yy, -1.0)])
                    }
                };
                let (start, value) = (self.inertia0[ENTRIES[k]], inertia[ENTRIES[k]]);
                out.push(Reported::new(name, start, value, gradient));
            }
        }
        if self.has(Estimate::Principal) {
            for k in 0..3 {
                let (value, gradient) = match self.at(Coordinate::Moment(k)) {
                    Some(i) => (x[i], self.gradient(&[(i, 1.0)])),
                    None => (self.moments0[k], self.gradient(&[])),
                };
                let name = format!("I_{}", k + 1);
                out.push(Reported::new(&name, self.moments0[k], value, gradient));
            }
        }
        for (estimate, prefix, of) in [
            (
                Estimate::Omega0,
                "omega0",
                Coordinate::Omega0 as fn(usize) -> Coordinate,
            ),
            (Estimate::GyroBias, "bias", Coordinate::Bias),
        ] {
            if !self.has(estimate) {
                continue;
            }
            for (k, axis) in AXES.iter().enumerate() {
                let i = self.at(of(k)).expect("free");
                let start = if estimate == Estimate::Omega0 {
                    self.omega0[k]
                } else {
                    0.0
                };
                let name = format!("{prefix}_{axis}");
                out.push(Reported::new(
                    &name,
                    start,
                    x[i],
                    self.gradient(&[(i, 1.0)]),
                ));
            }
        }
        if self.has(Estimate::Attitude0) {
            out.extend(self.reported_q0(x));
        }
        out
    }

    /// q₀'s components and their derivatives ½ q₀ ⊗ (0, J_r(δ) e_k) in δ.
    fn reported_q0(&self, x: &DVector<f64>) -> Vec<Reported> {
        let q = self.q0(x);
        let qa = [q.w, q.i, q.j, q.k];
        let start = [self.q0.w, self.q0.i, self.q0.j, self.q0.k];
        let jr = right_jacobian(&self.turn(x));
        let d: Vec<[f64; 4]> = (0..3)
            .map(|k| crate::motion::free::quaternion_rate(&qa, &jr.column(k).into()))
            .collect();
        (0..4)
            .map(|c| {
                let pairs: Vec<(usize, f64)> = (0..3)
                    .map(|k| (self.at(Coordinate::Turn(k)).expect("free"), d[k][c]))
                    .collect();
                let name = format!("q0_{}", ["w", "x", "y", "z"][c]);
                Reported::new(&name, start[c], qa[c], self.gradient(&pairs))
            })
            .collect()
    }
}

/// A reported parameter: its name, start, estimate and derivative in x.
#[derive(Debug, Clone, PartialEq)]
pub struct Reported {
    /// The contract's name.
    pub name: String,
    /// The scene's value.
    pub start: f64,
    /// The estimate.
    pub estimate: f64,
    /// ∂estimate/∂x.
    pub gradient: DVector<f64>,
}

impl Reported {
    fn new(name: &str, start: f64, estimate: f64, gradient: DVector<f64>) -> Self {
        Self {
            name: name.to_string(),
            start,
            estimate,
            gradient,
        }
    }
}

/// ⌊φ⌋×, the cross-product matrix.
fn cross_matrix(phi: &Vector3<f64>) -> Matrix3<f64> {
    phi.cross_matrix()
}

/// The right Jacobian of SO(3), J_r(φ) = I − (1 − cos θ)/θ² ⌊φ⌋× + (θ − sin θ)/θ³ ⌊φ⌋×² (Solà et al. 2018,
/// eq. 143), by its series below θ = 1e-4.
pub fn right_jacobian(phi: &Vector3<f64>) -> Matrix3<f64> {
    let theta = phi.norm();
    let k = cross_matrix(phi);
    let (a, b) = if theta < 1e-4 {
        (
            0.5 - theta * theta / 24.0,
            1.0 / 6.0 - theta * theta / 120.0,
        )
    } else {
        let t2 = theta * theta;
        (
            (1.0 - theta.cos()) / t2,
            (theta - theta.sin()) / (t2 * theta),
        )
    };
    Matrix3::identity() - k * a + k * k * b
}

/// The inverse of the right Jacobian, J_r⁻¹(φ) = I + ½ ⌊φ⌋× + (1/θ² − (1 + cos θ)/(2 θ sin θ)) ⌊φ⌋×² (Solà et al.
/// 2018, eq. 144), by its series below θ = 1e-4.
pub fn right_jacobian_inverse(phi: &Vector3<f64>) -> Matrix3<f64> {
    let theta = phi.norm();
    let k = cross_matrix(phi);
    let c = if theta < 1e-4 {
        1.0 / 12.0 + theta * theta / 720.0
    } else {
        1.0 / (theta * theta) - (1.0 + theta.cos()) / (2.0 * theta * theta.sin())
    };
    Matrix3::identity() + k * 0.5 + k * k * c
}

/// The covariance of the reported parameters, G C Gᵀ with G their derivatives in x.
pub fn reported_covariance(reported: &[Reported], covariance: &DMatrix<f64>) -> DMatrix<f64> {
    let g = DMatrix::from_fn(reported.len(), covariance.nrows(), |r, c| {
        reported[r].gradient[c]
    });
    &g * covariance * g.transpose()
}
