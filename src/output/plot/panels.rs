//! What each panel draws: its title, axis label and curves, with legend labels in the symbols of the notes (ω_b,x,
//! H_s,z, |R_A|, T + V) rather than CSV column names. Body-axes components are solid lines and space-axes ones
//! dashed with open circles (likewise bearing A solid, bearing B dashed with markers), so that a curve drawn over
//! another with the same values leaves both visible, in the plot and in the legend.

use plotters::style::RGBColor;

use super::Panel;
use super::series::{RunSeries, SceneFacts};
use crate::scene::Invariant;
use crate::text::for_people;

/// The smallest drift drawn on the log scale; smaller values (an exact zero, typically) are drawn at it, and the
/// legend says so.
pub const DRIFT_FLOOR: f64 = 1e-17;

/// A mark drawn along a curve at regular intervals (and in its legend sample).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Marker {
    /// An open circle.
    Circle,
    /// An open square.
    Square,
}

/// A curve to draw: its legend label, colour, line style and points (x, y) in drawing order.
pub(crate) struct Curve {
    pub label: String,
    pub color: RGBColor,
    pub dashed: bool,
    /// Marks along the curve, so that it stays visible where another curve covers it.
    pub marker: Option<Marker>,
    pub points: Vec<(f64, f64)>,
}

/// What one panel shows.
pub(super) struct PanelPlot {
    pub(super) title: String,
    pub(super) y_label: String,
    pub(super) curves: Vec<Curve>,
    /// Log scale (the drift panel).
    pub(super) log: bool,
    /// Legend lines that are text only.
    pub(super) notes: Vec<String>,
    /// The located events of the quantities the panel draws.
    pub(super) events: Vec<EventMarks>,
}

/// The occurrences of one `[[event]]` on a panel that draws its quantity: a marker at each (t, value), with a
/// vertical line at t, in the event's colour; the event's name in the legend.
pub(super) struct EventMarks {
    pub(super) name: String,
    pub(super) color: RGBColor,
    pub(super) points: Vec<(f64, f64)>,
}

impl PanelPlot {
    fn linear(title: impl Into<String>, y_label: &str, curves: Vec<Curve>) -> Self {
        Self {
            title: title.into(),
            y_label: y_label.into(),
            curves,
            log: false,
            notes: Vec::new(),
            events: Vec::new(),
        }
    }
}

const RED: RGBColor = RGBColor(0xd6, 0x27, 0x28);
const GREEN: RGBColor = RGBColor(0x2c, 0xa0, 0x2c);
const BLUE: RGBColor = RGBColor(0x1f, 0x77, 0xb4);
const GREY: RGBColor = RGBColor(0x55, 0x55, 0x55);
const PURPLE: RGBColor = RGBColor(0x94, 0x67, 0xbd);
const ORANGE: RGBColor = RGBColor(0xff, 0x7f, 0x0e);
const BLACK: RGBColor = RGBColor(0, 0, 0);
const XYZ: [RGBColor; 3] = [RED, GREEN, BLUE];

/// A vector's three components as curves: columns `{prefix}_x` …, labels `{symbol},x` …, coloured x red, y green,
/// z blue; the second set of a panel is dashed with open circles.
fn components(run: &RunSeries, prefix: &str, symbol: &str, second: bool) -> Vec<Curve> {
    ["x", "y", "z"]
        .iter()
        .zip(XYZ)
        .map(|(axis, color)| Curve {
            label: format!("{symbol},{axis}"),
            color,
            dashed: second,
            marker: second.then_some(Marker::Circle),
            points: run.points(&format!("{prefix}_{axis}")),
        })
        .collect()
}

/// One solid curve of the CSV column `column`.
fn single(run: &RunSeries, column: &str, label: &str, color: RGBColor) -> Curve {
    Curve {
        label: label.into(),
        color,
        dashed: false,
        marker: None,
        points: run.points(column),
    }
}

