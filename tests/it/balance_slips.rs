//! Balancing verdicts that can be trusted (issue 35): the grade judged at the service speed in the bearing planes
//! (ISO 21940-11, 4.4, 6.3.3, 7.2), unit slips caught with a warning and an `unverified` verdict, one format for
//! masses and angles, and `-o` refused onto its own scene.

use std::path::Path;

use crate::balance_grade::{FAN, FAN_PLANES, FAN_TABLE, HEADER, close, fan_text};
use crate::common::{eulerdyn, repo_path, write_file};
use eulerdyn::analysis::balance::influence::{self, Phasor, phasor};
use eulerdyn::analysis::balance::iso::{self, Verdict};
use eulerdyn::analysis::balance::{
    Planes, Readings, Request, TolerancePlanes, balance, balance_report,
};
use nalgebra::Vector2;
use serde_json::Value;

/// `eulerdyn balance SCENE --planes P --radius R` with `extra` arguments, stdout as text (exit 0 expected).
fn balance_text(scene: &Path, planes: &str, radius: &str, extra: &[&str]) -> String {
    let mut args = vec!["balance", scene.to_str().unwrap(), "--planes", planes];
    args.extend(["--radius", radius]);
    args.extend(extra);
    eulerdyn(args).expect_code(0).stdout.clone()
}

/// The same with `--json`, parsed.
fn balance_json(scene: &Path, planes: &str, radius: &str, extra: &[&str]) -> Value {
    let text = balance_text(scene, planes, radius, &[extra, &["--json"]].concat());
    serde_json::from_str(&text).unwrap()
}

