//! `eulerdyn plot`: the SVG it writes from a run's CSV (well formed, every panel with its title, axis labels with
//! units and legend in symbols, no NaN), the grid of panels, `--panels`, `--size`, `--title`, PNG output, the
//! panels of fixed-axis and gravity runs, and the clear errors on a CSV or an option it cannot use.

use std::path::{Path, PathBuf};

use crate::common::{dir_entries, eulerdyn, repo_path, write_file};
use crate::events::pendulum;

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

/// The SVG's drawing size: its viewBox's width and height (its units; the figure's pixels are `width`, `height`).
fn view_box(svg: &str) -> (f64, f64) {
    let numbers: Vec<f64> = attributes(svg, "viewBox")[0]
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect();
    (numbers[2], numbers[3])
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
    let (width, height) = view_box(svg);
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
    "Moment of momentum H, body axes",
    "Moment of momentum H, space axes",
    "Moment M about the moment center",
    "Angular velocity ω",
    "Kinetic energy T",
    "Drift of |H| and T since t = 0",
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
    let texts = texts(&svg);
    for legend in [
        "H_b,x",
        "H_s,z",
        "M_b,x",
        "M_s,y",
        "ω_b,z",
        "ω_s,x",
        "|H|",
        "T",
        "|H|: relative",
        "T: relative",
    ] {
        assert!(texts.contains(&legend), "no legend entry {legend:?}");
    }
    // Symbols, not column names.
    for column in ["H_b_x", "omega_b_z", "M_s_y", "energy", "H_norm"] {
        assert!(!texts.contains(&column), "{column} in {texts:?}");
    }
    // The disk's |H| and energy are constant: their drift is exactly 0 at most rows, drawn at the floor and said so.
    assert!(svg.contains("is drawn at 1e-17"), "no floor note");
    // The figure names the run it shows, from the sidecar.
    assert!(svg.contains("tilted-disk: dop853"), "no subtitle");
    assert_eq!(
        dir_entries(dir.path()),
        ["disk.csv", "disk.csv.meta.json", "disk.svg"]
    );
}

