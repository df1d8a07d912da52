//! The errors against time on a log scale: one curve per metric of a score (`score --plot`), or the attitude
//! error of each scene of a suite (`score --suite … --plot`). Drawn with plotters' SVG backend through the
//! figures' shared `draw_curve`; values below [`FLOOR`] (an exact 0) are drawn at it.

use plotters::prelude::*;

use super::Series;
use crate::output::plot::{
    Area, Curve, DrawResult, FONT, PALETTE, decade_label, decade_range, draw_curve, svg_text,
};

/// The smallest value drawn.
pub const FLOOR: f64 = 1e-17;

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
    svg_text((1000, 600), |root| draw(root, title, &curves))
}

fn draw(root: &Area<'_>, title: &str, curves: &[Curve]) -> DrawResult {
    root.fill(&WHITE)?;
    let body = root.titled(title, (FONT, 20).into_font().color(&BLACK))?;
    let points = || curves.iter().flat_map(|c| c.points.iter());
    let t1 = points().map(|p| p.0).fold(f64::MIN_POSITIVE, f64::max);
    let lo = points().map(|p| p.1).fold(f64::INFINITY, f64::min);
    let hi = points().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
    let (y0, y1) = if lo.is_finite() {
        decade_range(lo, hi)
    } else {
        (-17.0, 0.0)
    };
    let y_fmt = |v: &f64| decade_label(*v);
    let mut chart = ChartBuilder::on(&body)
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
    for curve in curves {
        draw_curve(&mut chart, curve, 8, 1)?;
        let style = ShapeStyle::from(&curve.color).stroke_width(2);
        chart
            .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())?
            .label(curve.label.as_str())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.3))
        .label_font((FONT, 14))
        .draw()?;
    Ok(())
}
