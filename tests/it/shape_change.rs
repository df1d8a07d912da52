//! Bodies that change shape (`[[body.moving_mass]]`, `[body] inertia_table`): M = d/dt(I·ω) about the system's
//! moving centre of mass, against closed forms, an independent formulation, both forms, and bad input.
//!
//! Closed forms: without external moment the moment of momentum about the centre of mass is constant (Rigid-body
//! dynamics, lecture notes, Thm 24; Landau & Lifshitz, *Mechanics*, §9); a body spinning about a symmetry axis
//! whose masses move symmetrically in the plane of the spin keeps ω along the axis, so ω = H / I_zz(t) and
//! T = H²/(2 I_zz) + Σ ½ m |ṙ|² (Kleppner & Kolenkow, *An Introduction to Mechanics*, 2nd ed., §7.3, the skater).

use eulerdyn::integrate::{self, OdeSystem, Schedule, Settings};
use eulerdyn::scene::{Overrides, Scene};
use eulerdyn::simulate;
use eulerdyn::{Form, Method, Sample};
use nalgebra::{Matrix3, SVector, UnitQuaternion, Vector3};

use crate::common::{
    assert_refused_writing_nothing, eulerdyn, scene_from, sweep_table, write_file,
};

/// The rows of `scene` and the values of its column `name` at each.
fn run(scene: &Scene) -> Vec<Sample> {
    simulate::samples(scene).unwrap().0
}

/// The values of column `name` at each row of `scene`'s run `rows`.
fn column(scene: &Scene, rows: &[Sample], name: &str) -> Vec<f64> {
    let columns = scene.facts().columns();
    let k = (columns.columns().iter())
        .position(|c| c.name == name)
        .unwrap_or_else(|| panic!("no column {name}"));
    let mut out = Vec::new();
    rows.iter()
        .map(|s| {
            columns.values(s, &mut out);
            out[k]
        })
        .collect()
}

/// The skater: an axisymmetric body (I = diag(2, 2, 3) kg·m², 10 kg) spinning at 4 rad/s about z, with a pair of
/// 0.5 kg masses moved from ±0.2 m to ±1.2 m along x between t = 1 and 5 s with `profile`; in `form` by `method`.
fn skater(profile: &str, form: Form, method: &str) -> String {
    let mass = |sign: f64, name: &str| {
        format!(
            "[[body.moving_mass]]\nname = \"{name}\"\nmass = 0.5\nfrom = [{}, 0.0, 0.0]\nto = [{}, 0.0, 0.0]\n\
             start = 1.0\nduration = 4.0\nprofile = \"{profile}\"\n",
            0.2 * sign,
            1.2 * sign
        )
    };
    format!(
        "[body]\nmass = 10.0\ninertia = [2.0, 2.0, 3.0]\n{}{}[initial]\nomega = [0.0, 0.0, 4.0]\n\
         [solver]\nmethod = \"{method}\"\nframe = \"{}\"\nrtol = 1e-12\natol = 1e-12\ndt = 1e-3\nt_end = 7.0\n\
         [output]\nevery = 0.05\n",
        mass(1.0, "left"),
        mass(-1.0, "right"),
        form.name()
    )
}

/// The skater's arm r(t), ṙ, r̈ (m): 0.2 + s(τ), τ = (t − 1)/4, s the profile.
fn arm(profile: &str, t: f64) -> (f64, f64, f64) {
    let tau = (t - 1.0) / 4.0;
    if !(0.0..1.0).contains(&tau) {
        return (if tau < 0.0 { 0.2 } else { 1.2 }, 0.0, 0.0);
    }
    match profile {
        "linear" => (0.2 + tau, 0.25, 0.0),
        _ => (
            0.2 + tau * tau * (3.0 - 2.0 * tau),
            6.0 * tau * (1.0 - tau) / 4.0,
            (6.0 - 12.0 * tau) / 16.0,
        ),
    }
}