/// Asserts that the report `text` says each of `expect` and gives no confident "pass".
fn assert_warned_without_a_pass(text: &str, expect: &[&str]) {
    for expect in expect {
        assert!(text.contains(expect), "`{expect}` is not in\n{text}");
    }
    assert!(!text.contains("pass against"), "{text}");
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The fan's table with its trial masses written in kg in the `trial_mass_g` column (20 g as 0.02), as
/// `scenarios/fan_rotor_measured_kg.csv` (the book's slip) has it.
fn fan_table_in_kg() -> String {
    let text = std::fs::read_to_string(repo_path(FAN_TABLE)).unwrap();
    let slipped = text.replace(",20,", ",0.02,");
    let bundled =
        std::fs::read_to_string(repo_path("scenarios/fan_rotor_measured_kg.csv")).unwrap();
    assert_eq!(
        bundled, slipped,
        "scenarios/fan_rotor_measured_kg.csv is the fan's table in kg"
    );
    slipped
}

// ---------------------------------------------------------------------------------------------------------------
// Slips

#[test]
fn trial_masses_in_kg_are_caught_and_no_verdict_is_given() {
    let dir = tempfile::tempdir().unwrap();
    let table = write_file(dir.path(), "kg.csv", fan_table_in_kg());
    let scene = repo_path(FAN);
    let measured = [
        "--grade",
        "6.3",
        "--service-rpm",
        "1500",
        "--measured",
        table.to_str().unwrap(),
    ];
    let text = balance_text(&scene, "-0.1,0.08", "0.25", &measured);
    // α = ΔV/T with T 1000 × too small: the fitted coefficients are 1000 × the model's, the corrections 1000 ×
    // too small, and the rotor seems finer than G 0.4.
    assert_warned_without_a_pass(
        &text,
        &[
            "warning: the influence coefficients fitted to the table are not the rigid-rotor model's",
            "plane A 1003 × at 0.1 deg, plane B 1000 × at 0.0 deg",
            "in kg instead of g",
            "finer than G 0.4",
            "before: meets G",
            "unverified against G 6.3 (see the warnings)",
        ],
    );
    let json = balance_json(&scene, "-0.1,0.08", "0.25", &measured);
    assert_eq!(json["warnings"].as_array().unwrap().len(), 2);
    let target = &json["grade"]["target"];
    assert_eq!(target["verdict"], "unverified");
    assert_eq!(target["verdict_before"], "unverified");
    assert_eq!(
        target["pass"], false,
        "no confident pass in the JSON either"
    );
    // With vibration readings (no comparison with the model) the initial grade still gives the slip away.
    let other = balance_text(
        &scene,
        "-0.1,0.08",
        "0.25",
        &[&measured[..], &["--readings", "other"]].concat(),
    );
    assert!(!other.contains("not the rigid-rotor model's"), "{other}");
    assert!(
        other.contains("finer than G 0.4") && other.contains("in kg instead of g"),
        "{other}"
    );
    assert!(other.contains("unverified against G 6.3"), "{other}");
}

#[test]
fn planes_in_mm_are_caught_in_both_modes_and_the_bearing_plane_grade_does_not_depend_on_them() {
    let scene = repo_path(FAN);
    let table = repo_path(FAN_TABLE);
    let measured = ["--grade", "6.3", "--measured", table.to_str().unwrap()];
    let text = balance_text(&scene, "-100,80", "0.25", &measured);
    for expect in [
        "warning: correction plane A at -100 m is 99.60 m outside the bearings (-0.4 m to 0.3 m)",
        "warning: correction plane B at 80 m",
        "the planes are likely in mm instead of m (--planes)",
        "not the rigid-rotor model's",
        "unverified against G 6.3",
    ] {
        assert!(text.contains(expect), "`{expect}` is not in\n{text}");
    }
    // From the model: the unbalance converted to the bearing planes keeps its resultant and moment, so the grade
    // is the rotor's whatever the correction planes (to round-off, 1e-9); the slip is still warned of.
    let right = balance_json(&scene, "-0.1,0.08", "0.25", &["--grade", "6.3"]);
    let slipped = balance_json(&scene, "-100,80", "0.25", &["--grade", "6.3"]);
    close(
        f(&slipped["grade"]["met_before"]),
        f(&right["grade"]["met_before"]),
        1e-9,
        "G",
    );
    assert_eq!(right["warnings"].as_array().unwrap().len(), 0);
    assert_eq!(slipped["warnings"].as_array().unwrap().len(), 2);
    assert_eq!(slipped["grade"]["target"]["verdict_before"], "unverified");
    assert_eq!(right["grade"]["target"]["verdict_before"], "fail");
}

#[test]
fn a_radius_in_mm_is_caught() {
    let scene = repo_path(FAN);
    let table = repo_path(FAN_TABLE);
    let measured = ["--grade", "6.3", "--measured", table.to_str().unwrap()];
    let text = balance_text(&scene, "-0.1,0.08", "250", &measured);
    // The cylinder (R 0.3 m, h 0.2 m) reaches √(0.3² + 0.1²) = 0.3162 m from the axis at most.
    for expect in [
        "warning: the correction radius 250 m is beyond the rotor, which reaches 0.3162 m",
        "the radius is likely in mm instead of m (--radius)",
        "coarser than G 4000",
        "unverified against G 6.3",
    ] {
        assert!(text.contains(expect), "`{expect}` is not in\n{text}");
    }
}

#[test]
fn a_clean_table_gets_no_warning_and_a_verdict() {
    let scene = repo_path(FAN);
    let table = repo_path(FAN_TABLE);
    for readings in ["force", "other"] {
        let extra = [
            "--grade",
            "6.3",
            "--service-rpm",
            "1500",
            "--measured",
            table.to_str().unwrap(),
            "--readings",
            readings,
        ];
        let text = balance_text(&scene, "-0.1,0.08", "0.25", &extra);
        assert!(!text.contains("warning:"), "{text}");
        assert!(
            text.contains("fail against G 6.3") && text.contains("pass against G 6.3"),
            "{text}"
        );
    }
    // The fitted coefficients are the model's within the readings' rounding (0.1 N, 1°): within 1 % and 1°.
    let request = Request {
        planes: FAN_PLANES,
        grade: None,
        rpm: None,
        service_rpm: None,
        tolerance_planes: TolerancePlanes::Bearings,
        readings: Readings::Force,
        measured: Some((table.clone(), std::fs::read_to_string(&table).unwrap())),
    };
    let fan = eulerdyn::scene::load(&scene, &Default::default()).unwrap();
    let found = balance_report(&fan, &request).unwrap().influence.unwrap();
    let model = influence::rigid_rotor_coefficients(
        [-0.4, 0.3],
        [-0.1, 0.08],
        0.25,
        50.0 * std::f64::consts::PI,
    );
    for (ratio, phase) in eulerdyn::analysis::balance::slips::compare_columns(&found.alpha, &model)
    {
        assert!(
            (ratio - 1.0).abs() < 0.01 && phase.abs() < 1.0,
            "{ratio} {phase}"
        );
    }
}

// ---------------------------------------------------------------------------------------------------------------
// The service speed

/// The fan's readings, exact, as a balancing machine at `omega` (rad/s) gives them: the rigid-rotor model's
/// coefficients times the fan's unbalance (the opposite of the model's corrections, g at R), an initial run and a
/// 20 g trial in each plane.
fn fan_table_at(omega: f64) -> String {
    let spec = eulerdyn::scene::load_spec(&repo_path(FAN)).unwrap();
    let model = balance(&spec, &FAN_PLANES).unwrap();
    let w = model.corrections.map(|c| phasor(c.mass * 1e3, c.angle_deg));
    let alpha = influence::rigid_rotor_coefficients([-0.4, 0.3], [-0.1, 0.08], 0.25, omega);
    let v0 = -(alpha * Vector2::new(w[0], w[1]));
    let cells = |v: Vector2<Phasor>| {
        let [(a, pa), (b, pb)] = [v[0], v[1]].map(influence::polar_deg);
        format!("{a},{pa},{b},{pb}")
    };
    let trial = |j: usize, angle: f64| v0 + alpha.column(j) * phasor(20.0, angle);
    format!(
        "{HEADER}\n1,,,,{}\n2,A,20,0,{}\n3,B,20,90,{}\n",
        cells(v0),
        cells(trial(0, 0.0)),
        cells(trial(1, 90.0))
    )
}

#[test]
fn a_fan_balanced_at_600_rpm_that_runs_at_2950_rpm_is_judged_at_2950() {
    let dir = tempfile::tempdir().unwrap();
    let service = iso::rpm_to_rad_s(2950.0);
    let text = fan_text().replace("rate = 157.07963267948966", &format!("rate = {service}"));
    let scene = write_file(dir.path(), "fan2950.toml", text);
    let table = write_file(
        dir.path(),
        "at600.csv",
        fan_table_at(iso::rpm_to_rad_s(600.0)),
    );
    let measured = [
        "--grade",
        "6.3",
        "--rpm",
        "600",
        "--measured",
        table.to_str().unwrap(),
    ];
    let out = balance_text(
        &scene,
        "-0.1,0.08",
        "0.25",
        &[&measured[..], &["--service-rpm", "2950"]].concat(),
    );
    for expect in [
        "measured runs at 600.000 rpm (62.8319 rad/s, --rpm); readings: bearing forces in N",
        "at the service speed 2950.00 rpm (308.923 rad/s, --service-rpm)",
        "tolerance planes: the bearings, A at -0.4 m and B at 0.3 m",
    ] {
        assert!(out.contains(expect), "`{expect}` is not in\n{out}");
    }
    assert!(
        !out.contains("warning:"),
        "the runs at 600 rpm match the model at --rpm\n{out}"
    );
    let at_service = balance_json(
        &scene,
        "-0.1,0.08",
        "0.25",
        &[&measured[..], &["--service-rpm", "2950"]].concat(),
    );
    let judged_at_600 = balance_json(
        &scene,
        "-0.1,0.08",
        "0.25",
        &[&measured[..], &["--service-rpm", "600"]].concat(),
    );
    close(f(&at_service["grade"]["rpm"]), 2950.0, 1e-12, "service rpm");
    assert_eq!(judged_at_600["grade"]["speed_from"], "service_rpm");
    // G = U Ω / (1000 m share) is proportional to Ω: the grade at 2950 rpm is 2950/600 of that at 600 rpm.
    let [g_service, g_600] = [&at_service, &judged_at_600].map(|v| f(&v["grade"]["met_before"]));
    close(g_service / g_600, 2950.0 / 600.0, 1e-12, "G ∝ Ω");
    // The exact readings give the model's unbalance: the same grade as the model's own (round-off, 1e-9).
    let model = balance_json(&scene, "-0.1,0.08", "0.25", &["--grade", "6.3"]);
    close(
        g_service,
        f(&model["grade"]["met_before"]),
        1e-9,
        "G from the readings",
    );
}

/// Issue 57: a rotor measured at 600 rpm that serves at 6000 rpm, graded without `--service-rpm`, was judged at the
/// scene's 600 rpm and given a confident "pass". With a measured table the grade now asks for the service speed
/// (a warning, the verdict `unverified`); without one it says where it was judged. G ∝ Ω (ISO 21940-11, 6.3.3):
/// at 6000 rpm the same unbalance meets a grade 10 × coarser.
#[test]
fn a_grade_without_the_service_speed_is_never_a_bare_pass() {
    let dir = tempfile::tempdir().unwrap();
    let at_600 = iso::rpm_to_rad_s(600.0);
    let text = fan_text().replace("rate = 157.07963267948966", &format!("rate = {at_600}"));
    let scene = write_file(dir.path(), "fan600.toml", text);
    let table = write_file(dir.path(), "at600.csv", fan_table_at(at_600));
    let measured = ["--grade", "63", "--measured", table.to_str().unwrap()];
    let out = balance_text(&scene, "-0.1,0.08", "0.25", &measured);
    assert_warned_without_a_pass(
        &out,
        &[
            "warning: the grade was judged at the scene's rate, 600.000 rpm, for want of --service-rpm",
            "give --service-rpm N for a verdict",
            "unverified against G 63 (see the warnings)",
        ],
    );
    let json = balance_json(&scene, "-0.1,0.08", "0.25", &measured);
    assert_eq!(json["grade"]["target"]["verdict"], "unverified");
    assert_eq!(json["grade"]["target"]["pass"], false);
    assert_eq!(json["grade"]["speed_from"], "scene");
    // The service speed given: no warning, a verdict, and the grade 10 × that judged at 600 rpm.
    let at_6000 = [&measured[..], &["--service-rpm", "6000"]].concat();
    let served = balance_json(&scene, "-0.1,0.08", "0.25", &at_6000);
    assert_eq!(served["warnings"].as_array().unwrap().len(), 0, "{served}");
    assert_eq!(
        served["grade"]["target"]["verdict_before"], "fail",
        "G 98.3 at 6000 rpm"
    );
    let ratio = f(&served["grade"]["met_before"]) / f(&json["grade"]["met_before"]);
    close(ratio, 10.0, 1e-12, "G ∝ Ω");
    // Without a measured table (the model's unbalance) the verdict names the speed it was judged at.
    let model = balance_text(&scene, "-0.1,0.08", "0.25", &["--grade", "63"]);
    assert!(
        model.contains("against G 63 at the scene's rate (--service-rpm N: at the rotor's maximum service speed)"),
        "{model}"
    );
}

#[test]
fn a_grade_needs_the_service_speed_of_a_scene_at_rest() {
    let dir = tempfile::tempdir().unwrap();
    let at_rest = fan_text().replace("rate = 157.07963267948966", "rate = 0.0");
    let scene = write_file(dir.path(), "rest.toml", &at_rest);
    let args = [
        "balance",
        scene.to_str().unwrap(),
        "--planes",
        "-0.1,0.08",
        "--radius",
        "0.25",
    ];
    // --rpm is the runs' speed, not the service speed: it does not stand in for it.
    let out = eulerdyn(args.iter().chain(&["--grade", "6.3", "--rpm", "1500"]));
    assert_eq!(out.code, Some(2));
    assert!(out.stderr.contains("give --service-rpm"), "{}", out.stderr);
    let out = eulerdyn(args.iter().chain(&["--grade", "6.3", "--service-rpm", "0"]));
    assert_eq!(out.code, Some(2));
    assert!(out.stderr.contains("--service-rpm 0: "), "{}", out.stderr);
}

// ---------------------------------------------------------------------------------------------------------------
// Tolerance planes, against hand-derived numbers

/// A 2 kg thin disk (R = 0.3 m) turning about its symmetry axis at 100 rad/s in bearings `bearings`, with the
/// point masses `masses` (kg, at) as its unbalance.
fn disk(bearings: [f64; 2], masses: &[(f64, [f64; 3])]) -> String {
    let mut text =
        String::from("[body]\nmass = 2.0\nshape = { type = \"thin_disk\", radius = 0.3 }\n");
    for (m, at) in masses {
        text += &format!(
            "[[body.point_mass]]\nmass = {m}\nat = [{}, {}, {}]\n",
            at[0], at[1], at[2]
        );
    }
    text + &format!(
        "[motion]\ntype = \"fixed_axis\"\naxis = [0.0, 0.0, 1.0]\nrate = 100.0\nbearings = [{}, {}]\n\
         [solver]\nt_end = 0.1\n[output]\nevery = 0.01\n",
        bearings[0], bearings[1]
    )
}

/// The assessment of `text` balanced in `planes` at R = 0.2 m against G 6.3, in `tolerance` planes.
fn assessed(text: &str, planes: [f64; 2], tolerance: TolerancePlanes) -> iso::Assessment {
    let scene = eulerdyn::scene::parse(Path::new("disk.toml"), text, &Default::default()).unwrap();
    let request = Request {
        planes: Planes {
            a: planes[0],
            b: planes[1],
            radius: 0.2,
        },
        grade: Some(6.3),
        rpm: None,
        service_rpm: None,
        tolerance_planes: tolerance,
        readings: Readings::Force,
        measured: None,
    };
    let report = balance_report(&scene, &request).unwrap();
    assert!(report.warnings.is_empty(), "{:?}", report.warnings);
    report.grade.unwrap()
}

#[test]
fn a_static_unbalance_goes_to_the_bearings_by_the_lever_rule_with_and_without_the_clamp() {
    // 10 g at 0.1 m in the plane of the centre of mass (z = 0): U = 1000 g·mm, a static unbalance; m = 2.01 kg.
    let masses = [(0.01, [0.1, 0.0, 0.0])];
    let m = 2.01;
    // Bearings at −0.2 and 0.3 m: U_A = 1000·0.3/0.5 = 600, U_B = 1000·0.2/0.5 = 400 g·mm (lever rule), shares
    // 0.6 and 0.4 (ISO 21940-11, 7.2.1, no clamp): each plane at its share, G = U Ω/(1000 m) = 49.75 mm/s
    // (the definition e·Ω of 6.3.1). The same for correction planes between the bearings and outside them.
    for planes in [[-0.1, 0.1], [-0.5, 0.6]] {
        let g = assessed(
            &disk([-0.2, 0.3], &masses),
            planes,
            TolerancePlanes::Bearings,
        );
        assert_eq!(g.planes, TolerancePlanes::Bearings);
        assert_eq!(g.z, [-0.2, 0.3]);
        close(g.unbalance[0][0], 600.0, 1e-12, "U_A");
        close(g.unbalance[0][1], 400.0, 1e-12, "U_B");
        close(g.shares[0], 0.6, 1e-12, "share A");
        close(g.met[0], 1000.0 * 100.0 / (1000.0 * m), 1e-12, "G");
    }
    // Bearings at −0.05 and 0.45 m: U_A = 900, U_B = 100; the lever shares 0.9 and 0.1 are clamped to 0.7 and
    // 0.3 (7.2.2): G = (900/0.7)·Ω/(1000 m) = 63.97 mm/s.
    let g = assessed(
        &disk([-0.05, 0.45], &masses),
        [-0.1, 0.1],
        TolerancePlanes::Bearings,
    );
    close(g.unbalance[0][0], 900.0, 1e-12, "U_A");
    close(g.unbalance[0][1], 100.0, 1e-12, "U_B");
    assert_eq!(g.shares, [0.7, 0.3]);
    close(
        g.met[0],
        900.0 / 0.7 * 100.0 / (1000.0 * m),
        1e-12,
        "G clamped",
    );
    // In the correction planes −0.1, 0.3 (last round's allotment): U = 1000·0.3/0.4 = 750 and 250, shares 0.75
    // and 0.25 clamped to 0.7 and 0.3: G = (750/0.7)·Ω/(1000 m) = 53.30 mm/s.
    let g = assessed(
        &disk([-0.2, 0.3], &masses),
        [-0.1, 0.3],
        TolerancePlanes::Correction,
    );
    assert_eq!(g.planes, TolerancePlanes::Correction);
    close(g.unbalance[0][0], 750.0, 1e-12, "U_1");
    close(
        g.met[0],
        750.0 / 0.7 * 100.0 / (1000.0 * m),
        1e-12,
        "G in the correction planes",
    );
    assert_eq!(g.target.unwrap().verdict, [Verdict::Fail, Verdict::Pass]);
}

#[test]
fn a_couple_unbalance_goes_to_the_bearings_as_a_couple_over_their_span() {
    // 10 g at 0.1 m at z = −0.1 (0°) and at z = 0.1 (180°): no static unbalance, a couple of 1000 g·mm × 0.2 m =
    // 2·10⁵ g·mm²; in bearings 0.5 m apart it is ±400 g·mm. Shares 0.6, 0.4: B is the worse, G = (400/0.4)·Ω/
    // (1000 m) with m = 2.02 kg.
    let masses = [(0.01, [0.1, 0.0, -0.1]), (0.01, [-0.1, 0.0, 0.1])];
    let text = disk([-0.2, 0.3], &masses);
    let g = assessed(&text, [-0.1, 0.1], TolerancePlanes::Bearings);
    close(g.unbalance[0][0], 400.0, 1e-12, "U_A");
    close(g.unbalance[0][1], 400.0, 1e-12, "U_B");
    close(g.met[0], 400.0 / 0.4 * 100.0 / (1000.0 * 2.02), 1e-12, "G");
    // In the correction planes it is the two masses themselves, 1000 g·mm each, shares ½.
    let g = assessed(&text, [-0.1, 0.1], TolerancePlanes::Correction);
    close(g.unbalance[0][0], 1000.0, 1e-12, "U_1");
    close(g.met[0], 1000.0 / 0.5 * 100.0 / (1000.0 * 2.02), 1e-12, "G");
    // iso::to_planes directly: the same resultant and moment.
    let [u_a, u_b] = iso::to_planes(
        [phasor(1000.0, 0.0), phasor(1000.0, 180.0)],
        [-0.1, 0.1],
        [-0.2, 0.3],
    );
    assert!((u_a - phasor(400.0, 0.0)).norm() < 1e-9 && (u_b - phasor(400.0, 180.0)).norm() < 1e-9);
}

// ---------------------------------------------------------------------------------------------------------------
// One format; -o onto the scene

#[test]
fn masses_print_in_g_and_angles_in_0_to_360_once_each() {
    // The notes' skewed disk: its model corrections are at ±90° from body x, −90° printed as 270.0.
    let scene = repo_path("scenarios/rotor_bearings.toml");
    let text = balance_text(&scene, "-0.1,0.1", "0.2", &[]);
    assert!(!text.contains(" kg at"), "{text}");
    assert!(text.contains("correction 487.1 g at "), "{text}");
    // An angle is a number followed by " deg" (positions such as "plane A at -0.1 m" may be negative).
    let negative_angle = text.split(" deg").any(|before| {
        let number = before.rsplit(' ').next().unwrap_or("");
        number.starts_with('-')
    });
    assert!(!negative_angle, "no negative angle\n{text}");
    let json = balance_json(&scene, "-0.1,0.1", "0.2", &[]);
    for c in json["corrections"].as_array().unwrap() {
        let angle = f(&c["angle_deg"]);
        assert!((0.0..360.0).contains(&angle), "{angle}");
        assert!(c.get("mass").is_none() && c.get("mass_g").is_some(), "{c}");
    }
    // Measured: the angle is in `corrections` only (no second form of it under `influence`).
    let table = repo_path(FAN_TABLE);
    let fan = balance_json(
        &repo_path(FAN),
        "-0.1,0.08",
        "0.25",
        &["--measured", table.to_str().unwrap()],
    );
    assert!(fan["influence"].get("corrections_g").is_none());
    for c in fan["corrections"].as_array().unwrap() {
        assert!((0.0..360.0).contains(&f(&c["angle_deg"])));
    }
}

#[test]
fn balance_onto_its_own_scene_is_refused_and_the_scene_is_untouched() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(dir.path(), "fan.toml", fan_text());
    let out = eulerdyn([
        "balance",
        scene.to_str().unwrap(),
        "--planes",
        "-0.1,0.08",
        "--radius",
        "0.25",
        "-o",
        scene.to_str().unwrap(),
    ]);
    assert_eq!(out.code, Some(2), "{}", out.stderr);
    assert!(
        out.stderr.contains("would overwrite the scene file"),
        "{}",
        out.stderr
    );
    assert_eq!(
        std::fs::read_to_string(&scene).unwrap(),
        fan_text(),
        "comments kept"
    );
}
