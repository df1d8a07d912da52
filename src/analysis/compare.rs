//! `eulerdyn compare`: the scene run in both forms of Euler's equation, side by side, and against the closed form
//! where one applies. The two runs stream in lockstep (the space form on a second thread), so memory does not grow
//! with the number of rows.

use std::ops::ControlFlow;
use std::sync::mpsc;
use std::thread;

use nalgebra::UnitQuaternion;

use crate::frames::Form;
use crate::integrate::IntegrateError;
use crate::method::Method;
use crate::sample::Sample;
use crate::scene::Exact;
use crate::scene::Scene;
use crate::simulate::{self, RunError};

/// The largest difference of one quantity over the rows: absolute, with the largest magnitude seen, so that the
/// relative difference is `abs / scale`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Largest {
    /// The largest absolute difference (the quantity's unit).
    pub abs: f64,
    /// The largest magnitude of the quantity seen.
    pub scale: f64,
}

impl Largest {
    fn add(&mut self, diff: f64, magnitude: f64) {
        self.abs = self.abs.max(diff);
        self.scale = self.scale.max(magnitude);
    }

    /// The difference relative to the largest magnitude (absolute when the quantity is zero throughout).
    pub fn relative(&self) -> f64 {
        if self.scale > 0.0 {
            self.abs / self.scale
        } else {
            self.abs
        }
    }
}

/// Differences between two sources, per quantity.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Differences {
    /// |Δω_b| (rad/s).
    pub omega: Largest,
    /// |ΔH_s| (kg·m²/s).
    pub h_s: Largest,
    /// Angle of the rotation between the two attitudes (rad; absolute).
    pub attitude: Largest,
    /// |ΔT| (J).
    pub energy: Largest,
    /// Δ|H| (kg·m²/s).
    pub h_norm: Largest,
    /// |ΔM_s| (N·m).
    pub moment: Largest,
}

/// Angle of the rotation taking attitude a to b (rad): 2·atan2(|v|, |w|) of q = a⁻¹b, accurate for tiny angles
/// (unlike 2·acos w) and insensitive to the sign of q.
pub fn attitude_angle(a: &UnitQuaternion<f64>, b: &UnitQuaternion<f64>) -> f64 {
    let q = a.rotation_to(b);
    2.0 * q.imag().norm().atan2(q.scalar().abs())
}

impl Differences {
    fn add_samples(&mut self, a: &Sample, b: &Sample) {
        self.omega
            .add((a.omega_b - b.omega_b).norm(), a.omega_b.norm());
        self.h_s.add((a.h_o_s - b.h_o_s).norm(), a.h_o_s.norm());
        self.attitude.add(attitude_angle(&a.q, &b.q), 0.0);
        self.energy.add((a.energy - b.energy).abs(), a.energy.abs());
        self.h_norm
            .add((a.h_o_s.norm() - b.h_o_s.norm()).abs(), a.h_o_s.norm());
        self.moment.add((a.m_o_s - b.m_o_s).norm(), a.m_o_s.norm());
    }

    fn add_exact(&mut self, s: &Sample, e: &Exact) {
        if let Some(omega_b) = e.omega_b {
            self.omega
                .add((*s.omega_b - omega_b).norm(), omega_b.norm());
        }
        if let Some(q) = e.q {
            self.attitude.add(attitude_angle(&s.q, &q), 0.0);
        }
        if let Some(h_s) = e.h_s {
            self.h_s.add((*s.h_o_s - h_s).norm(), h_s.norm());
            self.h_norm
                .add((s.h_o_s.norm() - h_s.norm()).abs(), h_s.norm());
        }
        if let Some(energy) = e.energy {
            self.energy.add((s.energy - energy).abs(), energy.abs());
        }
        if let Some(h_int) = s.h_o_s_integrated {
            self.h_s.add((h_int - s.h_o_s).norm(), s.h_o_s.norm());
        }
    }

    /// The quantities that were compared, as (name, relative difference).
    pub fn rows(&self) -> Vec<(&'static str, f64)> {
        [
            ("omega", self.omega),
            ("H_s", self.h_s),
            ("attitude angle (rad)", self.attitude),
            ("energy", self.energy),
            ("|H|", self.h_norm),
            ("M", self.moment),
        ]
        .into_iter()
        .filter(|(_, d)| *d != Largest::default())
        .map(|(n, d)| (n, d.relative()))
        .collect()
    }

