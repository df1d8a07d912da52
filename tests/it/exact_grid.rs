//! The exact torque-free flow on an equal grid (`exact`, issue 26): rows advanced by addition theorems
//! (`TorqueFreeBody::equal_grid`), against an mpmath oracle and against the direct evaluation of the closed form.

use std::convert::Infallible;

use eulerdyn::exact::{ANCHOR_ROWS, TorqueFreeBody};
use eulerdyn::motion::exact_flow::ExactFlow;
use eulerdyn::named::Named;
use eulerdyn::sample::Sample;
use eulerdyn::scene::Overrides;
use eulerdyn::simulate;
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use crate::common::scene_from;

/// The oracle: tests/data/make_exact_grid_oracle.py (mpmath, 40 digits; ω by Jacobi's functions, the precession
/// angle by quadrature of its rate, checked against mpmath's Taylor ODE solver), every 331st row of
/// t_k = k·1e-3 s, k ≤ 10⁵, for I = (1, 2, 3), ω(0) = (0.3, 0, 2), q(0) = 1.
const ORACLE: &str = include_str!("../data/exact_grid_oracle.csv");

struct OracleRow {
    k: usize,
    omega_b: Vector3<f64>,
    q_b: UnitQuaternion<f64>,
}

fn oracle() -> Vec<OracleRow> {
    ORACLE
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('k'))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            OracleRow {
                k: v[0] as usize,
                omega_b: Vector3::new(v[2], v[3], v[4]),
                q_b: UnitQuaternion::new_normalize(Quaternion::new(v[5], v[6], v[7], v[8])),
            }
        })
        .collect()
}

/// The angle of the rotation between two attitudes (rad).
fn angle(a: &UnitQuaternion<f64>, b: &UnitQuaternion<f64>) -> f64 {
    let d = a.inverse() * b;
    2.0 * d.imag().norm().min(1.0).asin()
}

fn benchmark_text(t_end: f64, every: f64) -> String {
    format!(
        "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 0.0, 2.0]\n\
         [solver]\nmethod = \"exact\"\nt_end = {t_end:?}\n[output]\nevery = {every:?}\n"
    )
}

#[test]
fn equal_grid_matches_the_mpmath_oracle_over_1e5_rows() {
    // Criterion (issue 26): error against the oracle ≤ 1e-13 over 10⁵ rows, at every oracle row (every 331st, so
    // every position between re-anchorings): ω relative to |ω|; the attitude as the angle between the rotations,
    // absolute. The precession angle is φ ≈ 600 rad at t = 100 s, whose binary64 rounding alone would be
    // ε·φ = 1.3e-13 rad; its secular part is formed and reduced modulo 4π in double-double (TorqueFreeBody::attitude),
    // so no allowance for it. The direct evaluation is held to the same bound.
    let oracle = oracle();
    assert_eq!((oracle.len(), oracle.last().unwrap().k), (304, 100_000));
    let exact = body([1.0, 2.0, 3.0], [0.3, 0.0, 2.0], UnitQuaternion::identity());
    let direct_q = oracle.iter().fold(0.0f64, |worst, o| {
        worst.max(angle(&exact.attitude(o.k as f64 * 1e-3), &o.q_b))
    });
    assert!(
        direct_q <= 1e-13,
        "direct evaluation: attitude error {direct_q:e} rad"
    );
    for frame in ["body", "space"] {
        let overrides = Overrides {
            form: Some(Named::parse(frame).unwrap()),
            ..Overrides::default()
        };
        let scene = scene_from(&benchmark_text(100.0, 1e-3), &overrides);
        let mut at = oracle.iter().peekable();
        let (mut k, mut err_omega, mut err_q) = (0usize, 0.0f64, 0.0f64);
        simulate::run(&scene, |s: &Sample| {
            if let Some(o) = at.next_if(|o| o.k == k) {
                err_omega = err_omega.max((*s.omega_b - o.omega_b).norm() / o.omega_b.norm());
                err_q = err_q.max(angle(&s.q, &o.q_b));
            }
            k += 1;
            Ok::<(), Infallible>(())
        })
        .unwrap();
        assert_eq!((k, at.next().map(|o| o.k)), (100_001, None));
        println!(
            "{frame} form, 1e5 rows: largest error against mpmath: ω {err_omega:.2e}, attitude {err_q:.2e} rad \
             (the direct evaluation's: {direct_q:.2e} rad)"
        );
        assert!(err_omega <= 1e-13, "{frame}: ω error {err_omega:e}");
        assert!(err_q <= 1e-13, "{frame}: attitude error {err_q:e} rad");
    }
}

