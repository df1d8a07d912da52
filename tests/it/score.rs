//! `eulerdyn score` and `eulerdyn suite`: trajectories whose errors the test knows, scored by the referee, and
//! every bad input refused with exit 2, naming the file, row and column, writing nothing.

use std::path::{Path, PathBuf};

use nalgebra::{UnitQuaternion, Vector3};

use crate::common::{dir_entries, eulerdyn, scene_from, write_file};
use eulerdyn::analysis::score::{self, ReadOptions, suite};
use eulerdyn::exact::TorqueFreeBody;
use eulerdyn::scene::Overrides;

/// A torque-free asymmetric body (I = 1, 2, 3: body axes principal), t_end = 5 s.
const FREE: &str = r#"name = "free"

[body]
mass = 1.0
inertia = [1.0, 2.0, 3.0]

[initial]
omega = [0.4, 0.2, 2.0]

[solver]
t_end = 5.0

[output]
every = 0.05
"#;

/// The closed form of [`FREE`] (Landau & Lifshitz §37), evaluated directly.
fn exact() -> TorqueFreeBody {
    TorqueFreeBody::new(
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(0.4, 0.2, 2.0),
        UnitQuaternion::identity(),
    )
    .unwrap()
}

/// Rows (t, q, ω_b) as a CSV with the suite's header, ω omitted when `with_omega` is false.
fn csv(rows: &[(f64, UnitQuaternion<f64>, Vector3<f64>)], with_omega: bool) -> String {
    let mut out = if with_omega {
        suite::HEADER.to_string()
    } else {
        "t,q_w,q_x,q_y,q_z".into()
    };
    out.push('\n');
    for (t, q, w) in rows {
        let q = q.quaternion();
        out.push_str(&format!("{t},{},{},{},{}", q.w, q.i, q.j, q.k));
        if with_omega {
            out.push_str(&format!(",{},{},{}", w.x, w.y, w.z));
        }
        out.push('\n');
    }
    out
}

/// Times k/60 up to `t_end`.
fn frames(t_end: f64) -> Vec<f64> {
    (0..=(t_end * 60.0).round() as usize)
        .map(|k| k as f64 / 60.0)
        .collect()
}

/// The exact rows of [`FREE`] at 60 Hz.
fn exact_rows() -> Vec<(f64, UnitQuaternion<f64>, Vector3<f64>)> {
    let e = exact();
    frames(5.0)
        .into_iter()
        .map(|t| (t, e.attitude(t), e.omega_p(t)))
        .collect()
}

fn score_text(dir: &Path, name: &str, text: &str, scene: &str) -> score::Score {
    let path = write_file(dir, name, text);
    score::score(
        &path,
        &scene_from(scene, &Overrides::default()),
        &ReadOptions::default(),
    )
    .unwrap()
}

#[test]
fn the_exact_solution_scores_round_off() {
    let dir = tempfile::tempdir().unwrap();
    let s = score_text(dir.path(), "exact.csv", &csv(&exact_rows(), true), FREE);
    // The referee is the same closed form (Landau & Lifshitz §37) stepped on the equal grid with re-anchoring,
    // within 1e-13 of the direct evaluation (core/src/exact/equal_grid.rs); 1e-12 leaves a decade for the printed
    // CSV's round trip (shortest representation: exact).
    for key in ["attitude", "omega", "energy", "h_norm", "h_direction"] {
        let m = s.metric(key).unwrap();
        assert!(m.largest < 1e-12, "{key}: {m:?}");
    }
    assert!(s.passes() && s.referee_adequate && s.reference_error.is_none());
}

#[test]
fn a_rotation_by_k_t_scores_k_t_end() {
    let dir = tempfile::tempdir().unwrap();
    let k = 0.02; // rad/s
    let axis = Vector3::new(1.0, -2.0, 0.5).normalize();
    let rows: Vec<_> = (exact_rows().into_iter())
        .map(|(t, q, w)| (t, UnitQuaternion::from_scaled_axis(axis * (k * t)) * q, w))
        .collect();
    let s = score_text(dir.path(), "turned.csv", &csv(&rows, false), FREE);
    // Turning every attitude by k·t about a fixed space axis puts it k·t from the reference (the angle of
    // a⁻¹b); 1e-12 is the closed form's round-off (above) plus that of composing the rotation.
    let m = s.metric("attitude").unwrap();
    assert!((m.largest - k * 5.0).abs() < 1e-12, "{m:?}");
    assert!((m.last - k * 5.0).abs() < 1e-12 && m.at == 5.0, "{m:?}");
    assert!(m.passes == (k * 5.0 <= score::metrics::ATTITUDE_MAX));
    assert_eq!(
        s.metrics.len(),
        1,
        "without omega only the attitude is measured"
    );
}

