#!/usr/bin/env python3
"""The SciPy baseline of issue 5: the benchmark body integrated by a SciPy script, timed against eulerdyn in the
same run.

The same equations as eulerdyn's body form (Euler's equations in principal axes, I1 w1' = M1 - (I3 - I2) w2 w3 and
cyclic; q' = 1/2 q (x) (0, w)), the same initial state, end time and rows, the same tolerance sweep (rtol 1e-3 ... 1e-13,
atol = rtol x the scene's atol/rtol), integrated by scipy.integrate.solve_ivp with DOP853 (Hairer's method, the one
eulerdyn's fastest run uses) and its rows by `t_eval`. Errors: the largest |w - w_ref| over the rows, w_ref from
eulerdyn's closed form (`--method exact`) for the torque-free scene, else from eulerdyn's reference run (DOP853 at
rtol 1e-14, atol 1e-15). eulerdyn's side is `eulerdyn accuracy` on the same scene, which times the integration alone
(median of repeats), as this script times `solve_ivp` alone (median of 3).

Usage (numpy and scipy installed, eulerdyn built with `cargo build --release`):

    python3 benches/scipy_baseline.py

Prints, per scene, SciPy's sweep and the cheapest setting of each reaching a largest w error <= 1e-10, and the ratio
of their times.
"""

import csv
import io
import math
import statistics
import subprocess
import sys
import time
import tomllib
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

ROOT = Path(__file__).resolve().parent.parent
EULERDYN = ROOT / "target" / "release" / "eulerdyn"
SCENES = ["scenarios/asymmetric_free.toml", "scenarios/benchmark_sine.toml"]
TARGET = 1e-10
RTOLS = [10.0 ** -k for k in range(3, 14)]
REPEATS = 3


def eulerdyn(*args):
    """stdout of an eulerdyn command; exits with its stderr if it fails."""
    done = subprocess.run([str(EULERDYN), *args], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"eulerdyn {' '.join(args)} failed ({done.returncode}): {done.stderr.strip()}")
    return done.stdout


def omega_rows(csv_text):
    """(t, w_b) of every row of an eulerdyn CSV."""
    rows = list(csv.DictReader(io.StringIO(csv_text)))
    t = np.array([float(r["t"]) for r in rows])
    w = np.array([[float(r[f"omega_b_{a}"]) for a in "xyz"] for r in rows])
    return t, w


def body_form(scene):
    """f(t, y) of the body form, y = (w_b, q_w, q_x, q_y, q_z), for a scene with principal inertia given as three
    moments and body-axis torques of constant or sine profile (what the two benchmark scenes use)."""
    i1, i2, i3 = scene["body"]["inertia"]
    torques = []
    for effect in scene.get("effect", []):
        if effect["type"] != "torque" or effect.get("frame", "body") != "body":
            sys.exit(f"scipy_baseline: effect {effect} is not modelled here")
        profile = effect.get("profile", "constant")
        if profile not in ("constant", "sine"):
            sys.exit(f"scipy_baseline: torque profile {profile} is not modelled here")
        omega = 2.0 * math.pi * effect.get("freq_hz", 0.0)
        phase = math.radians(effect.get("phase_deg", 0.0))
        torques.append((np.array(effect["value"], dtype=float), profile, omega, phase))

    def rhs(t, y):
        m = np.zeros(3)
        for value, profile, omega, phase in torques:
            m += value if profile == "constant" else value * math.sin(omega * t + phase)
        w1, w2, w3, qw, qx, qy, qz = y
        return np.array(
            [
                (m[0] - (i3 - i2) * w2 * w3) / i1,
                (m[1] - (i1 - i3) * w3 * w1) / i2,
                (m[2] - (i2 - i1) * w1 * w2) / i3,
                -0.5 * (qx * w1 + qy * w2 + qz * w3),
                0.5 * (qw * w1 + qy * w3 - qz * w2),
                0.5 * (qw * w2 + qz * w1 - qx * w3),
                0.5 * (qw * w3 + qx * w2 - qy * w1),
            ]
        )

    return rhs


