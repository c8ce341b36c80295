//! Typed errors. Every variant carries the offending value and says what would be valid, so a
//! caller (CLI, Python binding, sweep driver) can report it without string parsing.

use crate::labels::{Edge, GivenPoint, Half};
use crate::matching::{LoadIndex, MatchConstraint, MatchSide};
use crate::written::Written;
use thiserror::Error;

mod examples;
mod kind;
pub use examples::one_of_each;
pub use kind::{Alternative, ErrorKind};

/// Everything that can go wrong in the library. Messages state the problem and what would be
/// valid; they give no advice about any particular front end. Each variant has a stable name
/// ([`Error::name`]), a kind ([`Error::kind`]) and, where another route of this library may
/// succeed, an [`Error::alternative`]: front ends classify errors and choose their hints from
/// those (exhaustive matches written here, once), never by matching variants or reading
/// messages. New variants may be added, so matches on the variants outside this crate need a
/// wildcard arm.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum Error {
    /// A physical input is outside its valid range (or not finite).
    #[error("invalid {field} = {}: must be {valid}", Written(*.value))]
    InvalidInput {
        /// Name of the input, as the case file spells it where there is one.
        field: String,
        /// The rejected value.
        value: f64,
        /// The valid range, in words.
        valid: &'static str,
    },

    /// A count (cells, increments, points, cycles) is outside its valid range.
    #[error("invalid {field} = {value}: must be a whole number from {min} to {max}")]
    InvalidCount {
        /// Name of the input, as the case file spells it where there is one.
        field: String,
        /// The rejected value.
        value: u64,
        /// Smallest valid value.
        min: u64,
        /// Largest valid value (chosen from memory use and run time).
        max: u64,
    },

    /// A generated or tabulated history would have more increments than a run can hold.
    #[error("the history would have more than {max} increments (from {field}); split the study into shorter runs")]
    TooManyIncrements {
        /// The count or product of counts that made it too long.
        field: String,
        /// The limit, [`crate::history::MAX_INCREMENTS`].
        max: usize,
    },

    /// A value in a row of a table (a history) is outside its valid range.
    #[error("{table} row {row}: invalid {column} = {}: must be {valid}", Written(*.value))]
    InvalidRow {
        /// Which table.
        table: &'static str,
        /// 1-based data row.
        row: usize,
        /// The column, as the table's header names it.
        column: &'static str,
        /// The rejected value.
        value: f64,
        /// The valid range, in words.
        valid: &'static str,
    },

    /// A table (history, profile) has no data rows.
    #[error("the {what} table has no rows")]
    EmptyTable {
        /// Which table.
        what: &'static str,
    },

    /// A table (profile, history) has more rows than a run can hold.
    #[error("the {what} has {rows} rows, more than the {max} allowed; use a coarser table")]
    TooManyRows {
        /// Which table.
        what: &'static str,
        /// Rows given.
        rows: usize,
        /// The limit (for profiles, [`crate::profile::MAX_TABLE_ROWS`]).
        max: usize,
    },

    /// A tabulated profile is malformed.
    #[error("tabulated profile, row {row}: {problem}")]
    InvalidTable {
        /// 1-based data row (after any header).
        row: usize,
        /// What is wrong with it.
        problem: String,
    },

    /// The contact (or stick zone) would extend beyond the tabulated profile.
    #[error(
        "the {what} needs the profile out to |x| = {needed:.6}, but the table ends at x = {table_end:.6}; extend the table"
    )]
    BeyondTable {
        /// What needed the larger extent.
        what: &'static str,
        /// The |x| that would be needed.
        needed: f64,
        /// Last tabulated x.
        table_end: f64,
    },

    /// Along a half-cycle, the slip zone at one edge stops growing: its stick boundary moves
    /// outwards, or faster inwards than a receding contact edge (`docs/validity.md`). Material
    /// would then re-stick, or the edge keep slipping in the previous half's direction and reverse
    /// later; the steady-state analysis (and the exact evolution) assume neither.
    #[error(
        "slip at the {edge_name} edge does not keep one direction through half {half} of the cycle: from fraction \
         {fraction:.6} of that half its stick boundary would move at {boundary_rate:.6} (outwards positive, length per \
         half-cycle), but the steady-state analysis needs at most min(0, da/dt) = {limit_rate:.6}: that slip zone would \
         not grow monotonically (the edge would stick or re-stick, or keep slipping in the previous half's direction)",
        edge_name = .edge.name()
    )]
    SlipReversesInHalf {
        /// The half: [`Half::First`] from the first point as given to the second (printed "half 1"),
        /// [`Half::Second`] back ("half 2").
        half: Half,
        /// The edge whose slip zone stops growing.
        edge: Edge,
        /// Fraction of the half (0 to 1) where it first happens.
        fraction: f64,
        /// Outward speed of that stick boundary there, `dn/dt` at the right edge, `dm/dt` at the
        /// left (stick zone `[-m, n]`, t the fraction of the half), in length per half-cycle.
        boundary_rate: f64,
        /// The largest speed allowed, `min(0, da/dt)` (a the contact half-width).
        limit_rate: f64,
    },

    /// A load segment whose shear range leaves no stick zone: `dQ >= f (P1 + P2)`.
    #[error(
        "no stick zone exists for the load segment: its shear range dQ = {shear_range:.6} is not below f (P1 + P2) = {limit:.6}, \
         so the contact slides rigidly"
    )]
    NoStickZone {
        /// `dQ = Q2 - Q1`.
        shear_range: f64,
        /// `f (P1 + P2)`.
        limit: f64,
    },

    /// The permanent stick zone found does not lie inside both end contacts.
    #[error(
        "the stick zone [-m, n] = [{left:.6}, {right:.6}] does not lie inside both contacts of the cycle, whose common \
         part is [{:.6}, {:.6}] (the analysis requires max(b1) < -m < n < min(b2) over the two points, which is \
         -min(a1, a2) < -m < n < min(a1, a2) without a moment; the zone need not contain x = 0)",
        .common[0], .common[1]
    )]
    StickZoneOutsideContact {
        /// -m.
        left: f64,
        /// n.
        right: f64,
        /// The common part `[max(b1_1, b1_2), min(b2_1, b2_2)]` of the two points' contacts
        /// (`[-min(a1, a2), min(a1, a2)]` without a moment on a symmetric profile).
        common: [f64; 2],
    },

    /// Gross sliding at an end of the cycle, where an analysis needs partial slip.
    #[error(
        "the contact slides at the {point} point: |Q| = {shear:.6} >= f P = {limit:.6}; no steady partial-slip state exists \
         (the steady-state analysis reports this as the gross-sliding regime)"
    )]
    GrossSliding {
        /// The point as given (printed "first" or "second").
        point: GivenPoint,
        /// |Q| there.
        shear: f64,
        /// f P there.
        limit: f64,
    },

    /// The asymptotic estimate is undefined (its stick-zone load P_K is not positive).
    #[error("the asymptotic estimate P_K = {p_k:.6} at the {edge} edge is not positive: the edge description breaks down for this cycle")]
    AsymptoticBreakdown {
        /// "left" or "right".
        edge: &'static str,
        /// The estimate's P_K.
        p_k: f64,
    },

    /// The contact slides at an increment of a marched history.
    #[error("the contact slides at step {step}: |Q| = {shear:.6} >= f P = {limit:.6} (gross sliding); the history must keep |Q| < f P")]
    SlidesAtStep {
        /// 1-based increment.
        step: usize,
        /// |Q| there.
        shear: f64,
        /// f P there.
        limit: f64,
    },

    /// The stick/slip active set of an increment did not settle.
    #[error("the stick/slip state did not settle at step {step} after {iterations} passes; try more cells or smaller increments")]
    ActiveSet {
        /// 1-based increment.
        step: usize,
        /// Passes made.
        iterations: usize,
    },

    /// A dense Cholesky factorisation met a pivot that is not positive: the stick block of the
    /// kernel matrix is not numerically positive definite (it is in exact arithmetic).
    #[error("the dense Cholesky factorisation at step {step} met a non-positive pivot at cell {index}; use the Toeplitz solver or fewer cells")]
    NonPositivePivot {
        /// 1-based increment.
        step: usize,
        /// 0-based cell index of the failed pivot.
        index: usize,
    },

    /// A computation over the steady cycle was given a history without cycles.
    #[error("the {what} needs a cyclic history (kind = \"cycle\" or \"harmonic\"): its last cycle is taken as the steady cycle")]
    NoCycle {
        /// What needed the cycle.
        what: &'static str,
    },

    /// An iterative solve did not reach its tolerance.
    #[error("{what} did not converge {}", convergence_note(*.iterations, *.last_step))]
    NoConvergence {
        /// Which solve.
        what: &'static str,
        /// Iterations used.
        iterations: usize,
        /// Size of the last step relative to the scale of the unknowns.
        last_step: f64,
    },

    /// A march asked to run until its cycle repeats ([`crate::history::Steady`]) did not get
    /// there within its most cycles.
    #[error("no steady cycle within history.max_cycles = {max_cycles} cycles: the per-cell slip range still changed by {change:.3e} A f P between the last two cycles (history.steady_tolerance = {tolerance:e})")]
    NotSteady {
        /// The most cycles allowed.
        max_cycles: usize,
        /// The largest change of a cell's slip range between the last two cycles, a fraction
        /// of `A f P_max`.
        change: f64,
        /// The tolerance it had to meet.
        tolerance: f64,
    },

    /// A textual setting (an environment variable, a name) has a value that cannot be read.
    #[error("invalid {field} = {value:?}: must be {valid}")]
    InvalidText {
        /// Name of the setting.
        field: String,
        /// The rejected text.
        value: String,
        /// What would be valid, in words.
        valid: &'static str,
    },

    /// A range of values (a sweep axis) whose ends are out of order, or that a logarithmic
    /// scale cannot span.
    #[error("invalid {field} = {{ from = {}, to = {} }}: {problem}", Written(*.from), Written(*.to))]
    InvalidRange {
        /// Name of the range, as the input spells it.
        field: String,
        /// The first end.
        from: f64,
        /// The last end.
        to: f64,
        /// What is wrong and what would be valid, in words.
        problem: &'static str,
    },

    /// A value given for a parameter that the chosen kind does not use (a batch row's profile
    /// parameter of another kind): rejected rather than ignored, so a misplaced value is seen.
    #[error(
        "{field} = {} is not used by profile kind \"{kind}\": it must be NaN (not given)",
        Written(*.value)
    )]
    NotUsed {
        /// The parameter (column).
        field: String,
        /// The value given.
        value: f64,
        /// The kind that does not use it.
        kind: &'static str,
    },

    /// An analysis needs constants that were not given.
    #[error("the {what} needs {fields}")]
    MissingConstants {
        /// What needed them.
        what: &'static str,
        /// The fields, as the case file names them.
        fields: &'static str,
    },

    /// The worker pool of a batch could not be started (the system refused the threads).
    #[error("could not start the worker threads: {message}")]
    ThreadPool {
        /// What the system said.
        message: String,
    },

    /// The output columns handed to a batch ([`crate::batch::Batch::fill`]) hold different
    /// numbers of rows (a caller's allocation error: every column needs one value per row).
    #[error("the output columns of a batch hold different numbers of rows ({rows} and {other}); every column needs one value per row")]
    UnequalColumns {
        /// Rows of the first column.
        rows: usize,
        /// Rows of a column that differs from it.
        other: usize,
    },

    /// Two inputs that go together value by value have different lengths (depths and
    /// positions of stress points, the values of a traction and its nodes, the columns of a
    /// table or a batch).
    #[error("invalid {field}: {length} values, but {expected} are needed ({per})")]
    LengthMismatch {
        /// The input whose length is wrong, as the caller names it.
        field: String,
        /// How many values it has.
        length: usize,
        /// How many it needs: the length of the input it goes with.
        expected: usize,
        /// What it needs one value per, in words (`"one depth z per x"`).
        per: &'static str,
    },

    /// Prototype-to-test matching ([`crate::matching`]) found no valid test: the prototype's
    /// cycle, or the test cycle the matching equations give, fails `constraint`.
    #[error(
        "no valid test: the {side}'s cycle fails the {constraint} constraint{}",
        Error::cause_text(.cause)
    )]
    NoValidMatch {
        /// Whose cycle fails.
        side: MatchSide,
        /// What it fails.
        constraint: MatchConstraint,
        /// The analysis's own error, where there is one.
        cause: Option<Box<Error>>,
    },

    /// No test contact half-width gives the prototype's edge pressure intensity `K_N`.
    #[error(
        "no valid test: no test contact has the prototype's K_N = {target:.6e} at {load} (no solution bracketed \
         between contact half-widths {:.6e} and {:.6e}; K_N of the test profile does not reach it)",
        .searched[0], .searched[1]
    )]
    MatchNotBracketed {
        /// The load being matched.
        load: LoadIndex,
        /// The prototype's `K_N` there.
        target: f64,
        /// The smallest and largest test half-widths tried.
        searched: [f64; 2],
    },

    /// A contact (or zone) would reach beyond a two-sided tabulated profile.
    #[error(
        "the {what} needs the profile over [{:.6}, {:.6}], but the table covers [{:.6}, {:.6}]; extend the table",
        .needed[0], .needed[1], .defined[0], .defined[1]
    )]
    OutsideProfile {
        /// What needed the profile there.
        what: &'static str,
        /// The interval `[lo, hi]` that would be needed.
        needed: [f64; 2],
        /// The interval the table covers, first and last x.
        defined: [f64; 2],
    },

    /// A computation that assumes a symmetric profile (contact `[-a, a]` under P alone) was given
    /// an asymmetric one (unequal edge radii, a two-sided table), whose contact under P is not
    /// centred: such profiles are solved with the normal problem under P and a moment
    /// ([`crate::normal::Contact::normal_contact`]).
    #[error("the {what} assumes a symmetric profile, but this profile is asymmetric (unequal edge radii or a two-sided table); only the normal problem under P and a moment M accepts it")]
    AsymmetricProfile {
        /// The computation that needs symmetry.
        what: &'static str,
    },

    /// A wear run stopped at a physical cycle whose march failed (the contact opened entirely,
    /// left the grid, or slid where it may not); the checkpoints before it were reported.
    #[error("wear stopped at cycle {cycle}: {cause}")]
    WearStopped {
        /// The physical cycle (1-based) whose march failed.
        cycle: u64,
        /// Why.
        cause: Box<Error>,
    },

    /// The contact of a worn gap reached the end of its grid: the grid must be wider (the
    /// grid's width over the unworn contact's is `field`).
    #[error("the worn contact reached the end of its grid at x = {end}: raise {field} (the grid's width over the unworn contact's; 1 to 100)")]
    GridTooNarrow {
        /// The field that sets the grid's width (`wear.span`).
        field: &'static str,
        /// The x of the grid's end the contact reached.
        end: f64,
    },

    /// The moment would put a contact end beyond a tabulated profile at this normal load.
    #[error(
        "invalid {field} = {value}: at normal load P = {normal} a contact end would leave the tabulated profile; \
         the moment must be from {smallest:.6} to {largest:.6} at this P"
    )]
    MomentOutsideTable {
        /// The moment's name (`moment` for the library's normal solve; front ends may name the
        /// point, for example `cycle.point1.moment`).
        field: String,
        /// The rejected moment M.
        value: f64,
        /// The normal load P it was given with.
        normal: f64,
        /// The smallest valid moment at this P (the left contact end on the table's first row).
        smallest: f64,
        /// The largest valid moment at this P (the right contact end on the table's last row).
        largest: f64,
    },
}

