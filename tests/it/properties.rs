//! Property tests over random valid bodies (principal moments obeying the triangle inequality, principal axes in any
//! orientation), angular velocities and attitudes, with `dop853`, `split4` and `exact`:
//!
//! - the body and the space form agree;
//! - rotating the scene's body axes (I' = R I Rᵀ, ω' = R ω, q' = q R⁻¹) rotates the body-axis results and changes
//!   nothing else;
//! - the invariants hold within tolerance-scaled bounds: energy, |H| and H_s torque-free, |q| = 1 always;
//! - with damping and torques (random), the two forms still agree.
//!
//! Bounds: an adaptive method's global error is K·rtol·(1 + Ωt) with Ω = √(2E/I_min) the largest |ω| the energy
//! allows; split4's (Ω dt)⁴(1 + Ωt); exact's round-off. Where two runs are compared, the bound is the sum of
//! their two errors. The constants quoted at each property are the worst over 20000 random cases (measured with
//! the same generators and checks outside proptest); CI runs 64 cases per property
//! (`PROPTEST_CASES=20000 cargo test --test properties` runs more).

use std::convert::Infallible;
use std::path::Path;

use eulerdyn::analysis::compare::attitude_angle;
use eulerdyn::named::Named;
use eulerdyn::sample::Sample;
use eulerdyn::scene::Scene;
use eulerdyn::scene::{self, Overrides};
use eulerdyn::simulate;
use nalgebra::{Matrix3, Quaternion, Rotation3, UnitQuaternion, Vector3};
use proptest::prelude::*;

/// 64 cases per property, or `PROPTEST_CASES` when set.
fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(64)
}

const T_END: f64 = 3.0;
const RTOL: f64 = 1e-11;
/// split4's step as a fraction of 1/Ω.
const SPLIT_OMEGA_DT: f64 = 0.02;

/// A random torque-free (or effected) scene.
#[derive(Debug, Clone)]
struct Case {
    moments: [f64; 3],
    axes: Rotation3<f64>,
    omega_b: Vector3<f64>,
    attitude: UnitQuaternion<f64>,
}

impl Case {
    fn inertia_b(&self) -> Matrix3<f64> {
        self.axes.matrix()
            * Matrix3::from_diagonal(&Vector3::from(self.moments))
            * self.axes.matrix().transpose()
    }

    /// Ω = √(2E/I_min).
    fn omega_bound(&self) -> f64 {
        let i_b = self.inertia_b();
        let e = 0.5 * self.omega_b.dot(&(i_b * self.omega_b));
        let i_min = self.moments.iter().cloned().fold(f64::INFINITY, f64::min);
        (2.0 * e / i_min).sqrt()
    }

    /// The scene text, with the body axes turned by `turn` (I' = R I Rᵀ, ω' = R ω, q' = q R⁻¹) and `effects`
    /// appended.
    fn text(&self, turn: &Rotation3<f64>, effects: &str) -> String {
        let m = turn.matrix() * self.inertia_b() * turn.matrix().transpose();
        // Symmetrise exactly so that the tensor passes the symmetry check bit for bit.
        let m = (m + m.transpose()) * 0.5;
        let w = turn * self.omega_b;
        let q = self.attitude * UnitQuaternion::from_rotation_matrix(turn).inverse();
        let row = |i: usize| format!("[{:?}, {:?}, {:?}]", m[(i, 0)], m[(i, 1)], m[(i, 2)]);
        format!(
            "[body]\nmass = 1.0\ninertia = [{}, {}, {}]\n[initial]\nomega = [{:?}, {:?}, {:?}]\n\
             attitude = [{:?}, {:?}, {:?}, {:?}]\n{effects}[solver]\nt_end = {T_END:?}\n[output]\nevery = 0.25\n",
            row(0),
            row(1),
            row(2),
            w[0],
            w[1],
            w[2],
            q.w,
            q.i,
            q.j,
            q.k
        )
    }
}

fn rotation() -> impl Strategy<Value = Rotation3<f64>> {
    (-3.2f64..3.2, -1.6f64..1.6, -3.2f64..3.2)
        .prop_map(|(a, b, c)| Rotation3::from_euler_angles(a, b, c))
}

fn case() -> impl Strategy<Value = Case> {
    (
        0.5f64..3.0,
        0.5f64..3.0,
        0.05f64..0.95,
        prop_oneof![Just(None), rotation().prop_map(Some)],
        (-2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0),
        (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0),
    )
        .prop_filter_map(
            "|ω| and |q| bounded away from 0",
            |(a, b, u, axes, (wx, wy, wz), (qw, qx, qy, qz))| {
                let (lo, hi) = ((a - b).abs(), a + b);
                let c = lo + u * (hi - lo);
                let omega_b = Vector3::new(wx, wy, wz);
                let q = Quaternion::new(qw, qx, qy, qz);
                (omega_b.norm() > 0.1 && q.norm() > 0.2).then(|| Case {
                    moments: [a, b, c],
                    axes: axes.unwrap_or_else(Rotation3::identity),
                    omega_b,
                    attitude: UnitQuaternion::from_quaternion(q),
                })
            },
        )
}

