//! The work-precision figure of `eulerdyn accuracy`: error against wall time, both on log scales, a curve per
//! method and form (solid: body form, dashed: space form), a marker per run, and grey lines at the error levels
//! the summary names ([`crate::analysis::study::TARGETS`]).
//!
//! Drawn with plotters' SVG backend (pure Rust, no font libraries: the SVG names the font family and the viewer
//! renders the text). Log scales are drawn as log10 of the values on linear axes, labelled at every decade.
//! Failed runs are left out; an error of exactly 0 is drawn at [`ERROR_FLOOR`].

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::{Study, TARGETS};
use crate::frames::Form;
use crate::output::plot::{
    Area, Curve, DrawResult, FONT, PALETTE, decade_label, decade_range, draw_curve,
    draw_legend_entry, svg_text,
};

/// The smallest error drawn; smaller values (an exact 0) are drawn at it.
pub const ERROR_FLOOR: f64 = 1e-17;

const WIDTH: u32 = 1200;
const HEIGHT: u32 = 760;
const LEGEND_WIDTH: i32 = 300;

/// The curves of a study, a method in one form each, points (log10 wall time, log10 error) sorted by time.
fn curves(study: &Study) -> Vec<Curve> {
    let mut methods: Vec<&str> = Vec::new();
    let mut curves: Vec<Curve> = Vec::new();
    for row in &study.rows {
        let Some(err) = row.error(study.measure) else {
            continue;
        };
        if !(row.wall_s.is_finite() && row.wall_s > 0.0) {
            continue;
        }
        let method_index = match methods.iter().position(|m| *m == row.method) {
            Some(i) => i,
            None => {
                methods.push(&row.method);
                methods.len() - 1
            }
        };
        let label = format!("{} ({})", row.method, row.form.name());
        let point = (row.wall_s.log10(), err.max(ERROR_FLOOR).log10());
        match curves.iter_mut().find(|c| c.label == label) {
            Some(c) => c.points.push(point),
            None => curves.push(Curve {
                label,
                color: PALETTE[method_index % PALETTE.len()],
                dashed: row.form == Form::Space,
                marker: None,
                points: vec![point],
            }),
        }
    }
    for c in &mut curves {
        c.points.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    curves
}

/// The figure of `study`, as SVG text; the error says what could not be drawn.
pub fn render_svg(study: &Study) -> Result<String, String> {
    let curves = curves(study);
    svg_text((WIDTH, HEIGHT), |root| draw(root, study, &curves))
}

fn draw(root: &Area<'_>, study: &Study, curves: &[Curve]) -> DrawResult {
    root.fill(&WHITE)?;
    let name = if study.scene_name.is_empty() {
        study.scene_path.display().to_string()
    } else {
        study.scene_name.clone()
    };
    let title = format!(
        "What accuracy costs: {name} (t_end = {} s, {} rows)",
        study.t_end, study.rows_per_run
    );
    let body = root.titled(&title, (FONT, 22).into_font().color(&BLACK))?;
    let (w, _) = body.dim_in_pixel();
    let (chart_area, legend_area) = body.split_horizontally(w as i32 - LEGEND_WIDTH);
    let xs = curves.iter().flat_map(|c| c.points.iter().map(|p| p.0));
    let ys = curves.iter().flat_map(|c| c.points.iter().map(|p| p.1));
    let fold = |it: &mut dyn Iterator<Item = f64>| {
        it.fold(None, |acc: Option<(f64, f64)>, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
    };
    let (x0, x1) = fold(&mut xs.into_iter()).map_or((-4.0, -3.0), |(lo, hi)| decade_range(lo, hi));
    let target_logs: Vec<f64> = TARGETS.iter().map(|t| t.log10()).collect();
    let (y_lo, y_hi) = fold(&mut ys.into_iter()).unwrap_or((-12.0, -3.0));
    let (y0, y1) = decade_range(y_lo, y_hi);
    let x_fmt = |v: &f64| decade_label(*v);
    let y_fmt = |v: &f64| decade_label(*v);
    let mut chart = ChartBuilder::on(&chart_area)
        .margin(12)
        .margin_right(20)
        .x_label_area_size(48)
        .y_label_area_size(84)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .x_desc("wall time of the integration (s), median of repeats")
        .y_desc(format!("{} — {}", study.measure.column(), study.measure.describe()).as_str())
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .x_labels(((x1 - x0).round() as usize + 1).clamp(2, 14))
        .y_labels(((y1 - y0).round() as usize + 1).clamp(2, 19))
        .x_max_light_lines(0)
        .y_max_light_lines(0)
        .bold_line_style(BLACK.mix(0.12))
        .axis_desc_style((FONT, 15))
        .label_style((FONT, 13))
        .draw()?;
    for &t in &target_logs {
        if t > y0 && t < y1 {
            chart.draw_series(DashedLineSeries::new(
                [(x0, t), (x1, t)],
                4,
                4,
                ShapeStyle::from(&BLACK.mix(0.35)).stroke_width(1),
            ))?;
        }
    }
    for curve in curves {
        draw_curve(&mut chart, curve, 8, 1)?;
        let marker = if curve.dashed {
            ShapeStyle::from(&curve.color).stroke_width(2)
        } else {
            ShapeStyle::from(&curve.color).filled()
        };
        chart.draw_series(curve.points.iter().map(|&p| Circle::new(p, 4, marker)))?;
    }
    draw_legend(&legend_area, study, curves)
}

/// The legend, in its own column beside the chart so that it never hides a curve.
fn draw_legend(area: &Area<'_>, study: &Study, curves: &[Curve]) -> DrawResult {
    let text = TextStyle::from((FONT, 15).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let note = (FONT, 13)
        .into_font()
        .color(&RGBColor(90, 90, 90))
        .pos(Pos::new(HPos::Left, VPos::Center));
    let mut y = 30;
    for curve in curves {
        draw_legend_entry(area, curve, (6, y), &text, 1)?;
        y += 22;
    }
    y += 10;
    let mut notes = vec![
        "solid: body form, dashed: space form".to_string(),
        "grey: the summary's error levels".to_string(),
        format!("reference: {}", study.reference_short),
    ];
    if study.rows.iter().any(|r| r.failure.is_some()) {
        notes.push("failed runs (diverged) not drawn".into());
    }
    notes.push(format!("errors below {ERROR_FLOOR:e} drawn at it"));
    for line in notes {
        for part in wrap(&line, 40) {
            area.draw(&Text::new(part, (6, y), note.clone()))?;
            y += 17;
        }
    }
    Ok(())
}

/// Splits `text` into lines of at most about `width` characters, at spaces.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_breaks_at_spaces() {
        assert_eq!(wrap("a bb ccc dddd", 6), vec!["a bb", "ccc", "dddd"]);
    }
}
