//! What each method costs on the benchmark body (I = (1, 2, 3) kg·m², ω0 = (0.3, 0, 2) rad/s, torque-free), in
//! both forms of Euler's equation, against hand-written loops measured in the same process; then the fastest
//! method reaching a largest ω error ≤ 1e-10 rad/s on the benchmark scene (t_end = 100 s, rows every 0.5 s) and on
//! the same body under a sine torque (no closed form).
//!
//! The floors (hand-written loops, plain arrays, everything inlined, written for this one body):
//!
//! * the RK4 floor: classical RK4 with the right-hand side of each form inlined, the quaternion renormalised after
//!   every step (as every method of the project does). Its ns/step is the floor of the fixed-step methods, its
//!   ns/step / 4 (per right-hand-side evaluation) that of the adaptive ones; also timed with the sine torque.
//! * the DOPRI5 step: an accepted DOPRI5 step at a fixed step size (7 stages with FSAL, error norm, controller
//!   power, renormalisation, f at the renormalised state), per evaluation: what the adaptive methods' own work
//!   costs without step-size bookkeeping.
//! * the splitting floors: split2 and split4 themselves (the Casimir splitting C T_a T_c T_a, Suzuki's weights for
//!   split4, exact rotations, the same fusions of sub-flows and the same sin/cos series as the project's), in both
//!   forms. A split4 step is five Strang steps, so it cannot come near an RK4 step; its own loop is its floor. The
//!   bench checks that each reaches the project's state after 1e5 steps (ω and attitude to 1e-12) — the same work.
//!
//! Targets (issue 5): fixed-step methods ≤ 1.3 × the RK4 floor per step, and split2/split4 ≤ 1.3 × their own loop
//! per step; adaptive methods ≤ 1.5 × the floor per right-hand-side evaluation (the RK4 floor's ns/step / 4); the
//! fastest method to ω error ≤ 1e-10 in ≤ 0.25 ms.
//!
//! Per-step costs run `simulate::run` with rows only at 0 and t_end (so rows cost nothing); `exact` takes no
//! steps and is timed per row instead (a row every 1 ms). Each figure is the median (and the minimum) of 21
//! samples of at least ~3 ms each, the cases interleaved so that a slow spell of the machine hits all alike.
//!
//! Run: `cargo bench --bench methods`. `EULERDYN_BENCH_QUICK=1` skips the work-precision part.

use std::convert::Infallible;
use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

use eulerdyn::analysis::study::{self, StudyOptions, format_seconds};
use eulerdyn::exact::TorqueFreeBody;
use eulerdyn::frames::Form;
use eulerdyn::method::{Backend, Method};
use eulerdyn::scene::{self, Overrides};
use eulerdyn::simulate;
use eulerdyn::trig::{self, small_sin_cos};
use nalgebra::{UnitQuaternion, Vector3};

/// The benchmark body, torque-free, rows only at 0 and t_end.
const SPARSE_SCENE: &str = "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 0.0, 2.0]\n[solver]\nrtol = 1e-10\natol = 1e-12\ndt = 1e-3\nt_end = 100.0\n[output]\nevery = 100.0\n";

/// Principal moments and initial state of the benchmark body.
const MOMENTS: [f64; 3] = [1.0, 2.0, 3.0];
const OMEGA0: [f64; 3] = [0.3, 0.0, 2.0];

thread_local! {
    /// ns per right-hand-side evaluation of the hand-written RK4 loop with the sine torque.
    static SINE_FLOOR_NS_PER_EVAL: std::cell::Cell<f64> = const { std::cell::Cell::new(f64::NAN) };
    /// ns per evaluation of the hand-written DOPRI5 step on the body form plus the sine's cost.
    static SINE_DOPRI5_NS_PER_EVAL: std::cell::Cell<f64> = const { std::cell::Cell::new(f64::NAN) };
}

/// Samples per case and the least time of one sample.
const SAMPLES: usize = 21;
const SAMPLE_SECONDS: f64 = 3e-3;

// ---------------------------------------------------------------------------------------------------------------
// The floor: a hand-written RK4 loop on plain arrays, the right-hand side inlined, the quaternion renormalised
// after every step (as every method of the project does).

type Y = [f64; 7];

/// Body form: ω̇ = ((I2 − I3)/I1 ω2ω3, …), q̇ = ½ q ⊗ (0, ω).
#[inline(always)]
fn rhs_body(c: &[f64; 3], y: &Y) -> Y {
    let (w1, w2, w3) = (y[0], y[1], y[2]);
    let (qw, qx, qy, qz) = (y[3], y[4], y[5], y[6]);
    [
        c[0] * w2 * w3,
        c[1] * w3 * w1,
        c[2] * w1 * w2,
        -0.5 * (qx * w1 + qy * w2 + qz * w3),
        0.5 * (qw * w1 + qy * w3 - qz * w2),
        0.5 * (qw * w2 + qz * w1 - qx * w3),
        0.5 * (qw * w3 + qx * w2 - qy * w1),
    ]
}

