//! What an absent effect costs: the torque-free benchmark scene run through eulerdyn's general path
//! (`simulate::run`, the body form with its applied-moment type parameter) against a hand-written torque-free
//! right-hand side stepped by the same integrator, in the same process. Prints ns per step and the ratio.
//!
//! Run: `cargo bench --bench effects_cost`

use std::convert::Infallible;
use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

use eulerdyn::integrate::{self, OdeSystem, Schedule, Settings};
use eulerdyn::motion::free::{State, quaternion_rate};
use eulerdyn::scene::{self, Overrides};
use eulerdyn::simulate;

/// Euler's equations for principal moments (I1, I2, I3), written out by hand, and q̇ = ½ q ⊗ ω.
struct HandWritten {
    moments: [f64; 3],
}

impl OdeSystem<7> for HandWritten {
    #[inline]
    fn rhs(&mut self, _t: f64, y: &State) -> State {
        let [i1, i2, i3] = self.moments;
        let w = nalgebra::Vector3::new(y[0], y[1], y[2]);
        let dq = quaternion_rate(&[y[3], y[4], y[5], y[6]], &w);
        State::from([
            (i2 - i3) / i1 * w[1] * w[2],
            (i3 - i1) / i2 * w[2] * w[0],
            (i1 - i2) / i3 * w[0] * w[1],
            dq[0],
            dq[1],
            dq[2],
            dq[3],
        ])
    }

    fn project(&self, y: &mut State) {
        let n = (y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6]).sqrt();
        for k in 3..7 {
            y[k] /= n;
        }
    }
}

const SCENE: &str = "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 0.0, 2.0]\n[solver]\nmethod = \"rk4\"\ndt = 1e-3\nt_end = 100.0\n[output]\nevery = 100.0\n";

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let scene = scene::parse(Path::new("bench.toml"), SCENE, &Overrides::default()).unwrap();
    let steps = 100_000.0;
    let repeats = 15;
    let mut general = Vec::new();
    let mut hand = Vec::new();
    for _ in 0..repeats {
        let start = Instant::now();
        let report = simulate::run(&scene, |s| {
            black_box(s);
            Ok::<(), Infallible>(())
        })
        .unwrap();
        general.push(start.elapsed().as_secs_f64() * 1e9 / report.stats.steps as f64);

        let mut system = HandWritten {
            moments: [1.0, 2.0, 3.0],
        };
        let y0 = State::from([0.3, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0]);
        let schedule = Schedule::new(100.0, 100.0).unwrap();
        let settings = Settings {
            method: integrate::Method::Rk4,
            dt: 1e-3,
            ..Settings::default()
        };
        let start = Instant::now();
        let stats = integrate::integrate(&mut system, y0, &schedule, &settings, |_, y| {
            black_box(y);
            Ok::<(), Infallible>(())
        })
        .unwrap();
        hand.push(start.elapsed().as_secs_f64() * 1e9 / stats.steps as f64);
        assert_eq!(stats.steps as f64, steps);
    }
    let (g, h) = (median(general), median(hand));
    println!("torque-free benchmark body, rk4 dt = 1e-3, 1e5 steps, median of {repeats}:");
    println!("  general path (simulate::run, body form)   {g:8.1} ns/step");
    println!("  hand-written torque-free right-hand side  {h:8.1} ns/step");
    println!(
        "  ratio general / hand-written              {:8.3}  (aim <= 1.1)",
        g / h
    );
}
