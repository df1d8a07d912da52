"""`eulerdyn.run`: the command line's CSV, bit for bit, from a scene file or a dict, with each of its flags."""

import math
import warnings

import numpy as np
import pandas as pd
import pytest

import eulerdyn
from conftest import cli_csv, disk_dict


def assert_same_as_cli(df: pd.DataFrame, header, rows):
    """The DataFrame has the CSV's columns in its order, and every value is the CSV's float, bit for bit."""
    assert list(df.columns) == header
    assert len(df) == len(rows)
    assert all(df.dtypes == np.float64)
    csv_values = np.array(rows, dtype=np.float64)
    # Equality of the bits: the same float, including the sign of zero.
    assert np.array_equal(df.to_numpy().view(np.uint64), csv_values.view(np.uint64))


@pytest.mark.parametrize(
    "name",
    [
        "tilted_disk.toml",  # fixed axis: theta, H_s integrated, support columns
        "asymmetric_free.toml",  # free, dop853 at rtol 1e-12
        "rotor_bearings.toml",  # bearing reactions
        "heavy_top.toml",  # gravity: potential columns
        "rod_pendulum.toml",  # a hinge
        "damped_spin.toml",  # effects
    ],
)
def test_run_matches_the_cli_csv_bit_for_bit(scenario, name):
    path = scenario(name)
    header, rows = cli_csv(str(path))
    df = eulerdyn.run(path)
    assert_same_as_cli(df, header, rows)
    assert df.attrs["report"]["rows"] == len(rows)
    # A str path is the same scene.
    assert df.equals(eulerdyn.run(str(path)))


@pytest.mark.parametrize(
    "kwargs, flags",
    [
        ({"method": "rk4"}, ["--method", "rk4"]),
        ({"method": "split4", "dt": 0.01}, ["--method", "split4", "--dt", "0.01"]),
        ({"frame": "space"}, ["--frame", "space"]),
        ({"backend": "ode_solvers"}, ["--backend", "ode_solvers"]),
        ({"rtol": 1e-6}, ["--rtol", "1e-6"]),
        ({"rtol": 1e-6, "atol": 1e-3}, ["--rtol", "1e-6", "--atol", "1e-3"]),
        ({"method": "rk4", "dt": 0.05}, ["--method", "rk4", "--dt", "0.05"]),
        ({"t_end": 3.25}, ["--t-end", "3.25"]),
        ({"every": 0.3}, ["--every", "0.3"]),
        ({"method": "exact", "frame": "space", "every": 2.0}, ["--method", "exact", "--frame", "space", "--every", "2"]),
    ],
)
def test_each_override_is_the_cli_flag(scenario, kwargs, flags):
    path = scenario("asymmetric_free.toml")
    header, rows = cli_csv(str(path), *flags)
    df = eulerdyn.run(path, **kwargs)
    assert_same_as_cli(df, header, rows)
    # The override changed the run: it differs from the scene's own settings.
    plain = eulerdyn.run(path)
    assert not (df.shape == plain.shape and np.array_equal(df.to_numpy(), plain.to_numpy()))


def test_the_notes_disk_from_a_dict(tmp_path):
    """Professor Ali Meghdari's lecture notes *Rigid Body Dynamics*, the thin disk on a tilted axis (Theorem 25,
    eqs. 8.9 and 8.10): H is constant in body axes and turns in space; the moment that turns it has the magnitude
    |M| = ¼ m R² ω² sin θ cos θ = 1.9485571585… N·m, along −x₁ in body axes."""
    m, r, omega, theta = 2.0, 0.3, 10.0, math.radians(30.0)
    df = eulerdyn.run(disk_dict())
    moment = 0.25 * m * r * r * omega * omega * math.sin(theta) * math.cos(theta)
    assert f"{moment:.10f}".startswith("1.9485571585")
    assert np.allclose(df["M_b_x"].abs(), moment, rtol=1e-13, atol=0.0)
    assert (df["M_b_x"] < 0).all()
    assert np.allclose(df[["M_b_y", "M_b_z"]], 0.0, atol=1e-13)
    # H_s along the spin axis stays ¼ m R² ω (1 + cos²θ); H_b is constant.
    assert np.allclose(df["H_s_z"], 0.25 * m * r * r * omega * (1 + math.cos(theta) ** 2), rtol=1e-13)
    assert np.allclose(df["H_b_y"], df["H_b_y"].iloc[0], rtol=1e-13)
    assert len(df) == 101


def test_a_dict_is_the_same_scene_as_its_file(scenario):
    df = eulerdyn.run(disk_dict())
    header, rows = cli_csv(str(scenario("tilted_disk.toml")))
    assert_same_as_cli(df, header, rows)


def test_dict_values_may_be_ints_tuples_and_numpy():
    scene = disk_dict()
    scene["body"]["mass"] = 2  # an int, as `mass = 2` in a file
    scene["motion"]["tilt_deg"] = np.float64(30.0)
    scene["motion"]["rate"] = np.int64(10)
    scene["initial"]["attitude"] = np.array(scene["initial"]["attitude"])
    scene["output"] = {"every": 0.01}
    df = eulerdyn.run(scene)
    assert df.equals(eulerdyn.run(disk_dict()))


def test_dict_with_a_list_of_effects_runs():
    scene = {
        "body": {"mass": 1.0, "inertia": [1.0, 2.0, 3.0]},
        "initial": {"omega": [0.0, 0.0, 2.0]},
        "effect": [{"type": "damping", "c": 0.1}],
        "solver": {"t_end": 2.0},
        "output": {"every": 1.0},
    }
    df = eulerdyn.run(scene)
    # Linear damping M = -c ω about a principal axis: ω_z = 2 exp(-c t / I_z).
    assert df["omega_b_z"].iloc[-1] == pytest.approx(2.0 * math.exp(-0.1 * 2.0 / 3.0), rel=1e-9)


def test_the_frame_is_a_free_choice_for_the_values():
    body = eulerdyn.run(disk_dict(), frame="body")
    space = eulerdyn.run(disk_dict(), frame="space")
    assert np.allclose(body["M_s_x"], space["M_s_x"], atol=1e-12)


def test_a_coarse_fixed_step_and_a_drifting_energy_are_user_warnings(scenario):
    # The heavy top (150 rad/s) with rk4 and dt = 0.05 s, capped at the rows' 0.01 s: 1.5 rad per step, and T + V,
    # which a top on a fixed pivot conserves, drifts by about 8 % (the command line prints the same warnings).
    with pytest.warns(UserWarning) as record:
        eulerdyn.run(scenario("heavy_top.toml"), method="rk4", dt=0.05)
    texts = [str(w.message) for w in record]
    assert any("turns the body by 1.5 rad" in t for t in texts), texts
    assert any("the energy T + V, which this scene conserves, drifted by" in t for t in texts), texts
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        eulerdyn.run(scenario("heavy_top.toml"))


def test_a_unit_slip_is_a_user_warning_and_a_real_skew_is_not():
    # tilt_deg = 0.5236 is 30 degrees written in radians: warned of, as the command line's `run` does on stderr.
    with pytest.warns(UserWarning, match=r"motion.tilt_deg = 0.5236 is 0.5236 degrees; if radians were meant, that is 30.0 degrees"):
        eulerdyn.run(disk_dict(tilt_deg=0.5236))
    # A rotor's real skew of 1 degree: no warning.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        eulerdyn.run(disk_dict(tilt_deg=1.0))