    /// The largest relative difference of any quantity.
    pub fn worst(&self) -> f64 {
        self.rows().iter().map(|r| r.1).fold(0.0, f64::max)
    }
}

/// One quantity of [`Comparison::table`]: relative differences (the attitude's absolute, in rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ComparisonRow {
    /// The quantity's name, e.g. `H_s` or `attitude angle (rad)`.
    pub quantity: &'static str,
    /// Body form against space form.
    pub body_vs_space: f64,
    /// Body form against the closed form, when it gives this quantity.
    pub body_vs_exact: Option<f64>,
    /// Space form against the closed form, when it gives this quantity.
    pub space_vs_exact: Option<f64>,
}

/// The outcome of `compare`.
pub struct Comparison {
    /// The body form against the space form, row by row.
    pub body_vs_space: Differences,
    /// Against the closed form, for the body and the space form, when one applies.
    pub exact: Option<(&'static str, Differences, Differences)>,
    /// The largest difference allowed (`compare_tolerance`).
    pub tolerance: f64,
    /// Rows compared.
    pub rows: u64,
    /// What the comparison means for the scene's method, when that needs saying (`exact`, split2/split4).
    pub note: Option<String>,
}

impl Comparison {
    /// Whether every difference is within the scene's tolerance.
    pub fn passes(&self) -> bool {
        let exact_worst = self
            .exact
            .as_ref()
            .map_or(0.0, |(_, b, s)| b.worst().max(s.worst()));
        self.body_vs_space.worst().max(exact_worst) <= self.tolerance
    }

    /// The relative differences per quantity (those compared between the forms), with the closed form's where it
    /// gives that quantity.
    pub fn table(&self) -> Vec<ComparisonRow> {
        let exact_rows = self.exact.as_ref().map(|(_, b, s)| (b.rows(), s.rows()));
        let lookup =
            |rows: &[(&str, f64)], name: &str| rows.iter().find(|r| r.0 == name).map(|r| r.1);
        self.body_vs_space
            .rows()
            .into_iter()
            .map(|(quantity, body_vs_space)| ComparisonRow {
                quantity,
                body_vs_space,
                body_vs_exact: exact_rows.as_ref().and_then(|(b, _)| lookup(b, quantity)),
                space_vs_exact: exact_rows.as_ref().and_then(|(_, s)| lookup(s, quantity)),
            })
            .collect()
    }

    /// A table for people: one line per quantity.
    pub fn report(&self) -> String {
        let mut out = String::new();
        out.push_str(&format!(
            "largest differences over {} rows (relative to the largest magnitude; attitude in rad)\n",
            self.rows
        ));
        match &self.exact {
            Some((name, _, _)) => out.push_str(&format!("closed form: {name}\n")),
            None => out.push_str("closed form: none applies to this scene\n"),
        }
        if let Some(note) = &self.note {
            out.push_str(note);
            out.push('\n');
        }
        out.push_str(&format!(
            "{:<22} {:>14} {:>14} {:>14}\n",
            "quantity", "body vs space", "body vs exact", "space vs exact"
        ));
        let cell = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.3e}"));
        for row in self.table() {
            out.push_str(&format!(
                "{:<22} {:>14.3e} {:>14} {:>14}\n",
                row.quantity,
                row.body_vs_space,
                cell(row.body_vs_exact),
                cell(row.space_vs_exact)
            ));
        }
        out.push_str(&format!(
            "tolerance {:e}: {}\n",
            self.tolerance,
            if self.passes() { "within" } else { "EXCEEDED" }
        ));
        out
    }
}

/// What the comparison means for the scene's method, where it is not the obvious: for `exact` both forms are the
/// closed form, read two ways; for the splitting methods both forms are the same map.
fn method_note(scene: &Scene) -> Option<String> {
    if !scene.motion.is_free() {
        return None;
    }
    match scene.solver.method {
        Method::Exact => Some(
            "method exact: both forms are the closed form — body: omega from the Jacobi functions; space: omega \
             from the closed-form attitude and the constant H_s — so \"body vs space\" checks the attitude \
             against omega, and \"vs exact\" the rows against the oracle"
                .into(),
        ),
        Method::Split2 | Method::Split4 => Some(format!(
            "method {}: the body form turns H_p, the space form keeps H_s; the two are the same map in exact \
             arithmetic, so \"body vs space\" is round-off (amplified where the motion is unstable, as near \
             the separatrix)",
            scene.solver.method.name()
        )),
        _ => None,
    }
}

