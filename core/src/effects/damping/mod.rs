//! `type = "damping"`: viscous damping M = −c ω, whose power −c|ω|² is never positive.

use super::compiling::Compiling;
use super::kind::{EffectKind, KindSpec, Placement, SharedKeys};
use crate::keys::{Checked, KeyPath, Keys, finite, invalid, required};
use crate::text::plain;

/// Damping's key.
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
pub(crate) struct DampingKeys {
    /// viscous M = −c·ω, ≥ 0
    #[key(unit = "N·m·s", shown = "required for `damping`")]
    pub(crate) c: Option<f64>,
}

/// `type = "damping"`: M = −c ω.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DampingSpec {
    /// `c`: N·m·s, ≥ 0.
    pub c: f64,
}

impl KindSpec for DampingSpec {
    type Keys = DampingKeys;
    type Effect = Damping;

    /// Damping as its keys give it.
    fn read(keys: &DampingKeys, _: &SharedKeys, at: &KeyPath, kind_text: &str) -> Checked<Self> {
        Ok(DampingSpec {
            c: required(at.clone().key("c"), keys.c, kind_text)?,
        })
    }

    /// Its keys.
    fn write(&self, _: &mut SharedKeys) -> DampingKeys {
        DampingKeys { c: Some(self.c) }
    }

    /// Damping validated, its table at `at`: c ≥ 0, finite.
    fn validate(&self, at: &KeyPath, _on: &Placement) -> Checked<Damping> {
        let key = at.clone().key("c");
        let c = finite(key.clone(), self.c, "N*m*s")?;
        if c < 0.0 {
            return invalid(
                key,
                format!("must be >= 0 (N*m*s): a negative damping adds energy, got {c:?}"),
            );
        }
        Ok(Damping { c })
    }
}

/// Viscous damping M = −c ω (N·m·s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Damping {
    /// c (N·m·s).
    pub c: f64,
}

impl EffectKind for Damping {
    fn kind(&self) -> &'static str {
        "damping"
    }

    fn describe(&self) -> String {
        format!("viscous damping M = -{} N*m*s * omega", plain(self.c))
    }

    /// None: the moment grows with ω, but its power −c|ω|² is never positive.
    fn largest_moment(&self, _mass: f64) -> Option<f64> {
        None
    }

    fn compile(&self, into: &mut Compiling) {
        into.damping(self.c);
    }

    fn damping(&self) -> Option<f64> {
        Some(self.c)
    }
}
