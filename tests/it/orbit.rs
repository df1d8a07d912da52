//! `[orbit]`, the LVLH frame and the gravity gradient, against closed forms: the LVLH equilibrium of a body with
//! its principal axes on the frame's, the pitch libration (an exact pendulum), the moment at a known tilt and at any
//! attitude (an independent evaluation from the orbital elements), an inertially fixed body seen from the turning
//! frame, and bad input.

use std::f64::consts::PI;

use eulerdyn::exact::JacobiElliptic;
use eulerdyn::scene::{self, Overrides};
use eulerdyn::simulate;
use eulerdyn::{Form, Sample};
use nalgebra::{Matrix3, Vector3};

use crate::common::{eulerdyn, scene_from, write_file};

/// μ and R of the scene format (WGS 84).
const MU: f64 = 3.986004418e14;
const R_EARTH: f64 = 6378.137e3;
/// The body: principal moments along body x (roll, along-track at equilibrium), y (pitch) and z (nadir).
const I: [f64; 3] = [0.05, 0.04, 0.02];

/// A body of inertia `I` on a 500 km circular orbit (inclined, its node turned, the body past the node at t = 0),
/// under its gravity gradient when `gradient`, with `initial` as `[initial]`'s keys and `extra` appended.
fn scene_text(initial: &str, gradient: bool, form: Form, t_end: f64, extra: &str) -> String {
    let effect = if gradient {
        "[[effect]]\ntype = \"gravity_gradient\"\n"
    } else {
        ""
    };
    format!(
        "[body]\nmass = 4.0\ninertia = [{}, {}, {}]\n\
         [orbit]\naltitude_km = 500.0\ninclination_deg = 51.6\nraan_deg = 30.0\narg_lat_deg = 10.0\n\
         [initial]\n{initial}\n{effect}{extra}\
         [solver]\nframe = \"{}\"\nrtol = 1e-12\natol = 1e-14\nt_end = {t_end}\n[output]\nevery = 10.0\n",
        I[0],
        I[1],
        I[2],
        form.name()
    )
}

/// n = √(μ/r³) of the 500 km orbit.
fn mean_motion() -> f64 {
    (MU / (R_EARTH + 500e3).powi(3)).sqrt()
}

/// Every row of a run, with the values of its LVLH columns.
fn rows(text: &str) -> Vec<(Sample, [f64; 3])> {
    let scene = scene_from(text, &Overrides::default());
    let columns = scene.facts().columns();
    let names: Vec<String> = columns
        .columns()
        .iter()
        .map(|c| c.name.to_string())
        .collect();
    let at = |name: &str| names.iter().position(|n| n == name).unwrap();
    let (roll, pitch, yaw) = (at("roll_lvlh"), at("pitch_lvlh"), at("yaw_lvlh"));
    let mut out = Vec::new();
    simulate::run(&scene, |s| {
        let mut values = Vec::new();
        columns.values(s, &mut values);
        out.push((*s, [values[roll], values[pitch], values[yaw]]));
        Ok::<(), std::convert::Infallible>(())
    })
    .unwrap();
    out
}

#[test]
fn a_body_on_the_lvlh_axes_stays_there_in_both_forms() {
    // With its principal axes on the LVLH axes and turning with the frame, a body is in relative equilibrium
    // under the gravity gradient (Hughes, *Spacecraft Attitude Dynamics*, 1986, §8.1): the moment n̂ × I n̂ is zero
    // for n̂ on a principal axis, and ω = n ĥ is a steady rotation about a principal axis.
    for form in [Form::Body, Form::Space] {
        let text = scene_text(
            "attitude_lvlh_deg = [0.0, 0.0, 0.0]\nomega_lvlh = [0.0, 0.0, 0.0]",
            true,
            form,
            2.0 * 5677.0,
            "",
        );
        let rows = rows(&text);
        // Two orbits: what stays is round-off carried by the integration (rtol 1e-12 on angles of order n t).
        let largest =
            (rows.iter().flat_map(|(_, a)| a.iter())).fold(0.0_f64, |m, a| m.max(a.abs()));
        assert!(
            largest < 1e-9,
            "{form:?}: the body left LVLH by {largest:e} rad"
        );
    }
}

