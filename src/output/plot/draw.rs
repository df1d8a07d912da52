//! Drawing the figure with plotters' SVG backend: the title, then one panel per grid cell, each a chart (time on
//! x) above its legend. Solid curves are drawn first, dashed ones over them, and markers last, so that a curve
//! that coincides with another still shows (its markers and dashes).

use std::fmt;
use std::path::Path;

use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::layout::{CAPTION_PX, FigureSize, Grid, PX_PER_CM, TEXT_PX, TITLE_CM, TITLE_PX};
use super::panels::{Curve, DRIFT_FLOOR, EventMarks, Marker, PanelPlot, panel_plot};
use super::series::RunSeries;
use super::ticks::LinearTicks;
use super::{FONT, Panel, PlotError};

/// A region of an SVG figure.
pub(crate) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// What drawing into an [`Area`] gives.
pub(crate) type DrawResult = Result<(), DrawingAreaErrorKind<std::io::Error>>;

/// A chart of an SVG figure, both axes linear in f64 (log scales are drawn as log10 of the values).
pub(crate) type Chart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Ten colours told apart on screen and in print (matplotlib's `tab10`), in the order curves take them.
pub(crate) const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// The SVG text of a `size` (px) figure drawn by `draw`; the error says what could not be drawn.
pub(crate) fn svg_text(
    size: (u32, u32),
    draw: impl FnOnce(&Area<'_>) -> DrawResult,
) -> Result<String, String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        draw(&root).map_err(|e| format!("cannot draw the figure: {e}"))?;
        root.present()
            .map_err(|e| format!("cannot draw the figure: {e}"))?;
    }
    Ok(svg)
}

/// Drawing units (SVG user units) per pixel: the SVG is drawn at this finer grid, its viewBox scaled down to the
/// figure's size, so that curves are placed to a quarter pixel (plotters rounds coordinates to whole units).
pub(crate) const DOT: i32 = 4;
/// Height of a legend line (px).
const LEGEND_LINE: i32 = 16;
/// Marks along a curve with a marker.
const MARKS_PER_CURVE: usize = 10;

/// The plotters font size that gives an SVG `font-size` of at least `px` pixels, in drawing units of `dot` per
/// pixel: plotters writes its size divided by 1.24, and rounds some sizes down to whole units, so this is whole.
pub(crate) fn font_size(px: f64, dot: i32) -> f64 {
    (px * f64::from(dot) * 1.24).ceil()
}

/// The text size (px) at which `text` fits in `width` px: `px`, or smaller, but never below [`TEXT_PX`] (9 pt). The
/// width of a character is taken as 0.56 of the size (DejaVu Sans and Helvetica-like fonts average about that).
fn fitted_px(text: &str, px: f64, width: f64) -> f64 {
    let chars = text.chars().count().max(1) as f64;
    (width / (0.56 * chars)).clamp(TEXT_PX, px)
}

fn draw_error(file: &Path, e: impl fmt::Display) -> PlotError {
    PlotError::Output {
        file: file.to_path_buf(),
        problem: format!("cannot draw the figure: {e}"),
    }
}

/// The figure's default title: the scene, method and rows (from the sidecar), or the file name and rows.
pub(super) fn default_title(run: &RunSeries) -> String {
    match &run.scene {
        Some(s) => format!(
            "{}: {}, {} form, {} rows",
            s.name, s.method, s.frame, run.rows
        ),
        None => {
            let file_name = run.file.file_name().map_or_else(
                || run.file.display().to_string(),
                |n| n.to_string_lossy().into_owned(),
            );
            format!("{file_name}: {} rows", run.rows)
        }
    }
}

