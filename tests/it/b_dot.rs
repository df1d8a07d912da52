//! B-dot detumbling (`[[effect]] type = "b_dot"`) against what its law implies (Stickler & Alfriend, "Elementary
//! magnetic attitude control system", J. Spacecraft and Rockets 13(5), 1976; Markley & Crassidis, *Fundamentals of
//! Spacecraft Attitude Determination and Control*, 2014, §7.5.1): the commanded dipole m = −k dB_b/dt with
//! dB_b/dt = Rᵀ Ḃ_s − ω × B_b, evaluated here from the orbital elements and a finite difference of the field; each
//! axis clipped to ±m_max; the energy never rising but for the orbit's own part; both forms; a sweep; bad input.

use eulerdyn::Form;
use eulerdyn::scene::{self, Overrides};
use eulerdyn::simulate;
use nalgebra::{Rotation3, UnitQuaternion, Vector3};

use crate::common::{column, eulerdyn, scene_from, sweep_table, write_file};

const MU: f64 = 3.986004418e14;
const R_EARTH: f64 = 6378.137e3;
const EARTH_RATE: f64 = 7.2921159e-5;
/// A 3U CubeSat's inertia (kg·m²).
const I: [f64; 3] = [0.042, 0.040, 0.0067];
/// The orbit: 500 km, inclined 51.6°, node at 30°, the body 10° past it at t = 0.
const ORBIT: [f64; 3] = [51.6, 30.0, 10.0];
/// The field: tilted 11° toward longitude 40°, so that it turns with the Earth.
const FIELD: [f64; 3] = [11.0, 40.0, 3.12e-5];

/// The CubeSat tumbling at `omega` under B-dot of gain `gain` and limit `max_dipole`, in `form`, for `t_end` s.
fn scene_text(gain: f64, max_dipole: f64, omega: [f64; 3], form: Form, t_end: f64) -> String {
    format!(
        "[body]\nmass = 4.0\ninertia = [{}, {}, {}]\n\
         [orbit]\naltitude_km = 500.0\ninclination_deg = {}\nraan_deg = {}\narg_lat_deg = {}\n\
         [initial]\nomega = [{}, {}, {}]\n\
         [[effect]]\ntype = \"b_dot\"\ngain = {gain}\nmax_dipole = {max_dipole}\n\
         field_tilt_deg = {}\nfield_lon_deg = {}\nfield_b0 = {}\n\
         [solver]\nframe = \"{}\"\nrtol = 1e-12\natol = 1e-14\nt_end = {t_end}\n[output]\nevery = 5.0\n",
        I[0],
        I[1],
        I[2],
        ORBIT[0],
        ORBIT[1],
        ORBIT[2],
        omega[0],
        omega[1],
        omega[2],
        FIELD[0],
        FIELD[1],
        FIELD[2],
        form.name()
    )
}

/// The field B_s (T, space axes) at time `t`, from the orbital elements and the tilted dipole turning with the
/// Earth: r̂ = R_z(Ω) R_x(i) (cos u, sin u, 0), B = B₀ (R/r)³ (m̂ − 3(m̂·r̂) r̂) (Jackson, *Classical
/// Electrodynamics*, 3rd ed., eq. 5.56).
fn field_s(t: f64) -> Vector3<f64> {
    let r = R_EARTH + 500e3;
    let n = (MU / r.powi(3)).sqrt();
    let [i, raan, u0] = ORBIT.map(f64::to_radians);
    let u = u0 + n * t;
    let r_hat = Rotation3::from_axis_angle(&Vector3::z_axis(), raan)
        * Rotation3::from_axis_angle(&Vector3::x_axis(), i)
        * Vector3::new(u.cos(), u.sin(), 0.0);
    let (tilt, lon) = (FIELD[0].to_radians(), FIELD[1].to_radians());
    let m_hat = Vector3::new(
        tilt.sin() * (lon + EARTH_RATE * t).cos(),
        tilt.sin() * (lon + EARTH_RATE * t).sin(),
        tilt.cos(),
    );
    (m_hat - r_hat * (3.0 * m_hat.dot(&r_hat))) * (FIELD[2] * (R_EARTH / r).powi(3))
}

