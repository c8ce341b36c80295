//! Numbers in messages, as people write them: `1e300`, not a 301-digit decimal.

use std::fmt;

/// A value shown in an error message as a person would type it: Rust's shortest round-trip
/// digits, in plain notation for 1e-4 <= |x| < 1e16 (and 0), where that has no long runs of zeros
/// (`0.3`, `-250`, `200000`), and in scientific notation outside it (`1e300`, `-2.5e-7`). Either
/// form reads back as the same `f64`, so a message never changes the value it reports.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Written(pub f64);

impl fmt::Display for Written {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        let plain = x == 0.0 || !x.is_finite() || (1e-4..1e16).contains(&x.abs());
        if plain {
            write!(f, "{x}")
        } else {
            write!(f, "{x:e}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Written;

    #[test]
    fn values_read_as_typed_and_round_trip() {
        let cases: [(f64, &str); 9] = [
            (1e300, "1e300"),
            (-1.5e-7, "-1.5e-7"),
            (1e16, "1e16"),
            (9_999_999_999_999_998.0, "9999999999999998"),
            (1e-4, "0.0001"),
            (0.3, "0.3"),
            (-250.0, "-250"),
            (0.0, "0"),
            (f64::NAN, "NaN"),
        ];
        for (x, expected) in cases {
            let shown = Written(x).to_string();
            assert_eq!(shown, expected);
            if x.is_finite() {
                assert_eq!(shown.parse::<f64>().unwrap(), x, "{shown} reads back");
            }
        }
    }
}