/// The figure for `panels` (in a [`Grid`]) of `run` at `size`, titled `title` (none when empty), as SVG text.
pub(super) fn render_svg(
    run: &RunSeries,
    panels: &[Panel],
    size: FigureSize,
    title: &str,
    out_name: &Path,
) -> Result<String, PlotError> {
    let grid = Grid::for_panels(panels.len());
    let plots: Vec<PanelPlot> = panels.iter().map(|&p| panel_plot(run, p)).collect();
    let (width, height) = size.pixels();
    let title_px = if title.is_empty() {
        0
    } else {
        (TITLE_CM * PX_PER_CM).round() as u32
    };
    let dot = DOT as u32;
    let cell = (
        width / grid.columns as u32,
        (height - title_px) / grid.rows as u32,
    );
    let legend_rows = plots
        .iter()
        .map(|p| legend_rows(p, cell.0 as i32))
        .max()
        .unwrap_or(1);
    let mut svg = String::new();
    {
        let root =
            SVGBackend::with_string(&mut svg, (width * dot, height * dot)).into_drawing_area();
        let fail = |e| draw_error(out_name, e);
        root.fill(&WHITE).map_err(fail)?;
        if !title.is_empty() {
            let fitted = fitted_px(title, TITLE_PX, f64::from(width) - 16.0);
            let style = TextStyle::from((FONT, font_size(fitted, DOT)).into_font())
                .pos(Pos::new(HPos::Center, VPos::Center));
            root.draw(&Text::new(
                title.to_string(),
                ((width * dot) as i32 / 2, (title_px * dot) as i32 / 2),
                style,
            ))
            .map_err(fail)?;
        }
        for (k, plot) in plots.iter().enumerate() {
            let (row, column) = (k / grid.columns, k % grid.columns);
            let corner = (
                DOT * column as i32 * cell.0 as i32,
                DOT * (title_px as i32 + row as i32 * cell.1 as i32),
            );
            let area = root.clone().shrink(corner, (cell.0 * dot, cell.1 * dot));
            draw_panel(&area, run, plot, legend_rows).map_err(fail)?;
        }
        root.present().map_err(fail)?;
    }
    // The figure's size in pixels, its drawing in units of 1/DOT pixel.
    let drawn = format!("<svg width=\"{}\" height=\"{}\"", width * dot, height * dot);
    let shown = format!("<svg width=\"{width}\" height=\"{height}\"");
    Ok(svg.replacen(&drawn, &shown, 1))
}

/// Legend entries per line in a panel `width` px wide, and the width of each (px).
fn legend_columns(plot: &PanelPlot, width: i32) -> (usize, i32) {
    let longest = (plot.curves.iter().map(|c| &c.label))
        .chain(plot.events.iter().map(|e| &e.name))
        .map(|label| label.chars().count())
        .max()
        .unwrap_or(1) as f64;
    let entry = (longest * 0.6 * TEXT_PX) as i32 + 52;
    (((width - 16) / entry).max(1) as usize, entry)
}

/// The legend's left margin (px), and the indent of an entry's label after its line sample (px).
const LEGEND_LEFT: i32 = 12;
const LABEL_INDENT: i32 = 36;

/// The characters of legend text (at [`TEXT_PX`], 0.56 of it per character as in [`fitted_px`]) that fit in a
/// panel `width` px wide from `indent` px, at least 8.
fn chars_fitting(width: i32, indent: i32) -> usize {
    (f64::from(width - indent - LEGEND_LEFT) / (0.56 * TEXT_PX)).max(8.0) as usize
}