/// What `panel` shows of `run`, with the marks of the events whose quantity it draws.
pub(super) fn panel_plot(run: &RunSeries, panel: Panel) -> PanelPlot {
    PanelPlot {
        events: event_marks(run, panel),
        ..curves_plot(run, panel)
    }
}

/// The colours of the events, by the order of their first occurrence in the run (the same on every panel); not
/// those of the curves.
const EVENT_COLORS: [RGBColor; 4] = [
    RGBColor(0x8c, 0x56, 0x4b),
    RGBColor(0xe3, 0x77, 0xc2),
    RGBColor(0x17, 0xbe, 0xcf),
    RGBColor(0xbc, 0xbd, 0x22),
];

/// Whether `panel` draws the quantity `when` of an event (a CSV column, or `|X|`): one of its curves is that column
/// or that norm. The drift panel draws changes, not the quantities, so it has no events.
fn draws(run: &RunSeries, panel: Panel, when: &str) -> bool {
    match (panel, when) {
        (Panel::Drift, _) => false,
        (Panel::HBody | Panel::HSpace, "|H|") => true,
        (Panel::Bearings, "|R_A|" | "|R_B|") | (Panel::Support, "|F_sup|") => true,
        (Panel::Energy, "potential" | "energy_total") => {
            run.has("potential") && run.has("energy_total")
        }
        _ => panel.columns().contains(&when),
    }
}

/// The events of `run` whose quantity `panel` draws, one [`EventMarks`] per event, in the order of the events'
/// first occurrences.
fn event_marks(run: &RunSeries, panel: Panel) -> Vec<EventMarks> {
    let mut names: Vec<&str> = Vec::new();
    let mut marks: Vec<EventMarks> = Vec::new();
    for row in &run.events {
        let k = match names.iter().position(|n| *n == row.event) {
            Some(k) => k,
            None => {
                names.push(&row.event);
                names.len() - 1
            }
        };
        if !row.when.as_deref().is_some_and(|w| draws(run, panel, w)) {
            continue;
        }
        match marks.iter_mut().find(|m| m.name == row.event) {
            Some(m) => m.points.push((row.t, row.value)),
            None => marks.push(EventMarks {
                name: row.event.clone(),
                color: EVENT_COLORS[k % EVENT_COLORS.len()],
                points: vec![(row.t, row.value)],
            }),
        }
    }
    marks
}

/// The curves `panel` shows of `run`.
fn curves_plot(run: &RunSeries, panel: Panel) -> PanelPlot {
    match panel {
        Panel::HBody => h_panel(run, "H_b", "body"),
        Panel::HSpace => h_panel(run, "H_s", "space"),
        Panel::Moment => body_and_space_panel(run, "Moment M about the moment center", "M", "M"),
        Panel::Omega => body_and_space_panel(run, "Angular velocity ω", "ω", "omega"),
        Panel::Energy => energy_panel(run),
        Panel::Drift => drift_panel(run),
        Panel::Bearings => bearings_panel(run, "b", "body"),
        Panel::BearingsSpace => bearings_panel(run, "s", "space"),
        Panel::Support => support_panel(run),
        Panel::WheelSpin | Panel::WheelMomentum | Panel::WheelTorque | Panel::WheelFriction => {
            wheels_panel(run, panel)
        }
        plain => plain_panel(run, plain),
    }
}

/// A panel of [`Panel::plain_curves`]: each column as it is, blue alone, else red, green and blue in order.
fn plain_panel(run: &RunSeries, panel: Panel) -> PanelPlot {
    let (title, axis, labels) = panel.plain_curves().unwrap_or((panel.name(), "", &[]));
    let colors: &[RGBColor] = if labels.len() == 1 {
        &[BLUE]
    } else {
        &[RED, GREEN, BLUE]
    };
    let curves = (panel.columns().iter().zip(labels).zip(colors))
        .map(|((column, label), color)| single(run, column, label, *color))
        .collect();
    PanelPlot::linear(title, axis, curves)
}