/// Semi-implicit Euler at step h: ω ← ω + h·I⁻¹(−ω × Iω) (Euler's equation, torque-free), then q ← q·exp(hω/2)
/// with the new ω; with `gyroscopic` false the ω × Iω term is left out (ω stays constant).
fn semi_implicit_euler(h: f64, gyroscopic: bool) -> Vec<(f64, UnitQuaternion<f64>, Vector3<f64>)> {
    let inertia = Vector3::new(1.0, 2.0, 3.0);
    let (mut q, mut w) = (UnitQuaternion::identity(), Vector3::new(0.4, 0.2, 2.0));
    let mut rows = vec![(0.0, q, w)];
    for k in 1..=(5.0 / h).round() as usize {
        if gyroscopic {
            let h_b = inertia.component_mul(&w);
            w += h * (-w.cross(&h_b)).component_div(&inertia);
        }
        q *= UnitQuaternion::from_scaled_axis(w * h);
        rows.push((k as f64 * h, q, w));
    }
    rows
}

#[test]
fn semi_implicit_euler_scores_what_the_test_computes() {
    let dir = tempfile::tempdir().unwrap();
    let rows = semi_implicit_euler(1.0 / 60.0, true);
    let s = score_text(dir.path(), "euler.csv", &csv(&rows, true), FREE);
    let e = exact();
    let energy = |w: &Vector3<f64>| 0.5 * w.dot(&Vector3::new(1.0, 2.0, 3.0).component_mul(w));
    let mut attitude: f64 = 0.0;
    let mut drift: f64 = 0.0;
    for (t, q, w) in &rows {
        attitude = attitude.max(q.angle_to(&e.attitude(*t)));
        drift = drift.max((energy(w) - e.energy()).abs() / e.energy());
    }
    // The test's own errors against the closed form, to the referee's round-off (1e-12, above) relative to
    // errors of order 1e-2.
    let m = s.metric("attitude").unwrap();
    assert!((m.largest - attitude).abs() < 1e-10, "{m:?} vs {attitude}");
    let m = s.metric("energy").unwrap();
    assert!(
        (m.largest - drift).abs() < 1e-10 * drift.max(1.0),
        "{m:?} vs {drift}"
    );
    assert!(
        attitude > 1e-3,
        "semi-implicit Euler at 60 Hz is first order: a visible error"
    );
}

#[test]
fn without_the_gyroscopic_term_h_turns_in_space_and_fails() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(dir.path(), "free.toml", FREE);
    let theirs = write_file(
        dir.path(),
        "nogyro.csv",
        csv(&semi_implicit_euler(1.0 / 60.0, false), true),
    );
    let out = eulerdyn([
        "score",
        theirs.to_str().unwrap(),
        "--scene",
        scene.to_str().unwrap(),
    ]);
    out.expect_code(1);
    let line = (out.stdout.lines())
        .find(|l| l.starts_with("H direction drift in space (rad)"))
        .unwrap_or_else(|| panic!("{}", out.stdout));
    assert!(line.ends_with("FAIL"), "{line}");
    // With ω constant H_s = R(t)·Iω turns with the body; the angle is large (order 1 rad within 5 s).
    let largest: f64 = line.split_whitespace().nth(6).unwrap().parse().unwrap();
    assert!(largest > 0.1, "{line}");
}

/// The suite's tennis racket with an event `flip`, at 600 Hz.
fn racket() -> (String, TorqueFreeBody) {
    let text = suite::SCENES[1].1.to_string();
    let e = TorqueFreeBody::new(
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(0.05, 2.0, 0.05),
        UnitQuaternion::identity(),
    )
    .unwrap();
    (text, e)
}

