"""The first hour from Python (issue 38): `eulerdyn.plot` and `eulerdyn.view` give eulerdyn's own figure and 3D
page, the same as the command line's for the same run; a `logspace` sweep warns that it takes end values."""

import re

import pytest

import eulerdyn
from conftest import SCENARIOS, run_cli


def titles(svg: str) -> list:
    """The texts of the SVG (panel titles, legends, tick labels), in order."""
    return [t.strip() for t in re.findall(r"<text[^>]*>([^<]*)</text>", svg)]


def test_plot_of_a_scene_is_the_command_lines_figure(tmp_path):
    scene = SCENARIOS / "tilted_disk.toml"
    figure = eulerdyn.plot(scene)
    assert isinstance(figure, eulerdyn.Svg)
    assert figure._repr_svg_() == str(figure) and str(figure).startswith("<svg")
    csv = tmp_path / "disk.csv"
    run_cli("run", str(scene), "-o", str(csv))
    fig = tmp_path / "disk.svg"
    run_cli("plot", str(csv), "-o", str(fig))
    # The same panels, titles, legends and ticks as the command line's figure of the same run.
    assert titles(str(figure)) == titles(fig.read_text())
    assert "Moment of momentum H, space axes" in titles(str(figure))


def test_plot_takes_a_csv_a_dataframe_and_chosen_panels(tmp_path):
    scene = SCENARIOS / "tilted_disk.toml"
    csv = tmp_path / "disk.csv"
    run_cli("run", str(scene), "-o", str(csv))
    from_csv = eulerdyn.plot(csv, panels=["h_space", "omega"])
    texts = titles(str(from_csv))
    assert "Moment of momentum H, space axes" in texts
    assert "Angular velocity ω" in texts
    assert "Moment of momentum H, body axes" not in texts
    df = eulerdyn.run(scene)
    from_df = eulerdyn.plot(df, panels="h_space")
    # A DataFrame has no sidecar: the title is the temporary file's name and rows, the panel the same.
    assert "Moment of momentum H, space axes" in titles(str(from_df))
    assert any(t.endswith(f"{len(df)} rows") for t in titles(str(from_df)))
    out = tmp_path / "fig.svg"
    from_df.save(out)
    assert out.read_text() == str(from_df)


def test_plot_refuses_bad_panels_and_files_as_the_command_line_does(tmp_path):
    with pytest.raises(eulerdyn.SceneError, match='unknown panel "torque"'):
        eulerdyn.plot(SCENARIOS / "tilted_disk.toml", panels="torque")
    missing = tmp_path / "none.csv"
    with pytest.raises(eulerdyn.SceneError, match="none.csv"):
        eulerdyn.plot(missing)


def test_view_writes_the_3d_page(tmp_path):
    page = tmp_path / "disk.html"
    drawn = eulerdyn.view(SCENARIOS / "tilted_disk.toml", page)
    html = page.read_text()
    assert "<html" in html.lower() and "three" in html.lower()
    assert drawn["bytes"] == len(html.encode())
    assert drawn["rows_drawn"] >= 2 and drawn["rows_in_run"] >= drawn["rows_drawn"]
    # The same page as `eulerdyn view` of the same run.
    csv = tmp_path / "disk.csv"
    run_cli("run", str(SCENARIOS / "tilted_disk.toml"), "-o", str(csv))
    cli_page = tmp_path / "cli.html"
    run_cli("view", str(csv), "-o", str(cli_page))
    assert len(cli_page.read_text()) > 0
    assert eulerdyn.view(csv, tmp_path / "again.html")["rows_drawn"] == drawn["rows_drawn"]


def test_a_logspace_sweep_warns_that_it_takes_end_values():
    base = {"body": {"mass": 1.0, "inertia": [1.0, 2.0, 3.0]}, "initial": {"omega": [0.0, 0.0, 1.0]},
            "solver": {"t_end": 0.1}, "output": {"every": 0.05}}
    with pytest.warns(UserWarning, match="geomspace"):
        eulerdyn.sweep({"scene": base, "vary": [{"key": "initial.omega.2", "logspace": [2.0, 8.0, 3]}]})
