"""Errors: SceneError (a ValueError) with the command line's message naming the key; RunError with the time and the
reason; nothing else escapes (no PanicException)."""

import math

import pytest

import eulerdyn
from conftest import cli_error, disk_dict, run_cli


def test_scene_error_is_a_value_error():
    assert issubclass(eulerdyn.SceneError, ValueError)
    assert issubclass(eulerdyn.RunError, RuntimeError)
    assert not issubclass(eulerdyn.SceneError, eulerdyn.RunError)


def test_a_bad_file_gives_the_cli_message(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[body]\nmass = -1.0\ninertia = [1.0, 2.0, 3.0]\n[solver]\nt_end = 1.0\n[output]\nevery = 0.5\n")
    message = cli_error("run", str(bad))
    with pytest.raises(eulerdyn.SceneError) as e:
        eulerdyn.run(bad)
    assert str(e.value) == message
    assert e.value.key == "body.mass"
    assert (e.value.line, e.value.column) == (2, 1)
    assert e.value.file == str(bad)
    assert "finite number > 0" in e.value.problem
    # check, compare, accuracy and balance say the same.
    for call in (eulerdyn.check, eulerdyn.compare, eulerdyn.accuracy):
        with pytest.raises(eulerdyn.SceneError, match="key `body.mass`"):
            call(bad)


def test_a_missing_file_and_a_directory(tmp_path):
    missing = tmp_path / "nope.toml"
    with pytest.raises(eulerdyn.SceneError) as e:
        eulerdyn.run(missing)
    assert str(e.value) == cli_error("run", str(missing))
    with pytest.raises(eulerdyn.SceneError) as e:
        eulerdyn.check(tmp_path)
    assert str(e.value) == cli_error("check", str(tmp_path))


@pytest.mark.parametrize(
    "change, key, problem",
    [
        (lambda s: s["body"].update(mass=-2.0), "body.mass", "finite number > 0"),
        (lambda s: s["body"].update(mass=float("nan")), "body.mass", "finite"),
        (lambda s: s["body"].update(mass="2 kg"), "body.mass", "expected a number in SI units"),
        (lambda s: s["body"].update(mas=2.0), "body", "unknown field `mas`"),
        (lambda s: s["motion"].update(rate=None), "motion.rate", "leave the key out"),
        (lambda s: s["motion"].update(rate=object()), "motion.rate", "got object"),
        (lambda s: s["solver"].update(method="rk5"), "solver.method", "rk5"),
        (lambda s: s["output"].pop("every"), "output.every", "missing"),
        (lambda s: s["initial"].update(attitude=[1.0, 0.0]), "initial.attitude", "4"),
        (lambda s: s.update(effect={"type": "damping", "c": 0.1}), "effect", "[[effect]]"),
        (lambda s: s["motion"].update({1: 2}), "motion", "keys are strings"),
        (lambda s: s["solver"].update(t_end=10**30), "solver.t_end", "too large"),
    ],
)
def test_a_bad_dict_names_the_key(change, key, problem):
    scene = disk_dict()
    change(scene)
    with pytest.raises(eulerdyn.SceneError) as e:
        eulerdyn.run(scene)
    message = str(e.value)
    assert message.startswith(f"<dict>: key `{key}"), message
    assert problem in message
    assert e.value.key.startswith(key)
    assert e.value.file == "<dict>"
    assert e.value.line is None and e.value.column is None


def test_a_dict_gives_the_message_of_the_same_file(tmp_path):
    """The same scene as a dict and as a file: the same message but for the file's name and line."""
    text = "[body]\nmass = 1.0\ninertia = [1.0, 2.0, -3.0]\n[solver]\nt_end = 1.0\n[output]\nevery = 0.5\n"
    path = tmp_path / "s.toml"
    path.write_text(text)
    scene = {"body": {"mass": 1.0, "inertia": [1.0, 2.0, -3.0]}, "solver": {"t_end": 1.0}, "output": {"every": 0.5}}
    with pytest.raises(eulerdyn.SceneError) as from_dict:
        eulerdyn.run(scene)
    with pytest.raises(eulerdyn.SceneError) as from_file:
        eulerdyn.run(path)
    assert from_dict.value.key == from_file.value.key == "body.inertia"
    assert from_dict.value.problem == from_file.value.problem


@pytest.mark.parametrize(
    "kwargs, flags, flag, key",
    [
        ({"method": "euler"}, ["--method", "euler"], "--method", "solver.method (from method=)"),
        ({"frame": "lab"}, ["--frame", "lab"], "--frame", "solver.frame (from frame=)"),
        ({"backend": "gsl"}, ["--backend", "gsl"], "--backend", "solver.backend (from backend=)"),
        ({"rtol": -1.0}, ["--rtol", "-1"], "--rtol", "solver.rtol (from rtol=)"),
        ({"atol": 0.0}, ["--atol", "0"], "--atol", "solver.atol (from atol=)"),
        ({"dt": 0.0, "method": "rk4"}, ["--dt", "0", "--method", "rk4"], "--dt", "solver.dt (from dt=)"),
        ({"dt": -1.0, "method": "rk4"}, ["--dt", "-1", "--method", "rk4"], "--dt", "solver.dt (from dt=)"),
        ({"every": -0.1}, ["--every", "-0.1"], "--every", "output.every (from every=)"),
        ({"t_end": math.inf}, ["--t-end", "inf"], "--t-end", "solver.t_end (from t_end=)"),
    ],
)
def test_a_bad_override_names_the_keyword_argument(scenario, kwargs, flags, flag, key):
    """The command line's message, with the keyword argument that set the key in place of the flag (issue 27)."""
    path = scenario("asymmetric_free.toml")
    with pytest.raises(eulerdyn.SceneError) as e:
        eulerdyn.run(path, **kwargs)
    cli = cli_error("run", str(path), *flags)
    assert f"(from {flag})" in cli
    assert str(e.value) == cli.replace(f"(from {flag})", f"(from {key.split('(from ')[1]}")
    assert e.value.key == key
    assert "--" not in str(e.value)


def test_a_bad_method_in_compare_names_the_keyword_argument(scenario):
    with pytest.raises(eulerdyn.SceneError) as e:
        eulerdyn.compare(scenario("asymmetric_free.toml"), method="euler")
    assert e.value.key == "solver.method (from method=)"
    assert "key `solver.method (from method=)`" in str(e.value)


def test_a_scene_of_the_wrong_type_is_a_type_error():
    with pytest.raises(TypeError, match="path"):
        eulerdyn.run(42)


DIVERGING = """\
[body]
mass = 1.0
inertia = [1.0, 2.0, 3.0]
[initial]
omega = [1.0, 20.0, 1.0]
[solver]
method = "rk4"
dt = 0.4
t_end = 50.0
[output]
every = 0.4
"""


def test_a_failed_run_is_run_error_with_the_time(tmp_path):
    path = tmp_path / "diverging.toml"
    path.write_text(DIVERGING)
    stderr = run_cli("run", str(path), expect=1).stderr.strip().splitlines()
    # The coarse step is warned of first (a UserWarning in Python, a `warning:` line on stderr), then the error.
    with pytest.raises(eulerdyn.RunError) as e, pytest.warns(UserWarning, match="turns the body by 8.02 rad"):
        eulerdyn.run(path)
    assert stderr[0] == f"{path}: warning: a fixed step of 0.4 s turns the body by 8.02 rad (|omega| = 20 rad/s), " \
        "more than the 0.1 rad per step a fixed-step method needs to be accurate: the rows may be wrong; use " \
        "dt <= 0.00499 s or an adaptive method (dopri5, dop853)"
    assert f"error: {e.value}" == stderr[-1]
    assert str(e.value).startswith(f"{path}: the run failed: ")
    assert isinstance(e.value.t, float) and 0.0 < e.value.t <= 50.0
    assert f"t = {e.value.t}" in e.value.reason or str(e.value.t) in e.value.reason
    assert e.value.scene == str(path)


def test_huge_and_tiny_values_raise_scene_errors_not_panics():
    """Values at the edges of f64 go through validation: each is a SceneError or a run, never a panic."""
    for change in (
        lambda s: s["body"].update(mass=1e308),
        lambda s: s["body"]["shape"].update(radius=1e-308),
        lambda s: s["motion"].update(rate=1e308),
        lambda s: s["motion"].update(tilt_deg=-1e308),
        lambda s: s["output"].update(every=5e-324),
        lambda s: s["initial"].update(attitude=[0.0, 0.0, 0.0, 0.0]),
        lambda s: s["solver"].update(t_end=-0.0),
    ):
        scene = disk_dict()
        change(scene)
        try:
            eulerdyn.run(scene)
        except (eulerdyn.SceneError, eulerdyn.RunError) as e:
            assert str(e).startswith("<dict>"), e