#[test]
fn a_time_shifted_flip_reports_the_shift() {
    let dir = tempfile::tempdir().unwrap();
    let (scene, e) = racket();
    let shift = 0.05;
    let rows: Vec<_> = (0..=12 * 600)
        .map(|k| {
            let t = k as f64 / 600.0;
            (t, e.attitude(t - shift), e.omega_p(t - shift))
        })
        .collect();
    let s = score_text(dir.path(), "late.csv", &csv(&rows, true), &scene);
    let m = s.metric("event:flip").unwrap();
    // Every flip comes `shift` late. The crossing is interpolated linearly between rows 1/600 s apart; at the
    // crossing ω_y is at its steepest (an inflection), so the interpolation error is O(h³·ω_y''') ≈ 1e-8 s.
    assert!(m.note.is_none(), "{m:?}");
    assert!(
        (m.largest - shift).abs() < 1e-6 && (m.last - shift).abs() < 1e-6,
        "{m:?}"
    );
    assert!(m.passes == (shift <= score::metrics::EVENT_TIME_MAX));
    // Each occurrence's own error (the contract's "each event time"), matched in order: every one `shift` late.
    let each = m.occurrences.as_ref().expect("an event's occurrences");
    assert!(!each.is_empty(), "{each:?}");
    for o in each {
        let (theirs, reference) = (o.their_t.unwrap(), o.reference_t.unwrap());
        assert!((theirs - reference - shift).abs() < 1e-6, "{o:?}");
        assert_eq!(o.error, Some((theirs - reference).abs()));
    }
    let largest = each.iter().filter_map(|o| o.error).fold(0.0, f64::max);
    assert_eq!(largest, m.largest);
}

#[test]
fn the_suite_s_own_references_score_at_round_off() {
    let dir = tempfile::tempdir().unwrap();
    let out = eulerdyn(["suite", "--out", dir.path().to_str().unwrap()]);
    out.expect_code(0);
    let own = dir.path().join("self");
    std::fs::create_dir(&own).unwrap();
    for (name, _) in suite::SCENES {
        std::fs::copy(
            dir.path().join(format!("{name}.csv")),
            own.join(format!("{name}.csv")),
        )
        .unwrap();
    }
    let scores = suite::score_suite(dir.path(), "self", &ReadOptions::default(), false).unwrap();
    for s in &scores {
        for m in &s.metrics {
            // The reference read back from its CSV (shortest round-trip digits): the same rows exactly, so
            // nothing beyond the round-off of recomputing H and the energy from them. An event's time is the
            // exception: theirs is located between rows 1/60 s apart by linear interpolation, whose error is
            // second order in the row spacing (measured 1.98e-7 s for the racket's flip); 1e-6 s bounds it, five
            // orders below the threshold of one frame.
            let bound = if m.key.starts_with("event:") {
                1e-6
            } else {
                1e-12
            };
            assert!(m.largest < bound, "{}: {m:?}", s.scene);
        }
    }
    let card = eulerdyn([
        "score",
        "--suite",
        dir.path().to_str().unwrap(),
        "--engine",
        "self",
    ]);
    card.expect_code(0);
    assert!(
        card.stdout.starts_with("report card: self"),
        "{}",
        card.stdout
    );
    assert_eq!(
        card.stdout.lines().filter(|l| l.ends_with("pass")).count(),
        6,
        "{}",
        card.stdout
    );
}

/// Scores `text` as their CSV with `extra` arguments and a --plot path; asserts exit 2, a message naming the file
/// and `expect`, and that nothing was written.
fn refused(text: &[u8], extra: &[&str], expect: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(dir.path(), "free.toml", FREE);
    let theirs = write_file(dir.path(), "theirs.csv", text);
    let fig = dir.path().join("fig.svg");
    let mut args: Vec<String> = [
        "score",
        theirs.to_str().unwrap(),
        "--scene",
        scene.to_str().unwrap(),
    ]
    .map(String::from)
    .to_vec();
    args.extend(["--plot".into(), fig.to_str().unwrap().into()]);
    args.extend(extra.iter().map(|s| s.to_string()));
    let out = eulerdyn(&args);
    assert_eq!(out.code, Some(2), "{}", out.stderr);
    assert!(!out.panicked());
    for e in expect {
        assert!(out.stderr.contains(e), "`{e}` in: {}", out.stderr);
    }
    assert_eq!(
        dir_entries(dir.path()),
        ["free.toml", "theirs.csv"],
        "nothing written"
    );
    out.stderr.clone()
}