/// The wheels' spins Ω (rad/s), axial momenta J (a·ω + Ω) (N·m·s), friction torques, or their motor torques
/// applied (solid), commanded (dashed, circles) and their friction (dashed, squares): one colour per wheel in the
/// order of the run's columns.
fn wheels_panel(run: &RunSeries, panel: Panel) -> PanelPlot {
    const COLORS: [RGBColor; 4] = [RED, GREEN, BLUE, PURPLE];
    let mut curves = Vec::new();
    for (name, color) in run.wheel_names().iter().zip(COLORS.iter().cycle()) {
        let (suffix, symbol) = match panel {
            Panel::WheelSpin => ("spin", "Ω"),
            Panel::WheelMomentum => ("h", "h"),
            Panel::WheelFriction => ("friction", "τ_f"),
            _ => ("torque", "τ"),
        };
        curves.push(single(
            run,
            &format!("{name}_{suffix}"),
            &format!("{symbol} {name}"),
            *color,
        ));
        if panel != Panel::WheelTorque {
            continue;
        }
        let dashed = [
            ("torque_cmd", "τ_cmd", Marker::Circle),
            ("friction", "τ_f", Marker::Square),
        ];
        for (suffix, symbol, marker) in dashed {
            let column = format!("{name}_{suffix}");
            if run.has(&column) {
                curves.push(Curve {
                    dashed: true,
                    marker: Some(marker),
                    ..single(run, &column, &format!("{symbol} {name}"), *color)
                });
            }
        }
    }
    let (title, unit) = match panel {
        Panel::WheelSpin => ("Wheel spins relative to the body", "Ω (rad/s)"),
        Panel::WheelMomentum => ("Wheel axial momentum J (a·ω + Ω)", "h (N·m·s)"),
        Panel::WheelFriction => ("Wheel friction torques", "τ_f (N·m)"),
        _ if curves.len() > run.wheel_names().len() => ("Wheel torques: τ, τ_cmd, τ_f", "τ (N·m)"),
        _ => ("Wheel motor torques τ", "τ (N·m)"),
    };
    PanelPlot::linear(title, unit, curves)
}

/// The kinetic energy T; with the columns `potential` and `energy_total` (gravity scenes), also V and T + V.
fn energy_panel(run: &RunSeries) -> PanelPlot {
    let mut curves = vec![single(run, "energy", "T", PURPLE)];
    if run.has("potential") && run.has("energy_total") {
        curves.push(Curve {
            dashed: true,
            marker: Some(Marker::Square),
            ..single(run, "potential", "V", ORANGE)
        });
        curves.push(single(run, "energy_total", "T + V", BLACK));
        PanelPlot::linear(
            "Kinetic T, potential V and total T + V",
            "energy (J)",
            curves,
        )
    } else {
        PanelPlot::linear("Kinetic energy T", "energy (J)", curves)
    }
}

/// The magnitude of the vector with columns `{prefix}_x` … (read as a derived curve).
fn norm(run: &RunSeries, prefix: &str, label: &str, second: bool) -> Curve {
    Curve {
        label: label.into(),
        color: GREY,
        dashed: second,
        marker: second.then_some(Marker::Square),
        points: run
            .norms
            .iter()
            .find(|n| n.prefix == prefix)
            .map(|n| n.points.points())
            .unwrap_or_default(),
    }
}

/// The components of the bearings' forces on the body in `axes` (columns `R_A_{suffix}_x` …; A solid, B dashed with
/// circles), and their magnitudes (grey; |R_B| dashed with squares).
fn bearings_panel(run: &RunSeries, suffix: &str, axes: &str) -> PanelPlot {
    let (a, b) = (format!("R_A_{suffix}"), format!("R_B_{suffix}"));
    let curves = components(run, &a, "R_A", false)
        .into_iter()
        .chain(components(run, &b, "R_B", true))
        .chain([norm(run, &a, "|R_A|", false), norm(run, &b, "|R_B|", true)])
        .collect();
    PanelPlot::linear(
        format!("Bearing forces on the body, {axes} axes"),
        "R (N)",
        curves,
    )
}

