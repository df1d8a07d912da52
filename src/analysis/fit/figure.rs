//! The residuals against time (`fit --plot`): one chart per channel — the gyro's (rad/s) above the attitude's
//! (rad) — with a curve per body axis, on a linear scale about zero, each curve thinned to at most
//! [`MAX_POINTS`] points.

use plotters::prelude::*;

use super::solve::Residuals;
use crate::output::plot::{Area, Curve, DrawResult, FONT, MAX_POINTS, PALETTE, svg_text};

/// The figure's size in pixels (1/96 inch).
pub const PIXELS: (u32, u32) = (1000, 700);

/// The figure of `residuals` under `title`, as SVG text.
pub fn render_svg(title: &str, residuals: &[Residuals]) -> Result<String, String> {
    svg_text(PIXELS, |root| draw(root, title, residuals))
}

fn draw(root: &Area<'_>, title: &str, residuals: &[Residuals]) -> DrawResult {
    root.fill(&WHITE)?;
    let body = root.titled(title, (FONT, 20).into_font().color(&BLACK))?;
    let channels: Vec<(&str, &str, Vec<&Residuals>)> = [
        ("omega", "gyro: model + bias − measured (rad/s)"),
        ("attitude", "attitude: Log(q_meas⁻¹ ⊗ q_model) (rad)"),
    ]
    .into_iter()
    .map(|(prefix, label)| {
        let of: Vec<&Residuals> = residuals
            .iter()
            .filter(|r| r.name.starts_with(prefix))
            .collect();
        (prefix, label, of)
    })
    .filter(|c| !c.2.is_empty())
    .collect();
    let areas = body.split_evenly((channels.len().max(1), 1));
    for ((_, label, series), area) in channels.iter().zip(&areas) {
        chart(area, label, series)?;
    }
    Ok(())
}

/// One channel's chart.
fn chart(area: &Area<'_>, label: &str, series: &[&Residuals]) -> DrawResult {
    let curves: Vec<Curve> = (series.iter().enumerate())
        .map(|(k, s)| {
            let stride = s.t.len().div_ceil(MAX_POINTS).max(1);
            Curve {
                label: s.name.clone(),
                color: PALETTE[k % PALETTE.len()],
                dashed: false,
                marker: None,
                points: (s.t.iter().zip(&s.values))
                    .step_by(stride)
                    .map(|(&t, &v)| (t, v))
                    .collect(),
            }
        })
        .collect();
    let points = || curves.iter().flat_map(|c| c.points.iter());
    let t0 = points().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let t1 = points().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    let reach = points().map(|p| p.1.abs()).fold(0.0, f64::max);
    let reach = if reach > 0.0 { reach * 1.1 } else { 1.0 };
    let t1 = if t1 > t0 { t1 } else { t0 + 1.0 };
    let mut chart = ChartBuilder::on(area)
        .margin(12)
        .margin_right(20)
        .x_label_area_size(40)
        .y_label_area_size(90)
        .build_cartesian_2d(t0..t1, -reach..reach)?;
    chart
        .configure_mesh()
        .x_desc("t (s)")
        .y_desc(label)
        .y_label_formatter(&|v: &f64| format!("{v:.1e}"))
        .y_max_light_lines(0)
        .x_max_light_lines(0)
        .bold_line_style(BLACK.mix(0.12))
        .axis_desc_style((FONT, 14))
        .label_style((FONT, 12))
        .draw()?;
    for curve in &curves {
        let style = ShapeStyle::from(&curve.color).stroke_width(1);
        chart
            .draw_series(LineSeries::new(curve.points.iter().copied(), style))?
            .label(curve.label.clone())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], style));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK.mix(0.3))
        .label_font((FONT, 13))
        .draw()?;
    Ok(())
}
