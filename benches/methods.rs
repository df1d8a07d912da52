//! What each method costs on the benchmark body (I = (1, 2, 3) kg·m², ω0 = (0.3, 0, 2) rad/s, torque-free), in
//! both forms of Euler's equation, against a hand-written RK4 loop with the same right-hand side inlined (the
//! floor), in the same process; then the fastest method reaching a largest ω error ≤ 1e-10 rad/s on the benchmark
//! scene (t_end = 100 s, rows every 0.5 s) and on the same body under a sine torque (no closed form).
//!
//! Targets (issue 5): fixed-step methods ≤ 1.3 × the floor per step; adaptive methods ≤ 1.5 × the floor per
//! right-hand-side evaluation (the floor's ns/step / 4); the fastest method to ω error ≤ 1e-10 in ≤ 0.25 ms.
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

use eulerdyn::model::{BackendName, Frame, MethodName};
use eulerdyn::scene::{self, Overrides};
use eulerdyn::simulate;
use eulerdyn::study::{self, StudyOptions, format_seconds};

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

/// Body form under the benchmark's sine torque M_x = 0.5·sin(2π·0.5·t) N·m (scenarios/benchmark_sine.toml).
#[inline(always)]
fn rhs_body_sine(c: &[f64; 3], inv1: f64, t: f64, y: &Y) -> Y {
    let mut f = rhs_body(c, y);
    f[0] += inv1 * 0.5 * (std::f64::consts::PI * t).sin();
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
fn dopri5_floor_sample(frame: Frame) -> f64 {
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
        Frame::Body => rhs_body(&c, y),
        Frame::Space => rhs_space(&inv, y),
    };
    let mut y: Y = match frame {
        Frame::Body => [OMEGA0[0], OMEGA0[1], OMEGA0[2], 1.0, 0.0, 0.0, 0.0],
        Frame::Space => [
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
fn floor_sample(frame: Frame) -> f64 {
    let steps = 100_000u64;
    let h = black_box(1e-3);
    let [i1, i2, i3] = black_box(MOMENTS);
    let start = Instant::now();
    let y = match frame {
        Frame::Body => {
            let c = [(i2 - i3) / i1, (i3 - i1) / i2, (i1 - i2) / i3];
            let y0 = [OMEGA0[0], OMEGA0[1], OMEGA0[2], 1.0, 0.0, 0.0, 0.0];
            hand_rk4(|y| rhs_body(&c, y), black_box(y0), h, steps)
        }
        Frame::Space => {
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

/// One measured case: a method in a form on a backend.
struct Case {
    method: MethodName,
    backend: BackendName,
    frame: Frame,
    scene: eulerdyn::model::Scene,
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
    for backend in [BackendName::Own, BackendName::OdeSolvers] {
        for method in MethodName::ALL {
            if backend != BackendName::Own && !method.is_runge_kutta() {
                continue;
            }
            for frame in [Frame::Body, Frame::Space] {
                let overrides = Overrides {
                    method: Some(method.name().into()),
                    frame: Some(frame.name().into()),
                    backend: Some(backend.name().into()),
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
    for _ in 0..SAMPLES {
        floor_body.push(floor_sample(Frame::Body));
        floor_space.push(floor_sample(Frame::Space));
        floor_sine.push(floor_sine_sample());
        dopri5_body.push(dopri5_floor_sample(Frame::Body));
        dopri5_space.push(dopri5_floor_sample(Frame::Space));
        for case in &mut cases {
            case.sample();
        }
    }
    let floor = |frame: Frame| match frame {
        Frame::Body => (median(&floor_body), min(&floor_body)),
        Frame::Space => (median(&floor_space), min(&floor_space)),
    };
    println!(
        "benchmark body, torque-free, t_end = 100 s, rows at 0 and 100 s only; fixed-step methods dt = 1e-3 s \
         (1e5 steps), adaptive rtol = 1e-10, atol = 1e-12; median (min) of {SAMPLES} samples"
    );
    println!(
        "  floor: hand-written RK4 loop, same right-hand side inlined, quaternion renormalised every step:"
    );
    for frame in [Frame::Body, Frame::Space] {
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
        (median(&floor_sine) - floor(Frame::Body).0) / 4.0
    );
    println!(
        "  a hand-written DOPRI5 step (7 stages, error norm, controller power, renormalise, f at the new state):"
    );
    println!(
        "    body  form  {:5.1} ns per evaluation ({:5.1}) = {:.2} x the RK4 floor's",
        median(&dopri5_body),
        min(&dopri5_body),
        median(&dopri5_body) / (floor(Frame::Body).0 / 4.0)
    );
    println!(
        "    space form  {:5.1} ns per evaluation ({:5.1}) = {:.2} x the RK4 floor's",
        median(&dopri5_space),
        min(&dopri5_space),
        median(&dopri5_space) / (floor(Frame::Space).0 / 4.0)
    );
    SINE_FLOOR_NS_PER_EVAL.with(|c| c.set(median(&floor_sine) / 4.0));
    SINE_DOPRI5_NS_PER_EVAL
        .with(|c| c.set(median(&dopri5_body) + (median(&floor_sine) - floor(Frame::Body).0) / 4.0));
    let dopri5_floor = |frame: Frame| match frame {
        Frame::Body => median(&dopri5_body),
        Frame::Space => median(&dopri5_space),
    };
    println!();
    println!(
        "  {:<20} {:<6} {:>9} {:>9} {:>7} {:>9}  {:>15} {:>9}  {:<11} vs DOPRI5 step",
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
            BackendName::Own => case.method.name().to_string(),
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
            BackendName::Own if ratio <= target => "ok",
            BackendName::Own => "MISSED",
            _ => "(reference)",
        };
        let vs_dopri5 = if case.method.is_adaptive() {
            format!("{:.2} per eval", per_eval / dopri5_floor(case.frame))
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
        backends: vec![BackendName::Own],
        frames: vec![Frame::Body, Frame::Space],
        max_fixed_steps: 2e7,
        slow_curve_seconds: 0.5,
    };
    let study = match study::accuracy(&path, &text, &options, |_, _, _| {}) {
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
        if shown.iter().any(|(m, f)| *m == r.method && *f == r.frame) {
            continue;
        }
        shown.push((r.method.clone(), r.frame));
        let integrates = r.method_name.is_fixed_step() || r.method_name.is_adaptive();
        println!(
            "    {:<8} {:<5} {:<22} err_omega {:.2e}  {:>10}  ({} steps, {} evals){}",
            r.method,
            r.frame.name(),
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
        && study.measure == eulerdyn::study::Measure::Omega
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
    }
    match best {
        Some(r) => println!(
            "    fastest integration to err_omega <= 1e-10: {} ({} form, {}) in {}  (target <= 0.25 ms: {})",
            r.method,
            r.frame.name(),
            r.setting(),
            format_seconds(r.wall_s),
            if r.wall_s <= 0.25e-3 { "ok" } else { "MISSED" }
        ),
        None => println!("    no integrating method reached err_omega <= 1e-10"),
    }
}

fn main() {
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