/// The curves (polylines of more than 10 points, stroke width 2 px: 8 drawing units) drawn in `color`
/// (`#D62728`), in drawing order, as drawing coordinates (4 a pixel).
fn curves(svg: &str, color: &str) -> Vec<Vec<(f64, f64)>> {
    let key = format!("stroke=\"{color}\" stroke-width=\"8\" points=\"");
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

/// The text of every `<text>` element, trimmed.
fn texts(svg: &str) -> Vec<&str> {
    svg.split("<text")
        .skip(1)
        .filter_map(|t| Some(t[t.find('>')? + 1..t.find("</text>")?].trim()))
        .collect()
}

/// The (x, y) of the `<text>` element whose text is `content`.
fn text_position(svg: &str, content: &str) -> Option<(f64, f64)> {
    svg.split("<text").skip(1).find_map(|t| {
        let (attrs, rest) = t.split_once('>')?;
        if rest[..rest.find("</text>")?].trim() != content {
            return None;
        }
        let tag = format!("<text{attrs}>");
        Some((
            attributes(&tag, "x")[0].parse().ok()?,
            attributes(&tag, "y")[0].parse().ok()?,
        ))
    })
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
    // In space, H turns about z: its x and y components swing (±0.195 of a 1.1 kg·m²/s axis: ~40 px), z stays put.
    assert!(y_spread(&x[1]) > 100.0, "H_s_x: {}", y_spread(&x[1]));
    assert!(y_spread(&y[1]) > 100.0, "H_s_y: {}", y_spread(&y[1]));
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

/// The six panels every run has.
const SIX: &str = "h_body,h_space,moment,omega,energy,drift";

/// Plots `csv` with `args` after `-o out` and returns the SVG text (expects exit 0).
fn plot_svg(csv: &Path, out: &Path, args: &[&str]) -> String {
    let mut all = vec!["plot", text(csv), "-o", text(out)];
    all.extend(args);
    eulerdyn(&all).expect_code(0);
    std::fs::read_to_string(out).unwrap()
}

#[test]
fn panels_are_laid_out_in_a_grid_of_two_columns_sixteen_centimetres_wide() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tilted_disk", "disk", &["--t-end", "0.5"]);
    // The six panels every run has (the disk's default adds θ and the support).
    let svg = plot_svg(&csv, &dir.path().join("disk.svg"), &["--panels", SIX]);
    check_svg(&svg);
    // 16 cm at 96 px per inch: 605 px; three rows of 7 cm and the 0.9 cm title: 21.9 cm = 828 px.
    assert_eq!(attributes(&svg, "width")[0], "605");
    assert_eq!(attributes(&svg, "height")[0], "828");
    let at = |title: &str| text_position(&svg, title).unwrap_or_else(|| panic!("no {title:?}"));
    let [h_body, h_space, moment, omega, energy, drift] = PANEL_TITLES.map(at);
    // Row by row, two columns: the left titles centred in the left half, the right ones in the right half.
    let (view_width, _) = view_box(&svg);
    for (left, right) in [(h_body, h_space), (moment, omega), (energy, drift)] {
        assert_eq!(left.1, right.1, "one row");
        assert!(left.0 < 0.5 * view_width && right.0 > 0.5 * view_width);
        assert!((right.0 - left.0 - 0.5 * view_width).abs() < 0.05 * view_width);
    }
    assert!(h_body.1 < moment.1 && moment.1 < energy.1, "three rows");
    assert_eq!((h_body.0, moment.0), (moment.0, energy.0), "one column");
    // Two panels: one column.
    let two = plot_svg(
        &csv,
        &dir.path().join("two.svg"),
        &["--panels", "h_body,h_space"],
    );
    let (a, b) = (
        text_position(&two, PANEL_TITLES[0]).unwrap(),
        text_position(&two, PANEL_TITLES[1]).unwrap(),
    );
    assert!(a.0 == b.0 && a.1 < b.1, "{a:?} {b:?}");
}

#[test]
fn every_text_is_at_least_nine_points_in_a_sixteen_centimetre_figure() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tilted_disk", "disk", &["--t-end", "0.5"]);
    let svg = plot_svg(&csv, &dir.path().join("disk.svg"), &["--size", "16,20"]);
    // The figure is 16 cm = 16 / 2.54 in = 604.7 px of 1/96 in; 9 pt = 9/72 in = 12 px, 1.98 % of the width.
    let width_px: f64 = attributes(&svg, "width")[0].parse().unwrap();
    assert_eq!(width_px, (16.0f64 / 2.54 * 96.0).round());
    let (view_width, _) = view_box(&svg);
    let sizes = attributes(&svg, "font-size");
    assert!(
        sizes.len() > 50,
        "tick labels, titles, legends: {}",
        sizes.len()
    );
    for size in sizes {
        let in_px = size.parse::<f64>().unwrap() * width_px / view_width;
        let in_points = in_px * 72.0 / 96.0;
        assert!(in_points >= 9.0, "a text at {in_points} pt");
        assert!(in_px / width_px >= 12.0 / 604.72 - 1e-9);
    }
}

#[test]
fn size_and_title_are_honoured() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tilted_disk", "disk", &["--t-end", "0.5"]);
    let out = dir.path().join("disk.svg");
    // The six panels every run has (the disk's default adds θ and the support).
    let svg = plot_svg(
        &csv,
        &out,
        &[
            "--panels",
            SIX,
            "--size",
            "24,18",
            "--title",
            "The tilted disk",
        ],
    );
    check_svg(&svg);
    // 24 cm and 18 cm at 96 px per inch.
    assert_eq!(attributes(&svg, "width")[0], "907");
    assert_eq!(attributes(&svg, "height")[0], "680");
    let texts = texts(&svg);
    assert!(texts.contains(&"The tilted disk"), "{texts:?}");
    assert!(
        !svg.contains("tilted-disk: dop853"),
        "the default title is replaced"
    );
    let untitled = plot_svg(&csv, &out, &["--title", "", "--panels", "omega"]);
    assert!(!untitled.contains("dop853"), "no title");
    // One panel, no title band: 6 cm.
    assert_eq!(attributes(&untitled, "height")[0], "227");
}

