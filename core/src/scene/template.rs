//! A scene file as a template: its TOML table, with numeric keys set by their paths (`motion.tilt_deg`,
//! `initial.omega.2`, `effect.0.c`) before it is read into a [`SceneSpec`] — the scenes a sweep runs.

use std::path::Path;

use toml::{Table, Value};

use super::file::{SceneError, load_spec};
use super::source_map::{KeyPath, Segment};
use super::spec::SceneSpec;

/// A base scene whose numeric keys can be set.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneTemplate {
    table: Table,
}

impl SceneTemplate {
    /// Reads a scene file as a template. Its syntax and keys are checked as a scene file's (the messages name the
    /// file, key and line); validation is left to each scene made from it.
    pub fn load(path: &Path) -> Result<Self, SceneError> {
        let spec = load_spec(path)?;
        Self::from_spec(&spec).map_err(|problem| SceneError {
            file: path.to_path_buf(),
            key: None,
            location: None,
            problem,
        })
    }

    /// The template of a scene built in code.
    pub fn from_spec(spec: &SceneSpec) -> Result<Self, String> {
        Table::try_from(spec)
            .map(|table| Self { table })
            .map_err(|e| e.to_string())
    }

    /// Checks that `key` is a numeric key of the scene format that this base scene can take: set to `probe`, the
    /// table still reads as a scene. The error says why not (a key the format does not know, a key whose value is
    /// not a number, an array element of an array the base scene does not give).
    pub fn check_numeric_key(&self, key: &KeyPath, probe: f64) -> Result<(), String> {
        if let Some(problem) = self.unknown_key(key, probe) {
            return Err(problem);
        }
        let mut table = self.table.clone();
        set_number(&mut table, key, probe)?;
        match spec_of(&table) {
            Ok(_) => Ok(()),
            Err(e) => {
                let message = e.message().trim().to_string();
                if message.starts_with("unknown field") {
                    Err(format!(
                        "`{key}` is not a key of the scene format ({message})"
                    ))
                } else {
                    Err(format!("`{key}` is not a numeric key ({message})"))
                }
            }
        }
    }

    /// When a key of `key`'s path that the base scene does not give is not a key of the scene format either, the
    /// message naming it and the nearest valid key (by edit distance) in its place: a misspelt key is found
    /// before the arrays or tables it would lead into.
    fn unknown_key(&self, key: &KeyPath, probe: f64) -> Option<String> {
        let absent = first_absent(&self.table, key)?;
        let mut table = self.table.clone();
        set_number(&mut table, &truncated(key, absent + 1), probe).ok()?;
        let message = spec_of(&table).err()?.message().trim().to_string();
        let (wrong, valid) = unknown_field(&message)?;
        let Some(Segment::Key(name)) = key.segments().get(absent) else {
            return None;
        };
        if *name != wrong {
            return None;
        }
        let nearest = valid.iter().min_by_key(|v| {
            crate::named::edit_distance(&wrong.to_lowercase(), &v.to_lowercase())
        })?;
        let mut fixed = truncated(key, absent).key(nearest);
        for segment in &key.segments()[absent + 1..] {
            fixed = match segment {
                Segment::Key(name) => fixed.key(name),
                Segment::Index(i) => fixed.index(*i),
            };
        }
        let (key, fixed) = (dotted(key), dotted(&fixed));
        Some(format!(
            "`{key}` is not a key of the scene format: `{wrong}` is unknown there; the nearest valid key is \
             `{fixed}` (valid there: {})",
            valid
                .iter()
                .map(|v| format!("`{v}`"))
                .collect::<Vec<_>>()
                .join(", ")
        ))
    }

    /// The scene with each key set to its value.
    pub fn spec_with(&self, values: &[(KeyPath, f64)]) -> Result<SceneSpec, String> {
        let mut table = self.table.clone();
        for (key, value) in values {
            set_number(&mut table, key, *value)?;
        }
        spec_of(&table).map_err(|e| e.message().trim().to_string())
    }
}

/// Reads `table` as a scene through the scene file's own reader: written out as TOML text and parsed, so that every
/// table's deserialiser is compiled once, for text, and not a second time for `toml::Value`.
fn spec_of(table: &Table) -> Result<SceneSpec, toml::de::Error> {
    let text = toml::to_string(table).map_err(|e| serde::de::Error::custom(e.to_string()))?;
    toml::from_str(&text)
}

