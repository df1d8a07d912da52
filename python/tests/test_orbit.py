"""A body in orbit from Python: `[orbit]`, the LVLH columns and the environment's effects, as the command line
gives them (the closed forms themselves are tested in tests/it/orbit.rs)."""

import math

import numpy as np

import eulerdyn
from conftest import cli_csv


def boom_dict(effects):
    """A body on a 500 km polar orbit, released 5 deg from LVLH in pitch while turning with the frame."""
    return {
        "body": {"mass": 20.0, "inertia": [9.0, 10.0, 1.5]},
        "orbit": {"altitude_km": 500.0, "inclination_deg": 90.0},
        "initial": {"attitude_lvlh_deg": [0.0, 5.0, 0.0], "omega_lvlh": [0.0, 0.0, 0.0]},
        "effect": effects,
        "solver": {"rtol": 1e-12, "atol": 1e-14, "t_end": 6000.0},
        "output": {"every": 20.0},
    }


def test_the_bundled_boom_is_the_command_line_s_run_bit_for_bit(scenario):
    path = scenario("gravity_gradient_boom.toml")
    header, rows = cli_csv(str(path))
    df = eulerdyn.run(path)
    assert list(df.columns) == header
    assert header[-3:] == ["roll_lvlh", "pitch_lvlh", "yaw_lvlh"]
    assert np.array_equal(df.to_numpy().view(np.uint64), np.array(rows).view(np.uint64))


def test_a_dict_in_orbit_librates_in_pitch_at_the_closed_form_s_rate():
    df = eulerdyn.run(boom_dict([{"type": "gravity_gradient"}]))
    # Pure pitch: roll and yaw stay at round-off; the pitch swings within its 5 deg (the pendulum's energy bound).
    assert df["roll_lvlh"].abs().max() < 1e-9 and df["yaw_lvlh"].abs().max() < 1e-9
    assert df["pitch_lvlh"].abs().max() <= math.radians(5.0) * (1 + 1e-9)
    # Half a libration period later the pitch has turned to the other side: omega_p = n sqrt(3 (Ix - Iz)/Iy) = 1.5 n.
    n = math.sqrt(3.986004418e14 / (6378.137e3 + 500e3) ** 3)
    half = math.pi / (1.5 * n)
    near = df.iloc[(df["t"] - half).abs().argmin()]
    assert near["pitch_lvlh"] < -math.radians(4.9)


def test_the_magnetic_effect_writes_the_field_in_body_axes():
    df = eulerdyn.run(boom_dict([{"type": "magnetic", "dipole": [0.0, 0.0, 0.05]}]))
    field = df[["B_b_x", "B_b_y", "B_b_z"]].to_numpy()
    strength = np.linalg.norm(field, axis=1)
    # A centred dipole: between B0 (R/r)^3 on the equator and twice that over the poles.
    scale = 3.12e-5 * (6378.137e3 / (6378.137e3 + 500e3)) ** 3
    assert strength.min() >= scale * (1 - 1e-12) and strength.max() <= 2 * scale * (1 + 1e-12)
    assert strength.max() > 1.99 * scale  # the polar orbit passes over a pole


def test_the_bundled_cubesat_is_detumbled_by_b_dot_bit_for_bit_with_the_command_line(scenario):
    path = scenario("cubesat_b_dot.toml")
    header, rows = cli_csv(str(path))
    df = eulerdyn.run(path)
    assert list(df.columns) == header
    assert header[-6:] == ["B_b_x", "B_b_y", "B_b_z", "m_b_x", "m_b_y", "m_b_z"]
    assert np.array_equal(df.to_numpy().view(np.uint64), np.array(rows).view(np.uint64))


def test_b_dot_from_a_dict_holds_its_limit_and_takes_the_tumble_out():
    scene = boom_dict([{"type": "b_dot", "gain": 1.0e5, "max_dipole": 0.05}])
    scene["body"] = {"mass": 4.0, "inertia": [0.042, 0.040, 0.0067]}
    scene["initial"] = {"omega": [0.1, -0.15, 0.08]}
    scene["solver"] = {"rtol": 1e-10, "t_end": 6000.0}
    df = eulerdyn.run(scene)
    dipole = df[["m_b_x", "m_b_y", "m_b_z"]].to_numpy()
    # Each axis clipped exactly at the limit, and saturated while the tumble is fast.
    assert np.abs(dipole).max() == 0.05
    # B-dot never adds energy but for the orbit's own part of dB/dt (tests/it/b_dot.rs bounds it): here the energy
    # falls by more than half.
    assert df["energy"].iloc[-1] < 0.5 * df["energy"].iloc[0]