/// The largest differences between the equal grid, re-anchored every `anchor_rows` rows, and the direct evaluation
/// over `rows` rows of step `every`, as (rows so far, ω relative, attitude rad) at each of `checkpoints` and at the
/// end. No allowance for the rounding of the growing angles: both evaluations form τ = λt + τ₀, its reduction by 2K
/// and the precession angle's secular part in double-double (until issue 26's last step the comparison subtracted
/// 4ε·τ from ω's difference and 2ε·φ(t) from the attitude's, which grow with t).
fn against_direct(
    body: &TorqueFreeBody,
    every: f64,
    rows: usize,
    anchor_rows: u64,
    checkpoints: &[usize],
) -> Vec<(usize, f64, f64)> {
    let grid = body.equal_grid(every).with_anchor_rows(anchor_rows);
    let (mut err_omega, mut err_q) = (0.0f64, 0.0f64);
    let mut out = Vec::new();
    for (k, (t, omega_p, q)) in grid.take(rows + 1).enumerate() {
        let (omega_ref, q_ref) = (body.omega_p(t), body.attitude(t));
        err_omega = err_omega.max((omega_p - omega_ref).norm() / omega_ref.norm());
        err_q = err_q.max(angle(&q, &q_ref));
        if checkpoints.contains(&k) || k == rows {
            out.push((k, err_omega, err_q));
        }
    }
    out
}

fn body(moments: [f64; 3], omega: [f64; 3], q0: UnitQuaternion<f64>) -> TorqueFreeBody {
    TorqueFreeBody::new(Vector3::from(moments), Vector3::from(omega), q0).unwrap()
}

#[test]
fn roundoff_growth_without_reanchoring_sets_the_anchor_interval() {
    // The measurement behind ANCHOR_ROWS (docs/book/src/explanation/performance.md): the benchmark body on the grid of the oracle
    // (every = 1e-3 s, h = λ·every ≈ 0.004) and on the benchmark grid (every = 0.01 s, h ≈ 0.04), never re-anchored,
    // against the direct evaluation: the error grows with the number of rows; re-anchored every ANCHOR_ROWS rows it
    // stays at the level of the first ANCHOR_ROWS rows.
    let b = body([1.0, 2.0, 3.0], [0.3, 0.0, 2.0], UnitQuaternion::identity());
    let checkpoints = [10, 100, 256, 1000, 10_000];
    for every in [1e-3, 1e-2] {
        let free = against_direct(&b, every, 100_000, u64::MAX, &checkpoints);
        for (rows, e_w, e_q) in &free {
            println!(
                "every = {every}: after {rows:6} rows without re-anchoring: ω {e_w:.2e}, attitude {e_q:.2e} rad"
            );
        }
        let anchored = against_direct(&b, every, 100_000, ANCHOR_ROWS, &[]);
        let (_, e_w, e_q) = anchored[0];
        println!(
            "every = {every}: re-anchored every {ANCHOR_ROWS} rows, 1e5 rows: ω {e_w:.2e}, attitude {e_q:.2e} rad"
        );
        assert!(
            e_w <= 1e-13 && e_q <= 1e-13,
            "every {every}: {e_w:e}, {e_q:e}"
        );
        // Without re-anchoring the error after 1e5 rows exceeds that after 1e3 (it accumulates).
        let (e_1e3, e_1e5) = (free[3].1.max(free[3].2), free[5].1.max(free[5].2));
        assert!(
            e_1e5 > e_1e3,
            "every {every}: no growth ({e_1e3:e} → {e_1e5:e})"
        );
    }
}

