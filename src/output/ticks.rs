//! Tick labels of a linear axis: one notation for every tick of an axis (plain, or scientific when the axis reaches
//! 1e5 or stays below 1e-4), as many digits as the tick spacing needs, and — when the span is under a thousandth of
//! the values, where every label would repeat the same leading digits — an offset taken out of the labels and
//! written into the axis title ("energy (J) − 6.045").

/// How the ticks of one linear axis over [lo, hi] are written.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LinearTicks {
    /// Subtracted from every value before it is written; 0 unless the axis is narrow.
    offset: f64,
    /// The offset as written in the title (empty when there is none).
    offset_text: String,
    /// Scientific notation for every label.
    scientific: bool,
    /// The decade of the tick spacing's resolution (a hundredth of the span).
    resolution_exp: i32,
    /// Labels below this magnitude are written "0".
    zero_below: f64,
}

impl LinearTicks {
    /// The ticks of an axis spanning [lo, hi].
    pub(crate) fn new(lo: f64, hi: f64) -> Self {
        let span = (hi - lo).abs();
        let scale = lo.abs().max(hi.abs());
        // Ticks are at least a hundredth of the span apart.
        let resolution = (span / 100.0).max(f64::MIN_POSITIVE);
        let resolution_exp = resolution.log10().floor() as i32;
        let (offset, offset_text) = if span > 0.0 && span < 1e-3 * scale {
            // The midpoint rounded to the decade above the span: the labels keep only the digits that change.
            let decade = span.log10().floor() as i32 + 1;
            let decimals = (-decade).clamp(0, 17) as usize;
            let text = trim_zeros(&format!("{:.decimals$}", 0.5 * (lo + hi))).to_string();
            (text.parse().unwrap_or(0.0), text)
        } else {
            (0.0, String::new())
        };
        let reach = (lo - offset).abs().max((hi - offset).abs());
        let magnitude = reach.max(f64::MIN_POSITIVE).log10().floor() as i32;
        Self {
            offset,
            offset_text,
            scientific: magnitude >= 5 || magnitude <= -4,
            resolution_exp,
            zero_below: resolution * 1e-3,
        }
    }

    /// The label of the tick at `v`.
    pub(crate) fn label(&self, v: f64) -> String {
        let v = v - self.offset;
        if v.abs() < self.zero_below {
            return "0".into();
        }
        if self.scientific {
            let magnitude = v.abs().log10().floor() as i32;
            let digits = (magnitude - self.resolution_exp).clamp(0, 12) as usize;
            let text = format!("{v:.digits$e}");
            match text.split_once('e') {
                Some((mantissa, exp)) => format!("{}e{exp}", trim_zeros(mantissa)),
                None => text,
            }
        } else {
            let decimals = (-self.resolution_exp).clamp(0, 15) as usize;
            trim_zeros(&format!("{v:.decimals$}")).to_string()
        }
    }

    /// The axis title with the offset, if any: "energy (J) − 6.045".
    pub(crate) fn title(&self, title: &str) -> String {
        match self.offset_text.strip_prefix('-') {
            _ if self.offset_text.is_empty() => title.to_string(),
            Some(negative) => format!("{title} + {negative}"),
            None => format!("{title} − {}", self.offset_text),
        }
    }
}

/// "2.50" -> "2.5", "3.000" -> "3"; integers unchanged.
fn trim_zeros(number: &str) -> &str {
    if number.contains('.') {
        number.trim_end_matches('0').trim_end_matches('.')
    } else {
        number
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn label(v: f64, lo: f64, hi: f64) -> String {
        LinearTicks::new(lo, hi).label(v)
    }

    #[test]
    fn labels_use_the_digits_the_spacing_needs() {
        assert_eq!(label(0.5, 0.0, 1.0), "0.5");
        assert_eq!(label(3.95, 3.7, 4.2), "3.95");
        assert_eq!(label(1e-18, -1.0, 1.0), "0");
        assert_eq!(label(2.5e-6, 0.0, 1e-5), "2.5e-6");
        assert_eq!(label(30.0, 0.0, 60.0), "30");
        assert_eq!(label(-0.3000000000000001, -1.0, 1.0), "-0.3");
        assert_eq!(label(2e5, 0.0, 1e6), "2e5");
    }

    #[test]
    fn one_notation_for_every_tick_of_an_axis() {
        // A run to t = 1e5 s: 90000 and 1e5 on the same axis were written in two notations.
        let t = LinearTicks::new(0.0, 1e5);
        assert_eq!(t.label(9e4), "9e4");
        assert_eq!(t.label(1e5), "1e5");
        assert_eq!(t.label(0.0), "0");
        let small = LinearTicks::new(0.0, 100.0);
        assert_eq!(small.label(90.0), "90");
    }

    #[test]
    fn a_narrow_axis_takes_its_offset_into_the_title() {
        // An energy conserved to 1e-8 J around 6.045 J: the labels were "6.044999992", wider than the label area.
        let t = LinearTicks::new(6.044_999_99, 6.045_000_01);
        assert_eq!(t.title("energy (J)"), "energy (J) − 6.045");
        assert_eq!(t.label(6.045_000_005), "5e-9");
        assert_eq!(t.label(6.044_999_992), "-8e-9");
        assert!(t.label(6.045).len() <= 2);
        let negative = LinearTicks::new(-2.000_001, -1.999_999);
        assert_eq!(negative.title("M_b_x (N*m)"), "M_b_x (N*m) + 2");
        assert_eq!(negative.label(-1.999_999_5), "5e-7");
        // A wide axis has no offset.
        assert_eq!(LinearTicks::new(0.0, 10.0).title("t (s)"), "t (s)");
    }
}
