"""A body that changes shape from Python: `[[body.moving_mass]]` and `inertia_table`, their columns and errors, as
the command line gives them (the closed forms themselves are tested in tests/it/shape_change.rs)."""

import numpy as np
import pytest

import eulerdyn
from conftest import cli_csv


def skater(profile="smooth"):
    """An axisymmetric body spinning at 4 rad/s about z pulls a pair of 0.5 kg masses out from 0.2 to 1.2 m."""
    arm = lambda sign, name: {
        "name": name, "mass": 0.5, "from": [0.2 * sign, 0.0, 0.0], "to": [1.2 * sign, 0.0, 0.0],
        "start": 1.0, "duration": 4.0, "profile": profile,
    }
    return {
        "body": {"mass": 10.0, "inertia": [2.0, 2.0, 3.0], "moving_mass": [arm(1, "left"), arm(-1, "right")]},
        "initial": {"omega": [0.0, 0.0, 4.0]},
        "solver": {"rtol": 1e-12, "atol": 1e-12, "t_end": 7.0},
        "output": {"every": 0.1},
    }


def test_the_bundled_booms_are_the_command_line_s_run_bit_for_bit(scenario):
    path = scenario("deploying_booms.toml")
    header, rows = cli_csv(str(path))
    df = eulerdyn.run(path)
    assert list(df.columns) == header
    assert "I_b_zz" in header and "P_internal" in header and header[-3:] == ["tip_b_x", "tip_b_y", "tip_b_z"]
    assert np.array_equal(df.to_numpy().view(np.uint64), np.array(rows).view(np.uint64))


@pytest.mark.parametrize("profile", ["smooth", "linear"])
def test_a_dict_skater_turns_at_h_over_i_zz(profile):
    df = eulerdyn.run(skater(profile))
    h = 3.0 * 4.0 + 2 * 0.5 * 0.2**2 * 4.0
    # H about C is constant (no moment): omega_z = H / I_zz(t), I_zz = 3 + 2 m r(t)^2 (the columns give it).
    assert np.allclose(df["omega_b_z"], h / df["I_b_zz"], rtol=1e-9, atol=0)
    assert np.allclose(df["I_b_zz"], 3.0 + 2 * 0.5 * df["left_x"] ** 2, rtol=1e-14, atol=0)
    assert df["H_s_z"].max() - df["H_s_z"].min() <= 1e-9 * h
    # The drives pull the masses out against the spin: the energy falls, P_internal < 0 while they move.
    assert df["energy"].iloc[-1] < df["energy"].iloc[0]
    moving = df[(df["t"] > 1.05) & (df["t"] < 4.95)]
    assert (moving["P_internal"] < 0).all()


def test_bad_shape_change_input_is_a_scene_error_naming_the_key():
    scene = skater()
    scene["body"]["moving_mass"][0]["duration"] = -1.0
    with pytest.raises(eulerdyn.SceneError, match=r"body\.moving_mass\[0\]\.duration"):
        eulerdyn.run(scene)
    scene = skater()
    scene["solver"]["method"] = "exact"
    with pytest.raises(eulerdyn.SceneError, match="changes shape"):
        eulerdyn.run(scene)
