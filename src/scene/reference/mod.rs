//! The scene file's keys, declared once for the reader: each table's keys with their type, unit, default, the
//! origin a position is measured from, and meaning. The book's key reference is generated from [`keys`] (the
//! test `tests/it/book.rs`), and the unit test below checks that the declaration lists exactly the keys serde
//! accepts in each table (`deny_unknown_fields`), so that neither can drift from the code.
//!
//! Every position in body axes is measured from the *reference origin*: the shape's center, or the point the given
//! `inertia` is about (C when there are no point masses).

mod tables;

/// One key of a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Key {
    /// The key as written in the file.
    pub name: &'static str,
    /// What the value is: `number`, `[x, y, z]`, a string from a list, a table…
    pub kind: &'static str,
    /// SI unit (`1` dimensionless, `–` none).
    pub unit: &'static str,
    /// The value when the key is absent (`required` when it may not be).
    pub default: &'static str,
    /// For a position: the point it is measured from and its axes; else empty.
    pub origin: &'static str,
    /// What it means, its bounds.
    pub doc: &'static str,
}

/// One table of a scene file and its keys.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Table {
    /// As written in the file (`[body]`, `[[effect]]`; the top level is empty).
    pub header: &'static str,
    /// What the table is.
    pub about: &'static str,
    /// Its keys, in the order of the file form.
    pub keys: &'static [Key],
}

/// Every table of a scene file, in the order of the file form, with every key each accepts.
pub fn keys() -> &'static [Table] {
    &tables::TABLES
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;
    use std::path::Path;

    /// The keys serde accepts in `header`'s table: its message for an unknown key lists every expected field.
    fn accepted(header: &str) -> BTreeSet<String> {
        let text = format!("{header}\nzz_not_a_key = 1\n");
        let err = crate::scene::parse_spec(Path::new("keys.toml"), &text).unwrap_err();
        let problem = err.problem.clone();
        let (_, expected) = problem
            .split_once("expected")
            .unwrap_or_else(|| panic!("{header}: no field list in `{problem}`"));
        expected
            .split('`')
            .skip(1)
            .step_by(2)
            .map(String::from)
            .collect()
    }

    #[test]
    fn every_table_lists_exactly_the_keys_serde_accepts() {
        for table in keys() {
            let declared: BTreeSet<String> =
                table.keys.iter().map(|k| k.name.to_string()).collect();
            assert_eq!(
                declared.len(),
                table.keys.len(),
                "{}: a key twice",
                table.header
            );
            assert_eq!(accepted(table.header), declared, "table `{}`", table.header);
        }
    }

    #[test]
    fn the_solver_defaults_are_the_code_defaults() {
        use crate::method::{Method, defaults};
        let solver = keys().iter().find(|t| t.header == "[solver]").unwrap();
        let default = |name: &str| solver.keys.iter().find(|k| k.name == name).unwrap().default;
        assert_eq!(default("method"), format!("\"{}\"", Method::DEFAULT.name()));
        assert_eq!(default("rtol"), format!("{:e}", defaults::RTOL));
        assert_eq!(default("atol"), format!("{:e}", defaults::ATOL));
        assert_eq!(default("dt"), format!("{:e}", defaults::DT));
    }
}