/// Ḃ_s by the fourth-order central difference (−B(t+2h) + 8B(t+h) − 8B(t−h) + B(t−2h))/12h, h = 0.5 s: the field
/// turns at harmonics of 2u, so its error (h⁴/30)|B⁽⁵⁾| is about (2n h)⁴/30 ≈ 5e-14 of |Ḃ|; round-off adds
/// u|B|/h ≈ 7e-21 T/s, 2e-13 of |Ḃ| ≈ 3.5e-8 T/s.
fn field_rate_s(t: f64) -> Vector3<f64> {
    let h = 0.5;
    (field_s(t - 2.0 * h) - field_s(t + 2.0 * h) + (field_s(t + h) - field_s(t - h)) * 8.0)
        / (12.0 * h)
}

/// One row: t, q, ω_b, and the columns B_b, m_b, M_b and the energy.
struct Row {
    t: f64,
    q: UnitQuaternion<f64>,
    omega_b: Vector3<f64>,
    b_b: Vector3<f64>,
    m_b: Vector3<f64>,
    moment_b: Vector3<f64>,
    energy: f64,
}

fn rows(text: &str) -> Vec<Row> {
    let scene = scene_from(text, &Overrides::default());
    let columns = scene.facts().columns();
    let names: Vec<String> = (columns.columns().iter())
        .map(|c| c.name.to_string())
        .collect();
    let at = |name: &str| {
        (names.iter())
            .position(|n| n == name)
            .unwrap_or_else(|| panic!("no column {name} in {names:?}"))
    };
    let vector = |values: &[f64], name: &str| {
        let k = at(&format!("{name}_x"));
        Vector3::new(values[k], values[k + 1], values[k + 2])
    };
    let mut out = Vec::new();
    simulate::run(&scene, |s| {
        let mut values = Vec::new();
        columns.values(s, &mut values);
        out.push(Row {
            t: s.t,
            q: s.q,
            omega_b: *s.omega_b,
            b_b: vector(&values, "B_b"),
            m_b: vector(&values, "m_b"),
            moment_b: vector(&values, "M_b"),
            energy: values[at("energy")],
        });
        Ok::<(), std::convert::Infallible>(())
    })
    .unwrap();
    out
}

#[test]
fn the_dipole_is_minus_k_times_the_fields_rate_in_body_axes_and_the_moment_m_cross_b() {
    // Unclipped (m_max far above k|Ḃ|): m = −k (Rᵀ Ḃ_s − ω × B_b) at every row, Ḃ_s here a finite difference of
    // the field evaluated from the elements, and M = m × B_b.
    let gain = 2.0e4;
    let rows = rows(&scene_text(
        gain,
        1.0e3,
        [0.1, -0.15, 0.08],
        Form::Body,
        3000.0,
    ));
    for row in &rows {
        let b_b = row.q.inverse_transform_vector(&field_s(row.t));
        // B from angles rounded to ulps: ~1e-15 of |B| ≈ 3e-5 T.
        assert!((row.b_b - b_b).norm() < 1e-18, "t = {}: B_b", row.t);
        let rate_b = row.q.inverse_transform_vector(&field_rate_s(row.t)) - row.omega_b.cross(&b_b);
        let m_b = -rate_b * gain;
        // The finite difference's 1e-12 of the orbit's part |Ḃ_s| (≈ 3.5e-8 T/s), ~1e-15 of ω × B (≈ 6e-6 T/s).
        let tolerance =
            gain * (1e-11 * field_rate_s(row.t).norm() + 1e-14 * row.omega_b.norm() * b_b.norm());
        assert!(
            (row.m_b - m_b).norm() < tolerance,
            "t = {}: {:?} vs {m_b:?}",
            row.t,
            row.m_b
        );
        assert!(
            (row.moment_b - row.m_b.cross(&row.b_b)).norm() < 1e-15 * row.m_b.norm() * b_b.norm(),
            "t = {}: M",
            row.t
        );
    }
}