/// The exact period of a pure pitch libration of amplitude `theta0` (rad). The pitch equation of a body with its
/// roll and yaw at zero, I_y θ̈ + (3/2) n² (I_x − I_z) sin 2θ = 0 (Hughes 1986, §8.1), is a pendulum in φ = 2θ with
/// ω_p = n √(3 (I_x − I_z)/I_y), the contract's small-angle frequency; its period is 4 K(k)/ω_p with
/// k = sin(φ₀/2) (Landau & Lifshitz, *Mechanics*, §11, problem 1).
fn libration_period(theta0: f64) -> f64 {
    let omega_p = mean_motion() * (3.0 * (I[0] - I[2]) / I[1]).sqrt();
    let k = theta0.sin();
    4.0 * JacobiElliptic::new(k * k).unwrap().quarter_period() / omega_p
}

#[test]
fn the_pitch_libration_is_the_pendulum_of_the_closed_form_in_both_forms() {
    let theta0: f64 = 5f64.to_radians();
    let event =
        "[[event]]\nname = \"down\"\nwhen = \"pitch_lvlh\"\ncrosses = 0.0\ndirection = \"down\"\n";
    for form in [Form::Body, Form::Space] {
        let text = scene_text(
            "attitude_lvlh_deg = [0.0, 5.0, 0.0]\nomega_lvlh = [0.0, 0.0, 0.0]",
            true,
            form,
            4.5 * libration_period(theta0),
            event,
        );
        let scene = scene_from(&text, &Overrides::default());
        let (_, found) =
            simulate::run_with_events(&scene, |_| Ok::<(), std::convert::Infallible>(())).unwrap();
        let times: Vec<f64> = found.iter().map(|o| o.t).collect();
        // Downward crossings at T/4, 5T/4, … 17T/4.
        assert_eq!(times.len(), 5, "{form:?}: {times:?}");
        let expected = libration_period(theta0);
        // At 5° the pendulum's period is 1 + θ₀²/4 + … ≈ 1.0019 times the small-angle one: the test tells them
        // apart by far. The crossings are located to the integration's accuracy (rtol 1e-12), round-off on ~10⁴ s.
        for pair in times.windows(2) {
            let period = pair[1] - pair[0];
            assert!(
                ((period - expected) / expected).abs() < 1e-9,
                "{form:?}: period {period} s, the pendulum's {expected} s"
            );
        }
        let small_angle = 2.0 * PI / (mean_motion() * (3.0 * (I[0] - I[2]) / I[1]).sqrt());
        assert!((expected / small_angle - 1.0 - theta0.sin().powi(2) / 4.0).abs() < 1e-5);
    }
}

/// The unit vector to nadir from the orbital elements (Vallado, *Fundamentals of Astrodynamics and Applications*,
/// 4th ed., eq. 2-103 for a circular orbit: the position's direction at argument of latitude u).
fn nadir_s(inclination: f64, raan: f64, u: f64) -> Vector3<f64> {
    let (si, ci, so, co, su, cu) = (
        inclination.sin(),
        inclination.cos(),
        raan.sin(),
        raan.cos(),
        u.sin(),
        u.cos(),
    );
    -Vector3::new(co * cu - so * su * ci, so * cu + co * su * ci, su * si)
}

