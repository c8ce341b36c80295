//! One row of a steady batch: the values of a table's columns (Python's `steady_batch`, a sweep's
//! rows) turned into a validated contact and cycle. Errors name the column, not the case-file
//! field, so a caller can report them per row as they are.

use super::{steady_summary, SteadySummary};
use crate::error::{Error, Result};
use crate::steady::SteadyOptions;
use crate::{Contact, Cycle, Friction, LoadPoint, Material, Profile};

/// The input columns of a steady batch, in their documented order (a public interface). The
/// profile parameters a row's kind does not use (see [`ProfileKind::uses`]) may be absent or
/// NaN; the moments `moment1`, `moment2` (the last two) default to 0 where a front end's table
/// has no such column.
pub const STEADY_INPUT_COLUMNS: [&str; 16] = [
    "youngs_modulus",
    "poisson_ratio",
    "friction",
    "profile",
    "radius",
    "flat_half_width",
    "coefficient",
    "exponent",
    "normal1",
    "shear1",
    "bulk1",
    "normal2",
    "shear2",
    "bulk2",
    "moment1",
    "moment2",
];

/// The profile-parameter columns, in the order of [`SteadyRow::shape`].
pub const SHAPE_COLUMNS: [&str; 4] = ["radius", "flat_half_width", "coefficient", "exponent"];

/// The profile kinds a batch row can name (tabulated profiles need a table per row and are not
/// offered).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ProfileKind {
    /// `hertz`: `radius` R.
    Hertz,
    /// `flat-rounded`: `flat_half_width` b and `radius` R of the rounded edges.
    FlatRounded,
    /// `power-law`: g = B|x|^k with `coefficient` B and `exponent` k.
    PowerLaw,
}

impl ProfileKind {
    /// Every kind, in the order of their names in messages.
    pub const ALL: [ProfileKind; 3] = [Self::Hertz, Self::FlatRounded, Self::PowerLaw];

    /// The name a table gives: `"hertz"`, `"flat-rounded"` or `"power-law"` (the case file's
    /// `profile.kind`).
    pub fn name(self) -> &'static str {
        match self {
            Self::Hertz => "hertz",
            Self::FlatRounded => "flat-rounded",
            Self::PowerLaw => "power-law",
        }
    }

    /// The kind of a name.
    ///
    /// # Errors
    /// [`Error::InvalidText`] naming the `profile` column for any other text.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|k| k.name() == name)
            .ok_or_else(|| Error::InvalidText {
                field: "profile".into(),
                value: name.into(),
                valid: "one of \"hertz\", \"flat-rounded\", \"power-law\"",
            })
    }

    /// Which of [`SHAPE_COLUMNS`] the kind uses.
    pub fn uses(self) -> [bool; 4] {
        match self {
            Self::Hertz => [true, false, false, false],
            Self::FlatRounded => [true, true, false, false],
            Self::PowerLaw => [false, false, true, true],
        }
    }
}

/// One row's values as the table gives them: nothing is validated until [`SteadyRow::contact`]
/// and [`SteadyRow::cycle`]. Loads per unit thickness (N/mm), stresses and E in MPa, lengths in
/// mm in N-mm-MPa units (any consistent units work; results are in the same length unit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyRow {
    /// E of both bodies.
    pub youngs_modulus: f64,
    /// ν of both bodies.
    pub poisson_ratio: f64,
    /// Coulomb friction coefficient f.
    pub friction: f64,
    /// The profile kind.
    pub profile: ProfileKind,
    /// `radius`, `flat_half_width`, `coefficient`, `exponent` ([`SHAPE_COLUMNS`]); NaN where the
    /// table gives none.
    pub shape: [f64; 4],
    /// P, Q, σ at the first point as given (`normal1`, `shear1`, `bulk1`).
    pub point1: [f64; 3],
    /// P, Q, σ at the second point as given (`normal2`, `shear2`, `bulk2`).
    pub point2: [f64; 3],
    /// M, the pressure's moment about x = 0, at the first and second points as given
    /// (`moment1`, `moment2`; 0 without a moment).
    pub moment: [f64; 2],
}

/// The library's field names for the values of a row, and the columns that hold them.
const COLUMN_OF_FIELD: [(&str, &str); 15] = [
    ("material.youngs_modulus", "youngs_modulus"),
    ("material.poisson_ratio", "poisson_ratio"),
    ("friction.coefficient", "friction"),
    ("profile.radius", "radius"),
    ("profile.flat_half_width", "flat_half_width"),
    ("profile.coefficient", "coefficient"),
    ("profile.exponent", "exponent"),
    ("point1.normal", "normal1"),
    ("point1.shear", "shear1"),
    ("point1.bulk", "bulk1"),
    ("point2.normal", "normal2"),
    ("point2.shear", "shear2"),
    ("point2.bulk", "bulk2"),
    ("point1.moment", "moment1"),
    ("point2.moment", "moment2"),
];

