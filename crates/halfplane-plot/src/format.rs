//! Numbers as a reader of a paper expects them: plain notation (430.9, 0.0012, 12000), scientific
//! only for the very small or very large (1.5e-7), a true minus sign and never "−0".

/// Significant digits of a plain number (the integer part is always shown whole).
const SIGNIFICANT: i32 = 4;
/// Plain notation from this magnitude up (smaller: scientific).
const SMALLEST_PLAIN: f64 = 1e-4;
/// Plain notation below this magnitude (larger: scientific).
const LARGEST_PLAIN: f64 = 1e7;

/// `v` with four significant digits, trailing zeros dropped: "430.9" for 430.87,
/// "0.0012", "12000" (whole numbers keep every digit), "1.5e-7" below 1e-4 and "2.5e7" from 1e7,
/// "0" for zero of either sign, "−250" with a true minus sign; "NaN" and "∞" as such.
pub fn number(v: f64) -> String {
    if v.is_nan() {
        return "NaN".into();
    }
    if v.is_infinite() {
        return if v > 0.0 { "∞" } else { "−∞" }.into();
    }
    let m = v.abs();
    if m == 0.0 {
        return "0".into();
    }
    let text = if (SMALLEST_PLAIN..LARGEST_PLAIN).contains(&m) {
        let digits = m.log10().floor() as i32 + 1;
        let decimals = (SIGNIFICANT - digits).max(0) as usize;
        trim(&format!("{v:.decimals$}"))
    } else {
        let s = format!("{:.*e}", (SIGNIFICANT - 1) as usize, v);
        let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
        format!("{}e{exponent}", trim(mantissa))
    };
    signed(&text)
}

/// The labels of evenly spaced levels, all with `decimals` decimals (0.025, 0.050, 0.075), as
/// [`crate::levels`] gives them; levels finer than 1e-4 or beyond 1e7 as [`number`].
pub fn level_labels(levels: &[f64], decimals: usize) -> Vec<String> {
    let plain = levels
        .iter()
        .all(|l| l.abs() < LARGEST_PLAIN && (*l == 0.0 || decimals <= 4));
    levels
        .iter()
        .map(|&l| {
            if plain {
                signed(&format!("{l:.decimals$}"))
            } else {
                number(l)
            }
        })
        .collect()
}

/// Drops trailing zeros after a decimal point (and the point itself).
fn trim(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// A true minus sign, and no sign on a zero ("−0.00" is "0.00").
fn signed(s: &str) -> String {
    let body = s.strip_prefix('-').unwrap_or(s);
    if body.chars().all(|c| matches!(c, '0' | '.')) {
        body.to_string()
    } else if s.starts_with('-') {
        format!("−{body}")
    } else {
        body.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_plain_with_four_significant_digits() {
        for (v, want) in [
            (430.8712, "430.9"),
            (0.0012, "0.0012"),
            (0.00123456, "0.001235"),
            (1.5e-7, "1.5e-7"),
            (12000.0, "12000"),
            (123456.0, "123456"),
            (60.978, "60.98"),
            (-250.0, "−250"),
            (0.5, "0.5"),
            (1.0, "1"),
            (0.0, "0"),
            (-0.0, "0"),
            (2.5e7, "2.5e7"),
            (-3.25e-9, "−3.25e-9"),
            (9.99996, "10"),
        ] {
            assert_eq!(number(v), want, "{v}");
        }
        assert_eq!(number(f64::NAN), "NaN");
        assert_eq!(number(f64::NEG_INFINITY), "−∞");
    }

    #[test]
    fn level_labels_share_their_decimals() {
        let (levels, decimals) = crate::levels(0.0, 0.2, 8);
        let labels = level_labels(&levels, decimals);
        assert_eq!(labels[..3], ["0.025", "0.050", "0.075"]);
        let (levels, decimals) = crate::levels(-330.0, 470.0, 9);
        assert_eq!(
            level_labels(&levels, decimals),
            ["−300", "−200", "−100", "0", "100", "200", "300", "400"]
        );
        let (levels, decimals) = crate::levels(0.0, 4e-7, 4);
        assert_eq!(level_labels(&levels, decimals), ["1e-7", "2e-7", "3e-7"]);
    }
}
