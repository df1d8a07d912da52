//! Text set as outlines: each `<text>` element of a figure's SVG becomes one `<path>` of the embedded font's glyph
//! outlines (read by `ttf-parser`), so that the rasteriser needs no text engine and the PNG looks the same on every
//! machine.
//!
//! The layout is a single line, as plotters writes it: glyph advances from `hmtx`, pair kerning from the font's
//! `kern` table, `text-anchor` (start, middle, end) against the total advance, and `dy` in `em` (the font size),
//! `ex` (the font's x-height, `OS/2` sxHeight, or half an em where the font
//! does not give it, as CSS does) or user units. A glyph point (u, v) in font units lands at
//! (x + s·(pen + u), y + dy − s·v) with s = font-size / unitsPerEm. `fill`, `opacity` and `transform` are kept;
//! bold and italic are not synthesised (the figures use neither).

use std::fmt::Write as _;

use ttf_parser::{Face, GlyphId, OutlineBuilder};

/// The SVG `svg` with every `<text>` element replaced by the outlines of its text in the font `font` (TrueType
/// bytes); the error says what could not be read.
pub(super) fn outline_text(svg: &str, font: &[u8]) -> Result<String, String> {
    let face =
        Face::parse(font, 0).map_err(|e| format!("the embedded font cannot be read: {e}"))?;
    let mut out = String::with_capacity(svg.len());
    let mut rest = svg;
    while let Some(open) = rest.find("<text") {
        out.push_str(&rest[..open]);
        let element = &rest[open..];
        let head_end = element
            .find('>')
            .ok_or("the figure's SVG has an unterminated <text> element")?;
        let close = element
            .find("</text>")
            .ok_or("the figure's SVG has a <text> element without </text>")?;
        let attributes = parse_attributes(&element["<text".len()..head_end])?;
        let text = collapse_whitespace(&decode_entities(&element[head_end + 1..close]));
        write_path(&mut out, &face, &attributes, &text)?;
        rest = &element[close + "</text>".len()..];
    }
    out.push_str(rest);
    Ok(out)
}

/// The attributes of an element's start tag (the text between its name and `>`), in order.
fn parse_attributes(head: &str) -> Result<Vec<(&str, &str)>, String> {
    let mut attributes = Vec::new();
    let mut rest = head.trim_start();
    while !rest.is_empty() && rest != "/" {
        let (name, after) = rest
            .split_once("=\"")
            .ok_or_else(|| format!("cannot read the <text> attributes \"{head}\""))?;
        let (value, after) = after
            .split_once('"')
            .ok_or_else(|| format!("cannot read the <text> attributes \"{head}\""))?;
        attributes.push((name.trim(), value));
        rest = after.trim_start();
    }
    Ok(attributes)
}

