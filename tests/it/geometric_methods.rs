//! The project's own methods — `split2`, `split4` (Lie–Poisson splitting, effects as kicks) and `exact` (the
//! torque-free closed form) — selected like the others, against the closed forms and a tight DOP853 reference; the
//! observed order of convergence of every fixed-step method and of the adaptive ones against their tolerance; the
//! scene validation that goes with the new methods.
//!
//! Bounds are scaled like those of tests/free_rotation.rs: a fixed-step method of order p has global error
//! K·(|ω| dt)^p·(1 + |ω| t), an adaptive one K·rtol·(1 + |ω| t), with K = 1 where the measured constants are ≤ 0.2
//! (printed by `cargo test --test geometric_methods -- --nocapture`); a method that does not honour its order or its
//! tolerance misses by orders of magnitude.

use std::convert::Infallible;
use std::path::Path;

use eulerdyn::analysis::compare::{self, attitude_angle};
use eulerdyn::exact::TorqueFreeBody;
use eulerdyn::method::Method;
use eulerdyn::named::Named;
use eulerdyn::sample::Sample;
use eulerdyn::scene::Scene;
use eulerdyn::scene::{self, Overrides};
use eulerdyn::simulate::{self, RunReport};
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

use crate::common::{eulerdyn, repo_path, scene_from, write_file};

fn run(scene: &Scene) -> (Vec<Sample>, RunReport) {
    let mut out = Vec::new();
    let report = simulate::run(scene, |s| {
        out.push(*s);
        Ok::<(), Infallible>(())
    })
    .unwrap_or_else(|e| panic!("{e}"));
    (out, report)
}

