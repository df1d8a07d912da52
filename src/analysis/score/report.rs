//! The score in words: a table per trajectory (metric, largest, at t, final, threshold, verdict) and the suite's
//! report card (scene × metric, the largest value with its verdict).

use super::metrics::{
    ATTITUDE_MAX, ENERGY_MAX, EVENT_TIME_MAX, H_DIRECTION_MAX, H_NORM_MAX, OMEGA_MAX,
};
use super::{REFEREE_MARGIN, Score};

/// The verdict of a metric in a table.
fn verdict(passes: bool) -> &'static str {
    if passes { "pass" } else { "FAIL" }
}

/// The score as a table for people.
pub fn text(score: &Score) -> String {
    let mut out = format!(
        "score of {} against scene \"{}\": {} rows, t = 0 … {} s\nreference: {}\n",
        score.file, score.scene, score.rows, score.t_last, score.reference
    );
    match (&score.reference_error, score.referee_adequate) {
        (None, _) => out.push_str("referee error: round-off (closed form)\n"),
        (Some(e), adequate) => out.push_str(&format!(
            "referee error: attitude ≤ {:.1e} rad, omega ≤ {:.1e} (relative): {}\n",
            e.attitude,
            e.omega,
            if adequate {
                format!("at least {REFEREE_MARGIN}× below every error reported")
            } else {
                format!("NOT {REFEREE_MARGIN}× below the errors reported: the smallest errors are the referee's own")
            }
        )),
    }
    for line in (score.warnings.iter().map(|w| format!("warning: {w}")))
        .chain(score.hints.iter().map(|h| format!("hint: {h}")))
        .chain(score.notes.iter().cloned())
        .chain(score.diagnosis.iter().map(|d| d.line()))
    {
        out.push_str(&line);
        out.push('\n');
    }
    out.push_str(&format!(
        "{:<36} {:>10} {:>9} {:>10} {:>10}  verdict\n",
        "metric", "largest", "at t (s)", "final", "threshold"
    ));
    for m in &score.metrics {
        out.push_str(&format!(
            "{:<36} {:>10.3e} {:>9.3} {:>10.3e} {:>10.1e}  {}{}\n",
            m.name,
            m.largest,
            m.at,
            m.last,
            m.threshold,
            verdict(m.passes),
            m.note
                .as_ref()
                .map(|n| format!(" ({n})"))
                .unwrap_or_default()
        ));
        for (k, o) in m.occurrences.iter().flatten().enumerate() {
            let time = |t: Option<f64>| t.map_or("none".to_string(), |t| format!("{t:.6} s"));
            out.push_str(&format!(
                "  occurrence {}: reference {}, theirs {}{}\n",
                k + 1,
                time(o.reference_t),
                time(o.their_t),
                o.error
                    .map(|e| format!(", error {e:.3e} s"))
                    .unwrap_or_default()
            ));
        }
    }
    let failed = score.metrics.iter().filter(|m| !m.passes).count();
    let over = format!(
        "{failed} of {} metrics over their thresholds",
        score.metrics.len()
    );
    out.push_str(&match (score.ends_early, failed) {
        (None, 0) => "verdict: pass (every metric within its threshold)\n".to_string(),
        (None, _) => format!("verdict: FAIL ({over})\n"),
        (Some(t), _) => {
            format!(
                "verdict: FAIL (their rows end at t = {t:.3} s, before the scene's end; {over})\n"
            )
        }
    });
    out
}

/// The columns of the report card: key and heading.
const CARD: [(&str, &str); 6] = [
    ("attitude", "attitude rad"),
    ("omega", "omega rel"),
    ("energy", "energy rel"),
    ("h_norm", "|H| rel"),
    ("h_direction", "H dir rad"),
    ("event", "events s"),
];

/// The report card of an engine on the suite: one row per scene, the largest value of each metric with `*` where
/// it is over its threshold (events: the worst event), `-` where it was not measured.
pub fn card(engine: &str, scores: &[Score]) -> String {
    let mut out =
        format!("report card: {engine} (largest error over the scene; * over the threshold)\n");
    out.push_str(&format!("{:<24}", "scene"));
    for (_, heading) in CARD {
        out.push_str(&format!(" {heading:>13}"));
    }
    out.push_str("  verdict\n");
    for s in scores {
        out.push_str(&format!("{:<24}", s.scene));
        if s.missing {
            out.push_str(&format!("  missing: no {} (not scored)\n", s.file));
            continue;
        }
        for (key, _) in CARD {
            let worst = (s.metrics.iter())
                .filter(|m| m.key == key || (key == "event" && m.key.starts_with("event:")))
                .max_by(|a, b| a.largest.total_cmp(&b.largest));
            let cell = worst.map_or("-".to_string(), |m| {
                format!("{:.2e}{}", m.largest, if m.passes { " " } else { "*" })
            });
            out.push_str(&format!(" {cell:>13}"));
        }
        out.push_str(&format!("  {}\n", verdict(s.passes())));
        if let Some(t) = s.ends_early {
            out.push_str(&format!(
                "{:<24}their rows end at t = {t:.3} s, before the scene's t_end (the rest not scored)\n",
                ""
            ));
        }
        if let Some(d) = &s.diagnosis {
            out.push_str(&format!("{:<24}{}\n", "", d.line()));
        }
    }
    out.push_str(&format!(
        "thresholds: attitude {ATTITUDE_MAX:e} rad, omega {OMEGA_MAX:e}, energy {ENERGY_MAX:e}, |H| {H_NORM_MAX:e}, \
         H direction {H_DIRECTION_MAX:e} rad, events {EVENT_TIME_MAX:.4} s (one frame at 60 Hz)\n"
    ));
    out
}