/// `text` broken at spaces into lines of at most `chars` characters (a longer word on a line of its own).
fn wrap(text: &str, chars: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(line) if line.chars().count() + 1 + word.chars().count() <= chars => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

/// The lines of each curve's label, of each event's name and of each note in a panel `width` px wide: a label
/// wider than the panel (one entry a line) and a note wider than it are wrapped, so that the legend fits.
fn legend_texts(plot: &PanelPlot, width: i32) -> (Vec<Vec<String>>, Vec<Vec<String>>) {
    let (per_line, _) = legend_columns(plot, width);
    let label_chars = if per_line == 1 {
        chars_fitting(width, LEGEND_LEFT + LABEL_INDENT)
    } else {
        usize::MAX
    };
    let labels = (plot.curves.iter().map(|c| &c.label))
        .chain(plot.events.iter().map(|e| &e.name))
        .map(|label| wrap(label, label_chars))
        .collect();
    let note_chars = chars_fitting(width, LEGEND_LEFT);
    let notes = plot.notes.iter().map(|n| wrap(n, note_chars)).collect();
    (labels, notes)
}

/// The lines a panel's legend needs in a panel `width` px wide: its entries in columns (a wrapped label's lines
/// when one a line), then its notes' lines.
fn legend_rows(plot: &PanelPlot, width: i32) -> usize {
    let (per_line, _) = legend_columns(plot, width);
    let (labels, notes) = legend_texts(plot, width);
    let entries = if per_line == 1 {
        labels.iter().map(Vec::len).sum()
    } else {
        labels.len().div_ceil(per_line)
    };
    entries + notes.iter().map(Vec::len).sum::<usize>()
}

/// The x (time) range of the charts: the run's, or a unit range around a single time.
fn time_range(run: &RunSeries) -> (f64, f64) {
    if run.t_range.0 < run.t_range.1 {
        run.t_range
    } else {
        (run.t_range.0 - 0.5, run.t_range.0 + 0.5)
    }
}

/// The curves as drawn: a log panel's values as log10 (at least [`DRIFT_FLOOR`]).
fn drawn_curves(plot: &PanelPlot) -> Vec<Curve> {
    plot.curves
        .iter()
        .map(|c| Curve {
            label: c.label.clone(),
            color: c.color,
            dashed: c.dashed,
            marker: c.marker,
            points: if plot.log {
                c.points
                    .iter()
                    .map(|&(t, v)| (t, v.max(DRIFT_FLOOR).log10()))
                    .collect()
            } else {
                c.points.clone()
            },
        })
        .collect()
}

/// One panel: its chart in the upper part of `area`, its legend (`legend_rows` lines high) below.
fn draw_panel(
    area: &Area<'_>,
    run: &RunSeries,
    plot: &PanelPlot,
    legend_rows: usize,
) -> DrawResult {
    let (_, h) = area.dim_in_pixel();
    let legend_height = DOT * (legend_rows as i32 * LEGEND_LINE + 8);
    let (chart_area, legend_area) = area.split_vertically(h as i32 - legend_height);
    let (t0, t1) = time_range(run);
    let curves = drawn_curves(plot);
    let (lo, hi) = if plot.log {
        let floor = DRIFT_FLOOR.log10();
        let (lo, hi) = extent(curves.iter().flat_map(|c| c.points.iter().map(|p| p.1)))
            .unwrap_or((floor, floor));
        decade_range(lo, hi)
    } else {
        // The events' values too: an extremum located between the rows lies beyond the rows' values.
        let located = plot
            .events
            .iter()
            .flat_map(|e| e.points.iter().map(|p| p.1));
        let (lo, hi) = extent(
            curves
                .iter()
                .flat_map(|c| c.points.iter().map(|p| p.1))
                .chain(located),
        )
        .unwrap_or((-1.0, 1.0));
        linear_range(lo, hi)
    };
    let x_ticks = LinearTicks::new(t0, t1);
    let y_ticks = LinearTicks::new(lo, hi);
    let x_fmt = |v: &f64| x_ticks.label(*v);
    let y_fmt = |v: &f64| {
        if plot.log {
            decade_label(*v)
        } else {
            y_ticks.label(*v)
        }
    };
    let y_desc = if plot.log {
        plot.y_label.clone()
    } else {
        y_ticks.title(&plot.y_label)
    };
    // Room for the longest y tick label and the rotated axis title.
    let widest = [lo, hi, 0.5 * (lo + hi)]
        .iter()
        .map(|v| y_fmt(v).chars().count())
        .max()
        .unwrap_or(4) as f64;
    let y_area = (widest * 0.62 * TEXT_PX + 2.2 * TEXT_PX) as u32 * DOT as u32;
    let chart_area = draw_caption(&chart_area, &plot.title)?;
    let mut chart = ChartBuilder::on(&chart_area)
        .margin(4 * DOT as u32)
        .margin_right(14 * DOT as u32)
        .margin_top((TEXT_PX / 2.0) as u32 * DOT as u32 + 2 * DOT as u32)
        .x_label_area_size((3.3 * TEXT_PX) as u32 * DOT as u32)
        .y_label_area_size(y_area)
        .build_cartesian_2d(t0..t1, lo..hi)?;
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(x_ticks.title("t (s)"))
        .y_desc(y_desc)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .x_labels(6)
        .y_labels(6)
        .bold_line_style(BLACK.mix(0.15).stroke_width(DOT as u32))
        .light_line_style(BLACK.mix(0.04).stroke_width(DOT as u32))
        .axis_style(BLACK.stroke_width(DOT as u32))
        .set_all_tick_mark_size(5 * DOT)
        .max_light_lines(4)
        .axis_desc_style((FONT, font_size(TEXT_PX, DOT)))
        .label_style((FONT, font_size(TEXT_PX, DOT)));
    if plot.log {
        // A label at every decade (at most 7 of them), and no minor lines: they would be linear in the exponent.
        let decades = (hi - lo).round().clamp(1.0, 6.0) as usize;
        mesh.y_labels(decades + 1).y_max_light_lines(0);
    }
    mesh.draw()?;
    draw_curves(&mut chart, &curves)?;
    draw_events(&mut chart, &plot.events, (lo, hi))?;
    draw_legend(&legend_area, plot)
}

/// Draws the panel's `title` centred at the top of `area`, shrunk to fit its width (not below 9 pt), and returns
/// the area below it. (Drawn here rather than by plotters, so that the top tick label has room below it.)
fn draw_caption<'a>(
    area: &Area<'a>,
    title: &str,
) -> Result<Area<'a>, DrawingAreaErrorKind<std::io::Error>> {
    let (w, _) = area.dim_in_pixel();
    let px = fitted_px(title, CAPTION_PX, f64::from(w / DOT as u32) - 8.0);
    let band = (1.5 * CAPTION_PX) as i32 * DOT;
    let style = TextStyle::from((FONT, font_size(px, DOT)).into_font())
        .pos(Pos::new(HPos::Center, VPos::Center));
    area.draw(&Text::new(
        title.to_string(),
        (w as i32 / 2, band / 2 + 2 * DOT),
        style,
    ))?;
    let (_, below) = area.split_vertically(band + 2 * DOT);
    Ok(below)
}

