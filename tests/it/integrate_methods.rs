//! Tests of `eulerdyn::integrate`: accuracy of every method on problems with exact solutions,
//! exact row landing, projection, stats, failure modes, and one regression test per known
//! defect of ode_solvers 0.6.2 (each shows the raw defect, so an upgrade that fixes it is
//! noticed, and shows that our path is right).
//!
//! Error-bound reasoning used below: Hairer's controllers accept a step only if its scaled
//! error estimate is ≤ 1, i.e. the local error is ≲ √N·(atol + rtol·|y|). For a problem whose
//! flow is an isometry (a rotation) or a contraction (y' = λy, λ < 0), local errors are not
//! amplified, so the global error is ≤ Σ local errors ≤ steps·√N·(atol + rtol·max|y|). For
//! RK4 the local error of y' = λy per step is |λh|^5/120·|y| (Taylor remainder of e^{λh}), so
//! the global error is ≲ T·|λ|^5·h^4/120·max|y|.

use std::alloc::{GlobalAlloc, Layout, System as SysAlloc};
use std::cell::Cell;
use std::convert::Infallible;

use eulerdyn::integrate::{
    Backend, IntegrateError, Method, OdeSystem, Schedule, Settings, Stats, integrate,
};
use nalgebra::{SVector, Vector1, Vector2};
use ode_solvers::dop_shared::IntegrationError;
use ode_solvers::{Dop853, Dopri5, OutputType, Rk4, System};

// ---------------------------------------------------------------------------------------------
// Allocation tracking (per thread, so parallel tests do not disturb each other).

struct Tracking;

thread_local! {
    static LIVE: Cell<i64> = const { Cell::new(0) };
    static PEAK: Cell<i64> = const { Cell::new(0) };
    static ALLOCS: Cell<u64> = const { Cell::new(0) };
}

fn track(delta: i64, new_block: bool) {
    let _ = LIVE.try_with(|live| {
        let now = live.get() + delta;
        live.set(now);
        let _ = PEAK.try_with(|p| p.set(p.get().max(now)));
    });
    if new_block {
        let _ = ALLOCS.try_with(|a| a.set(a.get() + 1));
    }
}

