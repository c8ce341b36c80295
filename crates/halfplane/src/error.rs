//! Typed errors. Every variant carries the offending value and says what would be valid, so a
//! caller (CLI, Python binding, sweep driver) can report it without string parsing.

use thiserror::Error;

/// Everything that can go wrong in the library.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// A physical input is outside its valid range (or not finite).
    #[error("invalid {field} = {value}: must be {valid}")]
    InvalidInput {
        /// Name of the input, as the case file spells it where there is one.
        field: String,
        /// The rejected value.
        value: f64,
        /// The valid range, in words.
        valid: &'static str,
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

    /// Bulk tension is large enough to reverse slip at one edge, which the paper's analysis excludes.
    #[error(
        "slip reverses at one edge: the shear range dQ = {shear_range:.6} must exceed pi*a_max*|dsigma|/4 = {bulk_term:.6} \
         for slip to keep one direction at both edges (the paper's assumption); \
         use `halfplane march`, the numerical time-marching solver, for this load case"
    )]
    SlipReversal {
        /// Q2 - Q1 with point 1 the end of smaller Q.
        shear_range: f64,
        /// pi * a_max * |sigma1 - sigma2| / 4.
        bulk_term: f64,
    },

    /// The permanent stick zone found does not lie inside the smaller contact.
    #[error(
        "the stick zone [-m, n] = [{left:.6}, {right:.6}] does not lie inside the smaller contact [-{smaller_half_width:.6}, {smaller_half_width:.6}] \
         (the paper requires 0 < m, n < min(a1, a2)); use `halfplane march`, the numerical time-marching solver, for this load case"
    )]
    StickZoneOutsideContact {
        /// -m.
        left: f64,
        /// n.
        right: f64,
        /// min(a1, a2).
        smaller_half_width: f64,
    },

    /// Gross sliding at an end of the cycle, where an analysis needs partial slip.
    #[error(
        "the contact slides at the {point} point: |Q| = {shear:.6} >= f P = {limit:.6}; no steady partial-slip state exists \
         (`halfplane steady` reports this as the gross-sliding regime)"
    )]
    GrossSliding {
        /// "first" or "second", as given.
        point: &'static str,
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

    /// An iterative solve did not reach its tolerance.
    #[error(
        "{what} did not converge in {iterations} iterations (last relative step {last_step:e})"
    )]
    NoConvergence {
        /// Which solve.
        what: &'static str,
        /// Iterations used.
        iterations: usize,
        /// Size of the last step relative to the scale of the unknowns.
        last_step: f64,
    },
}

/// Shorthand used throughout the crate.
pub type Result<T> = std::result::Result<T, Error>;

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
