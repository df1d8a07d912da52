//! `[orbit]`'s keys, declared once by the typed [`OrbitSpec`], and their validation into a [`CircularOrbit`]. The
//! scene registers it with one field, `orbit: Option<OrbitSpec>`.

use super::{CircularOrbit, DEFAULT_B0, DipoleField, R_EARTH};
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

/// The Earth's field as the effects that act in it (`magnetic`, `b_dot`) give it: a centred dipole tilted from the
/// Earth's axis toward a longitude, its strength on the equator at the surface.
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
pub(crate) struct FieldKeys {
    /// magnetic, b_dot: the field dipole's tilt from the Earth's axis (0: aligned); a tilted dipole turns with the Earth
    #[key(unit = "deg", shown = "0")]
    pub(crate) field_tilt_deg: Option<f64>,
    /// magnetic, b_dot: the longitude the tilted dipole leans toward at t = 0, from space x
    #[key(unit = "deg", shown = "0")]
    pub(crate) field_lon_deg: Option<f64>,
    /// magnetic, b_dot: the field on the equator at the Earth's surface, > 0; B ∝ (R/r)³
    #[key(unit = "T", shown = "3.12e-5")]
    pub(crate) field_b0: Option<f64>,
}

/// The field's three numbers as a scene gives them: tilt and longitude (deg) and B₀ (T).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldSpec {
    /// `field_tilt_deg` (absent: 0).
    pub tilt_deg: f64,
    /// `field_lon_deg` (absent: 0).
    pub lon_deg: f64,
    /// `field_b0` (absent: [`DEFAULT_B0`]).
    pub b0: f64,
}

impl Default for FieldSpec {
    /// The default field: aligned with the Earth's axis, B₀ = [`DEFAULT_B0`].
    fn default() -> Self {
        FieldSpec {
            tilt_deg: 0.0,
            lon_deg: 0.0,
            b0: DEFAULT_B0,
        }
    }
}

impl FieldSpec {
    /// The field as its keys give it (each absent key at its default).
    pub(crate) fn read(keys: &FieldKeys) -> Self {
        let default = FieldSpec::default();
        FieldSpec {
            tilt_deg: keys.field_tilt_deg.unwrap_or(default.tilt_deg),
            lon_deg: keys.field_lon_deg.unwrap_or(default.lon_deg),
            b0: keys.field_b0.unwrap_or(default.b0),
        }
    }

    /// Its keys, each written.
    pub(crate) fn keys(&self) -> FieldKeys {
        FieldKeys {
            field_tilt_deg: Some(self.tilt_deg),
            field_lon_deg: Some(self.lon_deg),
            field_b0: Some(self.b0),
        }
    }

    /// The field validated (the keys in the table at `at`): B₀ > 0 (T), finite angles.
    pub(crate) fn validate(&self, at: &KeyPath) -> Checked<DipoleField> {
        let key = |name: &str| at.clone().key(name);
        let b0 = finite(key("field_b0"), self.b0, "T")?;
        if b0 <= 0.0 {
            return invalid(key("field_b0"), format!("must be > 0 (T), got {b0:?}"));
        }
        let angle =
            |name: &str, value: f64| finite(key(name), value, "degrees").map(f64::to_radians);
        Ok(DipoleField::new(
            b0,
            angle("field_tilt_deg", self.tilt_deg)?,
            angle("field_lon_deg", self.lon_deg)?,
        ))
    }
}