impl Error {
    /// The same error naming the moment `field` (for example `cycle.point1.moment`) instead of
    /// the library's plain `moment`: a [`Error::MomentOutsideTable`], or an
    /// [`Error::InvalidInput`] whose field is `moment`; other errors unchanged.
    pub fn with_moment_field(self, field: &str) -> Self {
        match self {
            Error::InvalidInput {
                field: named,
                value,
                valid,
            } if named == "moment" => Error::InvalidInput {
                field: field.into(),
                value,
                valid,
            },
            Error::MomentOutsideTable {
                value,
                normal,
                smallest,
                largest,
                ..
            } => Error::MomentOutsideTable {
                field: field.into(),
                value,
                normal,
                smallest,
                largest,
            },
            other => other,
        }
    }

    /// `": cause"` for [`Error::NoValidMatch`]'s message, empty without one.
    fn cause_text(cause: &Option<Box<Error>>) -> String {
        cause
            .as_ref()
            .map_or_else(String::new, |c| format!(": {c}"))
    }
}

/// Shorthand used throughout the crate.
pub type Result<T> = std::result::Result<T, Error>;

/// The largest magnitude accepted for a physical input, and (for the ones that must be positive)
/// the smallest. Every consistent unit system fits with room to spare (E = 2e11 Pa or 200 GPa,
/// lengths from nanometres to kilometres), and products and quotients of a few inputs then stay
/// far inside the range of f64: no derived quantity (A, a, K_N, K_T, |Q|/P, energies) can
/// overflow to infinity or underflow to zero.
pub const MAGNITUDE_LIMIT: f64 = 1e30;

