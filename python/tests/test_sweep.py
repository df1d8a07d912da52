"""sweep: the command's results table, the same across shards, and its bad input."""

import math

import numpy as np
import pandas as pd
import pytest

import eulerdyn
from conftest import REPO, disk_dict, run_cli
from eulerdyn._api import _sweep_table

BEARING_MAP = REPO / "scenarios" / "sweeps" / "disk_bearing_map.toml"


def without_wall_time(df: pd.DataFrame) -> pd.DataFrame:
    return df.drop(columns=["wall_s"]).reset_index(drop=True)


def test_the_bearing_map_is_the_cli_table():
    df = eulerdyn.sweep(BEARING_MAP, jobs=2)
    cli = _sweep_table(run_cli("sweep", str(BEARING_MAP)).stdout)
    assert list(df.columns) == list(cli.columns)
    assert len(df) == 19 * 11
    pd.testing.assert_frame_equal(without_wall_time(df), without_wall_time(cli))


def test_the_bearing_map_follows_the_closed_form():
    # The notes' disk (m = 2 kg, R = 0.3 m) on an axis tilted theta from its symmetry axis at rate omega: the
    # bearings supply |M| = 1/4 m R^2 omega^2 sin(theta) cos(theta) (Meghdari, Rigid Body Dynamics, the tilted disk).
    df = eulerdyn.sweep(BEARING_MAP)
    assert (df["status"] == "ok").all()
    theta = df["motion.tilt_deg"].map(math.radians)
    omega = df["motion.rate"]
    expected = 0.25 * 2.0 * 0.3**2 * omega**2 * theta.map(math.sin) * theta.map(math.cos)
    scale = expected.abs().max()
    assert ((df["max_M_norm"] - expected).abs() <= 1e-9 * scale).all()


def test_three_shards_merged_are_the_whole_sweep():
    whole = eulerdyn.sweep(BEARING_MAP, jobs=1)
    parts = [eulerdyn.sweep(BEARING_MAP, jobs=1, shard=f"{k}/3") for k in (1, 2, 3)]
    assert [len(p) for p in parts] == [70, 70, 69]
    merged = pd.concat(parts).sort_values("run")
    pd.testing.assert_frame_equal(without_wall_time(merged), without_wall_time(whole))


def test_bad_sweeps_raise_scene_error(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(
        f'scene = "{BEARING_MAP.parent / "disk_on_bearings.toml"}"\n[[vary]]\nkey = "motion.tilt"\nvalues = [1.0]\n'
    )
    with pytest.raises(eulerdyn.SceneError, match=r"bad.toml:3:1: key `vary\[0\].key`") as caught:
        eulerdyn.sweep(bad)
    assert "not a key of the scene format" in str(caught.value)
    with pytest.raises(eulerdyn.SceneError, match="--shard 4/3"):
        eulerdyn.sweep(BEARING_MAP, shard="4/3")
    with pytest.raises(eulerdyn.SceneError, match="jobs = 0"):
        eulerdyn.sweep(BEARING_MAP, jobs=0)


# scenarios/sweeps/disk_bearing_map.toml as a dict, its base scene as a path.
BEARING_MAP_DICT = {
    "scene": str(BEARING_MAP.parent / "disk_on_bearings.toml"),
    "vary": [
        {"key": "motion.tilt_deg", "linspace": [0.0, 90.0, 19]},
        {"key": "motion.rate", "logspace": [1.0, 100.0, 11]},
    ],
    "summary": {"columns": ["M_b_x"]},
}


def test_a_dict_is_the_same_sweep_as_its_file():
    whole = eulerdyn.sweep(BEARING_MAP, jobs=2, shard="1/5")
    from_dict = eulerdyn.sweep(BEARING_MAP_DICT, jobs=2, shard="1/5")
    assert len(from_dict) == 42
    pd.testing.assert_frame_equal(without_wall_time(from_dict), without_wall_time(whole))
    # The base scene as a pathlib.Path, and relative to the working directory.
    as_path = dict(BEARING_MAP_DICT, scene=BEARING_MAP.parent / "disk_on_bearings.toml")
    pd.testing.assert_frame_equal(
        without_wall_time(eulerdyn.sweep(as_path, shard="1/5")), without_wall_time(whole)
    )


def test_a_dict_sweep_of_a_dict_scene(monkeypatch, tmp_path):
    """The base scene as a dict: the notes' disk on its tilted axis, the rate varied. |M| = 1/4 m R^2 omega^2
    sin(theta) cos(theta) (Meghdari, Rigid Body Dynamics, the tilted disk), 1.9485571585 N m at 10 rad/s."""
    monkeypatch.chdir(tmp_path)
    plan = {"scene": disk_dict(), "vary": [{"key": "motion.rate", "values": [5.0, 10.0, 20.0]}]}
    df = eulerdyn.sweep(plan)
    assert list(df["run"]) == [0, 1, 2] and (df["status"] == "ok").all()
    theta = math.radians(30.0)
    expected = 0.25 * 2.0 * 0.3**2 * df["motion.rate"] ** 2 * math.sin(theta) * math.cos(theta)
    assert np.allclose(df["max_M_norm"], expected, rtol=1e-12, atol=0.0)
    assert df["max_M_norm"][1] == pytest.approx(1.9485571585, rel=1e-10)
    # Nothing is left in the working directory.
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "change, key, problem",
    [
        (lambda p: p["vary"][0].update(key="motion.tilt"), "vary[0].key", "not a key of the scene format"),
        (lambda p: p["vary"][0].update(values=[]), "vary[0].values", ""),
        (lambda p: p.update(runs=0), "runs", "at least 1"),
        (lambda p: p.update(seeds=1), None, "unknown field `seeds`"),
        (lambda p: p.pop("scene"), None, "scene"),
        (lambda p: p.update(scene=42), "scene", "got int"),
        (lambda p: p.update(scene="no/such/scene.toml"), "scene", "is not a file"),
        (lambda p: p["scene"]["body"].update(mass="2 kg"), "scene.body.mass", "expected a number in SI units"),
        (lambda p: p["scene"]["body"].update(mass=None), "scene.body.mass", "leave the key out"),
        (lambda p: p["scene"]["motion"].update(spin=1.0), "scene.motion", "unknown field `spin`"),
    ],
)
def test_a_bad_dict_sweep_names_dict_and_the_key(change, key, problem):
    plan = {"scene": disk_dict(), "vary": [{"key": "motion.rate", "values": [5.0, 10.0]}]}
    change(plan)
    with pytest.raises(eulerdyn.SceneError) as e:
        eulerdyn.sweep(plan)
    message = str(e.value)
    prefix = f"<dict>: key `{key}" if key else "<dict>: "
    assert message.startswith(prefix), message
    assert problem in message, message
    assert e.value.file == "<dict>"
    assert (e.value.line, e.value.column) == (None, None)
    # Nothing names the files the dict is written to.
    assert ".tmp" not in message and "sweep.toml" not in message, message