#[test]
fn the_skater_turns_at_h_over_i_zz_and_its_drives_supply_the_energy() {
    let h = 3.0 * 4.0 + 2.0 * 0.5 * 0.04 * 4.0;
    for profile in ["smooth", "linear"] {
        for form in [Form::Body, Form::Space] {
            let scene = scene_from(&skater(profile, form, "dop853"), &Overrides::default());
            let rows = run(&scene);
            let power = column(&scene, &rows, "P_internal");
            let i_zz = column(&scene, &rows, "I_b_zz");
            for (s, (p, i)) in rows.iter().zip(power.iter().zip(&i_zz)) {
                let (r, v, a) = arm(profile, s.t);
                let inertia = 3.0 + 2.0 * 0.5 * r * r;
                // dop853 at rtol = atol = 1e-12: the error a thousand times that, relative.
                assert!(
                    (i - inertia).abs() <= 1e-14 * inertia,
                    "{profile} t={}",
                    s.t
                );
                assert!(
                    (s.omega_b.z - h / inertia).abs() <= 1e-9 * h / inertia,
                    "{profile} {form:?} t={}: {}",
                    s.t,
                    s.omega_b.z
                );
                assert!(s.omega_b.x.abs() + s.omega_b.y.abs() <= 1e-12);
                let energy = h * h / (2.0 * inertia) + 0.5 * v * v;
                assert!(
                    (s.energy - energy).abs() <= 1e-9 * energy,
                    "{profile} t={}",
                    s.t
                );
                // dT/dt = −H² İ_zz/(2 I_zz²) + 2 m ṙ r̈ with İ_zz = 4 m r ṙ.
                let power_exact = -h * h * (2.0 * r * v) / (2.0 * inertia * inertia) + v * a;
                assert!(
                    (p - power_exact).abs() <= 1e-9 * (1.0 + power_exact.abs()),
                    "{profile} t={}: {p} vs {power_exact}",
                    s.t
                );
                // H_s constant: exactly in the space form (Ḣ_s = 0), to the tolerance in the body form.
                let allowed = if form == Form::Space { 0.0 } else { 1e-9 * h };
                assert!(
                    (s.h_o_s - rows[0].h_o_s).norm() <= allowed,
                    "{form:?} t={}",
                    s.t
                );
            }
        }
    }
}

#[test]
fn every_runge_kutta_method_and_backend_agrees_on_the_skater() {
    let reference = run(&scene_from(
        &skater("smooth", Form::Space, "dop853"),
        &Overrides::default(),
    ));
    for (method, backend, allowed) in [
        ("dopri5", "own", 1e-9),
        ("dop853", "ode_solvers", 1e-9),
        // rk4 at dt = 1 ms: error C (ω dt)⁴ ω t with ω ≤ 14 rad/s, a few 1e-8.
        ("rk4", "own", 1e-6),
    ] {
        for form in [Form::Body, Form::Space] {
            let text = skater("smooth", form, method)
                .replace("[solver]", &format!("[solver]\nbackend = \"{backend}\""));
            let rows = run(&scene_from(&text, &Overrides::default()));
            for (a, b) in rows.iter().zip(&reference) {
                assert!(
                    (a.omega_b - b.omega_b).norm() <= allowed * 14.0,
                    "{method} {backend} {form:?} t={}",
                    a.t
                );
                assert!(
                    a.q.angle_to(&b.q) <= allowed * 100.0,
                    "{method} {form:?} t={}",
                    a.t
                );
            }
        }
    }
}

#[test]
fn a_mass_moved_along_the_spin_axis_changes_nothing_of_the_spin() {
    // A mass on the spin axis adds μ P(r) with r ∥ z: nothing to I_zz or the products, and h = μ r × ṙ = 0; so
    // H_b = I ω stays (0, 0, I_zz ω_z) and ω stays ω₀ to round-off.
    let text = "[body]\nmass = 5.0\ninertia = [1.0, 1.5, 2.0]\n[[body.moving_mass]]\nmass = 0.3\n\
                from = [0.0, 0.0, 0.1]\nto = [0.0, 0.0, 0.9]\nstart = 0.5\nduration = 2.0\n\
                [initial]\nomega = [0.0, 0.0, 5.0]\n[solver]\nt_end = 4.0\n[output]\nevery = 0.25\n";
    for form in [Form::Body, Form::Space] {
        let scene = scene_from(
            text,
            &Overrides {
                form: Some(form),
                ..Overrides::default()
            },
        );
        let rows = run(&scene);
        let c_z = column(&scene, &rows, "C_b_z");
        assert!((c_z.last().unwrap() - 0.3 * 0.9 / 5.3).abs() < 1e-15);
        for s in &rows {
            assert!(
                (s.omega_b.into_inner() - Vector3::new(0.0, 0.0, 5.0)).amax() <= 1e-14,
                "{form:?} {}",
                s.omega_b
            );
        }
    }
}

