//! PNG output: the figure's SVG rasterised by resvg (pure Rust: usvg parses, tiny-skia paints) on a white
//! background. Text is set in DejaVu Sans, embedded in the program (`assets/fonts/`, Bitstream Vera licence), which
//! stands for the SVG's `sans-serif`: no system font is looked up, so the PNG is the same on every machine.
//!
//! The SVG's unit is 1/96 inch, so a PNG at `dpi` pixels per inch is the SVG scaled by dpi / 96: a 16 cm figure
//! at 300 dpi is 1890 px wide.

use resvg::tiny_skia::{Color, Pixmap, Transform};
use resvg::usvg;

/// The resolution of a PNG unless asked otherwise (pixels per inch): print quality.
pub const DEFAULT_DPI: f64 = 300.0;

/// The resolutions `--dpi` accepts.
pub const DPI_RANGE: (f64, f64) = (24.0, 1200.0);

/// The font every text of a PNG is set in.
const FONT_DATA: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");
const FONT_FAMILY: &str = "DejaVu Sans";

/// A PNG file's bytes and its size in pixels.
pub(super) struct PngImage {
    pub(super) bytes: Vec<u8>,
    pub(super) pixels: (u32, u32),
}

/// The PNG of the SVG text `svg` at `dpi` pixels per inch.
pub(super) fn rasterise(svg: &str, dpi: f64) -> Result<PngImage, String> {
    let mut options = usvg::Options {
        font_family: FONT_FAMILY.into(),
        ..usvg::Options::default()
    };
    let fonts = options.fontdb_mut();
    fonts.load_font_data(FONT_DATA.to_vec());
    fonts.set_sans_serif_family(FONT_FAMILY);
    let tree = usvg::Tree::from_str(svg, &options)
        .map_err(|e| format!("cannot read the figure's SVG for the PNG: {e}"))?;
    let scale = (dpi / 96.0) as f32;
    let size = tree.size();
    let pixels = (
        (size.width() * scale).round() as u32,
        (size.height() * scale).round() as u32,
    );
    let mut pixmap = Pixmap::new(pixels.0, pixels.1).ok_or_else(|| {
        format!(
            "a PNG of {} x {} pixels is too large; give a smaller --size or --dpi",
            pixels.0, pixels.1
        )
    })?;
    pixmap.fill(Color::WHITE);
    resvg::render(
        &tree,
        Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    let bytes = pixmap
        .encode_png()
        .map_err(|e| format!("cannot encode the PNG: {e}"))?;
    Ok(PngImage { bytes, pixels })
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
    fn a_96_dpi_png_has_the_svgs_pixel_size_and_300_dpi_scales_it() {
        let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="100" height="50"><text x="10" y="30" font-family="sans-serif" font-size="12">ω θ</text></svg>"#;
        let image = rasterise(svg, 96.0).unwrap();
        assert_eq!(image.pixels, (100, 50));
        assert!(image.bytes.starts_with(b"\x89PNG\r\n\x1a\n"));
        assert_eq!(rasterise(svg, 300.0).unwrap().pixels, (313, 156));
    }

    #[test]
    fn text_is_drawn_with_the_embedded_font() {
        let blank = r#"<svg xmlns="http://www.w3.org/2000/svg" width="60" height="20"></svg>"#;
        let text = r#"<svg xmlns="http://www.w3.org/2000/svg" width="60" height="20"><text x="2" y="15" font-family="sans-serif" font-size="12">ω_b,x</text></svg>"#;
        assert_ne!(
            rasterise(blank, 96.0).unwrap().bytes,
            rasterise(text, 96.0).unwrap().bytes
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
