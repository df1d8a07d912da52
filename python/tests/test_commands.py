"""check, compare, accuracy and balance: the commands' output, as Python data."""

import json
import math

import numpy as np
import pandas as pd
import pytest

import eulerdyn
from conftest import cli_csv, disk_dict, run_cli

STUDY_COLUMNS = [
    "method", "frame", "rtol", "dt", "err_omega", "err_attitude", "energy_drift", "H_drift", "wall_s", "steps",
    "rejected", "evals", "err_H_s", "atol", "backend", "repeats", "status",
]


@pytest.mark.parametrize("name", ["tilted_disk.toml", "asymmetric_free.toml", "rod_pendulum.toml", "heavy_top.toml"])
def test_check_is_what_the_cli_prints(scenario, name):
    path = scenario(name)
    info = eulerdyn.check(path)
    assert info["text"] == run_cli("check", str(path)).stdout
    header, rows = cli_csv(str(path))
    assert info["columns"] == header
    assert info["rows"] == len(rows)
    assert info["t_end"] == rows[-1][0]
    # Every line of the printout is under one of the items.
    lines = sum(len(v) for v in info["items"].values())
    assert lines == len(info["text"].splitlines())


def test_check_of_the_disk_dict():
    info = eulerdyn.check(disk_dict())
    assert info["motion"] == "fixed_axis"
    assert (info["method"], info["frame"], info["every"], info["rows"]) == ("dop853", "space", 0.01, 101)
    assert info["name"] == "tilted-disk"
    assert "dop853" in info["items"]["method"][0]
    assert info["text"].startswith("scene          tilted-disk\n")


def test_check_gives_the_facts_the_sidecar_writes(scenario, tmp_path):
    # One Facts value per scene: what check gives is what a run's sidecar records, and its numbers are those of
    # `check --json` (full precision).
    path = scenario("heavy_top.toml")
    facts = eulerdyn.check(path)["facts"]
    csv = tmp_path / "top.csv"
    run_cli("run", str(path), "-o", str(csv))
    sidecar = json.loads((tmp_path / "top.csv.meta.json").read_text())
    assert facts == sidecar["facts"]
    # A heavy top conserves T + V and H_s,z (Landau & Lifshitz §35: gravity's moment is horizontal).
    assert facts["invariants"] == ["energy_total", "H_s_z"]
    numbers = json.loads(run_cli("check", str(path), "--json").stdout)
    for key, value in facts["check"].items():
        assert numbers[key] == value, key


def test_compare_is_what_the_cli_prints(scenario):
    path = scenario("asymmetric_free.toml")
    result = eulerdyn.compare(path)
    assert result["text"] == run_cli("compare", str(path)).stdout
    assert result["passes"] is True
    assert result["tolerance"] == 1e-8
    assert result["closed_form"] is not None
    differences = result["differences"]
    assert list(differences.columns) == ["body vs space", "body vs exact", "space vs exact"]
    assert "omega" in differences.index
    assert (differences.max() <= 1e-8).all()


def test_compare_of_a_dict_that_exceeds_the_tolerance(tmp_path):
    """RK4 at a coarse step against the closed form: the command exits 1, the module says passes = False."""
    text = (
        "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 0.0, 2.0]\n"
        '[solver]\nmethod = "rk4"\ndt = 0.05\nt_end = 10.0\n[output]\nevery = 0.5\n[compare]\ntolerance = 1e-8\n'
    )
    path = tmp_path / "coarse.toml"
    path.write_text(text)
    scene = {
        "body": {"mass": 1.0, "inertia": [1.0, 2.0, 3.0]},
        "initial": {"omega": [0.3, 0.0, 2.0]},
        "solver": {"method": "rk4", "dt": 0.05, "t_end": 10.0},
        "output": {"every": 0.5},
        "compare": {"tolerance": 1e-8},
    }
    result = eulerdyn.compare(scene)
    cli = run_cli("compare", str(path), expect=1)
    assert result["text"] == cli.stdout
    assert result["passes"] is False
    assert result["differences"].to_numpy().max() > result["tolerance"]
    # With dop853 (the flag) it passes.
    assert eulerdyn.compare(scene, method="dop853")["passes"] is True


