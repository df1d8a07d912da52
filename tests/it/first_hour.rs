//! What a new user meets in the first hour (issue 38): sweep grids by end values (`geomspace`, `logspace` with its
//! warning) and a misspelt key answered with the nearest valid one; CSV inputs saved by spreadsheets (a UTF-8
//! byte-order mark, CRLF); `check`'s numbers rounded for people, a wheel's imbalance among the effects and its unit
//! slips; the default figures of a torque-free satellite (H_s flat at its value), of a carrier (bearing loads in
//! space axes), and legends that fit their panels.

use std::path::{Path, PathBuf};

use crate::common::{FREE_SCENE, eulerdyn, repo_path, write_file};

fn text(path: &Path) -> &str {
    path.to_str().expect("a UTF-8 path")
}

/// Runs `eulerdyn sweep` on a sweep over [`FREE_SCENE`] varying `initial.omega.2` as `way`; the results' first
/// column (the varied values, as the table writes them) and stderr.
fn sweep_values(way: &str) -> (Vec<f64>, String) {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "base.toml", FREE_SCENE);
    let sweep = write_file(
        dir.path(),
        "sweep.toml",
        format!("scene = \"base.toml\"\n[[vary]]\nkey = \"initial.omega.2\"\n{way}\n"),
    );
    let out = dir.path().join("results.csv");
    let outcome = eulerdyn(["sweep", text(&sweep), "-o", text(&out)]);
    outcome.expect_code(0);
    let table = std::fs::read_to_string(&out).unwrap();
    let values = (table.lines().skip(1))
        .map(|l| l.split(',').nth(1).unwrap().parse().unwrap())
        .collect();
    (values, outcome.stderr)
}

#[test]
fn geomspace_and_logspace_take_end_values_and_logspace_warns_so() {
    // numpy.geomspace(2, 8, 3) = [2, 4, 8]: the end values themselves, ratio (8/2)^(1/2) = 2.
    let (geom, quiet) = sweep_values("geomspace = [2.0, 8.0, 3]");
    assert_eq!(geom, [2.0, 4.0, 8.0]);
    assert!(!quiet.contains("warning"), "{quiet}");
    let (log, warned) = sweep_values("logspace = [2.0, 8.0, 3]");
    assert_eq!(log, geom);
    assert!(
        warned.contains("sweep.toml: warning: vary[0].logspace"),
        "{warned}"
    );
    assert!(warned.contains("geomspace = [2, 8, 3]"), "{warned}");
    assert!(warned.contains("not from 10^2 to 10^8"), "{warned}");
}

#[test]
fn a_misspelt_sweep_key_names_the_nearest_valid_key() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "base.toml", FREE_SCENE);
    for (key, nearest) in [
        ("initiall.omega.2", "initial.omega.2"),
        ("effects.0.c", "effect.0.c"),
        ("body.masss", "body.mass"),
    ] {
        let sweep = write_file(
            dir.path(),
            "sweep.toml",
            format!("scene = \"base.toml\"\n[[vary]]\nkey = \"{key}\"\nvalues = [1.0]\n"),
        );
        let outcome = eulerdyn(["sweep", text(&sweep)]);
        outcome.expect_code(2);
        let expected = format!("the nearest valid key is `{nearest}`");
        assert!(
            outcome.stderr.contains(&expected),
            "{key}: {}",
            outcome.stderr
        );
        assert!(outcome.stderr.contains("vary[0].key"), "{}", outcome.stderr);
        assert!(!outcome.stderr.contains("does not give this array"));
    }
}

/// A torque table's text as a spreadsheet saves it: a UTF-8 byte-order mark and CRLF line ends.
fn spreadsheet(text: &str) -> String {
    format!("\u{feff}{}", text.replace('\n', "\r\n"))
}