/// The exact CSV of [`FREE`] with row `row` (1-based) changed by `f`.
fn with_row(row: usize, f: impl Fn(&str) -> String) -> Vec<u8> {
    let text = csv(&exact_rows(), true);
    let lines: Vec<String> = (text.lines().enumerate())
        .map(|(i, l)| if i == row { f(l) } else { l.to_string() })
        .collect();
    (lines.join("\n") + "\n").into_bytes()
}

#[test]
fn bad_input_is_refused_naming_file_row_and_column() {
    let text = csv(&exact_rows(), true);
    refused(
        text.replacen("t,", "time,", 1).as_bytes(),
        &[],
        &["theirs.csv", "no time column `t`"],
    );
    refused(
        text.replacen("q_w", "qw", 1).as_bytes(),
        &[],
        &["theirs.csv", "no attitude columns"],
    );
    refused(
        &with_row(10, |l| format!("0.1{}", &l[l.find(',').unwrap()..])),
        &[],
        &["theirs.csv", "row 10, column `t`", "does not increase"],
    );
    refused(
        &with_row(3, |l| {
            let mut cells: Vec<String> = l.split(',').map(String::from).collect();
            let w: f64 = cells[1].parse().unwrap();
            cells[1] = format!("{}", w + 1e-5);
            cells.join(",")
        }),
        &[],
        &[
            "theirs.csv",
            "row 3, column `q_w,q_x,q_y,q_z`",
            "off a unit quaternion",
        ],
    );
    let past = format!("{}5.1,1,0,0,0,0,0,2\n", text);
    refused(
        past.as_bytes(),
        &[],
        &[
            "theirs.csv",
            "row 302, column `t`",
            "past the scene's t_end = 5 (if the times are in milliseconds, give them in seconds)",
        ],
    );
    // Times in milliseconds: the first past t_end says so; a time beyond 1000 × t_end does not suggest it.
    let far = format!("{}5001,1,0,0,0,0,0,2\n", text);
    let out = refused(far.as_bytes(), &[], &["past the scene's t_end = 5"]);
    assert!(!out.contains("milliseconds"), "{out}");
    refused(
        text.as_bytes(),
        &["--map", "w=q_w"],
        &["--map w=", "not one of eulerdyn's column names"],
    );
}

#[test]
fn a_slightly_off_quaternion_is_normalised_with_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(dir.path(), "free.toml", FREE);
    let text = with_row(3, |l| {
        let mut cells: Vec<String> = l.split(',').map(String::from).collect();
        let w: f64 = cells[1].parse().unwrap();
        cells[1] = format!("{}", w * (1.0 + 1e-9));
        cells.join(",")
    });
    let theirs = write_file(dir.path(), "theirs.csv", text);
    let out = eulerdyn([
        "score",
        theirs.to_str().unwrap(),
        "--scene",
        scene.to_str().unwrap(),
    ]);
    out.expect_code(0);
    assert!(
        out.stdout.contains("normalised") && out.stdout.contains("the first row 3"),
        "{}",
        out.stdout
    );
}

#[test]
fn a_spreadsheet_csv_other_orders_and_axes_score_the_same() {
    let dir = tempfile::tempdir().unwrap();
    let scene_text = scene_from(FREE, &Overrides::default());
    let plain = write_file(dir.path(), "plain.csv", csv(&exact_rows(), true));
    // A spreadsheet's save: byte-order mark, CRLF, renamed columns, scalar-last quaternion, ω in space axes,
    // and the matrix form.
    let mut text = String::from("\u{feff}time,qx,qy,qz,qw,wx,wy,wz\r\n");
    let mut matrix = String::from("t,R_11,R_12,R_13,R_21,R_22,R_23,R_31,R_32,R_33\n");
    for (t, q, w) in exact_rows() {
        let (c, w_s) = (q.quaternion(), q * w);
        text.push_str(&format!(
            "{t},{},{},{},{},{},{},{}\r\n",
            c.i, c.j, c.k, c.w, w_s.x, w_s.y, w_s.z
        ));
        let r = q.to_rotation_matrix();
        let m: Vec<String> = (0..3)
            .flat_map(|i| (0..3).map(move |j| (i, j)))
            .map(|(i, j)| r[(i, j)].to_string())
            .collect();
        matrix.push_str(&format!("{t},{}\n", m.join(",")));
    }
    let sheet = write_file(dir.path(), "sheet.csv", text);
    let matrix = write_file(dir.path(), "matrix.csv", matrix);
    let map = |pairs: &[(&str, &str)]| {
        pairs
            .iter()
            .map(|(a, b)| (a.to_string(), b.to_string()))
            .collect()
    };
    let options = ReadOptions {
        quaternion: score::QuaternionOrder::Xyzw,
        omega: Some(eulerdyn::frames::Axes::Space),
        map: map(&[
            ("t", "time"),
            ("q_0", "qx"),
            ("q_1", "qy"),
            ("q_2", "qz"),
            ("q_3", "qw"),
            ("omega_x", "wx"),
            ("omega_y", "wy"),
            ("omega_z", "wz"),
        ]),
    };
    let a = score::score(&plain, &scene_text, &ReadOptions::default()).unwrap();
    let b = score::score(&sheet, &scene_text, &options).unwrap();
    let c = score::score(&matrix, &scene_text, &ReadOptions::default()).unwrap();
    // The same trajectory in other clothes: the same errors, to round-off (1e-12 as above; the matrix's
    // conversion to a quaternion adds a few ε).
    for (x, y) in a.metrics.iter().zip(&b.metrics) {
        assert!((x.largest - y.largest).abs() < 1e-12, "{x:?} {y:?}");
    }
    assert!(c.metric("attitude").unwrap().largest < 1e-12);
}

