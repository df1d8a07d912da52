"""sweep: the command's results table, the same across shards, and its bad input."""

import math

import pandas as pd
import pytest

import eulerdyn
from conftest import REPO, run_cli

BEARING_MAP = REPO / "scenarios" / "sweeps" / "disk_bearing_map.toml"


def without_wall_time(df: pd.DataFrame) -> pd.DataFrame:
    return df.drop(columns=["wall_s"]).reset_index(drop=True)


def test_the_bearing_map_is_the_cli_table():
    df = eulerdyn.sweep(BEARING_MAP, jobs=2)
    cli = eulerdyn._table(run_cli("sweep", str(BEARING_MAP)).stdout)
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