fn scene(text: &str, method: &str, frame: &str, omega: f64) -> Scene {
    let o = Overrides {
        method: Some(Named::parse(method).unwrap()),
        form: Some(Named::parse(frame).unwrap()),
        rtol: Some(RTOL),
        atol: Some(RTOL * 1e-2),
        dt: Some(SPLIT_OMEGA_DT / omega),
        ..Overrides::default()
    };
    scene::parse(Path::new("prop.toml"), text, &o).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

fn rows(scene: &Scene) -> Vec<Sample> {
    let mut out = Vec::new();
    simulate::run(scene, |s| {
        out.push(*s);
        Ok::<(), Infallible>(())
    })
    .unwrap_or_else(|e| panic!("{e}"));
    out
}

/// The error bound of one run of `method` (relative to |ω|, or in rad for the attitude), K = `k`.
fn bound(method: &str, omega: f64, k: f64) -> f64 {
    let growth = 1.0 + omega * T_END;
    match method {
        "dop853" => k * RTOL * growth,
        "split4" => k * SPLIT_OMEGA_DT.powi(4) * growth,
        _ => 1e-12 * growth,
    }
}

/// Two runs of dop853 that should agree (the two forms) differ by the sum of their errors, K = 1 each — except
/// near the separatrix, where any two nearby solutions separate exponentially (rate up to Ω) and so do the two
/// runs' errors: over 20000 random cases the worst difference was 11.3 times the K = 1 sum torque-free and 4.1 with
/// effects. K = 50 keeps a 4× margin over that; a wrong form (a sign, a frame mix-up) misses by 10⁶ or more.
const K_FORMS_DOP853: f64 = 50.0;

/// The two forms of split4 are the same map, and split4 and exact compute in the principal axes whichever way the
/// body axes are turned: their comparisons differ by round-off only. Worst over 20000 cases: 6.4e-14·(1 + Ωt)
/// (forms), 7.5e-14·(1 + Ωt) (forms under effects), 8.9e-15·(1 + Ωt) (turned axes); bound 1e-12·(1 + Ωt).
const ROUND_OFF: f64 = 1e-12;

const METHODS: [&str; 3] = ["dop853", "split4", "exact"];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Body and space forms give the same ω_b, attitude and H_s: dop853 within the sum of its two errors,
    /// K_FORMS_DOP853; split4 (the same map) and exact (two readings of the closed form; worst 1.7e-15·(1 + Ωt))
    /// to round-off, ROUND_OFF·(1 + Ωt).
    #[test]
    fn body_and_space_forms_agree(c in case()) {
        let omega = c.omega_bound();
        let text = c.text(&Rotation3::identity(), "");
        for method in METHODS {
            let body = rows(&scene(&text, method, "body", omega));
            let space = rows(&scene(&text, method, "space", omega));
            let limit = match method {
                "dop853" => 2.0 * bound(method, omega, K_FORMS_DOP853),
                _ => ROUND_OFF * (1.0 + omega * T_END),
            };
            for (b, s) in body.iter().zip(&space) {
                prop_assert_eq!(b.t, s.t);
                let w = (b.omega_b - s.omega_b).norm() / omega;
                let q = attitude_angle(&b.q, &s.q);
                let h = (b.h_o_s - s.h_o_s).norm() / b.h_o_s.norm();
                prop_assert!(w <= limit && q <= limit && h <= limit,
                    "{method} t = {}: ω {w:e}, q {q:e}, H_s {h:e} > {limit:e}\n{text}", b.t);
            }
        }
    }

    /// Turning the body axes by R rotates ω_b, H_b, M_b by R and the attitude by R⁻¹ on the right, and leaves ω_s,
    /// H_s, the energy and |H| alone. split4 and exact work in the principal axes, found either way, so the two
    /// runs agree to round-off (ROUND_OFF); dop853's error control works per component, so its two runs differ
    /// within the sum of their errors, K = 1 each (worst over 20000 cases: 0.52 of it).
    #[test]
    fn rotating_the_body_axes_rotates_the_results(c in case(), turn in rotation()) {
        let omega = c.omega_bound();
        let plain = c.text(&Rotation3::identity(), "");
        let turned = c.text(&turn, "");
        let r_q = UnitQuaternion::from_rotation_matrix(&turn);
        for method in METHODS {
            let a = rows(&scene(&plain, method, "body", omega));
            let b = rows(&scene(&turned, method, "body", omega));
            let limit = match method {
                "dop853" => 2.0 * bound(method, omega, 1.0),
                _ => ROUND_OFF * (1.0 + omega * T_END),
            };
            for (x, y) in a.iter().zip(&b) {
                let w = (turn * *x.omega_b - *y.omega_b).norm() / omega;
                let ws = (x.omega_s - y.omega_s).norm() / omega;
                let q = attitude_angle(&(x.q * r_q.inverse()), &y.q);
                let h = (*x.h_o_s - *y.h_o_s).norm().max((turn * *x.h_o_b - *y.h_o_b).norm()) / x.h_o_s.norm();
                let e = (x.energy - y.energy).abs() / x.energy;
                prop_assert!(w <= limit && ws <= limit && q <= limit && h <= limit && e <= limit,
                    "{method} t = {}: ω_b {w:e} ω_s {ws:e} q {q:e} H {h:e} E {e:e} > {limit:e}\n{turned}", x.t);
            }
        }
    }

    /// Torque-free invariants: H_s (so |H|) and the energy. exact: round-off, 1e-12 (worst 5.6e-15). split4: |H| to
    /// 1e-13 (exact in the splitting, H_p rescaled to |H(0)| every step; worst 1.8e-15), H_s to 1e-12 (round-off of
    /// the attitude; worst 5.3e-14), the energy within its bounded error K(Ω dt)⁴, K = 1 (worst 4e-5 of it);
    /// dop853: all three within K·rtol·(1 + Ωt), K = 1 (worst 0.094 of it). |q| = 1 to 4ε (worst 3ε; the rows
    /// carry the renormalised state), 8ε for exact (worst 6ε: the closed-form attitude times P⁻¹).
    #[test]
    fn invariants_hold(c in case()) {
        let omega = c.omega_bound();
        let text = c.text(&Rotation3::identity(), "");
        for method in METHODS {
            for frame in ["body", "space"] {
                let rows = rows(&scene(&text, method, frame, omega));
                let (e0, h0) = (rows[0].energy, rows[0].h_o_s);
                let (limit_h, limit_hs, limit_e) = match method {
                    "dop853" => { let b = bound(method, omega, 1.0); (b, b, b) }
                    "split4" => (1e-13, 1e-12, SPLIT_OMEGA_DT.powi(4)),
                    _ => (1e-12, 1e-12, 1e-12),
                };
                for r in &rows {
                    let h = (r.h_o_s.norm() - h0.norm()).abs() / h0.norm();
                    let hs = (r.h_o_s - h0).norm() / h0.norm();
                    let e = (r.energy - e0).abs() / e0;
                    prop_assert!(h <= limit_h && hs <= limit_hs && e <= limit_e,
                        "{method} {frame} t = {}: |H| {h:e}, H_s {hs:e}, E {e:e}\n{text}", r.t);
                    let unit = if method == "exact" { 8.0 } else { 4.0 } * f64::EPSILON;
                    prop_assert!((r.q.into_inner().norm() - 1.0).abs() <= unit, "{method} {frame}: |q|");
                }
            }
        }
    }

    /// With damping and torques (constant in body axes, sine in space axes), the two forms still agree: split4's are
    /// the same map (ROUND_OFF), dop853's within the sum of their errors (K_FORMS_DOP853).
    #[test]
    fn forms_agree_under_effects(
        c in case(),
        damping in 0.0f64..0.5,
        m_b in (-0.3f64..0.3, -0.3f64..0.3, -0.3f64..0.3),
        m_s in (-0.3f64..0.3, -0.3f64..0.3, -0.3f64..0.3),
    ) {
        let effects = format!(
            "[[effect]]\ntype = \"damping\"\nc = {damping:?}\n\
             [[effect]]\ntype = \"torque\"\nframe = \"body\"\nvalue = [{:?}, {:?}, {:?}]\n\
             [[effect]]\ntype = \"torque\"\nframe = \"space\"\nvalue = [{:?}, {:?}, {:?}]\nprofile = \"sine\"\nfreq_hz = 0.4\n",
            m_b.0, m_b.1, m_b.2, m_s.0, m_s.1, m_s.2
        );
        let text = c.text(&Rotation3::identity(), &effects);
        // Ω: the torques add at most |M| t/√(2 I_min) to √E (the divergence guard's bound), so at most |M| t/I_min
        // to Ω = √(2E/I_min); taken √2 larger for margin.
        let i_min = c.moments.iter().cloned().fold(f64::INFINITY, f64::min);
        let m = Vector3::new(m_b.0, m_b.1, m_b.2).norm() + Vector3::new(m_s.0, m_s.1, m_s.2).norm();
        let omega = c.omega_bound() + std::f64::consts::SQRT_2 * m * T_END / i_min;
        for method in ["dop853", "split4"] {
            let body = rows(&scene(&text, method, "body", omega));
            let space = rows(&scene(&text, method, "space", omega));
            let limit = match method {
                "dop853" => 2.0 * bound(method, omega, K_FORMS_DOP853),
                _ => ROUND_OFF * (1.0 + omega * T_END),
            };
            for (b, s) in body.iter().zip(&space) {
                let w = (b.omega_b - s.omega_b).norm() / omega;
                let q = attitude_angle(&b.q, &s.q);
                prop_assert!(w <= limit && q <= limit, "{method} t = {}: ω {w:e}, q {q:e} > {limit:e}\n{text}", b.t);
            }
        }
    }
}
