//! The book (`docs/book/src`) cannot go stale: every ```toml block is a scene that `eulerdyn check` accepts, every
//! ```console block prints what it shows, every block that is not run says why, every relative link and image
//! resolves, and the reference tables are the code's (`EULERDYN_BLESS=1 cargo test --release --test it book`
//! rewrites them). ```rust blocks are doctests (lib.rs), ```python blocks run in `python/tests/test_book.py`.

mod blocks;
mod links;
mod tables;

use std::path::{Path, PathBuf};

use crate::common::repo_path;

/// Every Markdown file of the book, sorted.
fn book_files() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "md") {
                out.push(path);
            }
        }
    }
    let mut files = Vec::new();
    walk(&repo_path("docs/book/src"), &mut files);
    files.sort();
    files
}

/// `path` relative to the repository root, for messages.
fn shown(path: &Path) -> String {
    path.strip_prefix(repo_path(""))
        .unwrap_or(path)
        .display()
        .to_string()
}

/// Whether `EULERDYN_BLESS` asks the tests to rewrite what they compare.
fn blessing() -> bool {
    std::env::var_os("EULERDYN_BLESS").is_some()
}