/// Sets the number at `key`, creating the tables on its way that the base scene leaves out. An array element
/// must exist: the other elements of an array the base scene leaves out are unknown.
fn set_number(table: &mut Table, key: &KeyPath, value: f64) -> Result<(), String> {
    let Some((last, parents)) = key.segments().split_last() else {
        return Err("the key is empty".into());
    };
    let mut here = Here::Table(table);
    for (i, segment) in parents.iter().enumerate() {
        let so_far = || prefix(key, i + 1);
        here = match (here, segment) {
            (Here::Table(t), Segment::Key(name)) => {
                let next = key.segments().get(i + 1);
                if !t.contains_key(name) && matches!(next, Some(Segment::Index(_))) {
                    return Err(out_of_range(&so_far(), 0));
                }
                let entry = t
                    .entry(name.clone())
                    .or_insert_with(|| Value::Table(Table::new()));
                Here::of(entry).ok_or_else(|| format!("`{}` is a value, not a table", so_far()))?
            }
            (Here::Array(a), Segment::Index(n)) => {
                let len = a.len();
                let item = a.get_mut(*n).ok_or_else(|| out_of_range(&so_far(), len))?;
                Here::of(item).ok_or_else(|| format!("`{}` is a value, not a table", so_far()))?
            }
            (Here::Table(_), Segment::Index(_)) => return Err(not_array(&prefix(key, i))),
            (Here::Array(_), Segment::Key(_)) => return Err(not_table(&prefix(key, i))),
        };
    }
    match (here, last) {
        (Here::Table(t), Segment::Key(name)) => {
            t.insert(name.clone(), Value::Float(value));
        }
        (Here::Array(a), Segment::Index(n)) => {
            let len = a.len();
            *a.get_mut(*n)
                .ok_or_else(|| out_of_range(&key.to_string(), len))? = Value::Float(value);
        }
        (Here::Table(_), Segment::Index(_)) => return Err(not_array(&prefix(key, parents.len()))),
        (Here::Array(_), Segment::Key(_)) => return Err(not_table(&prefix(key, parents.len()))),
    }
    Ok(())
}

/// Where a path has got to: a table or an array.
enum Here<'a> {
    Table(&'a mut Table),
    Array(&'a mut Vec<Value>),
}

impl<'a> Here<'a> {
    fn of(value: &'a mut Value) -> Option<Self> {
        match value {
            Value::Table(t) => Some(Self::Table(t)),
            Value::Array(a) => Some(Self::Array(a)),
            _ => None,
        }
    }
}

/// The first `n` segments of `key`, written as in messages.
fn prefix(key: &KeyPath, n: usize) -> String {
    truncated(key, n).to_string()
}

/// The first `n` segments of `key`.
fn truncated(key: &KeyPath, n: usize) -> KeyPath {
    let mut path = KeyPath::root();
    for segment in &key.segments()[..n] {
        path = match segment {
            Segment::Key(name) => path.key(name),
            Segment::Index(i) => path.index(*i),
        };
    }
    path
}

/// The index of the first segment of `key` that is a key `table` does not give (none when the path stops at a
/// value or an index before it, or is given whole).
fn first_absent(table: &Table, key: &KeyPath) -> Option<usize> {
    let mut here: Option<&Value> = None;
    for (i, segment) in key.segments().iter().enumerate() {
        let next = match (here, segment) {
            (None, Segment::Key(name)) => table.get(name),
            (Some(Value::Table(t)), Segment::Key(name)) => t.get(name),
            (Some(Value::Array(a)), Segment::Index(n)) => a.get(*n),
            _ => return None,
        };
        match next {
            Some(value) => here = Some(value),
            None => return matches!(segment, Segment::Key(_)).then_some(i),
        }
    }
    None
}

/// serde's "unknown field `x`, expected one of `a`, `b`" (or "expected `a` or `b`"): x and the valid names.
fn unknown_field(message: &str) -> Option<(String, Vec<String>)> {
    let rest = message.strip_prefix("unknown field `")?;
    let (wrong, rest) = rest.split_once('`')?;
    let expected = rest.split_once("expected")?.1;
    let valid: Vec<String> = expected
        .split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_string)
        .collect();
    (!valid.is_empty()).then(|| (wrong.to_string(), valid))
}

