//! A circular orbit about the Earth (`[orbit]`) and its local-vertical local-horizontal frame: where the
//! environment's effects take the body (`gravity_gradient`) and the axes the `*_lvlh` columns and initial values are
//! given in. Space axes are Earth-centred inertial.
//!
//! On the orbit, at argument of latitude u = u₀ + n t with n = √(μ/r³), the position is r = r R_z(Ω) R_x(i)
//! (cos u, sin u, 0). The LVLH frame (Hughes, *Spacecraft Attitude Dynamics*, 1986, §8.1) has z to nadir (−r̂),
//! y against the orbit normal (−ĥ) and x = y × z along the velocity; it turns at n ĥ in space.

mod columns;
mod field;
mod keys;

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

use crate::text::for_people;

pub use columns::{field_columns, lvlh_columns};
pub use field::{DEFAULT_B0, DipoleField, EARTH_RATE};
pub(crate) use keys::FieldKeys;
pub(crate) use keys::validate_orbit;
pub use keys::{FieldSpec, OrbitSize, OrbitSpec};

/// The Earth's gravitational parameter μ (m³/s², EGM96/WGS 84).
pub const MU_EARTH: f64 = 3.986004418e14;
/// The Earth's equatorial radius (m, WGS 84).
pub const R_EARTH: f64 = 6378.137e3;

/// A circular orbit of radius r about the Earth, its plane at inclination i and right ascension of the ascending
/// node Ω, the body at argument of latitude u₀ at t = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircularOrbit {
    radius: f64,
    mean_motion: f64,
    arg_lat0: f64,
    inclination: f64,
    raan: f64,
    /// The orbit's plane axes (x to the ascending node, z along the orbit normal) in space: R_z(Ω) R_x(i).
    plane_s: Rotation3<f64>,
}

impl CircularOrbit {
    /// The orbit of radius `radius` (m, from the Earth's centre), inclination, RAAN and argument of latitude at
    /// t = 0 (rad); n = √(μ/r³).
    ///
    /// ```
    /// use eulerdyn::orbit::{CircularOrbit, R_EARTH};
    /// let leo = CircularOrbit::new(R_EARTH + 500e3, 97.4_f64.to_radians(), 0.0, 0.0);
    /// assert!((2.0 * std::f64::consts::PI / leo.mean_motion() / 60.0 - 94.6).abs() < 0.1); // minutes
    /// ```
    pub fn new(radius: f64, inclination: f64, raan: f64, arg_lat0: f64) -> Self {
        let plane_s = Rotation3::from_axis_angle(&Vector3::z_axis(), raan)
            * Rotation3::from_axis_angle(&Vector3::x_axis(), inclination);
        CircularOrbit {
            radius,
            mean_motion: (MU_EARTH / radius.powi(3)).sqrt(),
            arg_lat0,
            inclination,
            raan,
            plane_s,
        }
    }

    /// The orbit in words, as `eulerdyn check` prints it.
    ///
    /// ```
    /// use eulerdyn::orbit::{CircularOrbit, R_EARTH};
    /// let leo = CircularOrbit::new(R_EARTH + 500e3, 97.4_f64.to_radians(), 0.0, 0.0);
    /// assert!(leo.describe().starts_with("circular, r = 6878.14 km (altitude 500 km), inclination 97.4 deg"));
    /// ```
    pub fn describe(&self) -> String {
        format!(
            "circular, r = {} km (altitude {} km), inclination {} deg, RAAN {} deg, argument of latitude {} deg at \
             t = 0; period {} min (n = {} rad/s)",
            for_people(self.radius / 1e3),
            for_people((self.radius - R_EARTH) / 1e3),
            for_people(self.inclination.to_degrees()),
            for_people(self.raan.to_degrees()),
            for_people(self.arg_lat0.to_degrees()),
            for_people(2.0 * std::f64::consts::PI / self.mean_motion / 60.0),
            for_people(self.mean_motion)
        )
    }

