#!/usr/bin/env bash
# The library without the command line: a crate that depends on eulerdyn with `default-features = false` builds
# and runs the README's "From Rust code" example (taken from the README itself), and `cargo tree` shows none of
# clap, indicatif, ctrlc, plotters, resvg, rayon or rand in it (the core only: CONTRACT.md, fourth round). Shares this checkout's target directory, so only eulerdyn itself is compiled again.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/src"
cat > "$work/Cargo.toml" <<TOML
[package]
name = "uses-eulerdyn"
version = "0.0.0"
edition = "2024"
publish = false

[dependencies]
eulerdyn = { path = "$root", default-features = false }

[workspace]
TOML
# Same versions as the project's own lock file.
cp "$root/Cargo.lock" "$work/Cargo.lock"
# The README's example: the first ```rust block under "## From Rust code", inside a main that returns errors.
example="$(awk '/^## From Rust code/{f=1} f&&/^```rust/{b=1;next} b&&/^```/{exit} b{print}' "$root/README.md")"
[ -n "$example" ] || { echo "library_only: no rust example under '## From Rust code' in README.md" >&2; exit 1; }
{
  echo 'fn main() -> Result<(), Box<dyn std::error::Error>> {'
  echo "$example"
  echo '    Ok(())'
  echo '}'
} > "$work/src/main.rs"
tree="$(cargo tree --manifest-path "$work/Cargo.toml" -e normal --prefix none)"
for crate in clap indicatif ctrlc plotters resvg rayon rand rand_distr; do
  if grep -q "^$crate v" <<<"$tree"; then
    echo "library_only: $crate is compiled for a library user (default-features = false)" >&2
    exit 1
  fi
done
out="$(CARGO_TARGET_DIR="$root/target" cargo run -q --manifest-path "$work/Cargo.toml")"
grep -q "^H_s at t = 1 s: " <<<"$out" || { echo "library_only: unexpected output: $out" >&2; exit 1; }
# None of the embedded assets: three.js (feature `view`) and the DejaVu Sans font (feature `plot`).
bin="$root/target/debug/uses-eulerdyn"
for marker in OrbitControls "DejaVu Sans"; do
  if grep -q "$marker" "$bin"; then
    echo "library_only: the core's binary embeds '$marker' (an asset of a feature that is off)" >&2
    exit 1
  fi
done
echo "library_only: the README's Rust example ran with the core only (no clap, indicatif, ctrlc, plotters, resvg, rayon or rand): $out"