/// Rejects a value that is not finite or whose magnitude exceeds [`MAGNITUDE_LIMIT`].
#[inline]
pub(crate) fn physical(field: &str, value: f64) -> Result<f64> {
    if value.is_finite() && value.abs() <= MAGNITUDE_LIMIT {
        Ok(value)
    } else {
        Err(Error::InvalidInput {
            field: field.to_string(),
            value,
            valid: "a finite number of magnitude at most 1e30",
        })
    }
}

/// Rejects a value outside `[1/MAGNITUDE_LIMIT, MAGNITUDE_LIMIT]` (see [`MAGNITUDE_LIMIT`]).
#[inline]
pub(crate) fn physical_positive(field: &str, value: f64) -> Result<f64> {
    if value.is_finite() && (1.0 / MAGNITUDE_LIMIT..=MAGNITUDE_LIMIT).contains(&value) {
        Ok(value)
    } else {
        Err(Error::InvalidInput {
            field: field.to_string(),
            value,
            valid: "a finite number from 1e-30 to 1e30",
        })
    }
}

/// `check(field, value)` with the field's name built only if the value is rejected, so that
/// validating a valid value allocates nothing (batches validate millions of rows).
#[inline]
pub(crate) fn lazily_named(
    check: fn(&str, f64) -> Result<f64>,
    value: f64,
    field: impl FnOnce() -> String,
) -> Result<f64> {
    check("", value).map_err(|e| match e {
        Error::InvalidInput { value, valid, .. } => Error::InvalidInput {
            field: field(),
            value,
            valid,
        },
        other => other,
    })
}

/// Rejects a non-finite or non-positive value.
pub(crate) fn positive(field: &str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::InvalidInput {
            field: field.to_string(),
            value,
            valid: "a finite number > 0",
        })
    }
}

/// Rejects a non-finite value.
pub(crate) fn finite(field: &str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::InvalidInput {
            field: field.to_string(),
            value,
            valid: "a finite number",
        })
    }
}

/// How a [`Error::NoConvergence`] ended, as its message gives it. The last step is infinite
/// when no step was ever taken, because none reduced the residual.
fn convergence_note(iterations: usize, last_step: f64) -> String {
    let plural = if iterations == 1 { "" } else { "s" };
    let ending = if last_step.is_finite() {
        format!("last relative step {last_step:e}")
    } else {
        "no step reduced the residual".to_string()
    };
    format!("in {iterations} iteration{plural} ({ending})")
}
