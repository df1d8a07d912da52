//! The outputs the README and the book show are the commands' outputs, so that they cannot go stale: the code block
//! after a line `<!-- output of: eulerdyn ARGS -->` must be exactly what `eulerdyn ARGS` prints on stdout, run from
//! the repository root. `EULERDYN_BLESS=1 cargo test --test readme` rewrites the blocks from the commands.

use crate::common::{eulerdyn, repo_path};

const MARK: &str = "<!-- output of: eulerdyn ";

/// One shown output: the command's arguments and the lines of the README its block spans (fences excluded).
struct Shown {
    args: Vec<String>,
    lines: std::ops::Range<usize>,
}

/// Every marked block of `lines`.
fn shown_outputs(lines: &[&str]) -> Vec<Shown> {
    let mut found = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let Some(rest) = line.strip_prefix(MARK) else {
            continue;
        };
        let args = rest
            .strip_suffix(" -->")
            .unwrap_or_else(|| panic!("line {}: the mark must end with ` -->`", i + 1));
        assert!(
            lines.get(i + 1).is_some_and(|l| l.starts_with("```")),
            "line {}: the mark must be followed by a code block",
            i + 1
        );
        let end = (i + 2..lines.len())
            .find(|&k| lines[k] == "```")
            .unwrap_or_else(|| panic!("line {}: the code block is not closed", i + 2));
        found.push(Shown {
            args: args.split_whitespace().map(str::to_string).collect(),
            lines: i + 2..end,
        });
    }
    found
}

/// The shown outputs of `path` that the commands no longer print (rewritten in place when blessing).
fn stale_outputs(path: &std::path::Path) -> Vec<String> {
    let name = path
        .strip_prefix(repo_path(""))
        .unwrap_or(path)
        .display()
        .to_string();
    let text = std::fs::read_to_string(path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let shown = shown_outputs(&lines);
    let bless = std::env::var_os("EULERDYN_BLESS").is_some();
    let mut blessed: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
    let mut stale = Vec::new();
    for s in shown.iter().rev() {
        let out = eulerdyn(&s.args);
        assert!(
            matches!(out.code, Some(0 | 1)),
            "eulerdyn {}: {}",
            s.args.join(" "),
            out.stderr
        );
        let printed: Vec<String> = out.stdout.lines().map(str::to_string).collect();
        if printed.as_slice() != &blessed[s.lines.clone()] {
            stale.push(format!(
                "{name}:{}: `eulerdyn {}` now prints\n{}",
                s.lines.start + 1,
                s.args.join(" "),
                out.stdout
            ));
            blessed.splice(s.lines.clone(), printed);
        }
    }
    if bless && !stale.is_empty() {
        std::fs::write(path, blessed.join("\n") + "\n").unwrap();
        return Vec::new();
    }
    stale
}

/// README.md and the book's chapters (`docs/book/src`, where the README's sections went).
fn documents() -> Vec<std::path::PathBuf> {
    let mut files = vec![repo_path("README.md")];
    let mut dirs = vec![repo_path("docs/book/src")];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "md") {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

#[test]
fn the_readme_shows_what_the_commands_print() {
    let files = documents();
    let marked = files.iter().any(|path| {
        let text = std::fs::read_to_string(path).unwrap();
        !shown_outputs(&text.lines().collect::<Vec<_>>()).is_empty()
    });
    assert!(marked, "no `{MARK}…-->` mark in README.md or the book");
    let stale: Vec<String> = files.iter().flat_map(|path| stale_outputs(path)).collect();
    assert!(
        stale.is_empty(),
        "{}\n(EULERDYN_BLESS=1 cargo test --test readme rewrites the blocks)",
        stale.join("\n")
    );
}

/// Issue 57: pip said nothing for minutes while it compiled Rust. The README and the install page each say that pip
/// compiles Rust silently and show `pip install -v ./python`, which prints cargo's progress.
#[test]
fn the_set_up_pages_say_pip_compiles_rust_and_show_its_verbose_form() {
    for page in ["README.md", "docs/book/src/getting-started/install.md"] {
        let text = std::fs::read_to_string(repo_path(page)).unwrap();
        let flat = text.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(
            flat.contains("pip install -v ./python") && flat.contains("cargo's progress"),
            "{page} does not show `pip install -v ./python` and what it prints"
        );
        assert!(
            flat.contains("while Rust compiles") || flat.contains("while it compiles Rust"),
            "{page} does not say that pip is silent while it compiles Rust"
        );
    }
}