/// Space form: Ḣ_s = 0, ω_b = I⁻¹ R(q)ᵀ H_s with q normalised, q̇ = ½ q ⊗ (0, ω_b).
#[inline(always)]
fn rhs_space(inv: &[f64; 3], y: &Y) -> Y {
    let n = (y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6]).sqrt();
    let (qw, qx, qy, qz) = (y[3] / n, y[4] / n, y[5] / n, y[6] / n);
    let (h1, h2, h3) = (y[0], y[1], y[2]);
    // v_b = Rᵀ h: rotate by the conjugate quaternion, v + 2 w (v×u) + 2 u×(u×v)... written as the matrix Rᵀ.
    let hb1 = (1.0 - 2.0 * (qy * qy + qz * qz)) * h1
        + 2.0 * (qx * qy + qw * qz) * h2
        + 2.0 * (qx * qz - qw * qy) * h3;
    let hb2 = 2.0 * (qx * qy - qw * qz) * h1
        + (1.0 - 2.0 * (qx * qx + qz * qz)) * h2
        + 2.0 * (qy * qz + qw * qx) * h3;
    let hb3 = 2.0 * (qx * qz + qw * qy) * h1
        + 2.0 * (qy * qz - qw * qx) * h2
        + (1.0 - 2.0 * (qx * qx + qy * qy)) * h3;
    let (w1, w2, w3) = (inv[0] * hb1, inv[1] * hb2, inv[2] * hb3);
    let (qw, qx, qy, qz) = (y[3], y[4], y[5], y[6]);
    [
        0.0,
        0.0,
        0.0,
        -0.5 * (qx * w1 + qy * w2 + qz * w3),
        0.5 * (qw * w1 + qy * w3 - qz * w2),
        0.5 * (qw * w2 + qz * w1 - qx * w3),
        0.5 * (qw * w3 + qx * w2 - qy * w1),
    ]
}

#[inline(always)]
fn axpy(y: &Y, h: f64, k: &Y) -> Y {
    std::array::from_fn(|i| y[i] + h * k[i])
}

/// `steps` classical RK4 steps of size h from y, renormalising the quaternion after each.
#[inline(always)]
fn hand_rk4(f: impl Fn(&Y) -> Y, mut y: Y, h: f64, steps: u64) -> Y {
    for _ in 0..steps {
        let k1 = f(&y);
        let k2 = f(&axpy(&y, 0.5 * h, &k1));
        let k3 = f(&axpy(&y, 0.5 * h, &k2));
        let k4 = f(&axpy(&y, h, &k3));
        for i in 0..7 {
            y[i] += h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
        }
        let n = (y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6]).sqrt();
        for v in &mut y[3..7] {
            *v /= n;
        }
    }
    y
}

/// Body form under the benchmark's sine torque M_x = 0.5·sin(2π·0.5·t) N·m (scenarios/benchmark_sine.toml), the sine
/// inline (`eulerdyn::trig::sin`, as the project's torques).
#[inline(always)]
fn rhs_body_sine(c: &[f64; 3], inv1: f64, t: f64, y: &Y) -> Y {
    let mut f = rhs_body(c, y);
    f[0] += inv1 * 0.5 * trig::sin(std::f64::consts::PI * t);
    f
}

/// ns per step of the hand-written RK4 loop on the body form with the sine torque (1e5 steps of 1e-3 s).
fn floor_sine_sample() -> f64 {
    let steps = 100_000u64;
    let h = black_box(1e-3);
    let [i1, i2, i3] = black_box(MOMENTS);
    let c = [(i2 - i3) / i1, (i3 - i1) / i2, (i1 - i2) / i3];
    let inv1 = 1.0 / i1;
    let mut y = black_box([OMEGA0[0], OMEGA0[1], OMEGA0[2], 1.0, 0.0, 0.0, 0.0]);
    let start = Instant::now();
    for i in 0..steps {
        let t = i as f64 * h;
        let k1 = rhs_body_sine(&c, inv1, t, &y);
        let k2 = rhs_body_sine(&c, inv1, t + 0.5 * h, &axpy(&y, 0.5 * h, &k1));
        let k3 = rhs_body_sine(&c, inv1, t + 0.5 * h, &axpy(&y, 0.5 * h, &k2));
        let k4 = rhs_body_sine(&c, inv1, t + h, &axpy(&y, h, &k3));
        for j in 0..7 {
            y[j] += h / 6.0 * (k1[j] + 2.0 * (k2[j] + k3[j]) + k4[j]);
        }
        let n = (y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6]).sqrt();
        for v in &mut y[3..7] {
            *v /= n;
        }
    }
    black_box(y);
    start.elapsed().as_secs_f64() * 1e9 / steps as f64
}