#[test]
fn the_plot_is_written_atomically() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(dir.path(), "free.toml", FREE);
    let theirs = write_file(
        dir.path(),
        "euler.csv",
        csv(&semi_implicit_euler(1.0 / 60.0, true), true),
    );
    let fig: PathBuf = dir.path().join("errors.svg");
    let out = eulerdyn([
        "score",
        theirs.to_str().unwrap(),
        "--scene",
        scene.to_str().unwrap(),
        "--json",
        "--plot",
        fig.to_str().unwrap(),
    ]);
    assert!(out.code == Some(0) || out.code == Some(1), "{}", out.stderr);
    let json: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(json["metrics"][0]["key"], "attitude");
    let svg = std::fs::read_to_string(&fig).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("attitude error angle"));
}

/// Issue 57: one exit code for an output that cannot be created (2, as `run -o`), a PNG for `--plot FIG.png` (as
/// `plot`), the legend beside the curves and the thresholds drawn.
#[test]
fn score_outputs_follow_the_output_policy() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(dir.path(), "free.toml", FREE);
    let theirs = write_file(
        dir.path(),
        "euler.csv",
        csv(&semi_implicit_euler(1.0 / 60.0, true), true),
    );
    let score_to = |plot: &Path| {
        eulerdyn([
            "score",
            theirs.to_str().unwrap(),
            "--scene",
            scene.to_str().unwrap(),
            "--plot",
            plot.to_str().unwrap(),
        ])
    };
    let out = score_to(&dir.path().join("nodir/x.svg"));
    assert_eq!(out.code, Some(2), "{}", out.stderr);
    assert!(out.stderr.contains("nodir"), "{}", out.stderr);
    let png = dir.path().join("errors.png");
    let out = score_to(&png);
    assert!(out.code == Some(0) || out.code == Some(1), "{}", out.stderr);
    let bytes = std::fs::read(&png).unwrap();
    assert!(
        bytes.starts_with(b"\x89PNG\r\n\x1a\n"),
        "a PNG, not SVG text"
    );
    // 1000 × 600 px at 300 dpi.
    let size = |at: usize| u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap());
    assert_eq!((size(16), size(20)), (3125, 1875));
    let svg_path = dir.path().join("errors.svg");
    score_to(&svg_path);
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    // The legend's labels stand right of the chart, which ends 270 px before the figure's right edge.
    for label in [
        "attitude error angle (rad)",
        "dashed: each metric&apos;s threshold",
    ] {
        let at = svg
            .find(label)
            .unwrap_or_else(|| panic!("{label} not in the figure"));
        let head = &svg[svg[..at].rfind("<text").unwrap()..at];
        let x: f64 = head
            .split("x=\"")
            .nth(1)
            .unwrap()
            .split('"')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        assert!(x > 730.0, "{label} at x = {x}");
    }
    // Each metric's threshold is a dashed line of its colour: the five curves and their legend samples are ten
    // polylines, each dashed threshold across ~600 px in 4 px dashes and 5 px gaps dozens more.
    assert!(svg.matches("<polyline").count() > 10 + 5 * 20, "{svg}");
}

