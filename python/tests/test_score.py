"""`eulerdyn.score(theirs, scene, diagnose=False, ...)`: the dict `eulerdyn score THEIRS.csv --scene SCENE --json`
prints, for a path and for a DataFrame of the same rows; bad options raise SceneError."""

import json

import pandas as pd
import pytest

import eulerdyn
from conftest import run_cli


@pytest.fixture(scope="module")
def suite(tmp_path_factory):
    folder = tmp_path_factory.mktemp("suite")
    run_cli("suite", "--out", str(folder))
    return folder


def cli_json(*args):
    return json.loads(run_cli("score", *args, "--json").stdout)


def test_score_equals_the_commands_json(suite):
    theirs, scene = suite / "full_tensor.csv", suite / "full_tensor.toml"
    assert eulerdyn.score(theirs, scene) == cli_json(str(theirs), "--scene", str(scene))


def test_diagnose_equals_the_commands_json(suite):
    theirs, scene = suite / "tennis_racket.csv", suite / "tennis_racket.toml"
    got = eulerdyn.score(str(theirs), str(scene), diagnose=True)
    assert got == cli_json(str(theirs), "--scene", str(scene), "--diagnose")
    assert got["diagnosis"]["verdict"] in ("match", "nearest")
    assert len(got["diagnosis"]["candidates"]) == 120


def test_a_dataframe_scores_as_its_file(suite):
    theirs, scene = suite / "symmetric_precession.csv", suite / "symmetric_precession.toml"
    frame = pd.read_csv(theirs, float_precision="round_trip")
    from_frame = eulerdyn.score(frame, scene)
    from_file = eulerdyn.score(theirs, scene)
    assert from_frame["file"] == "<DataFrame>"
    assert from_frame["metrics"] == from_file["metrics"]


def test_options_are_the_commands_flags(suite):
    theirs, scene = suite / "full_tensor.csv", suite / "full_tensor.toml"
    frame = pd.read_csv(theirs, float_precision="round_trip").rename(columns={"q_w": "qw"})
    mapped = eulerdyn.score(frame, scene, map={"q_w": "qw"})
    assert mapped["metrics"] == eulerdyn.score(theirs, scene)["metrics"]
    with pytest.raises(eulerdyn.SceneError, match='quaternion="zyxw"'):
        eulerdyn.score(theirs, scene, quaternion="zyxw")
    with pytest.raises(eulerdyn.SceneError, match="no column `nowhere`"):
        eulerdyn.score(theirs, scene, map={"omega_x": "nowhere"})