#[test]
fn a_constant_inertia_table_reproduces_the_rigid_run() {
    let dir = tempfile::tempdir().unwrap();
    let tensor = "[[2.0, 0.1, -0.05], [0.1, 2.5, 0.2], [-0.05, 0.2, 3.2]]";
    write_file(
        dir.path(),
        "inertia.csv",
        "t,I_xx,I_yy,I_zz,I_xy,I_xz,I_yz\n0,2.0,2.5,3.2,0.1,-0.05,0.2\n10,2.0,2.5,3.2,0.1,-0.05,0.2\n",
    );
    let rigid = format!(
        "[body]\nmass = 5.0\ninertia = {tensor}\n[initial]\nomega = [0.7, -1.2, 2.5]\n\
         [solver]\nrtol = 1e-12\natol = 1e-12\nt_end = 8.0\n[output]\nevery = 0.1\n"
    );
    let table = rigid.replace("[initial]", "inertia_table = \"inertia.csv\"\n[initial]");
    for form in [Form::Body, Form::Space] {
        let overrides = Overrides {
            form: Some(form),
            ..Overrides::default()
        };
        let a = run(&scene_from(&rigid, &overrides));
        let path = write_file(dir.path(), "table.toml", &table);
        let b = run(&eulerdyn::scene::load(&path, &overrides).unwrap());
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(&b) {
            // Two integrations of one equation, each to rtol = 1e-12 over ~25 rad: agreement to 1e-9.
            assert!((x.omega_b - y.omega_b).norm() <= 1e-9, "{form:?} t={}", x.t);
            assert!(x.q.angle_to(&y.q) <= 1e-9, "{form:?} t={}", x.t);
            assert!((x.energy - y.energy).abs() <= 1e-9 * x.energy);
        }
    }
}

#[test]
fn a_major_axis_spinner_that_deploys_until_that_axis_is_intermediate_tumbles() {
    // I = diag(2, 2.5, 3), spin about z, the major axis (stable: Landau & Lifshitz §37; the notes' stability of
    // rotation about the principal axes). A pair of 0.3 kg masses deployed along ±z to 1 m adds 2 m z² to I_xx
    // and I_yy: (2.6, 3.1, 3.0), z becomes intermediate and the spin axis departs from H.
    let text = "[body]\nmass = 20.0\ninertia = [2.0, 2.5, 3.0]\n\
                [[body.moving_mass]]\nmass = 0.3\nfrom = [0.0, 0.0, 0.01]\nto = [0.0, 0.0, 1.0]\nstart = 5.0\nduration = 5.0\n\
                [[body.moving_mass]]\nmass = 0.3\nfrom = [0.0, 0.0, -0.01]\nto = [0.0, 0.0, -1.0]\nstart = 5.0\nduration = 5.0\n\
                [initial]\nomega = [0.02, 0.0, 4.0]\n[solver]\nt_end = 60.0\nrtol = 1e-10\natol = 1e-12\n[output]\nevery = 0.1\n";
    let rows = run(&scene_from(text, &Overrides::default()));
    // The angle between the body's z axis and H.
    let angle = |s: &Sample| s.h_o_b.angle(&Vector3::z()).to_degrees();
    let before = rows
        .iter()
        .filter(|s| s.t <= 5.0)
        .map(angle)
        .fold(0.0, f64::max);
    let after = rows
        .iter()
        .filter(|s| s.t >= 10.0)
        .map(angle)
        .fold(0.0, f64::max);
    assert!(before < 0.5, "stable before the deployment: {before} deg");
    assert!(after > 90.0, "tumbling after it: {after} deg");
}