#[test]
fn bad_sizes_titles_and_resolutions_are_refused_naming_the_flag() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tilted_disk", "disk", &["--t-end", "0.1"]);
    let svg = dir.path().join("x.svg");
    for (args, flag, says) in [
        (vec!["--size", "16"], "--size", "W,H"),
        (vec!["--size", "16x12"], "--size", "W,H"),
        (vec!["--size", "abc,12"], "--size", "not a number"),
        (vec!["--size", "0,12"], "--size", "out of range"),
        (vec!["--size", "16,-3"], "--size", "out of range"),
        (vec!["--size", "10,10"], "--size", "at least 12,14.4"),
        (vec!["--title", "two\nlines"], "--title", "one line"),
        (vec!["--dpi", "300"], "--dpi", "only a PNG"),
    ] {
        // The six panels every run has (the disk's default adds θ and the support).
        let mut all = vec!["plot", text(&csv), "-o", text(&svg), "--panels", SIX];
        all.extend(&args);
        let out = eulerdyn(&all);
        out.expect_code(2);
        assert!(!out.panicked(), "{}", out.stderr);
        assert!(
            out.stderr.contains(flag) && out.stderr.contains(says),
            "{args:?}: {}",
            out.stderr
        );
        assert!(!svg.exists(), "{args:?} wrote a figure");
    }
    let png = dir.path().join("x.png");
    let out = eulerdyn(["plot", text(&csv), "-o", text(&png), "--dpi", "0"]);
    out.expect_code(2);
    assert!(out.stderr.contains("--dpi"), "{}", out.stderr);
    assert!(!png.exists());
}

/// The width and height in a PNG's IHDR chunk.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"), "not a PNG");
    assert_eq!(&bytes[12..16], b"IHDR");
    let be = |b: &[u8]| u32::from_be_bytes([b[0], b[1], b[2], b[3]]);
    (be(&bytes[16..20]), be(&bytes[20..24]))
}

#[test]
fn a_png_is_written_at_the_requested_size_and_resolution() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tilted_disk", "disk", &["--t-end", "0.5"]);
    let png = dir.path().join("disk.png");
    let out = eulerdyn([
        "plot",
        text(&csv),
        "-o",
        text(&png),
        "--size",
        "16,10",
        "--panels",
        "h_space,omega",
    ]);
    out.expect_code(0);
    // 300 dpi by default: 16 cm = 1890 px, 10 cm = 1181 px.
    assert_eq!(png_size(&std::fs::read(&png).unwrap()), (1890, 1181));
    assert!(out.stderr.contains("1890 x 1181 px"), "{}", out.stderr);
    let upper = dir.path().join("DISK.PNG");
    eulerdyn([
        "plot",
        text(&csv),
        "-o",
        text(&upper),
        "--size",
        "16,10",
        "--dpi",
        "96",
        "--panels",
        "h_space,omega",
    ])
    .expect_code(0);
    let bytes = std::fs::read(&upper).unwrap();
    assert_eq!(png_size(&bytes), (605, 378));
    // Not blank: a 605 x 378 white image compresses to far less.
    assert!(bytes.len() > 20_000, "{} bytes", bytes.len());
}

#[test]
fn theta_support_and_bearing_panels_are_drawn_for_a_hinge_with_bearings() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "motor_runup", "motor", &["--t-end", "2"]);
    let svg = plot_svg(
        &csv,
        &dir.path().join("motor.svg"),
        &["--panels", "omega,theta,support,bearings"],
    );
    check_svg(&svg);
    let texts = texts(&svg);
    for expected in [
        "Angle θ turned about the fixed axis",
        "θ (rad)",
        "θ",
        "Support force F_sup, space axes",
        "F_sup,x",
        "|F_sup|",
        "Bearing forces on the body, body axes",
        "R_A,x",
        "R_B,z",
        "|R_A|",
        "|R_B|",
    ] {
        assert!(texts.contains(&expected), "no {expected:?}");
    }
    // The second set of each panel (space axes, bearing B, |R_B|) carries markers, so that it shows where it
    // covers the first: open circles in the components' colours, open squares for the magnitudes.
    for color in ["#D62728", "#2CA02C", "#1F77B4"] {
        let marks = svg
            .split("<circle")
            .skip(1)
            .filter(|c| c.contains(&format!("stroke=\"{color}\"")))
            .count();
        assert!(marks >= 2 * 10, "{color}: {marks} circles");
    }
    let squares = svg.matches("stroke=\"#555555\" stroke-width=\"6\"").count();
    assert!(squares > 20, "{squares} square markers");
}

