"""`eulerdyn.run(scene, moment=f)`: a Python callable as the moment law, against the built-in torque it computes, and
its failures (an exception, a wrong result, Ctrl-C) stopping the run with a clear error."""

import math
import signal
import threading

import numpy as np
import pytest

import eulerdyn

BODY = {"mass": 2.0, "inertia": [1.0, 2.0, 3.0]}
SOLVER = {"t_end": 3.0, "rtol": 1e-11, "atol": 1e-13}
SINE = {"value": [0.3, -0.2, 0.5], "freq_hz": 0.7, "phase_deg": 30.0}


def scene(effects=()):
    return {
        "body": BODY,
        "initial": {"omega": [0.1, 1.5, 0.2]},
        "effect": list(effects),
        "solver": SOLVER,
        "output": {"every": 0.1},
    }


def sine_law(t, q, omega_b):
    """The built-in sine torque M = value·sin(2π f t + φ) (the scene's `profile = "sine"`), computed in Python."""
    factor = math.sin(2.0 * math.pi * SINE["freq_hz"] * t + math.radians(SINE["phase_deg"]))
    return [v * factor for v in SINE["value"]]


@pytest.mark.parametrize("frame", ["body", "space"])
def test_a_callable_computing_the_sine_torque_gives_the_built_in_rows(frame):
    builtin = {"type": "torque", "profile": "sine", "frame": frame, **SINE}
    expected = eulerdyn.run(scene([builtin]))
    got = eulerdyn.run(scene(), moment=sine_law, moment_frame=frame)
    assert list(got.columns) == list(expected.columns)
    # The two sines differ by an ulp (the crate's inline sine, Python's math.sin): the rows agree to 1e-12.
    np.testing.assert_allclose(got.to_numpy(), expected.to_numpy(), rtol=0, atol=1e-12)
    assert got.attrs["report"]["evals"] > 0


def test_the_callable_is_given_t_q_and_omega_b():
    calls = []

    def spy(t, q, omega_b):
        calls.append((t, q, omega_b))
        return (0.0, 0.0, 0.0)

    df = eulerdyn.run(scene(), moment=spy, method="rk4", dt=0.05, t_end=0.1, every=0.1)
    # Once per right-hand-side evaluation, and once per row for its moment columns (M_b, M_s).
    report = df.attrs["report"]
    assert len(calls) == report["evals"] + report["rows"]
    t, q, omega_b = calls[0]
    assert t == 0.0 and q == (1.0, 0.0, 0.0, 0.0) and omega_b == pytest.approx((0.1, 1.5, 0.2))


def test_an_exception_in_the_callable_is_a_run_error_carrying_it():
    def broken(t, q, omega_b):
        if t > 0.5:
            raise ZeroDivisionError("the controller divided by zero")
        return (0.0, 0.0, 0.0)

    with pytest.raises(eulerdyn.RunError) as info:
        eulerdyn.run(scene(), moment=broken)
    message = str(info.value)
    assert "the moment function broken()" in message
    assert "ZeroDivisionError: the controller divided by zero" in message
    assert isinstance(info.value.__cause__, ZeroDivisionError)
    assert info.value.t > 0.5


@pytest.mark.parametrize(
    "result, problem",
    [
        ((1.0, 2.0), "must return 3 numbers (M_x, M_y, M_z in N*m), got 2 numbers"),
        ("abc", "must return 3 numbers (M_x, M_y, M_z in N*m), got 'abc' (a str)"),
        (None, "got None (a NoneType)"),
        ((0.0, math.nan, 0.0), "returned a non-finite moment (0, NaN, 0)"),
    ],
)
def test_a_wrong_result_is_a_clear_run_error(result, problem):
    with pytest.raises(eulerdyn.RunError) as info:
        eulerdyn.run(scene(), moment=lambda t, q, w: result)
    assert problem in str(info.value), str(info.value)


def test_bad_arguments_are_refused_before_the_run():
    with pytest.raises(TypeError, match="moment: expected a callable"):
        eulerdyn.run(scene(), moment=3)
    with pytest.raises(ValueError, match='moment_frame: unknown value "lab"; expected one of: body, space'):
        eulerdyn.run(scene(), moment=sine_law, moment_frame="lab")
    with pytest.raises(eulerdyn.SceneError, match='method "split2" cannot apply the user\'s moment "sine_law"'):
        eulerdyn.run(scene(), moment=sine_law, method="split2")


def test_ctrl_c_in_a_long_run_with_a_callable_interrupts_it():
    """SIGINT sent during the run: the law runs Python's signal handlers at its next call."""
    timer = threading.Timer(0.3, lambda: signal.raise_signal(signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            eulerdyn.run(scene(), moment=sine_law, t_end=1e5, every=1.0)
    finally:
        timer.cancel()
