//! The user's own moment law as an effect ([`UserMoment`], added to a built scene by
//! [`Scene::with_moment`](crate::scene::Scene::with_moment)): named, its work without a known bound.

use super::compiling::Compiling;
use super::kind::EffectKind;
use super::law::UserMoment;

impl EffectKind for UserMoment {
    fn kind(&self) -> &'static str {
        "user"
    }

    /// `user:NAME`.
    fn label(&self) -> String {
        format!("user:{}", self.name)
    }

    fn describe(&self) -> String {
        format!(
            "user's moment law \"{}\" (a Rust or Python function of t, q, omega) in {} axes",
            self.name,
            self.frame.name()
        )
    }

    /// None: the law has no known bound.
    fn largest_moment(&self, _mass: f64) -> Option<f64> {
        None
    }

    fn compile(&self, into: &mut Compiling) {
        into.rate_law(self.clone());
    }

    fn depends_on_rate(&self) -> bool {
        true
    }

    fn unbounded_work(&self) -> bool {
        true
    }
}
