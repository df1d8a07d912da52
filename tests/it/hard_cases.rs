//! The hard cases: the motions that break other simulators (drift over long horizons, the intermediate axis, the
//! separatrix, near-symmetric and singular bodies, fast spin, strong damping, degenerate tilts and rates), each with
//! its pass criterion stated in the test and every bound justified by a measurement or a derivation.
//!
//! Measured values quoted in the comments are from `cargo test --test hard_cases -- --nocapture`, which prints them.

use std::convert::Infallible;
use std::path::Path;

use eulerdyn::analysis::compare::attitude_angle;
use eulerdyn::exact::TorqueFreeBody;
use eulerdyn::method::Method;
use eulerdyn::named::Named;
use eulerdyn::sample::Sample;
use eulerdyn::scene::Scene;
use eulerdyn::scene::{self, Overrides};
use eulerdyn::simulate::{self, GuardedQuantity, RunError, RunReport};
use nalgebra::{UnitQuaternion, Vector3};

use crate::common::{eulerdyn, scene_from, sign_changes, write_file};

fn try_rows(scene: &Scene) -> (Vec<Sample>, Result<RunReport, RunError<Infallible>>) {
    let mut out = Vec::new();
    let r = simulate::run(scene, |s| {
        out.push(*s);
        Ok::<(), Infallible>(())
    });
    (out, r)
}

fn rows(scene: &Scene) -> Vec<Sample> {
    let (rows, r) = try_rows(scene);
    if let Err(e) = r {
        panic!("{e}");
    }
    rows
}

/// Runs the scene, handing each row to `f` (for long runs whose rows are not kept).
fn stream(scene: &Scene, mut f: impl FnMut(&Sample)) -> RunReport {
    simulate::run(scene, |s| {
        f(s);
        Ok::<(), Infallible>(())
    })
    .unwrap_or_else(|e| panic!("{e}"))
}

/// A torque-free scene with principal moments `inertia` (body axes principal).
fn free_text(inertia: [f64; 3], omega: [f64; 3], t_end: f64, every: f64) -> String {
    format!(
        "[body]\nmass = 1.0\ninertia = [{:?}, {:?}, {:?}]\n[initial]\nomega = [{:?}, {:?}, {:?}]\n\
         [solver]\nt_end = {t_end:?}\n[output]\nevery = {every:?}\n",
        inertia[0], inertia[1], inertia[2], omega[0], omega[1], omega[2]
    )
}

/// One method at its setting: `rtol` for the adaptive ones (atol = rtol/100), `dt` for the fixed-step ones.
#[derive(Debug, Clone, Copy)]
struct Setting {
    method: &'static str,
    frame: &'static str,
    rtol: Option<f64>,
    dt: Option<f64>,
}

impl Setting {
    fn overrides(&self) -> Overrides {
        Overrides {
            method: Some(Named::parse(self.method).unwrap()),
            form: Some(Named::parse(self.frame).unwrap()),
            rtol: self.rtol,
            atol: self.rtol.map(|r| r * 1e-2),
            dt: self.dt,
            ..Overrides::default()
        }
    }
}

impl std::fmt::Display for Setting {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} {}", self.method, self.frame)?;
        if let Some(r) = self.rtol {
            write!(f, " rtol {r:e}")?;
        }
        if let Some(dt) = self.dt {
            write!(f, " dt {dt:e}")?;
        }
        Ok(())
    }
}

/// Every method in both frames, the fixed steps given as |ω|·dt (`rk4`, `split2`, `split4`), scaled by `omega`.
fn every_method(omega: f64, steps: [f64; 3], rtols: [f64; 2]) -> Vec<Setting> {
    let mut out = Vec::new();
    for frame in ["body", "space"] {
        for (method, rtol, dt) in [
            ("rk4", None, Some(steps[0] / omega)),
            ("dopri5", Some(rtols[0]), None),
            ("dop853", Some(rtols[1]), None),
            ("split2", None, Some(steps[1] / omega)),
            ("split4", None, Some(steps[2] / omega)),
            ("exact", None, None),
        ] {
            out.push(Setting {
                method,
                frame,
                rtol,
                dt,
            });
        }
    }
    out
}

// ---------------------------------------------------------------------------------------------------------------
// Long horizon.

#[test]
fn long_horizon_split_methods_keep_h_exact_and_energy_bounded() {
    // Torque-free asymmetric body I = (1, 2, 3), ω(0) = (0.3, 0, 2): ω is periodic with 4K/λ = 3.1475 s (closed
    // form). 10⁵ periods = 3.1e5 s, 3.1e6 steps of dt = 0.1 s (|ω| dt ≈ 0.2). Criteria (issue 4):
    // - relative |H| drift ≤ 1e-12 (measured: 3.0e-16 in the body form, where H_p is rescaled to |H(0)| after every
    //   step, and exactly 0 in the space form, where H_s is untouched by the sub-flows);
    // - energy error bounded: the largest error in the last tenth of the run ≤ 2 × that in the first tenth
    //   (measured ratio 1.0000: split2 4.015e-5, split4 4.156e-8 in both tenths — no drift at all);
    // - ||q| − 1| ≤ 1e-13 (q renormalised every step; measured 2.2e-16).
    let exact = TorqueFreeBody::new(
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(0.3, 0.0, 2.0),
        UnitQuaternion::identity(),
    )
    .unwrap();
    let period = exact.period_omega().unwrap();
    assert!((period - 3.147_508_120_481_419_7).abs() < 1e-12, "{period}");
    let t_end = 1e5 * period;
    // Rows every 10 s: incommensurate with the period, so the rows sample every phase of the energy error.
    let text = free_text([1.0, 2.0, 3.0], [0.3, 0.0, 2.0], t_end, 10.0);
    for (method, frame) in [("split2", "body"), ("split4", "body"), ("split2", "space")] {
        let scene = scene_from(
            &text,
            &Overrides {
                method: Some(Named::parse(method).unwrap()),
                form: Some(Named::parse(frame).unwrap()),
                dt: Some(0.1),
                ..Overrides::default()
            },
        );
        let (e0, h0) = (exact.energy(), exact.h_s().norm());
        let n_rows = scene.schedule.len();
        let tenth = n_rows / 10;
        let (mut first, mut last, mut h_drift, mut q_norm) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        let mut k = 0;
        let report = stream(&scene, |r| {
            let e = ((r.energy - e0) / e0).abs();
            if k < tenth {
                first = first.max(e);
            }
            if k >= n_rows - tenth {
                last = last.max(e);
            }
            h_drift = h_drift.max(((r.h_o_s.norm() - h0) / h0).abs());
            q_norm = q_norm.max((r.q.into_inner().norm() - 1.0).abs());
            k += 1;
        });
        println!(
            "{method} {frame}: {} steps, |H| drift {h_drift:.3e}, energy error first tenth {first:.3e}, last tenth \
             {last:.3e} (ratio {:.4}), ||q|-1| {q_norm:.1e}",
            report.stats.steps,
            last / first
        );
        assert_eq!(k, n_rows);
        assert!(h_drift <= 1e-12, "{method} {frame}: |H| drift {h_drift:e}");
        assert!(
            last <= 2.0 * first,
            "{method} {frame}: energy error grew from {first:e} to {last:e}"
        );
        assert!(q_norm <= 1e-13, "{method} {frame}: ||q| - 1| = {q_norm:e}");
    }
}

