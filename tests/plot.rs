//! `eulerdyn plot`: the SVG it writes from a run's CSV (well formed, every panel with its title, axis labels with
//! units and legend, no NaN), `--panels`, and the clear errors on a CSV it cannot use.

mod common;

use std::path::{Path, PathBuf};

use common::{dir_entries, eulerdyn, repo_path, write_file};

/// A path as command-line text (temporary paths are UTF-8).
fn text(path: &Path) -> &str {
    path.to_str().expect("a UTF-8 path")
}

/// Runs a shipped scenario into `dir/name.csv` and returns the CSV path.
fn run_scenario(dir: &Path, scenario: &str, name: &str, extra: &[&str]) -> PathBuf {
    let csv = dir.join(format!("{name}.csv"));
    let scene = repo_path(&format!("scenarios/{scenario}.toml"));
    let mut args = vec!["run", text(&scene), "-o", text(&csv), "-q"];
    args.extend(extra);
    eulerdyn(&args).expect_code(0);
    csv
}

/// The values of every `name="..."` attribute of the SVG text.
fn attributes<'a>(svg: &'a str, name: &str) -> Vec<&'a str> {
    let key = format!(" {name}=\"");
    svg.match_indices(&key)
        .filter_map(|(i, _)| {
            let rest = &svg[i + key.len()..];
            rest.find('"').map(|end| &rest[..end])
        })
        .collect()
}

/// Checks that `svg` is one well-formed-looking SVG document whose coordinates are all finite numbers inside its
/// canvas; returns the number of polyline points.
fn check_svg(svg: &str) -> usize {
    assert!(svg.starts_with("<svg "), "{}", &svg[..svg.len().min(200)]);
    assert!(svg.trim_end().ends_with("</svg>"));
    assert_eq!(svg.matches("<svg").count(), 1);
    assert!(svg.contains("xmlns=\"http://www.w3.org/2000/svg\""));
    for bad in ["NaN", "nan", "inf"] {
        assert!(!svg.contains(bad), "the SVG contains {bad}");
    }
    let width: f64 = attributes(svg, "width")[0].parse().unwrap();
    let height: f64 = attributes(svg, "height")[0].parse().unwrap();
    for name in ["x", "y", "x1", "y1", "x2", "y2"] {
        for v in attributes(svg, name) {
            let v: f64 = v.parse().unwrap_or_else(|_| panic!("{name}=\"{v}\""));
            assert!(v.is_finite(), "{name} = {v}");
        }
    }
    let mut count = 0;
    for points in attributes(svg, "points") {
        for pair in points.split_whitespace() {
            let (x, y) = pair.split_once(',').expect("x,y");
            let (x, y): (f64, f64) = (x.parse().unwrap(), y.parse().unwrap());
            assert!(
                (-1.0..=width + 1.0).contains(&x) && (-1.0..=height + 1.0).contains(&y),
                "point {x},{y} outside the {width}x{height} canvas"
            );
            count += 1;
        }
    }
    count
}

const PANEL_TITLES: [&str; 6] = [
    "Moment of momentum H about the moment center, in body axes",
    "Moment of momentum H about the moment center, in space axes",
    "Moment M about the moment center",
    "Angular velocity ω",
    "Kinetic energy",
    "Change of |H| and energy since t = 0",
];