#[test]
fn a_free_run_has_no_theta_and_the_refusal_says_which_runs_do() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tennis_racket", "racket", &["--t-end", "1"]);
    let svg = dir.path().join("r.svg");
    for panel in ["theta", "support"] {
        let out = eulerdyn(["plot", text(&csv), "-o", text(&svg), "--panels", panel]);
        out.expect_code(2);
        assert!(
            out.stderr.contains(&format!("needed by {panel}"))
                && out
                    .stderr
                    .contains("only fixed_axis and hinge runs have them"),
            "{}",
            out.stderr
        );
        assert!(!svg.exists());
    }
}

#[test]
fn a_gravity_run_shows_t_v_and_t_plus_v_and_the_drift_of_its_invariants_only() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "heavy_top", "top", &["--t-end", "1"]);
    let svg = plot_svg(
        &csv,
        &dir.path().join("top.svg"),
        &["--panels", "energy,drift"],
    );
    check_svg(&svg);
    let texts = texts(&svg);
    // T + V and, gravity being vertical and its moment about the pivot horizontal, H_s,z.
    for expected in [
        "T",
        "V",
        "T + V",
        "T + V: relative",
        "H_s,z: relative",
        "Drift of T + V and H_s,z since t = 0",
    ] {
        assert!(texts.contains(&expected), "no {expected:?} in {texts:?}");
    }
    // Under gravity neither T nor |H| is an invariant: their drift is not drawn.
    for absent in ["T: relative", "|H|: relative"] {
        assert!(!texts.contains(&absent), "{absent}");
    }
    // Without a potential, the energy panel is T alone.
    let disk = run_scenario(dir.path(), "tilted_disk", "disk", &["--t-end", "0.2"]);
    let svg = plot_svg(&disk, &dir.path().join("disk.svg"), &["--panels", "energy"]);
    let texts = self::texts(&svg);
    assert!(
        texts.contains(&"T") && !texts.contains(&"T + V"),
        "{texts:?}"
    );
}

#[test]
fn a_scene_with_a_torque_has_no_invariant_to_draw() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "motor_runup", "motor", &["--t-end", "1"]);
    let svg = plot_svg(&csv, &dir.path().join("m.svg"), &["--panels", "drift"]);
    check_svg(&svg);
    let texts = texts(&svg);
    assert!(
        texts.contains(&"this scene has no invariant among |H|, T and T + V"),
        "{texts:?}"
    );
    assert!(
        !texts.iter().any(|t| t.ends_with(": relative")),
        "{texts:?}"
    );
}

/// The words of a command line, double quotes grouping (`--title "Tilted disk"`).
fn words(line: &str) -> Vec<String> {
    let mut words = Vec::new();
    for (k, part) in line.split('"').enumerate() {
        if k % 2 == 1 {
            words.push(part.to_string());
        } else {
            words.extend(part.split_whitespace().map(str::to_string));
        }
    }
    words
}

#[test]
fn the_examples_of_plot_help_that_plot_disk_csv_work() {
    let help = eulerdyn(["plot", "--help"]).stdout;
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "tilted_disk", "disk", &["--t-end", "0.5"]);
    let mut tried = 0;
    for line in help.lines().map(str::trim) {
        let Some(rest) = line.strip_prefix("eulerdyn plot disk.csv ") else {
            continue;
        };
        // The command ends where a comment, three spaces or more, begins.
        let command = rest.split("   ").next().unwrap();
        let mut args = vec!["plot".to_string(), text(&csv).to_string()];
        for word in words(command) {
            args.push(match word.strip_prefix("disk") {
                Some(_) => text(&dir.path().join(&word)).to_string(),
                None => word,
            });
        }
        eulerdyn(&args).expect_code(0);
        tried += 1;
    }
    assert!(tried >= 3, "{tried} examples in: {help}");
    assert!(png_size(&std::fs::read(dir.path().join("disk.png")).unwrap()).0 == 1890);
}