#[test]
fn exact_is_accurate_to_round_off_at_a_million_seconds() {
    // The closed form at t = 10⁶ s (3.2e5 periods, τ = λt ≈ 2e6) against a 60-digit reference computed with mpmath
    // (rounded to f64) from the same Landau–Lifshitz formulas (mpmath's own ellipfun, ellipk, ellipf), checked against
    // mpmath's Taylor ODE solver at t = 10 to 5e-19:
    //   a² = (2E I3 − M²)/(I1(I3 − I1)), b² = (2E I3 − M²)/(I2(I3 − I2)), c² = (M² − 2E I1)/(I3(I3 − I1)),
    //   λ² = (I3 − I2)(M² − 2E I1)/(I1 I2 I3), m = (I2 − I1)(2E I3 − M²)/((I3 − I2)(M² − 2E I1)),
    //   τ0 = F(atan2(ω2/b, ω1/a) | m), ω = (a cn, b sn, c dn)(λt + τ0 | m).
    // Criterion: relative ω error ≤ 1e-15 (issue 4 asked for 1e-10; measured 4.1e-12 while λ and the reduction
    // τ − 2jK by a rounded K were binary64, a few ulp of τ ≈ 2e6). Now λt + τ₀, 2K and the reduction are carried in
    // double-double (issue 26), and the error is the reference's own rounding to f64: measured 1.2e-16. Both forms:
    // the space form reads ω from the closed-form attitude and the constant H_s (ω_b = I⁻¹ q(t)⁻¹ H_s), so it checks
    // the attitude's nutation and spin at 10⁶ s as well (measured 1.7e-16; not the precession about H, which leaves
    // q⁻¹ H_s unchanged).
    let reference = Vector3::new(
        -0.175_316_223_086_086_1,
        -0.243_442_440_677_113,
        1.995_055_202_083_154_7,
    );
    let text = free_text([1.0, 2.0, 3.0], [0.3, 0.0, 2.0], 1e6, 1e5);
    for frame in ["body", "space"] {
        let scene = scene_from(
            &text,
            &Overrides {
                method: Some(Named::parse("exact").unwrap()),
                form: Some(Named::parse(frame).unwrap()),
                ..Overrides::default()
            },
        );
        let rows = rows(&scene);
        let last = rows.last().unwrap();
        assert_eq!((rows.len(), last.t), (11, 1e6));
        let err = (*last.omega_b - reference).norm() / reference.norm();
        println!("exact {frame} at t = 1e6 s: relative ω error {err:.3e}");
        assert!(err <= 1e-15, "{frame}: {err:e}");
    }
}

// ---------------------------------------------------------------------------------------------------------------
// The intermediate axis and the separatrix.

#[test]
fn intermediate_axis_flips_at_the_closed_form_interval_with_every_method() {
    // scenarios/tennis_racket.toml: I = (1, 2, 3), ω(0) = (0.001, 2, 0.001), a spin 5e-4 rad off the intermediate
    // axis. ω_y ∝ sn(λt + τ0) flips sign every 2K/λ = 14.97 s (Landau & Lifshitz §37). Near the separatrix the
    // interval depends on the invariants through ln(1/m′), so a method's energy error δE/E shifts it by about
    // (δE/E)/(m′ ln(16/m′)) with m′ = 2.5e-7 here: the fixed steps are chosen so that each method's energy error
    // is ≪ m′ (split2 (|ω|dt)² ≈ 4e-8 at |ω|dt = 2e-4; split4 and rk4 (|ω|dt)⁴ at 0.01; adaptive at their rtol).
    // Criterion: every measured interval within 1e-3 of 2K/λ — the resolution of locating a crossing by linear
    // interpolation between rows 0.05 s apart is ~1e-4 s; measured worst 1.6e-4 relative (dopri5 space, whose
    // energy error at rtol 1e-9 is the largest), 5.4e-7 for the others.
    let text = std::fs::read_to_string("scenarios/tennis_racket.toml").unwrap();
    let exact = TorqueFreeBody::new(
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(0.001, 2.0, 0.001),
        UnitQuaternion::identity(),
    )
    .unwrap();
    let interval = exact.flip_interval().unwrap();
    assert!((interval - 14.97).abs() < 0.01, "{interval}");
    let mut worst = 0.0f64;
    for s in every_method(2.0, [0.004, 2e-4, 0.01], [1e-9, 1e-10]) {
        let scene = scene_from(&text, &s.overrides());
        let flips = sign_changes(&rows(&scene), 1);
        assert!(flips.len() >= 4, "{s}: {} flips", flips.len());
        let err = flips
            .windows(2)
            .map(|p| ((p[1] - p[0]) - interval).abs() / interval)
            .fold(0.0, f64::max);
        println!(
            "{s}: {} flips, worst interval error {err:.2e} of 2K/λ",
            flips.len()
        );
        worst = worst.max(err);
        assert!(err <= 1e-3, "{s}: flip interval off by {err:e} of 2K/λ");
    }
    println!("worst {worst:.2e}");
}