/// Issue 57: `suite --out` onto a file is bad input (exit 2), and a card with one scene's output missing scores the
/// rest and marks it (exit 1: not everything passes).
#[test]
fn a_suite_missing_a_scene_is_scored_and_marked() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_file(dir.path(), "a_file", "x");
    let out = eulerdyn(["suite", "--out", file.to_str().unwrap()]);
    assert_eq!(out.code, Some(2), "{}", out.stderr);
    assert!(out.stderr.contains("a_file"), "{}", out.stderr);
    let suite_dir = dir.path().join("suite");
    eulerdyn(["suite", "--out", suite_dir.to_str().unwrap()]).expect_code(0);
    let own = suite_dir.join("self");
    std::fs::create_dir(&own).unwrap();
    let (missing, _) = suite::SCENES[1];
    for (name, _) in suite::SCENES.iter().filter(|(n, _)| *n != missing) {
        std::fs::copy(
            suite_dir.join(format!("{name}.csv")),
            own.join(format!("{name}.csv")),
        )
        .unwrap();
    }
    let args = [
        "score",
        "--suite",
        suite_dir.to_str().unwrap(),
        "--engine",
        "self",
    ];
    let card = eulerdyn(args);
    assert_eq!(card.code, Some(1), "{}", card.stderr);
    let lines: Vec<&str> = card.stdout.lines().collect();
    assert_eq!(
        lines.iter().filter(|l| l.ends_with("pass")).count(),
        5,
        "{}",
        card.stdout
    );
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with(missing) && l.contains("missing: no ")),
        "{}",
        card.stdout
    );
    let json = eulerdyn([&args[..], &["--json"]].concat());
    let scores: serde_json::Value = serde_json::from_str(&json.stdout).unwrap();
    let marked: Vec<&serde_json::Value> = (scores.as_array().unwrap().iter())
        .filter(|s| s["missing"] == true)
        .collect();
    assert_eq!(marked.len(), 1);
    assert_eq!(marked[0]["scene"], missing);
    // No output at all is bad input.
    let none = eulerdyn([
        "score",
        "--suite",
        suite_dir.to_str().unwrap(),
        "--engine",
        "nobody",
    ]);
    assert_eq!(none.code, Some(2), "{}", none.stderr);
}

/// Issue 57: the two likeliest export slips — the quaternion written x, y, z, w and ω in space axes — failed loudly
/// with no hint, though the first row is not the scene's q₀ and ω₀. Now each is named, in the text and the JSON,
/// and the flags it names make the same file score at round-off.
#[test]
fn an_xyzw_quaternion_and_space_omega_are_named_from_the_first_row() {
    let dir = tempfile::tempdir().unwrap();
    // FREE tilted by 20° about x at t = 0, so that space and body axes differ.
    let q0 = UnitQuaternion::from_euler_angles(20f64.to_radians(), 0.0, 0.0);
    let c = q0.quaternion();
    let tilted = FREE.replace(
        "omega = [0.4, 0.2, 2.0]",
        &format!(
            "omega = [0.4, 0.2, 2.0]\nattitude = [{}, {}, {}, {}]",
            c.w, c.i, c.j, c.k
        ),
    );
    let scene = write_file(dir.path(), "tilted.toml", &tilted);
    let body =
        TorqueFreeBody::new(Vector3::new(1.0, 2.0, 3.0), Vector3::new(0.4, 0.2, 2.0), q0).unwrap();
    // Written x, y, z, w in the generic columns q_0..q_3 (read w, x, y, z without --quaternion); ω in space axes.
    let rows = |header: &str| {
        let mut text = format!("t,{header},omega_x,omega_y,omega_z\n");
        for t in frames(5.0) {
            let (q, w_s) = (body.attitude(t), body.attitude(t) * body.omega_p(t));
            let c = q.quaternion();
            text += &format!(
                "{t},{},{},{},{},{},{},{}\n",
                c.i, c.j, c.k, c.w, w_s.x, w_s.y, w_s.z
            );
        }
        text
    };
    let theirs = write_file(dir.path(), "slips.csv", rows("q_0,q_1,q_2,q_3"));
    let args = [
        "score",
        theirs.to_str().unwrap(),
        "--scene",
        scene.to_str().unwrap(),
    ];
    let out = eulerdyn(args);
    assert_eq!(out.code, Some(1), "{}", out.stderr);
    for hint in [
        "hint: the first row's attitude is the scene's q0 with its components in the other order: give --quaternion xyzw",
        "hint: the first row's omega",
    ] {
        assert!(
            out.stdout.contains(hint),
            "`{hint}` is not in\n{}",
            out.stdout
        );
    }
    let json: serde_json::Value =
        serde_json::from_str(&eulerdyn([&args[..], &["--json"]].concat()).stdout).unwrap();
    assert_eq!(
        json["hints"].as_array().unwrap().len(),
        2,
        "{}",
        json["hints"]
    );
    // With the quaternion read in its order, the ω hint is exact: it names --omega space.
    let xyzw = [&args[..], &["--quaternion", "xyzw"]].concat();
    let out = eulerdyn(&xyzw);
    assert!(
        out.stdout.contains("hint: the first row's omega is the scene's omega0 in the other axes: give --omega space"),
        "{}",
        out.stdout
    );
    // Columns named q_w..q_z say their order themselves: the hint is about the header.
    let named = write_file(dir.path(), "named.csv", rows("q_w,q_x,q_y,q_z"));
    let out = eulerdyn([
        "score",
        named.to_str().unwrap(),
        "--scene",
        scene.to_str().unwrap(),
    ]);
    assert!(
        out.stdout.contains(
            "the columns q_w, q_x, q_y, q_z hold x, y, z, w; name them for what they hold"
        ),
        "{}",
        out.stdout
    );
    let fixed = eulerdyn([&xyzw[..], &["--omega", "space", "--json"]].concat());
    assert_eq!(fixed.code, Some(0), "{}", fixed.stdout);
    let json: serde_json::Value = serde_json::from_str(&fixed.stdout).unwrap();
    assert_eq!(json["hints"].as_array().unwrap().len(), 0);
}

