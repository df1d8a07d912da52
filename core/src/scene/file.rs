//! Scene files: TOML text into a [`SceneSpec`] (unknown keys are errors), validated into a [`Scene`].
//!
//! Every error names the file, the key (with line and column where the parser knows them) and what is wrong.

use std::fmt;
use std::path::{Path, PathBuf};

use super::model::{Scene, SceneSource};
use super::source_map::{KeyPath, SourceMap};
use super::spec::{SceneFile, SceneSpec};
use super::validate::{InvalidScene, Overrides};
use crate::keys::Part;
use crate::named::Named;

/// A scene that could not be read or is not valid.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError {
    /// The scene file.
    pub file: PathBuf,
    /// The key at fault, e.g. `body.mass` or `effect[1].c`.
    pub key: Option<String>,
    /// Line and column (1-based) where the parser knows them.
    pub location: Option<(usize, usize)>,
    /// What is wrong and what would be valid.
    pub problem: String,
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file.display())?;
        if let Some((line, col)) = self.location {
            write!(f, ":{line}:{col}")?;
        }
        if let Some(key) = &self.key {
            write!(f, ": key `{key}`")?;
        }
        write!(f, ": {}", self.problem)
    }
}

impl std::error::Error for SceneError {}

/// Reads and validates a scene file, applying command-line overrides.
pub fn load(path: &Path, overrides: &Overrides) -> Result<Scene, SceneError> {
    parse(path, &read(path)?, overrides)
}

/// Reads a scene file into its typed value, without validating it (to change it before [`SceneSpec::build`]).
pub fn load_spec(path: &Path) -> Result<SceneSpec, SceneError> {
    parse_spec(path, &read(path)?)
}

/// The text of a scene file (or another TOML input file: the messages name it): a directory, an unreadable file
/// and text that is not UTF-8 are errors naming the file.
pub fn read(path: &Path) -> Result<String, SceneError> {
    let error = |problem: String| SceneError {
        file: path.to_path_buf(),
        key: None,
        location: None,
        problem,
    };
    if path.is_dir() {
        return Err(error(
            "is a directory; give the path of a scene file (.toml)".into(),
        ));
    }
    let bytes = std::fs::read(path).map_err(|e| error(format!("cannot read the file: {e}")))?;
    String::from_utf8(bytes).map_err(|e| {
        let offset = e.utf8_error().valid_up_to();
        let before = String::from_utf8_lossy(&e.as_bytes()[..offset]).into_owned();
        let map = SourceMap::new(&before);
        SceneError {
            location: Some(map.line_col(offset.min(before.len()))),
            ..error("the file is not valid UTF-8 text; a scene file is TOML".into())
        }
    })
}

/// Parses and validates scene text; `path` is used in messages only.
///
/// ```
/// use std::path::Path;
/// use eulerdyn::scene::{Overrides, parse};
/// let text = "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[solver]\nt_end = 1.0\n[output]\nevery = 0.5\n";
/// let scene = parse(Path::new("inline.toml"), text, &Overrides::default()).unwrap();
/// assert_eq!(scene.schedule.len(), 3);
/// let bad = text.replace("mass = 1.0", "mass = -1.0");
/// let err = parse(Path::new("inline.toml"), &bad, &Overrides::default()).unwrap_err();
/// assert!(err.to_string().starts_with("inline.toml:2:1: key `body.mass`: must be a finite number > 0"));
/// ```
pub fn parse(path: &Path, text: &str, overrides: &Overrides) -> Result<Scene, SceneError> {
    let doc = parse_spec(path, text)?;
    let mut scene = doc
        .build_with(overrides)
        .map_err(|inv| located(path, text, inv))?;
    scene.source = Some(SceneSource {
        path: path.to_path_buf(),
        text: text.to_string(),
    });
    Ok(scene)
}