/// Draws `curves`: the solid ones first, the dashed ones over them, then the markers of every curve.
fn draw_curves(chart: &mut Chart<'_, '_>, curves: &[Curve]) -> DrawResult {
    for curve in curves.iter().filter(|c| !c.dashed) {
        draw_curve(chart, curve, 7, DOT)?;
    }
    for curve in curves.iter().filter(|c| c.dashed) {
        draw_curve(chart, curve, 7, DOT)?;
    }
    for (k, curve) in curves.iter().enumerate() {
        draw_marks(chart, curve, k)?;
    }
    Ok(())
}

/// Draws `curve` as a line 2 px wide, solid or dashed (dashes of `dash` px, 5 px apart), in a drawing of `dot`
/// units per pixel.
pub(crate) fn draw_curve(
    chart: &mut Chart<'_, '_>,
    curve: &Curve,
    dash: u32,
    dot: i32,
) -> DrawResult {
    let style = ShapeStyle::from(&curve.color).stroke_width(2 * dot as u32);
    let points = curve.points.iter().copied();
    if curve.dashed {
        let dot = dot as u32;
        chart.draw_series(DashedLineSeries::new(points, dash * dot, 5 * dot, style))?;
    } else {
        chart.draw_series(LineSeries::new(points, style))?;
    }
    Ok(())
}

/// The marker of `curve` at [`MARKS_PER_CURVE`] points evenly spaced in time, shifted by the curve's index `k` so
/// that the marks of neighbouring curves do not sit on each other.
fn draw_marks(chart: &mut Chart<'_, '_>, curve: &Curve, k: usize) -> DrawResult {
    let (Some(marker), Some(first), Some(last)) =
        (curve.marker, curve.points.first(), curve.points.last())
    else {
        return Ok(());
    };
    let phase = ((k % 4) as f64 + 0.5) / 4.0;
    let span = last.0 - first.0;
    let mut at = curve.points.iter().peekable();
    let mut marks = Vec::with_capacity(MARKS_PER_CURVE);
    for j in 0..MARKS_PER_CURVE {
        let t = first.0 + span * (j as f64 + phase) / MARKS_PER_CURVE as f64;
        while let Some(p) = at.next_if(|p| p.0 < t) {
            if at.peek().is_none() {
                marks.push(*p);
            }
        }
        if let Some(p) = at.peek() {
            marks.push(**p);
        }
    }
    let style = ShapeStyle::from(&curve.color).stroke_width(3 * DOT as u32 / 2);
    let (r, a) = (4 * DOT, 3 * DOT);
    match marker {
        Marker::Circle => {
            chart.draw_series(
                marks
                    .into_iter()
                    .map(|p| EmptyElement::at(p) + Circle::new((0, 0), r, style)),
            )?;
        }
        Marker::Square => {
            chart.draw_series(
                marks
                    .into_iter()
                    .map(|p| EmptyElement::at(p) + PathElement::new(square(0, 0, a), style)),
            )?;
        }
    }
    Ok(())
}