/// Issue 55: eulerdyn's own CSV (`omega_b_x..z`) is read as body-axis ω without `--map`, and a `--map` to a column the
/// file lacks is refused naming that column.
#[test]
fn eulerdyns_own_omega_columns_are_read_and_a_map_to_a_missing_column_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let own = csv(&exact_rows(), true).replacen(
        "omega_x,omega_y,omega_z",
        "omega_b_x,omega_b_y,omega_b_z",
        1,
    );
    assert!(own.starts_with("t,q_w,q_x,q_y,q_z,omega_b_x"), "{own}");
    let s = score_text(dir.path(), "own.csv", &own, FREE);
    // The same rows as the_exact_solution_scores_round_off, so ω is measured and at round-off (1e-12, as there).
    let omega = s.metric("omega").expect("ω measured from omega_b_*");
    assert!(omega.largest < 1e-12, "{omega:?}");
    let theirs = write_file(dir.path(), "theirs.csv", csv(&exact_rows(), true));
    let scene = write_file(dir.path(), "free.toml", FREE);
    let out = eulerdyn([
        "score",
        theirs.to_str().unwrap(),
        "--scene",
        scene.to_str().unwrap(),
        "--map",
        "omega_x=wx",
    ]);
    assert_eq!(out.code, Some(2), "{}", out.stderr);
    assert!(
        out.stderr
            .contains("--map omega_x=wx: the file has no column `wx`"),
        "{}",
        out.stderr
    );
}

/// The suite's tennis racket without its `[[event]]`: the scene as a user writes it before thinking of events.
fn racket_without_event() -> String {
    let (text, _) = racket();
    let start = text
        .find("[[event]]")
        .expect("the suite's racket has an event");
    let end = start + text[start..].find("\n\n").unwrap() + 2;
    format!("{}{}", &text[..start], &text[end..])
}

