//! Every bundled scenario's CSV stays byte-identical: a refactor must not change a digit (issue 33, "Done when").
//! `tests/golden/scenario_csv.txt` keeps, per scenario, the FNV-1a 64-bit hash of the CSV `eulerdyn run` writes,
//! its length and its row count. A change of output that is meant (a new column, a fixed bug) is blessed with
//! `EULERDYN_BLESS=1 cargo test --release --test it scenario_csv` and the new file is committed with the reason.

use std::fmt::Write as _;
use std::fs;

use crate::common::{bundled_scenarios, eulerdyn, repo_path};

const GOLDEN: &str = "tests/golden/scenario_csv.txt";

/// FNV-1a, 64 bits (Fowler, Noll & Vo; the offset basis and prime of the published parameters).
fn fnv1a64(bytes: &[u8]) -> u64 {
    (bytes.iter()).fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// One line per bundled scenario, in file-name order: `name hash bytes rows`.
fn fingerprints() -> String {
    let dir = tempfile::tempdir().unwrap();
    let scenes = bundled_scenarios();
    let mut text = String::new();
    for scene in scenes {
        let name = scene.file_stem().unwrap().to_string_lossy().into_owned();
        let out = dir.path().join(format!("{name}.csv"));
        eulerdyn([
            "run",
            scene.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "-q",
        ])
        .expect_code(0);
        let bytes = fs::read(&out).unwrap();
        let rows = bytes.iter().filter(|&&b| b == b'\n').count() - 1;
        writeln!(
            text,
            "{name} {:016x} {} {rows}",
            fnv1a64(&bytes),
            bytes.len()
        )
        .unwrap();
    }
    text
}

#[test]
fn fnv1a64_matches_the_published_test_vectors() {
    // The FNV test suite (isthe.com/chongo/src/fnv/test_fnv.c): "" and "a" under FNV-1a 64.
    assert_eq!(fnv1a64(b""), 0xcbf2_9ce4_8422_2325);
    assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
}

#[test]
fn every_bundled_scenario_writes_the_same_bytes() {
    let now = fingerprints();
    let path = repo_path(GOLDEN);
    if std::env::var_os("EULERDYN_BLESS").is_some() {
        fs::write(&path, &now).unwrap();
        return;
    }
    let kept = fs::read_to_string(&path).unwrap_or_default();
    let differ: Vec<String> = (now.lines().zip(kept.lines()))
        .filter(|(a, b)| a != b)
        .map(|(a, b)| format!("  now  {a}\n  kept {b}"))
        .collect();
    assert!(
        differ.is_empty() && now.lines().count() == kept.lines().count(),
        "a bundled scenario's CSV changed (bless with EULERDYN_BLESS=1 if it is meant):\n{}\n\
         ({} scenarios now, {} kept in {GOLDEN})",
        differ.join("\n"),
        now.lines().count(),
        kept.lines().count()
    );
}
