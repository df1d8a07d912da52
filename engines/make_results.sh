#!/usr/bin/env bash
# Makes the committed results of the engines: the report cards at 60 Hz (results/cards_60hz.txt), each with the
# diagnosis of every scene (results/diagnoses_60hz.txt, `score --diagnose`) and the work-precision figure (results/work_precision.csv, docs/engines_work_precision.svg).
# Needs the built binary (EULERDYN_BIN, default target/release/eulerdyn) and engines/.venv (see README.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${EULERDYN_BIN:-$PWD/target/release/eulerdyn}"
py=engines/.venv/bin/python
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$bin" -q suite --out "$work/suite"
"$py" engines/mujoco/run_suite.py --suite "$work/suite" --integrator Euler --integrator RK4
"$py" engines/pybullet/run_suite.py --suite "$work/suite"
: > engines/results/cards_60hz.txt
for engine in mujoco_euler mujoco_rk4 pybullet; do
  "$bin" score --suite "$work/suite" --engine "$engine" >> engines/results/cards_60hz.txt || [ $? -eq 1 ]
  echo >> engines/results/cards_60hz.txt
done
: > engines/results/diagnoses_60hz.txt
for engine in mujoco_euler mujoco_rk4 pybullet; do
  "$bin" score --suite "$work/suite" --engine "$engine" --diagnose >> engines/results/diagnoses_60hz.txt || [ $? -eq 1 ]
  echo >> engines/results/diagnoses_60hz.txt
done
"$py" engines/work_precision.py --bin "$bin" --suite "$work/suite"
cat engines/results/cards_60hz.txt