/// Parses scene text into its typed value; errors name the key, line and column. A torque table's relative `file`
/// becomes relative to the scene file's directory.
pub fn parse_spec(path: &Path, text: &str) -> Result<SceneSpec, SceneError> {
    if text.trim().is_empty() {
        return Err(SceneError {
            file: path.to_path_buf(),
            key: None,
            location: None,
            problem:
                "the file is empty; a scene needs at least [body], solver.t_end and output.every"
                    .into(),
        });
    }
    let file: SceneFile = parse_toml(path, text)?;
    let spec = SceneSpec::read(&file, &KeyPath::root()).map_err(|inv| located(path, text, inv))?;
    // A table's file is relative to the scene file.
    Ok(spec.with_files_in(path.parent().unwrap_or(Path::new(""))))
}

/// A scene that is not valid as an error of the file `path` with text `text`: its key's line and column.
fn located(path: &Path, text: &str, inv: InvalidScene) -> SceneError {
    SceneError {
        file: path.to_path_buf(),
        location: SourceMap::new(text).locate(&inv.key),
        key: Some(inv.key.to_string()),
        problem: inv.problem,
    }
}

/// Parses TOML text into any typed value with the scene file's messages (file, key, line and column, in plain
/// words); for input files that are not scenes, e.g. a sweep file.
pub fn parse_toml<T: serde::de::DeserializeOwned>(
    path: &Path,
    text: &str,
) -> Result<T, SceneError> {
    toml::from_str(text).map_err(|e| toml_error(path, text, &SourceMap::new(text), &e))
}

/// The parser's or serde's error as a scene error: the key (for a wrong value) or the line (for broken syntax)
/// where it happened, in the user's words rather than Rust's.
fn toml_error(path: &Path, text: &str, map: &SourceMap, e: &toml::de::Error) -> SceneError {
    let span = e.span();
    let problem = e.message().trim().to_string();
    let file = path.to_path_buf();
    // serde names a missing key in its message; the span is then that of its table (empty for the root).
    let missing = problem
        .strip_prefix("missing field `")
        .and_then(|rest| rest.split('`').next());
    if let Some(name) = missing {
        let table = span
            .as_ref()
            .map_or_else(KeyPath::root, |s| map.table_at(s));
        return SceneError {
            file,
            location: if table.is_root() {
                None
            } else {
                span.map(|s| map.line_col(s.start))
            },
            key: Some(table.key(name).to_string()),
            problem: format!("missing: this key is required ({problem})"),
        };
    }
    // The parser's "duplicate key" does not say which; its span does.
    let duplicate = span
        .as_ref()
        .and_then(|s| text.get(s.clone()))
        .map(str::trim)
        .filter(|name| problem == "duplicate key" && !name.is_empty() && !name.contains('\n'));
    let problem = match duplicate {
        Some(name) => format!("duplicate key `{name}`: each key and table may be given only once"),
        None => problem,
    };
    // A value of the wrong kind belongs to its key; broken syntax (an unclosed `[table`, a key without `=`)
    // belongs to its line, whatever key came before it.
    let key = span
        .as_ref()
        .filter(|_| is_value_error(&problem))
        .and_then(|s| map.key_at(s.start).or_else(|| map.key_near(s.start)));
    let problem = match (&key, &span) {
        (Some(key), _) => in_plain_words(&problem, key),
        (None, Some(s)) => format!("{problem}, in the line `{}`", map.line_text(s.start)),
        (None, None) => problem,
    };
    SceneError {
        file,
        key: key.map(|k| k.to_string()),
        location: span.map(|s| map.line_col(s.start)),
        problem,
    }
}

/// Whether serde's message is about a value (its key is at fault) rather than the file's syntax.
fn is_value_error(problem: &str) -> bool {
    [
        "invalid type",
        "invalid value",
        "invalid length",
        "unknown field",
        "unknown variant",
        "unknown value",
        "duplicate key",
        "data did not match",
        "principal moments",
    ]
    .iter()
    .any(|prefix| problem.starts_with(prefix))
}

