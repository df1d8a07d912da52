//! `[orbit]`'s keys, declared once by the typed [`OrbitSpec`], and their validation into a [`CircularOrbit`]. The
//! scene registers it with one field, `orbit: Option<OrbitSpec>`.

use super::{CircularOrbit, R_EARTH};
use crate::keys::{Checked, Either, Group, KeyPath, Keys, Table, finite, invalid};

/// `[orbit]`: a circular orbit about the Earth.
#[derive(Debug, Clone, Copy, PartialEq, Table)]
#[table(
    file = OrbitFile,
    header = "[orbit]",
    about = "a circular orbit about the Earth (space axes: Earth-centred inertial), for the environment's effects and the LVLH columns",
    derive(Copy)
)]
pub struct OrbitSpec {
    /// `altitude_km` or `radius_km`.
    #[key(flatten = SizeKeys)]
    pub size: OrbitSize,
    /// the orbit plane's inclination to the equator
    #[key(unit = "deg", default = 0.0)]
    pub inclination_deg: f64,
    /// the right ascension of the ascending node
    #[key(unit = "deg", default = 0.0)]
    pub raan_deg: f64,
    /// the body's argument of latitude at t = 0 (from the ascending node)
    #[key(unit = "deg", default = 0.0)]
    pub arg_lat_deg: f64,
}

/// How big the orbit is: its altitude above the equatorial radius R = 6378.137 km, or its radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OrbitSize {
    /// `altitude_km`.
    AltitudeKm(f64),
    /// `radius_km`.
    RadiusKm(f64),
}

/// `altitude_km` or `radius_km`, read as the orbit's [`OrbitSize`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
#[keys(either(
    altitude_km,
    radius_km,
    "give either `altitude_km` or `radius_km`, not both",
    OrbitSize::AltitudeKm,
    OrbitSize::RadiusKm
))]
pub(crate) struct SizeKeys {
    /// above the Earth's equatorial radius R = 6378.137 km; > 0
    #[key(unit = "km", shown = "one of `altitude_km` / `radius_km`")]
    altitude_km: Option<f64>,
    /// from the Earth's centre; > R
    #[key(unit = "km", shown = "one of `altitude_km` / `radius_km`")]
    radius_km: Option<f64>,
}

/// One of `altitude_km` and `radius_km` is required.
impl Group<SizeKeys> for OrbitSize {
    fn read(keys: &SizeKeys, at: &KeyPath) -> Checked<Self> {
        match keys.either() {
            Some(size) => Ok(size),
            None => invalid(
                at.clone(),
                "an orbit needs `altitude_km` (above the Earth's equatorial radius) or `radius_km`",
            ),
        }
    }

    fn write(&self, keys: &mut SizeKeys) {
        keys.set_either(Some(*self));
    }
}

/// `[orbit]` as a [`CircularOrbit`]: its radius above the Earth's surface (altitude > 0, or radius > R), its
/// angles finite.
pub(crate) fn validate_orbit(spec: &OrbitSpec) -> Checked<CircularOrbit> {
    let key = |name: &str| KeyPath::root().key("orbit").key(name);
    let radius = match spec.size {
        OrbitSize::AltitudeKm(h) if finite(key("altitude_km"), h, "km")? > 0.0 => R_EARTH + h * 1e3,
        OrbitSize::AltitudeKm(h) => {
            return invalid(key("altitude_km"), format!("must be > 0 (km), got {h:?}"));
        }
        OrbitSize::RadiusKm(r) if finite(key("radius_km"), r, "km")? * 1e3 > R_EARTH => r * 1e3,
        OrbitSize::RadiusKm(r) => {
            return invalid(
                key("radius_km"),
                format!(
                    "must be above the Earth's surface, > {} km, got {r:?}",
                    R_EARTH / 1e3
                ),
            );
        }
    };
    let angle = |name: &str, value: f64| finite(key(name), value, "degrees").map(f64::to_radians);
    Ok(CircularOrbit::new(
        radius,
        angle("inclination_deg", spec.inclination_deg)?,
        angle("raan_deg", spec.raan_deg)?,
        angle("arg_lat_deg", spec.arg_lat_deg)?,
    ))
}