fn sci(values: &[f64]) -> String {
    values
        .iter()
        .map(|v| format!("{v:.2e}"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn rows(scene: &Scene) -> Vec<Sample> {
    run(scene).0
}

/// The largest of |ω − ω_ref| (rad/s) and the attitude angle to the reference (rad) over rows at the same times.
fn largest_error(rows: &[Sample], reference: &[Sample]) -> f64 {
    rows.iter()
        .zip(reference)
        .map(|(r, f)| {
            (r.omega_b - f.omega_b)
                .norm()
                .max(attitude_angle(&r.q, &f.q))
        })
        .fold(0.0, f64::max)
}

fn with(method: &str, frame: &str, dt: Option<f64>, rtol: Option<f64>) -> Overrides {
    Overrides {
        method: Some(Named::parse(method).unwrap()),
        form: Some(Named::parse(frame).unwrap()),
        dt,
        rtol,
        atol: rtol.map(|r| r * 1e-2),
        ..Overrides::default()
    }
}

/// A full tensor: diag(moments) in axes rotated by `axes`, written as TOML.
fn rotated_tensor(moments: [f64; 3], axes: &Rotation3<f64>) -> String {
    let m =
        axes.matrix() * Matrix3::from_diagonal(&Vector3::from(moments)) * axes.matrix().transpose();
    let r = |i: usize| format!("[{:?}, {:?}, {:?}]", m[(i, 0)], m[(i, 1)], m[(i, 2)]);
    format!("[{}, {}, {}]", r(0), r(1), r(2))
}

/// The torque-free scene used throughout: I = (1, 2, 3) (or that tensor in rotated body axes), a tilted attitude.
fn free_text(inertia: &str, omega_b: Vector3<f64>, t_end: f64, every: f64) -> String {
    format!(
        "[body]\nmass = 1.0\ninertia = {inertia}\n[initial]\nomega = [{:?}, {:?}, {:?}]\n\
         attitude = [0.9, 0.1, -0.3, 0.2]\n[solver]\nt_end = {t_end:?}\n[output]\nevery = {every:?}\n",
        omega_b[0], omega_b[1], omega_b[2]
    )
}

/// The closed form of a torque-free scene, in body axes: (ω_b(t), q_b(t)).
struct Oracle {
    exact: TorqueFreeBody,
    p_b: UnitQuaternion<f64>,
}

impl Oracle {
    fn of(scene: &Scene) -> Self {
        let principal = scene.body.principal();
        let p_b = UnitQuaternion::from_rotation_matrix(&principal.axes_b);
        let eulerdyn::scene::Motion::Free { omega0_b, .. } = &scene.motion else {
            panic!("free motion")
        };
        let exact = TorqueFreeBody::new(
            principal.moments,
            p_b.inverse_transform_vector(omega0_b),
            scene.attitude0 * p_b,
        )
        .unwrap();
        Self { exact, p_b }
    }

    /// Largest ω error (relative to `scale`) and attitude error (rad) over the rows.
    fn errors(&self, rows: &[Sample], scale: f64) -> (f64, f64) {
        rows.iter().fold((0.0f64, 0.0f64), |(w, q), r| {
            let omega_b = self.p_b * self.exact.omega_p(r.t);
            let q_b = self.exact.attitude(r.t) * self.p_b.inverse();
            (
                w.max((*r.omega_b - omega_b).norm() / scale),
                q.max(attitude_angle(&r.q, &q_b)),
            )
        })
    }
}

/// A scene with every kind of effect: damping, a sine torque in space axes, gravity about a pivot off the
/// principal axes; a full inertia tensor.
const MIXED: &str = "[body]\nmass = 2.0\ninertia = [[2.0, 0.1, 0.0], [0.1, 2.5, 0.2], [0.0, 0.2, 3.0]]\n\
    [initial]\nomega = [0.3, -0.5, 2.0]\nattitude = [0.9, 0.1, -0.3, 0.2]\n\
    [[effect]]\ntype = \"damping\"\nc = 0.3\n\
    [[effect]]\ntype = \"torque\"\nframe = \"space\"\nvalue = [0.1, 0.2, -0.3]\nprofile = \"sine\"\nfreq_hz = 0.3\n\
    [[effect]]\ntype = \"torque\"\nframe = \"body\"\nvalue = [0.0, 0.05, 0.02]\nprofile = \"step\"\nt_on = 0.0\nt_off = 100.0\n\
    [[effect]]\ntype = \"gravity\"\ng = [0.0, 0.0, -9.81]\npivot = [0.0, 0.05, -0.1]\n\
    [solver]\nt_end = 3.0\n[output]\nevery = 0.1\n";

#[test]
fn split_and_exact_match_the_closed_form_in_both_frames_and_any_body_axes() {
    // Both classes of motion (circulating about the major and the minor axis); body axes principal, and the same
    // body given as a full tensor in rotated axes (the principal mapping P of the splitting and of `exact`).
    // split2 at |ω|dt = 0.01, split4 at |ω|dt = 0.04 over |ω|t ≈ 40: bounds K(|ω|dt)^p(1 + |ω|t), K = 1; measured
    // constants ≤ 0.05. exact: 1e-12 (round-off of the closed form; measured ≤ 1e-14).
    let axes = Rotation3::from_euler_angles(0.3, -0.5, 1.2);
    let cases = [
        ("[1.0, 2.0, 3.0]".to_string(), Vector3::new(0.3, 0.0, 2.0)),
        (
            rotated_tensor([1.0, 2.0, 3.0], &axes),
            axes * Vector3::new(2.0, 0.2, 0.3),
        ),
    ];
    for (inertia, omega0_b) in cases {
        let w = omega0_b.norm() * 1.1;
        let t_end = 20.0;
        let text = free_text(&inertia, omega0_b, t_end, 0.25);
        for frame in ["body", "space"] {
            for (method, dt, p) in [
                ("split2", 0.01 / w, 2),
                ("split4", 0.04 / w, 4),
                ("exact", 0.0, 0),
            ] {
                let scene = scene_from(&text, &with(method, frame, (dt > 0.0).then_some(dt), None));
                let (err_w, err_q) = Oracle::of(&scene).errors(&rows(&scene), omega0_b.norm());
                let bound = if p == 0 {
                    1e-12
                } else {
                    (w * dt).powi(p) * (1.0 + w * t_end)
                };
                println!(
                    "{method} {frame}: ω {err_w:.2e}, attitude {err_q:.2e} (bound {bound:.2e}, constant {:.3})",
                    err_w.max(err_q) / bound
                );
                assert!(
                    err_w <= bound && err_q <= bound,
                    "{method} {frame}: {err_w:e} {err_q:e}"
                );
            }
        }
    }
}

#[test]
fn observed_order_of_every_fixed_step_method() {
    // Halving the step divides the global error by 2^p: measured log₂ ratios within ±0.2 of p (issue 4). Two
    // problems: the torque-free body against its closed form (steps 0.01, 0.005, 0.0025 s; |ω| ≈ 2), and a body
    // under every effect (MIXED) against DOP853 at rtol 1e-13 (error ≲ 1e-13 — two decades under the smallest
    // error measured, 1.5e-11, so the reference does not bend the ratio) with steps 0.02, 0.01, 0.005 s. The steps
    // lie in the asymptotic range: measured ratios 3.99–4.01 (rk4, split4), 2.00 (split2); the next coarser halving
    // (0.04 → 0.02) gives 1.5–3.6, which is why it is not used. The fixed-axis motion integrates Ḣ_s = M_s by the
    // kicks alone (trapezoid, triple jump) and shows the same orders on H_s_int.
    let free = free_text("[1.0, 2.0, 3.0]", Vector3::new(0.3, 0.0, 2.0), 20.0, 0.25);
    let oracle = Oracle::of(&scene_from(&free, &Overrides::default()));
    let reference = rows(&scene_from(
        MIXED,
        &Overrides {
            rtol: Some(1e-13),
            atol: Some(1e-15),
            ..Overrides::default()
        },
    ));
    let tilted = std::fs::read_to_string(repo_path("scenarios/tilted_disk.toml")).unwrap();
    for (method, p) in [("rk4", 4.0), ("split2", 2.0), ("split4", 4.0)] {
        for frame in ["body", "space"] {
            for problem in ["free", "mixed", "fixed axis"] {
                let steps: [f64; 3] = match problem {
                    "free" => [0.01, 0.005, 0.0025],
                    "mixed" => [0.02, 0.01, 0.005],
                    _ => [0.01, 0.005, 0.0025],
                };
                let errors: Vec<f64> = steps
                    .iter()
                    .map(|&dt| {
                        let o = with(method, frame, Some(dt), None);
                        match problem {
                            "free" => {
                                let (w, q) = oracle.errors(&rows(&scene_from(&free, &o)), 1.0);
                                w.max(q)
                            }
                            "mixed" => largest_error(&rows(&scene_from(MIXED, &o)), &reference),
                            _ => rows(&scene_from(&tilted, &o))
                                .iter()
                                .map(|r| (r.h_o_s_integrated.unwrap() - r.h_o_s).norm())
                                .fold(0.0, f64::max),
                        }
                    })
                    .collect();
                let ratios: Vec<f64> = errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect();
                println!(
                    "{method} {frame} {problem}: errors {}, observed orders {ratios:.3?}",
                    sci(&errors)
                );
                for r in ratios {
                    assert!(
                        (r - p).abs() <= 0.2,
                        "{method} {frame} {problem}: order {r} vs {p}"
                    );
                }
            }
        }
    }
}

#[test]
fn observed_order_of_the_adaptive_methods_against_their_tolerance() {
    // With local extrapolation and error control per step, the global error of DOPRI5 and DOP853 is proportional to
    // rtol (tolerance proportionality, HNW I §II.4): the least-squares slope of log(error) against log(rtol) over
    // rtol = 1e-6 … 1e-11 (atol = rtol/100) is 1 ± 0.2 (measured 0.95–1.03 torque-free, 0.88–1.01 under every
    // effect). Rows are 5 s and 1.5 s apart, so the row times do not cap the step.
    let free = free_text("[1.0, 2.0, 3.0]", Vector3::new(0.3, 0.0, 2.0), 20.0, 5.0);
    let oracle = Oracle::of(&scene_from(&free, &Overrides::default()));
    let mixed = MIXED.replace("every = 0.1", "every = 1.5");
    let reference = rows(&scene_from(
        &mixed,
        &Overrides {
            rtol: Some(1e-13),
            atol: Some(1e-15),
            ..Overrides::default()
        },
    ));
    let rtols = [1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11];
    for method in ["dopri5", "dop853"] {
        for frame in ["body", "space"] {
            for problem in ["free", "mixed"] {
                let errors: Vec<f64> = rtols
                    .iter()
                    .map(|&rtol| {
                        let o = with(method, frame, None, Some(rtol));
                        if problem == "free" {
                            let (w, q) = oracle.errors(&rows(&scene_from(&free, &o)), 1.0);
                            w.max(q)
                        } else {
                            largest_error(&rows(&scene_from(&mixed, &o)), &reference)
                        }
                    })
                    .collect();
                let xs: Vec<f64> = rtols.iter().map(|r| r.log10()).collect();
                let ys: Vec<f64> = errors.iter().map(|e| e.log10()).collect();
                let n = xs.len() as f64;
                let (mx, my) = (xs.iter().sum::<f64>() / n, ys.iter().sum::<f64>() / n);
                let slope = xs
                    .iter()
                    .zip(&ys)
                    .map(|(x, y)| (x - mx) * (y - my))
                    .sum::<f64>()
                    / xs.iter().map(|x| (x - mx) * (x - mx)).sum::<f64>();
                println!(
                    "{method} {frame} {problem}: errors {}, slope {slope:.3}",
                    sci(&errors)
                );
                assert!(
                    (slope - 1.0).abs() <= 0.2,
                    "{method} {frame} {problem}: slope {slope}"
                );
            }
        }
    }
}

#[test]
fn body_and_space_forms_of_the_splitting_are_the_same_map() {
    // The body form turns H_p and the space form keeps H_s; in exact arithmetic they are the same map, so their rows
    // differ by round-off only: ≤ 1e-12 relative over 3000 steps with every effect and 12000 torque-free steps
    // (measured ≤ 3e-13). A sign error in either sub-flow would make them differ at O(dt).
    let free = free_text("[1.0, 2.0, 3.0]", Vector3::new(0.3, 0.0, 2.0), 30.0, 0.5);
    for text in [free.as_str(), MIXED] {
        for method in ["split2", "split4"] {
            let body = rows(&scene_from(text, &with(method, "body", Some(0.0025), None)));
            let space = rows(&scene_from(
                text,
                &with(method, "space", Some(0.0025), None),
            ));
            let mut worst = 0.0f64;
            for (b, s) in body.iter().zip(&space) {
                assert_eq!(b.t, s.t);
                worst = worst
                    .max((b.omega_b - s.omega_b).norm() / b.omega_b.norm().max(1e-300))
                    .max((b.h_o_s - s.h_o_s).norm() / b.h_o_s.norm())
                    .max(attitude_angle(&b.q, &s.q));
            }
            println!("{method}: body vs space {worst:.2e}");
            assert!(worst <= 1e-12, "{method}: {worst:e}");
        }
    }
}

#[test]
fn the_work_counters_of_the_new_methods() {
    // split2: steps of dt, one Strang step each; evals count sub-flows — Casimir splitting with three distinct
    // moments: 4 rotations per Strang step (C, T_a, T_c, T_a), + 2 kicks with effects; split4: five Strang steps.
    // exact: one closed-form evaluation per row, steps = row intervals. rejected = 0 always.
    let free = free_text("[1.0, 2.0, 3.0]", Vector3::new(0.3, 0.0, 2.0), 1.0, 0.1);
    for (text, kicks) in [(free.as_str(), 0), (MIXED, 2)] {
        for (method, per_step) in [("split2", 4 + kicks), ("split4", 5 * (4 + kicks))] {
            let (rows, report) = run(&scene_from(text, &with(method, "body", Some(0.01), None)));
            let t_end = rows.last().unwrap().t;
            let steps = (t_end / 0.01).round() as u64;
            assert_eq!(report.stats.steps, steps, "{method}");
            assert_eq!(report.stats.evals, per_step * steps, "{method}");
            assert_eq!(report.stats.rejected, 0);
        }
    }
    let (rows, report) = run(&scene_from(&free, &with("exact", "body", None, None)));
    assert_eq!(report.stats.evals, rows.len() as u64);
    assert_eq!(report.stats.steps, rows.len() as u64 - 1);
    // A symmetric body: the zero-rate rotation is skipped (I = (1, 1, 1.7): C and T_3 only).
    let sym = free_text("[1.0, 1.0, 1.7]", Vector3::new(0.4, 0.1, 3.0), 1.0, 0.1);
    let (_, report) = run(&scene_from(&sym, &with("split2", "body", Some(0.01), None)));
    assert_eq!(report.stats.evals, 2 * report.stats.steps);
}

#[test]
fn exact_reads_the_closed_form_two_ways() {
    // Body form: ω from the Jacobi functions; space form: ω = I⁻¹ q(t)⁻¹ H_s from the closed-form attitude. Both are
    // the closed form to round-off (the attitude integral and ω agree: measured ≤ 5e-16 over 100 s), and the space
    // form's H_s is the constant.
    let text = std::fs::read_to_string(repo_path("scenarios/asymmetric_free.toml")).unwrap();
    let body = rows(&scene_from(&text, &with("exact", "body", None, None)));
    let space = rows(&scene_from(&text, &with("exact", "space", None, None)));
    let mut worst = 0.0f64;
    for (b, s) in body.iter().zip(&space) {
        worst = worst.max((b.omega_b - s.omega_b).norm() / b.omega_b.norm());
        assert_eq!(s.h_o_s, space[0].h_o_s);
        assert_eq!(*b.m_o_b, Vector3::zeros());
    }
    println!("exact body vs space: {worst:.2e}");
    assert!(worst <= 1e-14, "{worst:e}");
}

#[test]
fn compare_runs_the_new_methods() {
    // `eulerdyn compare` with split2/split4/exact: the two forms in lockstep and against the closed form. For the
    // splitting the two forms differ by round-off (≤ 1e-12); for exact both are the closed form (≤ 1e-14); a note
    // says what the comparison means. split4 at dt = 1e-3 is within the scene's tolerance 1e-8 (measured 1.3e-10).
    let text = std::fs::read_to_string(repo_path("scenarios/asymmetric_free.toml")).unwrap();
    for (method, dt, within) in [
        ("split2", 1e-3, false),
        ("split4", 1e-3, true),
        ("exact", 1e-3, true),
    ] {
        let scene = scene_from(&text, &with(method, "body", Some(dt), None));
        let c = compare::compare(&scene).unwrap();
        println!("{method}:\n{}", c.report());
        assert!(
            c.note.as_deref().is_some_and(|n| n.contains(method)),
            "{method}"
        );
        let limit = if method == "exact" { 1e-14 } else { 1e-12 };
        assert!(
            c.body_vs_space.worst() <= limit,
            "{method}: {}",
            c.body_vs_space.worst()
        );
        assert_eq!(c.passes(), within, "{method}");
    }
    let dir = tempfile::tempdir().unwrap();
    let path = write_file(
        dir.path(),
        "exact.toml",
        text.replace("method = \"dop853\"", "method = \"exact\""),
    );
    let out = eulerdyn(["compare", path.to_str().unwrap()]);
    out.expect_code(0);
    assert!(out.stdout.contains("method exact"), "{}", out.stdout);
}

#[test]
fn exact_with_effects_is_refused_naming_the_method_and_the_effect() {
    // `exact` is the torque-free closed form: a scene with an effect is refused at validation (exit 2), the message
    // naming solver.method, the effect's key and type, and the methods that can run it.
    let base = "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 0.0, 2.0]\n\
                [solver]\nmethod = \"exact\"\nt_end = 1.0\n[output]\nevery = 0.1\n";
    for (effect, kind) in [
        ("type = \"torque\"\nvalue = [0.0, 0.0, 0.1]", "torque"),
        (
            "type = \"gravity\"\ng = [0.0, 0.0, -9.81]\npivot = [0.0, 0.0, -0.1]",
            "gravity",
        ),
        ("type = \"damping\"\nc = 0.1", "damping"),
    ] {
        let text = format!("{base}[[effect]]\n{effect}\n");
        let err = scene::parse(Path::new("s.toml"), &text, &Overrides::default()).unwrap_err();
        assert_eq!(err.key.as_deref(), Some("solver.method"), "{err}");
        let expected = format!(
            "method \"exact\" is the torque-free closed form; the scene's effect[0] ({kind}) needs rk4, dopri5, dop853, split2 or split4"
        );
        assert_eq!(err.problem, expected);
        assert!(err.location.is_some(), "{err}");
    }
    // From the command line: the key says it came from --method; exit 2; nothing written.
    let dir = tempfile::tempdir().unwrap();
    let path = write_file(
        dir.path(),
        "heavy.toml",
        std::fs::read_to_string(repo_path("scenarios/heavy_top.toml")).unwrap(),
    );
    let csv = dir.path().join("out.csv");
    let out = eulerdyn([
        "run",
        path.to_str().unwrap(),
        "--method",
        "exact",
        "-o",
        csv.to_str().unwrap(),
    ]);
    out.expect_code(2);
    assert!(
        out.stderr.contains("solver.method (from --method)")
            && out.stderr.contains("effect[0] (gravity)"),
        "{}",
        out.stderr
    );
    assert!(!csv.exists());
}

#[test]
fn the_ode_solvers_backend_runs_only_the_runge_kutta_methods() {
    let text = free_text("[1.0, 2.0, 3.0]", Vector3::new(0.3, 0.0, 2.0), 1.0, 0.1);
    for method in Method::ALL {
        let o = Overrides {
            method: Some(method),
            backend: Some(Named::parse("ode_solvers").unwrap()),
            ..Overrides::default()
        };
        let r = scene::parse(Path::new("s.toml"), &text, &o);
        if method.is_runge_kutta() {
            assert!(r.is_ok(), "{}", method.name());
        } else {
            let err = r.unwrap_err();
            assert_eq!(
                err.key.as_deref(),
                Some("solver.backend (from --backend)"),
                "{err}"
            );
            assert!(
                err.problem.contains(method.name())
                    && err.problem.contains("rk4, dopri5 and dop853")
            );
        }
    }
}

#[test]
fn every_shipped_torque_free_and_effect_scenario_runs_with_the_splitting() {
    // Each scenario with free motion, through split4 at |ω|dt ≈ 0.02 (dt from its initial |ω|): no divergence, the
    // guard silent, |H| exact when torque-free (≤ 1e-13 over the run; the rows' H_s norm) and the rows finite.
    let dir = repo_path("scenarios");
    let mut ran = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let base = scene_from(&text, &Overrides::default());
        // A body with rotors is refused by the splitting (tests/it/rotors.rs).
        let Some((omega0_b, _)) = base.motion.rigid_free() else {
            continue;
        };
        // So is a moment law of ω such as B-dot (tests/it/b_dot.rs).
        if base.effects.iter().any(|e| e.depends_on_rate()) {
            continue;
        }
        let dt = 0.02 / omega0_b.norm().max(1.0);
        let scene = scene_from(&text, &with("split4", "body", Some(dt), None));
        let rows = rows(&scene);
        let h0 = rows[0].h_o_s.norm();
        for r in &rows {
            assert!(
                r.omega_b
                    .iter()
                    .chain(r.h_o_s.iter())
                    .all(|v| v.is_finite())
            );
            if scene.effects.is_empty() {
                assert!(
                    (r.h_o_s.norm() - h0).abs() <= 1e-13 * h0,
                    "{}",
                    path.display()
                );
            }
        }
        ran += 1;
    }
    assert!(ran >= 6, "{ran} free scenarios");
}
