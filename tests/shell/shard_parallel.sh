#!/usr/bin/env bash
# A sweep split into 3 shards run concurrently by GNU parallel, merged as the README shows (the header once, the
# rows sorted by `run`), must equal the unsharded table in every column but `wall_s` (CONTRACT.md, "Sweeps and
# Monte Carlo": run i's draws depend only on the seed and i).
#   tests/shell/shard_parallel.sh [EULERDYN_BINARY] [SWEEP.toml]
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${1:-target/release/eulerdyn}
sweep=${2:-scenarios/sweeps/tumble_monte_carlo.toml}
command -v parallel >/dev/null || { echo "shard test: GNU parallel is not installed (apt-get install parallel)" >&2; exit 1; }
[ -x "$bin" ] || { echo "shard test: no eulerdyn binary at $bin (cargo build first)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$bin" sweep "$sweep" --jobs 2 -o "$work/whole.csv" 2>/dev/null
parallel --will-cite --halt now,fail=1 "$bin" sweep "$sweep" --jobs 1 --shard {}/3 -o "$work/shard_{}.csv" \
  '2>/dev/null' ::: 1 2 3
{ head -n 1 "$work/shard_1.csv"; tail -q -n +2 "$work"/shard_*.csv | sort -t, -k1,1n; } > "$work/merged.csv"

python3 - "$work/whole.csv" "$work/merged.csv" <<'PY'
import csv, sys
whole, merged = (list(csv.reader(open(p, newline=""))) for p in sys.argv[1:3])
header = whole[0]
assert merged[0] == header, f"headers differ:\n{merged[0]}\n{header}"
assert len(whole) > 100, f"the sweep has only {len(whole) - 1} rows"
assert len(merged) == len(whole), f"{len(merged) - 1} merged rows, {len(whole) - 1} unsharded"
keep = [i for i, name in enumerate(header) if name != "wall_s"]
assert len(keep) == len(header) - 1, "no wall_s column"
for a, b in zip(whole[1:], merged[1:]):
    assert [a[i] for i in keep] == [b[i] for i in keep], f"run {a[0]} differs:\n{a}\n{b}"
assert [int(r[0]) for r in merged[1:]] == list(range(len(whole) - 1)), "runs are not 0..n in order"
print(f"shard test: 3 shards through GNU parallel, merged, equal the unsharded table ({len(whole) - 1} runs, "
      f"{len(keep)} columns compared)")
PY