#[test]
fn the_gravity_gradient_moment_is_the_closed_form_at_any_attitude() {
    let n = mean_motion();
    let inertia = Matrix3::from_diagonal(&Vector3::from(I));
    // A pure pitch tilt θ: M = (0, −(3/2) n² (I_x − I_z) sin 2θ, 0) in body axes (Hughes 1986, §8.1).
    let tilt = 20f64.to_radians();
    let text = scene_text(
        "attitude_lvlh_deg = [0.0, 20.0, 0.0]\nomega_lvlh = [0.0, 0.0, 0.0]",
        true,
        Form::Body,
        10.0,
        "",
    );
    let (first, _) = rows(&text)[0];
    let expected = Vector3::new(0.0, -1.5 * n * n * (I[0] - I[2]) * (2.0 * tilt).sin(), 0.0);
    // Both are the same few products of numbers of order n² I: a few ulps of |M| ~ 1e-8 N·m.
    assert!(
        (*first.m_o_b - expected).norm() < 1e-20,
        "{:?} vs {expected:?}",
        first.m_o_b
    );
    // Any attitude, at every row: M = 3 n² n̂_b × (I n̂_b) with n̂ from the orbital elements independently of
    // eulerdyn's LVLH frame (Schaub & Junkins, *Analytical Mechanics of Space Systems*, §4.6.3).
    let text = scene_text(
        "attitude_euler_deg = [40.0, -25.0, 70.0]\nomega = [0.01, -0.02, 0.03]",
        true,
        Form::Body,
        600.0,
        "",
    );
    let (inclination, raan, u0) = (51.6f64.to_radians(), 30f64.to_radians(), 10f64.to_radians());
    for (s, _) in rows(&text) {
        let nadir_b =
            s.q.inverse_transform_vector(&nadir_s(inclination, raan, u0 + n * s.t));
        let expected = 3.0 * n * n * nadir_b.cross(&(inertia * nadir_b));
        // The orbit's angle n t and the attitude carry relative round-off ~1e-14 into a moment of ~1e-7 N·m.
        assert!(
            (*s.m_o_b - expected).norm() < 1e-19,
            "t = {}: {:?} vs {expected:?}",
            s.t,
            s.m_o_b
        );
    }
}

#[test]
fn an_inertially_fixed_body_pitches_up_at_the_orbit_rate() {
    // Without a moment the body keeps its attitude in space while the LVLH frame turns at n ĥ = −n y_LVLH: seen
    // from the frame, the body turns at +n about y, pitch(t) = θ₀ + n t, roll and yaw zero. With `omega_lvlh` zero
    // instead, it turns with the frame and every angle stays.
    let n = mean_motion();
    let fixed = rows(&scene_text(
        "attitude_lvlh_deg = [0.0, -30.0, 0.0]\nomega = [0.0, 0.0, 0.0]",
        false,
        Form::Body,
        1000.0,
        "",
    ));
    for (s, [roll, pitch, yaw]) in &fixed {
        let expected = -30f64.to_radians() + n * s.t;
        assert!(
            (pitch - expected).abs() < 1e-12,
            "t = {}: {pitch} vs {expected}",
            s.t
        );
        assert!(
            roll.abs() < 1e-12 && yaw.abs() < 1e-12,
            "t = {}: {roll}, {yaw}",
            s.t
        );
    }
    // Turning with the frame about a principal axis (body y on −ĥ), a free body keeps its angles from it.
    let turning = rows(&scene_text(
        "attitude_lvlh_deg = [0.0, -30.0, 0.0]\nomega_lvlh = [0.0, 0.0, 0.0]",
        false,
        Form::Space,
        1000.0,
        "",
    ));
    for (s, [roll, pitch, yaw]) in &turning {
        let pitch_error = pitch + 30f64.to_radians();
        assert!(
            roll.abs() < 1e-10 && pitch_error.abs() < 1e-10 && yaw.abs() < 1e-10,
            "t = {}: {roll}, {pitch}, {yaw}",
            s.t
        );
    }
    // Any angles given are the first row's.
    let (_, first) = rows(&scene_text(
        "attitude_lvlh_deg = [10.0, -30.0, 45.0]",
        false,
        Form::Body,
        10.0,
        "",
    ))[0];
    let given = [10f64, -30.0, 45.0].map(f64::to_radians);
    assert!(
        (0..3).all(|k| (first[k] - given[k]).abs() < 1e-14),
        "{first:?}"
    );
    // The attitude at t = 0 is the LVLH frame's times the angles': the body's x axis, for zero angles, along the
    // velocity (the frame's x, ĥ × r̂).
    let scene = scene_from(
        &scene_text(
            "attitude_lvlh_deg = [0.0, 0.0, 0.0]",
            false,
            Form::Body,
            10.0,
            "",
        ),
        &Overrides::default(),
    );
    let (i, o, u) = (51.6f64.to_radians(), 30f64.to_radians(), 10f64.to_radians());
    let r_hat = -nadir_s(i, o, u);
    let h_hat = Vector3::new(o.sin() * i.sin(), -o.cos() * i.sin(), i.cos());
    let x_body = scene.attitude0 * Vector3::x();
    assert!((x_body - h_hat.cross(&r_hat)).norm() < 1e-15, "{x_body:?}");
}

