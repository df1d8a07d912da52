//! Messages in the scene author's words: broken syntax named by its line, values of the wrong kind said plainly,
//! numbers printed as written (exponent form), `[effect]` for `[[effect]]`.

use crate::common::{eulerdyn, write_file};

const BASE: &str = "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n";
const TAIL: &str = "[solver]\nt_end = 1.0\n[output]\nevery = 0.1\n";

/// The stderr of `run` on `text` with `flags`, which must be refused with exit 2.
fn refusal(text: &str, flags: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(dir.path(), "scene.toml", text);
    let mut args = vec!["run", scene.to_str().unwrap()];
    args.extend_from_slice(flags);
    let out = eulerdyn(args);
    assert_eq!(out.code, Some(2), "{}", out.stderr);
    out.stderr
}

#[test]
fn an_unclosed_table_is_named_by_its_own_line_not_the_key_before_it() {
    let err = refusal(
        &format!("{BASE}[solver\nt_end = 1.0\n[output]\nevery = 0.1\n"),
        &[],
    );
    assert!(
        err.contains(":4:") && err.contains("in the line `[solver`"),
        "{err}"
    );
    assert!(!err.contains("key `body`"), "{err}");
}

#[test]
fn a_number_with_a_unit_is_refused_in_plain_words() {
    let text = format!(
        "{BASE}[motion]\ntype = \"fixed_axis\"\naxis = [0.0, 0.0, 1.0]\nrate = \"1000 rpm\"\n{TAIL}"
    );
    let err = refusal(&text, &[]);
    assert!(
        err.contains("motion.rate") && err.contains("without a unit"),
        "{err}"
    );
    assert!(!err.contains("f64"), "Rust's words: {err}");
}

#[test]
fn a_single_effect_table_is_told_to_be_an_array_of_tables() {
    let err = refusal(
        &format!("{BASE}[effect]\ntype = \"damping\"\nc = 0.1\n{TAIL}"),
        &[],
    );
    assert!(err.contains("write [[effect]]"), "{err}");
    assert!(!err.contains("expected a sequence"), "serde's words: {err}");
}

#[test]
fn a_tiny_tolerance_is_printed_in_exponent_form() {
    let err = refusal(&format!("{BASE}{TAIL}"), &["--rtol", "1e-20"]);
    assert!(err.contains("got 1e-20"), "{err}");
    assert!(!err.contains("0.0000000000"), "{err}");
}

#[test]
fn accuracy_help_lists_every_column_of_the_table() {
    let help = eulerdyn(["accuracy", "--help"]);
    help.expect_code(0);
    let columns = eulerdyn::analysis::study::TABLE_COLUMNS.join(",");
    assert!(
        help.stdout.contains(&columns),
        "{columns} in\n{}",
        help.stdout
    );
}