/// One mass m moved on the rest of the body (mass m_r, C at the origin, inertia I_r), written with the reduced mass
/// μ = m m_r/(m + m_r) and the relative position r (the two-body problem: I = I_r + μ P(r), h = μ r × ṙ), and
/// integrated in ω: I ω̇ = −İ ω − ḣ − ω × (I ω + h), q̇ = ½ q ⊗ (0, ω) — the expanded equation, in another state.
struct TwoBody {
    inertia_r: Matrix3<f64>,
    mu: f64,
    from: Vector3<f64>,
    to: Vector3<f64>,
}

impl TwoBody {
    /// r, ṙ, r̈ of a smooth move over t ∈ [0.5, 3.5].
    fn path(&self, t: f64) -> (Vector3<f64>, Vector3<f64>, Vector3<f64>) {
        let tau = ((t - 0.5) / 3.0).clamp(0.0, 1.0);
        let span = self.to - self.from;
        let inside = (0.0..1.0).contains(&tau) && t > 0.5;
        let (ds, dds) = match inside {
            true => (6.0 * tau * (1.0 - tau) / 3.0, (6.0 - 12.0 * tau) / 9.0),
            false => (0.0, 0.0),
        };
        (
            self.from + span * (tau * tau * (3.0 - 2.0 * tau)),
            span * ds,
            span * dds,
        )
    }
}

impl OdeSystem<7> for TwoBody {
    fn rhs(&mut self, t: f64, y: &SVector<f64, 7>) -> SVector<f64, 7> {
        let (r, v, a) = self.path(t);
        let p = |d: &Vector3<f64>| Matrix3::identity() * d.norm_squared() - d * d.transpose();
        let inertia = self.inertia_r + p(&r) * self.mu;
        let inertia_dot =
            (Matrix3::identity() * (2.0 * r.dot(&v)) - v * r.transpose() - r * v.transpose())
                * self.mu;
        let (h, h_dot) = (r.cross(&v) * self.mu, r.cross(&a) * self.mu);
        let w = Vector3::new(y[0], y[1], y[2]);
        let rhs = -inertia_dot * w - h_dot - w.cross(&(inertia * w + h));
        let w_dot = inertia.try_inverse().unwrap() * rhs;
        let q = nalgebra::Quaternion::new(y[3], y[4], y[5], y[6]);
        let q_dot = q * nalgebra::Quaternion::new(0.0, w.x, w.y, w.z) * 0.5;
        SVector::from([
            w_dot.x, w_dot.y, w_dot.z, q_dot.w, q_dot.i, q_dot.j, q_dot.k,
        ])
    }

    fn project(&self, y: &mut SVector<f64, 7>) {
        let n = (y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6]).sqrt();
        for k in 3..7 {
            y[k] /= n;
        }
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        [0.5, 3.5].into_iter().find(|b| *b > t)
    }
}

