#!/usr/bin/env python3
"""The fit bench of issue 54: `eulerdyn fit` against the same fit by a SciPy script, timed in the same run.

The problem: a body with principal moments (0.0412, 0.0398, 0.0071) kg*m^2 tumbling from w0 = (0.08, -0.12, 0.15)
rad/s under a known body torque (2, -1, 1.5) uN*m, read by a gyro at 100 Hz for 100 s (10^4 rows) with white noise
sigma = 2e-4 rad/s and a bias of (2, -1.5, 1) mrad/s; estimated: the three principal moments, w0 and the bias (9
parameters; the torque fixes the scale), from the CAD's (0.042, 0.040, 0.0068) and the gyro's first reading.

- eulerdyn: `eulerdyn fit DATA --scene START --estimate principal,omega0,gyro_bias --sigma-omega 2e-4 --json`, the
  whole process (reading the CSV, the fit, printing), median of 5 runs.
- SciPy: scipy.optimize.least_squares (Levenberg-Marquardt, MINPACK, its default finite-difference Jacobian) over
  scipy.integrate.solve_ivp (DOP853, rtol 1e-10, atol 1e-12, rows by t_eval) of Euler's equations in principal axes
  with the torque, the same residuals (w(t) + b - w_meas)/sigma, the same start; the fit alone, median of 3.

Usage (numpy and scipy installed, eulerdyn built with `cargo build --release`):

    python3 benches/fit_scipy.py

Prints both estimates, their difference in standard errors, and the ratio of the times.
"""

import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import least_squares

ROOT = Path(__file__).resolve().parent.parent
EULERDYN = ROOT / "target" / "release" / "eulerdyn"
SIGMA = 2e-4
TORQUE = np.array([2e-6, -1e-6, 1.5e-6])
NAMES = ["I_1", "I_2", "I_3", "omega0_x", "omega0_y", "omega0_z", "bias_x", "bias_y", "bias_z"]


def scene(moments, omega, rtol=""):
    return (
        f"[body]\nmass = 4.0\ninertia = {list(moments)}\n[initial]\nomega = {list(omega)}\n"
        f"[[effect]]\ntype = \"torque\"\nframe = \"body\"\nvalue = {TORQUE.tolist()}\n"
        f"[solver]\n{rtol}t_end = 100.0\n[output]\nevery = 0.01\n"
    )


def eulerdyn(*args):
    done = subprocess.run([str(EULERDYN), *args], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"eulerdyn {' '.join(args)} failed ({done.returncode}): {done.stderr.strip()}")
    return done.stdout


def measured(folder):
    """The gyro log (t, w_meas) of the true body, written to folder/gyro.csv."""
    truth = folder / "truth.toml"
    truth.write_text(scene([0.0412, 0.0398, 0.0071], [0.08, -0.12, 0.15], "rtol = 1e-13\natol = 1e-15\n"))
    rows = np.genfromtxt(eulerdyn("run", str(truth)).splitlines(), delimiter=",", names=True)
    rng = np.random.default_rng(54)
    t = rows["t"]
    w = np.column_stack([rows[f"omega_b_{a}"] for a in "xyz"]) + [2e-3, -1.5e-3, 1e-3]
    w += rng.normal(0.0, SIGMA, w.shape)
    np.savetxt(folder / "gyro.csv", np.column_stack([t, w]), delimiter=",", fmt="%.10g",
               header="t,omega_x,omega_y,omega_z", comments="")
    return t, w


def scipy_fit(t, w_meas, x0):
    def residuals(x):
        i, w0, b = x[0:3], x[3:6], x[6:9]

        def euler(_, w):
            return [((i[1] - i[2]) * w[1] * w[2] + TORQUE[0]) / i[0],
                    ((i[2] - i[0]) * w[2] * w[0] + TORQUE[1]) / i[1],
                    ((i[0] - i[1]) * w[0] * w[1] + TORQUE[2]) / i[2]]

        sol = solve_ivp(euler, (0.0, t[-1]), w0, method="DOP853", t_eval=t, rtol=1e-10, atol=1e-12)
        return ((sol.y.T + b - w_meas) / SIGMA).ravel()

    result = least_squares(residuals, x0, method="lm")
    return result


def main():
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        t, w = measured(folder)
        start = folder / "start.toml"
        start.write_text(scene([0.042, 0.040, 0.0068], w[0].tolist()))
        args = ["fit", str(folder / "gyro.csv"), "--scene", str(start), "--estimate", "principal,omega0,gyro_bias",
                "--sigma-omega", str(SIGMA), "--json"]
        ours, times = None, []
        for _ in range(5):
            began = time.perf_counter()
            ours = json.loads(eulerdyn(*args))
            times.append(time.perf_counter() - began)
        eulerdyn_s = statistics.median(times)
        x0 = np.concatenate([[0.042, 0.040, 0.0068], w[0], [0.0, 0.0, 0.0]])
        times = []
        for _ in range(3):
            began = time.perf_counter()
            result = scipy_fit(t, w, x0)
            times.append(time.perf_counter() - began)
        scipy_s = statistics.median(times)
    by_name = {p["name"]: p for p in ours["parameters"]}
    print(f"{len(t)} gyro rows, 9 parameters; eulerdyn converged: {ours['converged']} after {ours['iterations']} "
          f"iterations; SciPy: {result.message} ({result.nfev} residual evaluations)")
    print(f"{'parameter':<10} {'eulerdyn':>15} {'std error':>10} {'SciPy':>15} {'diff/se':>8}")
    for k, name in enumerate(NAMES):
        p = by_name[name]
        print(f"{name:<10} {p['estimate']:>15.9g} {p['std_error']:>10.3g} {result.x[k]:>15.9g} "
              f"{(p['estimate'] - result.x[k]) / p['std_error']:>8.1e}")
    print(f"time: eulerdyn {eulerdyn_s:.3f} s (whole process, median of 5), SciPy {scipy_s:.2f} s (the fit, median "
          f"of 3): SciPy / eulerdyn = {scipy_s / eulerdyn_s:.0f} x")


if __name__ == "__main__":
    main()
