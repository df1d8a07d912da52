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

/// An upper bound of the precession angle φ(t) about H: |H|/I_min · t (its rate is at most that; L&L §37).
fn precession_bound(body: &TorqueFreeBody, t: f64) -> f64 {
    body.h_s().norm() / body.moments_p().min() * t
}

#[test]
fn equal_grid_matches_the_mpmath_oracle_over_1e5_rows() {
    // Criterion (issue 26): error against the oracle ≤ 1e-13 over 10⁵ rows, at every oracle row (every 331st, so
    // every position between re-anchorings): ω relative to |ω|; the attitude as the angle between the rotations,
    // beyond the rounding of the precession angle itself, ε·φ(t) (φ ≈ 600 rad at t = 100 s, where ε·φ = 1.3e-13
    // rad: no binary64 evaluation has the angle more accurately — the direct evaluation's error is printed beside).
    let oracle = oracle();
    assert_eq!((oracle.len(), oracle.last().unwrap().k), (304, 100_000));
    let exact = body([1.0, 2.0, 3.0], [0.3, 0.0, 2.0], UnitQuaternion::identity());
    let (direct_q, direct_excess) = oracle.iter().fold((0.0f64, 0.0f64), |(worst, excess), o| {
        let t = o.k as f64 * 1e-3;
        let e = angle(&exact.attitude(t), &o.q_b);
        let beyond = e - f64::EPSILON * precession_bound(&exact, t);
        (worst.max(e), excess.max(beyond))
    });
    for frame in ["body", "space"] {
        let overrides = Overrides {
            frame: Some(Named::parse(frame).unwrap()),
            ..Overrides::default()
        };
        let scene = scene_from(&benchmark_text(100.0, 1e-3), &overrides);
        let mut at = oracle.iter().peekable();
        let (mut k, mut err_omega, mut err_q, mut excess_q) = (0usize, 0.0f64, 0.0f64, 0.0f64);
        simulate::run(&scene, |s: &Sample| {
            if let Some(o) = at.next_if(|o| o.k == k) {
                err_omega = err_omega.max((s.omega_b - o.omega_b).norm() / o.omega_b.norm());
                let e = angle(&s.q, &o.q_b);
                err_q = err_q.max(e);
                excess_q = excess_q.max(e - f64::EPSILON * precession_bound(&exact, s.t));
            }
            k += 1;
            Ok::<(), Infallible>(())
        })
        .unwrap();
        assert_eq!((k, at.next().map(|o| o.k)), (100_001, None));
        println!(
            "{frame} form, 1e5 rows: largest error against mpmath: ω {err_omega:.2e}, attitude {err_q:.2e} rad \
             ({excess_q:.2e} beyond ε·φ; the direct evaluation's: {direct_q:.2e} rad, {direct_excess:.2e} beyond)"
        );
        assert!(err_omega <= 1e-13, "{frame}: ω error {err_omega:e}");
        assert!(excess_q <= 1e-13, "{frame}: attitude error {err_q:e} rad");
    }
}

/// The largest differences between the equal grid, re-anchored every `anchor_rows` rows, and the direct evaluation
/// over `rows` rows of step `every`, as (rows so far, ω relative, attitude rad) at each of `checkpoints` and at the
/// end: raw, and beyond what the two evaluations' rounding of their angles explains (`beyond`: 4ε·τ for ω, 2ε·φ(t)
/// for the attitude).
fn against_direct(
    body: &TorqueFreeBody,
    every: f64,
    rows: usize,
    anchor_rows: u64,
    checkpoints: &[usize],
    beyond: bool,
) -> Vec<(usize, f64, f64)> {
    let grid = body.equal_grid(every).with_anchor_rows(anchor_rows);
    let (mut err_omega, mut err_q) = (0.0f64, 0.0f64);
    let mut out = Vec::new();
    for (k, (t, omega_p, q)) in grid.take(rows + 1).enumerate() {
        let (omega_ref, q_ref) = (body.omega_p(t), body.attitude(t));
        // Both have the precession angle to its rounding, ε·φ each, and τ = λt + τ₀ to a few ε·τ (the direct
        // evaluation reduces τ by a rounded 2K; the walk adds the rounded step): λ ≤ |H|/I_min bounds τ − τ₀ too.
        let rounding = if beyond {
            2.0 * f64::EPSILON * precession_bound(body, t)
        } else {
            0.0
        };
        err_omega = err_omega.max((omega_p - omega_ref).norm() / omega_ref.norm() - 2.0 * rounding);
        err_q = err_q.max(angle(&q, &q_ref) - rounding);
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
    // The measurement behind ANCHOR_ROWS (docs/performance.md): the benchmark body on the grid of the oracle
    // (every = 1e-3 s, h = λ·every ≈ 0.004) and on the benchmark grid (every = 0.01 s, h ≈ 0.04), never re-anchored,
    // against the direct evaluation: the error grows with the number of rows; re-anchored every ANCHOR_ROWS rows it
    // stays at the level of the first ANCHOR_ROWS rows.
    let b = body([1.0, 2.0, 3.0], [0.3, 0.0, 2.0], UnitQuaternion::identity());
    let checkpoints = [10, 100, 256, 1000, 10_000];
    for every in [1e-3, 1e-2] {
        let free = against_direct(&b, every, 100_000, u64::MAX, &checkpoints, false);
        for (rows, e_w, e_q) in &free {
            println!(
                "every = {every}: after {rows:6} rows without re-anchoring: ω {e_w:.2e}, attitude {e_q:.2e} rad"
            );
        }
        let anchored = against_direct(&b, every, 100_000, ANCHOR_ROWS, &[], true);
        let (_, e_w, e_q) = anchored[0];
        println!(
            "every = {every}: re-anchored every {ANCHOR_ROWS} rows, 1e5 rows: ω {e_w:.2e}, attitude {e_q:.2e} rad \
             beyond the rounding of the angles"
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
    // Π by Carlson's R_J) is independent of the addition theorems; criterion 1e-13 (ω relative, attitude rad) beyond
    // the rounding of the angles (see against_direct); 1e-12 next to the separatrix, where sn, cn, dn are
    // ill-conditioned in τ (a 1e-16 error of τ moves cn by ~1e-14), and for the thin rod, whose precession rate
    // |H|/I₁ ≈ 300 rad/s turns it by ~150 rad between re-anchorings, carried by the step's constant J(h) to a few ε.
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
            1e-12,
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
        let [(_, e_w, e_q)] = against_direct(&b, every, rows, ANCHOR_ROWS, &[], true)[..] else {
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
            frame: Some(Named::parse(frame).unwrap()),
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
            err_h = err_h.max((s.h_s - d.h_s).norm() / d.h_s.norm());
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
