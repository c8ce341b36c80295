//! The units a case is written in, named by its optional `[units]` section. They only label
//! output (table headers, figure axes and the JSON `units` object): the numbers are computed and
//! printed as given, so the names must be those of a consistent set the case was written in.

use anyhow::{bail, Result};
use serde::{Deserialize, Serialize};

/// The longest unit name `[units]` takes, in characters: enough for "kN/m", "lbf", "µm" or
/// "N/mm^2", short enough to keep the table columns aligned.
pub const MAX_UNIT_CHARS: usize = 12;

/// `[units]` as the case file gives it.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawUnits {
    force: Option<String>,
    length: Option<String>,
    stress: Option<String>,
}

/// Validated unit names (default N, mm, MPa).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Units {
    /// Force, e.g. "N". Loads P and Q are force per unit thickness: see [`Units::force_per_length`].
    pub force: String,
    /// Length, e.g. "mm" (x, a, m, n, slip, the thickness of the plane-strain slice).
    pub length: String,
    /// Stress, e.g. "MPa" (bulk tension sigma, traction, pressure, Young's modulus).
    pub stress: String,
}

impl Default for Units {
    fn default() -> Self {
        Self {
            force: "N".into(),
            length: "mm".into(),
            stress: "MPa".into(),
        }
    }
}

/// A physical quantity a column or axis shows, to be labelled with its unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// A pure number or a name.
    None,
    /// Force per unit thickness (P, Q, S, P_K).
    ForcePerLength,
    /// Length (a, m, n, slip).
    Length,
    /// Stress (sigma).
    Stress,
    /// Stress intensity factor (K_N, K_T): stress times the square root of a length.
    Intensity,
    /// Dissipated energy per unit thickness: force times length per length.
    Energy,
    /// Moment per unit thickness (M): force times length per length, written "N mm/mm".
    Moment,
    /// Volume per unit thickness (worn volume): a length squared, written "mm^2".
    Area,
}

impl Units {
    /// Force per unit thickness, "N/mm" by default.
    pub fn force_per_length(&self) -> String {
        format!("{}/{}", self.force, self.length)
    }

    /// The label of `q` ("" for [`Quantity::None`]).
    pub fn of(&self, q: Quantity) -> String {
        match q {
            Quantity::None => String::new(),
            Quantity::ForcePerLength => self.force_per_length(),
            Quantity::Length => self.length.clone(),
            Quantity::Stress => self.stress.clone(),
            Quantity::Intensity => format!("{} {}^1/2", self.stress, self.length),
            Quantity::Energy | Quantity::Moment => {
                format!("{} {}/{}", self.force, self.length, self.length)
            }
            Quantity::Area => format!("{}^2", self.length),
        }
    }

    /// Resolves `[units]`: every name optional (defaults N, mm, MPa), and each non-empty, at most
    /// [`MAX_UNIT_CHARS`] characters, printable and without spaces or commas (so a label never
    /// breaks a table column or a CSV line).
    pub(crate) fn resolve(raw: Option<RawUnits>) -> Result<Self> {
        let raw = raw.unwrap_or_default();
        let d = Self::default();
        Ok(Self {
            force: name(raw.force, "units.force", d.force, "N, kN, lbf")?,
            length: name(raw.length, "units.length", d.length, "mm, m, in")?,
            stress: name(raw.stress, "units.stress", d.stress, "MPa, Pa, psi")?,
        })
    }
}

fn name(given: Option<String>, field: &str, default: String, e_g: &str) -> Result<String> {
    let Some(s) = given else {
        return Ok(default);
    };
    let n = s.chars().count();
    let bad = s
        .chars()
        .find(|c| c.is_control() || c.is_whitespace() || *c == ',' || *c == '"');
    if n == 0 || n > MAX_UNIT_CHARS || bad.is_some() {
        bail!(
            "invalid {field} = {s:?}: must be a unit name of 1 to {MAX_UNIT_CHARS} printable \
             characters without spaces, commas or quotes (e.g. {e_g})"
        );
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn resolve(force: &str) -> Result<Units> {
        Units::resolve(Some(RawUnits {
            force: Some(force.into()),
            length: None,
            stress: None,
        }))
    }

    #[test]
    fn names_are_checked() {
        assert_eq!(resolve("kN").unwrap().force_per_length(), "kN/mm");
        for bad in ["", "a b", "N,mm", "\u{7}", "abcdefghijklm"] {
            let e = resolve(bad).unwrap_err().to_string();
            assert!(e.contains("units.force") && e.contains("1 to 12"), "{e}");
        }
        assert_eq!(Units::resolve(None).unwrap(), Units::default());
    }
}
