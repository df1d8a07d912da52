//! What `eulerdyn balance` prints: the report as text, and the same figures as JSON (`--json`).

use nalgebra::{Matrix2, Vector2};
use serde_json::{Value, json};

use super::format::{angle_text, correction_line, sig};
use super::influence::{Phasor, polar_deg};
use super::iso::{self, Assessment, TolerancePlanes, Verdict};
use super::{Influence, Report, Source};

const PLANES: [&str; 2] = ["A", "B"];

/// "12.34 at 56.7 deg" (a phase that rounds to 360.0 is shown as 0.0).
fn polar_text(v: Phasor) -> String {
    let (amp, phase) = polar_deg(v);
    format!("{} at {} deg", sig(amp, 4), angle_text(phase))
}

/// A residual `v` as [`polar_text`], or "0 (round-off)" when it is below 1e-9 of `scale` (what it was before).
fn residual_text(v: Phasor, scale: f64) -> String {
    if v.norm() <= ROUND_OFF * scale {
        "0 (round-off)".into()
    } else {
        polar_text(v)
    }
}

/// A residual below this fraction of its value before balancing is round-off, and printed as such.
const ROUND_OFF: f64 = 1e-9;

/// A phasor as JSON: amplitude, phase (deg, in [0, 360)), real and imaginary parts.
fn polar_json(v: Phasor) -> Value {
    let (amp, phase) = polar_deg(v);
    json!({ "amp": amp, "phase_deg": phase, "re": v.re, "im": v.im })
}

fn vector_json(v: &Vector2<Phasor>) -> Value {
    Value::Array(v.iter().map(|&x| polar_json(x)).collect())
}

fn matrix_json(m: &Matrix2<Phasor>) -> Value {
    json!([
        [polar_json(m[(0, 0)]), polar_json(m[(0, 1)])],
        [polar_json(m[(1, 0)]), polar_json(m[(1, 1)])]
    ])
}

impl Report {
    /// The report as text: the corrections (as `balance` always printed them, or the measured ones with their
    /// coefficients), the unbalance per plane, and the grade.
    pub fn text(&self) -> String {
        let mut text = match &self.influence {
            None => self.balance.report(),
            Some(found) => self.influence_text(found),
        };
        text += "unbalance per plane (U = m·r, g·mm, at the heavy spot's angle):\n";
        for (j, name) in PLANES.iter().enumerate() {
            let [before, after] = [self.unbalance[0][j], self.unbalance[1][j]];
            text += &format!(
                "  plane {name}: {} before, {} after\n",
                polar_text(before),
                residual_text(after, before.norm())
            );
        }
        for warning in &self.warnings {
            text += &format!("warning: {warning}\n");
        }
        if let Some(grade) = &self.grade {
            text += &grade_text(grade, !self.warnings.is_empty());
        }
        text
    }

    /// The coefficients, the condition number, the corrections in g and the readings before and after.
    fn influence_text(&self, found: &Influence) -> String {
        let r = &self.balance.reference_b;
        let mut text = format!(
            "angles about the axis from {} across it: ({:.6}, {:.6}, {:.6}) in body axes\n",
            self.balance.reference_name, r.x, r.y, r.z
        );
        text += &match found.source {
            Source::Measured => format!(
                "influence coefficients fitted to {} ({} runs, {} with trial masses{}), reading per g at R = {} m:\n",
                found.table.display(),
                found.runs,
                found.trial_runs,
                if found.runs > 3 {
                    "; least squares"
                } else {
                    ""
                },
                self.planes.radius
            ),
            Source::Model => format!(
                "one-shot balancing: {} has only the initial run; influence coefficients predicted by the scene's \
                 rigid-rotor model (force on the bearing, N per g at R = {} m, at the runs' speed):\n",
                found.table.display(),
                self.planes.radius,
            ),
        };
        text += &self.runs_text();
        text += "              plane A                  plane B\n";
        for (i, name) in PLANES.iter().enumerate() {
            let [a, b] = [found.alpha[(i, 0)], found.alpha[(i, 1)]].map(polar_text);
            text += &format!("  sensor {name}    {a:<24} {b}\n");
        }
        text += &format!(
            "condition number of the coefficient matrix: {}\n",
            sig(found.condition, 4)
        );
        if found.ill_conditioned() {
            text += &format!(
                "warning: the condition number is above {}: the two planes act nearly alike on the sensors, and \
                 errors in the readings are magnified that much in the corrections; place the planes farther apart\n",
                super::CONDITION_WARNING
            );
        }
        for (name, c) in PLANES.iter().zip(&self.balance.corrections) {
            text += &correction_line(name, c.z, (c.mass, c.angle_deg), &c.at_b);
        }
        let v0 = &found.measured_initial;
        text += &format!(
            "initial readings: A {}, B {}\n",
            polar_text(v0[0]),
            polar_text(v0[1])
        );
        let scale = v0.norm();
        text += &format!(
            "predicted residual readings (the initial run with the corrections): A {}, B {}\n",
            residual_text(found.residual[0], scale),
            residual_text(found.residual[1], scale)
        );
        text
    }

