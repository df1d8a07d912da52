//! `type = "b_dot"`: magnetorquers under the B-dot law, m = −k dB_b/dt with each axis clipped to ±m_max, acting in
//! the Earth's field: M = m × B_b (Stickler & Alfriend, "Elementary magnetic attitude control system", *J.
//! Spacecraft and Rockets* 13(5), 1976; Markley & Crassidis, *Fundamentals of Spacecraft Attitude Determination
//! and Control*, 2014, §7.5.1). The rate is the model's: with B_b = Rᵀ B_s(r(t), t),
//! dB_b/dt = Rᵀ Ḃ_s − ω × B_b, so its work is P = m·(B_b × ω) = Σᵢ clip(−k Ḃᵢ) Ḃᵢ − m·Rᵀ Ḃ_s: never positive but
//! for the orbit's own part, |m||Ḃ_s|.

mod columns;

use nalgebra::{UnitQuaternion, Vector3};

use super::compiling::Compiling;
use super::kind::{EffectKind, KindSpec, Placement, SharedKeys};
use super::law::{MomentLaw, UserMoment};
use crate::frames::Axes;
use crate::keys::{Checked, KeyPath, Keys, finite, invalid, required};
use crate::orbit::{CircularOrbit, DipoleField, FieldSpec};
use crate::text::for_people;

/// B-dot's keys (the field's are [`crate::orbit::FieldKeys`], shared with `magnetic`).
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
pub(crate) struct BDotKeys {
    /// b_dot: the gain k of m = −k·dB_b/dt, ≥ 0
    #[key(unit = "A·m²·s/T", shown = "required for `b_dot`")]
    pub(crate) gain: Option<f64>,
    /// b_dot: each magnetorquer's largest dipole; m is clipped to ±this per body axis, ≥ 0
    #[key(unit = "A·m²", shown = "required for `b_dot`")]
    pub(crate) max_dipole: Option<f64>,
}

/// `type = "b_dot"`: magnetorquers commanded m = −k dB_b/dt, clipped per axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BDotSpec {
    /// `gain`: k (A·m²·s/T).
    pub gain: f64,
    /// `max_dipole`: each axis's limit (A·m²).
    pub max_dipole: f64,
    /// `field_tilt_deg`, `field_lon_deg`, `field_b0`: the Earth's field.
    pub field: FieldSpec,
}

impl BDotSpec {
    /// Magnetorquers of gain `gain` (A·m²·s/T) and limit `max_dipole` (A·m² per axis) in the default field.
    ///
    /// ```
    /// use eulerdyn::effects::{BDotSpec, EffectSpec};
    /// let spec = EffectSpec::from(BDotSpec::new(1.0e4, 0.2));
    /// assert_eq!(spec.kind(), "b_dot");
    /// ```
    pub fn new(gain: f64, max_dipole: f64) -> Self {
        BDotSpec {
            gain,
            max_dipole,
            field: FieldSpec::default(),
        }
    }
}

impl KindSpec for BDotSpec {
    type Keys = BDotKeys;
    type Effect = BDot;

    /// The law as its keys and the field's give it.
    fn read(keys: &BDotKeys, shared: &SharedKeys, at: &KeyPath, kind_text: &str) -> Checked<Self> {
        let key = |name: &str| at.clone().key(name);
        Ok(BDotSpec {
            gain: required(key("gain"), keys.gain, kind_text)?,
            max_dipole: required(key("max_dipole"), keys.max_dipole, kind_text)?,
            field: FieldSpec::read(&shared.field),
        })
    }

    /// Its keys and the field's ([`FieldSpec::keys`]).
    fn write(&self, shared: &mut SharedKeys) -> BDotKeys {
        shared.field = self.field.keys();
        BDotKeys {
            gain: Some(self.gain),
            max_dipole: Some(self.max_dipole),
        }
    }

    /// The law validated: an orbit and a free body, k ≥ 0 and m_max ≥ 0 finite, a valid field.
    fn validate(&self, at: &KeyPath, on: &Placement) -> Checked<BDot> {
        let orbit = on.in_orbit(at, "b_dot")?;
        let at_least_zero = |name: &str, value: f64, unit: &str| {
            let key = at.clone().key(name);
            match finite(key.clone(), value, unit)? {
                v if v >= 0.0 => Ok(v),
                v => invalid(key, format!("must be >= 0 ({unit}), got {v:?}")),
            }
        };
        Ok(BDot {
            orbit,
            field: self.field.validate(at)?,
            gain: at_least_zero("gain", self.gain, "A*m^2*s/T")?,
            max_dipole: at_least_zero("max_dipole", self.max_dipole, "A*m^2")?,
        })
    }
}

/// Magnetorquers under the B-dot law in the Earth's field along a circular orbit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BDot {
    /// The orbit.
    pub orbit: CircularOrbit,
    /// The Earth's field.
    pub field: DipoleField,
    /// k (A·m²·s/T).
    pub gain: f64,
    /// Each axis's limit (A·m²).
    pub max_dipole: f64,
}

impl BDot {
    /// The field in body axes and the commanded dipole at (t, q, ω_b): B_b = Rᵀ B_s and
    /// m_i = clip(−k (Rᵀ Ḃ_s − ω × B_b)_i, ±m_max) (T, A·m²).
    pub fn field_and_dipole_b(
        &self,
        t: f64,
        q: &UnitQuaternion<f64>,
        omega_b: &Vector3<f64>,
    ) -> (Vector3<f64>, Vector3<f64>) {
        let (r_s, v_s) = self.orbit.position_and_velocity_s(t);
        let b_b = q.inverse_transform_vector(&self.field.b_s(&r_s, t));
        let b_rate_b =
            q.inverse_transform_vector(&self.field.b_rate_s(&r_s, &v_s, t)) - omega_b.cross(&b_b);
        let m_b = (b_rate_b * -self.gain).map(|m| m.clamp(-self.max_dipole, self.max_dipole));
        (b_b, m_b)
    }
}

impl MomentLaw for BDot {
    /// M = m × B_b, body axes.
    fn moment(&self, t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>) -> Vector3<f64> {
        let (b_b, m_b) = self.field_and_dipole_b(t, q, omega_b);
        m_b.cross(&b_b)
    }
}

impl EffectKind for BDot {
    fn kind(&self) -> &'static str {
        "b_dot"
    }

    fn describe(&self) -> String {
        format!(
            "b_dot: magnetorquers m = -{} A*m^2*s/T * dB_b/dt, each axis within +-{} A*m^2, in a centred dipole \
             field, B0 = {} T: M = m x B_b",
            for_people(self.gain),
            for_people(self.max_dipole),
            for_people(self.field.b0())
        )
    }

    /// √3 m_max · 2B₀(R/r)³: |m| ≤ √3 m_max, |B| at most over a pole.
    fn largest_moment(&self, _mass: f64) -> Option<f64> {
        Some(3f64.sqrt() * self.max_dipole * self.field.largest_b(self.orbit.radius()))
    }

    fn size_key(&self) -> &'static str {
        "max_dipole"
    }

    fn compile(&self, into: &mut Compiling) {
        into.rate_law(UserMoment::new("b_dot", Axes::Body, *self));
    }

    fn depends_on_rate(&self) -> bool {
        true
    }

    fn columns(&self) -> Option<crate::sample::ColumnGroup> {
        Some(columns::dipole_columns(*self))
    }

    fn field(&self) -> Option<(CircularOrbit, DipoleField)> {
        Some((self.orbit, self.field))
    }
}