#[test]
fn a_torque_table_with_a_byte_order_mark_and_crlf_runs_as_the_plain_one() {
    let dir = tempfile::tempdir().unwrap();
    let table = "t,M_x,M_y,M_z\n0,0.1,0,0\n1,0.2,0,0.05\n2,0,0,0\n";
    write_file(dir.path(), "plain.csv", table);
    write_file(dir.path(), "saved.csv", spreadsheet(table).as_bytes());
    let scene = |file: &str| {
        format!(
            "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n\n[[effect]]\ntype = \"torque_table\"\n\
             file = \"{file}\"\n\n[solver]\nt_end = 2.0\n\n[output]\nevery = 0.25\n"
        )
    };
    let mut csvs = Vec::new();
    for name in ["plain", "saved"] {
        let path = write_file(
            dir.path(),
            &format!("{name}.toml"),
            scene(&format!("{name}.csv")),
        );
        eulerdyn(["check", text(&path)]).expect_code(0);
        let out = eulerdyn(["run", text(&path), "-q"]);
        out.expect_code(0);
        csvs.push(out.stdout);
    }
    assert_eq!(csvs[0], csvs[1]);
}

#[test]
fn the_phasor_reader_takes_a_byte_order_mark_and_crlf() {
    use eulerdyn::analysis::balance::table;
    let plain = std::fs::read_to_string(repo_path("scenarios/fan_rotor_measured.csv")).unwrap();
    let path = Path::new("measured.csv");
    let read = table::parse(path, &plain).unwrap();
    assert_eq!(table::parse(path, &spreadsheet(&plain)).unwrap(), read);
}

/// A free body with one wheel of J = 0.06 kg·m² whose static imbalance is `u_gmm` g·mm.
fn wheel_scene(dir: &Path, u_gmm: &str) -> PathBuf {
    write_file(
        dir,
        "wheel.toml",
        format!(
            "[body]\nmass = 10.0\ninertia = [1.0, 1.0, 2.0]\n\n[[body.rotor]]\nname = \"wheel\"\n\
             axis = [0.0, 0.0, 1.0]\ninertia = 0.06\nspin = 100.0\nimbalance_static_gmm = {u_gmm}\n\n\
             [solver]\nt_end = 0.1\n\n[output]\nevery = 0.05\n"
        ),
    )
}

#[test]
fn check_rounds_for_people_and_lists_the_imbalance_among_the_effects() {
    let dir = tempfile::tempdir().unwrap();
    let out = eulerdyn(["check", text(&wheel_scene(dir.path(), "20.0"))]);
    out.expect_code(0);
    // 20 g·mm = 2e-5 kg·m, computed as 20 × 1e-6 = 1.9999999999999998e-5 and printed rounded.
    assert!(out.stdout.contains("static 2e-05 kg*m"), "{}", out.stdout);
    assert!(!out.stdout.contains("0.0000199999"), "{}", out.stdout);
    let effects = out
        .stdout
        .lines()
        .find(|l| l.starts_with("effects"))
        .unwrap();
    assert!(effects.contains("imbalance of rotor wheel"), "{effects}");
    assert!(!out.stdout.contains("warning"), "{}", out.stdout);
}

#[test]
fn an_imbalance_no_wheel_could_have_is_warned_of_as_a_unit_slip() {
    let dir = tempfile::tempdir().unwrap();
    // 20 kg·m written as g·mm: above sqrt(J·m) = sqrt(0.06 × 10) kg·m = 7.7e5 g·mm, the wheel's whole mass at its
    // radius of gyration.
    let big = eulerdyn(["check", text(&wheel_scene(dir.path(), "2e7"))]);
    big.expect_code(0);
    assert!(
        big.stdout.contains("is more than a wheel of J = 0.06"),
        "{}",
        big.stdout
    );
    // 2e-5 kg·m written in the g·mm key: 10⁶ × too small, finer than any balancing grade.
    let small = eulerdyn(["check", text(&wheel_scene(dir.path(), "2e-5"))]);
    small.expect_code(0);
    assert!(
        small.stdout.contains("finer than any balancing grade"),
        "{}",
        small.stdout
    );
    assert!(small.stdout.contains("that is 20 g*mm"), "{}", small.stdout);
}