    /// "measured runs at 600.000 rpm (62.8319 rad/s, --rpm); readings: bearing forces in N" (or "the scene's
    /// rate"; "vibration, any unit").
    fn runs_text(&self) -> String {
        let readings = match self.readings {
            super::Readings::Force => "bearing forces in N (compared with the rigid-rotor model)",
            super::Readings::Other => {
                "vibration in any unit (--readings other: not compared with the model)"
            }
        };
        match self.runs_speed {
            Some((omega, from_rpm)) => format!(
                "measured runs at {} rpm ({} rad/s, {}); readings: {readings}\n",
                sig(omega * 30.0 / std::f64::consts::PI, 6),
                sig(omega, 6),
                if from_rpm {
                    "--rpm"
                } else {
                    "the scene's rate"
                }
            ),
            None => format!(
                "measured runs at an unknown speed (no --rpm, the scene at rest); readings: {readings}\n"
            ),
        }
    }

    /// Every figure of the text, as JSON.
    pub fn json(&self) -> Value {
        let b = &self.balance;
        let corrections: Vec<Value> = b
            .corrections
            .iter()
            .zip(PLANES)
            .map(|(c, name)| {
                json!({ "plane": name, "z": c.z, "mass_g": c.mass * 1e3,
                        "angle_deg": c.angle_deg, "at_b": [c.at_b.x, c.at_b.y, c.at_b.z] })
            })
            .collect();
        let unbalance =
            |k: usize| Value::Array(self.unbalance[k].iter().map(|&u| polar_json(u)).collect());
        json!({
            "scene_file": self.scene_file.display().to_string(),
            "mode": match &self.influence {
                None => "model",
                Some(f) if f.source == Source::Measured => "measured",
                Some(_) => "one_shot",
            },
            "planes": { "a": self.planes.a, "b": self.planes.b, "radius": self.planes.radius },
            "reference_name": b.reference_name,
            "reference_b": [b.reference_b.x, b.reference_b.y, b.reference_b.z],
            "corrections": corrections,
            "rate": b.rate,
            "largest_reaction_before": b.largest_reaction[0],
            "largest_reaction_after": b.largest_reaction[1],
            "unbalance_gmm": { "before": unbalance(0), "after": unbalance(1) },
            "grade": self.grade.as_ref().map(grade_json),
            "influence": self.influence.as_ref().map(influence_json),
            "runs_rpm": self.runs_speed.map(|(w, _)| w * 30.0 / std::f64::consts::PI),
            "runs_speed_from": self.runs_speed.map(|(_, from_rpm)| if from_rpm { "rpm" } else { "scene" }),
            "readings": self.readings.name(),
            "warnings": self.warnings,
        })
    }
}

/// The influence-coefficient figures as JSON.
fn influence_json(found: &Influence) -> Value {
    json!({
        "table": found.table.display().to_string(),
        "source": match found.source { Source::Measured => "measured", Source::Model => "model" },
        "runs": found.runs,
        "trial_runs": found.trial_runs,
        "coefficients": matrix_json(&found.alpha),
        "condition_number": found.condition,
        "condition_warning": found.ill_conditioned(),
        "initial_readings": vector_json(&found.measured_initial),
        "fitted_initial_readings": vector_json(&found.fitted_initial),
        "predicted_residual_readings": vector_json(&found.residual),
    })
}