#[test]
fn b_dot_holds_its_limit_and_never_raises_the_energy_but_by_the_orbits_part() {
    // With Ḃ_b = Rᵀ Ḃ_s + B_b × ω, the moment's power is P = ω·(m × B_b) = m·(B_b × ω) = Σᵢ mᵢ Ḃᵢ − m·Rᵀ Ḃ_s, and
    // mᵢ = clip(−k Ḃᵢ) has the sign of −Ḃᵢ: the sum is never positive, so P ≤ |m| |Ḃ_s| at every instant
    // (Markley & Crassidis 2014, §7.5.1, for the unclipped law). Both forms; the torquers saturate.
    let max_dipole = 0.05;
    for form in [Form::Body, Form::Space] {
        let rows = rows(&scene_text(
            1.0e5,
            max_dipole,
            [0.1, -0.15, 0.08],
            form,
            6000.0,
        ));
        let mut saturated = 0;
        for row in &rows {
            // The clip is exact: no axis beyond the limit.
            assert!(row.m_b.amax() <= max_dipole, "t = {}: {:?}", row.t, row.m_b);
            saturated += usize::from(row.m_b.amax() == max_dipole);
            let power = row.omega_b.dot(&row.moment_b);
            let bound = row.m_b.norm() * field_rate_s(row.t).norm();
            // Rounding of the products: 1e-15 of |ω| |M|.
            assert!(
                power <= bound + 1e-15 * row.omega_b.norm() * row.moment_b.norm(),
                "{form:?} t = {}: P = {power:e} > {bound:e}",
                row.t
            );
        }
        assert!(
            saturated > rows.len() / 10,
            "{form:?}: saturated in {saturated} rows"
        );
        // Between rows, T rises by at most √3 m_max max|Ḃ_s| Δt (the bound above integrated), beyond the
        // integration's error (rtol 1e-12 of T).
        let rate_max = (0..=1200)
            .map(|k| field_rate_s(k as f64 * 5.0).norm())
            .fold(0.0, f64::max)
            * 1.01;
        for pair in rows.windows(2) {
            let rise = pair[1].energy - pair[0].energy;
            let bound = 3f64.sqrt() * max_dipole * rate_max * (pair[1].t - pair[0].t);
            assert!(
                rise <= bound + 1e-10 * pair[0].energy,
                "{form:?} t = {}: {rise:e}",
                pair[0].t
            );
        }
        // And the tumble is being taken out: the energy falls by more than half in the run.
        let (first, last) = (rows[0].energy, rows[rows.len() - 1].energy);
        assert!(last < 0.5 * first, "{form:?}: {first} → {last}");
    }
}

#[test]
fn both_forms_of_eulers_equation_detumble_alike() {
    // The body form integrates I ω̇ = M − ω × Iω, the space form Ḣ_s = M_s with I_s(q): the same motion.
    let run = |form| rows(&scene_text(1.0e5, 0.05, [0.1, -0.15, 0.08], form, 2000.0));
    let (body, space) = (run(Form::Body), run(Form::Space));
    assert_eq!(body.len(), space.len());
    for (b, s) in body.iter().zip(&space) {
        // rtol 1e-12 over some 60 radians of tumble, and a saturating (non-smooth) law: 1e-7 rad/s of 0.2.
        assert!((b.omega_b - s.omega_b).norm() < 1e-7, "t = {}", b.t);
    }
}

