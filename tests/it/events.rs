//! `[[event]]`: moments located between the rows on the continuous solution, against closed forms.

use std::f64::consts::PI;

use eulerdyn::events::{Kind, Occurrence};
use eulerdyn::exact::{JacobiElliptic, TorqueFreeBody};
use eulerdyn::scene::Overrides;
use eulerdyn::simulate;
use nalgebra::{UnitQuaternion, Vector3};

use crate::common::{eulerdyn, scene_from, write_file};

/// A compound pendulum: a thin rod (1 kg, 1 m) hinged at one end, released from rest at `theta0_deg`, hanging along
/// −y at θ = 0 (as scenarios/rod_pendulum.toml), with rows every 0.05 s and the events given.
pub fn pendulum(theta0_deg: f64, method: &str, t_end: f64, events: &str) -> String {
    format!(
        r#"[body]
mass = 1.0
shape = {{ type = "thin_rod", length = 1.0 }}
[motion]
type = "hinge"
axis = [0.0, 0.0, 1.0]
point = [-0.5, 0.0, 0.0]
angle_deg = {theta0_deg}
[initial]
attitude = [0.7071067811865476, 0.0, 0.0, -0.7071067811865476]
[[effect]]
type = "gravity"
g = [0.0, -9.81, 0.0]
{events}
[solver]
method = "{method}"
t_end = {t_end}
[output]
every = 0.05
"#
    )
}

/// The compound pendulum's period T = 4 K(k) √(I_A/(m g d)), k = sin(θ₀/2) (Landau & Lifshitz, *Mechanics*, §11,
/// problem 1 — the simple pendulum's period with l = I_A/(m d); Goldstein, *Classical Mechanics*, 3rd ed., §3.6
/// ex.), for the rod: I_A = m l²/3, d = l/2.
fn pendulum_period(theta0_deg: f64) -> f64 {
    let k = (theta0_deg.to_radians() / 2.0).sin();
    let quarter = JacobiElliptic::new(k * k).unwrap().quarter_period();
    let (i_a, mgd): (f64, f64) = (1.0 / 3.0, 9.81 * 0.5);
    4.0 * quarter * (i_a / mgd).sqrt()
}

fn occurrences(text: &str) -> (Vec<Occurrence>, simulate::RunReport, Vec<f64>) {
    let scene = scene_from(text, &Overrides::default());
    let mut times = Vec::new();
    let (report, events) = simulate::run_with_events(&scene, |s| {
        times.push(s.t);
        Ok::<(), std::convert::Infallible>(())
    })
    .unwrap();
    (events, report, times)
}

/// The largest |spacing − expected| of consecutive occurrences' times.
fn spacing_error(events: &[Occurrence], expected: f64) -> f64 {
    (events.windows(2))
        .map(|w| (w[1].t - w[0].t - expected).abs())
        .fold(0.0, f64::max)
}

const THETA_DOWN: &str = r#"[[event]]
name = "down"
when = "theta"
crosses = 0.0
direction = "down""#;

#[test]
fn pendulum_period_from_theta_crossings() {
    // Rows every 0.05 s do not matter: the crossings are located on the steps' dense output.
    let period = pendulum_period(30.0);
    for (method, tol) in [("dop853", 1e-9), ("dopri5", 1e-9), ("rk4", 1e-7)] {
        let (events, _, _) = occurrences(&pendulum(30.0, method, 10.0, THETA_DOWN));
        assert!(events.len() >= 5, "{method}: {events:?}");
        assert!(
            events
                .iter()
                .all(|e| e.kind == Kind::Down && e.value.abs() < 1e-12)
        );
        let err = spacing_error(&events, period);
        eprintln!("{method}: period error {err:e}");
        assert!(err < tol, "{method}: period error {err:e}");
        // The first crossing of θ = 0 is a quarter period after the release from rest.
        assert!(
            (events[0].t - period / 4.0).abs() < tol,
            "{method}: {}",
            events[0].t
        );
    }
}

#[test]
fn terminal_event_ends_the_run_at_the_quarter_period() {
    let stop = format!("{THETA_DOWN}\nstop = true");
    let (events, report, times) = occurrences(&pendulum(30.0, "dop853", 10.0, &stop));
    let quarter = pendulum_period(30.0) / 4.0;
    assert_eq!(events.len(), 1);
    assert!((events[0].t - quarter).abs() < 1e-9, "{}", events[0].t);
    // The rows: every 0.05 s up to the event, then one at the event's time, and no more.
    assert_eq!(*times.last().unwrap(), events[0].t);
    assert_eq!(times.len(), (quarter / 0.05).floor() as usize + 2);
    assert_eq!(report.rows as usize, times.len());
}

