//! Where keys are in a scene file's text: key paths, byte offset → line and column, and key path ↔ span.

use std::ops::Range;

use toml::de::{DeTable, DeValue};

pub use crate::keys::KeyPath;
pub(crate) use crate::keys::Segment;

/// A scene file's text, for turning offsets and key paths into line and column.
pub struct SourceMap<'a> {
    text: &'a str,
}

/// A key found in the text: its path, the span of the key and the span of its value.
struct Entry {
    path: KeyPath,
    key_span: Range<usize>,
    value_span: Range<usize>,
}

impl<'a> SourceMap<'a> {
    /// The map of a scene file's `text`.
    pub fn new(text: &'a str) -> Self {
        Self { text }
    }

    /// 1-based line and column (in characters) of a byte offset.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.text.len());
        let before = self.text.get(..offset).unwrap_or(self.text);
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let col = before[line_start..].chars().count() + 1;
        (line, col)
    }

    /// The text of the line holding the byte offset, trimmed.
    pub fn line_text(&self, offset: usize) -> &str {
        let (line, _) = self.line_col(offset);
        self.text.lines().nth(line - 1).unwrap_or("").trim()
    }

    /// The innermost key whose key or value contains the byte offset.
    pub fn key_at(&self, offset: usize) -> Option<KeyPath> {
        self.entries()
            .into_iter()
            .filter(|e| e.key_span.contains(&offset) || e.value_span.contains(&offset))
            .min_by_key(|e| {
                let k = e.key_span.len();
                if e.key_span.contains(&offset) {
                    k
                } else {
                    e.value_span.len()
                }
            })
            .map(|e| e.path)
    }

    /// The table whose value spans exactly `span` (the innermost one), or the root when no table does: where the
    /// parser reports a missing key.
    pub fn table_at(&self, span: &Range<usize>) -> KeyPath {
        self.entries()
            .into_iter()
            .filter(|e| e.value_span == *span)
            .max_by_key(|e| e.path.segments().len())
            .map_or_else(KeyPath::root, |e| e.path)
    }

    /// For text that does not parse as TOML: the key written on the line of `offset`, inside the table opened by the
    /// last `[table]` or `[[array]]` header before it — read from the text itself. `None` when neither is there.
    pub fn key_near(&self, offset: usize) -> Option<KeyPath> {
        let mut cut = offset.min(self.text.len());
        while !self.text.is_char_boundary(cut) {
            cut -= 1;
        }
        let (before, after) = self.text.split_at(cut);
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let mut table = KeyPath::root();
        let mut array_counts: Vec<(String, usize)> = Vec::new();
        for line in before[..line_start].lines().map(str::trim) {
            if let Some(name) = line.strip_prefix("[[").and_then(|r| r.split("]]").next()) {
                let name = name.trim().to_string();
                let index = match array_counts.iter_mut().find(|(n, _)| *n == name) {
                    Some((_, count)) => {
                        *count += 1;
                        *count
                    }
                    None => {
                        array_counts.push((name.clone(), 0));
                        0
                    }
                };
                table = dotted(KeyPath::root(), &name).index(index);
            } else if let Some(name) = line.strip_prefix('[').and_then(|r| r.split(']').next()) {
                table = dotted(KeyPath::root(), name.trim());
            }
        }
        let line = before[line_start..].to_string() + after.lines().next().unwrap_or("");
        // The key before `=`, or, on a line with no `=`, the first word (what the parser took for a key).
        let key = line
            .split_once('=')
            .map_or_else(|| line.split_whitespace().next().unwrap_or(""), |(k, _)| k)
            .trim();
        let key = Some(key).filter(|k| {
            !k.is_empty()
                && k.chars()
                    .all(|c| c.is_ascii_alphanumeric() || "_-.".contains(c))
        });
        match key {
            Some(k) => Some(dotted(table, k)),
            None if !table.is_root() => Some(table),
            None => None,
        }
    }

    /// Line and column of a key (of its value where the key is written, else of the key), or of the nearest
    /// enclosing key that is written in the file. `None` for values from the command line.
    pub fn locate(&self, path: &KeyPath) -> Option<(usize, usize)> {
        if path.is_from_flag() {
            return None;
        }
        let entries = self.entries();
        let mut prefix = path.segments();
        while !prefix.is_empty() {
            if let Some(e) = entries.iter().find(|e| e.path.segments() == prefix) {
                return Some(self.line_col(e.key_span.start));
            }
            prefix = &prefix[..prefix.len() - 1];
        }
        None
    }

    fn entries(&self) -> Vec<Entry> {
        let mut out = Vec::new();
        if let Ok(table) = DeTable::parse(self.text) {
            collect_table(table.get_ref(), &KeyPath::root(), &mut out);
        }
        out
    }
}

/// `path` extended by a dotted key `a.b.c`.
fn dotted(path: KeyPath, name: &str) -> KeyPath {
    name.split('.').map(str::trim).fold(path, KeyPath::key)
}

fn collect_table(table: &DeTable<'_>, path: &KeyPath, out: &mut Vec<Entry>) {
    for (key, value) in table.iter() {
        let child = path.clone().key(key.get_ref());
        out.push(Entry {
            path: child.clone(),
            key_span: key.span(),
            value_span: value.span(),
        });
        collect_value(value.get_ref(), &child, out);
    }
}

fn collect_value(value: &DeValue<'_>, path: &KeyPath, out: &mut Vec<Entry>) {
    match value {
        DeValue::Table(t) => collect_table(t, path, out),
        DeValue::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                let child = path.clone().index(i);
                out.push(Entry {
                    path: child.clone(),
                    key_span: item.span(),
                    value_span: item.span(),
                });
                collect_value(item.get_ref(), &child, out);
            }
        }
        _ => {}
    }
}