def scipy_sweep(scene, t_rows, w_ref):
    rhs = body_form(scene)
    y0 = np.array([*scene["initial"]["omega"], 1.0, 0.0, 0.0, 0.0])
    t_end = t_rows[-1]
    atol_ratio = scene["solver"]["atol"] / scene["solver"]["rtol"]
    results = []
    for rtol in RTOLS:
        atol = rtol * atol_ratio
        times = []
        for _ in range(REPEATS):
            start = time.perf_counter()
            sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", t_eval=t_rows, rtol=rtol, atol=atol)
            times.append(time.perf_counter() - start)
        if not sol.success:
            print(f"    rtol {rtol:.0e}: solve_ivp failed: {sol.message}")
            continue
        err = float(np.max(np.linalg.norm(sol.y[:3].T - w_ref, axis=1)))
        results.append((rtol, err, statistics.median(times), sol.nfev))
    return results


def eulerdyn_fastest(scene_file):
    """The fastest integrating run of `eulerdyn accuracy` reaching the target: (label, err, wall_s, evals)."""
    table = list(csv.DictReader(io.StringIO(eulerdyn("accuracy", "-q", scene_file))))
    reaching = [
        r
        for r in table
        if r["status"] == "ok" and r["method"] != "exact" and float(r["err_omega"]) <= TARGET
    ]
    best = min(reaching, key=lambda r: float(r["wall_s"]))
    setting = f"rtol {best['rtol']}" if best["rtol"] else f"dt {best['dt']}"
    label = f"{best['method']} {best['frame']} form, {setting}"
    return label, float(best["err_omega"]), float(best["wall_s"]), int(best["evals"])


def main():
    if not EULERDYN.exists():
        sys.exit(f"{EULERDYN} not found: run `cargo build --release` first")
    for scene_file in SCENES:
        scene = tomllib.loads((ROOT / scene_file).read_text())
        path = str(ROOT / scene_file)
        if scene.get("effect"):
            reference = ["--method", "dop853", "--frame", "body", "--rtol", "1e-14", "--atol", "1e-15"]
            reference_name = "eulerdyn dop853 at rtol 1e-14, atol 1e-15"
        else:
            reference = ["--method", "exact"]
            reference_name = "eulerdyn's closed form"
        t_rows, w_ref = omega_rows(eulerdyn("run", "-q", path, *reference))
        print(f"{scene_file} (reference: {reference_name}; {len(t_rows)} rows)")
        print(f"    {'rtol':>7} {'err_omega':>10} {'time':>10} {'nfev':>7}  (scipy {__import__('scipy').__version__}"
              f" solve_ivp DOP853, median of {REPEATS})")
        results = scipy_sweep(scene, t_rows, w_ref)
        for rtol, err, wall, nfev in results:
            print(f"    {rtol:7.0e} {err:10.2e} {wall * 1e3:8.1f} ms {nfev:7d}")
        label, e_err, e_wall, e_evals = eulerdyn_fastest(path)
        print(f"    eulerdyn fastest to err_omega <= {TARGET:.0e}: {label}: {e_wall * 1e3:.3f} ms "
              f"({e_evals} evaluations, err {e_err:.2e})")
        reaching = [r for r in results if r[1] <= TARGET]
        if not reaching:
            print(f"    SciPy: no setting of the sweep reached {TARGET:.0e}")
            continue
        rtol, err, wall, nfev = min(reaching, key=lambda r: r[2])
        print(f"    SciPy fastest to err_omega <= {TARGET:.0e}: rtol {rtol:.0e}: {wall * 1e3:.1f} ms "
              f"({nfev} evaluations, err {err:.2e})")
        print(f"    SciPy / eulerdyn: {wall / e_wall:.0f} x the time; per evaluation "
              f"{wall / nfev * 1e9:.0f} ns vs {e_wall / e_evals * 1e9:.1f} ns")
        print()


if __name__ == "__main__":
    main()