/// The force the support applies to the body, F_sup = m a_C − Σ F_effects, in space axes, and its magnitude.
fn support_panel(run: &RunSeries) -> PanelPlot {
    let curves = components(run, "F_sup_s", "F_sup", false)
        .into_iter()
        .chain([norm(run, "F_sup_s", "|F_sup|", true)])
        .collect();
    PanelPlot::linear("Support force F_sup, space axes", "F_sup (N)", curves)
}

/// A change of H within this fraction of the run's momentum scale is round-off: H = I ω + Σ J Ω a is summed in
/// binary64 (unit round-off ε = 1.1e-16) at every row, and Runge–Kutta steps keep the linear invariant H_b of a
/// torque-free gyrostat to round-off (HNW I, §II.1: every RK method conserves linear invariants); 1e-12 ≈ 10⁴ ε
/// leaves room for round-off accumulated over 10⁴ rows.
pub const ROUND_OFF: f64 = 1e-12;

/// Draws flat the curves of `plot` when all of them stay within `tolerance` of each other's range but not within
/// 1e-9 of their magnitude (a quantity constant to round-off about zero, which auto-scaling would blow up into
/// noise): each at its mean, rounded to a multiple
/// of `tolerance`, its value in its legend label (`H_s,x = 0`); a note says so.
fn flatten_constant(mut plot: PanelPlot, tolerance: f64, unit: &str) -> PanelPlot {
    let values = || {
        plot.curves
            .iter()
            .flat_map(|c| c.points.iter().map(|p| p.1))
    };
    let lo = values().fold(f64::INFINITY, f64::min);
    let hi = values().fold(f64::NEG_INFINITY, f64::max);
    // A range within 1e-9 of its magnitude is drawn flat at its value already (`draw::linear_range`).
    let relative = hi - lo <= 1e-9 * lo.abs().max(hi.abs());
    let constant = tolerance > 0.0 && lo <= hi && hi - lo <= tolerance && !relative;
    if !constant {
        return plot;
    }
    for curve in &mut plot.curves {
        let n = curve.points.len().max(1) as f64;
        let mean = curve.points.iter().map(|p| p.1).sum::<f64>() / n;
        // + 0.0 turns a rounded −0 into 0.
        let value = (mean / tolerance).round() * tolerance + 0.0;
        for p in &mut curve.points {
            p.1 = value;
        }
        curve.label = format!("{} = {}", curve.label, for_people(value));
    }
    plot.notes
        .push(format!("constant to round-off ({tolerance:.0e} {unit})"));
    plot
}

/// H in one set of axes (columns `{columns}_x` …), with |H| grey, dashed with squares; drawn flat when it is
/// constant to [`ROUND_OFF`] of the run's momentum scale.
fn h_panel(run: &RunSeries, columns: &str, axes: &str) -> PanelPlot {
    flatten_constant(
        h_curves(run, columns, axes),
        ROUND_OFF * run.momentum_scale(),
        "kg·m²/s",
    )
}

/// H in one set of axes (columns `{columns}_x` …), with |H| grey, dashed with squares.
fn h_curves(run: &RunSeries, columns: &str, axes: &str) -> PanelPlot {
    let symbol = format!("H_{}", &axes[..1]);
    let norm = Curve {
        label: "|H|".into(),
        color: GREY,
        dashed: true,
        marker: Some(Marker::Square),
        points: run.points("H_norm"),
    };
    let curves = components(run, columns, &symbol, false)
        .into_iter()
        .chain([norm])
        .collect();
    PanelPlot::linear(
        format!("Moment of momentum H, {axes} axes"),
        "H (kg·m²/s)",
        curves,
    )
}

