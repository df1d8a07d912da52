//! `type = "magnetic"`: the body's residual dipole m (A·m², body axes) in the Earth's field along the orbit,
//! M = m × B_b with B_b = Rᵀ B_s(r(t), t) ([`DipoleField`]).

use nalgebra::Vector3;

use super::compiling::{AttitudeLaw, Compiling};
use super::kind::{EffectKind, KindSpec, Placement, SharedKeys};
use crate::keys::{Checked, KeyPath, Keys, vector};
use crate::orbit::{CircularOrbit, DipoleField, FieldSpec};
use crate::text::{for_people, vec3};

/// A residual dipole's key (the field's are [`crate::orbit::FieldKeys`], shared with `b_dot`).
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
pub(crate) struct MagneticKeys {
    /// magnetic: the body's residual magnetic dipole, body axes; the moment is m × B
    #[key(unit = "A·m²", shown = "[0, 0, 0]")]
    pub(crate) dipole: Option<[f64; 3]>,
}

/// `type = "magnetic"`: a residual dipole in a centred-dipole Earth field ([`DipoleField`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MagneticSpec {
    /// `dipole`: the body's residual dipole, body axes (A·m²; absent: zero).
    pub dipole: [f64; 3],
    /// `field_tilt_deg`, `field_lon_deg`, `field_b0`: the Earth's field.
    pub field: FieldSpec,
}

impl MagneticSpec {
    /// A residual dipole `dipole` (A·m², body axes) in the default field, aligned with the Earth's axis.
    ///
    /// ```
    /// use eulerdyn::scene::{EffectSpec, MagneticSpec};
    /// let spec = EffectSpec::from(MagneticSpec::new([0.0, 0.0, 0.05]));
    /// assert_eq!(spec.kind(), "magnetic");
    /// ```
    pub fn new(dipole: [f64; 3]) -> Self {
        MagneticSpec {
            dipole,
            field: FieldSpec::default(),
        }
    }
}

impl KindSpec for MagneticSpec {
    type Keys = MagneticKeys;
    type Effect = MagneticDipole;

    /// The dipole as its keys and the field's give it.
    fn read(keys: &MagneticKeys, shared: &SharedKeys, _: &KeyPath, _: &str) -> Checked<Self> {
        Ok(MagneticSpec {
            dipole: keys.dipole.unwrap_or([0.0; 3]),
            field: FieldSpec::read(&shared.field),
        })
    }

    /// Its keys and the field's ([`FieldSpec::keys`]).
    fn write(&self, shared: &mut SharedKeys) -> MagneticKeys {
        shared.field = self.field.keys();
        MagneticKeys {
            dipole: Some(self.dipole),
        }
    }

    /// The dipole validated: an orbit and a free body, a finite dipole (A·m²) and a valid field
    /// ([`FieldSpec::validate`]).
    fn validate(&self, at: &KeyPath, on: &Placement) -> Checked<MagneticDipole> {
        Ok(MagneticDipole {
            orbit: on.in_orbit(at, "magnetic")?,
            field: self.field.validate(at)?,
            dipole_b: vector(at.clone().key("dipole"), self.dipole, "A*m^2")?,
        })
    }
}

/// A residual dipole m (A·m², body axes) in the Earth's field along a circular orbit: M = m × B_b.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MagneticDipole {
    /// The orbit.
    pub orbit: CircularOrbit,
    /// The Earth's field.
    pub field: DipoleField,
    /// m, body axes (A·m²).
    pub dipole_b: Vector3<f64>,
}

impl EffectKind for MagneticDipole {
    fn kind(&self) -> &'static str {
        "magnetic"
    }

    fn describe(&self) -> String {
        format!(
            "magnetic: residual dipole {} A*m^2 (body axes) in a centred dipole field, B0 = {} T on the equator at \
             the surface: M = m x B_b",
            vec3(&self.dipole_b),
            for_people(self.field.b0())
        )
    }

    /// |m| 2B₀(R/r)³: the field's largest, over a pole.
    fn largest_moment(&self, _mass: f64) -> Option<f64> {
        Some(self.dipole_b.norm() * self.field.largest_b(self.orbit.radius()))
    }

    fn size_key(&self) -> &'static str {
        "dipole"
    }

    fn compile(&self, into: &mut Compiling) {
        into.attitude_law(std::sync::Arc::new(*self));
    }

    fn field(&self) -> Option<(CircularOrbit, DipoleField)> {
        Some((self.orbit, self.field))
    }
}

impl AttitudeLaw for MagneticDipole {
    /// B_s(r(t), t).
    fn vector_s(&self, t: f64) -> Vector3<f64> {
        self.field.b_s(&self.orbit.position_s(t), t)
    }

    /// m × B_b.
    fn moment_b(&self, b_b: &Vector3<f64>) -> Vector3<f64> {
        self.dipole_b.cross(b_b)
    }
}