def test_accuracy_quick_study_of_a_dict():
    scene = {
        "body": {"mass": 1.0, "inertia": [1.0, 2.0, 3.0]},
        "initial": {"omega": [0.3, 0.0, 2.0]},
        "solver": {"t_end": 2.0},
        "output": {"every": 0.5},
    }
    table = eulerdyn.accuracy(scene, quick=True)
    assert list(table.columns) == STUDY_COLUMNS
    assert set(table["method"]) >= {"rk4", "dopri5", "dop853", "split2", "split4", "exact"}
    assert (table["status"] == "ok").all()
    # Against the closed form, dop853 at rtol 1e-10 is far better than at 1e-4.
    dop853 = table[table["method"] == "dop853"].set_index("rtol")["err_omega"]
    assert dop853[1e-10] < 1e-3 * dop853[1e-4]
    # The command's cells, typed: counts as ints, numbers as floats (NaN for an empty cell), names as str.
    assert str(table["steps"].dtype) == "int64" and str(table["repeats"].dtype) == "int64"
    assert table["rtol"].dtype == float and table["dt"].dtype == float
    assert table[table["method"] == "rk4"]["rtol"].isna().all()
    assert table[table["method"] == "rk4"]["dt"].notna().all()
    assert set(table["frame"]) == {"body"} and set(table["backend"]) == {"own"}
    assert "dop853" in table.attrs["summary"]
    # Typed by column, not by cells: the same dtypes for the rk4 rows alone (rtol empty) and the others.
    for name, dtype in table.dtypes.items():
        if name in ("steps", "rejected", "evals", "repeats"):
            assert dtype == np.int64, name
        elif name in ("method", "frame", "backend", "status"):
            assert pd.api.types.is_string_dtype(dtype) and dtype != np.float64, name
        else:
            assert dtype == np.float64, name
    rk4 = eulerdyn._api._table(
        table[table["method"] == "rk4"].to_csv(index=False, na_rep=""),
        eulerdyn._api._STUDY_COUNTS,
        eulerdyn._api._STUDY_TEXTS,
    )
    assert rk4["rtol"].isna().all()
    assert rk4.dtypes.to_dict() == table.dtypes.to_dict()


def test_accuracy_refuses_a_scene_it_cannot_study():
    scene = {"body": {"mass": 1.0, "inertia": [1.0, 2.0, 3.0]}, "solver": {"t_end": 0.0}, "output": {"every": 0.5}}
    with pytest.raises(eulerdyn.SceneError, match="t_end = 0"):
        eulerdyn.accuracy(scene, quick=True)


def test_balance_is_what_the_cli_prints(scenario):
    path = scenario("rotor_bearings.toml")
    result = eulerdyn.balance(path, planes=(-0.1, 0.1), radius=0.2)
    assert result["text"] == run_cli("balance", str(path), "--planes", "-0.1,0.1", "--radius", "0.2").stdout
    assert result["largest_reaction_after"] < 1e-9 * result["largest_reaction_before"]
    # The balanced scene runs, and its bearing reactions no longer rotate.
    df = eulerdyn.run(result["scene"])
    for column in ("R_A_s_x", "R_A_s_y", "R_B_s_x", "R_B_s_y"):
        assert np.ptp(df[column]) <= 1e-9 * 19.62, column


def test_balance_of_the_notes_disk():
    """The notes' skewed disk (s = 0, |d| = ¼ m R² sin θ cos θ): two equal masses ¼ m R² sin θ cos θ / (R_c (z₂ − z₁))
    on opposite sides."""
    m, r, theta, r_c, (z1, z2) = 2.0, 0.3, math.radians(30.0), 0.2, (-0.1, 0.1)
    result = eulerdyn.balance(disk_dict(), planes=(z1, z2), radius=r_c)
    expected = 0.25 * m * r * r * math.sin(theta) * math.cos(theta) / (r_c * (z2 - z1))
    masses = [c["mass_g"] * 1e-3 for c in result["corrections"]]
    assert masses == pytest.approx([expected, expected], rel=1e-12)
    assert [c["plane"] for c in result["corrections"]] == ["A", "B"]
    # At R_c from the axis u = (0, −sin θ, cos θ) (body axes), on opposite sides of it, in their planes.
    u = np.array([0.0, -math.sin(theta), math.cos(theta)])
    a, b = (np.array(c["at_b"]) for c in result["corrections"])
    assert (np.dot(a, u), np.dot(b, u)) == pytest.approx((z1, z2), abs=1e-12)
    radial_a, radial_b = a - np.dot(a, u) * u, b - np.dot(b, u) * u
    assert np.dot(radial_a, radial_b) == pytest.approx(-r_c * r_c, rel=1e-12)


def test_balance_refuses_a_free_body():
    scene = {"body": {"mass": 1.0, "inertia": [1.0, 2.0, 3.0]}, "solver": {"t_end": 1.0}, "output": {"every": 0.5}}
    with pytest.raises(eulerdyn.SceneError, match="<dict>: cannot balance: .*fixed_axis or a hinge"):
        eulerdyn.balance(scene, planes=(-0.1, 0.1), radius=0.2)