/// A tennis racket (the body of scenarios/tennis_racket.toml, spun further from the separatrix so that the flips are
/// less sensitive to the integration error) with ω_y's sign changes as events, run with `method`.
fn racket(method: &str) -> String {
    format!(
        r#"[body]
mass = 1.0
inertia = [1.0, 2.0, 3.0]
[initial]
omega = [0.2, 2.0, 0.2]
[[event]]
name = "flip"
when = "omega_b_y"
crosses = 0.0
[solver]
method = "{method}"
rtol = 1e-12
atol = 1e-14
t_end = 60.0
[output]
every = 0.05
"#
    )
}

#[test]
fn dzhanibekov_flips_are_2k_over_lambda_apart() {
    // The intermediate component ∝ sn τ changes sign every 2K(k)/λ (Landau & Lifshitz, *Mechanics*, §37, eq.
    // (37.10) and after: the period of sn is 4K); core/src/exact/torque_free.rs's flip_interval.
    let exact = TorqueFreeBody::new(
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(0.2, 2.0, 0.2),
        UnitQuaternion::identity(),
    )
    .unwrap();
    let interval = exact.flip_interval().unwrap();
    let mut errors = Vec::new();
    for method in ["dop853", "dopri5", "exact"] {
        let (events, _, _) = occurrences(&racket(method));
        assert!(events.len() >= 3, "{method}: {events:?}");
        let kinds: Vec<Kind> = events.iter().map(|e| e.kind).collect();
        assert!(
            kinds.windows(2).all(|w| w[0] != w[1]),
            "{method}: {kinds:?}"
        );
        let err = spacing_error(&events, interval);
        eprintln!("{method}: flip spacing error {err:e} (2K/λ = {interval})");
        errors.push((method, err));
    }
    for (method, err) in errors {
        assert!(err < 1e-9, "{method}: {err:e}");
    }
}

#[test]
fn sine_driven_hinge_rate_extrema() {
    // A disk on a hinge through C (I = m r²/2 = 0.5 kg·m²) from rest, driven by M sin(ω_f t) about the axis:
    // θ̇ = M/(I ω_f)·(1 − cos ω_f t) (integrating θ̈ = M sin(ω_f t)/I), so the rate's maxima are at
    // t = (2j+1)π/ω_f with the value 2M/(I ω_f), its minima (zero) at 2jπ/ω_f, j ≥ 1.
    let (m, i, f) = (0.3, 0.5, 0.7);
    let omega_f = 2.0 * PI * f;
    for method in ["dop853", "dopri5"] {
        let text = sine_hinge(m, 0.05, method, 6.0, true);
        let (events, _, _) = occurrences(&text);
        let maxima: Vec<&Occurrence> = events.iter().filter(|e| e.kind == Kind::Max).collect();
        let minima: Vec<&Occurrence> = events.iter().filter(|e| e.kind == Kind::Min).collect();
        assert_eq!(maxima.len(), 4, "{method}: {events:?}");
        assert_eq!(minima.len(), 4, "{method}: {events:?}");
        for (j, e) in maxima.iter().enumerate() {
            let t = (2 * j + 1) as f64 * PI / omega_f;
            eprintln!("{method}: max {j} at {} (error {:e})", e.t, e.t - t);
            assert!(
                (e.t - t).abs() < 1e-7,
                "{method}: max {j} at {} vs {t}",
                e.t
            );
            assert!((e.value - 2.0 * m / (i * omega_f)).abs() < 1e-9);
        }
        for (j, e) in minima.iter().enumerate() {
            let t = (2 * j + 2) as f64 * PI / omega_f;
            assert!(
                (e.t - t).abs() < 1e-7,
                "{method}: min {j} at {} vs {t}",
                e.t
            );
            assert!(e.value.abs() < 1e-9);
        }
    }
}