def test_a_dict_sweep_of_a_bad_scene_file_names_the_file(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[body]\nmas = 1.0\ninertia = [1.0, 2.0, 3.0]\n[solver]\nt_end = 1.0\n[output]\nevery = 0.5\n")
    with pytest.raises(eulerdyn.SceneError) as e:
        eulerdyn.sweep({"scene": str(bad), "vary": [{"key": "body.inertia.0", "values": [1.0]}]})
    assert str(e.value).startswith(f"{bad}:2:1: key `body.mas`: unknown field `mas`"), str(e.value)
    assert (e.value.file, e.value.line) == (str(bad), 2)


def small_sweep(masses):
    """A box, torque-free, its mass varied: a negative mass is an invalid run (a row with a message and empty
    cells)."""
    scene = {
        "body": {"mass": 1.0, "inertia": [1.0, 2.0, 3.0]},
        "initial": {"omega": [0.3, 0.0, 2.0]},
        "solver": {"t_end": 0.5},
        "output": {"every": 0.25},
    }
    return {"scene": scene, "vary": [{"key": "body.mass", "values": masses}]}


def test_a_column_has_one_dtype_with_or_without_empty_cells():
    """The same columns, the same dtypes: all runs ok (empty messages), an invalid run (empty numbers, a message),
    and no rows at all (issue 21)."""
    ok = eulerdyn.sweep(small_sweep([1.0, 2.0]))
    mixed = eulerdyn.sweep(small_sweep([1.0, -1.0]))
    empty = eulerdyn.sweep(small_sweep([1.0]), shard="2/2")
    assert list(ok["message"]) == ["", ""]
    assert list(mixed["status"]) == ["ok", "invalid"] and "body.mass" in mixed["message"][1]
    assert mixed["max_M_norm"].isna().tolist() == [False, True]
    assert len(empty) == 0
    assert list(mixed.columns) == list(ok.columns) == list(empty.columns)
    assert mixed.dtypes.to_dict() == ok.dtypes.to_dict()
    assert empty.dtypes.to_dict() == ok.dtypes.to_dict()
    # The rule: counts int64, names and messages pandas' string dtype, every other column float64.
    for name, dtype in ok.dtypes.items():
        if name in ("run", "steps", "evals"):
            assert dtype == np.int64, name
        elif name in ("status", "message"):
            assert pd.api.types.is_string_dtype(dtype) and dtype != np.float64, name
        else:
            assert dtype == np.float64, name


def test_a_sweep_of_the_wrong_type_is_a_type_error():
    with pytest.raises(TypeError, match="sweep: expected a sweep file's path .* or a dict of its keys, got int"):
        eulerdyn.sweep(42)