#[test]
fn orbit_mistakes_name_their_key_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let base = scene_text("omega = [0.0, 0.0, 0.1]", true, Form::Body, 1.0, "");
    let cases = [
        (
            base.replace("[orbit]\naltitude_km = 500.0\ninclination_deg = 51.6\nraan_deg = 30.0\narg_lat_deg = 10.0\n", ""),
            "effect[0].type",
            "needs an `[orbit]`",
        ),
        (
            base.replace("altitude_km = 500.0", "altitude_km = -1.0"),
            "orbit.altitude_km",
            "must be > 0",
        ),
        (
            base.replace("altitude_km = 500.0", "altitude_km = 500.0\nradius_km = 6878.0"),
            "orbit.radius_km",
            "give either `altitude_km` or `radius_km`",
        ),
        (
            base.replace("altitude_km = 500.0", "radius_km = 6000.0"),
            "orbit.radius_km",
            "above the Earth's surface",
        ),
        (
            base.replace("[orbit]\naltitude_km = 500.0\ninclination_deg = 51.6\nraan_deg = 30.0\narg_lat_deg = 10.0\n", "")
                .replace("omega = [0.0, 0.0, 0.1]", "attitude_lvlh_deg = [0.0, 1.0, 0.0]")
                .replace("[[effect]]\ntype = \"gravity_gradient\"\n", ""),
            "initial.attitude_lvlh_deg",
            "need an `[orbit]`",
        ),
        (
            base.replace("omega = [0.0, 0.0, 0.1]", "omega = [0.0, 0.0, 0.1]\nomega_lvlh = [0.0, 0.0, 0.0]"),
            "initial.omega_lvlh",
            "give either `omega`",
        ),
        (
            base.replace("[orbit]", "[[effect]]\ntype = \"gravity\"\npivot = [0.0, 0.0, 0.1]\n[orbit]"),
            "effect[1].type",
            "does not combine with uniform `gravity`",
        ),
    ];
    for (text, key, problem) in cases {
        let path = write_file(dir.path(), "orbit.toml", &text);
        let out = dir.path().join("orbit.csv");
        let outcome = eulerdyn([
            "run".as_ref(),
            path.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
        ]);
        assert_eq!(outcome.code, Some(2), "{text}\n{}", outcome.stderr);
        assert!(
            outcome.stderr.contains(&format!("key `{key}`")) && outcome.stderr.contains(problem),
            "{key}: {}",
            outcome.stderr
        );
        assert!(!out.exists(), "{key}: a CSV was written");
    }
    let parsed = scene::parse_spec(
        std::path::Path::new("x.toml"),
        &base.replace("gravity_gradient", "gravity_gradiant"),
    )
    .unwrap_err();
    assert!(
        parsed.problem.contains("gravity_gradient"),
        "{}",
        parsed.problem
    );
}

