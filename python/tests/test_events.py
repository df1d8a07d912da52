"""Events in Python: `df.attrs["events"]` of `eulerdyn.run` and `eulerdyn.events`, the occurrences the command line
writes to `FILE.events.csv` (the same library call, `simulate::run_with_events`)."""

import csv
import math

import numpy as np
import pytest

import eulerdyn
from conftest import REPO, cli_error, disk_dict, run_cli

#: The compound pendulum of tests/it/events.rs: a thin rod (1 kg, 1 m) hinged at one end, released from rest at 30°,
#: rows every 0.05 s, with θ's downward crossings of 0 (`down`) and ω_b,z's minima (`fast`) as events; as a file,
#: and as a dict of the same keys.
PENDULUM_FILE = REPO / "tests" / "data" / "pendulum_events.toml"
PENDULUM = {
    "name": "pendulum-events",
    "body": {"mass": 1.0, "shape": {"type": "thin_rod", "length": 1.0}},
    "motion": {"type": "hinge", "axis": [0.0, 0.0, 1.0], "point": [-0.5, 0.0, 0.0], "angle_deg": 30.0},
    "initial": {"attitude": [0.7071067811865476, 0.0, 0.0, -0.7071067811865476]},
    "effect": [{"type": "gravity", "g": [0.0, -9.81, 0.0]}],
    "event": [
        {"name": "down", "when": "theta", "crosses": 0.0, "direction": "down"},
        {"name": "fast", "when": "omega_b_z", "extremum": "min"},
    ],
    "solver": {"method": "dop853", "t_end": 3.0},
    "output": {"every": 0.05},
}


def elliptic_k(k: float) -> float:
    """The complete elliptic integral of the first kind K(k) = π / (2 AGM(1, √(1 − k²))) (Abramowitz & Stegun,
    *Handbook of Mathematical Functions*, 17.6.1)."""
    a, b = 1.0, math.sqrt(1.0 - k * k)
    while abs(a - b) > 1e-16 * a:
        a, b = (a + b) / 2.0, math.sqrt(a * b)
    return math.pi / (2.0 * a)


def pendulum_period(theta0_deg: float) -> float:
    """The compound pendulum's period T = 4 K(k) √(I_A/(m g d)), k = sin(θ₀/2) (Landau & Lifshitz, *Mechanics*,
    §11, problem 1, with l = I_A/(m d)); the rod: I_A = m l²/3 = 1/3, d = l/2 = 1/2, m g = 9.81."""
    k = math.sin(math.radians(theta0_deg) / 2.0)
    return 4.0 * elliptic_k(k) * math.sqrt((1.0 / 3.0) / (9.81 * 0.5))


def cli_events(scene_path, tmp_path):
    """`eulerdyn run SCENE -o FILE`'s `FILE.events.csv`: its header and rows (t and value as Python's floats)."""
    out = tmp_path / "cli.csv"
    run_cli("run", str(scene_path), "-o", str(out))
    with open(f"{out}.events.csv", newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = [(r[0], float(r[1]), float(r[2]), r[3]) for r in reader]
    return header, rows


def test_pendulum_events_are_the_clis(tmp_path):
    path = PENDULUM_FILE
    header, rows = cli_events(path, tmp_path)
    assert header == ["event", "t", "value", "direction"]
    assert [r[0] for r in rows].count("down") == 2 and [r[0] for r in rows].count("fast") == 2, rows
    df = eulerdyn.run(path)
    for events in (df.attrs["events"], eulerdyn.events(path), eulerdyn.events(PENDULUM)):
        assert list(events.columns) == header
        assert events["t"].dtype == np.float64 and events["value"].dtype == np.float64
        assert list(events["event"]) == [r[0] for r in rows]
        assert list(events["direction"]) == [r[3] for r in rows]
        # The same located times and values as the command line's, to round-off (the same library call).
        for t, v, (_, t_cli, v_cli, _) in zip(events["t"], events["value"], rows):
            assert abs(t - t_cli) <= 1e-12 * t_cli, (t, t_cli)
            assert abs(v - v_cli) <= 1e-12 * max(1.0, abs(v_cli)), (v, v_cli)
    # And they are the pendulum's: the first θ crossing a quarter period after the release, the next a period later.
    period = pendulum_period(30.0)
    down = df.attrs["events"].query("event == 'down'")
    t = down["t"].to_numpy()
    assert np.all(np.abs(down["value"]) < 1e-12)
    assert abs(t[0] - period / 4.0) < 1e-9, t[0]
    assert abs(t[1] - t[0] - period) < 1e-9
    # Located between the rows, not on them (rows every 0.05 s).
    assert all(abs(ti / 0.05 - round(ti / 0.05)) > 1e-6 for ti in t)
    # events() keeps no rows but reports the same run, and takes run()'s keywords.
    assert eulerdyn.events(path).attrs["report"]["rows"] == len(df)
    dopri5 = eulerdyn.events(path, method="dopri5", t_end=1.0).query("event == 'down'")
    assert len(dopri5) == 1 and abs(dopri5["t"].iloc[0] - period / 4.0) < 1e-9


def test_a_scene_without_events_has_none():
    events = eulerdyn.events(disk_dict())
    assert len(events) == 0
    assert list(events.columns) == ["event", "t", "value", "direction"]
    assert events["t"].dtype == np.float64
    df = eulerdyn.run(disk_dict())
    assert len(df) > 0
    assert len(df.attrs["events"]) == 0


def test_a_stop_event_ends_the_rows_at_its_time():
    scene = {**PENDULUM, "event": [{**PENDULUM["event"][0], "stop": True}]}
    df = eulerdyn.run(scene)
    events = df.attrs["events"]
    assert len(events) == 1
    assert df["t"].iloc[-1] == events["t"].iloc[0]
    assert abs(events["t"].iloc[0] - pendulum_period(30.0) / 4.0) < 1e-9


@pytest.mark.parametrize(
    "event, key, problem",
    [
        ({"name": "x", "when": "no_such_column", "crosses": 0.0}, "event[0].when", "no_such_column"),
        ({"name": "x", "when": "theta", "crosses": 0.0, "direction": "sideways"}, "event[0].direction", "sideways"),
        ({"name": "x", "when": "theta"}, "event[0]", "crosses"),
    ],
)
def test_a_bad_event_key_is_a_scene_error_naming_it(tmp_path, event, key, problem):
    scene = {**PENDULUM, "event": [event]}
    for call in (eulerdyn.run, eulerdyn.events):
        with pytest.raises(eulerdyn.SceneError) as e:
            call(scene)
        assert e.value.key is not None and e.value.key.startswith(key), (e.value.key, str(e.value))
        assert problem in str(e.value)
    # The command line says the same of the same scene in a file.
    path = tmp_path / "bad.toml"
    path.write_text(PENDULUM_FILE.read_text().replace('when = "theta"', f'when = "{event["when"]}"', 1))
    if event["when"] != "theta":
        message = cli_error("run", str(path))
        with pytest.raises(eulerdyn.SceneError) as e:
            eulerdyn.events(path)
        assert str(e.value) == message
