//! The errors against time on a log scale: one curve per metric of a score (`score --plot`), or the attitude
//! error of each scene of a suite (`score --suite … --plot`), each with its threshold as a dashed line of its
//! colour. Drawn with plotters' SVG backend through the figures' shared `draw_curve`; values below [`FLOOR`] (an
//! exact 0) are drawn at it. The legend stands beside the chart, so that it never covers a curve.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::Series;
use crate::output::plot::{
    Area, Curve, DrawResult, FONT, PALETTE, decade_label, decade_range, draw_curve,
    draw_legend_entry, svg_text,
};

/// The smallest value drawn.
pub const FLOOR: f64 = 1e-17;

/// The figure's size in pixels (1/96 inch).
pub const PIXELS: (u32, u32) = (1000, 600);

/// The width of the legend's column (px).
const LEGEND_WIDTH: u32 = 270;

/// The figure of `series` (their names label the curves) under `title`, as SVG text.
pub fn render_svg(title: &str, series: &[Series]) -> Result<String, String> {
    let curves: Vec<Curve> = (series.iter().enumerate())
        .map(|(k, s)| Curve {
            label: s.name.clone(),
            color: PALETTE[k % PALETTE.len()],
            dashed: k >= PALETTE.len(),
            marker: None,
            points: (s.t.iter().zip(&s.values))
                .map(|(&t, &v)| (t, v.max(FLOOR).log10()))
                .collect(),
        })
        .collect();
    let thresholds: Vec<f64> = series
        .iter()
        .map(|s| s.threshold.max(FLOOR).log10())
        .collect();
    svg_text(PIXELS, |root| draw(root, title, &curves, &thresholds))
}

fn draw(root: &Area<'_>, title: &str, curves: &[Curve], thresholds: &[f64]) -> DrawResult {
    root.fill(&WHITE)?;
    let body = root.titled(title, (FONT, 20).into_font().color(&BLACK))?;
    let (w, _) = body.dim_in_pixel();
    let (chart_area, legend_area) = body.split_horizontally(w.saturating_sub(LEGEND_WIDTH));
    let points = || curves.iter().flat_map(|c| c.points.iter());
    let t1 = points().map(|p| p.0).fold(f64::MIN_POSITIVE, f64::max);
    let levels = || points().map(|p| p.1).chain(thresholds.iter().copied());
    let lo = levels().fold(f64::INFINITY, f64::min);
    let hi = levels().fold(f64::NEG_INFINITY, f64::max);
    let (y0, y1) = if lo.is_finite() {
        decade_range(lo, hi)
    } else {
        (-17.0, 0.0)
    };
    let y_fmt = |v: &f64| decade_label(*v);
    let mut chart = ChartBuilder::on(&chart_area)
        .margin(12)
        .margin_right(20)
        .x_label_area_size(44)
        .y_label_area_size(80)
        .build_cartesian_2d(0.0..t1, y0..y1)?;
    chart
        .configure_mesh()
        .x_desc("t (s)")
        .y_desc("error (log scale)")
        .y_label_formatter(&y_fmt)
        .y_labels(((y1 - y0).round() as usize + 1).clamp(2, 19))
        .y_max_light_lines(0)
        .x_max_light_lines(0)
        .bold_line_style(BLACK.mix(0.12))
        .axis_desc_style((FONT, 15))
        .label_style((FONT, 13))
        .draw()?;
    for (curve, &level) in curves.iter().zip(thresholds) {
        draw_curve(&mut chart, curve, 8, 1)?;
        let threshold = Curve {
            label: String::new(),
            color: curve.color,
            dashed: true,
            marker: None,
            points: vec![(0.0, level), (t1, level)],
        };
        draw_curve(&mut chart, &threshold, 4, 1)?;
    }
    draw_legend(&legend_area, curves)
}

/// The legend's column: one line per curve, then what the dashed lines are.
fn draw_legend(area: &Area<'_>, curves: &[Curve]) -> DrawResult {
    let text = TextStyle::from((FONT, 14).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let line = 22;
    let mut y = 40;
    for curve in curves {
        draw_legend_entry(area, curve, (8, y), &text, 1)?;
        y += line;
    }
    let note = (FONT, 13)
        .into_font()
        .color(&RGBColor(0x55, 0x55, 0x55))
        .pos(Pos::new(HPos::Left, VPos::Center));
    area.draw(&Text::new(
        "dashed: each metric's threshold",
        (8, y + line / 2),
        note,
    ))?;
    Ok(())
}