#[test]
fn a_sweep_over_gains_and_inertias_never_ends_with_more_energy() {
    // Every run of a grid over the gain and the inertia: the final energy below the initial (B-dot takes energy out
    // but for the orbit's tiny part), each run `ok`.
    let dir = tempfile::tempdir().unwrap();
    let base = write_file(
        dir.path(),
        "base.toml",
        scene_text(1.0e5, 0.2, [0.1, -0.15, 0.08], Form::Body, 3000.0)
            .replace("rtol = 1e-12\natol = 1e-14", "rtol = 1e-9"),
    );
    let sweep = write_file(
        dir.path(),
        "sweep.toml",
        format!(
            "scene = \"{}\"\n[[vary]]\nkey = \"effect.0.gain\"\nlogspace = [1.0e3, 1.0e6, 4]\n\
             [[vary]]\nkey = \"body.inertia.2\"\nvalues = [0.0067, 0.02]\n[summary]\ncolumns = [\"energy\"]\n",
            base.display()
        ),
    );
    let (head, rows) = sweep_table(&sweep, dir.path());
    assert_eq!(rows.len(), 8);
    let status = head.iter().position(|h| h == "status").unwrap();
    assert!(rows.iter().all(|row| &row[status] == "ok"), "{rows:?}");
    // T(0) = ½ Σ Iᵢ ωᵢ² of each run's inertia; the energy never exceeds it by more than the orbit's part
    // integrated, √3 m_max max|Ḃ_s| t_end, and ends below it.
    let rate_max = (0..=600)
        .map(|k| field_rate_s(k as f64 * 5.0).norm())
        .fold(0.0, f64::max)
        * 1.01;
    let allowance = 3f64.sqrt() * 0.2 * rate_max * 3000.0;
    let i_z = column(&head, &rows, "body.inertia.2");
    let (largest, last) = (
        column(&head, &rows, "max_energy"),
        column(&head, &rows, "final_energy"),
    );
    for run in 0..rows.len() {
        let t0 =
            0.5 * (I[0] * 0.1f64.powi(2) + I[1] * 0.15f64.powi(2) + i_z[run] * 0.08f64.powi(2));
        assert!(
            largest[run] <= t0 * (1.0 + 1e-9) + allowance,
            "run {run}: {} vs {t0}",
            largest[run]
        );
        assert!(last[run] < t0, "run {run}: {} vs {t0}", last[run]);
    }
}

#[test]
fn b_dot_mistakes_name_their_key_and_write_nothing() {
    let good = scene_text(1.0e5, 0.2, [0.1, 0.0, 0.0], Form::Body, 10.0);
    let without_orbit = good.replace(
        "[orbit]\naltitude_km = 500.0\ninclination_deg = 51.6\nraan_deg = 30\narg_lat_deg = 10\n",
        "",
    );
    assert!(!without_orbit.contains("[orbit]"));
    for (text, key, problem) in [
        (without_orbit, "effect[0].type", "needs an `[orbit]`"),
        (
            good.replace("gain = 100000", "gain = -1.0"),
            "effect[0].gain",
            "must be >= 0",
        ),
        (
            good.replace("max_dipole = 0.2", "max_dipole = -0.1"),
            "effect[0].max_dipole",
            "must be >= 0",
        ),
        (
            good.replace("gain = 100000\n", ""),
            "effect[0].gain",
            "missing",
        ),
        (
            good.replace("[solver]\n", "[solver]\nmethod = \"split2\"\n"),
            "solver.method",
            "depends on omega",
        ),
        (
            good.replace(
                "[solver]",
                "[[effect]]\ntype = \"magnetic\"\nfield_b0 = 3.0e-5\n[solver]",
            ),
            "effect[1].field_b0",
            "one Earth",
        ),
        (
            good.replace("gain = 100000", "gain = 1.0e5\ndipole = [0.0, 0.0, 1.0]"),
            "effect[0].dipole",
            "takes no `dipole`",
        ),
    ] {
        let err = scene::parse(std::path::Path::new("x.toml"), &text, &Overrides::default())
            .expect_err(&text);
        assert!(
            err.key.as_deref() == Some(key) && err.problem.contains(problem),
            "{key}: {err}"
        );
        // From the command line: exit 2 naming the file and key, no CSV written.
        let dir = tempfile::tempdir().unwrap();
        let scene = write_file(dir.path(), "bad.toml", &text);
        let out = dir.path().join("out.csv");
        let outcome = eulerdyn(["run", scene.to_str().unwrap(), "-o", out.to_str().unwrap()]);
        outcome.expect_code(2);
        assert!(
            outcome.stderr.contains("bad.toml") && outcome.stderr.contains(key),
            "{}",
            outcome.stderr
        );
        assert!(!out.exists(), "{key}: nothing written");
    }
}

#[test]
fn a_misspelt_effect_type_suggests_b_dot() {
    let text =
        scene_text(1.0e5, 0.2, [0.1, 0.0, 0.0], Form::Body, 10.0).replace("\"b_dot\"", "\"bdot\"");
    let err =
        scene::parse(std::path::Path::new("x.toml"), &text, &Overrides::default()).unwrap_err();
    assert!(
        err.key.as_deref() == Some("effect[0].type")
            && err.problem.contains("the nearest is `b_dot`"),
        "{err}"
    );
}
