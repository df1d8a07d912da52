//! The checks that both the scene file's reading (`scene::spec`) and validation share: the error that names the key
//! at fault, and the tests of a key's presence and of a number's range that produce it.

use std::fmt;

use nalgebra::Vector3;

use super::KeyPath;

/// A scene that is not valid: the key at fault (e.g. `body.mass`, `effect[1].c`) and what is wrong.
#[derive(Debug, Clone, PartialEq)]
pub struct InvalidScene {
    /// The key at fault.
    pub key: KeyPath,
    /// What is wrong and what would be valid.
    pub problem: String,
}

impl fmt::Display for InvalidScene {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "key `{}`: {}", self.key, self.problem)
    }
}

impl std::error::Error for InvalidScene {}

pub(crate) type Invalid = InvalidScene;
pub(crate) type Checked<T> = Result<T, Invalid>;

pub(crate) fn invalid<T>(key: KeyPath, problem: impl Into<String>) -> Checked<T> {
    Err(Invalid {
        key,
        problem: problem.into(),
    })
}

/// The value of a key that `kind` requires.
pub(crate) fn required<T>(key: KeyPath, value: Option<T>, kind: &str) -> Checked<T> {
    value.ok_or_else(|| Invalid {
        problem: format!("missing: {kind} needs `{}`", key.last_key()),
        key,
    })
}

/// Refuses the keys of `table` that are given (`given`, as the table's `given()` lists them) but that `kind` does
/// not take (`takes`); `type`, which names the kind, is always taken.
pub(crate) fn only_keys(
    table: &KeyPath,
    kind: &str,
    takes: &[&str],
    given: &[&str],
) -> Checked<()> {
    match given
        .iter()
        .find(|name| **name != "type" && !takes.contains(name))
    {
        None => Ok(()),
        Some(name) => invalid(
            table.clone().key(name),
            if takes.is_empty() {
                format!("{kind} takes no `{name}`")
            } else {
                format!(
                    "{kind} takes no `{name}`; its keys are: {}",
                    takes.join(", ")
                )
            },
        ),
    }
}

pub(crate) fn finite(key: KeyPath, v: f64, unit: &str) -> Checked<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        invalid(key, format!("must be a finite number ({unit}), got {v:?}"))
    }
}

pub(crate) fn positive(key: KeyPath, v: f64, unit: &str) -> Checked<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        invalid(
            key,
            format!("must be a finite number > 0 ({unit}), got {v:?}"),
        )
    }
}

pub(crate) fn vector(key: KeyPath, v: [f64; 3], unit: &str) -> Checked<Vector3<f64>> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(Vector3::from(v))
    } else {
        invalid(
            key,
            format!("every component must be a finite number ({unit}), got {v:?}"),
        )
    }
}