#[test]
fn every_panel_of_the_tilted_disk_is_drawn_with_title_axis_labels_and_legend() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tilted_disk", "disk", &[]);
    let svg_path = dir.path().join("disk.svg");
    let out = eulerdyn(["plot", text(&csv), "-o", text(&svg_path)]);
    out.expect_code(0);
    assert!(
        out.stdout.is_empty(),
        "data goes to the file: {}",
        out.stdout
    );
    assert!(out.stderr.contains("wrote"), "{}", out.stderr);
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    let points = check_svg(&svg);
    // 101 rows: 4 + 4 + 6 + 6 + 1 curves of 101 points, 2 drift curves of 100 points, plus legend samples.
    assert!(points >= 21 * 101 + 200, "{points}");
    for title in PANEL_TITLES {
        assert!(svg.contains(title), "no panel title {title:?}");
    }
    for label in [
        "t (s)",
        "H (kg·m²/s)",
        "M (N·m)",
        "ω (rad/s)",
        "energy (J)",
        "|x(t) − x(0)| / |x(0)|",
    ] {
        assert!(
            svg.contains(&label.replace('&', "&amp;")),
            "no axis label {label:?}"
        );
    }
    for legend in [
        "H_b_x",
        "H_s_z",
        "M_b_x body",
        "M_s_y space",
        "omega_b_z body",
        "|H|: relative",
        "energy: relative",
    ] {
        assert!(svg.contains(legend), "no legend entry {legend:?}");
    }
    // The disk's |H| and energy are constant: their drift is exactly 0 at most rows, drawn at the floor and said so.
    assert!(svg.contains("is drawn at 1e-17"), "no floor note");
    // The figure names the run it shows, from the sidecar.
    assert!(svg.contains("scene tilted-disk, dop853"), "no subtitle");
    assert_eq!(
        dir_entries(dir.path()),
        ["disk.csv", "disk.csv.meta.json", "disk.svg"]
    );
}

/// The curves (polylines of more than 10 points, stroke width 2) drawn in `color` (`#D62728`), in drawing order,
/// as pixel coordinates.
fn curves(svg: &str, color: &str) -> Vec<Vec<(f64, f64)>> {
    let key = format!("stroke=\"{color}\" stroke-width=\"2\" points=\"");
    svg.match_indices(&key)
        .filter_map(|(i, _)| {
            let rest = &svg[i + key.len()..];
            let points: Vec<(f64, f64)> = rest[..rest.find('"')?]
                .split_whitespace()
                .filter_map(|p| {
                    let (x, y) = p.split_once(',')?;
                    Some((x.parse().ok()?, y.parse().ok()?))
                })
                .collect();
            (points.len() > 10).then_some(points)
        })
        .collect()
}

/// The spread of a curve's pixel heights.
fn y_spread(points: &[(f64, f64)]) -> f64 {
    let ys = points.iter().map(|p| p.1);
    ys.clone().fold(f64::NEG_INFINITY, f64::max) - ys.fold(f64::INFINITY, f64::min)
}

#[test]
fn the_tilted_disk_shows_h_constant_in_the_body_and_turning_in_space() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tilted_disk", "disk", &[]);
    let svg_path = dir.path().join("disk_h.svg");
    eulerdyn([
        "plot",
        text(&csv),
        "-o",
        text(&svg_path),
        "--panels",
        "h_body,h_space",
    ])
    .expect_code(0);
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    check_svg(&svg);
    // x red, y green, z blue; in each color the body-axes curve is drawn first, then the space-axes one.
    let [x, y, z] = ["#D62728", "#2CA02C", "#1F77B4"].map(|c| curves(&svg, c));
    assert!(
        x.len() == 2 && y.len() == 2 && z.len() == 2,
        "{} {} {}",
        x.len(),
        y.len(),
        z.len()
    );
    for (name, body) in [("H_b_x", &x[0]), ("H_b_y", &y[0]), ("H_b_z", &z[0])] {
        assert_eq!(body.len(), 101, "{name}");
        assert_eq!(y_spread(body), 0.0, "{name} is a flat line");
    }
    // In space, H turns about z: its x and y components swing (±0.195 of a 1.1 kg·m²/s axis: ~85 px), z stays put.
    assert!(y_spread(&x[1]) > 50.0, "H_s_x: {}", y_spread(&x[1]));
    assert!(y_spread(&y[1]) > 50.0, "H_s_y: {}", y_spread(&y[1]));
    assert_eq!(y_spread(&z[1]), 0.0, "H_s_z");
}

#[test]
fn panels_chooses_the_panels_and_their_order() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tennis_racket", "racket", &["--t-end", "20"]);
    let svg_path = dir.path().join("racket.svg");
    eulerdyn([
        "plot",
        text(&csv),
        "-o",
        text(&svg_path),
        "--panels",
        "drift,omega",
    ])
    .expect_code(0);
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    check_svg(&svg);
    let drift = svg.find(PANEL_TITLES[5]).expect("the drift panel");
    let omega = svg.find(PANEL_TITLES[3]).expect("the omega panel");
    assert!(drift < omega, "drawn in the order given");
    for absent in [PANEL_TITLES[0], PANEL_TITLES[1], PANEL_TITLES[4]] {
        assert!(!svg.contains(absent), "{absent} was not asked for");
    }
    // Two panels: a shorter canvas than six.
    let height: u32 = attributes(&svg, "height")[0].parse().unwrap();
    assert!(height < 1000, "{height}");
}

