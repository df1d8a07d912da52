//! The book's code blocks: scenes through `check`, shell sessions against their shown output, and the reason of
//! every block that is not run.

use std::path::Path;
use std::process::Command;

use super::{book_files, shown};
use crate::common::{eulerdyn, repo_path};

/// One fenced block: its file, the 1-based line of its opening fence, its info string, its lines (without the
/// fence's indentation) and the line above the fence.
pub(super) struct Block {
    pub file: String,
    pub line: usize,
    pub info: String,
    pub body: Vec<String>,
    pub above: String,
}

/// The fenced blocks of `text` (fences may be indented, as in a list).
pub(super) fn blocks_of(file: &str, text: &str) -> Vec<Block> {
    let lines: Vec<&str> = text.lines().collect();
    let mut found = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let indent = lines[i].len() - lines[i].trim_start().len();
        let Some(info) = lines[i].trim_start().strip_prefix("```") else {
            i += 1;
            continue;
        };
        let end = (i + 1..lines.len())
            .find(|&k| lines[k].trim_start() == "```")
            .unwrap_or_else(|| panic!("{file}:{}: the block is not closed", i + 1));
        let body = lines[i + 1..end]
            .iter()
            .map(|l| l.get(indent..).unwrap_or(l.trim_start()).to_string())
            .collect();
        found.push(Block {
            file: file.to_string(),
            line: i + 1,
            info: info.trim().to_string(),
            body,
            above: if i > 0 {
                lines[i - 1].trim().into()
            } else {
                String::new()
            },
        });
        i = end + 1;
    }
    found
}

/// Every block of the book.
pub(super) fn book_blocks() -> Vec<Block> {
    (book_files().iter())
        .flat_map(|path| blocks_of(&shown(path), &std::fs::read_to_string(path).unwrap()))
        .collect()
}

/// The languages whose blocks a test runs.
const RUN: [&str; 4] = ["toml", "console", "python", "rust"];

/// Whether `line` is `<!-- not runnable: REASON -->` with a reason.
fn says_why(line: &str) -> bool {
    (line.strip_prefix("<!-- not runnable:"))
        .and_then(|rest| rest.strip_suffix("-->"))
        .is_some_and(|reason| !reason.trim().is_empty())
}

#[test]
fn every_block_is_run_or_says_why_not() {
    let mut wrong = Vec::new();
    for b in book_blocks() {
        let ok = if b.info.ends_with(",ignore") || b.info == "ignore" {
            says_why(&b.above)
        } else if b.info.is_empty() {
            // A command's shown output, checked by tests/it/readme.rs.
            b.above.starts_with("<!-- output of: eulerdyn ")
        } else {
            RUN.contains(&b.info.as_str())
        };
        if !ok {
            wrong.push(format!("{}:{}: ```{}", b.file, b.line, b.info));
        }
    }
    assert!(
        wrong.is_empty(),
        "blocks that are neither run nor marked `<!-- not runnable: REASON -->` + ```LANG,ignore:\n{}",
        wrong.join("\n")
    );
}

/// Removes a temporary scene however the test ends.
struct TempScene(std::path::PathBuf);

impl Drop for TempScene {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

#[test]
fn every_toml_block_is_a_scene_that_check_accepts() {
    let mut failed = Vec::new();
    let blocks: Vec<Block> = book_blocks()
        .into_iter()
        .filter(|b| b.info == "toml")
        .collect();
    assert!(!blocks.is_empty(), "no ```toml block in the book");
    for b in blocks {
        // Inside scenarios/ so that relative paths resolve as for a bundled scene; not named *.toml, so that the
        // tests that list the bundled scenes do not see it.
        let name = format!(".book-{}-{}.scene", b.file.replace(['/', '.'], "_"), b.line);
        let temp = TempScene(repo_path("scenarios").join(name));
        std::fs::write(&temp.0, b.body.join("\n") + "\n").unwrap();
        let out = eulerdyn(["check".as_ref(), temp.0.as_os_str()]);
        if out.code != Some(0) {
            failed.push(format!("{}:{}: {}", b.file, b.line, out.stderr.trim()));
        }
    }
    assert!(
        failed.is_empty(),
        "scenes that `eulerdyn check` refuses:\n{}",
        failed.join("\n")
    );
}

/// Whether `printed` matches `expected`, where an expected line `...` matches any number of lines.
pub(super) fn matches(expected: &[String], printed: &[&str]) -> bool {
    match expected.split_first() {
        None => printed.is_empty(),
        Some((first, rest)) if first == "..." => {
            (0..=printed.len()).any(|skip| matches(rest, &printed[skip..]))
        }
        Some((first, rest)) => printed
            .split_first()
            .is_some_and(|(line, more)| line == first && matches(rest, more)),
    }
}

/// The commands of a ```console block, each with the lines shown after it.
pub(super) fn commands(body: &[String]) -> Vec<(String, Vec<String>)> {
    let mut out: Vec<(String, Vec<String>)> = Vec::new();
    for line in body {
        match line.strip_prefix("$ ") {
            Some(cmd) => out.push((cmd.to_string(), Vec::new())),
            None => match out.last_mut() {
                Some((_, shown)) => shown.push(line.clone()),
                None => panic!("a console block must start with `$ `: {line}"),
            },
        }
    }
    out
}

/// Runs `cmd` with bash from the repository root, with the built `eulerdyn` first on the PATH.
pub(super) fn shell(cmd: &str) -> std::process::Output {
    let bin = Path::new(env!("CARGO_BIN_EXE_eulerdyn")).parent().unwrap();
    let path = std::env::join_paths(std::iter::once(bin.to_path_buf()).chain(
        std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()),
    ))
    .unwrap();
    Command::new("bash")
        .args(["-o", "pipefail", "-c", cmd])
        .current_dir(repo_path(""))
        .env("PATH", path)
        .output()
        .unwrap()
}

#[test]
fn every_console_block_prints_what_it_shows() {
    let mut wrong = Vec::new();
    for b in book_blocks().into_iter().filter(|b| b.info == "console") {
        for (cmd, expected) in commands(&b.body) {
            let out = shell(&cmd);
            let stdout = String::from_utf8_lossy(&out.stdout);
            // Trailing blanks are not compared: Markdown editors drop them.
            let printed: Vec<&str> = stdout.lines().map(str::trim_end).collect();
            let expected: Vec<String> = expected.iter().map(|l| l.trim_end().to_string()).collect();
            if !out.status.success() || !matches(&expected, &printed) {
                wrong.push(format!(
                    "{}:{}: `{cmd}` ({}) printed\n{stdout}{}",
                    b.file,
                    b.line,
                    out.status,
                    String::from_utf8_lossy(&out.stderr)
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_wildcard_line_matches_any_number_of_lines() {
    let e = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    assert!(matches(&e(&["a", "...", "d"]), &["a", "b", "c", "d"]));
    assert!(matches(&e(&["a", "...", "d"]), &["a", "d"]));
    assert!(!matches(&e(&["a", "...", "d"]), &["a", "b"]));
    assert!(!matches(&e(&["a"]), &["a", "b"]));
}