/// The closed outline of a square of half side `a` centred at (`x`, `y`) (plotters' rectangles have no stroke
/// width).
fn square(x: i32, y: i32, a: i32) -> Vec<(i32, i32)> {
    vec![
        (x - a, y - a),
        (x + a, y - a),
        (x + a, y + a),
        (x - a, y + a),
        (x - a, y - a),
    ]
}

/// Half the diagonal of an event's diamond (px).
const DIAMOND: i32 = 5;

/// The corners of a diamond of half diagonal `a` centred at (`x`, `y`), top first.
fn diamond(x: i32, y: i32, a: i32) -> Vec<(i32, i32)> {
    vec![(x, y - a), (x + a, y), (x, y + a), (x - a, y)]
}

/// Draws each event's occurrences over the curves: a thin vertical line at t across the chart's y range
/// `(lo, hi)`, and a filled diamond at (t, value).
fn draw_events(
    chart: &mut Chart<'_, '_>,
    events: &[EventMarks],
    (lo, hi): (f64, f64),
) -> DrawResult {
    for event in events {
        let line = ShapeStyle::from(&event.color.mix(0.6)).stroke_width(DOT as u32);
        for &(t, _) in &event.points {
            chart.draw_series(LineSeries::new([(t, lo), (t, hi)], line))?;
        }
        let fill = ShapeStyle::from(&event.color).filled();
        chart
            .draw_series((event.points.iter()).map(|&p| {
                EmptyElement::at(p) + Polygon::new(diamond(0, 0, DIAMOND * DOT), fill)
            }))?;
    }
    Ok(())
}

/// An event's legend entry at (`x`, `y`): a short vertical line with its diamond, and the event's name.
fn draw_event_legend_entry(
    area: &Area<'_>,
    event: &EventMarks,
    (x, y): (i32, i32),
    text: &TextStyle<'_>,
) -> DrawResult {
    let middle = x + 14 * DOT;
    let line = ShapeStyle::from(&event.color.mix(0.6)).stroke_width(DOT as u32);
    area.draw(&PathElement::new(
        vec![(middle, y - 7 * DOT), (middle, y + 7 * DOT)],
        line,
    ))?;
    let fill = ShapeStyle::from(&event.color).filled();
    area.draw(&Polygon::new(diamond(middle, y, DIAMOND * DOT), fill))?;
    area.draw(&Text::new(
        event.name.clone(),
        (x + 36 * DOT, y),
        text.clone(),
    ))
}

/// One legend entry at (`x`, `y`), in a drawing of `dot` units per pixel: a sample of the curve's line (three
/// dashes when dashed, its marker in the middle) and its label.
pub(crate) fn draw_legend_entry(
    area: &Area<'_>,
    curve: &Curve,
    (x, y): (i32, i32),
    text: &TextStyle<'_>,
    dot: i32,
) -> DrawResult {
    let style = ShapeStyle::from(&curve.color).stroke_width(2 * dot as u32);
    if curve.dashed {
        for dx in [0, 11, 22] {
            let from = x + dx * dot;
            area.draw(&PathElement::new(
                vec![(from, y), (from + 7 * dot, y)],
                style,
            ))?;
        }
    } else {
        area.draw(&PathElement::new(vec![(x, y), (x + 29 * dot, y)], style))?;
    }
    let mark = ShapeStyle::from(&curve.color).stroke_width(3 * dot as u32 / 2);
    let middle = x + 14 * dot;
    match curve.marker {
        Some(Marker::Circle) => area.draw(&Circle::new((middle, y), 4 * dot, mark))?,
        Some(Marker::Square) => {
            let a = 3 * dot;
            area.draw(&PathElement::new(square(middle, y, a), mark))?
        }
        None => {}
    }
    area.draw(&Text::new(
        curve.label.clone(),
        (x + 36 * dot, y),
        text.clone(),
    ))
}

