#!/bin/sh
# Makes the gallery of the README (docs/*.svg) with eulerdyn itself. Run from the repository root:
#   sh docs/make_gallery.sh
# The CSV files go to a temporary directory; only the figures are kept. tests/gallery.rs runs this script with
# EULERDYN (the binary), GALLERY_DIR (where the figures go) and GALLERY_FIGURES_ONLY=1 (no timed study) set, and
# checks that it remakes the committed figures byte for byte.
set -eu
eulerdyn=${EULERDYN:-"cargo run --quiet --release --"}
out=${GALLERY_DIR:-docs}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The tilted disk: H constant in body axes, turning about the spin axis in space axes.
$eulerdyn run scenarios/tilted_disk.toml -o "$work/tilted_disk.csv"
$eulerdyn plot "$work/tilted_disk.csv" -o "$out/tilted_disk_h.svg" --panels h_body,h_space

# The tennis-racket flip: omega in body and space axes, and the drift of |H| and energy.
$eulerdyn run scenarios/tennis_racket.toml -o "$work/tennis_racket.csv"
$eulerdyn plot "$work/tennis_racket.csv" -o "$out/tennis_racket.svg" --panels omega,drift

# The heavy top: H about the pivot precessing (with nutation) in space; kinetic energy traded with potential, T + V
# conserved (its drift, the scene's one invariant among |H|, T and T + V).
$eulerdyn run scenarios/heavy_top.toml -o "$work/heavy_top.csv"
$eulerdyn plot "$work/heavy_top.csv" -o "$out/heavy_top.svg" --panels h_space,energy,drift

# A motor runs the skewed disk up on its hinge: the rate rises to 10 rad/s, the bearings' couple with its square.
$eulerdyn run scenarios/motor_runup.toml -o "$work/motor_runup.csv"
$eulerdyn plot "$work/motor_runup.csv" -o "$out/motor_runup_bearings.svg" --panels omega,theta,moment,bearings

# A turbine rotor at 10 000 rpm in a yawing aircraft: the gyroscopic couple, carried by the bearings as vertical
# forces that reverse with the yaw (space axes: in body axes they turn with the rotor).
$eulerdyn run scenarios/turbine_yawing_aircraft.toml -o "$work/turbine.csv"
$eulerdyn plot "$work/turbine.csv" -o "$out/turbine_bearings.svg" --panels omega,bearings_space

# The same rotor in a coordinated 3 g turn about a centre 694 m away: the bearings carry m (a − g), 3 g along the
# apparent vertical, and the gyroscopic couple as vertical forces ±C ω Ω/(b − a); in space axes the horizontal part
# turns with the heading.
$eulerdyn run scenarios/turbine_turn_3g.toml -o "$work/turbine_turn.csv"
$eulerdyn plot "$work/turbine_turn.csv" -o "$out/turbine_turn_bearings.svg" --panels omega,bearings_space

# Explorer 1's lesson: a minor-axis spin with a nutation damper (a free wheel under viscous friction) ends about the
# major axis — omega turning from z to x, the energy falling to |H|²/(2 I_max) while |H| stays, the damper's spin.
$eulerdyn run scenarios/explorer1.toml -o "$work/explorer1.csv"
$eulerdyn plot "$work/explorer1.csv" -o "$out/explorer1.svg" --panels omega,energy,wheel_spin

# A boom held by the gravity gradient on a 500 km orbit: roll, pitch and yaw from the LVLH frame librating about
# nadir, and the gradient's moment that drives them.
$eulerdyn run scenarios/gravity_gradient_boom.toml -o "$work/gravity_gradient_boom.csv"
$eulerdyn plot "$work/gravity_gradient_boom.csv" -o "$out/gravity_gradient_boom.svg" --panels lvlh,moment

$eulerdyn run scenarios/cubesat_b_dot.toml -o "$work/cubesat_b_dot.csv"
$eulerdyn plot "$work/cubesat_b_dot.csv" -o "$out/cubesat_b_dot.svg" --panels omega,energy,field,dipole

# A slew through three wheels that saturate at 0.05 N·m (examples/wheel_slew.rs, a PD law): the body's rate, the
# wheels' speeds and their commanded and applied torques. SLEW_CSV: a run of it made already (the gallery test's).
slew_csv=${SLEW_CSV:-"$work/slew.csv"}
[ -n "${SLEW_CSV:-}" ] || cargo run --quiet --release --example wheel_slew -- "$slew_csv" > /dev/null
$eulerdyn plot "$slew_csv" -o "$out/slew_wheels.svg" --panels omega,wheel_spin,wheel_torque

# What accuracy costs: the work-precision study of the benchmark body (about 10 s; its times differ run to run).
[ -n "${GALLERY_FIGURES_ONLY:-}" ] && exit 0
$eulerdyn accuracy scenarios/asymmetric_free.toml -o docs/work_precision.csv --plot docs/work_precision.svg
