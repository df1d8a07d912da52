//! The figure's size and its grid of panels.
//!
//! Sizes are in centimetres. The SVG's unit is the CSS pixel, 1/96 inch, so a figure W cm wide is
//! W · 96 / 2.54 px wide (16 cm: 605 px) and prints at W cm when placed at its own size. Text sizes follow from
//! 1 pt = 1/72 inch = 96/72 px: every text of the figure (tick labels, axis titles, legends) is at least
//! [`TEXT_PX`] = 12 px = 9 pt, whatever the figure's size; in a 16 cm figure that is 1.98 % of its width.
//!
//! Panels are laid out in a grid: one column for one or two panels, two columns for three or more, filled row by
//! row in the order given. The default size is 16 cm wide (a page's text width) and as tall as the rows need:
//! [`CELL_HEIGHT_CM`] per row (7 cm for two columns) plus [`TITLE_CM`] for the title.

use std::str::FromStr;

/// Pixels (1/96 inch) per centimetre.
pub const PX_PER_CM: f64 = 96.0 / 2.54;

/// The default figure width (cm).
pub const DEFAULT_WIDTH_CM: f64 = 16.0;

/// The height of a grid row (cm) by default: one column of panels, two columns.
pub const CELL_HEIGHT_CM: [f64; 2] = [6.0, 7.0];

/// The height of the figure's title band (cm), when it has a title.
pub const TITLE_CM: f64 = 0.9;

/// The smallest panel (cm, width and height) a requested size may give.
pub const MIN_CELL_CM: (f64, f64) = (6.0, 4.5);

/// The smallest and largest width or height (cm) that `--size` accepts.
pub const SIZE_RANGE_CM: (f64, f64) = (4.0, 200.0);

/// Pixels of `points` (1/72 inch).
pub const fn pt_to_px(points: f64) -> f64 {
    points * 96.0 / 72.0
}

/// The size of tick labels, axis titles and legends (px): 9 pt.
pub const TEXT_PX: f64 = pt_to_px(9.0);
/// The size of a panel's title (px): 10 pt.
pub const CAPTION_PX: f64 = pt_to_px(10.0);
/// The size of the figure's title (px): 11 pt.
pub const TITLE_PX: f64 = pt_to_px(11.0);

/// A figure's size in centimetres, as `--size W,H` gives it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FigureSize {
    /// Width (cm).
    pub width_cm: f64,
    /// Height (cm).
    pub height_cm: f64,
}

impl FigureSize {
    /// The size in whole pixels (1/96 inch).
    pub fn pixels(self) -> (u32, u32) {
        let px = |cm: f64| (cm * PX_PER_CM).round() as u32;
        (px(self.width_cm), px(self.height_cm))
    }
}

impl FromStr for FigureSize {
    type Err = String;

    /// `W,H` in centimetres, each a number in [`SIZE_RANGE_CM`].
    fn from_str(text: &str) -> Result<Self, String> {
        let (lo, hi) = SIZE_RANGE_CM;
        let usage = format!(
            "give the figure's width and height in centimetres as W,H, e.g. 16,12 (each from {lo} to {hi})"
        );
        let Some((w, h)) = text.split_once(',') else {
            return Err(format!("\"{text}\" is not W,H; {usage}"));
        };
        let number = |part: &str| -> Result<f64, String> {
            match part.trim().parse::<f64>() {
                Ok(v) if (lo..=hi).contains(&v) => Ok(v),
                Ok(_) => Err(format!("{} cm is out of range; {usage}", part.trim())),
                Err(_) => Err(format!("\"{}\" is not a number; {usage}", part.trim())),
            }
        };
        Ok(Self {
            width_cm: number(w)?,
            height_cm: number(h)?,
        })
    }
}

/// Panels in rows and columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Grid {
    /// Panels across.
    pub columns: usize,
    /// Panels down.
    pub rows: usize,
}

impl Grid {
    /// The grid of `panels` panels: one column for up to two, else two columns.
    pub fn for_panels(panels: usize) -> Self {
        let columns = if panels <= 2 { 1 } else { 2 };
        Self {
            columns,
            rows: panels.max(1).div_ceil(columns),
        }
    }

    /// The figure's size: `requested`, or the default for this grid; a requested size that leaves a panel smaller
    /// than [`MIN_CELL_CM`] is refused with the smallest size that fits.
    pub fn figure_size(
        self,
        requested: Option<FigureSize>,
        titled: bool,
    ) -> Result<FigureSize, String> {
        let title = if titled { TITLE_CM } else { 0.0 };
        let Some(size) = requested else {
            return Ok(FigureSize {
                width_cm: DEFAULT_WIDTH_CM,
                height_cm: title + self.rows as f64 * CELL_HEIGHT_CM[self.columns.min(2) - 1],
            });
        };
        let cell = (
            size.width_cm / self.columns as f64,
            (size.height_cm - title) / self.rows as f64,
        );
        if cell.0 < MIN_CELL_CM.0 || cell.1 < MIN_CELL_CM.1 {
            let need_w = MIN_CELL_CM.0 * self.columns as f64;
            let need_h = MIN_CELL_CM.1 * self.rows as f64 + title;
            return Err(format!(
                "{},{} cm is too small for {} row(s) of {} panel(s): each panel needs at least {} x {} cm, so give at least {need_w},{need_h:.1}",
                size.width_cm,
                size.height_cm,
                self.rows,
                self.columns,
                MIN_CELL_CM.0,
                MIN_CELL_CM.1
            ));
        }
        Ok(size)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nine_points_are_twelve_pixels_and_sixteen_centimetres_are_605() {
        assert_eq!(TEXT_PX, 12.0);
        let size = FigureSize {
            width_cm: 16.0,
            height_cm: 12.0,
        };
        assert_eq!(size.pixels(), (605, 454));
    }

    #[test]
    fn sizes_parse_and_bad_ones_are_refused() {
        let size: FigureSize = "16, 12.5".parse().unwrap();
        assert_eq!((size.width_cm, size.height_cm), (16.0, 12.5));
        for bad in ["16", "16x12", "a,12", "0,12", "16,-1", "16,1e9", "16,nan"] {
            assert!(bad.parse::<FigureSize>().is_err(), "{bad}");
        }
    }

    #[test]
    fn grids_have_two_columns_from_three_panels_and_small_sizes_are_refused() {
        for (panels, columns, rows) in [(1, 1, 1), (2, 1, 2), (3, 2, 2), (6, 2, 3)] {
            assert_eq!(
                Grid::for_panels(panels),
                Grid { columns, rows },
                "{panels} panels"
            );
        }
        let six = Grid::for_panels(6).figure_size(None, true).unwrap();
        assert_eq!((six.width_cm, six.height_cm), (16.0, 21.9));
        let small = FigureSize {
            width_cm: 10.0,
            height_cm: 10.0,
        };
        let e = Grid::for_panels(6)
            .figure_size(Some(small), true)
            .unwrap_err();
        assert!(e.contains("at least 12,14.4"), "{e}");
    }
}
