//! Choices written by name in scene files and on the command line (methods, backends, forms, axes): one way to
//! look a name up, one message for a name that is not one of them, and serde by name.

/// A closed set of values, each with the name scene files and the command line use.
pub trait Named: Sized + Copy + 'static {
    /// Every value, in the order they are listed to users.
    const ALL: &'static [Self];

    /// The value's name.
    fn name(&self) -> &'static str;

    /// The value named `name`, or the message for a name that is none of them: `unknown value "x"; expected one
    /// of: a, b, c`.
    ///
    /// ```
    /// use eulerdyn::{Method, named::Named};
    /// assert_eq!(Method::parse("rk4"), Ok(Method::Rk4));
    /// assert!(Method::parse("euler").unwrap_err().contains("expected one of: rk4, dopri5"));
    /// ```
    fn parse(name: &str) -> Result<Self, String> {
        Self::ALL
            .iter()
            .copied()
            .find(|v| v.name() == name)
            .ok_or_else(|| {
                let names: Vec<&str> = Self::ALL.iter().map(Self::name).collect();
                format!(
                    "unknown value \"{name}\"; expected one of: {}{}",
                    names.join(", "),
                    nearest_hint(name, &names)
                )
            })
    }
}

/// `; the nearest is `x``: the choice nearest `name` by edit distance, when it is within a third of the longer
/// name (two edits at least): a misspelling, not another word. Empty otherwise.
///
/// ```
/// use eulerdyn::named::nearest_hint;
/// assert_eq!(nearest_hint("bdot", &["magnetic", "b_dot"]), "; the nearest is `b_dot`");
/// assert_eq!(nearest_hint("euler", &["rk4", "dop853"]), "");
/// ```
pub fn nearest_hint(name: &str, choices: &[&str]) -> String {
    let lower = name.to_lowercase();
    let nearest = (choices.iter())
        .map(|c| (edit_distance(&lower, &c.to_lowercase()), *c))
        .min_by_key(|(d, _)| *d);
    match nearest {
        Some((d, choice)) if d > 0 && d <= 2.max(name.len().max(choice.len()) / 3) => {
            format!("; the nearest is `{choice}`")
        }
        _ => String::new(),
    }
}

/// The Levenshtein distance of `a` and `b` (insertions, deletions and substitutions of characters), by the
/// two-row dynamic programme of Wagner & Fischer, "The string-to-string correction problem", JACM 21 (1974).
pub(crate) fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let substitute = diagonal + usize::from(ca != *cb);
            diagonal = row[j + 1];
            row[j + 1] = substitute.min(row[j] + 1).min(diagonal + 1);
        }
    }
    row[b.len()]
}

/// serde by [`Named::name`], so that a scene file's `method = "rk4"` is a typed value and a wrong name gets the
/// message of [`Named::parse`].
macro_rules! serde_by_name {
    ($type:ty) => {
        impl serde::Serialize for $type {
            fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                serializer.serialize_str(crate::named::Named::name(self))
            }
        }

        impl<'de> serde::Deserialize<'de> for $type {
            fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
                let name = String::deserialize(deserializer)?;
                <$type as crate::named::Named>::parse(&name).map_err(serde::de::Error::custom)
            }
        }
    };
}

pub(crate) use serde_by_name;

#[cfg(test)]
mod tests {
    use super::edit_distance;

    #[test]
    fn the_edit_distance_counts_single_character_edits() {
        // Wagner & Fischer (1974): kitten → sitting takes 3 edits (two substitutions, one insertion).
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("effects", "effect"), 1);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(edit_distance("same", "same"), 0);
    }
}
