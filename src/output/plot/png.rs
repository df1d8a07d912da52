//! PNG output: the figure's SVG rasterised by resvg (pure Rust: usvg parses, tiny-skia paints) on a white
//! background. Its text is first set as outlines of DejaVu Sans (`glyphs`), embedded in the program
//! (`assets/fonts/`, Bitstream Vera licence), which stands for the SVG's `sans-serif`: no system font is looked up,
//! so the PNG is the same on every machine.
//!
//! A PNG at `dpi` pixels per inch of a figure W cm wide is round(W / 2.54 · dpi) pixels wide: a 16 cm figure at
//! 300 dpi is 1890 px wide.

use resvg::tiny_skia::{Color, Pixmap, Transform};
use resvg::usvg;

use super::FigureSize;
use super::glyphs;

/// The resolution of a PNG unless asked otherwise (pixels per inch): print quality.
pub const DEFAULT_DPI: f64 = 300.0;

/// The resolutions `--dpi` accepts.
pub const DPI_RANGE: (f64, f64) = (24.0, 1200.0);

/// The font every text of a PNG is set in.
const FONT_DATA: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");

/// A PNG file's bytes and its size in pixels.
pub(super) struct PngImage {
    pub(super) bytes: Vec<u8>,
    pub(super) pixels: (u32, u32),
}

/// The PNG, `pixels` wide and high, of the SVG text `svg` (scaled to fill it).
pub(super) fn rasterise(svg: &str, pixels: (u32, u32)) -> Result<PngImage, String> {
    let svg = glyphs::outline_text(svg, FONT_DATA)?;
    let tree = usvg::Tree::from_str(&svg, &usvg::Options::default())
        .map_err(|e| format!("cannot read the figure's SVG for the PNG: {e}"))?;
    let size = tree.size();
    let mut pixmap = Pixmap::new(pixels.0, pixels.1).ok_or_else(|| {
        format!(
            "a PNG of {} x {} pixels cannot be made; give a smaller --size or --dpi",
            pixels.0, pixels.1
        )
    })?;
    pixmap.fill(Color::WHITE);
    let scale = Transform::from_scale(
        pixels.0 as f32 / size.width(),
        pixels.1 as f32 / size.height(),
    );
    resvg::render(&tree, scale, &mut pixmap.as_mut());
    let bytes = pixmap
        .encode_png()
        .map_err(|e| format!("cannot encode the PNG: {e}"))?;
    Ok(PngImage { bytes, pixels })
}

/// The size in pixels of a PNG of a figure of `size` at `dpi` pixels per inch.
pub(super) fn png_pixels(size: FigureSize, dpi: f64) -> (u32, u32) {
    let px = |cm: f64| (cm / 2.54 * dpi).round() as u32;
    (px(size.width_cm), px(size.height_cm))
}

/// A `--dpi` value: a number in [`DPI_RANGE`].
pub fn parse_dpi(text: &str) -> Result<f64, String> {
    let (lo, hi) = DPI_RANGE;
    match text.trim().parse::<f64>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(format!(
            "\"{text}\" is not a resolution; give pixels per inch from {lo} to {hi}, e.g. 300"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_png_has_the_pixel_size_of_its_centimetres_at_its_dpi() {
        let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="100" height="50"><text x="10" y="30" font-family="sans-serif" font-size="12">ω θ</text></svg>"#;
        let image = rasterise(svg, (100, 50)).unwrap();
        assert_eq!(image.pixels, (100, 50));
        assert!(image.bytes.starts_with(b"\x89PNG\r\n\x1a\n"));
        let size = FigureSize {
            width_cm: 16.0,
            height_cm: 10.0,
        };
        assert_eq!(png_pixels(size, 300.0), (1890, 1181));
        assert_eq!(png_pixels(size, 96.0), (605, 378));
    }

    #[test]
    fn text_is_drawn_with_the_embedded_font() {
        let blank = r#"<svg xmlns="http://www.w3.org/2000/svg" width="60" height="20"></svg>"#;
        let text = r#"<svg xmlns="http://www.w3.org/2000/svg" width="60" height="20"><text x="2" y="15" font-family="sans-serif" font-size="12">ω_b,x</text></svg>"#;
        assert_ne!(
            rasterise(blank, (60, 20)).unwrap().bytes,
            rasterise(text, (60, 20)).unwrap().bytes
        );
    }

    #[test]
    fn dpi_values_out_of_range_are_refused() {
        assert_eq!(parse_dpi("300"), Ok(300.0));
        for bad in ["0", "-5", "abc", "5000", "nan"] {
            assert!(parse_dpi(bad).is_err(), "{bad}");
        }
    }
}
