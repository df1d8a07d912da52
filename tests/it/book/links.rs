//! No broken link: every relative link and image of the book (and of README.md) names an existing file, and an
//! anchor names a heading of that file, as mdBook makes its ids.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use super::{book_files, shown};
use crate::common::repo_path;

/// The text of `text` outside code: fenced blocks and inline code spans removed (lines kept).
fn prose(text: &str) -> String {
    let mut out = String::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        } else if !fenced {
            let spans: Vec<&str> = line.split('`').collect();
            for piece in spans.iter().step_by(2) {
                out.push_str(piece);
            }
        }
        out.push('\n');
    }
    out
}

/// The targets of `[text](target)` and `![alt](target)` in `text`, with their line numbers.
pub(super) fn link_targets(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    for (n, line) in prose(text).lines().enumerate() {
        for (i, _) in line.match_indices("](") {
            let rest = &line[i + 2..];
            if let Some(end) = rest.find(')') {
                let target = rest[..end].split_whitespace().next().unwrap_or("");
                out.push((n + 1, target.to_string()));
            }
        }
    }
    out
}

/// The ids mdBook gives the headings of `text`: lower case, letters, digits, `-` and `_` kept, spaces to `-`, the
/// rest dropped; a repeated id gets `-1`, `-2`, ….
pub(super) fn heading_ids(text: &str) -> BTreeSet<String> {
    let mut ids = BTreeSet::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        }
        let Some(title) = line.strip_prefix('#').filter(|_| !fenced) else {
            continue;
        };
        let title = title.trim_start_matches('#').trim();
        let id: String = (title.chars())
            .filter_map(|c| match c {
                c if c.is_alphanumeric() || c == '_' || c == '-' => {
                    Some(c.to_lowercase().next().unwrap())
                }
                c if c.is_whitespace() => Some('-'),
                _ => None,
            })
            .collect();
        let mut unique = id.clone();
        let mut k = 1;
        while ids.contains(&unique) {
            unique = format!("{id}-{k}");
            k += 1;
        }
        ids.insert(unique);
    }
    ids
}

/// What is wrong with the link `target` of the file `from`, if anything.
fn broken(from: &Path, target: &str) -> Option<String> {
    if target.contains("://") || target.starts_with("mailto:") || target.is_empty() {
        return None;
    }
    let (file, anchor) = target.split_once('#').unwrap_or((target, ""));
    let path: PathBuf = if file.is_empty() {
        from.to_path_buf()
    } else {
        from.parent().unwrap().join(file)
    };
    if !path.exists() {
        return Some(format!("{target}: no file {}", path.display()));
    }
    let is_markdown = path.extension().is_some_and(|e| e == "md");
    if anchor.is_empty() || !is_markdown {
        return None;
    }
    let ids = heading_ids(&std::fs::read_to_string(&path).unwrap());
    (!ids.contains(anchor)).then(|| format!("{target}: no heading with the id `{anchor}`"))
}

/// The files `{{#include FILE}}` names in `text`.
fn includes(text: &str) -> Vec<String> {
    (text.match_indices("{{#include "))
        .filter_map(|(i, _)| {
            let rest = &text[i + "{{#include ".len()..];
            let end = rest.find("}}")?;
            Some(rest[..end].split(':').next()?.trim().to_string())
        })
        .collect()
}

#[test]
fn every_link_and_image_resolves() {
    let mut files = book_files();
    files.push(repo_path("README.md"));
    let mut bad = Vec::new();
    for path in &files {
        let text = std::fs::read_to_string(path).unwrap();
        for (line, target) in link_targets(&text) {
            if let Some(problem) = broken(path, &target) {
                bad.push(format!("{}:{line}: {problem}", shown(path)));
            }
        }
        for file in includes(&text) {
            if let Some(problem) = broken(path, &file) {
                bad.push(format!("{}: include {problem}", shown(path)));
            }
        }
    }
    assert!(bad.is_empty(), "broken links:\n{}", bad.join("\n"));
}