#[test]
fn near_the_separatrix_the_flip_time_matches_2k_over_lambda() {
    // I = (1, 2, 3), ω(0) = (0, 2, ω3) with ω3 chosen so that the complementary parameter m′ = 1 − m = 1e-6:
    // m′ = ω3²/(ω3² + ω2²/3) (L&L §37 with ω1 = 0). ω(0) starts at the top of the sn-hump (τ0 = K), so ω_y
    // changes sign at t = K/λ, 3K/λ, 5K/λ, … (intervals 2K/λ = 14.4 s) and ω_x at 2K/λ, 4K/λ, …
    // Criterion: every crossing time within 1e-3·2K/λ of the closed form. A method's energy error shifts the
    // crossings by about (δE/E)/(m′ ln(16/m′)) of 2K/λ, so the steps keep δE/E ≲ 1e-9 (see the tennis racket
    // test). Measured worst 2.2e-6 relative (dopri5 space), ≤ 3e-8 for the others.
    let w2 = 2.0f64;
    let mc = 1e-6f64;
    let w3 = w2 * (mc / (3.0 * (1.0 - mc))).sqrt();
    let exact = TorqueFreeBody::new(
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(0.0, w2, w3),
        UnitQuaternion::identity(),
    )
    .unwrap();
    let m = exact.elliptic_parameter().unwrap();
    assert!(
        ((1.0 - m) - mc).abs() < 1e-9 * mc + 1e-15,
        "m′ = {}",
        1.0 - m
    );
    let flip = exact.flip_interval().unwrap();
    let quarter = flip / 2.0; // K/λ
    let t_end = 3.7 * flip;
    let text = free_text([1.0, 2.0, 3.0], [0.0, w2, w3], t_end, 0.01);
    let mut worst = 0.0f64;
    for s in every_method(2.0, [0.004, 2e-4, 0.01], [1e-10, 1e-11]) {
        let rows = rows(&scene_from(&text, &s.overrides()));
        let y = sign_changes(&rows, 1);
        let x = sign_changes(&rows[1..], 0);
        // ω_y: K/λ, 3K/λ, 5K/λ, 7K/λ; ω_x: 2K/λ, 4K/λ, 6K/λ.
        assert_eq!((y.len(), x.len()), (4, 3), "{s}: crossings {y:?} {x:?}");
        let mut err = 0.0f64;
        for (j, t) in y.iter().enumerate() {
            err = err.max((t - (2 * j + 1) as f64 * quarter).abs() / flip);
        }
        for (j, t) in x.iter().enumerate() {
            err = err.max((t - (2 * j + 2) as f64 * quarter).abs() / flip);
        }
        println!("{s}: worst crossing error {err:.2e} of 2K/λ = {flip:.4} s");
        worst = worst.max(err);
        assert!(err <= 1e-3, "{s}: {err:e}");
    }
    println!("worst {worst:.2e}");
}