#[test]
fn by_default_a_run_gets_the_panels_it_has() {
    let dir = tempfile::tempdir().unwrap();
    let axis_titles = [
        "Angle θ turned about the fixed axis",
        "Support force F_sup, space axes",
        "Bearing forces on the body, body axes",
    ];
    // A hinge with bearings: the six panels every run has, then θ, the support and the bearings.
    let motor = run_scenario(dir.path(), "motor_runup", "motor", &["--t-end", "1"]);
    let out = eulerdyn(["plot", text(&motor), "-o", text(&dir.path().join("m.svg"))]);
    out.expect_code(0);
    assert!(
        out.stderr.contains(
            "panels h_body, h_space, moment, omega, energy, drift, theta, support, bearings;"
        ),
        "{}",
        out.stderr
    );
    let svg = std::fs::read_to_string(dir.path().join("m.svg")).unwrap();
    check_svg(&svg);
    // (Its energy and drift panels are titled for a driven, damped run; the wrote line above lists them.)
    for title in PANEL_TITLES[..4].iter().chain(&axis_titles) {
        assert!(svg.contains(title), "no panel {title:?}");
    }
    // A fixed axis without bearings: θ and the support, no bearings.
    let disk = run_scenario(dir.path(), "tilted_disk", "disk", &["--t-end", "0.5"]);
    let out = eulerdyn(["plot", text(&disk), "-o", text(&dir.path().join("d.svg"))]);
    out.expect_code(0);
    assert!(
        out.stderr
            .contains("panels h_body, h_space, moment, omega, energy, drift, theta, support;"),
        "{}",
        out.stderr
    );
    // A free run: the six free-body panels only.
    let racket = run_scenario(dir.path(), "tennis_racket", "racket", &["--t-end", "1"]);
    let svg = plot_svg(&racket, &dir.path().join("r.svg"), &[]);
    for title in PANEL_TITLES {
        assert!(svg.contains(title), "no panel {title:?}");
    }
    for title in axis_titles {
        assert!(!svg.contains(title), "a free run has no {title:?}");
    }
    // stdin to stdout: the same choice, from the header.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_eulerdyn"))
        .args(["plot", "-", "-o", "-"])
        .stdin(std::fs::File::open(&motor).unwrap())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let svg = String::from_utf8(out.stdout).unwrap();
    assert!(svg.contains(axis_titles[2]), "the bearings from stdin");
}

#[test]
fn help_says_what_the_default_panels_are() {
    let help = eulerdyn(["plot", "--help"]).stdout;
    assert!(!help.contains("[default: all]"), "{help}");
    assert!(!help.contains("(default: all)"), "{help}");
    assert!(help.contains("Default: the panels the run has"), "{help}");
}

#[test]
fn bearings_of_a_run_without_bearings_are_refused_saying_so() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("x.svg");
    for (scenario, panels) in [
        ("tilted_disk", "bearings"),
        ("tennis_racket", "omega,bearings"),
    ] {
        let csv = run_scenario(dir.path(), scenario, scenario, &["--t-end", "0.5"]);
        let out = eulerdyn(["plot", text(&csv), "-o", text(&svg), "--panels", panels]);
        out.expect_code(2);
        assert!(
            out.stderr.contains("this run has no bearings ("),
            "{}",
            out.stderr
        );
        assert!(out.stderr.contains(text(&csv)), "{}", out.stderr);
        assert!(
            !out.stderr.contains("is it a CSV written by") && !out.stderr.contains("no column"),
            "no list of missing columns: {}",
            out.stderr
        );
        assert!(!svg.exists());
    }
}

#[test]
fn a_scene_file_is_named_as_such_with_the_commands_that_plot_its_run() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(
        dir.path(),
        "spin.toml",
        std::fs::read_to_string(repo_path("scenarios/tilted_disk.toml")).unwrap(),
    );
    let svg = dir.path().join("spin.svg");
    let out = eulerdyn(["plot", text(&scene), "-o", text(&svg)]);
    out.expect_code(2);
    let scene_csv = text(&scene).replace(".toml", ".csv");
    for expected in [
        format!("{}: this is a scene file", text(&scene)),
        format!("eulerdyn run {} -o {scene_csv}", text(&scene)),
        format!("eulerdyn plot {scene_csv}"),
    ] {
        assert!(
            out.stderr.contains(&expected),
            "{expected:?} in {}",
            out.stderr
        );
    }
    assert!(!out.stderr.contains("no column"), "{}", out.stderr);
    assert!(!svg.exists());
}