#[test]
fn an_unknown_panel_is_bad_input_listing_the_panels() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tilted_disk", "disk", &["--t-end", "0.1"]);
    let out = eulerdyn([
        "plot",
        text(&csv),
        "-o",
        text(&dir.path().join("x.svg")),
        "--panels",
        "h_body,bearing",
    ]);
    out.expect_code(2);
    assert!(out.stderr.contains("--panels"), "{}", out.stderr);
    assert!(out.stderr.contains("\"bearing\""), "{}", out.stderr);
    assert!(
        out.stderr
            .contains("h_body, h_space, moment, omega, energy, drift"),
        "{}",
        out.stderr
    );
    assert!(!dir.path().join("x.svg").exists());
}

/// Plots `csv_text` (written to a file) and expects bad input; returns stderr.
fn refused(csv_text: &str, panels: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let csv = write_file(dir.path(), "bad.csv", csv_text);
    let svg = write_file(dir.path(), "fig.svg", "precious\n");
    let out = eulerdyn(["plot", text(&csv), "-o", text(&svg), "--panels", panels]);
    out.expect_code(2);
    assert!(!out.panicked(), "{}", out.stderr);
    assert!(out.stderr.starts_with("error: "), "{}", out.stderr);
    assert!(
        out.stderr.contains(text(&csv)),
        "names the file: {}",
        out.stderr
    );
    // Nothing written, the existing figure untouched.
    assert_eq!(std::fs::read(&svg).unwrap(), b"precious\n");
    assert_eq!(dir_entries(dir.path()), ["bad.csv", "fig.svg"]);
    out.stderr
}

#[test]
fn an_empty_file_is_refused() {
    let e = refused("", "all");
    assert!(e.contains("the file is empty"), "{e}");
}

#[test]
fn a_header_without_rows_is_refused() {
    let e = refused("t,energy\n", "energy");
    assert!(e.contains("no data rows"), "{e}");
}

#[test]
fn a_missing_column_is_named_with_the_panel_that_needs_it() {
    let e = refused("t,H_b_y,H_b_z,H_norm\n0,1,2,3\n", "h_body");
    assert!(e.contains("`H_b_x`"), "{e}");
    assert!(e.contains("h_body"), "{e}");
    assert!(e.contains("t,H_b_y,H_b_z,H_norm"), "shows the header: {e}");
}

#[test]
fn a_file_that_is_not_comma_separated_gets_a_hint() {
    let e = refused("t;energy\n0;1\n", "energy");
    assert!(e.contains("`t`"), "{e}");
    assert!(e.contains("separated by commas"), "{e}");
}

#[test]
fn a_cell_that_is_not_a_number_is_named_by_row_and_column() {
    let e = refused("t,energy\n0,1\n0.1,1\n0.2,abc\n", "energy");
    assert!(e.contains("row 3 (line 4)"), "{e}");
    assert!(e.contains("column `energy`"), "{e}");
    assert!(e.contains("`abc` is not a number"), "{e}");
}

#[test]
fn a_non_finite_or_empty_cell_is_refused() {
    let e = refused("t,energy\n0,1\n0.1,NaN\n", "energy");
    assert!(
        e.contains("row 2 (line 3), column `energy`: `NaN` is not a finite number"),
        "{e}"
    );
    let e = refused("t,energy\n0,\n", "energy");
    assert!(e.contains("column `energy`: is empty"), "{e}");
}

#[test]
fn a_row_of_the_wrong_length_is_refused_with_its_line() {
    let e = refused("t,energy\n0,1\n0.1,1,7\n", "energy");
    assert!(e.contains("line 3"), "{e}");
    assert!(e.contains("3 fields but the header has 2"), "{e}");
}