#[test]
fn an_independent_two_body_formulation_in_omega_agrees_to_1e_10() {
    let text = "[body]\nmass = 6.0\ninertia = [[1.2, 0.05, -0.1], [0.05, 1.8, 0.08], [-0.1, 0.08, 2.4]]\n\
                [[body.moving_mass]]\nmass = 0.8\nfrom = [0.3, -0.2, 0.1]\nto = [-0.4, 0.9, 0.5]\nstart = 0.5\nduration = 3.0\n\
                [initial]\nomega = [1.1, -0.6, 2.2]\n[solver]\nt_end = 5.0\nrtol = 1e-13\natol = 1e-13\n[output]\nevery = 0.01\n";
    let mut two_body = TwoBody {
        inertia_r: Matrix3::new(1.2, 0.05, -0.1, 0.05, 1.8, 0.08, -0.1, 0.08, 2.4),
        mu: 0.8 * 6.0 / 6.8,
        from: Vector3::new(0.3, -0.2, 0.1),
        to: Vector3::new(-0.4, 0.9, 0.5),
    };
    let settings = Settings {
        method: Method::Dop853,
        rtol: 1e-13,
        atol: 1e-13,
        ..Settings::default()
    };
    let mut expected = Vec::new();
    let y0 = SVector::from([1.1, -0.6, 2.2, 1.0, 0.0, 0.0, 0.0]);
    integrate::integrate(
        &mut two_body,
        y0,
        &Schedule::new(0.01, 5.0).unwrap(),
        &settings,
        |t, y| {
            expected.push((t, *y));
            Ok::<(), std::convert::Infallible>(())
        },
    )
    .unwrap();
    for form in [Form::Body, Form::Space] {
        let scene = scene_from(
            text,
            &Overrides {
                form: Some(form),
                ..Overrides::default()
            },
        );
        let rows = run(&scene);
        let power = column(&scene, &rows, "P_internal");
        for (s, (t, y)) in rows.iter().zip(&expected) {
            assert_eq!(s.t, *t);
            let w = Vector3::new(y[0], y[1], y[2]);
            let q =
                UnitQuaternion::new_normalize(nalgebra::Quaternion::new(y[3], y[4], y[5], y[6]));
            assert!(
                (s.omega_b.into_inner() - w).norm() <= 1e-10 * w.norm(),
                "{form:?} t={t}: {} vs {w}",
                s.omega_b
            );
            assert!(s.q.angle_to(&q) <= 1e-10, "{form:?} t={t}");
        }
        // P_internal = dT/dt without moment: the five-point difference of the energy column (step h = 0.01 s,
        // error h⁴/30 |T⁽⁵⁾|: 1.4e-5 of the largest |P| measured at h = 0.05 s, so ~2e-8 here), away from the
        // move's ends (where T'' jumps); the integration's own error (rtol = 1e-13) adds ~1e-11.
        let largest = power.iter().fold(0.0f64, |m, p| m.max(p.abs()));
        let mut worst = 0.0f64;
        for k in 2..rows.len() - 2 {
            let t = rows[k].t;
            if (t - 0.5).abs() < 0.03 || (t - 3.5).abs() < 0.03 {
                continue;
            }
            let e = |j: usize| rows[j].energy;
            let difference =
                (e(k - 2) - 8.0 * e(k - 1) + 8.0 * e(k + 1) - e(k + 2)) / (12.0 * 0.01);
            worst = worst.max((difference - power[k]).abs() / largest);
        }
        assert!(worst <= 1e-7, "{worst:e}");
    }
}

