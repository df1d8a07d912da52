//! The path of a key in a scene (`body.mass`, `effect[1].c`): what every message about a key names.

use std::fmt;

/// One step of a key path.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Segment {
    Key(String),
    Index(usize),
}

/// The path of a key in a scene, e.g. `body.mass` or `effect[1].c`; optionally set from a command-line flag.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct KeyPath {
    segments: Vec<Segment>,
    flag: Option<String>,
}

impl KeyPath {
    /// The document root (an empty path).
    pub fn root() -> Self {
        Self::default()
    }

    /// This path extended by a table key.
    pub fn key(mut self, name: &str) -> Self {
        self.segments.push(Segment::Key(name.to_string()));
        self
    }

    /// This path extended by an array index.
    pub fn index(mut self, i: usize) -> Self {
        self.segments.push(Segment::Index(i));
        self
    }

    /// The last table key of the path (`c` for `effect[1].c`); empty for the root.
    pub fn last_key(&self) -> &str {
        self.segments
            .iter()
            .rev()
            .find_map(|s| match s {
                Segment::Key(k) => Some(k.as_str()),
                Segment::Index(_) => None,
            })
            .unwrap_or("")
    }

    /// Whether this is the document root.
    pub fn is_root(&self) -> bool {
        self.segments.is_empty()
    }

    /// A dotted key as a sweep writes it: `motion.tilt_deg`, `initial.omega.2`, `effect.0.c` (a segment of digits
    /// is an array index). `None` when a segment is empty.
    ///
    /// ```
    /// use eulerdyn::scene::source_map::KeyPath;
    /// assert_eq!(KeyPath::dotted("effect.0.c").unwrap().to_string(), "effect[0].c");
    /// assert!(KeyPath::dotted("motion..rate").is_none());
    /// ```
    pub fn dotted(text: &str) -> Option<Self> {
        text.split('.').try_fold(Self::root(), |path, segment| {
            let segment = segment.trim();
            if segment.is_empty() {
                None
            } else if segment.bytes().all(|b| b.is_ascii_digit()) {
                segment.parse().ok().map(|i| path.index(i))
            } else {
                Some(path.key(segment))
            }
        })
    }

    /// The steps of the path, from the root.
    pub(crate) fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// Whether the value was given by a command-line flag instead of the file.
    pub(crate) fn is_from_flag(&self) -> bool {
        self.flag.is_some()
    }

    /// Marks the value as given by a command-line flag instead of the file.
    pub fn from_flag(mut self, flag: &str) -> Self {
        self.flag = Some(flag.to_string());
        self
    }
}

impl fmt::Display for KeyPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, s) in self.segments.iter().enumerate() {
            match s {
                Segment::Key(k) if i == 0 => write!(f, "{k}")?,
                Segment::Key(k) => write!(f, ".{k}")?,
                Segment::Index(n) => write!(f, "[{n}]")?,
            }
        }
        if let Some(flag) = &self.flag {
            write!(f, " (from {flag})")?;
        }
        Ok(())
    }
}