#[test]
fn spins_about_the_major_and_minor_axes_stay_in_their_cones() {
    // A spin 0.035 rad off the major axis (ω = (0.05, 0.05, 2)) and off the minor axis (ω = (2, 0.05, 0.05)) of
    // I = (1, 2, 3) is stable: H_b stays on a cone about the axis, between the smallest and largest angle of the
    // closed form (sampled at 4000 points over one period), for 10⁴ periods (≈ 3.1e4 s). No spurious flip: the
    // axial component of ω never changes sign. Criterion: every row's angle within the closed-form range widened
    // by 1e-3 of the cone's angle — a method's energy error δE/E moves the cone by about (δE/E)/θ² of θ
    // (θ² ≈ 1e-3), so the steps (|ω|dt = 0.04 for rk4 and split2, 0.1 for split4) and tolerances keep δE/E ≲ 1e-7.
    // Measured worst excursion 1.9e-5 (rk4), 8.9e-6 (split2), 6.0e-6 (dopri5), ≤ 1e-7 for the others: ≥ 50×
    // margin.
    for (omega0, axis) in [([0.05, 0.05, 2.0], 2usize), ([2.0, 0.05, 0.05], 0usize)] {
        let w0 = Vector3::from(omega0);
        let exact =
            TorqueFreeBody::new(Vector3::new(1.0, 2.0, 3.0), w0, UnitQuaternion::identity())
                .unwrap();
        let period = exact.period_omega().unwrap();
        let angle = |h_b: &Vector3<f64>| h_b.xyz().remove_row(axis).norm().atan2(h_b[axis].abs());
        let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
        for k in 0..4000 {
            let a = angle(&exact.h_p(period * k as f64 / 4000.0));
            lo = lo.min(a);
            hi = hi.max(a);
        }
        let t_end = 1e4 * period;
        let text = free_text([1.0, 2.0, 3.0], omega0, t_end, 0.37);
        for s in every_method(2.0, [0.04, 0.04, 0.1], [1e-9, 1e-10]) {
            if s.frame == "space" && s.method != "dop853" && s.method != "split2" {
                continue; // both forms are exercised by the other tests; one adaptive and one split here.
            }
            let scene = scene_from(&text, &s.overrides());
            let (mut a_min, mut a_max, mut flipped) = (f64::INFINITY, 0.0f64, false);
            stream(&scene, |r| {
                let a = angle(&r.h_o_b);
                a_min = a_min.min(a);
                a_max = a_max.max(a);
                flipped |= r.omega_b[axis] <= 0.0;
            });
            let excursion = ((lo - a_min).max(a_max - hi) / hi).max(0.0);
            println!(
                "axis {axis} {s}: angle {a_min:.6}..{a_max:.6} rad, closed form {lo:.6}..{hi:.6}, excursion \
                 {excursion:.2e} of the cone"
            );
            assert!(!flipped, "{s}: spurious flip about axis {axis}");
            assert!(excursion <= 1e-3, "{s}: left the cone by {excursion:e}");
        }
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Near-symmetric and singular bodies.

#[test]
fn near_symmetric_body_is_accurate_in_closed_form_and_with_every_method() {
    // I2 − I1 = 1e-10·I1: the elliptic parameter m ≈ 1e-11 (the modulus → 0 case). Replacing the elliptic formulas
    // by the symmetric closed form would neglect (I2 − I1)/I1·ω·t ≈ 1e-8 rad over 20 s; here the closed form is
    // checked against DOP853 at rtol = 1e-13 (an independent numerical solution: they agree to 3.3e-14, bound
    // 1e-13·(1 + |ω|t)), and every method against the closed form within its tolerance-scaled bound: adaptive
    // K·rtol·(1 + |ω|t), fixed step K·(|ω|dt)^p·(1 + |ω|t), K = 1 (measured constants ≤ 0.061; a wrong method misses
    // by orders of magnitude). The splitting methods are exact in the symmetric limit (Casimir splitting) and
    // measure ≤ 1e-13 here.
    let inertia = [1.0, 1.0 + 1e-10, 1.8];
    let omega0 = [0.4, 0.1, 3.0];
    let exact = TorqueFreeBody::new(
        Vector3::from(inertia),
        Vector3::from(omega0),
        UnitQuaternion::identity(),
    )
    .unwrap();
    let m = exact.elliptic_parameter().unwrap();
    println!("m = {m:e}");
    assert!(m > 0.0 && m < 1e-9, "m = {m:e}");
    let t_end = 20.0;
    let w = Vector3::from(omega0).norm();
    let text = free_text(inertia, omega0, t_end, 0.1);
    let err_of = |rows: &[Sample]| {
        rows.iter()
            .map(|r| {
                ((*r.omega_b - exact.omega_p(r.t)).norm() / w)
                    .max(attitude_angle(&r.q, &exact.attitude(r.t)))
            })
            .fold(0.0, f64::max)
    };
    let reference = rows(&scene_from(
        &text,
        &Overrides {
            rtol: Some(1e-13),
            atol: Some(1e-15),
            ..Overrides::default()
        },
    ));
    let err = err_of(&reference);
    println!("closed form vs dop853 rtol 1e-13: {err:.2e}");
    assert!(err <= 1e-13 * (1.0 + w * t_end), "{err:e}");
    for s in every_method(w, [0.05, 0.01, 0.05], [1e-9, 1e-10]) {
        let err = err_of(&rows(&scene_from(&text, &s.overrides())));
        let accuracy = match (s.rtol, s.dt, s.method) {
            (Some(rtol), _, _) => rtol,
            (_, Some(dt), "split2") => (w * dt).powi(2),
            (_, Some(dt), _) => (w * dt).powi(4),
            _ => 1e-14,
        };
        let bound = accuracy * (1.0 + w * t_end);
        println!(
            "{s}: error {err:.2e} (bound {bound:.2e}, constant {:.3})",
            err / bound
        );
        assert!(err <= bound, "{s}: {err:e} > {bound:e}");
    }
}

#[test]
fn a_thin_rod_is_refused_with_a_clear_error_for_every_method() {
    // A thin rod (zero moment about its own axis) turning freely: refused, by choice (README, "Numerical
    // stability"): the inertia tensor does not determine the spin about the rod's axis. Every method and frame: a
    // scene error naming the key and the reason, exit 2 from the CLI, no output file, never a NaN.
    let text = "[body]\nmass = 1.0\nshape = { type = \"thin_rod\", length = 1.0 }\n[initial]\nomega = [0.0, 1.0, 2.0]\n\
                [solver]\nt_end = 1.0\n[output]\nevery = 0.1\n";
    for method in Method::ALL {
        for frame in ["body", "space"] {
            let err = scene::parse(
                Path::new("rod.toml"),
                text,
                &Overrides {
                    method: Some(method),
                    form: Some(Named::parse(frame).unwrap()),
                    ..Overrides::default()
                },
            )
            .unwrap_err();
            assert_eq!(err.key.as_deref(), Some("body.shape"), "{err}");
            assert!(err.problem.contains("zero principal moment"), "{err}");
            assert!(!err.to_string().contains("NaN"), "{err}");
        }
    }
    let dir = tempfile::tempdir().unwrap();
    let path = write_file(dir.path(), "rod.toml", text);
    let csv = dir.path().join("rod.csv");
    for method in ["split4", "exact", "rk4"] {
        let out = eulerdyn([
            "run",
            path.to_str().unwrap(),
            "--method",
            method,
            "-o",
            csv.to_str().unwrap(),
        ]);
        out.expect_code(2);
        assert!(
            out.stderr.contains("zero principal moment") && out.stderr.contains("body.shape"),
            "{}",
            out.stderr
        );
        assert!(!csv.exists());
    }
}

#[test]
fn an_almost_singular_rod_turns_as_a_linear_rotor_without_nan() {
    // Just above the refusal threshold (moment ratio 1e-10 > 1e-12): a cylinder of radius 4.1e-6 m, length 1 m
    // (symmetry axis body z, I3 = 1e-10·I1). Spinning at 3 rad/s about its own axis and turning at ≈ 1.1 rad/s
    // across it, it must behave as the limit says: the rod stays perpendicular to the fixed H_s and turns
    // uniformly about it at |H|/I1, and the spin about its axis stays 3 rad/s (I1 = I2: Euler's third equation gives
    // ω̇3 = 0). Every method agrees with the closed form (the symmetric case of TorqueFreeBody).
    // Bounds: the rod's direction (the physically meaningful part) to the tolerance-scaled bound (K = 1) of the
    // method, in both forms. The spin about the rod's own axis is ill-conditioned by I1/I3 = 1e10 in either form:
    // the body form's ω̇3 = (I1 − I2)ω1ω2/I3 is a rounded zero divided by I3, the space form's ω3 = H3/I3 a rounded
    // rotation of H_s divided by I3; either way a round-off of ε ≈ 1e-16 becomes ≈ 1e-6 relative, so the spin is
    // checked to 1e-6 (measured ≤ 3e-8 for the Runge–Kutta methods). (At the refusal threshold, I3/I1 = 1e-12,
    // this would be 1e-4.) The splitting methods turn the body about its axis exactly (Casimir splitting: for
    // I1 = I2 the drift is two commuting exact flows): measured spin error ≤ 2.3e-13 in the body form.
    // The space form is stiff here: ω3 = H3/I3 responds to an attitude change δ with |H|δ/I3, a rate 1e10 times
    // the motion's, so an explicit fixed step must be tiny (RK4 needs dt ≈ 1e-5; at |ω|dt = 0.05 it blows up) and
    // the adaptive methods take ~2.4e5 steps per second of motion. Criterion there: RK4 stops with
    // RunError::Diverged (the guard), never a NaN; the others finish and pass the rod checks. t_end = 2 s keeps
    // the adaptive space-form runs at ~0.3 s each. In the space form ω3 = (rod_s·H_s)/I3: an error δ in the rod's
    // direction becomes an error κ·δ in ω3/3 with κ = |H|/(3 I3) ≈ 3.7e9 — the space form cannot know the spin of
    // a near-singular axis better than that, whatever the method — so there the spin is checked to κ·(rod
    // direction error + 8ε) (measured: dopri5 1.7e-3, dop853 2.5e-4, split4 2.0e-5, exact 1.5e-6, all within it).
    let (mass, length) = (1.0, 1.0);
    let radius = (1e-10f64 / 6.0).sqrt() * length;
    let text = format!(
        "[body]\nmass = {mass:?}\nshape = {{ type = \"cylinder\", radius = {radius:?}, height = {length:?} }}\n\
         [initial]\nomega = [1.0, 0.5, 3.0]\n[solver]\nt_end = 2.0\n[output]\nevery = 0.02\n"
    );
    let base = scene_from(&text, &Overrides::default());
    let moments = base.body.principal().moments;
    println!("moments {moments:?}, ratio {:e}", moments[2] / moments[0]);
    assert!(moments[2] / moments[0] < 1.1e-10);
    let exact = TorqueFreeBody::new(
        moments,
        Vector3::new(1.0, 0.5, 3.0),
        UnitQuaternion::identity(),
    )
    .unwrap();
    let h_s = exact.h_s();
    let precession = h_s.norm() / moments[0];
    let kappa = h_s.norm() / (3.0 * moments[2]);
    let w = 3.2;
    for s in every_method(w, [0.05, 0.01, 0.05], [1e-9, 1e-10]) {
        let (rows, result) = try_rows(&scene_from(&text, &s.overrides()));
        assert!(rows.iter().all(|r| r.omega_b.iter().all(|v| v.is_finite())));
        if (s.method, s.frame) == ("rk4", "space") {
            let Err(RunError::Diverged(d)) = result else {
                panic!("{s}: expected the guard to stop the stiff space form");
            };
            println!("{s}: {d}");
            continue;
        }
        if let Err(e) = result {
            panic!("{s}: {e}");
        }
        let accuracy = match (s.rtol, s.dt, s.method) {
            (Some(rtol), _, _) => rtol,
            (_, Some(dt), "split2") => (w * dt).powi(2),
            (_, Some(dt), _) => (w * dt).powi(4),
            _ => 1e-14,
        };
        let bound = accuracy * (1.0 + w * 2.0);
        let (mut err_rod, mut err_spin, mut perp) = (0.0f64, 0.0f64, 0.0f64);
        let axis0 = Vector3::z();
        for r in &rows {
            let rod_s = r.q * axis0;
            // The rod turns about H at |H|/I1: rod(t) = Rot(Ĥ, |H|t/I1) · rod(0).
            let expected = UnitQuaternion::from_axis_angle(
                &nalgebra::Unit::new_normalize(h_s),
                precession * r.t,
            ) * axis0;
            err_rod = err_rod.max((rod_s - expected).norm());
            perp = perp.max(rod_s.dot(&h_s.normalize()).abs());
            err_spin = err_spin.max((r.omega_b[2] - 3.0).abs() / 3.0);
        }
        println!(
            "{s}: rod direction error {err_rod:.2e}, |rod·Ĥ| {perp:.2e}, spin error {err_spin:.2e} (bound {bound:.2e})"
        );
        assert!(
            err_rod <= bound,
            "{s}: rod direction {err_rod:e} > {bound:e}"
        );
        assert!(
            perp <= 1e-9 + bound,
            "{s}: rod not perpendicular to H: {perp:e}"
        );
        // Space form: ω3 = (rod_s·H_s)/I3, so an error δ in the rod's direction gives |δ||H|/I3 in ω3.
        let spin_bound = if s.frame == "body" {
            1e-6
        } else {
            kappa * (err_rod + 8.0 * f64::EPSILON)
        };
        assert!(
            err_spin <= spin_bound,
            "{s}: spin {err_spin:e} > {spin_bound:e}"
        );
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Fast spin.

#[test]
fn fast_spin_adaptive_methods_finish_and_a_too_large_fixed_step_is_caught() {
    // ω = (1, 2, 1e4) rad/s about the major axis of I = (1, 2, 3), 1 s (1e4 rad). Criteria:
    // - adaptive methods finish, with accepted + rejected steps ≤ |ω| t_end · rtol^(−1/(p+1)) (the step of an order-p
    //   pair is about rtol^(1/(p+1))/|ω|; measured: dopri5 at 1e-8 uses 0.57 of it, dop853 at 1e-10 0.22), and
    //   agree with the closed form within the tolerance-scaled bound (adaptive K·rtol·(1 + |ω|t), K = 1);
    // - split2/split4 and exact finish and agree with the closed form: bound 1e-3·(|ω|dt)^p(1 + |ω|t) — the spin
    //   itself is an exact rotation of the splitting and only the transverse part (2.2e-4 of |ω|) carries splitting
    //   error, so the measured constants are 5e-6 (split2, |ω|dt = 0.02) and 1.3e-7 (split4, |ω|dt = 0.1): ≥ 50×
    //   margin; exact to 1e-12 (measured 2.9e-14: the rows from the equal-grid walk, the reference evaluated
    //   directly; the precession angle φ ≈ 3e4 rad has its secular part in double-double in both, so no allowance
    //   for its rounding ε·φ ≈ 7e-12, which the bound carried until then, measured 6.6e-12);
    // - RK4 with |ω|·dt = 5 (beyond its stability limit 2√2 on the imaginary axis) blows up: the run stops with
    //   RunError::Diverged carrying the time and a hint, and every row delivered before is finite, earlier than that
    //   time, and within the guard's allowance of the conserved energy (no garbage row).
    let omega0 = [1.0, 2.0, 1e4];
    let w = Vector3::from(omega0).norm();
    let text = free_text([1.0, 2.0, 3.0], omega0, 1.0, 1e-3);
    let exact = TorqueFreeBody::new(
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::from(omega0),
        UnitQuaternion::identity(),
    )
    .unwrap();
    let err_of = |rows: &[Sample]| {
        rows.iter()
            .map(|r| {
                ((*r.omega_b - exact.omega_p(r.t)).norm() / w)
                    .max(attitude_angle(&r.q, &exact.attitude(r.t)))
            })
            .fold(0.0, f64::max)
    };
    for (method, order, rtol) in [("dopri5", 5.0, 1e-8), ("dop853", 8.0, 1e-10)] {
        for frame in ["body", "space"] {
            let s = Setting {
                method,
                frame,
                rtol: Some(rtol),
                dt: None,
            };
            let (rows, r) = try_rows(&scene_from(&text, &s.overrides()));
            let stats = r.unwrap_or_else(|e| panic!("{s}: {e}")).stats;
            let limit = w * 1.0 * rtol.powf(-1.0 / (order + 1.0));
            let used = (stats.steps + stats.rejected) as f64;
            let err = err_of(&rows);
            let bound = rtol * (1.0 + w);
            println!(
                "{s}: {} steps + {} rejected = {:.2} of the limit {limit:.3e}; error {err:.2e} (bound {bound:.2e})",
                stats.steps,
                stats.rejected,
                used / limit
            );
            assert!(used <= limit, "{s}: {used} steps");
            assert!(err <= bound, "{s}: {err:e}");
        }
    }
    for (method, dt, order) in [("split2", 2e-6, 2), ("split4", 1e-5, 4), ("exact", 0.0, 0)] {
        let s = Setting {
            method,
            frame: "body",
            rtol: None,
            dt: (dt > 0.0).then_some(dt),
        };
        let err = err_of(&rows(&scene_from(&text, &s.overrides())));
        let bound = if order == 0 {
            1e-12
        } else {
            1e-3 * (w * dt).powi(order) * (1.0 + w)
        };
        println!("{s}: error {err:.2e} (bound {bound:.2e})");
        assert!(err <= bound, "{s}: {err:e}");
    }
    for frame in ["body", "space"] {
        let scene = scene_from(
            &text,
            &Overrides {
                method: Some(Named::parse("rk4").unwrap()),
                form: Some(Named::parse(frame).unwrap()),
                dt: Some(5e-4),
                ..Overrides::default()
            },
        );
        let guard = simulate::DivergenceGuard::new(&scene).unwrap();
        let (rows, r) = try_rows(&scene);
        let Err(RunError::Diverged(d)) = r else {
            panic!(
                "rk4 {frame}: expected a divergence, got {:?}",
                r.map(|r| r.rows)
            );
        };
        let msg = d.to_string();
        println!("rk4 {frame} dt 5e-4: {} rows, then: {msg}", rows.len());
        assert!(d.t > 0.0 && d.t <= 0.01, "{frame}: {}", d.t);
        assert!(
            msg.contains(&format!("t = {}", d.t)) && msg.contains("smaller dt"),
            "{msg}"
        );
        assert!(matches!(
            d.quantity,
            GuardedQuantity::Energy | GuardedQuantity::HNorm | GuardedQuantity::HSpace
        ));
        let e0 = exact.energy();
        for r in &rows {
            assert!(r.t < d.t);
            assert!(
                r.omega_b
                    .iter()
                    .chain(r.h_o_s.iter())
                    .all(|v| v.is_finite())
            );
            assert!(
                (r.energy - e0).abs() <= guard.allowance(r.t) * e0,
                "{frame}: garbage row at t = {}",
                r.t
            );
        }
    }
    // Through the command line: exit 1, the time and the hint, and no output file.
    let dir = tempfile::tempdir().unwrap();
    let path = write_file(dir.path(), "fast.toml", &text);
    let csv = dir.path().join("fast.csv");
    let out = eulerdyn([
        "run",
        path.to_str().unwrap(),
        "--method",
        "rk4",
        "--dt",
        "5e-4",
        "-o",
        csv.to_str().unwrap(),
    ]);
    out.expect_code(1);
    assert!(
        out.stderr.contains("diverged at t = ") && out.stderr.contains("smaller dt"),
        "{}",
        out.stderr
    );
    assert!(!csv.exists());
}

// ---------------------------------------------------------------------------------------------------------------
// Strong damping, degenerate tilts, zero rate, t_end = 0.

#[test]
fn strong_damping_decays_exactly_and_an_unstable_step_is_caught() {
    // Spin about the major axis (I3 = 3) under M = −cω with c = 3, t_end = 50: c·t_end/I = 50 (issue: ≥ 50).
    // ω3(t) = 5 exp(−c t/I3) (ω decays by e⁻⁵⁰ ≈ 2e-22). Criterion: |ω3 − exact| ≤ bound·5 at every row, with the
    // tolerance-scaled bound (K = 1) of the method (for the splitting methods the damping kick is the exact
    // exponential and the spin about a principal axis an exact rotation, so their error is round-off: bound
    // 1e-13, measured ≤ 1e-15). A transverse perturbation (ω(0) = (0.3, 0.2, 5)) is checked against DOP853 at
    // rtol 1e-13 with the same bounds (measured constants ≤ 1e-4).
    // RK4 with c·dt/I = 3 lies outside its stability interval (−2.785, 0) on the real axis: the energy grows,
    // which damping cannot do, and the guard stops the run (RunError::Diverged, energy). The splitting methods
    // at the same step still decay (exact kicks: unconditionally stable).
    let damped = |omega: [f64; 3]| {
        format!(
            "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [{:?}, {:?}, {:?}]\n\
             [[effect]]\ntype = \"damping\"\nc = 3.0\n[solver]\nt_end = 50.0\n[output]\nevery = 0.25\n",
            omega[0], omega[1], omega[2]
        )
    };
    let text = damped([0.0, 0.0, 5.0]);
    for s in every_method(5.0, [0.01, 0.01, 0.05], [1e-9, 1e-10]) {
        if s.method == "exact" {
            continue; // refused with effects: see geometric_methods.rs
        }
        let rows = rows(&scene_from(&text, &s.overrides()));
        let err = rows
            .iter()
            .map(|r| (r.omega_b[2] - 5.0 * (-r.t).exp()).abs() / 5.0)
            .fold(0.0, f64::max);
        let bound = match (s.rtol, s.dt, s.method) {
            (Some(rtol), _, _) => rtol * (1.0 + 5.0 * 50.0),
            (_, Some(dt), "rk4") => (5.0 * dt).powi(4) * (1.0 + 5.0 * 50.0),
            _ => 1e-13,
        };
        println!("{s}: ω3 error {err:.2e} (bound {bound:.2e})");
        assert!(err <= bound, "{s}: {err:e}");
        assert!(rows.iter().all(|r| r.omega_b.xy().norm() == 0.0));
    }
    let text = damped([0.3, 0.2, 5.0]);
    let reference = rows(&scene_from(
        &text,
        &Overrides {
            rtol: Some(1e-13),
            atol: Some(1e-16),
            ..Overrides::default()
        },
    ));
    for s in every_method(5.0, [0.01, 0.001, 0.02], [1e-9, 1e-10]) {
        if s.method == "exact" {
            continue;
        }
        let rows = rows(&scene_from(&text, &s.overrides()));
        let err = rows
            .iter()
            .zip(&reference)
            .map(|(r, f)| ((r.omega_b - f.omega_b).norm() / 5.0).max(attitude_angle(&r.q, &f.q)))
            .fold(0.0, f64::max);
        let bound = match (s.rtol, s.dt, s.method) {
            (Some(rtol), _, _) => rtol * (1.0 + 5.0 * 50.0),
            (_, Some(dt), "split2") => (5.0 * dt).powi(2) * (1.0 + 5.0 * 50.0),
            (_, Some(dt), _) => (5.0 * dt).powi(4) * (1.0 + 5.0 * 50.0),
            _ => unreachable!(),
        };
        println!("tumbling {s}: error {err:.2e} (bound {bound:.2e})");
        assert!(err <= bound, "{s}: {err:e}");
    }
    let unstable = |method: &str| {
        scene_from(
            &damped([0.0, 0.0, 5.0]),
            &Overrides {
                method: Some(Named::parse(method).unwrap()),
                dt: Some(3.0),
                every: Some(3.0),
                ..Overrides::default()
            },
        )
    };
    let (delivered, r) = try_rows(&unstable("rk4"));
    match r {
        Err(RunError::Diverged(d)) => {
            println!("rk4 c·dt/I = 3: {d}");
            assert_eq!(d.quantity, GuardedQuantity::Energy);
            assert!(delivered.iter().all(|r| r.energy <= delivered[0].energy));
        }
        other => panic!("rk4 with c·dt/I = 3: {:?}", other.map(|r| r.rows)),
    }
    for method in ["split2", "split4"] {
        let rows = rows(&unstable(method));
        for pair in rows.windows(2) {
            assert!(
                pair[1].omega_b[2] < pair[0].omega_b[2],
                "{method}: no decay at t = {}",
                pair[1].t
            );
            let expected = 5.0 * (-pair[1].t).exp();
            assert!(
                (pair[1].omega_b[2] - expected).abs() <= 1e-13 * 5.0,
                "{method}"
            );
        }
    }
}

#[test]
fn fixed_axis_at_zero_ninety_degrees_and_a_tiny_tilt() {
    // The notes' thin disk (m = 2 kg, R = 0.3 m, ω = 10 rad/s) on a fixed axis tilted θ from its symmetry axis:
    // the bearing moment is M = ¼ m R² ω² sin θ cos θ about body x (−, eq. 8.9 with ω constant), zero at θ = 0 and
    // 90° (principal axes) and 1.7e-10·¼mR²ω² at θ = 1e-8 degrees. Every method: M_b_x to 1e-14 of ¼mR²ω² (the
    // closed form, whatever the method: the rows of a prescribed motion are computed, not integrated), and H_s_int,
    // Ḣ_s = M_s integrated by the method, within its tolerance-scaled bound (K = 1) of the closed-form H_s (which
    // turns about the axis at ω when θ is not 0 or 90°).
    let text = std::fs::read_to_string("scenarios/tilted_disk.toml").unwrap();
    let (m, r, w) = (2.0, 0.3, 10.0);
    let scale = 0.25 * m * r * r * w * w;
    for tilt in [0.0f64, 90.0, 1e-8] {
        let theta = tilt.to_radians();
        let scene_text = text.replace("tilt_deg = 30 ", &format!("tilt_deg = {tilt:?} "));
        assert_ne!(scene_text, text, "the scenario sets tilt_deg = 30");
        for s in every_method(w, [0.01, 0.001, 0.01], [1e-9, 1e-10]) {
            let rows = rows(&scene_from(&scene_text, &s.overrides()));
            let expected = -scale * theta.sin() * theta.cos();
            let bound = match (s.rtol, s.dt, s.method) {
                (Some(rtol), _, _) => rtol * (1.0 + w * 1.0),
                (_, Some(dt), "split2") => (w * dt).powi(2) * (1.0 + w * 1.0),
                (_, Some(dt), _) => (w * dt).powi(4) * (1.0 + w * 1.0),
                _ => 1e-15,
            };
            let (mut err_m, mut err_h) = (0.0f64, 0.0f64);
            for row in &rows {
                err_m = err_m.max((row.m_o_b[0] - expected).abs() / scale);
                err_m = err_m.max(row.m_o_b.yz().norm() / scale);
                let h_int = row.h_o_s_integrated.unwrap();
                err_h = err_h.max((h_int - row.h_o_s).norm() / row.h_o_s.norm());
            }
            println!(
                "tilt {tilt} deg {s}: M error {err_m:.2e}, H_s_int error {err_h:.2e} (bound {bound:.2e})"
            );
            assert!(err_m <= 1e-14, "tilt {tilt} {s}: M {err_m:e}");
            assert!(
                err_h <= bound,
                "tilt {tilt} {s}: H_s_int {err_h:e} > {bound:e}"
            );
        }
    }
}

#[test]
fn zero_rate_stays_at_rest_with_every_method() {
    // ω(0) = 0, torque-free and damped: every method and frame keeps ω = 0, H = 0, energy 0 and the attitude
    // exactly (no division by |ω|, no NaN). A fixed axis at rate 0: M = 0 and θ = 0.
    let free = "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nattitude = [0.9, 0.1, -0.3, 0.2]\n\
                [solver]\nt_end = 1.0\n[output]\nevery = 0.25\n";
    let damped = format!("{free}[[effect]]\ntype = \"damping\"\nc = 0.5\n");
    for text in [free.to_string(), damped] {
        for s in every_method(1.0, [0.01, 0.01, 0.01], [1e-9, 1e-10]) {
            let Ok(scene) = scene::parse(Path::new("t.toml"), &text, &s.overrides()) else {
                assert!(s.method == "exact" && text.contains("damping"));
                continue;
            };
            let rows = rows(&scene);
            assert_eq!(rows.len(), 5);
            for r in &rows {
                assert_eq!(*r.omega_b, Vector3::zeros(), "{s}");
                assert_eq!(*r.h_o_s, Vector3::zeros(), "{s}");
                assert_eq!(r.energy, 0.0, "{s}");
                assert!(attitude_angle(&r.q, &scene.attitude0) <= 1e-15, "{s}");
            }
        }
    }
    let text = std::fs::read_to_string("scenarios/tilted_disk.toml")
        .unwrap()
        .replace("rate = 10.0", "rate = 0.0");
    for s in every_method(1.0, [0.01, 0.01, 0.01], [1e-9, 1e-10]) {
        for r in rows(&scene_from(&text, &s.overrides())) {
            assert_eq!(*r.m_o_b, Vector3::zeros(), "{s}");
            assert_eq!(r.theta, Some(0.0), "{s}");
            assert_eq!(
                r.h_o_s_integrated.map(|h| *h),
                Some(Vector3::zeros()),
                "{s}"
            );
        }
    }
}

#[test]
fn t_end_zero_gives_the_initial_row_with_every_method() {
    // t_end = 0: one row, t = 0, the initial state itself, for every method, frame and kind of motion.
    let texts = [
        free_text([1.0, 2.0, 3.0], [0.3, 0.0, 2.0], 0.0, 0.1),
        std::fs::read_to_string("scenarios/heavy_top.toml").unwrap(),
        std::fs::read_to_string("scenarios/tilted_disk.toml").unwrap(),
    ];
    for text in &texts {
        for s in every_method(1.0, [0.01, 0.01, 0.01], [1e-9, 1e-10]) {
            let mut o = s.overrides();
            o.t_end = Some(0.0);
            let Ok(scene) = scene::parse(Path::new("t.toml"), text, &o) else {
                assert!(s.method == "exact" && text.contains("gravity"));
                continue;
            };
            let (rows, r) = try_rows(&scene);
            let report = r.unwrap_or_else(|e| panic!("{s}: {e}"));
            assert_eq!(rows.len(), 1, "{s}");
            assert_eq!(rows[0].t, 0.0);
            assert_eq!(report.stats.steps, 0, "{s}");
            assert!(attitude_angle(&rows[0].q, &scene.attitude0) <= 1e-15, "{s}");
            if let eulerdyn::scene::Motion::Free { omega0_b, .. } = &scene.motion {
                assert!(
                    (rows[0].omega_b - *omega0_b).norm() <= 1e-15 * omega0_b.norm(),
                    "{s}"
                );
            }
        }
    }
}