/// Each row's time, attitude and the values of the columns `names`, of a run of `text`.
fn columns_of(text: &str, names: &[&str]) -> Vec<(f64, nalgebra::UnitQuaternion<f64>, Vec<f64>)> {
    let scene = scene_from(text, &Overrides::default());
    let columns = scene.facts().columns();
    let all: Vec<String> = columns
        .columns()
        .iter()
        .map(|c| c.name.to_string())
        .collect();
    let at: Vec<usize> = (names.iter())
        .map(|n| {
            all.iter()
                .position(|c| c == n)
                .unwrap_or_else(|| panic!("no column {n}"))
        })
        .collect();
    let mut out = Vec::new();
    simulate::run(&scene, |s| {
        let mut values = Vec::new();
        columns.values(s, &mut values);
        out.push((s.t, s.q, at.iter().map(|&k| values[k]).collect()));
        Ok::<(), std::convert::Infallible>(())
    })
    .unwrap();
    out
}

/// A body at rest in space axes on a polar 500 km orbit, `arg_lat_deg` past the node at t = 0, with the magnetic
/// effect's keys `magnetic`.
fn polar_text(arg_lat_deg: f64, magnetic: &str, initial: &str, t_end: f64) -> String {
    format!(
        "[body]\nmass = 4.0\ninertia = [{}, {}, {}]\n\
         [orbit]\naltitude_km = 500.0\ninclination_deg = 90.0\narg_lat_deg = {arg_lat_deg}\n\
         [initial]\n{initial}\n[[effect]]\ntype = \"magnetic\"\n{magnetic}\n\
         [solver]\nrtol = 1e-12\natol = 1e-14\nt_end = {t_end}\n[output]\nevery = 10.0\n",
        I[0], I[1], I[2]
    )
}

#[test]
fn the_dipole_field_over_the_poles_and_the_equator_is_the_closed_form() {
    // A centred dipole along the Earth's axis, its moment pointing south: B = B₀ (R/r)³ (ẑ − 3(ẑ·r̂) r̂) — on the
    // equator B₀ (R/r)³ northward, over either pole 2B₀ (R/r)³ along −ẑ (Jackson, *Classical Electrodynamics*,
    // 3rd ed., eq. 5.56; Wertz 1978, appendix H). The body sits at the identity, so B_b = B_s.
    let scale = 3.12e-5 * (R_EARTH / (R_EARTH + 500e3)).powi(3);
    for (arg_lat, expected) in [
        (0.0, Vector3::new(0.0, 0.0, scale)),
        (90.0, Vector3::new(0.0, 0.0, -2.0 * scale)),
        (180.0, Vector3::new(0.0, 0.0, scale)),
        (270.0, Vector3::new(0.0, 0.0, -2.0 * scale)),
    ] {
        let rows = columns_of(
            &polar_text(arg_lat, "", "", 10.0),
            &["B_b_x", "B_b_y", "B_b_z"],
        );
        let b = Vector3::from_column_slice(&rows[0].2);
        // The position's angles round to a few ulps of 1: B to ~1e-15 of its size.
        assert!(
            (b - expected).norm() < 1e-19,
            "u = {arg_lat}°: {b:?} vs {expected:?}"
        );
    }
}