/// The legend, below the chart so that it never hides a curve: entries in columns, line by line, then the notes.
fn draw_legend(area: &Area<'_>, plot: &PanelPlot) -> DrawResult {
    let text = TextStyle::from((FONT, font_size(TEXT_PX, DOT)).into_font())
        .pos(Pos::new(HPos::Left, VPos::Center));
    let note = (FONT, font_size(TEXT_PX, DOT))
        .into_font()
        .color(&RGBColor(0x55, 0x55, 0x55))
        .pos(Pos::new(HPos::Left, VPos::Center));
    let (w, _) = area.dim_in_pixel();
    let (per_line, entry) = legend_columns(plot, w as i32 / DOT);
    let (labels, notes) = legend_texts(plot, w as i32 / DOT);
    let left = LEGEND_LEFT;
    let mut y = LEGEND_LINE / 2;
    let entries = plot.curves.len() + plot.events.len();
    for (k, lines) in labels.iter().enumerate() {
        let column = (k % per_line) as i32;
        let at = (DOT * (left + column * entry), DOT * y);
        match plot.curves.get(k) {
            Some(curve) => {
                let first = lines.first().cloned().unwrap_or_default();
                let shown = Curve {
                    label: first,
                    points: Vec::new(),
                    ..*curve
                };
                draw_legend_entry(area, &shown, at, &text, DOT)?
            }
            None => draw_event_legend_entry(area, &plot.events[k - plot.curves.len()], at, &text)?,
        }
        for more in lines.iter().skip(1) {
            y += LEGEND_LINE;
            let at = (DOT * (left + column * entry + LABEL_INDENT), DOT * y);
            area.draw(&Text::new(more.clone(), at, text.clone()))?;
        }
        if column as usize + 1 == per_line || k + 1 == entries {
            y += LEGEND_LINE;
        }
    }
    for line in notes.iter().flatten() {
        area.draw(&Text::new(
            line.clone(),
            (DOT * left, DOT * y),
            note.clone(),
        ))?;
        y += LEGEND_LINE;
    }
    Ok(())
}

/// The smallest and largest of `values`, or `None` when there are none.
fn extent(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values.fold(None, |acc, y| match acc {
        None => Some((y, y)),
        Some((lo, hi)) => Some((lo.min(y), hi.max(y))),
    })
}

/// A linear axis range around [lo, hi]: 5 % margins; a constant (or constant to 1e-9 relative) gets ±5 % of its
/// value (±1 around 0), so that a constant reads as a flat line at its value instead of magnified round-off.
fn linear_range(lo: f64, hi: f64) -> (f64, f64) {
    let scale = lo.abs().max(hi.abs());
    let span = hi - lo;
    if span <= 1e-9 * scale || scale == 0.0 {
        let mid = 0.5 * (lo + hi);
        let half = if mid == 0.0 { 1.0 } else { 0.05 * mid.abs() };
        (mid - half, mid + half)
    } else {
        (lo - 0.05 * span, hi + 0.05 * span)
    }
}

/// The range of a log axis drawn as exponents: [lo, hi] (log10 of the values) widened to whole decades.
pub(crate) fn decade_range(lo: f64, hi: f64) -> (f64, f64) {
    let (lo, hi) = (lo.floor(), hi.ceil());
    if hi <= lo { (lo, lo + 1.0) } else { (lo, hi) }
}

/// The label of the exponent `v` on a log axis: `1e-12` at a whole decade, else the value.
pub(crate) fn decade_label(v: f64) -> String {
    if (v - v.round()).abs() < 1e-9 {
        format!("1e{}", v.round() as i32)
    } else {
        format!("{:.1e}", 10f64.powf(v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn legend_text_is_wrapped_at_spaces_to_fit() {
        assert_eq!(
            wrap("|H|: absolute (kg·m²/s), as |H|(0) = 0", 20),
            vec!["|H|: absolute", "(kg·m²/s), as |H|(0)", "= 0"]
        );
        assert_eq!(wrap("short", 20), vec!["short"]);
        for line in wrap("a b c d e f g h i j k l m n o p", 5) {
            assert!(line.chars().count() <= 5, "{line}");
        }
    }

    #[test]
    fn ranges_of_constants_are_widened_around_the_value() {
        assert_eq!(linear_range(2.0, 2.0), (1.9, 2.1));
        assert_eq!(linear_range(0.0, 0.0), (-1.0, 1.0));
        let (lo, hi) = linear_range(0.0, 10.0);
        assert!(lo < 0.0 && hi > 10.0);
        assert_eq!(decade_range(-15.5, -12.7), (-16.0, -12.0));
        assert_eq!(decade_range(-17.0, -17.0), (-17.0, -16.0));
        assert_eq!(decade_label(-16.0), "1e-16");
        assert_eq!(decade_label(0.0), "1e0");
    }
}