/// A hand-written DOPRI5 loop (Dormand & Prince 1980, HNW I Table 5.2): every step computes the 7 stages (FSAL),
/// the error norm of HNW I eq. (4.11) and the controller's power err^(0.2 − 0.75·0.04), renormalises the
/// quaternion and re-evaluates f at the renormalised state (as the project's dopri5 does: 7 evaluations per
/// step). The step is fixed (h = 0.05 s, no rejection), so this is the work of an accepted adaptive step without
/// the bookkeeping of step-size selection. Returns ns per right-hand-side evaluation.
fn dopri5_floor_sample(frame: Form) -> f64 {
    const A: [[f64; 6]; 6] = [
        [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
        [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
        [
            19372.0 / 6561.0,
            -25360.0 / 2187.0,
            64448.0 / 6561.0,
            -212.0 / 729.0,
            0.0,
            0.0,
        ],
        [
            9017.0 / 3168.0,
            -355.0 / 33.0,
            46732.0 / 5247.0,
            49.0 / 176.0,
            -5103.0 / 18656.0,
            0.0,
        ],
        [
            35.0 / 384.0,
            0.0,
            500.0 / 1113.0,
            125.0 / 192.0,
            -2187.0 / 6784.0,
            11.0 / 84.0,
        ],
    ];
    const E: [f64; 7] = [
        71.0 / 57600.0,
        0.0,
        -71.0 / 16695.0,
        71.0 / 1920.0,
        -17253.0 / 339200.0,
        22.0 / 525.0,
        -1.0 / 40.0,
    ];
    let steps = 20_000u64;
    let h = black_box(0.005);
    let (rtol, atol) = black_box((1e-10, 1e-12));
    let [i1, i2, i3] = black_box(MOMENTS);
    let c = [(i2 - i3) / i1, (i3 - i1) / i2, (i1 - i2) / i3];
    let inv = [1.0 / i1, 1.0 / i2, 1.0 / i3];
    let f = |y: &Y| match frame {
        Form::Body => rhs_body(&c, y),
        Form::Space => rhs_space(&inv, y),
    };
    let mut y: Y = match frame {
        Form::Body => [OMEGA0[0], OMEGA0[1], OMEGA0[2], 1.0, 0.0, 0.0, 0.0],
        Form::Space => [
            i1 * OMEGA0[0],
            i2 * OMEGA0[1],
            i3 * OMEGA0[2],
            1.0,
            0.0,
            0.0,
            0.0,
        ],
    };
    y = black_box(y);
    let start = Instant::now();
    let mut k1 = f(&y);
    let mut facs = 0.0;
    for _ in 0..steps {
        let mut k: [Y; 7] = [k1; 7];
        for s in 1..6 {
            let arg: Y = std::array::from_fn(|i| {
                let mut sum = 0.0;
                for (j, a) in A[s - 1].iter().enumerate().take(s) {
                    sum += a * k[j][i];
                }
                y[i] + h * sum
            });
            k[s] = f(&arg);
        }
        let y_new: Y = std::array::from_fn(|i| {
            let mut sum = 0.0;
            for (j, a) in A[5].iter().enumerate() {
                sum += a * k[j][i];
            }
            y[i] + h * sum
        });
        k[6] = f(&y_new);
        let mut err = 0.0;
        for i in 0..7 {
            let mut e = 0.0;
            for (j, ej) in E.iter().enumerate() {
                e += ej * k[j][i];
            }
            let sk = atol + rtol * y[i].abs().max(y_new[i].abs());
            err += (h * e / sk).powi(2);
        }
        facs += (err / 7.0).sqrt().powf(0.2 - 0.75 * 0.04);
        y = y_new;
        let n = (y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6]).sqrt();
        for v in &mut y[3..7] {
            *v /= n;
        }
        k1 = f(&y);
    }
    black_box((y, facs));
    start.elapsed().as_secs_f64() * 1e9 / (steps * 7) as f64
}

/// ns per step of the hand-written loop in `frame` (1e5 steps of 1e-3 s, as the rk4 case).
fn floor_sample(frame: Form) -> f64 {
    let steps = 100_000u64;
    let h = black_box(1e-3);
    let [i1, i2, i3] = black_box(MOMENTS);
    let start = Instant::now();
    let y = match frame {
        Form::Body => {
            let c = [(i2 - i3) / i1, (i3 - i1) / i2, (i1 - i2) / i3];
            let y0 = [OMEGA0[0], OMEGA0[1], OMEGA0[2], 1.0, 0.0, 0.0, 0.0];
            hand_rk4(|y| rhs_body(&c, y), black_box(y0), h, steps)
        }
        Form::Space => {
            let inv = [1.0 / i1, 1.0 / i2, 1.0 / i3];
            let y0 = [
                i1 * OMEGA0[0],
                i2 * OMEGA0[1],
                i3 * OMEGA0[2],
                1.0,
                0.0,
                0.0,
                0.0,
            ];
            hand_rk4(|y| rhs_space(&inv, y), black_box(y0), h, steps)
        }
    };
    black_box(y);
    start.elapsed().as_secs_f64() * 1e9 / steps as f64
}

// ---------------------------------------------------------------------------------------------------------------
// The splitting methods' own floors: split2/split4 written by hand for this one body, torque-free, on plain arrays,
// everything inlined. The same method as the project's: the Casimir splitting (I_r = I₂; T_a about axis 1 with
// rate 1/I₁ − 1/I₂, T_c about axis 3 with rate 1/I₃ − 1/I₂, C about H with rate 1/I₂), Strang's drift
// C(τ) T_a(τ/2) T_c(τ) T_a(τ/2) composed with the same weights (split4: Suzuki's five stages), each sub-flow the
// exact rotation, q renormalised and, in the body form, H rescaled to |H(0)| after every step. Written the way one
// writes a Strang splitting for speed, with the same fusions as the project: the Casimir rotations of a step as
// one C(h), the two T_a(wh/2) between stages as one, the last T_a of a step with the first of the next (closed at
// the end). sin/cos by the project's series for |x| ≤ 1/16 (`eulerdyn::trig::small_sin_cos`), so that the two
// do the same arithmetic; `split_floor_sample` checks that they reach the same state.

/// The state of the hand-written splitting: H (principal = body axes in the body form, space axes in the space
/// form) and q (principal → space, (w, x, y, z)).
#[derive(Clone, Copy)]
struct SplitY {
    h: [f64; 3],
    q: [f64; 4],
}

/// The rates of the benchmark body's Casimir splitting: k_a, k_c, 1/I_r; and in the space form nothing else.
struct Rates {
    k_a: f64,
    k_c: f64,
    casimir: f64,
}

/// a ⊗ b.
#[inline(always)]
fn quat_mul(a: &[f64; 4], b: &[f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// T_a(τ) about axis 1: angle k_a·H₁·τ, H₁ = H_p,1 (body form) or (R(q) e₁)·H_s (space form); q ← q ⊗ (cos,
/// sin·e₁) of the half angle; body form: (H₂, H₃) turned by the full angle.
#[inline(always)]
fn turn_a<const BODY: bool>(k: f64, tau: f64, y: &mut SplitY) {
    let [w, x, yy, z] = y.q;
    let h1 = if BODY {
        y.h[0]
    } else {
        (1.0 - 2.0 * (yy * yy + z * z)) * y.h[0]
            + 2.0 * (yy * x + w * z) * y.h[1]
            + 2.0 * (z * x - w * yy) * y.h[2]
    };
    let (s2, c2) = small_sin_cos((0.5 * k * tau) * h1);
    y.q = [
        c2 * w - s2 * x,
        c2 * x + s2 * w,
        c2 * yy + s2 * z,
        c2 * z - s2 * yy,
    ];
    if BODY {
        let (s, c) = (2.0 * s2 * c2, (c2 - s2) * (c2 + s2));
        let (h2, h3) = (y.h[1], y.h[2]);
        y.h[1] = c * h2 + s * h3;
        y.h[2] = c * h3 - s * h2;
    }
}

/// T_c(τ) about axis 3, as [`turn_a`]: angle k_c·H₃·τ; body form: (H₁, H₂) turned by the full angle.
#[inline(always)]
fn turn_c<const BODY: bool>(k: f64, tau: f64, y: &mut SplitY) {
    let [w, x, yy, z] = y.q;
    let h3 = if BODY {
        y.h[2]
    } else {
        2.0 * (x * z + w * yy) * y.h[0]
            + 2.0 * (yy * z - w * x) * y.h[1]
            + (1.0 - 2.0 * (x * x + yy * yy)) * y.h[2]
    };
    let (s2, c2) = small_sin_cos((0.5 * k * tau) * h3);
    y.q = [
        c2 * w - s2 * z,
        c2 * x + s2 * yy,
        c2 * yy - s2 * x,
        c2 * z + s2 * w,
    ];
    if BODY {
        let (s, c) = (2.0 * s2 * c2, (c2 - s2) * (c2 + s2));
        let (h1, h2) = (y.h[0], y.h[1]);
        y.h[0] = c * h1 + s * h2;
        y.h[1] = c * h2 - s * h1;
    }
}

/// `steps` torque-free steps of size h of the Casimir splitting composed with the N stage `weights` (split2: [1];
/// split4: Suzuki's), in the body form (`BODY`) or the space form, fused (see above), closed at the end.
#[inline(always)]
fn hand_split<const BODY: bool, const N: usize>(
    r: &Rates,
    weights: [f64; N],
    mut y: SplitY,
    h: f64,
    steps: u64,
) -> SplitY {
    let n0 = (y.h[0] * y.h[0] + y.h[1] * y.h[1] + y.h[2] * y.h[2]).sqrt();
    let inv_n0_sq = 1.0 / (n0 * n0);
    // The durations of the fused rotations, once: C(h Σw); before stage s the T_a (half of stage 0, closing the
    // open one; halves of stages s − 1 and s); T_c of stage s; the open T_a (half of the last stage).
    let tau_casimir = weights.iter().sum::<f64>() * h;
    let tau_a: [f64; N] = std::array::from_fn(|s| {
        if s == 0 {
            0.5 * weights[0] * h
        } else {
            (0.5 * weights[s - 1] + 0.5 * weights[s]) * h
        }
    });
    let tau_c = weights.map(|w| w * h);
    let tau_open = 0.5 * weights[N - 1] * h;
    let mut open = 0.0;
    for _ in 0..steps {
        // C(h): q ← q ⊗ r (body form) or r ⊗ q (space form), r = (cos, sin·H/|H|) of |H|h/(2I_r).
        let norm = (y.h[0] * y.h[0] + y.h[1] * y.h[1] + y.h[2] * y.h[2]).sqrt();
        let (s2, c2) = small_sin_cos(0.5 * norm * tau_casimir * r.casimir);
        let v = s2 / norm;
        let rot = [c2, v * y.h[0], v * y.h[1], v * y.h[2]];
        y.q = if BODY {
            quat_mul(&y.q, &rot)
        } else {
            quat_mul(&rot, &y.q)
        };
        turn_a::<BODY>(r.k_a, tau_a[0] + open, &mut y);
        turn_c::<BODY>(r.k_c, tau_c[0], &mut y);
        for s in 1..N {
            turn_a::<BODY>(r.k_a, tau_a[s], &mut y);
            turn_c::<BODY>(r.k_c, tau_c[s], &mut y);
        }
        open = tau_open;
        let f = 1.5 - 0.5 * (y.q[0] * y.q[0] + y.q[1] * y.q[1] + y.q[2] * y.q[2] + y.q[3] * y.q[3]);
        for v in &mut y.q {
            *v *= f;
        }
        if BODY {
            let f = 1.5 - 0.5 * ((y.h[0] * y.h[0] + y.h[1] * y.h[1] + y.h[2] * y.h[2]) * inv_n0_sq);
            for v in &mut y.h {
                *v *= f;
            }
        }
    }
    turn_a::<BODY>(r.k_a, open, &mut y);
    y
}

/// Suzuki's fractal weights of split4: p, p, 1 − 4p, p, p with p = 1/(4 − 4^{1/3}).
fn suzuki_weights() -> [f64; 5] {
    let p = 1.0 / (4.0 - 4f64.cbrt());
    [p, p, 1.0 - 4.0 * p, p, p]
}

/// ns per step of the hand-written split2 (`fourth` false) or split4 in `frame` (1e5 steps of 1e-3 s, as the
/// project's case), and the final state as (ω_b, q_b).
fn split_floor_sample(frame: Form, fourth: bool) -> (f64, [f64; 3], [f64; 4]) {
    let steps = 100_000u64;
    let h = black_box(1e-3);
    let [i1, i2, i3] = black_box(MOMENTS);
    let r = Rates {
        k_a: 1.0 / i1 - 1.0 / i2,
        k_c: 1.0 / i3 - 1.0 / i2,
        casimir: 1.0 / i2,
    };
    // T_a is about axis 1 (the smallest moment), T_c about axis 3 (the largest), I_r = I₂.
    assert!(i1 < i2 && i2 < i3);
    let y0 = SplitY {
        h: [i1 * OMEGA0[0], i2 * OMEGA0[1], i3 * OMEGA0[2]],
        q: [1.0, 0.0, 0.0, 0.0],
    };
    let (strang, suzuki) = (black_box([1.0]), black_box(suzuki_weights()));
    let start = Instant::now();
    let y = match (frame, fourth) {
        (Form::Body, false) => hand_split::<true, 1>(&r, strang, black_box(y0), h, steps),
        (Form::Space, false) => hand_split::<false, 1>(&r, strang, black_box(y0), h, steps),
        (Form::Body, true) => hand_split::<true, 5>(&r, suzuki, black_box(y0), h, steps),
        (Form::Space, true) => hand_split::<false, 5>(&r, suzuki, black_box(y0), h, steps),
    };
    let ns = start.elapsed().as_secs_f64() * 1e9 / steps as f64;
    let y = black_box(y);
    let h_p = if frame == Form::Body {
        y.h
    } else {
        // H_p = R(q)ᵀ H_s.
        let [w, x, yy, z] = y.q;
        let hs = y.h;
        [
            (1.0 - 2.0 * (yy * yy + z * z)) * hs[0]
                + 2.0 * (x * yy + w * z) * hs[1]
                + 2.0 * (x * z - w * yy) * hs[2],
            2.0 * (x * yy - w * z) * hs[0]
                + (1.0 - 2.0 * (x * x + z * z)) * hs[1]
                + 2.0 * (yy * z + w * x) * hs[2],
            2.0 * (x * z + w * yy) * hs[0]
                + 2.0 * (yy * z - w * x) * hs[1]
                + (1.0 - 2.0 * (x * x + yy * yy)) * hs[2],
        ]
    };
    (ns, [h_p[0] / i1, h_p[1] / i2, h_p[2] / i3], y.q)
}

/// The samples of one splitting floor and its final state.
struct SplitFloor {
    frame: Form,
    /// split4 (else split2).
    fourth: bool,
    /// ns per step of each sample.
    samples: Vec<f64>,
    /// ω_b and q_b after 1e5 steps.
    omega_b: [f64; 3],
    q: [f64; 4],
}

/// The largest difference between the hand-written splitting's final state and the project's run of the same
/// method and form (the SPARSE_SCENE, 100 s): (|Δω|/|ω|, attitude angle in rad).
fn split_floor_check(case: &Case, omega_b: [f64; 3], q: [f64; 4]) -> (f64, f64) {
    let mut last = None;
    simulate::run(&case.scene, |s| {
        last = Some(*s);
        Ok::<(), Infallible>(())
    })
    .expect("the benchmark scene runs");
    let s = last.expect("a row at t_end");
    let d_omega = (0..3)
        .map(|i| (s.omega_b[i] - omega_b[i]).powi(2))
        .sum::<f64>()
        .sqrt()
        / s.omega_b.norm();
    // The vector part of q_project⁻¹ ⊗ q_hand is sin(angle/2) times the axis.
    let conj = [s.q.w, -s.q.i, -s.q.j, -s.q.k];
    let d = quat_mul(&conj, &q);
    let angle = 2.0
        * (d[1] * d[1] + d[2] * d[2] + d[3] * d[3])
            .sqrt()
            .min(1.0)
            .asin();
    (d_omega, angle)
}

// ---------------------------------------------------------------------------------------------------------------

/// One measured case: a method in a form on a backend.
struct Case {
    method: Method,
    backend: Backend,
    frame: Form,
    scene: eulerdyn::scene::Scene,
    /// ns per step (per row for `exact`) of each sample.
    samples: Vec<f64>,
    steps: u64,
    evals: u64,
    rows: u64,
}

impl Case {
    /// Whether the method takes no steps (`exact`): it is timed per row.
    fn per_row(&self) -> bool {
        !self.method.is_fixed_step() && !self.method.is_adaptive()
    }

    /// Runs the scene until at least SAMPLE_SECONDS have passed; records ns per step (per row for `exact`).
    fn sample(&mut self) {
        let mut runs = 0u64;
        let start = Instant::now();
        loop {
            let report = simulate::run(&self.scene, |s| {
                black_box(s);
                Ok::<(), Infallible>(())
            })
            .expect("the benchmark scene runs");
            runs += 1;
            self.steps = report.stats.steps;
            self.evals = report.stats.evals;
            self.rows = report.rows;
            if start.elapsed().as_secs_f64() >= SAMPLE_SECONDS {
                break;
            }
        }
        let per = if self.per_row() {
            self.rows
        } else {
            self.steps
        };
        self.samples
            .push(start.elapsed().as_secs_f64() * 1e9 / (runs * per) as f64);
    }
}

fn median(v: &[f64]) -> f64 {
    let mut v = v.to_vec();
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn min(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::INFINITY, f64::min)
}

fn per_step_costs() {
    let path = Path::new("benchmark.toml");
    let mut cases = Vec::new();
    for backend in [Backend::Own, Backend::OdeSolvers] {
        for method in Method::ALL {
            if backend != Backend::Own && !method.is_runge_kutta() {
                continue;
            }
            for frame in [Form::Body, Form::Space] {
                let overrides = Overrides {
                    method: Some(method),
                    form: Some(frame),
                    backend: Some(backend),
                    // `exact` takes no steps: time it per row, a row every 1 ms.
                    every: (!method.is_fixed_step() && !method.is_adaptive()).then_some(1e-3),
                    ..Overrides::default()
                };
                match scene::parse(path, SPARSE_SCENE, &overrides) {
                    Ok(scene) => cases.push(Case {
                        method,
                        backend,
                        frame,
                        scene,
                        samples: Vec::new(),
                        steps: 0,
                        evals: 0,
                        rows: 0,
                    }),
                    Err(e) => println!("  (not measured: {} {}: {e})", method.name(), frame.name()),
                }
            }
        }
    }
    let mut floor_body = Vec::new();
    let mut floor_space = Vec::new();
    let mut floor_sine = Vec::new();
    let mut dopri5_body = Vec::new();
    let mut dopri5_space = Vec::new();
    let mut split_floors: Vec<SplitFloor> = [false, true]
        .into_iter()
        .flat_map(|fourth| {
            [Form::Body, Form::Space].map(|frame| SplitFloor {
                frame,
                fourth,
                samples: Vec::new(),
                omega_b: [0.0; 3],
                q: [0.0; 4],
            })
        })
        .collect();
    for _ in 0..SAMPLES {
        floor_body.push(floor_sample(Form::Body));
        floor_space.push(floor_sample(Form::Space));
        floor_sine.push(floor_sine_sample());
        dopri5_body.push(dopri5_floor_sample(Form::Body));
        dopri5_space.push(dopri5_floor_sample(Form::Space));
        for floor in &mut split_floors {
            let (ns, omega_b, q) = split_floor_sample(floor.frame, floor.fourth);
            floor.samples.push(ns);
            (floor.omega_b, floor.q) = (omega_b, q);
        }
        for case in &mut cases {
            case.sample();
        }
    }
    let floor = |frame: Form| match frame {
        Form::Body => (median(&floor_body), min(&floor_body)),
        Form::Space => (median(&floor_space), min(&floor_space)),
    };
    println!(
        "benchmark body, torque-free, t_end = 100 s, rows at 0 and 100 s only; fixed-step methods dt = 1e-3 s \
         (1e5 steps), adaptive rtol = 1e-10, atol = 1e-12; median (min) of {SAMPLES} samples"
    );
    println!(
        "  floor: hand-written RK4 loop, same right-hand side inlined, quaternion renormalised every step:"
    );
    for frame in [Form::Body, Form::Space] {
        let (m, lo) = floor(frame);
        println!(
            "    {:5} form  {m:7.1} ns/step ({lo:5.1})  = {:5.1} ns per right-hand-side evaluation",
            frame.name(),
            m / 4.0
        );
    }
    println!(
        "    body form with the sine torque  {:7.1} ns/step ({:5.1})  = {:5.1} ns per evaluation (the sine costs {:.1} ns)",
        median(&floor_sine),
        min(&floor_sine),
        median(&floor_sine) / 4.0,
        (median(&floor_sine) - floor(Form::Body).0) / 4.0
    );
    println!(
        "  a hand-written DOPRI5 step (7 stages, error norm, controller power, renormalise, f at the new state):"
    );
    println!(
        "    body  form  {:5.1} ns per evaluation ({:5.1}) = {:.2} x the RK4 floor's",
        median(&dopri5_body),
        min(&dopri5_body),
        median(&dopri5_body) / (floor(Form::Body).0 / 4.0)
    );
    println!(
        "    space form  {:5.1} ns per evaluation ({:5.1}) = {:.2} x the RK4 floor's",
        median(&dopri5_space),
        min(&dopri5_space),
        median(&dopri5_space) / (floor(Form::Space).0 / 4.0)
    );
    SINE_FLOOR_NS_PER_EVAL.with(|c| c.set(median(&floor_sine) / 4.0));
    SINE_DOPRI5_NS_PER_EVAL
        .with(|c| c.set(median(&dopri5_body) + (median(&floor_sine) - floor(Form::Body).0) / 4.0));
    let dopri5_floor = |frame: Form| match frame {
        Form::Body => median(&dopri5_body),
        Form::Space => median(&dopri5_space),
    };
    println!(
        "  the splitting methods' own floors: split2/split4 written by hand for this body (plain arrays, the same \
         fused sub-flows and sin/cos series), final state after 1e5 steps against the project's run:"
    );
    let mut own_floor = Vec::new();
    for SplitFloor {
        frame,
        fourth,
        samples,
        omega_b,
        q,
    } in &split_floors
    {
        let name = if *fourth { "split4" } else { "split2" };
        let case = cases
            .iter()
            .find(|c| c.backend == Backend::Own && c.method.name() == name && c.frame == *frame)
            .expect("the project's splitting case");
        let (d_omega, angle) = split_floor_check(case, *omega_b, *q);
        let (m, lo) = (median(samples), min(samples));
        println!(
            "    {name} {:5} form  {m:7.1} ns/step ({lo:5.1}) = {:.2} x the RK4 floor's step; |d omega|/|omega| \
             {d_omega:.1e}, attitude {angle:.1e} rad",
            frame.name(),
            m / floor(*frame).0
        );
        assert!(
            d_omega <= 1e-12 && angle <= 1e-12,
            "the hand-written {name} ({}) does not reach the project's state",
            frame.name()
        );
        own_floor.push((name, *frame, m));
    }
    let own_floor = |method: &str, frame: Form| {
        own_floor
            .iter()
            .find(|(n, f, _)| *n == method && *f == frame)
            .map(|(_, _, m)| *m)
    };
    println!();
    println!(
        "  {:<20} {:<6} {:>9} {:>9} {:>7} {:>9}  {:>15} {:>9}  {:<11} vs the hand-written step (DOPRI5 per eval; split2/4 per step, target <= 1.3)",
        "method",
        "form",
        "ns/step",
        "(min)",
        "evals",
        "ns/eval",
        "vs RK4 floor",
        "target",
        "verdict",
    );
    for case in &cases {
        let (m, lo) = (median(&case.samples), min(&case.samples));
        let label = match case.backend {
            Backend::Own => case.method.name().to_string(),
            b => format!("{}/{}", case.method.name(), b.name()),
        };
        let (floor_m, _) = floor(case.frame);
        if case.per_row() {
            println!(
                "  {label:<20} {:<6} {m:9.1} {lo:9.1}   (ns per row: closed form at {} rows, no steps)",
                case.frame.name(),
                case.rows
            );
            continue;
        }
        let evals_per_step = case.evals as f64 / case.steps as f64;
        let per_eval = m / evals_per_step;
        let (ratio, basis, target) = if case.method.is_fixed_step() {
            (m / floor_m, "per step", 1.3)
        } else {
            (per_eval / (floor_m / 4.0), "per eval", 1.5)
        };
        // The target is for the project's own methods; the ode_solvers rows show what owning the tableaus saved.
        let verdict = match case.backend {
            Backend::Own if ratio <= target => "ok",
            Backend::Own => "MISSED",
            _ => "(reference)",
        };
        let own = match case.backend {
            Backend::Own => own_floor(case.method.name(), case.frame),
            _ => None,
        };
        let vs_dopri5 = if case.method.is_adaptive() {
            format!("{:.2} per eval", per_eval / dopri5_floor(case.frame))
        } else if let Some(own) = own {
            let r = m / own;
            format!(
                "{r:.2} per step vs its own loop: {}",
                if r <= 1.3 { "ok" } else { "MISSED" }
            )
        } else {
            String::new()
        };
        println!(
            "  {label:<20} {:<6} {m:9.1} {lo:9.1} {evals_per_step:7.2} {per_eval:9.2}  {ratio:6.2} {basis} {:>9}  {verdict:<11} {vs_dopri5}",
            case.frame.name(),
            format!("<= {target}"),
        );
    }
    println!(
        "  (split2/split4 evaluations are sub-flows, not right-hand sides; their step is compared with the RK4 floor's)"
    );
}

/// The fastest run of `scene_file` reaching err_omega ≤ 1e-10, over a fine sweep.
fn fastest_to_1e10(scene_file: &str) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(scene_file);
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) => {
            println!("  {}: cannot read: {e}", path.display());
            return;
        }
    };
    // rtol 1e-8 … 1e-12 at four per decade; fixed steps halved 12 times; own backend, both forms.
    let options = StudyOptions {
        rtols: (32..=48).map(|k| 10f64.powf(-f64::from(k) / 4.0)).collect(),
        halvings: 12,
        repeats: 21,
        backends: vec![Backend::Own],
        frames: vec![Form::Body, Form::Space],
        max_fixed_steps: 2e7,
        slow_curve_seconds: 0.5,
    };
    let study = match scene::parse(&path, &text, &Overrides::default())
        .map_err(study::StudyError::from)
        .and_then(|scene| study::accuracy(&scene, &options, |_, _, _| {}))
    {
        Ok(s) => s,
        Err(e) => {
            println!("  {}: {e}", path.display());
            return;
        }
    };
    println!("  {} — reference: {}", scene_file, study.reference);
    let mut reaching: Vec<_> = study
        .rows
        .iter()
        .filter(|r| r.error(study.measure).is_some_and(|e| e <= 1e-10))
        .collect();
    reaching.sort_by(|a, b| a.wall_s.total_cmp(&b.wall_s));
    let mut shown = Vec::new();
    for r in reaching {
        if shown.iter().any(|(m, f)| *m == r.method && *f == r.form) {
            continue;
        }
        shown.push((r.method.clone(), r.form));
        let integrates = r.method_name.is_fixed_step() || r.method_name.is_adaptive();
        println!(
            "    {:<8} {:<5} {:<22} err_omega {:.2e}  {:>10}  ({} steps, {} evals){}",
            r.method,
            r.form.name(),
            r.setting(),
            r.err_omega,
            format_seconds(r.wall_s),
            r.steps,
            r.evals,
            if integrates {
                ""
            } else {
                "  [closed form, no integration]"
            }
        );
    }
    let best = study
        .rows
        .iter()
        .filter(|r| r.method_name.is_fixed_step() || r.method_name.is_adaptive())
        .filter(|r| r.error(study.measure).is_some_and(|e| e <= 1e-10))
        .min_by(|a, b| a.wall_s.total_cmp(&b.wall_s));
    if let Some(r) = best
        && study.measure == eulerdyn::analysis::study::Measure::Omega
        && scene_file.contains("sine")
    {
        let per_eval = SINE_FLOOR_NS_PER_EVAL.with(|c| c.get());
        let per_eval_pair = SINE_DOPRI5_NS_PER_EVAL.with(|c| c.get());
        println!(
            "    its {} evaluations would take {} at the RK4 floor's {per_eval:.1} ns each (sine included), {} at the \
             hand-written DOPRI5 step's {per_eval_pair:.1} ns (sine included); it takes {:.1} ns each",
            r.evals,
            format_seconds(r.evals as f64 * per_eval * 1e-9),
            format_seconds(r.evals as f64 * per_eval_pair * 1e-9),
            r.wall_s * 1e9 / r.evals as f64
        );
        let without_sine = constant_torque_cost(&path, &text, r);
        match without_sine {
            Ok((evals, ns_per_eval)) => println!(
                "    the same run with the sine replaced by a constant torque of the same value (same method and \
                 tolerances): {evals} evaluations at {ns_per_eval:.1} ns each; at that rate these {} evaluations \
                 would take {}: the sine's arithmetic costs {:.1} ns per evaluation",
                r.evals,
                format_seconds(r.evals as f64 * ns_per_eval * 1e-9),
                r.wall_s * 1e9 / r.evals as f64 - ns_per_eval
            ),
            Err(e) => println!("    constant-torque variant: {e}"),
        }
    }
    match best {
        Some(r) => println!(
            "    fastest integration to err_omega <= 1e-10: {} ({} form, {}) in {}  (target <= 0.25 ms: {})",
            r.method,
            r.form.name(),
            r.setting(),
            format_seconds(r.wall_s),
            if r.wall_s <= 0.25e-3 { "ok" } else { "MISSED" }
        ),
        None => println!("    no integrating method reached err_omega <= 1e-10"),
    }
}

