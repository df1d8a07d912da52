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
engines=(mujoco_euler mujoco_implicitfast mujoco_rk4 pybullet drake dart rapier rapier_default rapier_nogyro)
"$bin" -q suite --out "$work/suite"
"$py" engines/mujoco/run_suite.py --suite "$work/suite" --integrator Euler --integrator implicitfast --integrator RK4
"$py" engines/pybullet/run_suite.py --suite "$work/suite"
"$py" engines/drake/run_suite.py --suite "$work/suite" 2> "$work/drake.log" || { cat "$work/drake.log"; exit 1; }
"$py" engines/dart/run_suite.py --suite "$work/suite" 2> "$work/dart.log" || { tail "$work/dart.log"; exit 1; }
"$py" engines/rapier/run_suite.py --suite "$work/suite"
"$py" -m pip list 2>/dev/null | grep -E '^(mujoco|pybullet|drake|dartpy|rapier3d) ' > engines/results/versions.txt
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