/// The compound pendulum of tests/it/events.rs (a thin rod, 1 kg, 1 m, hinged at one end, released from rest at 30°)
/// for 3 s with rows every 0.05 s, with θ's downward crossings of 0 (`down`), ω_b,z's minima
/// (`fast`) and the maxima of the kinetic energy (`peak_t`) as events; run into `dir/pend.csv`.
fn pendulum_with_events(dir: &Path) -> PathBuf {
    let events = r#"[[event]]
name = "down"
when = "theta"
crosses = 0.0
direction = "down"
[[event]]
name = "fast"
when = "omega_b_z"
extremum = "min"
[[event]]
name = "peak_t"
when = "energy"
extremum = "max""#;
    let scene = write_file(dir, "pend.toml", pendulum(30.0, "dop853", 3.0, events));
    let csv = dir.join("pend.csv");
    eulerdyn(["run", text(&scene), "-o", text(&csv), "-q"]).expect_code(0);
    csv
}

/// The located events of the run whose CSV is `csv` (its events file): (event, t, value).
fn located(csv: &Path) -> Vec<(String, f64, f64)> {
    let events = std::fs::read_to_string(format!("{}.events.csv", csv.display())).unwrap();
    (events.lines().skip(1))
        .map(|l| {
            let cells: Vec<&str> = l.split(',').collect();
            (
                cells[0].into(),
                cells[1].parse().unwrap(),
                cells[2].parse().unwrap(),
            )
        })
        .collect()
}

/// The centres of the event diamonds (`<polygon>`s of 4 corners, top first) filled with `color`, in drawing units.
fn diamonds(svg: &str, color: &str) -> Vec<(f64, f64)> {
    let key = format!("fill=\"{color}\" points=\"");
    svg.match_indices(&key)
        .map(|(i, _)| {
            let rest = &svg[i + key.len()..];
            let corners: Vec<(f64, f64)> = rest[..rest.find('"').unwrap()]
                .split_whitespace()
                .map(|p| {
                    let (x, y) = p.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect();
            assert_eq!(corners.len(), 4, "{corners:?}");
            (corners[0].0, corners[1].1)
        })
        .collect()
}

/// The y of the polyline `curve` at x, linearly between its points.
fn y_at(curve: &[(f64, f64)], x: f64) -> f64 {
    let k = curve
        .windows(2)
        .position(|w| w[0].0 <= x && x <= w[1].0)
        .unwrap();
    let ((x0, y0), (x1, y1)) = (curve[k], curve[k + 1]);
    y0 + (y1 - y0) * (x - x0) / (x1 - x0)
}

#[test]
fn events_are_marked_at_their_located_time_on_the_panel_of_their_quantity() {
    let dir = tempfile::tempdir().unwrap();
    let csv = pendulum_with_events(dir.path());
    let events = located(&csv);
    let downs: Vec<f64> = (events.iter())
        .filter(|e| e.0 == "down")
        .map(|e| e.1)
        .collect();
    assert_eq!(downs.len(), 2, "{events:?}");
    // The theta panel alone: the θ crossings marked, the others (ω, T) not drawn.
    let svg = plot_svg(&csv, &dir.path().join("theta.svg"), &["--panels", "theta"]);
    check_svg(&svg);
    // A diamond at each occurrence, then one in the legend.
    let marks = diamonds(&svg, "#8C564B");
    assert_eq!(marks.len(), downs.len() + 1, "{marks:?}");
    assert_eq!(svg.matches("<polygon").count(), downs.len() + 1);
    let legend = texts(&svg);
    assert!(legend.contains(&"down"), "{legend:?}");
    assert!(
        !legend.contains(&"fast") && !legend.contains(&"peak_t"),
        "{legend:?}"
    );
    // θ's curve: rows from t = 0 to t = 3 s, so x is linear in t from its first point to its last.
    let theta = &curves(&svg, "#1F77B4")[0];
    let (x0, x1) = (theta[0].0, theta.last().unwrap().0);
    for (&(x, y), t) in marks.iter().zip(&downs) {
        // At the located time (to the drawing's unit, a quarter pixel), not at a row (every 0.05 s = 8 units).
        let expected = x0 + (x1 - x0) * t / 3.0;
        assert!(
            (x - expected).abs() <= 1.0,
            "x {x}, expected {expected} for t = {t}"
        );
        // On the curve, at θ = 0.
        assert!((y - y_at(theta, x)).abs() <= 2.0, "y {y} off the curve");
    }
    // The omega panel marks ω_b,z's minima.
    let svg = plot_svg(&csv, &dir.path().join("omega.svg"), &["--panels", "omega"]);
    let fast = (events.iter()).filter(|e| e.0 == "fast").count();
    assert_eq!(svg.matches("<polygon").count(), fast + 1);
    assert!(texts(&svg).contains(&"fast"));
    // The energy panel: T's maxima; h_body draws no quantity of an event.
    let svg = plot_svg(
        &csv,
        &dir.path().join("t.svg"),
        &["--panels", "energy,h_body"],
    );
    let peaks = (events.iter()).filter(|e| e.0 == "peak_t").count();
    assert!(peaks >= 3, "{events:?}");
    assert_eq!(svg.matches("<polygon").count(), peaks + 1);
}

#[test]
fn a_run_without_events_has_no_event_marks() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run_scenario(dir.path(), "rod_pendulum", "rod", &[]);
    let svg = plot_svg(
        &csv,
        &dir.path().join("rod.svg"),
        &["--panels", "theta,omega"],
    );
    check_svg(&svg);
    assert_eq!(svg.matches("<polygon").count(), 0);
}

#[test]
fn a_corrupt_events_file_is_refused_naming_it_and_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let csv = pendulum_with_events(dir.path());
    let events = dir.path().join("pend.csv.events.csv");
    let good = std::fs::read_to_string(&events).unwrap();
    let second_row = good.lines().nth(2).unwrap().to_string();
    for (bad, line, problem) in [
        ("t,event\n".to_string(), 1, "header"),
        (
            good.replacen(&second_row, "down,soon,0,down", 1),
            3,
            "t \"soon\"",
        ),
        (
            good.replacen(&second_row, "down,1.0,0,sideways", 1),
            3,
            "sideways",
        ),
        (good.replacen(&second_row, "down,1.0", 1), 3, "2 cells"),
    ] {
        std::fs::write(&events, bad).unwrap();
        let svg = write_file(dir.path(), "fig.svg", "precious\n");
        let out = eulerdyn(["plot", text(&csv), "-o", text(&svg)]);
        out.expect_code(2);
        assert!(!out.panicked(), "{}", out.stderr);
        assert!(
            out.stderr
                .starts_with(&format!("error: {}: line {line}: ", text(&events))),
            "{}",
            out.stderr
        );
        assert!(out.stderr.contains(problem), "{}", out.stderr);
        assert_eq!(std::fs::read(&svg).unwrap(), b"precious\n");
    }
}

