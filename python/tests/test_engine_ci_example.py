"""An engine's own test, as its developers would write it with `eulerdyn.score` (the scoring guide includes this
file): the engine here is a few lines of NumPy taking MuJoCo's and DART's step — semi-implicit Euler with the
gyroscopic term explicit, the attitude turned by the exponential map — at 480 Hz on the suite's tennis racket,
with rows at 60 Hz."""

import numpy as np
import pandas as pd
import pytest

import eulerdyn
from conftest import run_cli


def quat_mul(a, b):
    """The Hamilton product of quaternions (w, x, y, z)."""
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return np.array([aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw])


def my_engine(inertia, omega0, t_end, rate, out_rate=60):
    """The engine under test: ω ← ω + h I⁻¹(−ω × Iω), then q ← q ⊗ exp(h ω / 2), rows at `out_rate`."""
    inertia = np.diag(inertia)
    q, omega, h = np.array([1.0, 0.0, 0.0, 0.0]), np.array(omega0, dtype=float), 1.0 / rate
    rows = []
    for k in range(int(round(t_end * out_rate)) + 1):
        rows.append([k / out_rate, *q, *omega])
        for _ in range(rate // out_rate):
            omega = omega + h * np.linalg.solve(inertia, -np.cross(omega, inertia @ omega))
            angle = np.linalg.norm(omega) * h
            q = quat_mul(q, np.array([np.cos(angle / 2), *(np.sin(angle / 2) * omega / np.linalg.norm(omega))]))
    return pd.DataFrame(rows, columns=["t", "q_w", "q_x", "q_y", "q_z", "omega_x", "omega_y", "omega_z"])


@pytest.fixture(scope="module")
def racket(tmp_path_factory):
    folder = tmp_path_factory.mktemp("suite")
    run_cli("suite", "--out", str(folder))
    return folder / "tennis_racket.toml"


def test_our_step_is_the_step_we_meant_and_flips_on_time(racket):
    trajectory = my_engine([1.0, 2.0, 3.0], [0.05, 2.0, 0.05], t_end=12.0, rate=480)
    card = eulerdyn.score(trajectory, racket, diagnose=True)
    # The diagnosis names our step: 8 substeps of 1/480 s a row, to round-off.
    closest = card["diagnosis"]["closest"]
    assert card["diagnosis"]["verdict"] == "match", card["diagnosis"]
    assert (closest["method"], closest["gyroscopic"], closest["substeps"]) == ("semi_implicit_euler", "full", 8)
    # At 480 Hz the flip comes within one frame at 60 Hz; the attitude is not yet within 1e-2 rad.
    metrics = {m["key"]: m for m in card["metrics"]}
    assert metrics["event:flip"]["passes"], metrics["event:flip"]
    assert not metrics["attitude"]["passes"]