#[test]
fn a_missing_file_or_directory_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("none.csv");
    let out = eulerdyn([
        "plot",
        text(&missing),
        "-o",
        text(&dir.path().join("x.svg")),
    ]);
    out.expect_code(2);
    assert!(
        out.stderr.contains("none.csv: cannot read"),
        "{}",
        out.stderr
    );
    let out = eulerdyn([
        "plot",
        text(dir.path()),
        "-o",
        text(&dir.path().join("x.svg")),
    ]);
    out.expect_code(2);
    assert!(out.stderr.contains("is a directory"), "{}", out.stderr);
}

#[test]
fn a_missing_output_directory_or_the_csv_itself_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tilted_disk", "disk", &["--t-end", "0.1"]);
    let out = eulerdyn([
        "plot",
        text(&csv),
        "-o",
        text(&dir.path().join("no/such/dir/x.svg")),
    ]);
    out.expect_code(2);
    assert!(out.stderr.contains("x.svg"), "{}", out.stderr);
    assert!(out.stderr.contains("does not exist"), "{}", out.stderr);
    let before = std::fs::read(&csv).unwrap();
    let out = eulerdyn(["plot", text(&csv), "-o", text(&csv)]);
    out.expect_code(2);
    assert!(out.stderr.contains("overwrite the CSV"), "{}", out.stderr);
    assert_eq!(std::fs::read(&csv).unwrap(), before);
}

#[test]
fn columns_are_found_by_name_in_any_order_and_extra_columns_are_ignored() {
    // As pandas writes it back with an index column, columns reordered, spaces after commas.
    let csv_text = "\
,energy, H_norm,t,note
0,2.0,1.0,0.0,3
1,2.0,1.0,0.5,3
2,2.0000000001,1.0,1.0,3
";
    let dir = tempfile::tempdir().unwrap();
    let csv = write_file(dir.path(), "pandas.csv", csv_text);
    let svg_path = dir.path().join("fig.svg");
    eulerdyn([
        "plot",
        text(&csv),
        "-o",
        text(&svg_path),
        "--panels",
        "energy,drift",
    ])
    .expect_code(0);
    let svg = std::fs::read_to_string(svg_path).unwrap();
    check_svg(&svg);
    assert!(
        svg.contains("pandas.csv: 3 rows"),
        "no sidecar: the file name only"
    );
}

#[test]
fn a_single_row_plots_without_nan() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "asymmetric_free", "one", &["--t-end", "0"]);
    let svg_path = dir.path().join("one.svg");
    eulerdyn(["plot", text(&csv), "-o", text(&svg_path)]).expect_code(0);
    check_svg(&std::fs::read_to_string(svg_path).unwrap());
}

#[test]
fn the_csv_can_come_from_stdin_and_the_svg_go_to_stdout() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tilted_disk", "disk", &["--t-end", "0.2"]);
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_eulerdyn"))
        .args(["plot", "-", "-o", "-", "--panels", "h_space"])
        .stdin(std::fs::File::open(&csv).unwrap())
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = String::from_utf8(out.stdout).unwrap();
    check_svg(&svg);
    assert!(svg.contains("stdin: 21 rows"));
    assert!(svg.contains(PANEL_TITLES[1]));
}

#[test]
fn a_long_run_is_reduced_to_a_bounded_number_of_points_keeping_its_extremes() {
    let mut csv_text = String::from("t,energy\n");
    let n = 200_000;
    for k in 0..n {
        let t = k as f64 * 1e-3;
        let e = if k == 123_457 {
            9.0
        } else {
            1.0 + 0.1 * t.sin()
        };
        csv_text.push_str(&format!("{t},{e}\n"));
    }
    let dir = tempfile::tempdir().unwrap();
    let csv = write_file(dir.path(), "long.csv", csv_text);
    let svg_path = dir.path().join("long.svg");
    eulerdyn([
        "plot",
        text(&csv),
        "-o",
        text(&svg_path),
        "--panels",
        "energy",
    ])
    .expect_code(0);
    let svg = std::fs::read_to_string(svg_path).unwrap();
    let points = check_svg(&svg);
    assert!(points <= 4096 + 2 + 10, "{points} points");
    // The spike sets the top of the axis: a tick label above 8 exists.
    assert!(
        svg.contains(">\n9\n<") || svg.contains(">\n8\n<"),
        "the spike survives"
    );
}