/// A vector in body axes (`{quantity}_b_x` …, solid) and in space axes (`{quantity}_s_x` …, dashed with circles).
fn body_and_space_panel(run: &RunSeries, title: &str, symbol: &str, quantity: &str) -> PanelPlot {
    let unit = if quantity == "M" { "N·m" } else { "rad/s" };
    let curves = components(run, &format!("{quantity}_b"), &format!("{symbol}_b"), false)
        .into_iter()
        .chain(components(
            run,
            &format!("{quantity}_s"),
            &format!("{symbol}_s"),
            true,
        ))
        .collect();
    PanelPlot::linear(title, &format!("{symbol} ({unit})"), curves)
}

/// The CSV columns of the drift curves of the scene's invariants ([`Facts`]: |H|, T, T + V, and H_s,z where H_s
/// is not conserved whole), or `None` when the sidecar does not tell (none, or one written before 0.2).
pub(super) fn invariants(scene: Option<&SceneFacts>) -> Option<Vec<&'static str>> {
    let facts = scene?.facts.as_ref()?;
    let whole_h_s = facts.conserves(Invariant::HSpaceX);
    Some(
        (facts.invariants.iter())
            .filter(|i| match i {
                Invariant::HSpaceX | Invariant::HSpaceY => false,
                Invariant::HSpaceZ => !whole_h_s,
                _ => true,
            })
            .map(|i| i.column())
            .collect(),
    )
}

/// The symbol, colour and unit of a drift curve's quantity.
fn drift_style(column: &str) -> (&'static str, RGBColor, &'static str) {
    match column {
        "H_norm" => ("|H|", ORANGE, "kg·m²/s"),
        "energy_total" => ("T + V", BLACK, "J"),
        "H_s_z" => ("H_s,z", BLUE, "kg·m²/s"),
        _ => ("T", PURPLE, "J"),
    }
}

/// The drift of the scene's invariants (all of |H|, T and T + V the file has when the scene is not known) on a log
/// scale, values below [`DRIFT_FLOOR`] drawn at it.
fn drift_panel(run: &RunSeries) -> PanelPlot {
    let kept = invariants(run.scene.as_ref());
    let mut notes = Vec::new();
    let mut clamped = false;
    let mut curves = Vec::new();
    for d in &run.drifts {
        // Without the scene, H_s,z (an invariant only under vertical gravity) is left out.
        let shown = match &kept {
            Some(k) => k.contains(&d.column),
            None => d.column != "H_s_z",
        };
        if !shown {
            continue;
        }
        let (name, color, unit) = drift_style(d.column);
        let label = if d.x0 == Some(0.0) {
            format!("{name}: absolute ({unit}), as {name}(0) = 0")
        } else {
            format!("{name}: relative")
        };
        let mut points = d.points.points();
        for p in &mut points {
            if p.1 < DRIFT_FLOOR {
                clamped = true;
                p.1 = DRIFT_FLOOR;
            }
        }
        curves.push(Curve {
            label,
            color,
            dashed: false,
            marker: None,
            points,
        });
    }
    if clamped {
        notes.push(format!(
            "drift < {DRIFT_FLOOR:.0e} (e.g. 0) is drawn at {DRIFT_FLOOR:.0e}"
        ));
    }
    let title = match &kept {
        None => "Change of |H| and T since t = 0 (their drift where they are invariants)".into(),
        Some(k) if k.is_empty() || curves.is_empty() => {
            notes.push("this scene has no invariant among |H|, T and T + V".into());
            "Change of the invariants since t = 0".into()
        }
        Some(_) => {
            let names: Vec<&str> = curves
                .iter()
                .map(|c| c.label.split(':').next().unwrap_or(""))
                .collect();
            format!("Drift of {} since t = 0", names.join(" and "))
        }
    };
    PanelPlot {
        title,
        y_label: "|x(t) − x(0)| / |x(0)|".into(),
        curves,
        log: true,
        notes,
        events: Vec::new(),
    }
}
