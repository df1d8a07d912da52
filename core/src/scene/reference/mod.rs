//! The scene file's keys for the reader: each table's keys with their type, unit, default, the origin a position
//! is measured from, and meaning — the `TABLE` of each table's one declaration (`#[derive(Table)]` or `#[derive(Keys)]`), which also
//! makes the serde form, so the two cannot drift. The book's key reference is generated from [`keys`] (the test
//! `tests/it/book.rs`); the unit test below checks each table against the keys serde names in its message for an
//! unknown key.
//!
//! Every position in body axes is measured from the *reference origin*: the shape's center, or the point the given
//! `inertia` is about (C when there are no point masses).

pub use crate::keys::{Key, Table};
use crate::scene::spec::file_form::SceneFile;

/// Every table of a scene file, in the order of the file form: the top level, then each table a key holds after
/// the table holding it (depth first, `keys::Key::holding`), a table's parts after it — with every key each
/// accepts.
pub fn keys() -> &'static [Table] {
    fn walk(table: &Table, all: &mut Vec<Table>) {
        all.push(*table);
        for held in table.keys.iter().filter_map(|k| k.table) {
            walk(held, all);
        }
        for part in table.parts {
            walk(part, all);
        }
    }
    static ALL: std::sync::OnceLock<Vec<Table>> = std::sync::OnceLock::new();
    ALL.get_or_init(|| {
        let mut all = Vec::new();
        walk(&SceneFile::TABLE, &mut all);
        all
    })
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