/// The sine-torque scene with every sine profile made constant (`freq_hz` dropped), run with the method, form and
/// tolerances of `row`: its evaluations and the median ns per evaluation of the whole integration (the study's timing:
/// `simulate::run` with the rows consumed), over [`SAMPLES`] runs.
fn constant_torque_cost(
    path: &Path,
    text: &str,
    row: &eulerdyn::analysis::study::StudyRow,
) -> Result<(u64, f64), String> {
    let constant: String = text
        .lines()
        .filter(|line| !line.trim_start().starts_with("freq_hz"))
        .map(|line| line.replace("profile = \"sine\"", "profile = \"constant\""))
        .collect::<Vec<_>>()
        .join("\n");
    let overrides = Overrides {
        method: Some(row.method_name),
        form: Some(row.form),
        backend: Some(row.backend),
        rtol: row.rtol,
        atol: row.atol,
        dt: row.dt,
        ..Overrides::default()
    };
    let scene = scene::parse(path, &constant, &overrides).map_err(|e| e.to_string())?;
    let mut times = Vec::with_capacity(SAMPLES);
    let mut evals = 0;
    for _ in 0..SAMPLES {
        let start = Instant::now();
        let report = simulate::run(&scene, |s| {
            black_box(s);
            Ok::<(), Infallible>(())
        })
        .map_err(|e| e.to_string())?;
        times.push(start.elapsed().as_secs_f64());
        evals = report.stats.evals;
    }
    Ok((evals, median(&times) * 1e9 / evals as f64))
}

