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
                    "unknown value \"{name}\"; expected one of: {}",
                    names.join(", ")
                )
            })
    }
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