/// serde's wording for a value of the wrong kind, said for a scene file's author.
fn in_plain_words(problem: &str, key: &KeyPath) -> String {
    if let Some(given) = problem
        .strip_prefix("invalid type: string ")
        .and_then(|rest| rest.strip_suffix(", expected f64"))
    {
        return format!("expected a number in SI units, without a unit; got the string {given}");
    }
    let table_array = ["effect", "point_mass"]
        .into_iter()
        .find(|name| key.last_key() == *name);
    if let (Some(name), true) = (table_array, problem.contains("expected a sequence")) {
        let full = key.to_string();
        return format!(
            "[{full}] is one table, but `{name}` is a list of tables: write [[{full}]] for each entry"
        );
    }
    match problem.strip_suffix(", expected f64") {
        Some(what) => format!(
            "expected a number, got {}",
            what.trim_start_matches("invalid type: ")
        ),
        None => problem.to_string(),
    }
}

/// The value a command-line flag names (`--method rk4`), or the error that names the scene file and the key it
/// overrides, e.g. `solver.method (from --method)`, with the names that are valid.
pub fn flag_value<T: Named>(
    file: &Path,
    section: &str,
    name: &str,
    given: Option<&str>,
) -> Result<Option<T>, SceneError> {
    let Some(given) = given else {
        return Ok(None);
    };
    T::parse(given).map(Some).map_err(|problem| SceneError {
        file: file.to_path_buf(),
        key: Some(
            KeyPath::root()
                .key(section)
                .key(name)
                .from_flag(&format!("--{}", name.replace('_', "-")))
                .to_string(),
        ),
        location: None,
        problem,
    })
}

/// The command line's overriding flags as given (`--method rk4 --dt 0.01`; the Python module's keyword arguments),
/// before their names are checked.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Flags<'a> {
    /// `--method`.
    pub method: Option<&'a str>,
    /// `--frame` (the form integrated).
    pub frame: Option<&'a str>,
    /// `--backend`.
    pub backend: Option<&'a str>,
    /// `--rtol`.
    pub rtol: Option<f64>,
    /// `--atol`.
    pub atol: Option<f64>,
    /// `--dt` (s).
    pub dt: Option<f64>,
    /// `--t-end` (s).
    pub t_end: Option<f64>,
    /// `--every` (s).
    pub every: Option<f64>,
}

impl Flags<'_> {
    /// The overrides the flags give for the scene `file`; a bad name is an error naming the file and the key it
    /// overrides, e.g. `solver.method (from --method)` (see [`flag_value`]). The numbers are checked with the
    /// scene ([`SceneSpec::build_with`]).
    pub fn overrides(&self, file: &Path) -> Result<Overrides, SceneError> {
        Ok(Overrides {
            method: flag_value(file, "solver", "method", self.method)?,
            form: flag_value(file, "solver", "frame", self.frame)?,
            backend: flag_value(file, "solver", "backend", self.backend)?,
            rtol: self.rtol,
            atol: self.atol,
            dt: self.dt,
            t_end: self.t_end,
            every: self.every,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::method::Method;

    #[test]
    fn flags_become_overrides_or_name_the_key_they_override() {
        let file = Path::new("s.toml");
        let flags = Flags {
            method: Some("rk4"),
            dt: Some(0.5),
            ..Flags::default()
        };
        let o = flags.overrides(file).unwrap();
        assert_eq!(
            (o.method, o.dt, o.form),
            (Some(Method::Rk4), Some(0.5), None)
        );
        let bad = Flags {
            frame: Some("lab"),
            ..Flags::default()
        };
        let e = bad.overrides(file).unwrap_err();
        assert_eq!(e.key.as_deref(), Some("solver.frame (from --frame)"));
        assert!(
            e.to_string()
                .starts_with("s.toml: key `solver.frame (from --frame)`: ")
        );
    }
}