#[test]
fn a_tilted_field_turns_with_the_earth_and_its_moment_is_m_cross_b() {
    // The field of a dipole tilted 11° toward longitude 40° at t = 0, turning with the Earth at 7.2921159e-5 rad/s,
    // evaluated here from the orbital elements (Vallado's position, the dipole's axis turned about z) and its
    // moment m × B_b on a tumbling body, against every row of the run, in both forms of Euler's equation.
    let magnetic = "dipole = [0.02, -0.05, 0.03]\nfield_tilt_deg = 11.0\nfield_lon_deg = 40.0";
    let run = |form| {
        let text = scene_text("omega = [0.02, -0.01, 0.03]", false, form, 3000.0, "").replace(
            "[solver]",
            &format!("[[effect]]\ntype = \"magnetic\"\n{magnetic}\n[solver]"),
        );
        columns_of(
            &text,
            &["B_b_x", "B_b_y", "B_b_z", "M_b_x", "M_b_y", "M_b_z"],
        )
    };
    let rows: Vec<_> = run(Form::Body)
        .into_iter()
        .chain(run(Form::Space))
        .collect();
    let (i, o, u0, n) = (
        51.6f64.to_radians(),
        30f64.to_radians(),
        10f64.to_radians(),
        mean_motion(),
    );
    let (tilt, lon, earth) = (11f64.to_radians(), 40f64.to_radians(), 7.2921159e-5);
    let b0 = 3.12e-5 * R_EARTH.powi(3);
    let dipole = Vector3::new(0.02, -0.05, 0.03);
    for (t, q, values) in &rows {
        let r_hat = -nadir_s(i, o, u0 + n * t);
        let r = R_EARTH + 500e3;
        let m_hat = Vector3::new(
            tilt.sin() * (lon + earth * t).cos(),
            tilt.sin() * (lon + earth * t).sin(),
            tilt.cos(),
        );
        let b_s = (m_hat - r_hat * (3.0 * m_hat.dot(&r_hat))) * (b0 / r.powi(3));
        let b_b = q.inverse_transform_vector(&b_s);
        let got_b = Vector3::new(values[0], values[1], values[2]);
        let got_m = Vector3::new(values[3], values[4], values[5]);
        // Angles of order 1e-1..1 rad rounded to ulps: B to ~1e-15 relative (|B| ~ 3e-5 T), M likewise.
        assert!(
            (got_b - b_b).norm() < 1e-18,
            "t = {t}: {got_b:?} vs {b_b:?}"
        );
        assert!(
            (got_m - dipole.cross(&b_b)).norm() < 1e-19,
            "t = {t}: {got_m:?}"
        );
    }
}

#[test]
fn magnetic_mistakes_name_their_key() {
    for (text, key, problem) in [
        (
            polar_text(0.0, "", "", 1.0).replace(
                "[orbit]\naltitude_km = 500.0\ninclination_deg = 90.0\narg_lat_deg = 0\n",
                "",
            ),
            "effect[0].type",
            "needs an `[orbit]`",
        ),
        (
            polar_text(0.0, "field_b0 = 0.0", "", 1.0),
            "effect[0].field_b0",
            "must be > 0",
        ),
        (
            polar_text(0.0, "dipole = [1.0, 2.0]", "", 1.0),
            "effect[0].dipole",
            "3 numbers",
        ),
        (
            polar_text(0.0, "c = 1.0", "", 1.0),
            "effect[0].c",
            "takes no `c`",
        ),
    ] {
        let err =
            scene::parse(std::path::Path::new("x.toml"), &text, &Overrides::default()).unwrap_err();
        assert!(
            err.key.as_deref() == Some(key) && err.problem.contains(problem),
            "{key}: {err}"
        );
    }
}

/// The LVLH axes in space at argument of latitude `u` (columns x, y, z): z = n̂ (nadir), y = −ĥ (against the orbit
/// normal), x = y × z (along the velocity) — Hughes 1986, §8.1.
fn lvlh_axes_s(inclination: f64, raan: f64, u: f64) -> Matrix3<f64> {
    let z = nadir_s(inclination, raan, u);
    let h = Vector3::new(
        raan.sin() * inclination.sin(),
        -raan.cos() * inclination.sin(),
        inclination.cos(),
    );
    let y = -h;
    Matrix3::from_columns(&[y.cross(&z), y, z])
}

/// 3-2-1 angles (roll, pitch, yaw) of R = R_z(yaw) R_y(pitch) R_x(roll).
fn angles_321(r: &Matrix3<f64>) -> [f64; 3] {
    [
        r[(2, 1)].atan2(r[(2, 2)]),
        -r[(2, 0)].asin(),
        r[(1, 0)].atan2(r[(0, 0)]),
    ]
}

