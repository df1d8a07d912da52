#!/usr/bin/env python3
"""A general multibody engine on the benchmark body: MuJoCo against eulerdyn, in the same run.

The benchmark body of issue 5 (I = diag(1, 2, 3) kg m^2 about C, omega0 = (0.3, 0, 2) rad/s in body axes,
torque-free, t_end = 100 s, rows every 0.5 s) as one body on a free joint, gravity off, stepped by MuJoCo's
integrators (semi-implicit Euler, implicitfast, RK4) at fixed time steps. MuJoCo's free-joint angular velocity
(qvel[3:6]) is in the body's local frame, so it compares directly with eulerdyn's omega_b. Errors: the largest
|omega_b - omega_ref| over the rows, omega_ref from eulerdyn's closed form (`--method exact`); energy drift: the
largest |E - E0|/E0. MuJoCo is timed stepping in C (`mj_step` with `nstep`), median of 3; eulerdyn's side is
`eulerdyn accuracy` on the same scene (integration alone, median of repeats): for each MuJoCo run, the cheapest
eulerdyn run at least as accurate.

Usage (pip install mujoco numpy; eulerdyn built with `cargo build --release`):

    python3 benches/mujoco_baseline.py
"""

import csv
import io
import statistics
import subprocess
import sys
import time
from pathlib import Path

import mujoco
import numpy as np

ROOT = Path(__file__).resolve().parent.parent
EULERDYN = ROOT / "target" / "release" / "eulerdyn"
SCENE = ROOT / "scenarios" / "asymmetric_free.toml"
INERTIA = np.array([1.0, 2.0, 3.0])
OMEGA0 = np.array([0.3, 0.0, 2.0])
EVERY = 0.5
ROWS = 201
INTEGRATORS = ["Euler", "implicitfast", "RK4"]
STEPS = [1e-2, 1e-3, 1e-4]
REPEATS = 3

MODEL = """
<mujoco>
  <option gravity="0 0 0" timestep="{dt}" integrator="{integrator}"/>
  <worldbody>
    <body name="body">
      <freejoint/>
      <inertial pos="0 0 0" mass="1" diaginertia="1 2 3"/>
    </body>
  </worldbody>
</mujoco>
"""


def eulerdyn(*args):
    """stdout of an eulerdyn command; exits with its stderr if it fails."""
    done = subprocess.run([str(EULERDYN), *args], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"eulerdyn {' '.join(args)} failed ({done.returncode}): {done.stderr.strip()}")
    return done.stdout


def mujoco_run(integrator, dt):
    """omega_b at every row and the median wall time of the stepping."""
    model = mujoco.MjModel.from_xml_string(MODEL.format(dt=dt, integrator=integrator))
    per_row = round(EVERY / dt)
    if abs(per_row * dt - EVERY) > 1e-12:
        sys.exit(f"dt {dt} does not divide the row interval {EVERY}")
    times = []
    for _ in range(REPEATS):
        data = mujoco.MjData(model)
        data.qvel[3:6] = OMEGA0
        rows = [data.qvel[3:6].copy()]
        wall = 0.0
        for _ in range(ROWS - 1):
            start = time.perf_counter()
            mujoco.mj_step(model, data, nstep=per_row)
            wall += time.perf_counter() - start
            rows.append(data.qvel[3:6].copy())
        times.append(wall)
    return np.array(rows), statistics.median(times), per_row * (ROWS - 1)


def main():
    if not EULERDYN.exists():
        sys.exit(f"{EULERDYN} not found: run `cargo build --release` first")
    reference = list(csv.DictReader(io.StringIO(eulerdyn("run", "-q", str(SCENE), "--method", "exact"))))
    omega_ref = np.array([[float(r[f"omega_b_{a}"]) for a in "xyz"] for r in reference])
    if len(omega_ref) != ROWS:
        sys.exit(f"expected {ROWS} rows from {SCENE}, got {len(omega_ref)}")
    energy0 = 0.5 * INERTIA @ OMEGA0**2
    table = list(csv.DictReader(io.StringIO(eulerdyn("accuracy", "-q", str(SCENE)))))
    integrating = [r for r in table if r["status"] == "ok" and r["method"] != "exact"]

    print(f"MuJoCo {mujoco.__version__} against eulerdyn: {SCENE.relative_to(ROOT)}, {ROWS} rows, "
          f"reference: eulerdyn's closed form")
    print(f"  {'MuJoCo':<13} {'dt (s)':>7} {'steps':>8} {'err_omega':>10} {'energy drift':>12} {'time':>10}   "
          f"cheapest eulerdyn run at least as accurate")
    for integrator in INTEGRATORS:
        for dt in STEPS:
            omega, wall, steps = mujoco_run(integrator, dt)
            err = float(np.max(np.linalg.norm(omega - omega_ref, axis=1)))
            energy = 0.5 * (omega**2) @ INERTIA
            drift = float(np.max(np.abs(energy - energy0)) / energy0)
            better = [r for r in integrating if float(r["err_omega"]) <= err]
            if better:
                best = min(better, key=lambda r: float(r["wall_s"]))
                setting = f"rtol {best['rtol']}" if best["rtol"] else f"dt {best['dt']}"
                ours = (f"{best['method']} {best['frame']} {setting}: err {float(best['err_omega']):.1e} in "
                        f"{float(best['wall_s']) * 1e3:.3f} ms ({wall / float(best['wall_s']):.0f} x faster)")
            else:
                ours = "none in the sweep"
            print(f"  {integrator:<13} {dt:7.0e} {steps:8d} {err:10.2e} {drift:12.2e} {wall * 1e3:7.1f} ms   {ours}")


if __name__ == "__main__":
    main()