/// The panels a scene's `Facts` name for its runs (`Facts::panels`, in the sidecar) are those the plot reads from
/// a run's header when there is no sidecar (`Panel::of_run`), for every bundled scenario: a CSV with its sidecar
/// and the same CSV piped in draw the same figure. The scenarios cover each kind: a free body, an axis, bearings,
/// bearings in a moving support (space axes), wheels.
#[test]
fn the_facts_name_the_panels_a_runs_header_shows_for_every_bundled_scenario() {
    use eulerdyn::panel::Panel;
    use eulerdyn::scene::{self, Overrides};
    let scenes = crate::common::bundled_scenarios();
    let mut seen = Vec::new();
    for path in &scenes {
        let scene = scene::load(path, &Overrides::default()).unwrap();
        let facts = scene.facts().clone();
        let columns: Vec<String> = (scene.facts().columns().columns().iter())
            .map(|c| c.name.to_string())
            .collect();
        let has = |c: &str| columns.iter().any(|n| n == c);
        // The wheels' names, as the plot reads them from a header: the prefixes of `<name>_spin` and `<name>_h`.
        let wheels: Vec<String> = (columns.iter())
            .filter_map(|c| c.strip_suffix("_spin"))
            .filter(|n| has(&format!("{n}_h")))
            .map(str::to_string)
            .collect();
        assert_eq!(wheels.len(), scene.spec.body.rotor.len());
        let from_header = Panel::of_run(has, facts.moving_support, &wheels);
        assert_eq!(facts.panels, from_header, "{}", path.display());
        seen.extend(facts.panels);
    }
    for kind in [
        Panel::Theta,
        Panel::Bearings,
        Panel::BearingsSpace,
        Panel::WheelSpin,
        Panel::WheelFriction,
    ] {
        assert!(
            seen.contains(&kind),
            "no bundled scenario has the {kind} panel"
        );
    }
}