// ---------------------------------------------------------------------------------------------------------------
// Per row on the sweep's equal grid: the benchmark scene with 10 001 rows over 100 s (a row every 0.01 s).

/// The benchmark scene on an equal grid of 10 001 rows over 100 s.
const GRID_SCENE: &str = "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 0.0, 2.0]\n[solver]\nrtol = 1e-12\natol = 1e-14\nt_end = 100.0\n[output]\nevery = 0.01\n";

/// Runs `once` (which handles `per` rows) until at least SAMPLE_SECONDS have passed: ns per row.
fn ns_per_row(per: u64, mut once: impl FnMut()) -> f64 {
    let (mut runs, start) = (0u64, Instant::now());
    while runs == 0 || start.elapsed().as_secs_f64() < SAMPLE_SECONDS {
        once();
        runs += 1;
    }
    start.elapsed().as_secs_f64() * 1e9 / (runs * per) as f64
}

/// ns per row of `scene` through `simulate::run`, rows handed to a sink that drops them (as a sweep's summary does).
fn run_per_row(scene: &eulerdyn::scene::Scene) -> f64 {
    let rows = scene.schedule.len() as u64;
    ns_per_row(rows, || {
        simulate::run(scene, |s| {
            black_box(s);
            Ok::<(), Infallible>(())
        })
        .expect("the benchmark scene runs");
    })
}