#[test]
fn roll_and_yaw_exchange_their_swing_as_an_independent_integration_says() {
    // A boom (I_y > I_x > I_z: every libration stable) released 5° in roll while turning with the LVLH frame:
    // roll and yaw are coupled through the orbit's rate (Hughes 1986, §8.2), so a yaw swing grows from nothing.
    // Against an independent integration of the same system written here from scratch: I ω̇ = 3n² r̂_b × I r̂_b −
    // ω × Iω and Ṙ = R [ω]× for the rotation matrix R (body → space), classical RK4 at h = 0.5 s (|ω| h ≈ 5e-4:
    // the step's error ~(|ω|h)⁵ per step is below 1e-13 over the orbit), r̂ from the orbital elements.
    let inertia = Matrix3::from_diagonal(&Vector3::new(9.0, 10.0, 1.5));
    let (inclination, raan, u0) = (51.6f64.to_radians(), 30f64.to_radians(), 10f64.to_radians());
    let n = mean_motion();
    let text = "[body]\nmass = 20.0\ninertia = [9.0, 10.0, 1.5]\n\
         [orbit]\naltitude_km = 500.0\ninclination_deg = 51.6\nraan_deg = 30.0\narg_lat_deg = 10.0\n\
         [initial]\nattitude_lvlh_deg = [5.0, 0.0, 0.0]\nomega_lvlh = [0.0, 0.0, 0.0]\n\
         [[effect]]\ntype = \"gravity_gradient\"\n\
         [solver]\nmethod = \"dop853\"\nrtol = 1e-12\natol = 1e-14\nt_end = 6000.0\n[output]\nevery = 100.0\n";
    let rows = rows(text);
    // The independent run: R(0) = L(0) R_x(5°); ω(0) = R_body←LVLH (the frame's rate, −n along y_LVLH).
    let roll0 = nalgebra::Rotation3::from_axis_angle(&Vector3::x_axis(), 5f64.to_radians());
    let mut r_bs = lvlh_axes_s(inclination, raan, u0) * roll0.matrix();
    let mut omega_b = roll0.matrix().transpose() * Vector3::new(0.0, -n, 0.0);
    let inverse = inertia.try_inverse().unwrap();
    let rate = |t: f64, r: &Matrix3<f64>, w: &Vector3<f64>| {
        let r_hat_b = r.transpose() * -nadir_s(inclination, raan, u0 + n * t);
        let moment = 3.0 * n * n * r_hat_b.cross(&(inertia * r_hat_b));
        (
            r * w.cross_matrix(),
            inverse * (moment - w.cross(&(inertia * w))),
        )
    };
    let h = 0.5;
    let mut t = 0.0;
    let mut largest_yaw: f64 = 0.0;
    for (sample, [roll, pitch, yaw]) in &rows {
        while t < sample.t - 1e-9 {
            let (k1r, k1w) = rate(t, &r_bs, &omega_b);
            let (k2r, k2w) = rate(
                t + h / 2.0,
                &(r_bs + k1r * (h / 2.0)),
                &(omega_b + k1w * (h / 2.0)),
            );
            let (k3r, k3w) = rate(
                t + h / 2.0,
                &(r_bs + k2r * (h / 2.0)),
                &(omega_b + k2w * (h / 2.0)),
            );
            let (k4r, k4w) = rate(t + h, &(r_bs + k3r * h), &(omega_b + k3w * h));
            r_bs += (k1r + k2r * 2.0 + k3r * 2.0 + k4r) * (h / 6.0);
            omega_b += (k1w + k2w * 2.0 + k3w * 2.0 + k4w) * (h / 6.0);
            t += h;
        }
        let expected = angles_321(&(lvlh_axes_s(inclination, raan, u0 + n * t).transpose() * r_bs));
        for (got, want) in [roll, pitch, yaw].into_iter().zip(expected) {
            // Both integrations to ~1e-12 (measured: 1e-13 apart); R is not re-orthonormalised, its drift is of
            // the same order.
            assert!(
                (got - want).abs() < 1e-10,
                "t = {}: {got} vs {want}",
                sample.t
            );
        }
        largest_yaw = largest_yaw.max(yaw.abs());
    }
    // The coupling: yaw, zero at the start, swings to degrees (3.4° here).
    assert!(largest_yaw > 2f64.to_radians(), "largest yaw {largest_yaw}");
}