/// The error with its field renamed to the column that holds the value.
fn in_column(error: Error) -> Error {
    match error {
        Error::InvalidInput {
            field,
            value,
            valid,
        } => {
            let column = COLUMN_OF_FIELD
                .iter()
                .find(|(f, _)| *f == field)
                .map_or(field, |(_, c)| (*c).to_string());
            Error::InvalidInput {
                field: column,
                value,
                valid,
            }
        }
        other => other,
    }
}

impl SteadyRow {
    /// The validated contact.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the column of an invalid value (a parameter the kind needs
    /// that is NaN is invalid), and [`Error::NotUsed`] for a parameter the kind does not use that
    /// is not NaN (a value in the wrong column is never ignored silently).
    #[inline]
    pub fn contact(&self) -> Result<Contact> {
        let uses = self.profile.uses();
        for ((column, value), used) in SHAPE_COLUMNS.iter().zip(self.shape).zip(uses) {
            if !used && !value.is_nan() {
                return Err(Error::NotUsed {
                    field: (*column).to_string(),
                    value,
                    kind: self.profile.name(),
                });
            }
        }
        let [radius, flat_half_width, coefficient, exponent] = self.shape;
        let profile = match self.profile {
            ProfileKind::Hertz => Profile::hertz(radius),
            ProfileKind::FlatRounded => Profile::flat_rounded(flat_half_width, radius),
            ProfileKind::PowerLaw => Profile::power_law(coefficient, exponent),
        }
        .map_err(in_column)?;
        let material = Material::new(self.youngs_modulus, self.poisson_ratio).map_err(in_column)?;
        let friction = Friction::new(self.friction).map_err(in_column)?;
        Ok(Contact::new(profile, material, friction))
    }

    /// The validated cycle, points as given.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the column of an invalid load.
    #[inline]
    pub fn cycle(&self) -> Result<Cycle> {
        let point = |name: &str, [p, q, s]: [f64; 3], m: f64| {
            LoadPoint::new(name, p, q, s)?.with_moment(name, m)
        };
        Ok(Cycle::new(
            point("point1", self.point1, self.moment[0]).map_err(in_column)?,
            point("point2", self.point2, self.moment[1]).map_err(in_column)?,
        ))
    }

    /// The row's steady state, summarised: [`SteadyRow::contact`], [`SteadyRow::cycle`], then
    /// [`steady_summary`]. Exactly the analysis of a case file with the same values.
    ///
    /// # Errors
    /// Those of the three steps.
    pub fn steady_summary(&self, options: &SteadyOptions) -> Result<SteadySummary> {
        let contact = self.contact()?;
        let cycle = self.cycle()?;
        steady_summary(&contact, &cycle, options)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{reference, steady};

    fn reference_row() -> SteadyRow {
        let nan = f64::NAN;
        SteadyRow {
            youngs_modulus: 200_000.0,
            poisson_ratio: 0.3,
            friction: 0.6,
            profile: ProfileKind::Hertz,
            shape: [reference::RADIUS, nan, nan, nan],
            point1: [1000.0, -250.0, -20.0],
            point2: [1400.0, 250.0, 20.0],
            moment: [0.0, 0.0],
        }
    }

    #[test]
    fn a_row_is_the_same_analysis_as_the_reference_case() {
        let options = SteadyOptions::default();
        let direct = steady::analyse(&reference::hertz(), &reference::cycle(), &options)
            .expect("the reference cycle solves");
        let row = reference_row().steady_summary(&options).expect("solves");
        assert_eq!(row, SteadySummary::of(&direct), "bit-identical summary");
    }

    #[test]
    fn errors_name_the_column() {
        type Spoil = fn(&mut SteadyRow);
        let cases: [(&str, Spoil); 8] = [
            ("youngs_modulus", |r| r.youngs_modulus = -1.0),
            ("poisson_ratio", |r| r.poisson_ratio = 0.5),
            ("friction", |r| r.friction = f64::NAN),
            ("radius", |r| r.shape[0] = f64::NAN),
            ("normal1", |r| r.point1[0] = 0.0),
            ("shear2", |r| r.point2[1] = f64::INFINITY),
            ("bulk2", |r| r.point2[2] = 1e31),
            ("moment1", |r| r.moment[0] = f64::NAN),
        ];
        for (column, spoil) in cases {
            let mut row = reference_row();
            spoil(&mut row);
            match row.steady_summary(&SteadyOptions::default()) {
                Err(Error::InvalidInput { field, .. }) => assert_eq!(field, column),
                other => panic!("{column}: {other:?}"),
            }
        }
        let mut row = reference_row();
        row.shape[1] = 0.3;
        let e = row.contact().unwrap_err();
        assert!(
            matches!(&e, Error::NotUsed { field, kind: "hertz", .. } if field == "flat_half_width"),
            "{e:?}"
        );
        assert!(e.to_string().contains("flat_half_width = 0.3"), "{e}");
        assert!(matches!(
            ProfileKind::from_name("Hertz"),
            Err(Error::InvalidText { field, .. }) if field == "profile"
        ));
        for kind in ProfileKind::ALL {
            assert_eq!(ProfileKind::from_name(kind.name()), Ok(kind));
        }
    }
}
