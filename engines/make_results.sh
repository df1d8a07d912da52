#!/usr/bin/env bash
# Makes the committed results of the engines: the report cards at 60 Hz (results/cards_60hz.txt), each with the
# diagnosis of every scene (results/diagnoses_60hz.txt, `score --diagnose`), the engines' versions
# (results/versions.txt) and the work-precision figure with measured cost (results/work_precision.csv,
# docs/engines_work_precision.svg). Needs the built binary (EULERDYN_BIN, default target/release/eulerdyn) and
# engines/.venv (see README.md); run it on a quiet machine, since the figure's cost axis is measured.
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${EULERDYN_BIN:-$PWD/target/release/eulerdyn}"
py=engines/.venv/bin/python
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
packages="$("$py" engines/adapters.py packages)"
mapfile -t engines < <("$py" engines/adapters.py engines)
"$bin" -q suite --out "$work/suite"
for name in $("$py" engines/adapters.py adapters); do
  "$py" "engines/$name/run_suite.py" --suite "$work/suite" 2> "$work/$name.log" || { tail "$work/$name.log"; exit 1; }
done
"$py" -m pip list 2>/dev/null | grep -E "^(${packages// /|}) " > engines/results/versions.txt
: > engines/results/cards_60hz.txt
: > engines/results/diagnoses_60hz.txt
for engine in "${engines[@]}"; do
  "$bin" score --suite "$work/suite" --engine "$engine" >> engines/results/cards_60hz.txt || [ $? -eq 1 ]
  echo >> engines/results/cards_60hz.txt
  "$bin" score --suite "$work/suite" --engine "$engine" --diagnose >> engines/results/diagnoses_60hz.txt || [ $? -eq 1 ]
  echo >> engines/results/diagnoses_60hz.txt
done
"$py" engines/work_precision.py --bin "$bin" --suite "$work/suite" 2> "$work/work_precision.log" \
  || { tail "$work/work_precision.log"; exit 1; }
cat engines/results/cards_60hz.txt