/// `text` with the XML entities (`&amp;`, `&lt;`, `&gt;`, `&quot;`, `&apos;`, `&#…;`, `&#x…;`) replaced.
fn decode_entities(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(amp) = rest.find('&') {
        out.push_str(&rest[..amp]);
        let after = &rest[amp + 1..];
        let decoded = after.split_once(';').and_then(|(name, tail)| {
            let c = match name {
                "amp" => Some('&'),
                "lt" => Some('<'),
                "gt" => Some('>'),
                "quot" => Some('"'),
                "apos" => Some('\''),
                _ => name
                    .strip_prefix("#x")
                    .map(|hex| u32::from_str_radix(hex, 16))
                    .or_else(|| name.strip_prefix('#').map(str::parse))
                    .and_then(Result::ok)
                    .and_then(char::from_u32),
            }?;
            Some((c, tail))
        });
        match decoded {
            Some((c, tail)) => {
                out.push(c);
                rest = tail;
            }
            None => {
                out.push('&');
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

/// SVG's default white-space handling: newlines removed, tabs made spaces, leading and trailing spaces dropped,
/// runs of spaces made one.
fn collapse_whitespace(text: &str) -> String {
    let joined: String = text
        .chars()
        .filter(|&c| c != '\n' && c != '\r')
        .map(|c| if c == '\t' { ' ' } else { c })
        .collect();
    joined
        .split(' ')
        .filter(|w| !w.is_empty())
        .collect::<Vec<_>>()
        .join(" ")
}

/// Writes the `<path>` of `text` laid out by `attributes` (module docs).
fn write_path(
    out: &mut String,
    face: &Face<'_>,
    attributes: &[(&str, &str)],
    text: &str,
) -> Result<(), String> {
    let get = |name: &str| attributes.iter().find(|(n, _)| *n == name).map(|(_, v)| *v);
    let number = |name: &str, default: f64| -> Result<f64, String> {
        get(name).map_or(Ok(default), |v| {
            v.parse()
                .map_err(|_| format!("the <text> attribute {name}=\"{v}\" is not a number"))
        })
    };
    let font_size = number("font-size", 16.0)?;
    let (x, y) = (number("x", 0.0)?, number("y", 0.0)?);
    let per_unit = font_size / f64::from(face.units_per_em());
    let dy = get("dy").map_or(Ok(0.0), |v| length(v, font_size, face))?;
    let glyphs: Vec<GlyphId> = text
        .chars()
        .map(|c| face.glyph_index(c).unwrap_or(GlyphId(0)))
        .collect();
    let pens = pen_positions(face, &glyphs);
    let advance = pens.last().copied().unwrap_or(0.0);
    let shift = match get("text-anchor") {
        Some("middle") => -advance / 2.0,
        Some("end") => -advance,
        _ => 0.0,
    };
    let mut outline = Outline {
        d: String::new(),
        origin: (x, y + dy),
        scale: per_unit,
        pen: 0.0,
    };
    for (glyph, pen) in glyphs.iter().zip(&pens) {
        outline.pen = pen + shift;
        face.outline_glyph(*glyph, &mut outline);
    }
    out.push_str("<path d=\"");
    out.push_str(outline.d.trim_end());
    out.push('"');
    for name in ["opacity", "fill", "transform"] {
        if let Some(value) = get(name) {
            let _ = write!(out, " {name}=\"{value}\"");
        }
    }
    out.push_str("/>");
    Ok(())
}

/// Each glyph's pen position (font units from the start of the line), then the line's total advance.
fn pen_positions(face: &Face<'_>, glyphs: &[GlyphId]) -> Vec<f64> {
    let kerning = |left: GlyphId, right: GlyphId| -> f64 {
        face.tables().kern.map_or(0.0, |kern| {
            kern.subtables
                .into_iter()
                .filter(|t| t.horizontal && !t.variable)
                .find_map(|t| t.glyphs_kerning(left, right))
                .map_or(0.0, f64::from)
        })
    };
    let mut pens = Vec::with_capacity(glyphs.len() + 1);
    let mut pen = 0.0;
    for (i, glyph) in glyphs.iter().enumerate() {
        if i > 0 {
            pen += kerning(glyphs[i - 1], *glyph);
        }
        pens.push(pen);
        pen += f64::from(face.glyph_hor_advance(*glyph).unwrap_or(0));
    }
    pens.push(pen);
    pens
}

/// An SVG length `value` in user units: a number, or one followed by `em` (× `font_size`) or `ex` (× the font's
/// x-height at `font_size`).
fn length(value: &str, font_size: f64, face: &Face<'_>) -> Result<f64, String> {
    let bad = || format!("the <text> attribute dy=\"{value}\" is not a length");
    let (number, unit) = match value {
        v if v.ends_with("em") => (&v[..v.len() - 2], font_size),
        v if v.ends_with("ex") => {
            let x_height = face
                .x_height()
                .map_or(0.5, |h| f64::from(h) / f64::from(face.units_per_em()));
            (&v[..v.len() - 2], x_height * font_size)
        }
        v => (v, 1.0),
    };
    number
        .trim()
        .parse::<f64>()
        .map(|n| n * unit)
        .map_err(|_| bad())
}

/// Path data of glyph outlines: font units (u, v) at pen position `pen` mapped to (x₀ + s·(pen + u), y₀ − s·v).
struct Outline {
    d: String,
    origin: (f64, f64),
    scale: f64,
    pen: f64,
}

impl Outline {
    fn point(&mut self, u: f32, v: f32) {
        let x = self.origin.0 + self.scale * (self.pen + f64::from(u));
        let y = self.origin.1 - self.scale * f64::from(v);
        let _ = write!(self.d, "{x:.2} {y:.2} ");
    }
}

impl OutlineBuilder for Outline {
    fn move_to(&mut self, x: f32, y: f32) {
        self.d.push('M');
        self.point(x, y);
    }
    fn line_to(&mut self, x: f32, y: f32) {
        self.d.push('L');
        self.point(x, y);
    }
    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        self.d.push('Q');
        self.point(x1, y1);
        self.point(x, y);
    }
    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        self.d.push('C');
        self.point(x1, y1);
        self.point(x2, y2);
        self.point(x, y);
    }
    fn close(&mut self) {
        self.d.push_str("Z ");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FONT: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");

    /// The extent (x min, x max, y min, y max) of the numbers of a path's `d`.
    fn extent(svg: &str) -> (f64, f64, f64, f64) {
        let d = svg.split("d=\"").nth(1).unwrap().split('"').next().unwrap();
        let numbers: Vec<f64> = d
            .split(|c: char| c.is_ascii_alphabetic() || c == ' ')
            .filter(|s| !s.is_empty())
            .map(|s| s.parse().unwrap())
            .collect();
        let (xs, ys): (Vec<f64>, Vec<f64>) = numbers.chunks(2).map(|p| (p[0], p[1])).unzip();
        let min = |v: &[f64]| v.iter().copied().fold(f64::INFINITY, f64::min);
        let max = |v: &[f64]| v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        (min(&xs), max(&xs), min(&ys), max(&ys))
    }

    #[test]
    fn a_capital_h_stands_on_the_baseline_at_the_fonts_cap_height() {
        // DejaVu Sans: unitsPerEm 2048, 'H' from y = 0 to its cap height 1493 (the font's glyf table).
        let svg = r#"<svg><text x="100" y="500" font-size="2048">H</text></svg>"#;
        let out = outline_text(svg, FONT).unwrap();
        assert!(
            out.starts_with("<svg><path d=\"M") && out.ends_with("/></svg>"),
            "{out}"
        );
        let (_, _, y_min, y_max) = extent(&out);
        assert!((y_max - 500.0).abs() < 0.01, "baseline: {y_max}");
        assert!(
            (y_min - (500.0 - 1493.0)).abs() < 0.01,
            "cap height: {y_min}"
        );
    }

    #[test]
    fn anchors_place_the_line_by_its_advance() {
        let at = |anchor: &str| {
            let svg = format!(
                r#"<text x="1000" y="0" text-anchor="{anchor}" font-size="100">t (s)</text>"#
            );
            extent(&outline_text(&svg, FONT).unwrap())
        };
        // DejaVu Sans's advances (hmtx): t 803, space 651, ( 799, s 1067, ) 799: 4119 units of 2048 an em.
        let advance = 4119.0 / 2048.0 * 100.0;
        let (start, middle, end) = (at("start"), at("middle"), at("end"));
        assert!(
            (start.0 - end.0 - advance).abs() < 0.02,
            "{start:?} {end:?}"
        );
        assert!(
            (start.0 - middle.0 - advance / 2.0).abs() < 0.02,
            "{middle:?}"
        );
        assert!(start.0 >= 1000.0 && end.1 <= 1000.0, "{start:?} {end:?}");
    }

    #[test]
    fn dy_in_em_and_ex_moves_the_baseline() {
        let base = |dy: &str| {
            let svg = format!(r#"<text x="0" y="0" dy="{dy}" font-size="2048">H</text>"#);
            extent(&outline_text(&svg, FONT).unwrap()).3
        };
        assert!((base("0.76em") - 0.76 * 2048.0).abs() < 0.01);
        // DejaVu Sans's OS/2 table (version 1) has no sxHeight: an ex is then half an em, as in CSS and usvg.
        assert!((base("-0.5ex") + 512.0).abs() < 0.01);
        assert!((base("12") - 12.0).abs() < 0.01);
    }

    #[test]
    fn paint_and_rotation_are_kept_and_entities_read() {
        let svg = r##"<text x="16" y="526" dy="0.76em" text-anchor="middle" font-family="sans-serif" font-size="48.4" opacity="1" fill="#000000" transform="rotate(270, 16, 526)">
a &amp; b &lt; ω
</text>"##;
        let out = outline_text(svg, FONT).unwrap();
        assert!(
            out.ends_with(r##" opacity="1" fill="#000000" transform="rotate(270, 16, 526)"/>"##),
            "{out}"
        );
        assert_eq!(
            collapse_whitespace(&decode_entities("\na &amp; b &lt; &#969;&#x3c9;\n")),
            "a & b < ωω"
        );
        assert_eq!(decode_entities("R&D & more"), "R&D & more");
    }

    #[test]
    fn unreadable_text_elements_are_refused() {
        assert!(outline_text("<text x=\"1\" y=\"2\">a", FONT).is_err());
        assert!(
            outline_text("<text x=\"one\">a</text>", FONT)
                .unwrap_err()
                .contains("x=\"one\"")
        );
        assert!(outline_text("<text dy=\"1furlong\">a</text>", FONT).is_err());
        assert!(outline_text("<svg/>", &[0, 1, 2]).is_err());
    }
}