#[test]
fn a_flipping_body_s_flips_are_scored_without_an_event() {
    let dir = tempfile::tempdir().unwrap();
    let (_, e) = racket();
    // 40 s: the racket flips every 2K/λ ≈ 8.2 s.
    let scene = racket_without_event().replace("t_end = 12.0", "t_end = 40.0");
    assert!(
        !scene.contains("[[event]]") && scene.contains("t_end = 40.0"),
        "{scene}"
    );
    let shift = 0.01;
    let rows: Vec<_> = (0..=40 * 600)
        .map(|k| {
            let t = k as f64 / 600.0;
            (t, e.attitude(t - shift), e.omega_p(t - shift))
        })
        .collect();
    let s = score_text(dir.path(), "late.csv", &csv(&rows, true), &scene);
    let m = s
        .metric("event:flip")
        .expect("the flips, found without an [[event]]");
    assert_eq!(m.name, score::flips::LABEL);
    let each = m.occurrences.as_ref().unwrap();
    // ω₂ ∝ sn τ changes sign every 2K/λ (Landau & Lifshitz §37; `TorqueFreeBody::flip_interval`): the reference's
    // flips, located on the closed form by Brent's method to 1e-13 s, are that far apart to round-off.
    let interval = e.flip_interval().unwrap();
    let reference: Vec<f64> = each.iter().filter_map(|o| o.reference_t).collect();
    assert!(reference.len() >= 4, "{each:?}");
    for pair in reference.windows(2) {
        assert!(
            (pair[1] - pair[0] - interval).abs() < 1e-9,
            "{pair:?} against {interval}"
        );
    }
    // Their flips come `shift` late (linear interpolation between rows 1/600 s apart: O(h³·ω₂''') ≈ 1e-8 s, as
    // in `a_time_shifted_flip_reports_the_shift`); the last reference flip may fall after their last row.
    for o in each
        .iter()
        .filter(|o| o.their_t.is_some() && o.reference_t.is_some())
    {
        assert!((o.error.unwrap() - shift).abs() < 1e-6, "{o:?}");
    }
    assert!(m.passes == m.note.is_none(), "{m:?}");
}

#[test]
fn the_scene_s_own_flip_event_is_not_scored_twice_and_a_major_axis_wobble_is_no_flip() {
    let dir = tempfile::tempdir().unwrap();
    let (scene, e) = racket();
    let rows: Vec<_> = (0..=12 * 60)
        .map(|k| {
            let t = k as f64 / 60.0;
            (t, e.attitude(t), e.omega_p(t))
        })
        .collect();
    let s = score_text(dir.path(), "racket.csv", &csv(&rows, true), &scene);
    let flips: Vec<_> = s.metrics.iter().filter(|m| m.key == "event:flip").collect();
    assert_eq!(flips.len(), 1, "{flips:?}");
    assert_eq!(flips[0].name, "event `flip` time error (s)");
    // FREE circulates about its major axis: ω₂ changes sign, but the intermediate axis stays far from H
    // (H₂,max/|H| = 0.15 by the closed form in score/flips.rs), so nothing flips and no metric is added.
    let s = score_text(dir.path(), "free.csv", &csv(&exact_rows(), true), FREE);
    assert!(s.metric("event:flip").is_none(), "{:?}", s.metrics);
}

#[test]
fn a_trajectory_that_ends_early_is_not_a_pass_and_says_where_it_ends() {
    // An engine that stopped (Drake's top diverges at t = 0.73 s of 5 s): the exact rows of FREE up to t = 2 s
    // pass every metric, but the scene is not scored past 2 s, so the score is not a pass (exit 1).
    let dir = tempfile::tempdir().unwrap();
    let rows: Vec<_> = exact_rows().into_iter().filter(|r| r.0 <= 2.0).collect();
    let s = score_text(dir.path(), "short.csv", &csv(&rows, true), FREE);
    assert!(s.metrics.iter().all(|m| m.passes), "{:?}", s.metrics);
    assert_eq!(s.ends_early, Some(2.0));
    assert!(!s.passes());
    assert!(
        s.notes.iter().any(|n| n.contains("end at t = 2.000 s")),
        "{:?}",
        s.notes
    );
    let text = score::report::text(&s);
    assert!(
        text.contains("verdict: FAIL (their rows end at t = 2.000 s"),
        "{text}"
    );
    // The whole run, or one that ends within a row of t_end, is scored as before.
    let s = score_text(dir.path(), "whole.csv", &csv(&exact_rows(), true), FREE);
    assert_eq!(s.ends_early, None);
    assert!(s.passes());
    // The command: exit 1, and the JSON says where their rows end.
    let scene = write_file(dir.path(), "free.toml", FREE);
    let short = dir.path().join("short.csv");
    let out = eulerdyn([
        "score",
        short.to_str().unwrap(),
        "--scene",
        scene.to_str().unwrap(),
        "--json",
    ]);
    out.expect_code(1);
    let json: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(json["ends_early"], 2.0, "{json}");
}