/// A case of `equal_grid_matches_the_direct_evaluation_for_every_kind_of_motion`: name, moments, ω(0), every, rows,
/// tolerance.
type Case = (&'static str, [f64; 3], [f64; 3], f64, usize, f64);

#[test]
fn equal_grid_matches_the_direct_evaluation_for_every_kind_of_motion() {
    // Each case: moments, ω(0), grid step, rows. The direct evaluation (Jacobi's functions by Landen's transformation,
    // Π by Carlson's R_J) is independent of the addition theorems; criterion 1e-13 (ω relative, attitude rad), with no
    // allowance for the rounding of the angles any more (see against_direct) — next to the separatrix too, where it
    // was 1e-12 while τ = λt + τ₀ was rounded in binary64 (sn, cn, dn are ill-conditioned in τ there: a 1e-16 error
    // of τ moves cn by ~1e-14; τ and its reduction are now double-double in both evaluations). 1e-12 for the thin
    // rod (ν = −n ≈ 1e4): the second argument of the arctangent in J's addition theorem, 1 + ν(sn²(u+h) − sn u sn h
    // cn(u+h) dn(u+h)), is formed from terms of size ν that can cancel to O(1), so a row's increment of φ rounds at
    // ~ε·ν (measured: 2e-13 after a single row from a re-anchoring, 3e-13 over the run).
    let q0 = UnitQuaternion::from_euler_angles(0.3, -1.1, 2.0);
    let cases: [Case; 9] = [
        (
            "benchmark, coarse grid",
            [1.0, 2.0, 3.0],
            [0.3, 0.0, 2.0],
            0.5,
            4000,
            1e-13,
        ),
        (
            "steps of several periods",
            [1.0, 2.0, 3.0],
            [0.3, 0.0, 2.0],
            7.3,
            1000,
            1e-13,
        ),
        (
            "about the smallest axis",
            [1.0, 2.0, 3.0],
            [3.0, 0.4, 0.2],
            0.01,
            5000,
            1e-13,
        ),
        (
            "user axes unsorted",
            [3.0, 1.0, 2.5],
            [0.2, 1.5, -0.7],
            0.02,
            5000,
            1e-13,
        ),
        (
            "symmetric (m = 0)",
            [2.0, 2.0, 3.0],
            [0.5, -0.2, 1.0],
            0.05,
            3000,
            1e-13,
        ),
        (
            "prolate, nearly symmetric",
            [1.0, 3.0, 3.0000001],
            [2.0, 0.1, 0.3],
            0.01,
            5000,
            1e-13,
        ),
        (
            "large ν (thin rod)",
            [0.01, 1.0, 1.01],
            [0.1, 0.5, 3.0],
            0.002,
            5000,
            1e-12,
        ),
        (
            "near the separatrix",
            [1.0, 2.0, 3.0],
            [0.001, 2.0, 0.001],
            0.05,
            5000,
            1e-13,
        ),
        (
            "separatrix (direct rows)",
            [1.0, 2.0, 3.0],
            [3.0, 0.5, 1.732_050_807_568_877_2],
            0.05,
            300,
            1e-13,
        ),
    ];
    for (name, moments, omega, every, rows, tol) in cases {
        let b = body(moments, omega, q0);
        let [(_, e_w, e_q)] = against_direct(&b, every, rows, ANCHOR_ROWS, &[])[..] else {
            unreachable!()
        };
        println!(
            "{name}: m = {:?}, walk {}: ω {e_w:.2e}, attitude {e_q:.2e}",
            b.elliptic_parameter(),
            b.equal_grid(every).is_walk()
        );
        assert!(
            e_w <= tol && e_q <= tol,
            "{name}: ω {e_w:e}, attitude {e_q:e}"
        );
    }
}

#[test]
fn the_walk_is_used_where_it_applies() {
    let q0 = UnitQuaternion::identity();
    assert!(
        body([1.0, 2.0, 3.0], [0.3, 0.0, 2.0], q0)
            .equal_grid(0.01)
            .is_walk()
    );
    // Stationary (a spin about a principal axis) and the separatrix (M² = 2E·I₂): evaluated directly.
    assert!(
        !body([1.0, 2.0, 3.0], [0.0, 0.0, 2.0], q0)
            .equal_grid(0.01)
            .is_walk()
    );
    assert!(
        !body([1.0, 2.0, 3.0], [3.0, 0.5, 1.732_050_807_568_877_2], q0)
            .equal_grid(0.01)
            .is_walk()
    );
}

#[test]
fn a_full_inertia_tensor_gets_the_rows_of_the_direct_evaluation() {
    // Principal axes off the body axes: the walk's rows, in body axes (EqualGrid::in_axes), against ExactFlow's
    // direct evaluation of the same rows (body form: ω_b, H_b from ω_p; space form: from the attitude and H_s).
    let text = "[body]\nmass = 2.0\ninertia = [[2.0, 0.1, 0.0], [0.1, 2.5, 0.2], [0.0, 0.2, 3.0]]\n\
        [initial]\nomega = [0.3, -0.5, 2.0]\nattitude = [0.9, 0.1, -0.3, 0.2]\n\
        [solver]\nmethod = \"exact\"\nt_end = 20.0\n[output]\nevery = 0.01\n";
    for frame in ["body", "space"] {
        let overrides = Overrides {
            form: Some(Named::parse(frame).unwrap()),
            ..Overrides::default()
        };
        let scene = scene_from(text, &overrides);
        let eulerdyn::scene::Motion::Free { omega0_b, body, .. } = &scene.motion else {
            panic!("a free body");
        };
        let flow = ExactFlow::new(body, omega0_b, &scene.attitude0).unwrap();
        let (mut rows, mut err_omega, mut err_h, mut err_q) = (0, 0.0f64, 0.0f64, 0.0f64);
        simulate::run(&scene, |s: &Sample| {
            let d = flow.sample(s.t, scene.solver.form);
            err_omega = err_omega.max((s.omega_b - d.omega_b).norm() / d.omega_b.norm());
            err_h = err_h.max((s.h_o_s - d.h_o_s).norm() / d.h_o_s.norm());
            err_q = err_q.max(angle(&s.q, &d.q));
            rows += 1;
            Ok::<(), Infallible>(())
        })
        .unwrap();
        println!(
            "{frame} form, {rows} rows: ω {err_omega:.2e}, H_s {err_h:.2e}, attitude {err_q:.2e} rad"
        );
        assert_eq!(rows, 2001);
        assert!(
            err_omega <= 1e-13 && err_h <= 1e-13 && err_q <= 1e-13,
            "{frame}"
        );
    }
}