/// Issue 26: `exact` per row on the equal grid against `dop853` at rtol 1e-12 on the same grid, both through
/// `simulate::run` (the whole row: closed form or integration, the row's vectors, the divergence guard), and the
/// closed form alone, advanced by the addition theorems (`TorqueFreeBody::equal_grid`) and evaluated directly at
/// each row (`omega_p` and `attitude`, what `exact` did before). Median (min) of SAMPLES interleaved samples.
fn equal_grid_costs() {
    let path = Path::new("benchmark.toml");
    let with = |method: Method| {
        let overrides = Overrides {
            method: Some(method),
            ..Overrides::default()
        };
        scene::parse(path, GRID_SCENE, &overrides).expect("the grid scene is valid")
    };
    let (exact, dop853) = (with(Method::Exact), with(Method::Dop853));
    let rows = exact.schedule.len();
    let body = TorqueFreeBody::new(
        Vector3::from(MOMENTS),
        Vector3::from(OMEGA0),
        UnitQuaternion::identity(),
    )
    .expect("the benchmark body");
    let every = exact.schedule.every();
    let (mut t_exact, mut t_dop, mut t_walk, mut t_direct) = (vec![], vec![], vec![], vec![]);
    for _ in 0..SAMPLES {
        t_exact.push(run_per_row(&exact));
        t_dop.push(run_per_row(&dop853));
        t_walk.push(ns_per_row(rows as u64, || {
            for row in body.equal_grid(every).take(rows) {
                black_box(row);
            }
        }));
        t_direct.push(ns_per_row(rows as u64, || {
            for k in 0..rows {
                let t = k as f64 * every;
                black_box((body.omega_p(t), body.attitude(t)));
            }
        }));
    }
    let (exact_ns, dop_ns) = (median(&t_exact), median(&t_dop));
    println!(
        "equal grid: the benchmark body, {rows} rows over 100 s (every 0.01 s); ns per row, median (min) of \
         {SAMPLES} samples:"
    );
    println!(
        "  exact  (simulate::run)            {exact_ns:7.1} ({:6.1})   target <= 200 ns: {}",
        min(&t_exact),
        if exact_ns <= 200.0 { "ok" } else { "MISSED" }
    );
    println!(
        "  dop853 rtol 1e-12 (simulate::run) {dop_ns:7.1} ({:6.1})   = {:.2} x exact (target >= 2: {})",
        min(&t_dop),
        dop_ns / exact_ns,
        if dop_ns >= 2.0 * exact_ns {
            "ok"
        } else {
            "MISSED"
        }
    );
    println!(
        "  closed form alone: addition theorems {:6.1} ({:6.1}), direct evaluation {:6.1} ({:6.1}) = {:.1} x",
        median(&t_walk),
        min(&t_walk),
        median(&t_direct),
        min(&t_direct),
        median(&t_direct) / median(&t_walk)
    );
    println!();
}

fn main() {
    equal_grid_costs();
    per_step_costs();
    if std::env::var_os("EULERDYN_BENCH_QUICK").is_some() {
        return;
    }
    println!();
    println!(
        "fastest to a largest omega error <= 1e-10 rad/s (t_end = 100 s, rows every 0.5 s; median of 21 repeats; \
         one line per method and form, its cheapest setting reaching it):"
    );
    fastest_to_1e10("scenarios/asymmetric_free.toml");
    fastest_to_1e10("scenarios/benchmark_sine.toml");
}
