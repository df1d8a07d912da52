#!/usr/bin/env python3
"""How the fit guide's two measured logs were made (`python3 scenarios/fit_data.py`, after `cargo build --release`):
each is an eulerdyn run of a "true" body, read at a sensor's rate, with a MEMS gyro's noise and bias added (Python's
own random numbers, seeded, so that the files are made again byte for byte).

- cubesat_gyro.csv: a 3U CubeSat tumbling after deployment, torque-free, its true inertia a little off the CAD's
  (products of inertia of a few 1e-4 kg*m^2, the z moment 4 % higher); a gyro at 10 Hz for 600 s, white noise
  sigma = 2e-4 rad/s per axis and a turn-on bias of (2, -1.5, 1) mrad/s.
- payload_gyro.csv: a 12 kg payload on an air bearing excited by a known body torque (0.05 N*m about x for 2 s,
  then about z), a gyro at 50 Hz for 40 s with sigma = 5e-4 rad/s and no bias.
"""

import csv
import io
import random
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
EULERDYN = ROOT / "target" / "release" / "eulerdyn"

CUBESAT_TRUTH = """
[body]
mass = 4.0
inertia = [[0.0412, 0.0003, -0.0002], [0.0003, 0.0398, 0.0004], [-0.0002, 0.0004, 0.0071]]
[initial]
omega = [0.08, -0.12, 0.15]
[solver]
rtol = 1e-13
atol = 1e-15
t_end = 600.0
[output]
every = 0.1
"""

PAYLOAD_TRUTH = """
[body]
mass = 12.0
inertia = [[0.52, -0.03, 0.01], [-0.03, 0.61, 0.02], [0.01, 0.02, 0.33]]
[initial]
omega = [0.02, 0.01, -0.03]
[[effect]]
type = "torque"
frame = "body"
value = [0.05, 0.0, 0.0]
profile = "step"
t_on = 5.0
t_off = 7.0
[[effect]]
type = "torque"
frame = "body"
value = [0.0, 0.0, 0.05]
profile = "step"
t_on = 15.0
t_off = 17.0
[solver]
rtol = 1e-13
atol = 1e-15
t_end = 40.0
[output]
every = 0.02
"""


def measured(truth, seed, sigma, bias, out):
    """Runs `truth`, adds N(0, sigma) and `bias` to omega_b, writes t,omega_x,omega_y,omega_z to `out`."""
    with tempfile.TemporaryDirectory() as folder:
        scene = Path(folder) / "truth.toml"
        scene.write_text(truth)
        done = subprocess.run([str(EULERDYN), "run", str(scene)], capture_output=True, text=True, check=False)
    if done.returncode != 0:
        sys.exit(done.stderr)
    rng = random.Random(seed)
    rows = csv.DictReader(io.StringIO(done.stdout))
    with open(out, "w", newline="") as f:
        f.write("t,omega_x,omega_y,omega_z\n")
        for row in rows:
            w = [float(row[f"omega_b_{a}"]) + b + rng.gauss(0.0, sigma) for a, b in zip("xyz", bias)]
            f.write(f"{float(row['t']):.10g},{w[0]:.7e},{w[1]:.7e},{w[2]:.7e}\n")


if __name__ == "__main__":
    measured(CUBESAT_TRUTH, 2026, 2e-4, (2e-3, -1.5e-3, 1e-3), ROOT / "scenarios" / "cubesat_gyro.csv")
    measured(PAYLOAD_TRUTH, 1129, 5e-4, (0.0, 0.0, 0.0), ROOT / "scenarios" / "payload_gyro.csv")
