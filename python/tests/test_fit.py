"""`eulerdyn.fit(measured, scene, estimate=[...])`: the dict `eulerdyn fit MEASURED.csv --scene SCENE --estimate
LIST --json` prints, for a path and a DataFrame; and the same estimates as an independent SciPy fit of the same
problem (`scipy.optimize.least_squares`, MINPACK's LM with finite-difference Jacobians, over `solve_ivp`'s DOP853).

The model of the SciPy fit is written here from the textbook: Euler's equations in principal axes,
I1 w1' = (I2 - I3) w2 w3 and cyclic (the lecture notes' Euler equations; Landau & Lifshitz, Mechanics, eq. 36.5),
the third moment held (the motion fixes the inertia only up to a common factor)."""

import json

import numpy as np
import pandas as pd
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import least_squares

import eulerdyn
from conftest import run_cli

SIGMA = 2e-3
I3 = 1.6


def scene(moments, omega):
    return {
        "body": {"mass": 1.0, "inertia": list(moments)},
        "initial": {"omega": list(omega)},
        "solver": {"t_end": 10.0},
        "output": {"every": 0.05},
    }


@pytest.fixture(scope="module")
def measured():
    """A triaxial tumble's gyro readings every 0.05 s for 10 s with N(0, SIGMA) noise (seeded)."""
    truth = eulerdyn.run(scene([1.0, 1.3, I3], [0.4, 0.1, 1.5]))
    rng = np.random.default_rng(20261129)
    frame = pd.DataFrame({"t": truth["t"]})
    for axis in "xyz":
        frame[f"omega_{axis}"] = truth[f"omega_b_{axis}"] + rng.normal(0.0, SIGMA, len(truth))
    return frame


START = scene([1.05, 1.25, I3], [0.41, 0.09, 1.49])


def test_fit_equals_the_commands_json(measured, tmp_path):
    path = tmp_path / "gyro.csv"
    measured.to_csv(path, index=False, float_format="%.17g")
    start = tmp_path / "start.toml"
    start.write_text(
        "[body]\nmass = 1.0\ninertia = [1.05, 1.25, 1.6]\n[initial]\nomega = [0.41, 0.09, 1.49]\n"
        "[solver]\nt_end = 10.0\n[output]\nevery = 0.05\n"
    )
    got = eulerdyn.fit(path, start, estimate=["principal", "omega0"], sigma_omega=SIGMA)
    cli = json.loads(
        run_cli(
            "fit", str(path), "--scene", str(start), "--estimate", "principal,omega0",
            "--sigma-omega", str(SIGMA), "--json",
        ).stdout
    )
    assert got == cli
    from_frame = eulerdyn.fit(measured, START, estimate=["principal", "omega0"], sigma_omega=SIGMA)
    assert from_frame["file"] == "<DataFrame>"
    assert from_frame["parameters"] == got["parameters"]


def test_an_unknown_parameter_raises_scene_error(measured):
    with pytest.raises(eulerdyn.SceneError, match="--estimate mass"):
        eulerdyn.fit(measured, START, estimate=["mass"])


def scipy_fit(measured):
    """The same problem by SciPy: x = (I1, I2, w0), residuals (w(t) - w_meas) / SIGMA."""
    t = measured["t"].to_numpy()
    w_meas = measured[["omega_x", "omega_y", "omega_z"]].to_numpy()

    def residuals(x):
        i1, i2, w0 = x[0], x[1], x[2:5]

        def euler(_, w):
            return [(i2 - I3) * w[1] * w[2] / i1, (I3 - i1) * w[2] * w[0] / i2, (i1 - i2) * w[0] * w[1] / I3]

        sol = solve_ivp(euler, (0.0, t[-1]), w0, method="DOP853", t_eval=t, rtol=1e-12, atol=1e-14)
        return ((sol.y.T - w_meas) / SIGMA).ravel()

    x0 = np.array([1.05, 1.25, 0.41, 0.09, 1.49])
    result = least_squares(residuals, x0, method="lm", xtol=1e-14, ftol=1e-14, gtol=1e-14)
    cov = np.linalg.inv(result.jac.T @ result.jac)
    return result.x, np.sqrt(np.diag(cov))


def test_the_estimates_and_errors_are_scipys(measured):
    ours = eulerdyn.fit(measured, START, estimate=["principal", "omega0"], sigma_omega=SIGMA)
    by_name = {p["name"]: p for p in ours["parameters"]}
    x, se = scipy_fit(measured)
    for k, name in enumerate(["I_1", "I_2", "omega0_x", "omega0_y", "omega0_z"]):
        p = by_name[name]
        # Both minimise the same sum of squares: the optima differ by the two integrations' error (rtol 1e-12)
        # and SciPy's finite-difference Jacobian at its last step, far below the estimate's own uncertainty (3e-7 of it measured).
        assert abs(p["estimate"] - x[k]) <= 1e-5 * p["std_error"], (name, p["estimate"], x[k])
        # The standard errors from J at the optimum: SciPy's J by forward differences (relative error ~1e-7: 1.3e-7 measured).
        assert abs(p["std_error"] - se[k]) <= 1e-6 * se[k], (name, p["std_error"], se[k])
    assert ours["scale_held"] and by_name["I_3"]["std_error"] == 0.0


def test_a_moment_law_acts_in_the_model_and_fixes_the_scale():
    # M = k (w_ref - w), a known law: it acts in the fit's model as in the run, and fixes the inertia's scale.
    def law(t, q, w):
        return [0.02 * (0.0 - w[0]), 0.02 * (0.0 - w[1]), 0.02 * (1.0 - w[2])]

    truth = eulerdyn.run(scene([1.0, 1.3, I3], [0.4, 0.1, 1.5]), moment=law, rtol=1e-13, atol=1e-15)
    gyro = truth.rename(columns={f"omega_b_{a}": f"omega_{a}" for a in "xyz"})
    gyro = gyro[["t", "omega_x", "omega_y", "omega_z"]]
    result = eulerdyn.fit(gyro, START, estimate=["principal", "omega0"], moment=law)
    by_name = {p["name"]: p["estimate"] for p in result["parameters"]}
    assert result["converged"] and not result["scale_held"]
    # Noise-free rows of a run at rtol 1e-13: the truth to 1e-7.
    for name, value in [("I_1", 1.0), ("I_2", 1.3), ("I_3", I3), ("omega0_x", 0.4)]:
        assert abs(by_name[name] - value) < 1e-7, (name, by_name[name])
    # Without the law the same rows are fitted by a torque-free body, which cannot follow them.
    without = eulerdyn.fit(gyro, START, estimate=["principal", "omega0"])
    assert without["scale_held"] and without["rms"]["omega"] > 1e3 * result["rms"]["omega"]