#[test]
fn every_chapter_is_in_the_summary() {
    let summary_path = repo_path("docs/book/src/SUMMARY.md");
    let summary = std::fs::read_to_string(&summary_path).unwrap();
    let listed: BTreeSet<String> = link_targets(&summary).into_iter().map(|(_, t)| t).collect();
    let src = repo_path("docs/book/src");
    let missing: Vec<String> = (book_files().iter())
        .map(|p| p.strip_prefix(&src).unwrap().display().to_string())
        .filter(|p| p != "SUMMARY.md" && !listed.contains(p))
        .collect();
    assert!(
        missing.is_empty(),
        "chapters not in SUMMARY.md: {missing:?}"
    );
}

#[test]
fn ids_are_made_as_mdbook_makes_them() {
    let ids = heading_ids("# Two forms of Euler's equation, and I(θ)\n## `run -o`\n## A\n## A\n");
    let want = ["two-forms-of-eulers-equation-and-iθ", "run--o", "a", "a-1"];
    assert_eq!(ids, want.iter().map(|s| s.to_string()).collect());
}

/// The repository paths (`tests/…`, `src/…`, `core/…`, `scenarios/…`, `benches/…`, `python/…`, `examples/…`, `engines/…`)
/// that `text` cites outside fenced blocks, with their line numbers; a pattern (`*`, `{`, `<`) or a placeholder
/// (`core/src/motion/NAME.rs`) is not one.
fn cited_paths(text: &str) -> Vec<(usize, String)> {
    const ROOTS: [&str; 8] = [
        "tests/",
        "src/",
        "core/",
        "scenarios/",
        "benches/",
        "python/",
        "examples/",
        "engines/",
    ];
    let in_path = |c: char| c.is_ascii_alphanumeric() || "_./-".contains(c);
    let mut out = Vec::new();
    let mut fenced = false;
    for (n, line) in text.lines().enumerate() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        for root in ROOTS {
            for (i, _) in line.match_indices(root) {
                if line[..i].chars().next_back().is_some_and(in_path) {
                    continue; // part of a longer path, e.g. docs/book/src/…
                }
                let rest = &line[i..];
                let end = rest.find(|c: char| !in_path(c)).unwrap_or(rest.len());
                let path = rest[..end].trim_end_matches(['.', ',', ':', '/']);
                let placeholder = path.split('/').any(|part| {
                    let stem = part.split('.').next().unwrap_or("");
                    !stem.is_empty() && stem.chars().all(|c| c.is_ascii_uppercase() || c == '_')
                });
                let pattern = placeholder || rest[end..].starts_with(['*', '{', '<']);
                if !pattern && path.len() > root.len() {
                    out.push((n + 1, path.to_string()));
                }
            }
        }
    }
    out
}

/// Issue 57: the book cited test files by paths they had left. Every repository path it cites exists.
#[test]
fn every_repository_path_the_book_cites_exists() {
    let mut files = book_files();
    files.push(repo_path("README.md"));
    files.push(repo_path("ARCHITECTURE.md"));
    let mut bad = Vec::new();
    for path in &files {
        let text = std::fs::read_to_string(path).unwrap();
        for (line, cited) in cited_paths(&text) {
            // From the repository's root, or from the book's (`src/SUMMARY.md`).
            let book = repo_path("docs/book").join(&cited);
            if !repo_path(&cited).exists() && !book.exists() {
                bad.push(format!("{}:{line}: {cited}", shown(path)));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "paths that do not exist:\n{}",
        bad.join("\n")
    );
}

#[test]
fn cited_paths_are_found_whole_and_patterns_left_out() {
    let text = "see tests/it/book.rs, and `scenarios/tilted_disk.toml`.\n```sh\neulerdyn run src/nothing.rs\n```\n\
                docs/book/src/x.md and scenarios/sweeps/*.toml, core/src/motion/NAME.rs";
    let cited: Vec<String> = cited_paths(text).into_iter().map(|(_, p)| p).collect();
    assert_eq!(cited, ["tests/it/book.rs", "scenarios/tilted_disk.toml"]);
}