#[test]
fn run_writes_the_events_file_and_lists_it() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(
        dir.path(),
        "p.toml",
        pendulum(30.0, "dop853", 3.0, THETA_DOWN),
    );
    let out = dir.path().join("p.csv");
    eulerdyn([
        "run".as_ref(),
        scene.as_os_str(),
        "-o".as_ref(),
        out.as_os_str(),
    ])
    .expect_code(0);
    let text = std::fs::read_to_string(dir.path().join("p.csv.events.csv")).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "event,t,value,direction");
    assert_eq!(lines.len(), 1 + 2, "{text}");
    assert!(lines[1].starts_with("down,") && lines[1].ends_with(",down"));
    let meta = std::fs::read_to_string(dir.path().join("p.csv.meta.json")).unwrap();
    assert!(meta.contains("\"file\": \"p.csv.events.csv\""), "{meta}");
    // Without -o, the table goes to stderr and stdout stays the CSV.
    let run = eulerdyn(["run".as_ref(), scene.as_os_str()]);
    run.expect_code(0);
    assert!(run.stdout.starts_with("t,"));
    assert!(
        run.stderr.contains("event") && run.stderr.contains("down"),
        "{}",
        run.stderr
    );
}

#[test]
fn bad_events_exit_2_naming_key_and_line() {
    let cases = [
        (
            "when = \"omega_q\"\ncrosses = 0.0",
            "event[0].when",
            "not a column",
        ),
        (
            "when = \"|R_A|\"\ncrosses = 1.0",
            "event[0].when",
            "R_A_s_x",
        ),
        (
            "when = \"theta\"\ncrosses = 0.0\nextremum = \"max\"",
            "event[0].extremum",
            "not both",
        ),
        ("when = \"theta\"", "event[0]", "needs `crosses"),
        (
            "when = \"theta\"\ncrosses = 0.0\ndirection = \"sideways\"",
            "sideways",
            "up",
        ),
        (
            "when = \"theta\"\nextremum = \"max\"\ndirection = \"up\"",
            "event[0].direction",
            "crosses",
        ),
    ];
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("bad.csv");
    for (body, key, problem) in cases {
        let event = format!("[[event]]\nname = \"e\"\n{body}");
        let scene = write_file(
            dir.path(),
            "bad.toml",
            pendulum(30.0, "dop853", 1.0, &event),
        );
        let run = eulerdyn([
            "run".as_ref(),
            scene.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
        ]);
        run.expect_code(2);
        assert!(
            run.stderr.contains(key) && run.stderr.contains(problem),
            "{body}: {}",
            run.stderr
        );
        assert!(run.stderr.contains("bad.toml:"), "{}", run.stderr);
        assert!(!out.exists() && !run.panicked());
    }
    let two = format!("{THETA_DOWN}\n{THETA_DOWN}");
    let scene = write_file(dir.path(), "dup.toml", pendulum(30.0, "dop853", 1.0, &two));
    let run = eulerdyn(["run".as_ref(), scene.as_os_str()]);
    run.expect_code(2);
    assert!(
        run.stderr.contains("event[1].name") && run.stderr.contains("unique"),
        "{}",
        run.stderr
    );
    let bad_name = THETA_DOWN.replace("\"down\"\nwhen", "\"a-b\"\nwhen");
    let scene = write_file(
        dir.path(),
        "name.toml",
        pendulum(30.0, "dop853", 1.0, &bad_name),
    );
    let run = eulerdyn(["run".as_ref(), scene.as_os_str()]);
    run.expect_code(2);
    assert!(run.stderr.contains("event[0].name"), "{}", run.stderr);
}

/// A disk on a hinge through C (I = m r²/2 = 0.5 kg·m²) from rest, driven by `m` sin(2π·0.7 t) N·m about the axis
/// with `method`, rows every `every` s to `t_end`, and the event `fastest` on θ̇'s maxima (and `slowest` on its
/// minima when `minima`).
fn sine_hinge(m: f64, every: f64, method: &str, t_end: f64, minima: bool) -> String {
    let slowest = if minima {
        "[[event]]\nname = \"slowest\"\nwhen = \"theta_dot\"\nextremum = \"min\"\n"
    } else {
        ""
    };
    format!(
        r#"[body]
mass = 1.0
shape = {{ type = "thin_disk", radius = 1.0 }}
[motion]
type = "hinge"
axis = [0.0, 0.0, 1.0]
[[effect]]
type = "torque"
value = [0.0, 0.0, {m}]
profile = "sine"
freq_hz = 0.7
[[event]]
name = "fastest"
when = "theta_dot"
extremum = "max"
{slowest}[solver]
method = "{method}"
t_end = {t_end}
[output]
every = {every}
"#
    )
}