/// The two runs of `compare` could not exchange a row: the other run stopped early (its own error says why).
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("the other form's run stopped early")]
pub struct HandOver;

/// Runs the scene in both frames (in lockstep) and against its closed form.
pub fn compare(scene: &Scene) -> Result<Comparison, RunError<HandOver>> {
    compare_until(scene, || ControlFlow::Continue(()))
}

/// [`compare`], with `poll` called at every row of the body-form run: once it breaks, both runs stop and the
/// result is `Err(RunError::Sink(HandOver))` (the Python module's Ctrl-C).
pub fn compare_until(
    scene: &Scene,
    mut poll: impl FnMut() -> ControlFlow<()>,
) -> Result<Comparison, RunError<HandOver>> {
    let mut body_scene = scene.clone();
    body_scene.solver.form = Form::Body;
    let mut space_scene = scene.clone();
    space_scene.solver.form = Form::Space;
    let oracle = scene.facts().oracle();
    let (sender, receiver) = mpsc::sync_channel::<Sample>(1024);
    let space_run = thread::spawn(move || {
        simulate::run(&space_scene, |s| sender.send(*s).map_err(|_| HandOver))
    });
    let mut body_vs_space = Differences::default();
    let mut body_vs_exact = Differences::default();
    let mut space_vs_exact = Differences::default();
    let mut rows = 0;
    let body_result = simulate::run(&body_scene, |b: &Sample| {
        if poll().is_break() {
            return Err(HandOver);
        }
        let Ok(s) = receiver.recv() else {
            // The space run stopped early; its own result says why.
            return Err(HandOver);
        };
        rows += 1;
        body_vs_space.add_samples(b, &s);
        if let Some(oracle) = &oracle {
            let exact = oracle.at(b.t);
            body_vs_exact.add_exact(b, &exact);
            space_vs_exact.add_exact(&s, &exact);
        }
        Ok(())
    });
    drop(receiver);
    let space_result = space_run.join().unwrap_or_else(|_| {
        Err(RunError::Integrate(IntegrateError::Backend {
            t: f64::NAN,
            message: "the space-form run panicked".into(),
        }))
    });
    // An integration failure (or divergence) in either run is the cause; a failed hand-over is only its
    // consequence.
    match (body_result, space_result) {
        (Ok(_), Ok(_)) => {}
        (Err(e @ (RunError::Integrate(_) | RunError::Diverged(_))), _)
        | (_, Err(e @ (RunError::Integrate(_) | RunError::Diverged(_)))) => return Err(e),
        (Err(e), _) | (_, Err(e)) => return Err(e),
    }
    Ok(Comparison {
        body_vs_space,
        exact: oracle.map(|o| (o.name(), body_vs_exact, space_vs_exact)),
        tolerance: scene.compare_tolerance,
        rows,
        note: method_note(scene),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn free_scene() -> Scene {
        crate::scene::SceneSpec::new(
            crate::scene::BodySpec::principal(1.0, [1.0, 2.0, 3.0]),
            2.0,
            0.5,
        )
        .with_omega([0.3, 0.0, 2.0])
        .build()
        .unwrap()
    }

    #[test]
    fn the_table_is_the_report_s_rows() {
        let c = compare(&free_scene()).unwrap();
        let table = c.table();
        assert_eq!(table.len(), c.body_vs_space.rows().len());
        // The torque-free body has a closed form for every quantity compared.
        assert!(
            table
                .iter()
                .all(|r| r.body_vs_exact.is_some() && r.space_vs_exact.is_some())
        );
        for r in &table {
            let line = c
                .report()
                .lines()
                .find(|l| l.starts_with(r.quantity))
                .map(str::to_string);
            assert!(line.is_some_and(|l| l.contains(&format!("{:.3e}", r.body_vs_space))));
        }
    }

    #[test]
    fn a_poll_that_breaks_stops_both_runs() {
        let mut polls = 0;
        let result = compare_until(&free_scene(), || {
            polls += 1;
            if polls > 2 {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        });
        assert!(matches!(result, Err(RunError::Sink(HandOver))));
        assert_eq!(polls, 3);
    }
}
