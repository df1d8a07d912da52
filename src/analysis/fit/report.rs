//! The fit in words: what was fitted to what, a table of the parameters (start, estimate, standard error, 95 %
//! interval), the correlations, the residuals per channel, χ²/dof, the solver's end and the notes.

use super::solve::Fit;

/// The fit as text for people.
pub fn text(fit: &Fit) -> String {
    let mut out = format!(
        "fit of {} to {}: {} rows ({} with a gyro reading, {} with an attitude); estimated: {}\n",
        fit.scene,
        fit.file,
        fit.rows,
        fit.gyro_rows,
        fit.attitude_rows,
        fit.estimate.join(", ")
    );
    for w in &fit.warnings {
        out.push_str(&format!("warning: {w}\n"));
    }
    out.push_str(&format!(
        "{:<10} {:>14} {:>14} {:>11}   {:<31}\n",
        "parameter", "start", "estimate", "std error", "95 % interval"
    ));
    for p in &fit.parameters {
        out.push_str(&format!(
            "{:<10} {:>14.7e} {:>14.7e} {:>11.3e}   [{:.7e}, {:.7e}]\n",
            p.name, p.start, p.estimate, p.std_error, p.low, p.high
        ));
    }
    out.push_str("correlation:\n");
    out.push_str(&format!("{:<10}", ""));
    for name in &fit.correlation.names {
        out.push_str(&format!(" {name:>8}"));
    }
    out.push('\n');
    for (name, row) in fit.correlation.names.iter().zip(&fit.correlation.matrix) {
        out.push_str(&format!("{name:<10}"));
        for v in row {
            out.push_str(&format!(" {v:>8.3}"));
        }
        out.push('\n');
    }
    for (channel, rms, sigma, unit) in [
        ("gyro", fit.rms.omega, fit.sigma.omega, "rad/s"),
        ("attitude", fit.rms.attitude, fit.sigma.attitude, "rad"),
    ] {
        if let (Some(rms), Some(sigma)) = (rms, sigma) {
            out.push_str(&format!(
                "{channel} residuals: RMS {rms:.3e} {unit} (sigma {sigma:.3e} {unit})\n"
            ));
        }
    }
    out.push_str(&format!(
        "chi2/dof {:.4} ({} degrees of freedom); {} after {} iterations ({})\n",
        fit.chi2_dof,
        fit.dof,
        if fit.converged {
            "converged"
        } else {
            "NOT converged"
        },
        fit.iterations,
        fit.termination
    ));
    for note in &fit.notes {
        out.push_str(&format!("note: {note}\n"));
    }
    if let Some(why) = &fit.unphysical {
        out.push_str(&format!("{why}\n"));
    }
    out
}