#[test]
fn a_sweep_reports_the_located_maximum_where_its_rows_miss_the_peak() {
    // θ̇ = M/(I ω_f)(1 − cos ω_f t) peaks at 2M/(I ω_f) at t = (2j+1)π/ω_f = 0.714 s, 2.143 s (see
    // sine_driven_hinge_rate_extrema); rows every 0.5 s miss both: the largest row value is at t = 2.0 s,
    // (1 − cos 2ω_f)/2 = 0.905 of the peak. The sweep's located `fastest_max` is the closed form's peak, its sampled
    // `max_theta_dot` that row's value.
    let dir = tempfile::tempdir().unwrap();
    write_file(
        dir.path(),
        "base.toml",
        sine_hinge(0.3, 0.5, "dop853", 3.0, false),
    );
    let sweep = write_file(
        dir.path(),
        "sweep.toml",
        "scene = \"base.toml\"\n[[vary]]\nkey = \"effect.0.value.2\"\nvalues = [0.3, 0.6]\n[summary]\ncolumns = [\"theta_dot\"]\n",
    );
    let (head, rows) = crate::common::sweep_table(&sweep, dir.path());
    let located = crate::common::column(&head, &rows, "fastest_max");
    let sampled = crate::common::column(&head, &rows, "max_theta_dot");
    let omega_f = 2.0 * PI * 0.7;
    for (run, m) in [0.3, 0.6].into_iter().enumerate() {
        let peak = 2.0 * m / (0.5 * omega_f);
        assert!(
            (located[run] - peak).abs() <= 1e-9 * peak,
            "run {run}: located {} vs {peak}",
            located[run]
        );
        let at_row = peak * (1.0 - (2.0 * omega_f).cos()) / 2.0;
        assert!(
            (sampled[run] - at_row).abs() <= 1e-9 * peak && sampled[run] < 0.95 * located[run],
            "run {run}: the rows miss the peak: sampled {} (row at 2 s: {at_row}) vs located {}",
            sampled[run],
            located[run]
        );
    }
}

#[test]
fn a_spin_up_loads_its_bearings_past_a_threshold_when_the_closed_form_says() {
    // The notes' disk (m = 2 kg, R = 0.3 m) skewed θ = 30° on its shaft through C, spun up from rest at α: the
    // moment across the axis is c·√(α² + ω⁴) with c = (I₃ − I₁) sin θ cos θ = ¼ m R² sin θ cos θ and ω = α t
    // (M = I α u + ω u × I ω u, eqs. 8.9–8.10 of the notes: the two parts are perpendicular), carried by the
    // bearings as a couple: |R_A| = c √(α² + α⁴ t⁴)/(b − a). It reaches R* at t* = ((R*(b − a)/c)² − α²)^¼ / α.
    let (m, r, theta, alpha, (a, b), r_star) =
        (2.0, 0.3, 30f64.to_radians(), 2.0, (-0.1, 0.15), 1.0);
    let c = 0.25 * m * r * r * theta.sin() * theta.cos();
    let t_star = ((r_star * (b - a) / c).powi(2) - alpha * alpha).powf(0.25) / alpha;
    let text = format!(
        r#"[body]
mass = {m}
shape = {{ type = "thin_disk", radius = {r} }}
[motion]
type = "fixed_axis"
tilt_deg = 30.0
accel = {alpha}
bearings = [{a}, {b}]
[[event]]
name = "rated"
when = "|R_A|"
crosses = {r_star}
direction = "up"
[solver]
t_end = 3.0
[output]
every = 0.5
"#
    );
    let (events, _, _) = occurrences(&text);
    assert_eq!(events.len(), 1, "{events:?}");
    assert!(
        (events[0].t - t_star).abs() <= 1e-9,
        "|R_A| = {r_star} N at {} s, closed form {t_star} s",
        events[0].t
    );
}

#[test]
fn a_stop_exactly_on_a_row_ends_the_run_with_that_row_once() {
    // A prescribed spin-up θ̇ = α t with α = 2 rad/s² crosses 3 rad/s at t = 1.5 s, exactly on a row (every 0.5 s).
    for method in ["rk4", "dop853", "exact"] {
        let text = format!(
            r#"[body]
mass = 2.0
shape = {{ type = "thin_disk", radius = 0.3 }}
[motion]
type = "fixed_axis"
tilt_deg = 30.0
accel = 2.0
[[event]]
name = "fast"
when = "theta_dot"
crosses = 3.0
stop = true
[solver]
method = "{method}"
t_end = 3.0
[output]
every = 0.5
"#
        );
        let (events, report, times) = occurrences(&text);
        assert_eq!(times, [0.0, 0.5, 1.0, 1.5], "{method}: rows");
        assert_eq!(report.rows, 4, "{method}");
        assert_eq!(
            (events.len(), events[0].t),
            (1, 1.5),
            "{method}: {events:?}"
        );
    }
}