    /// r (m).
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The inclination i (rad).
    pub fn inclination(&self) -> f64 {
        self.inclination
    }

    /// The right ascension of the ascending node Ω (rad).
    pub fn raan(&self) -> f64 {
        self.raan
    }

    /// The argument of latitude at t = 0, u₀ (rad).
    pub fn arg_lat0(&self) -> f64 {
        self.arg_lat0
    }

    /// n = √(μ/r³) (rad/s).
    pub fn mean_motion(&self) -> f64 {
        self.mean_motion
    }

    /// The LVLH frame at time `t` (s): its axes in space, LVLH → space. In the orbit's plane axes it is R_z(u)
    /// times the frame at u = 0 (x along +y, y along −z, z along −x).
    pub fn lvlh_s(&self, t: f64) -> UnitQuaternion<f64> {
        let u = self.arg_lat0 + self.mean_motion * t;
        let at_node = Matrix3::new(0.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0, -1.0, 0.0);
        let in_plane = Rotation3::from_axis_angle(&Vector3::z_axis(), u)
            * Rotation3::from_matrix_unchecked(at_node);
        UnitQuaternion::from_rotation_matrix(&(self.plane_s * in_plane))
    }

    /// The LVLH frame's angular velocity in space axes, n ĥ (rad/s).
    pub fn lvlh_rate_s(&self) -> Vector3<f64> {
        self.plane_s * Vector3::z() * self.mean_motion
    }

    /// The body's position from the Earth's centre at `t`, space axes (m): r = −r n̂.
    pub fn position_s(&self, t: f64) -> Vector3<f64> {
        -self.nadir_s(t) * self.radius
    }

    /// The body's position and velocity at `t`, space axes (m, m/s): r and v = n ĥ × r.
    pub fn position_and_velocity_s(&self, t: f64) -> (Vector3<f64>, Vector3<f64>) {
        let r_s = self.position_s(t);
        (r_s, self.lvlh_rate_s().cross(&r_s))
    }

    /// The direction to nadir at `t`, space axes: −r̂ = −R_z(Ω) R_x(i) (cos u, sin u, 0).
    pub fn nadir_s(&self, t: f64) -> Vector3<f64> {
        let u = self.arg_lat0 + self.mean_motion * t;
        -(self.plane_s * Vector3::new(u.cos(), u.sin(), 0.0))
    }

    /// The body's attitude `q` (body → space) at `t` as 3-2-1 angles from LVLH, (roll, pitch, yaw) (rad):
    /// R_LVLH←body = R_z(yaw) R_y(pitch) R_x(roll).
    pub fn lvlh_angles(&self, t: f64, q: &UnitQuaternion<f64>) -> [f64; 3] {
        let (roll, pitch, yaw) = (self.lvlh_s(t).inverse() * q).euler_angles();
        [roll, pitch, yaw]
    }

    /// The attitude (body → space) at `t` of a body at 3-2-1 angles `[roll, pitch, yaw]` (rad) from LVLH.
    pub fn attitude_from_lvlh(&self, t: f64, [roll, pitch, yaw]: [f64; 3]) -> UnitQuaternion<f64> {
        self.lvlh_s(t) * UnitQuaternion::from_euler_angles(roll, pitch, yaw)
    }

    /// The gravity-gradient moment on a body of inertia `inertia_c_b` about C (body axes) whose nadir direction is
    /// `nadir_b` (body axes, unit): M = 3μ/r³ · r̂_b × (I r̂_b) = 3n² · n̂_b × (I n̂_b) (Hughes 1986, §8.1; Schaub &
    /// Junkins, *Analytical Mechanics of Space Systems*, §4.6.3).
    pub fn gravity_gradient_b(
        &self,
        nadir_b: &Vector3<f64>,
        inertia_c_b: &Matrix3<f64>,
    ) -> Vector3<f64> {
        3.0 * self.mean_motion.powi(2) * nadir_b.cross(&(inertia_c_b * nadir_b))
    }
}
