//! Counts as the case file gives them ([`RawCount`]), checked into a `usize` with an error that
//! names the field, the value and the valid range ([`count_in`]).

use super::FieldError;
use anyhow::Result;
use serde::{Deserialize, Deserializer};

/// A count as the case file gives it. Any TOML value is taken here and checked when resolved,
/// so that the error names the field, the value and the valid range (serde's own message would
/// say "expected usize", and a negative or huge integer would not name the field).
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum RawCount {
    Integer(i128),
    Float(f64),
    /// Anything else, as written.
    Other(String),
}

impl<'de> Deserialize<'de> for RawCount {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct Visitor;
        impl serde::de::Visitor<'_> for Visitor {
            type Value = RawCount;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a whole number")
            }
            fn visit_i64<E>(self, v: i64) -> std::result::Result<RawCount, E> {
                Ok(RawCount::Integer(v.into()))
            }
            fn visit_u64<E>(self, v: u64) -> std::result::Result<RawCount, E> {
                Ok(RawCount::Integer(v.into()))
            }
            fn visit_i128<E>(self, v: i128) -> std::result::Result<RawCount, E> {
                Ok(RawCount::Integer(v))
            }
            fn visit_u128<E>(self, v: u128) -> std::result::Result<RawCount, E> {
                Ok(i128::try_from(v)
                    .map_or_else(|_| RawCount::Other(v.to_string()), RawCount::Integer))
            }
            fn visit_f64<E>(self, v: f64) -> std::result::Result<RawCount, E> {
                Ok(RawCount::Float(v))
            }
            fn visit_bool<E>(self, v: bool) -> std::result::Result<RawCount, E> {
                Ok(RawCount::Other(v.to_string()))
            }
            fn visit_str<E>(self, v: &str) -> std::result::Result<RawCount, E> {
                Ok(RawCount::Other(format!("\"{v}\"")))
            }
        }
        d.deserialize_any(Visitor)
    }
}

/// Checks a count: a whole number (an integer, or a float with no fraction) from `min` to
/// `max`. The library checks its own ranges again; this turns values that do not fit a `usize`
/// (negative, huge, fractional, not a number) into the same kind of message.
pub(crate) fn count_in(value: &RawCount, field: &str, min: usize, max: usize) -> Result<usize> {
    let whole = match value {
        RawCount::Integer(i) => Some(*i),
        // Every float of magnitude below 2^100 converts exactly when it has no fraction.
        RawCount::Float(f) if f.is_finite() && f.fract() == 0.0 && f.abs() < 1e30 => {
            Some(*f as i128)
        }
        _ => None,
    };
    match whole.and_then(|w| usize::try_from(w).ok()) {
        Some(n) if (min..=max).contains(&n) => Ok(n),
        _ => {
            let shown = match value {
                RawCount::Integer(i) => i.to_string(),
                RawCount::Float(f) => halfplane::written::Written(*f).to_string(),
                RawCount::Other(s) => s.clone(),
            };
            Err(FieldError {
                field: field.into(),
                message: format!(
                    "invalid {field} = {shown}: must be a whole number from {min} to {max}"
                ),
            }
            .into())
        }
    }
}