/// "G 6.3" of a grade, with the finest standard grade it meets.
fn grade_name(g: f64) -> String {
    match iso::standard_grade_met(g) {
        Some(standard) => format!("G {} (standard grade G {standard})", sig(g, 3)),
        None => format!("G {} (coarser than G 4000)", sig(g, 3)),
    }
}

/// The grade block of the text; `warned`: a warning about the input stands (the verdicts read `unverified`).
fn grade_text(grade: &Assessment, warned: bool) -> String {
    let source = if grade.from_service_rpm {
        "--service-rpm"
    } else {
        "the scene's rate"
    };
    let mut text = format!(
        "balance grade (ISO 21940-11) at the service speed {} rpm ({} rad/s, {source}), rotor mass {} kg, centre of mass at {} m along the axis:\n",
        sig(grade.omega * 30.0 / std::f64::consts::PI, 6),
        sig(grade.omega, 6),
        sig(grade.mass, 6),
        sig(grade.z_c, 4)
    );
    let [a, b] = grade.z;
    text += &match grade.planes {
        TolerancePlanes::Bearings => format!(
            "  tolerance planes: the bearings, A at {a} m and B at {b} m (the correction planes' unbalance converted \
             to them, same resultant and moment)\n"
        ),
        TolerancePlanes::Correction => {
            format!("  tolerance planes: the correction planes, A at {a} m and B at {b} m\n")
        }
    };
    let [before, after] = grade.unbalance;
    text += &format!(
        "  unbalance in the tolerance planes (g·mm): A {} before, {} after; B {} before, {} after\n",
        sig(before[0], 4),
        sig(after[0], 4),
        sig(before[1], 4),
        sig(after[1], 4)
    );
    text += &format!(
        "  shares of U_per: plane A {:.1} %, plane B {:.1} % (lever rule about the centre of mass, kept within 30-70 %)\n",
        grade.shares[0] * 100.0,
        grade.shares[1] * 100.0
    );
    if let Some(t) = &grade.target {
        text += &format!(
            "  G {}: U_per = 1000·G·m/Ω = {} g·mm; plane A {} g·mm, plane B {} g·mm\n",
            t.grade,
            sig(t.u_per, 4),
            sig(t.u_per_planes[0], 4),
            sig(t.u_per_planes[1], 4)
        );
    }
    for (k, when) in ["before", "after"].iter().enumerate() {
        let verdict = grade.target.as_ref().map_or(String::new(), |t| {
            let why = match (warned, grade.from_service_rpm) {
                (true, _) => " (see the warnings)",
                (false, false) => {
                    " at the scene's rate (--service-rpm N: at the rotor's maximum service speed)"
                }
                (false, true) => "",
            };
            format!(": {} against G {}{why}", t.verdict[k].word(), t.grade)
        });
        let met = if k == 1 && grade.met[1] <= ROUND_OFF * grade.met[0] {
            "every grade (the residual is round-off)".to_string()
        } else {
            grade_name(grade.met[k])
        };
        text += &format!("  {when}: meets {met}{verdict}\n");
    }
    text
}

/// The grade figures as JSON.
fn grade_json(grade: &Assessment) -> Value {
    json!({
        "omega": grade.omega,
        "rpm": grade.omega * 30.0 / std::f64::consts::PI,
        "speed_from": if grade.from_service_rpm { "service_rpm" } else { "scene" },
        "mass_kg": grade.mass,
        "z_c": grade.z_c,
        "tolerance_planes": grade.planes.name(),
        "tolerance_planes_z": grade.z,
        "tolerance_unbalance_gmm": { "before": grade.unbalance[0], "after": grade.unbalance[1] },
        "shares": grade.shares,
        "met_before": grade.met[0],
        "met_after": grade.met[1],
        "standard_before": iso::standard_grade_met(grade.met[0]),
        "standard_after": iso::standard_grade_met(grade.met[1]),
        "target": grade.target.as_ref().map(|t| json!({
            "grade": t.grade,
            "u_per_gmm": t.u_per,
            "u_per_planes_gmm": t.u_per_planes,
            "pass_before": t.verdict[0] == Verdict::Pass,
            "pass": t.verdict[1] == Verdict::Pass,
            "verdict_before": t.verdict[0].word(),
            "verdict": t.verdict[1].word(),
        })),
    })
}
