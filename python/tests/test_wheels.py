"""`eulerdyn.run(scene, wheel_torque=f)` and `sweep(..., wheel_torque=f, moment=f)`: a Python wheel law against the
scene's own constant motor torque, its limits applied, and its failures (an exception, a wrong number of torques,
a wheel with its own driver) as clear errors."""

import numpy as np
import pytest

import eulerdyn

I_XX, J = 2.0, 0.05


def scene(extra=None):
    wheel = {"name": "wx", "axis": [1.0, 0.0, 0.0], "inertia": J, **(extra or {})}
    return {
        "body": {"mass": 10.0, "inertia": [I_XX, 3.0, 4.0], "rotor": [wheel]},
        "solver": {"method": "dop853", "t_end": 4.0, "rtol": 1e-12, "atol": 1e-14},
        "output": {"every": 0.5},
    }


def constant(t, q, omega_b, spins):
    return [0.1]


def test_a_constant_law_gives_the_rows_of_the_constant_motor_torque():
    # The law commands what `torque = 0.1` applies: the same equations, the same rows (the command columns aside).
    expected = eulerdyn.run(scene({"torque": 0.1, "max_torque": 1.0}))
    got = eulerdyn.run(scene({"max_torque": 1.0}), wheel_torque=constant)
    assert list(got.columns) == list(expected.columns)
    np.testing.assert_array_equal(got.to_numpy(), expected.to_numpy())


def test_the_law_is_clipped_and_both_torques_are_written():
    # τ_cmd = 0.1 clipped to 0.02: ω_x = −τ_max t / (I − J) (the gyrostat about x, H_s = 0; tests/it/wheels.rs).
    df = eulerdyn.run(scene({"max_torque": 0.02}), wheel_torque=constant)
    assert (df["wx_torque_cmd"] == 0.1).all() and (df["wx_torque"] == 0.02).all()
    # dop853 at rtol 1e-12 on a linear motion: 1e-9 relative is far above its error.
    np.testing.assert_allclose(df["omega_b_x"], -0.02 * df["t"] / (I_XX - J), rtol=1e-9, atol=1e-15)


def test_the_law_is_given_t_q_omega_b_and_the_spins():
    calls = []

    def spy(t, q, omega_b, spins):
        calls.append((t, q, omega_b, spins))
        return (0.0,)

    eulerdyn.run(scene({"spin": 3.0}), wheel_torque=spy, t_end=0.5)
    t, q, omega_b, spins = calls[0]
    assert t == 0.0 and q == (1.0, 0.0, 0.0, 0.0) and omega_b == (0.0, 0.0, 0.0) and spins == (3.0,)


def test_an_exception_in_the_law_is_a_run_error_naming_it():
    def broken(t, q, omega_b, spins):
        raise ZeroDivisionError("no torque today")

    with pytest.raises(eulerdyn.RunError, match="wheel_torque function broken") as caught:
        eulerdyn.run(scene(), wheel_torque=broken)
    assert isinstance(caught.value.__cause__, ZeroDivisionError)


def test_a_wrong_number_of_torques_is_a_clear_error():
    def two(t, q, omega_b, spins):
        return [0.0, 0.0]

    with pytest.raises(eulerdyn.RunError, match="must return 1 numbers"):
        eulerdyn.run(scene(), wheel_torque=two)


def test_a_wheel_with_its_own_driver_refuses_the_law():
    with pytest.raises(eulerdyn.SceneError, match=r"body\.rotor\[0\]\.mode.*`wx`"):
        eulerdyn.run(scene({"mode": "free"}), wheel_torque=constant)


def test_sweep_takes_wheel_torque_and_moment():
    sweep = {
        "scene": scene({"max_torque": 1.0}),
        "vary": [{"key": "body.rotor.0.max_torque", "values": [0.02, 0.05]}],
    }
    table = eulerdyn.sweep(sweep, jobs=1, wheel_torque=constant, moment=lambda t, q, w: (0.0, 0.0, 0.0))
    assert list(table["status"]) == ["ok", "ok"]
    # The clipped torque sets the final rate: ω_x(4) = −τ_max·4/(I − J), as above.
    expected = [-0.02 * 4.0 / (I_XX - J), -0.05 * 4.0 / (I_XX - J)]
    np.testing.assert_allclose(table["final_omega_b_x"], expected, rtol=1e-9)