#[test]
fn an_inertia_table_spins_up_as_h_over_i_and_check_says_h_is_taken_zero() {
    // I_zz from 3 to 1.5 kg·m² between t = 1 and 3 s (linear), ω along z: ω = H/I_zz(t), T = H²/(2 I_zz).
    let dir = tempfile::tempdir().unwrap();
    write_file(
        dir.path(),
        "deploy.csv",
        "t,I_xx,I_yy,I_zz,I_xy,I_xz,I_yz\n1,2,2,3,0,0,0\n3,1.25,1.25,1.5,0,0,0\n",
    );
    let scene_path = write_file(
        dir.path(),
        "scene.toml",
        "[body]\nmass = 5.0\ninertia = [2.0, 2.0, 3.0]\ninertia_table = \"deploy.csv\"\n[initial]\nomega = [0.0, 0.0, 2.0]\n\
         [solver]\nrtol = 1e-12\natol = 1e-12\nt_end = 4.0\n[output]\nevery = 0.1\n",
    );
    let scene = eulerdyn::scene::load(&scene_path, &Overrides::default()).unwrap();
    let rows = run(&scene);
    let power = column(&scene, &rows, "P_internal");
    for (s, p) in rows.iter().zip(&power) {
        let i = match s.t {
            t if t <= 1.0 => 3.0,
            t if t >= 3.0 => 1.5,
            t => 3.0 - 0.75 * (t - 1.0),
        };
        let i_dot = if (1.0..3.0).contains(&s.t) {
            -0.75
        } else {
            0.0
        };
        assert!((s.omega_b.z - 6.0 / i).abs() <= 1e-9 * 6.0 / i, "t={}", s.t);
        assert!((s.energy - 18.0 / i).abs() <= 1e-9 * 18.0 / i);
        assert!(
            (p - (-0.5 * (6.0 / i).powi(2) * i_dot)).abs() <= 1e-9 * 20.0,
            "t={}: {p}",
            s.t
        );
    }
    let out = eulerdyn(["check", scene_path.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert!(
        out.stdout.contains("no moment of momentum relative") && out.stdout.contains("at t = 3 s"),
        "{}",
        out.stdout
    );
}

#[test]
fn an_event_finds_the_time_the_skater_reaches_a_rate() {
    // ω_z = H/I_zz(t) = 6 rad/s at I_zz = 2.08/…: solved here by bisection on the closed form.
    let h = 3.0 * 4.0 + 2.0 * 0.5 * 0.04 * 4.0;
    let text = skater("smooth", Form::Body, "dop853")
        .replace("[[body.moving_mass]]\nname = \"left\"", "[[event]]\nname = \"slow\"\nwhen = \"omega_b_z\"\ncrosses = 3.5\n[[body.moving_mass]]\nname = \"left\"");
    let scene = scene_from(&text, &Overrides::default());
    let (_, occurrences) =
        simulate::run_with_events(&scene, |_| Ok::<(), std::convert::Infallible>(())).unwrap();
    let omega = |t: f64| {
        let (r, ..) = arm("smooth", t);
        h / (3.0 + r * r)
    };
    let (mut lo, mut hi) = (1.0, 5.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if omega(mid) > 3.5 { lo = mid } else { hi = mid }
    }
    assert_eq!(occurrences.len(), 1, "{occurrences:?}");
    assert!(
        (occurrences[0].t - lo).abs() < 1e-8,
        "{} vs {lo}",
        occurrences[0].t
    );
}

#[test]
fn a_sweep_over_the_deployed_position_follows_h_over_i() {
    let dir = tempfile::tempdir().unwrap();
    let base = write_file(
        dir.path(),
        "base.toml",
        skater("smooth", Form::Space, "dop853"),
    );
    let sweep = write_file(
        dir.path(),
        "sweep.toml",
        format!(
            "scene = \"{}\"\n[[vary]]\nkey = \"body.moving_mass.0.to.0\"\nvalues = [0.6, 1.2]\n\
             [[vary]]\nkey = \"body.moving_mass.1.duration\"\nvalues = [4.0]\n[summary]\ncolumns = [\"omega_b_z\"]\n",
            base.display()
        ),
    );
    let (head, rows) = sweep_table(&sweep, dir.path());
    assert_eq!(rows.len(), 2, "{head:?}");
    let final_omega = head
        .iter()
        .position(|h| h == "final_omega_b_z")
        .unwrap_or_else(|| panic!("{head:?}"));
    let h = 3.0 * 4.0 + 2.0 * 0.5 * 0.04 * 4.0;
    for (row, x) in rows.iter().zip([0.6f64, 1.2]) {
        // The left mass at x, the right at −1.2: C moves, so the closed form is the library's I_zz about C.
        let (m, big_m): (f64, f64) = (0.5, 11.0);
        let c = m * (x - 1.2) / big_m;
        let i_zz = 3.0 + 10.0 * c * c + m * (x - c).powi(2) + m * (1.2 + c).powi(2);
        let omega: f64 = row[final_omega].parse().unwrap();
        assert!(
            (omega - h / i_zz).abs() <= 1e-9 * h / i_zz,
            "x={x}: {omega} vs {}",
            h / i_zz
        );
    }
}

#[test]
fn bad_input_exits_2_naming_the_key_and_writes_nothing() {
    let base = skater("smooth", Form::Body, "dop853");
    let first = "mass = 0.5\nfrom = [0.2, 0.0, 0.0]";
    let cases = [
        ("mass <= 0", base.replacen(first, "mass = 0.0\nfrom = [0.2, 0.0, 0.0]", 1), "mass"),
        ("duration <= 0", base.replacen("duration = 4.0", "duration = 0.0", 1), "duration"),
        ("no duration", base.replacen("duration = 4.0\n", "", 1), "duration"),
        ("table and from", base.replacen(first, "mass = 0.5\ntable = \"p.csv\"\nfrom = [0.2, 0.0, 0.0]", 1), "from"),
        ("a position beyond double precision", base.replacen("from = [0.2, 0.0, 0.0]", "from = [1e300, 0.0, 0.0]", 1), "moving_mass"),
        ("a speed beyond double precision", base.replacen("duration = 4.0", "duration = 1e-300", 1), "moving_mass"),
        ("a name twice", base.replace("name = \"right\"", "name = \"left\""), "name"),
        ("exact", base.replace("method = \"dop853\"", "method = \"exact\""), "method"),
        ("split4 with damping", base.replace("method = \"dop853\"", "method = \"split4\"").replace("[solver]", "[[effect]]\ntype = \"damping\"\nc = 0.1\n[solver]"), "method"),
        ("fixed axis", base.replace("[initial]\nomega = [0.0, 0.0, 4.0]\n", "[motion]\ntype = \"fixed_axis\"\naxis = [0.0, 0.0, 1.0]\nrate = 4.0\n"), "moving_mass"),
        ("gravity", base.replace("[solver]", "[[effect]]\ntype = \"gravity\"\ng = [0.0, 0.0, -9.81]\npivot = [0.0, 0.0, -0.1]\n[solver]"), "moving_mass"),
        ("table and masses", base.replace("inertia = [2.0, 2.0, 3.0]", "inertia = [2.0, 2.0, 3.0]\ninertia_table = \"i.csv\""), "inertia_table"),
        ("missing table", base.replacen(first, "mass = 0.5\ntable = \"none.csv\"", 1).replacen("to = [1.2, 0.0, 0.0]\nstart = 1.0\nduration = 4.0\nprofile = \"smooth\"\n", "", 1), "table"),
    ];
    let cases: Vec<(&str, String, &str)> = cases.into_iter().collect();
    assert_refused_writing_nothing(&cases);
}

#[test]
fn tables_that_are_no_path_or_no_body_exit_2_naming_the_file_and_row() {
    for (name, file, text, key, problem) in [
        (
            "a path table not increasing",
            "p.csv",
            "t,x,y,z\n0,0,0,0\n0,1,0,0\n",
            "table",
            "strictly increasing",
        ),
        (
            "an inertia not positive definite",
            "i.csv",
            "t,I_xx,I_yy,I_zz,I_xy,I_xz,I_yz\n0,1,1,1,0,0,0\n1,1,1,-1,0,0,0\n",
            "inertia_table",
            "positive definite",
        ),
        (
            "an inertia breaking the triangle inequality",
            "i.csv",
            "t,I_xx,I_yy,I_zz,I_xy,I_xz,I_yz\n0,1,1,1,0,0,0\n1,1,1,3,0,0,0\n",
            "inertia_table",
            "triangle",
        ),
    ] {
        let dir = tempfile::tempdir().unwrap();
        write_file(dir.path(), file, text);
        let scene = match file {
            "p.csv" => {
                "[body]\nmass = 1.0\ninertia = [1.0, 1.0, 1.0]\n[[body.moving_mass]]\nmass = 0.1\ntable = \"p.csv\"\n[solver]\nt_end = 1.0\n[output]\nevery = 0.1\n"
            }
            _ => {
                "[body]\nmass = 1.0\ninertia = [1.0, 1.0, 1.0]\ninertia_table = \"i.csv\"\n[solver]\nt_end = 1.0\n[output]\nevery = 0.1\n"
            }
        };
        let scene_path = write_file(dir.path(), "scene.toml", scene);
        let out_csv = dir.path().join("out.csv");
        let out = eulerdyn([
            "run",
            scene_path.to_str().unwrap(),
            "-o",
            out_csv.to_str().unwrap(),
        ]);
        assert_eq!(out.code, Some(2), "{name}: {}", out.stderr);
        assert!(
            out.stderr.contains(key)
                && out.stderr.contains(file)
                && out.stderr.contains("row 2")
                && out.stderr.contains(problem),
            "{name}: {}",
            out.stderr
        );
        assert!(!out_csv.exists(), "{name}");
    }
}

#[test]
fn split2_and_split4_converge_at_their_orders_and_keep_h_s_to_round_off_in_both_forms() {
    // The midpoint-frozen Strang step is symmetric in (t, y): order 2, and Suzuki's composition order 4 (Blanes &
    // Casas, *A Concise Introduction to Geometric Numerical Integration*, §3.3; McLachlan 1993 for the rigid drift).
    // Halving the step divides the error by 2^p: measured 4.00 (split2) and 16.0 (split4), within ±10 % here. The
    // steps divide the move's start and end (0.5 s and 3.5 s), so no corner falls inside a step.
    let text = "[body]\nmass = 6.0\ninertia = [[1.2, 0.05, -0.1], [0.05, 1.8, 0.08], [-0.1, 0.08, 2.4]]\n\
                [[body.moving_mass]]\nmass = 0.8\nfrom = [0.3, -0.2, 0.1]\nto = [-0.4, 0.9, 0.5]\nstart = 0.5\nduration = 3.0\n\
                [initial]\nomega = [1.1, -0.6, 2.2]\n[solver]\nt_end = 5.0\nrtol = 1e-13\natol = 1e-13\n[output]\nevery = 0.1\n";
    let reference = run(&scene_from(text, &Overrides::default()));
    let error = |method: Method, dt: f64, form: Form| {
        let overrides = Overrides {
            method: Some(method),
            dt: Some(dt),
            form: Some(form),
            ..Overrides::default()
        };
        let rows = run(&scene_from(text, &overrides));
        // H_s: untouched in the space form; in the body form every sub-flow is a rotation, so it moves by
        // round-off only (a few ulp a sub-flow, ≤ 10⁴ sub-flows here: 1e-11 of |H|).
        let h0 = rows[0].h_o_s;
        let moved = rows
            .iter()
            .map(|s| (s.h_o_s - h0).norm())
            .fold(0.0, f64::max);
        let allowed = if form == Form::Space {
            0.0
        } else {
            1e-11 * h0.norm()
        };
        assert!(
            moved <= allowed,
            "{method:?} {form:?}: H_s moved by {moved:e}"
        );
        (rows.iter().zip(&reference))
            .map(|(a, b)| (a.omega_b - b.omega_b).norm())
            .fold(0.0, f64::max)
    };
    for form in [Form::Body, Form::Space] {
        let ratio2 = error(Method::Split2, 0.01, form) / error(Method::Split2, 0.005, form);
        assert!(
            (ratio2 / 4.0 - 1.0).abs() < 0.1,
            "split2 {form:?}: {ratio2}"
        );
        let ratio4 = error(Method::Split4, 0.02, form) / error(Method::Split4, 0.01, form);
        assert!(
            (ratio4 / 16.0 - 1.0).abs() < 0.1,
            "split4 {form:?}: {ratio4}"
        );
    }
}

#[test]
fn compare_finds_no_closed_form_and_plot_draws_the_inertia_and_the_drives_power() {
    // The closed forms are of rigid bodies: compare holds the two forms against each other only.
    let scene = crate::common::repo_path("scenarios/deploying_booms.toml");
    let out = eulerdyn(["compare", scene.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}{}", out.stdout, out.stderr);
    assert!(
        out.stdout.contains("closed form: none applies"),
        "{}",
        out.stdout
    );
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("booms.csv");
    let svg = dir.path().join("booms.svg");
    assert_eq!(
        eulerdyn(["run", scene.to_str().unwrap(), "-o", csv.to_str().unwrap()]).code,
        Some(0)
    );
    let plot = eulerdyn(["plot", csv.to_str().unwrap(), "-o", svg.to_str().unwrap()]);
    assert_eq!(plot.code, Some(0), "{}", plot.stderr);
    assert!(
        plot.stderr.contains("inertia, internal_power"),
        "{}",
        plot.stderr
    );
    let figure = std::fs::read_to_string(&svg).unwrap();
    assert!(figure.len() > 10_000);
}