fn out_of_range(path: &str, len: usize) -> String {
    if len == 0 {
        format!(
            "`{path}`: the base scene does not give this array, so its other elements are unknown; give it in the base scene"
        )
    } else {
        format!("`{path}`: the index is out of range (the array has {len} elements, from 0)")
    }
}

fn not_array(path: &str) -> String {
    format!("`{path}` is not an array: an index can only follow an array")
}

fn not_table(path: &str) -> String {
    format!("`{path}` is an array: give an index (e.g. `{path}.0`)")
}

/// A key path as a sweep file writes it: `effect.0.c` (a [`KeyPath`] displays `effect[0].c`, as scene messages do).
fn dotted(key: &KeyPath) -> String {
    (key.segments().iter())
        .map(|s| match s {
            Segment::Key(name) => name.to_string(),
            Segment::Index(i) => i.to_string(),
        })
        .collect::<Vec<_>>()
        .join(".")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{AxisDirection, BodySpec, FixedAxisSpec, MotionSpec, ShapeSpec};

    fn disk() -> SceneTemplate {
        let spec = SceneSpec::new(BodySpec::shape(2.0, ShapeSpec::thin_disk(0.3)), 1.0, 0.1)
            .with_motion(FixedAxisSpec::tilted(30.0, 10.0))
            .with_omega([0.0, 0.0, 1.0]);
        SceneTemplate::from_spec(&spec).unwrap()
    }

    fn key(text: &str) -> KeyPath {
        KeyPath::dotted(text).unwrap()
    }

    #[test]
    fn sets_present_absent_and_element_keys() {
        let t = disk();
        let spec = t
            .spec_with(&[
                (key("motion.tilt_deg"), 45.0),
                (key("body.mass"), 3.0),
                (key("initial.omega.2"), 5.0),
                (key("solver.rtol"), 1e-8),
            ])
            .unwrap();
        let direction = spec
            .motion
            .as_ref()
            .and_then(MotionSpec::axis)
            .map(|a| a.direction);
        assert_eq!(direction, Some(AxisDirection::TiltDeg(45.0)));
        assert_eq!(spec.body.mass, 3.0);
        assert_eq!(spec.initial.unwrap().omega, Some([0.0, 0.0, 5.0]));
        assert_eq!(spec.solver.rtol, Some(1e-8));
    }

    #[test]
    fn refuses_unknown_non_numeric_and_missing_arrays() {
        let t = disk();
        let unknown = t
            .check_numeric_key(&key("motion.tilt_degs"), 1.0)
            .unwrap_err();
        assert!(
            unknown.contains("not a key of the scene format"),
            "{unknown}"
        );
        let text = t.check_numeric_key(&key("solver.method"), 1.0).unwrap_err();
        assert!(text.contains("not a numeric key"), "{text}");
        let table = t.check_numeric_key(&key("motion"), 1.0).unwrap_err();
        assert!(table.contains("not a numeric key"), "{table}");
        let missing = t.check_numeric_key(&key("effect.0.c"), 1.0).unwrap_err();
        assert!(missing.contains("does not give this array"), "{missing}");
        let range = t
            .check_numeric_key(&key("initial.omega.3"), 1.0)
            .unwrap_err();
        assert!(range.contains("out of range (the array has 3"), "{range}");
        assert!(t.check_numeric_key(&key("motion.rate"), 1.0).is_ok());
    }

    #[test]
    fn a_misspelt_key_names_the_nearest_valid_key() {
        let t = disk();
        let array = t.check_numeric_key(&key("effects.0.c"), 1.0).unwrap_err();
        assert!(
            array.contains("the nearest valid key is `effect.0.c`"),
            "{array}"
        );
        assert!(!array.contains("does not give this array"), "{array}");
        let table = t.check_numeric_key(&key("solvr.rtol"), 1e-8).unwrap_err();
        assert!(
            table.contains("the nearest valid key is `solver.rtol`"),
            "{table}"
        );
        let leaf = t
            .check_numeric_key(&key("motion.tilt_degs"), 1.0)
            .unwrap_err();
        assert!(
            leaf.contains("the nearest valid key is `motion.tilt_deg`"),
            "{leaf}"
        );
    }
}
