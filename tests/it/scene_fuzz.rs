//! Random and mutated scene documents through the parser, the validator and what `check` prints: nothing panics,
//! and every rejection says where — a key, or for text with no key at all, a line and column.
//!
//! CI runs 500 cases per property. For a release check run more, e.g.
//! `PROPTEST_CASES=20000 cargo test --release --test scene_fuzz`.

use std::path::Path;

use eulerdyn::analysis::describe::describe;
use eulerdyn::scene::{self, Overrides, SceneError};
use proptest::prelude::*;

/// 500 cases per property, or `PROPTEST_CASES` when set.
fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(500)
}

fn scenarios() -> Vec<String> {
    let mut out: Vec<String> = std::fs::read_dir("scenarios")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect();
    out.sort();
    out
}

/// Parses, validates and describes: the whole of `eulerdyn check` but the printing.
fn check(text: &str) -> Result<String, SceneError> {
    scene::parse(Path::new("fuzz.toml"), text, &Overrides::default())
        .map(|s| describe(&s, &[]).text())
}

fn assert_says_where(text: &str, result: &Result<String, SceneError>) {
    if let Err(e) = result {
        let message = e.to_string();
        assert!(message.starts_with("fuzz.toml"), "no file in: {message}");
        assert!(!e.problem.is_empty(), "no problem in: {message}");
        assert!(
            e.key.is_some() || e.location.is_some() || text.trim().is_empty(),
            "neither key nor line for:\n{text}\n=> {message}"
        );
    }
}

/// A value a mutation may put in place of another: wrong types, out of range, non-finite, arrays of wrong length.
fn replacement() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("nan".to_string()),
        Just("inf".to_string()),
        Just("-inf".to_string()),
        Just("0".to_string()),
        Just("-1.0".to_string()),
        Just("1e308".to_string()),
        Just("1e-320".to_string()),
        Just("\"text\"".to_string()),
        Just("true".to_string()),
        Just("[]".to_string()),
        Just("[1.0, 2.0]".to_string()),
        Just("[1.0, 2.0, 3.0, 4.0]".to_string()),
        Just("[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]]".to_string()),
        Just("{ type = \"nope\" }".to_string()),
        any::<f64>().prop_map(|v| format!("{v:?}")),
        (-1e3f64..1e3).prop_map(|v| format!("{v:?}")),
    ]
}

/// One mutation of a scene's lines.
#[derive(Debug, Clone)]
enum Mutation {
    DeleteLine(usize),
    DuplicateLine(usize),
    ReplaceValue(usize, String),
    InsertUnknownKey(usize),
    Truncate(usize),
    SwapLines(usize, usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        any::<usize>().prop_map(Mutation::DeleteLine),
        any::<usize>().prop_map(Mutation::DuplicateLine),
        (any::<usize>(), replacement()).prop_map(|(i, v)| Mutation::ReplaceValue(i, v)),
        any::<usize>().prop_map(Mutation::InsertUnknownKey),
        any::<usize>().prop_map(Mutation::Truncate),
        (any::<usize>(), any::<usize>()).prop_map(|(a, b)| Mutation::SwapLines(a, b)),
    ]
}

fn apply(text: &str, mutations: &[Mutation]) -> String {
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    for m in mutations {
        if lines.is_empty() {
            break;
        }
        let n = lines.len();
        match m {
            Mutation::DeleteLine(i) => {
                lines.remove(i % n);
            }
            Mutation::DuplicateLine(i) => {
                let line = lines[i % n].clone();
                lines.insert(i % n, line);
            }
            Mutation::ReplaceValue(i, v) => {
                let line = &mut lines[i % n];
                if let Some((key, _)) = line.split_once('=') {
                    *line = format!("{key}= {v}");
                }
            }
            Mutation::InsertUnknownKey(i) => lines.insert(i % n, "colour = 3".into()),
            Mutation::Truncate(i) => {
                let joined = lines.join("\n");
                let mut cut = i % (joined.len() + 1);
                while !joined.is_char_boundary(cut) {
                    cut -= 1;
                }
                lines = joined[..cut].lines().map(String::from).collect();
            }
            Mutation::SwapLines(a, b) => lines.swap(a % n, b % n),
        }
    }
    lines.join("\n")
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn mutated_scenarios_never_panic_and_rejections_name_the_place(
        which in any::<usize>(),
        mutations in prop::collection::vec(mutation(), 1..4),
    ) {
        let all = scenarios();
        let text = apply(&all[which % all.len()], &mutations);
        let result = check(&text);
        assert_says_where(&text, &result);
    }

    #[test]
    fn random_text_never_panics(text in "\\PC{0,200}") {
        let result = check(&text);
        assert_says_where(&text, &result);
    }

    #[test]
    fn random_tables_of_plausible_keys_never_panic(
        keys in prop::collection::vec(
            (prop::sample::select(vec![
                "body", "motion", "initial", "solver", "output", "compare", "effect", "body.shape",
            ]),
            prop::sample::select(vec![
                "mass", "shape", "inertia", "type", "axis", "tilt_deg", "rate", "accel", "point", "omega",
                "attitude", "frame", "value", "profile", "freq_hz", "phase_deg", "t_on", "t_off", "g", "pivot",
                "c", "method", "rtol", "atol", "dt", "t_end", "every", "tolerance", "radius", "length", "size",
            ]),
            replacement()),
            0..14,
        ),
    ) {
        let mut text = String::new();
        for (table, key, value) in keys {
            if table == "effect" {
                text.push_str(&format!("[[effect]]\n{key} = {value}\n"));
            } else {
                text.push_str(&format!("[{table}]\n{key} = {value}\n"));
            }
        }
        let result = check(&text);
        assert_says_where(&text, &result);
    }
}

#[test]
fn every_bundled_scenario_is_valid() {
    for text in scenarios() {
        check(&text).unwrap();
    }
}