// SAFETY: forwards every call unchanged to the system allocator; only counts sizes.
unsafe impl GlobalAlloc for Tracking {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        track(layout.size() as i64, true);
        unsafe { SysAlloc.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        track(layout.size() as i64, true);
        unsafe { SysAlloc.alloc_zeroed(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        track(-(layout.size() as i64), false);
        unsafe { SysAlloc.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        track(new_size as i64 - layout.size() as i64, true);
        unsafe { SysAlloc.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Tracking = Tracking;

/// Runs `f` and returns its result, the number of allocations it made on this thread, and the
/// peak of live heap bytes above the level at entry.
fn measure<R>(f: impl FnOnce() -> R) -> (R, u64, i64) {
    let base = LIVE.with(Cell::get);
    PEAK.with(|p| p.set(base));
    let a0 = ALLOCS.with(Cell::get);
    let r = f();
    let allocs = ALLOCS.with(Cell::get) - a0;
    let peak = PEAK.with(Cell::get) - base;
    (r, allocs, peak)
}

// ---------------------------------------------------------------------------------------------
// Test systems (each counts its RHS calls).

/// y' = λy; exact y0·e^{λt}.
struct Exp {
    lambda: f64,
    calls: u64,
}
impl OdeSystem<1> for Exp {
    fn rhs(&mut self, _t: f64, y: &Vector1<f64>) -> Vector1<f64> {
        self.calls += 1;
        y * self.lambda
    }
}

/// Scaled harmonic oscillator x' = ωv, v' = −ωx (a rotation: isometric flow);
/// exact (cos ωt, −sin ωt) from (1, 0).
struct Oscillator {
    omega: f64,
    calls: u64,
}
impl OdeSystem<2> for Oscillator {
    fn rhs(&mut self, _t: f64, y: &Vector2<f64>) -> Vector2<f64> {
        self.calls += 1;
        Vector2::new(self.omega * y[1], -self.omega * y[0])
    }
}
fn oscillator_exact(omega: f64, t: f64) -> Vector2<f64> {
    Vector2::new((omega * t).cos(), -(omega * t).sin())
}

/// y' = cos(ωt), time-dependent only; exact sin(ωt)/ω from 0.
struct Cosine {
    omega: f64,
    calls: u64,
}
impl OdeSystem<1> for Cosine {
    fn rhs(&mut self, t: f64, _y: &Vector1<f64>) -> Vector1<f64> {
        self.calls += 1;
        Vector1::new((self.omega * t).cos())
    }
}

/// The oscillator with a projection that renormalises |y| = 1 and counts its calls.
struct Circle {
    omega: f64,
    projections: Cell<u64>,
    calls: u64,
}
impl OdeSystem<2> for Circle {
    fn rhs(&mut self, _t: f64, y: &Vector2<f64>) -> Vector2<f64> {
        self.calls += 1;
        Vector2::new(self.omega * y[1], -self.omega * y[0])
    }
    fn project(&self, y: &mut Vector2<f64>) {
        self.projections.set(self.projections.get() + 1);
        *y /= y.norm();
    }
}

/// y' = y², y(0) = 1: exact 1/(1 − t), blows up at t = 1.
struct Blowup;
impl OdeSystem<1> for Blowup {
    fn rhs(&mut self, _t: f64, y: &Vector1<f64>) -> Vector1<f64> {
        Vector1::new(y[0] * y[0])
    }
}

// ---------------------------------------------------------------------------------------------
// ode_solvers adapters for the raw-defect demonstrations.

struct RawExp;
impl System<f64, Vector1<f64>> for RawExp {
    fn system(&self, _x: f64, y: &Vector1<f64>, dy: &mut Vector1<f64>) {
        dy[0] = y[0];
    }
}

struct RawCosine {
    omega: f64,
}
impl System<f64, Vector1<f64>> for RawCosine {
    fn system(&self, x: f64, _y: &Vector1<f64>, dy: &mut Vector1<f64>) {
        dy[0] = (self.omega * x).cos();
    }
}

struct RawOscillator {
    omega: f64,
}
impl System<f64, Vector2<f64>> for RawOscillator {
    fn system(&self, _x: f64, y: &Vector2<f64>, dy: &mut Vector2<f64>) {
        dy[0] = self.omega * y[1];
        dy[1] = -self.omega * y[0];
    }
}

// ---------------------------------------------------------------------------------------------
// Helpers.

const ALL: [(Method, Backend); 6] = [
    (Method::Rk4, Backend::Own),
    (Method::Rk4, Backend::OdeSolvers),
    (Method::Dopri5, Backend::Own),
    (Method::Dopri5, Backend::OdeSolvers),
    (Method::Dop853, Backend::Own),
    (Method::Dop853, Backend::OdeSolvers),
];

fn settings(method: Method, backend: Backend) -> Settings {
    Settings {
        method,
        backend,
        rtol: 1e-10,
        atol: 1e-12,
        dt: 1e-2,
        max_steps: 10_000_000,
    }
}

type Rows<const N: usize> = Vec<(f64, SVector<f64, N>)>;

/// Integrates and collects every row.
fn collect<const N: usize, S: OdeSystem<N>>(
    sys: &mut S,
    y0: SVector<f64, N>,
    schedule: &Schedule,
    settings: &Settings,
) -> (Rows<N>, Result<Stats, IntegrateError>) {
    let mut rows = Vec::new();
    let r = integrate(sys, y0, schedule, settings, |t, y| {
        rows.push((t, *y));
        Ok::<(), Infallible>(())
    });
    (rows, r)
}

/// Largest |y(t_k) − exact(t_k)| over the rows.
fn max_err<const N: usize>(rows: &Rows<N>, exact: impl Fn(f64) -> SVector<f64, N>) -> f64 {
    rows.iter()
        .map(|(t, y)| (y - exact(*t)).amax())
        .fold(0.0, f64::max)
}

/// Bound for the adaptive methods: steps·√N·(atol + rtol·ymax) (see the module docs).
fn adaptive_bound(s: &Settings, stats: &Stats, n: usize, ymax: f64) -> f64 {
    stats.steps as f64 * (n as f64).sqrt() * (s.atol + s.rtol * ymax)
}

// ---------------------------------------------------------------------------------------------
// Accuracy of every method.

#[test]
fn exponential_decay_every_method() {
    let lambda = -1.3;
    let schedule = Schedule::new(0.5, 10.0).unwrap();
    for (method, backend) in ALL {
        let s = settings(method, backend);
        let mut sys = Exp { lambda, calls: 0 };
        let (rows, r) = collect(&mut sys, Vector1::new(1.0), &schedule, &s);
        let stats = r.unwrap();
        let err = max_err(&rows, |t| Vector1::new((lambda * t).exp()));
        let bound = match method {
            // Contractive flow: global error ≤ Σ local errors ≤ T·|λ|^5·h^4/120·max|y|, ×2 slack.
            Method::Rk4 => 2.0 * 10.0 * lambda.abs().powi(5) * s.dt.powi(4) / 120.0,
            _ => adaptive_bound(&s, &stats, 1, 1.0),
        };
        println!("exp {method:?}/{backend:?}: err {err:.3e} bound {bound:.3e} {stats:?}");
        assert!(err <= bound, "{method:?}/{backend:?}: {err:e} > {bound:e}");
        assert_eq!(stats.evals, sys.calls, "{method:?}/{backend:?}: evals");
    }
}

#[test]
fn harmonic_oscillator_every_method() {
    let omega = 2.0;
    let t_end = 10.0;
    let schedule = Schedule::new(0.25, t_end).unwrap();
    for (method, backend) in ALL {
        let s = settings(method, backend);
        let mut sys = Oscillator { omega, calls: 0 };
        let (rows, r) = collect(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s);
        let stats = r.unwrap();
        let err = max_err(&rows, |t| oscillator_exact(omega, t));
        let bound = match method {
            // Isometric flow: per step |ωh|^5/120 (RK4 local error of a rotation by ωh),
            // T/h steps, ×2 slack.
            Method::Rk4 => 2.0 * t_end * omega.powi(5) * s.dt.powi(4) / 120.0,
            _ => adaptive_bound(&s, &stats, 2, 1.0),
        };
        println!("osc {method:?}/{backend:?}: err {err:.3e} bound {bound:.3e} {stats:?}");
        assert!(err <= bound, "{method:?}/{backend:?}: {err:e} > {bound:e}");
        assert_eq!(stats.evals, sys.calls, "{method:?}/{backend:?}: evals");
    }
}

#[test]
fn rk4_observed_order_is_four() {
    // Halving dt divides the global error by 2^4 = 16 for an order-4 method; the asymptotic
    // regime holds for ωh ≤ 0.1 (next error term is O(h^5), relative size ~ωh/5 ≤ 2%), so
    // log2(ratio) must be within ±0.2 of 4.
    let omega = 2.0;
    let schedule = Schedule::new(1.0, 10.0).unwrap();
    for backend in [Backend::Own, Backend::OdeSolvers] {
        let mut errs = Vec::new();
        for dt in [0.05, 0.025, 0.0125, 0.00625] {
            let s = Settings {
                dt,
                ..settings(Method::Rk4, backend)
            };
            let mut sys = Oscillator { omega, calls: 0 };
            let (rows, r) = collect(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s);
            r.unwrap();
            errs.push(max_err(&rows, |t| oscillator_exact(omega, t)));
        }
        for w in errs.windows(2) {
            let order = (w[0] / w[1]).log2();
            println!(
                "rk4 {backend:?}: {:.3e} -> {:.3e}, order {order:.4}",
                w[0], w[1]
            );
            assert!(
                (order - 4.0).abs() < 0.2,
                "{backend:?}: observed order {order}"
            );
        }
    }
}

#[test]
fn adaptive_error_scales_with_tolerance() {
    // Tightening rtol by 10^3 must reduce the error by at least 10^2 (the global error is
    // roughly proportional to the tolerance; one decade of slack for the controller).
    let omega = 2.0;
    let schedule = Schedule::new(1.0, 10.0).unwrap();
    for (method, backend) in ALL.into_iter().filter(|(m, _)| *m != Method::Rk4) {
        let err_at = |rtol: f64| {
            let s = Settings {
                rtol,
                atol: rtol * 1e-2,
                ..settings(method, backend)
            };
            let mut sys = Oscillator { omega, calls: 0 };
            let (rows, r) = collect(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s);
            r.unwrap();
            max_err(&rows, |t| oscillator_exact(omega, t))
        };
        let (coarse, fine) = (err_at(1e-6), err_at(1e-9));
        println!("{method:?}/{backend:?}: rtol 1e-6 → {coarse:.3e}, 1e-9 → {fine:.3e}");
        assert!(fine * 100.0 <= coarse, "{method:?}/{backend:?}");
    }
}

// ---------------------------------------------------------------------------------------------
// Defect (a): DOP853 nodes c12 = c13 = 0 in ode_solvers 0.6.2.

#[test]
fn defect_a_dop853_time_dependent_rhs() {
    let omega = 3.0;
    let t_end = 5.0;
    let (rtol, atol) = (1e-10, 1e-12);
    let exact = |t: f64| (omega * t).sin() / omega;

    // Raw ode_solvers: stage 12 is evaluated at t instead of t + h.
    let mut raw = Dop853::from_param(
        RawCosine { omega },
        0.0,
        t_end,
        0.0,
        Vector1::new(0.0),
        rtol,
        atol,
        0.9,
        0.0,
        0.333,
        6.0,
        t_end,
        0.0,
        u32::MAX,
        u32::MAX,
        OutputType::Sparse,
    );
    raw.integrate().unwrap();
    let raw_err = raw
        .x_out()
        .iter()
        .zip(raw.y_out())
        .map(|(x, y)| (y[0] - exact(*x)).abs())
        .fold(0.0, f64::max);

    // Ours: own DOP853, and ode_solvers' DOP853 on the autonomous form.
    let schedule = Schedule::new(0.5, t_end).unwrap();
    let mut ours = Vec::new();
    for backend in [Backend::Own, Backend::OdeSolvers] {
        let s = settings(Method::Dop853, backend);
        let mut sys = Cosine { omega, calls: 0 };
        let (rows, r) = collect(&mut sys, Vector1::new(0.0), &schedule, &s);
        let stats = r.unwrap();
        let err = max_err(&rows, |t| Vector1::new(exact(t)));
        let bound = adaptive_bound(&s, &stats, 1, 1.0);
        println!("c12: {backend:?} err {err:.3e} (bound {bound:.3e}), {stats:?}");
        assert!(err <= bound, "{backend:?}: {err:e} > {bound:e}");
        ours.push(err);
    }
    println!("c12: raw ode_solvers DOP853 err {raw_err:.3e}");
    // The raw error is far above anything the tolerance allows (and above ours).
    assert!(
        raw_err > 1e3 * rtol,
        "ode_solvers DOP853 c12/c13 defect fixed? err {raw_err:e}"
    );
    assert!(raw_err > 100.0 * ours[0].max(ours[1]));
}

// ---------------------------------------------------------------------------------------------
// Defect (b): Dense output's last row and solout's (x, y) pairs.

/// y' = y, recording the (x, y) pairs ode_solvers passes to `solout`.
struct RecordingExp<'a> {
    seen: &'a mut Vec<(f64, f64)>,
}
impl System<f64, Vector1<f64>> for RecordingExp<'_> {
    fn system(&self, _x: f64, y: &Vector1<f64>, dy: &mut Vector1<f64>) {
        dy[0] = y[0];
    }
    fn solout(&mut self, x: f64, y: &Vector1<f64>, _dy: &Vector1<f64>) -> bool {
        self.seen.push((x, y[0]));
        false
    }
}

#[test]
fn defect_b_dense_output_last_row_and_solout() {
    // y' = y on [0, 1], dense output every 0.5, rtol 1e-10: every row should be e^x to ~1e-9.
    let mut scratch = Vec::new();
    let mut raw = Dopri5::new(
        RecordingExp { seen: &mut scratch },
        0.0,
        1.0,
        0.5,
        Vector1::new(1.0),
        1e-10,
        1e-10,
    );
    raw.integrate().unwrap();
    let (x, y) = (raw.x_out(), raw.y_out());
    let last_err = (y.last().unwrap()[0] - x.last().unwrap().exp()).abs();
    println!(
        "dense rows: {:?}",
        x.iter().zip(y).map(|(x, y)| (*x, y[0])).collect::<Vec<_>>()
    );
    // The last row (t = 1) is extrapolated from the first step's interpolant: wrong by ≫ tol.
    assert_eq!(*x.last().unwrap(), 1.0);
    assert!(
        last_err > 1e-4,
        "Dense last-row defect fixed? err {last_err:e}"
    );

    // solout: the y it receives is not the solution at the x it receives.
    let mut seen = Vec::new();
    let mut raw = Dopri5::new(
        RecordingExp { seen: &mut seen },
        0.0,
        1.0,
        0.5,
        Vector1::new(1.0),
        1e-10,
        1e-10,
    );
    raw.integrate().unwrap();
    drop(raw);
    let worst = seen
        .iter()
        .map(|(x, y)| (y - x.exp()).abs())
        .fold(0.0, f64::max);
    println!("solout pairs: {seen:?}");
    assert!(worst > 1e-3, "Dense solout mismatch fixed? worst {worst:e}");

    // Ours (both backends): every row is e^t to the tolerance, exactly at k·0.5 and t_end.
    let schedule = Schedule::new(0.5, 1.0).unwrap();
    for (method, backend) in ALL.into_iter().filter(|(m, _)| *m != Method::Rk4) {
        let s = settings(method, backend);
        let mut sys = Exp {
            lambda: 1.0,
            calls: 0,
        };
        let (rows, r) = collect(&mut sys, Vector1::new(1.0), &schedule, &s);
        let stats = r.unwrap();
        let times: Vec<f64> = rows.iter().map(|r| r.0).collect();
        assert_eq!(times, vec![0.0, 0.5, 1.0]);
        // Growing flow (factor e on [0, 1]): bound Σ local errors × e.
        let bound = std::f64::consts::E * adaptive_bound(&s, &stats, 1, std::f64::consts::E);
        let err = max_err(&rows, |t| Vector1::new(t.exp()));
        assert!(err <= bound, "{method:?}/{backend:?}: {err:e} > {bound:e}");
    }
}

// ---------------------------------------------------------------------------------------------
// Defect (c): Rk4 steps past x_end.

#[test]
fn defect_c_rk4_overshoots_end() {
    let mut raw = Rk4::new(RawExp, 0.0, Vector1::new(1.0), 1.0, 0.3);
    let stats = raw.integrate().unwrap();
    let x_last = *raw.x_out().last().unwrap();
    println!("raw Rk4: last x = {x_last}, steps {}", stats.accepted_steps);
    assert!(x_last > 1.0 + 0.1, "Rk4 overshoot fixed? last x {x_last}");

    // Ours: dt = 0.3 on rows every 1.0 → n = ⌈1/0.3⌉ = 4 steps of 0.25 per row, landing exactly.
    let schedule = Schedule::new(1.0, 3.0).unwrap();
    for backend in [Backend::Own, Backend::OdeSolvers] {
        let s = Settings {
            dt: 0.3,
            ..settings(Method::Rk4, backend)
        };
        let mut sys = Exp {
            lambda: 1.0,
            calls: 0,
        };
        let (rows, r) = collect(&mut sys, Vector1::new(1.0), &schedule, &s);
        let stats = r.unwrap();
        assert_eq!(stats.steps, 12, "{backend:?}");
        assert_eq!(
            rows.iter().map(|r| r.0).collect::<Vec<_>>(),
            vec![0.0, 1.0, 2.0, 3.0]
        );
        // Four RK4 steps of h = 1/4 multiply y by R(1/4)^4 per row, R(z) = 1+z+z²/2+z³/6+z⁴/24.
        let r4 = {
            let z: f64 = 0.25;
            (1.0 + z + z * z / 2.0 + z.powi(3) / 6.0 + z.powi(4) / 24.0).powi(4)
        };
        for (k, (_, y)) in rows.iter().enumerate() {
            let expect = r4.powi(k as i32);
            assert!(
                (y[0] - expect).abs() <= 1e-14 * expect,
                "{backend:?} row {k}"
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Defect (d): every step kept in memory.

#[test]
fn defect_d_memory_is_bounded() {
    // Raw ode_solvers keeps every step: peak heap ≥ steps·16 bytes for a 2-vector state.
    let ((stats, steps_kept), _, raw_peak) = measure(|| {
        let mut raw = Dopri5::from_param(
            RawOscillator { omega: 1.0 },
            0.0,
            2000.0,
            0.0,
            Vector2::new(1.0, 0.0),
            1e-10,
            1e-12,
            0.9,
            0.04,
            0.2,
            10.0,
            2000.0,
            0.0,
            u32::MAX,
            u32::MAX,
            OutputType::Sparse,
        );
        let stats = raw.integrate().unwrap();
        (stats, raw.x_out().len())
    });
    println!(
        "raw Dopri5: {} steps, {steps_kept} kept, peak {raw_peak} B",
        stats.accepted_steps
    );
    assert_eq!(steps_kept, stats.accepted_steps as usize + 1);
    assert!(raw_peak >= 16 * stats.accepted_steps as i64);

    let run = |backend: Backend, t_end: f64| {
        let schedule = Schedule::new(10.0, t_end).unwrap();
        let s = settings(Method::Dopri5, backend);
        let mut sys = Oscillator {
            omega: 1.0,
            calls: 0,
        };
        measure(|| {
            integrate(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s, |_, _| {
                Ok::<(), Infallible>(())
            })
            .unwrap()
        })
    };
    // Own backend: no heap allocation at all during the run, however long.
    for method in [Method::Rk4, Method::Dopri5, Method::Dop853] {
        let schedule = Schedule::new(10.0, 2000.0).unwrap();
        let s = settings(method, Backend::Own);
        let mut sys = Oscillator {
            omega: 1.0,
            calls: 0,
        };
        let (stats, allocs, peak) = measure(|| {
            integrate(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s, |_, _| {
                Ok::<(), Infallible>(())
            })
            .unwrap()
        });
        println!(
            "own {method:?}: {} steps, {allocs} allocations, peak {peak} B",
            stats.steps
        );
        assert_eq!((allocs, peak), (0, 0), "{method:?}");
    }
    // ode_solvers backend: the peak does not grow with the run length (one interval at a time).
    let (short, _, peak_short) = run(Backend::OdeSolvers, 200.0);
    let (long, _, peak_long) = run(Backend::OdeSolvers, 2000.0);
    println!(
        "ode_solvers path: {} steps peak {peak_short} B; {} steps peak {peak_long} B",
        short.steps, long.steps
    );
    assert!(long.steps > 9 * short.steps);
    assert!(
        peak_long <= peak_short + 1024,
        "{peak_long} vs {peak_short}"
    );
    assert!(peak_long * 10 < raw_peak);
}

// ---------------------------------------------------------------------------------------------
// Defect (e): n_max = 100000 and stiffness detection abort long runs.

/// Stiff scalar problem y' = −λ(y − cos t): explicit methods run at their stability limit
/// (hλ ≈ 3.3 for DOPRI5), which ode_solvers' stiffness test reports as an error although the
/// solution is still computed correctly (just with many steps).
struct Relaxation {
    lambda: f64,
}
impl System<f64, Vector1<f64>> for Relaxation {
    fn system(&self, x: f64, y: &Vector1<f64>, dy: &mut Vector1<f64>) {
        dy[0] = -self.lambda * (y[0] - x.cos());
    }
}
impl OdeSystem<1> for Relaxation {
    fn rhs(&mut self, t: f64, y: &Vector1<f64>) -> Vector1<f64> {
        Vector1::new(-self.lambda * (y[0] - t.cos()))
    }
}

#[test]
fn defect_e_step_limit_and_stiffness_abort() {
    // n_max: a 2·10^5-step run through the plain constructor stops at 100000 steps.
    let omega = 50.0;
    let t_end = 600.0;
    let mut raw = Dopri5::new(
        RawOscillator { omega },
        0.0,
        t_end,
        t_end,
        Vector2::new(1.0, 0.0),
        1e-7,
        1e-9,
    );
    raw.set_output(OutputType::Sparse);
    let e = raw.integrate().unwrap_err();
    println!("raw Dopri5 long run: {e}");
    assert!(matches!(
        e,
        IntegrationError::MaxNumStepReached {
            n_step: 100_001,
            ..
        }
    ));

    // Ours, both backends, one single row interval [0, t_end]: no abort, stats add up.
    let schedule = Schedule::new(t_end, t_end).unwrap();
    for backend in [Backend::Own, Backend::OdeSolvers] {
        let s = Settings {
            rtol: 1e-7,
            atol: 1e-9,
            ..settings(Method::Dopri5, backend)
        };
        let mut sys = Oscillator { omega, calls: 0 };
        let (rows, r) = collect(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s);
        let stats = r.unwrap();
        println!("Dopri5 {backend:?} long run: {stats:?}");
        assert!(stats.steps > 200_000, "{backend:?}: {stats:?}");
        assert!(stats.steps + stats.rejected < u64::from(u32::MAX));
        assert_eq!(stats.evals, sys.calls);
        if backend == Backend::Own {
            // hinit (2) + 6 per attempt (FSAL).
            assert_eq!(stats.evals, 2 + 6 * (stats.steps + stats.rejected));
        }
        assert_eq!(rows.last().unwrap().0, t_end);
        let err = max_err(&rows, |t| oscillator_exact(omega, t));
        assert!(
            err <= adaptive_bound(&s, &stats, 2, 1.0),
            "{backend:?}: {err:e}"
        );
    }

    // Stiffness detection: the plain constructor aborts a mildly stiff problem.
    let lambda = 1e4;
    let t_end = 10.0;
    let mut raw = Dopri5::new(
        Relaxation { lambda },
        0.0,
        t_end,
        t_end,
        Vector1::new(1.0),
        1e-6,
        1e-8,
    );
    raw.set_output(OutputType::Sparse);
    let e = raw.integrate().unwrap_err();
    println!("raw Dopri5 stiff: {e}");
    assert!(matches!(e, IntegrationError::StiffnessDetected { .. }));
    // Ours: completes; after the e^{−λt} transient y is the particular solution
    // y_p = (λ² cos t + λ sin t)/(λ² + 1), here to ~rtol.
    let schedule = Schedule::new(1.0, t_end).unwrap();
    for backend in [Backend::Own, Backend::OdeSolvers] {
        let s = Settings {
            rtol: 1e-6,
            atol: 1e-8,
            ..settings(Method::Dopri5, backend)
        };
        let mut sys = Relaxation { lambda };
        let (rows, r) = collect(&mut sys, Vector1::new(1.0), &schedule, &s);
        let stats = r.unwrap();
        let (t, y) = rows.last().unwrap();
        let slow = (t.cos() * lambda * lambda + lambda * t.sin()) / (lambda * lambda + 1.0);
        println!(
            "Dopri5 {backend:?} stiff: {stats:?}, y(t_end) − y_p = {:.2e}",
            y[0] - slow
        );
        assert!((y[0] - slow).abs() < 1e-5, "{backend:?}");
    }
}

#[test]
fn long_fixed_step_run_stats_add_up() {
    // 2·10^5 RK4 steps (dt = 1e-3 on [0, 200]) on both backends: exact counts.
    let schedule = Schedule::new(10.0, 200.0).unwrap();
    let mut finals = Vec::new();
    for backend in [Backend::Own, Backend::OdeSolvers] {
        let s = Settings {
            dt: 1e-3,
            ..settings(Method::Rk4, backend)
        };
        let mut sys = Oscillator {
            omega: 1.0,
            calls: 0,
        };
        let (rows, r) = collect(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s);
        let stats = r.unwrap();
        assert_eq!(
            stats,
            Stats {
                steps: 200_000,
                rejected: 0,
                evals: 800_000
            },
            "{backend:?}"
        );
        assert_eq!(sys.calls, 800_000);
        assert_eq!(rows.len(), 21);
        finals.push(rows.last().unwrap().1);
    }
    // Same steps on both backends: agreement to rounding (≈ 2·10^5 steps × ε).
    assert!((finals[0] - finals[1]).amax() < 1e-10);
}

#[test]
fn own_dop853_eval_count_is_exact() {
    // hinit (2) + 11 stage evaluations per attempt + 1 FSAL evaluation per accepted step.
    let schedule = Schedule::new(0.1, 20.0).unwrap();
    let s = settings(Method::Dop853, Backend::Own);
    let mut sys = Oscillator {
        omega: 3.0,
        calls: 0,
    };
    let (_, r) = collect(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s);
    let st = r.unwrap();
    println!("own Dop853: {st:?}");
    assert_eq!(st.evals, 2 + 11 * (st.steps + st.rejected) + st.steps);
    assert_eq!(st.evals, sys.calls);
}

// ---------------------------------------------------------------------------------------------
// Defect (f): no renormalisation between steps in ode_solvers; our `project`.

#[test]
fn defect_f_projection() {
    // Raw ode_solvers RK4 on a rotation with a coarse step drifts off |y| = 1 (RK4 shrinks the
    // norm by |R(iωh)| = 1 − (ωh)^6/144 + … per step), and its API gives no way to renormalise
    // between steps (System::system takes &self, solout gets &y).
    let mut raw = Rk4::new(
        RawOscillator { omega: 1.0 },
        0.0,
        Vector2::new(1.0, 0.0),
        100.0,
        0.25,
    );
    raw.integrate().unwrap();
    let drift = (raw.y_out().last().unwrap().norm() - 1.0).abs();
    println!("raw Rk4 norm drift: {drift:.3e}");
    assert!(drift > 1e-4);

    // Ours: |y| = 1 to rounding at every row; project called once at t0 and after every
    // accepted step (own) or every row interval (ode_solvers).
    let schedule = Schedule::new(1.0, 100.0).unwrap();
    for (method, backend) in ALL {
        let s = Settings {
            dt: 0.25,
            rtol: 1e-6,
            atol: 1e-9,
            ..settings(method, backend)
        };
        let mut sys = Circle {
            omega: 1.0,
            projections: Cell::new(0),
            calls: 0,
        };
        let (rows, r) = collect(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s);
        let stats = r.unwrap();
        let worst = rows
            .iter()
            .map(|(_, y)| (y.norm() - 1.0).abs())
            .fold(0.0, f64::max);
        assert!(
            worst <= 2.0 * f64::EPSILON,
            "{method:?}/{backend:?}: {worst:e}"
        );
        let expected = match backend {
            Backend::Own => 1 + stats.steps,
            Backend::OdeSolvers => rows.len() as u64,
        };
        assert_eq!(sys.projections.get(), expected, "{method:?}/{backend:?}");
        assert_eq!(stats.evals, sys.calls, "{method:?}/{backend:?}");
        if (method, backend) == (Method::Dopri5, Backend::Own) {
            // FSAL is refreshed (1 extra evaluation) only after steps whose state the
            // renormalisation actually changed.
            let base = 2 + 6 * (stats.steps + stats.rejected);
            assert!(
                stats.evals > base && stats.evals <= base + stats.steps,
                "{stats:?}"
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Rows.

#[test]
fn rows_land_exactly_on_schedule() {
    for (every, t_end) in [
        (0.3, 1.0),
        (0.5, 2.5),
        (0.7, 0.35),
        (0.25, 0.0),
        (1.0 / 3.0, 2.0),
    ] {
        let schedule = Schedule::new(every, t_end).unwrap();
        let expected: Vec<f64> = schedule.iter().collect();
        // k·every for the grid rows, then t_end, bit for bit.
        for (k, t) in expected.iter().enumerate() {
            let want = if k + 1 == expected.len() {
                t_end
            } else {
                k as f64 * every
            };
            assert_eq!(*t, want);
        }
        for (method, backend) in ALL {
            let s = settings(method, backend);
            let mut sys = Oscillator {
                omega: 2.0,
                calls: 0,
            };
            let (rows, r) = collect(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s);
            let stats = r.unwrap();
            let times: Vec<f64> = rows.iter().map(|r| r.0).collect();
            assert_eq!(
                times, expected,
                "{method:?}/{backend:?} every {every} t_end {t_end}"
            );
            if t_end == 0.0 {
                assert_eq!(rows, vec![(0.0, Vector2::new(1.0, 0.0))]);
                assert_eq!(stats, Stats::default());
            }
            // Each row holds the state at its own time (not interpolated from elsewhere).
            let bound = match method {
                Method::Rk4 => 1e-6,
                _ => adaptive_bound(&s, &stats, 2, 1.0).max(1e-12),
            };
            assert!(max_err(&rows, |t| oscillator_exact(2.0, t)) <= bound);
        }
    }
}

#[test]
fn backends_agree_for_each_method() {
    // Both backends solve the same problem to the same tolerance; they must agree within the
    // sum of their error bounds (RK4: identical steps, so to rounding).
    let omega = 2.0;
    let schedule = Schedule::new(0.5, 20.0).unwrap();
    for method in [Method::Rk4, Method::Dopri5, Method::Dop853] {
        let mut out = Vec::new();
        for backend in [Backend::Own, Backend::OdeSolvers] {
            let s = settings(method, backend);
            let mut sys = Oscillator { omega, calls: 0 };
            let (rows, r) = collect(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s);
            out.push((rows, r.unwrap(), s));
        }
        let diff = out[0]
            .0
            .iter()
            .zip(&out[1].0)
            .map(|(a, b)| {
                assert_eq!(a.0, b.0);
                (a.1 - b.1).amax()
            })
            .fold(0.0, f64::max);
        let bound = match method {
            Method::Rk4 => 1e-12,
            _ => {
                adaptive_bound(&out[0].2, &out[0].1, 2, 1.0)
                    + adaptive_bound(&out[1].2, &out[1].1, 2, 1.0)
            }
        };
        println!(
            "{method:?}: own {:?} vs ode_solvers {:?}: max diff {diff:.3e} (bound {bound:.3e})",
            out[0].1, out[1].1
        );
        assert!(diff <= bound, "{method:?}: {diff:e} > {bound:e}");
    }
}

// ---------------------------------------------------------------------------------------------
// Failures.

#[test]
fn blow_up_is_reported_near_t_equals_one() {
    // y' = y², y(0) = 1 → 1/(1 − t): every method stops near t = 1; rows before the blow-up
    // are reported, no row is non-finite or after t = 1.
    let schedule = Schedule::new(0.25, 2.0).unwrap();
    for (method, backend) in ALL {
        let s = Settings {
            dt: 1e-3,
            ..settings(method, backend)
        };
        let (rows, r) = collect(&mut Blowup, Vector1::new(1.0), &schedule, &s);
        let e = r.unwrap_err();
        println!("blow-up {method:?}/{backend:?}: {e}");
        let t = match e {
            IntegrateError::NonFinite { t } => t,
            IntegrateError::StepSizeTooSmall { t, .. } => t,
            other => panic!("{method:?}/{backend:?}: unexpected {other}"),
        };
        // RK4 with h = 1e-3 overflows within a few steps past t = 1 (hy ≳ 1 there); the
        // adaptive methods stall where h ≤ 16ε·t, i.e. within ~1e-11 of the singularity of their
        // own numerical solution, which lies within the accumulated error (~1e-11) of t = 1.
        assert!((t - 1.0).abs() < 0.02, "{method:?}/{backend:?}: t = {t}");
        assert!(rows.iter().all(|(_, y)| y[0].is_finite()));
        // The row t = 1 itself may be reported (finite) when the numerical singularity lies
        // just after 1 (RK4: a few steps after; DOP853 here: at 1 + 8e-12).
        let last = rows.last().unwrap().0;
        assert!(
            last == 0.75 || last == 1.0,
            "{method:?}/{backend:?}: {last}"
        );
        assert!(matches!(method, Method::Rk4) || (t - 1.0).abs() < 1e-6);
    }
}

#[test]
fn callback_error_stops_the_run() {
    let schedule = Schedule::new(0.25, 2.0).unwrap();
    for (method, backend) in ALL {
        let s = settings(method, backend);
        let mut sys = Oscillator {
            omega: 1.0,
            calls: 0,
        };
        let mut seen = Vec::new();
        let r = integrate(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s, |t, _| {
            seen.push(t);
            if t >= 0.5 { Err("disk full") } else { Ok(()) }
        });
        match r {
            Err(IntegrateError::Stopped { t, cause }) => {
                assert_eq!((t, cause), (0.5, "disk full"));
            }
            other => panic!("{method:?}/{backend:?}: {other:?}"),
        }
        assert_eq!(seen, vec![0.0, 0.25, 0.5]);
        let msg = IntegrateError::Stopped {
            t: 0.5,
            cause: "disk full",
        }
        .to_string();
        assert!(msg.contains("0.5") && msg.contains("disk full"));
    }
}

#[test]
fn step_budget_and_invalid_settings() {
    let schedule = Schedule::new(1.0, 10.0).unwrap();
    for (method, backend) in ALL {
        let s = Settings {
            max_steps: 20,
            dt: 1e-3,
            ..settings(method, backend)
        };
        let mut sys = Oscillator {
            omega: 1.0,
            calls: 0,
        };
        let (rows, r) = collect(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s);
        let e = r.unwrap_err();
        assert!(
            matches!(e, IntegrateError::TooManySteps { .. }),
            "{method:?}/{backend:?}: {e}"
        );
        assert!(e.to_string().contains("max_steps"));
        assert!(rows.len() < schedule.len());
    }
    let bad = [
        Settings {
            dt: 0.0,
            ..settings(Method::Rk4, Backend::Own)
        },
        Settings {
            rtol: 0.0,
            ..settings(Method::Dopri5, Backend::Own)
        },
        Settings {
            atol: f64::NAN,
            ..settings(Method::Dop853, Backend::OdeSolvers)
        },
    ];
    for s in bad {
        let mut sys = Oscillator {
            omega: 1.0,
            calls: 0,
        };
        let (rows, r) = collect(&mut sys, Vector2::new(1.0, 0.0), &schedule, &s);
        assert!(
            matches!(r, Err(IntegrateError::InvalidSettings { .. })),
            "{s:?}"
        );
        assert!(rows.is_empty());
    }
    // A non-finite initial state is never reported.
    let mut sys = Oscillator {
        omega: 1.0,
        calls: 0,
    };
    let (rows, r) = collect(
        &mut sys,
        Vector2::new(f64::NAN, 0.0),
        &schedule,
        &Settings::default(),
    );
    assert!(matches!(r, Err(IntegrateError::NonFinite { t: 0.0 })));
    assert!(rows.is_empty());
}