/// Runs the scenario and plots it with the default panels; the SVG text.
fn default_figure(dir: &Path, scenario: &str) -> String {
    let csv = dir.join("run.csv");
    let scene = repo_path(&format!("scenarios/{scenario}.toml"));
    eulerdyn(["run", text(&scene), "-o", text(&csv), "-q"]).expect_code(0);
    let svg = dir.join("run.svg");
    eulerdyn(["plot", text(&csv), "-o", text(&svg)]).expect_code(0);
    std::fs::read_to_string(svg).unwrap()
}

/// The text of every `<text>` element, trimmed, with its x and y.
fn texts(svg: &str) -> Vec<(f64, f64, String)> {
    let number = |tag: &str, name: &str| -> f64 {
        let key = format!(" {name}=\"");
        let rest = &tag[tag.find(&key).unwrap() + key.len()..];
        rest[..rest.find('"').unwrap()].parse().unwrap()
    };
    svg.split("<text")
        .skip(1)
        .map(|t| {
            let (tag, rest) = t.split_once('>').unwrap();
            let content = rest[..rest.find("</text>").unwrap()].trim().to_string();
            (number(tag, "x"), number(tag, "y"), content)
        })
        .collect()
}

#[test]
fn a_torque_free_satellite_draws_h_s_flat_at_its_value() {
    let dir = tempfile::tempdir().unwrap();
    let svg = default_figure(dir.path(), "satellite_wheels");
    let all = texts(&svg);
    let notes: Vec<&String> = (all.iter().map(|t| &t.2))
        .filter(|t| t.starts_with("constant to round-off"))
        .collect();
    // Both H panels: H_s = 0 (the scene's description: nothing outside acts, the body starts at rest) and so H_b.
    assert_eq!(notes.len(), 2, "{notes:?}");
    for label in [
        "H_s,x = 0",
        "H_s,y = 0",
        "H_s,z = 0",
        "H_b,x = 0",
        "|H| = 0",
    ] {
        assert!(all.iter().any(|t| t.2 == label), "{label}");
    }
    // The H_s panel's y ticks are those of a flat line at 0 (the range ±1 around it), not round-off magnified into
    // ticks of 1e-17.
    let title = all
        .iter()
        .position(|t| t.2 == "Moment of momentum H, space axes")
        .unwrap();
    let ticks: Vec<&str> = all[title..title + 16]
        .iter()
        .map(|t| t.2.as_str())
        .collect();
    assert!(
        ticks.iter().any(|t| ["1", "0.5", "-0.5", "-1"].contains(t)),
        "{ticks:?}"
    );
    assert!(!ticks.iter().any(|t| t.contains("e-")), "{ticks:?}");
}

#[test]
fn a_carrier_run_draws_its_bearing_loads_in_space_axes_by_default() {
    let dir = tempfile::tempdir().unwrap();
    let svg = default_figure(dir.path(), "turbine_yawing_aircraft");
    let titles: Vec<String> = texts(&svg).into_iter().map(|t| t.2).collect();
    assert!(titles.contains(&"Bearing forces on the body, space axes".to_string()));
    assert!(!titles.contains(&"Bearing forces on the body, body axes".to_string()));
}

#[test]
fn legends_fit_their_panels() {
    // A body at rest has T(0) = 0 and |H|(0) = 0: the drift legend's longest labels ("|H|: absolute (kg·m²/s), as
    // |H|(0) = 0"). Each legend text must end inside its panel: at most 0.6 of the 12 px size per character (the
    // estimate the layout uses), in drawing units of 4 per pixel.
    let dir = tempfile::tempdir().unwrap();
    let svg = default_figure(dir.path(), "satellite_wheels");
    let width: f64 = 4.0 * 605.0;
    let half = width / 2.0;
    let left_anchored = svg.split("<text").skip(1).map(|t| {
        let tag = &t[..t.find('>').unwrap()];
        !tag.contains("text-anchor") || tag.contains("text-anchor=\"start\"")
    });
    for ((x, _, content), left) in texts(&svg).into_iter().zip(left_anchored) {
        if !left {
            continue;
        }
        let chars = content.chars().count() as f64;
        let right = x + 4.0 * 0.56 * 12.0 * chars;
        let edge = if x < half { half } else { width };
        assert!(
            right <= edge,
            "{content:?} at x = {x} ends at {right} > {edge}"
        );
    }
}