FAN_ARGS = ("--planes", "-0.1,0.08", "--radius", "0.25")


def test_balance_to_a_grade_from_measurements_is_what_the_cli_prints(scenario):
    """The fan of "Balancing to a grade": the dict is `--json`'s report, its text the command's output."""
    import json

    path, table = scenario("fan_rotor_g63.toml"), scenario("fan_rotor_measured.csv")
    result = eulerdyn.balance(path, planes=(-0.1, 0.08), radius=0.25, grade=6.3, service_rpm=1500, measured=table)
    flags = (*FAN_ARGS, "--grade", "6.3", "--service-rpm", "1500", "--measured", str(table))
    assert result["text"] == run_cli("balance", str(path), *flags).stdout
    report = json.loads(run_cli("balance", str(path), *flags, "--json").stdout)
    for key in ("mode", "unbalance_gmm", "grade", "influence", "planes", "corrections", "warnings"):
        assert result[key] == report[key], key
    assert result["mode"] == "measured"
    assert result["grade"]["target"]["pass"] and not result["grade"]["target"]["pass_before"]
    assert not result["influence"]["condition_warning"]
    # Each mass and angle once (issue 35): no second form under "influence", angles in [0, 360).
    assert "corrections_g" not in result["influence"]
    assert all(0.0 <= c["angle_deg"] < 360.0 for c in result["corrections"])
    assert result["warnings"] == [] and result["grade"]["tolerance_planes"] == "bearings"
    # Issue 57: without the service speed a grade from measurements is judged at the scene's rate, and says so.
    unserved = eulerdyn.balance(path, planes=(-0.1, 0.08), radius=0.25, grade=6.3, measured=table)
    assert unserved["grade"]["target"]["verdict"] == "unverified"
    assert any("--service-rpm" in w for w in unserved["warnings"])


def test_balance_one_shot_and_at_another_speed(scenario):
    path = scenario("fan_rotor_g63.toml")
    result = eulerdyn.balance(path, planes=(-0.1, 0.08), radius=0.25, measured=scenario("fan_rotor_initial.csv"))
    assert result["mode"] == "one_shot" and "one-shot balancing" in result["text"]
    # ISO 21940-11: U_per = 1000 G m / Ω, at the service speed (--service-rpm; issue 35: --rpm is the runs').
    result = eulerdyn.balance(path, planes=(-0.1, 0.08), radius=0.25, grade=6.3, service_rpm=3000.0)
    target = result["grade"]["target"]
    mass = result["grade"]["mass_kg"]
    assert target["u_per_gmm"] == pytest.approx(1000 * 6.3 * mass / (3000 * math.pi / 30), rel=1e-14)
    flags = (*FAN_ARGS, "--grade", "6.3", "--service-rpm", "3000", "--tolerance-planes", "correction")
    result = eulerdyn.balance(path, planes=(-0.1, 0.08), radius=0.25, grade=6.3, service_rpm=3000.0,
                              tolerance_planes="correction")
    assert result["text"] == run_cli("balance", str(path), *flags).stdout


@pytest.mark.parametrize(
    "keywords, cli_flags",
    [
        ({"grade": 0.0}, ("--grade", "0")),
        ({"rpm": -1500.0}, ("--rpm", "-1500")),
        ({"service_rpm": 0.0}, ("--service-rpm", "0")),
    ],
)
def test_balance_refuses_a_bad_grade_or_speed_as_the_cli_does(scenario, keywords, cli_flags):
    path = scenario("fan_rotor_g63.toml")
    message = run_cli("balance", str(path), *FAN_ARGS, *cli_flags, expect=2).stderr.strip()[len("error: "):]
    with pytest.raises(eulerdyn.SceneError) as e:
        eulerdyn.balance(path, planes=(-0.1, 0.08), radius=0.25, **keywords)
    assert str(e.value) == message


def test_balance_names_the_line_of_a_bad_table(scenario, tmp_path):
    table = tmp_path / "t.csv"
    table.write_text(
        "run,trial_plane,trial_mass_g,trial_angle_deg,A_amp,A_phase_deg,B_amp,B_phase_deg\n"
        "1,,,,41.4,41,16.0,78\n2,A,20,0,lots,15,58.4,15\n3,B,20,0,75.0,21,89.4,10\n"
    )
    with pytest.raises(eulerdyn.SceneError, match=r"t\.csv: line 3 \(run 2\), A_amp `lots`: not a finite number") as e:
        eulerdyn.balance(scenario("fan_rotor_g63.toml"), planes=(-0.1, 0.08), radius=0.25, measured=table)
    assert e.value.file == str(table)
