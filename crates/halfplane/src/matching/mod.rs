//! Prototype-to-test matching: the loads at which a test geometry (a Hertzian pad, say)
//! reproduces the contact-edge state of a prototype (a flat punch with rounded edges), the use the
//! paper's section "Asymptotic representation" was written for (docs/matching.md).
//!
//! Two modes ([`Mode`]), both keeping the points in the prototype's order:
//!
//! - **asymptotic**: at each point the test's edge pressure intensity `K_N` (eq. (31)) equals
//!   the prototype's, which fixes the test's P; its shear intensity `K_T` (eq. (32)) equals the
//!   prototype's at both edges, which fixes Q and sigma. Every load point maps on its own
//!   ([`map_point`]), so a whole history maps row by row ([`map_history`]);
//! - **exact**: `K_N` equal at both points; the exact slip-zone lengths at both edges at the
//!   second point (as given) equal the prototype's from [`crate::steady::analyse`]; the mean of `K_T`
//!   over the two points equal at each edge.
//!
//! The matching relations are symmetric, so the inverse (the prototype loads a test represents)
//! is the same call with the roles swapped.
//!
//! Sign conventions are those of [`crate::asymptotic`]: bulk tension adds to the shear at the left
//! edge. Rooms: `solve` holds the equations, `report` the comparison and the warnings.

mod report;
mod solve;

pub use report::{
    Compared, MatchReport, MatchWarning, Side, EDGE_MOTION_WARNING, SLIP_ZONE_WARNING,
};
pub use solve::{map_history, map_history_at, map_point, map_point_at};

use crate::error::{Error, Result};
use crate::labels::{display_as_str, Edge, GivenPoint};
use crate::load::Cycle;
use crate::normal::Contact;
use crate::steady::{Regime, SteadyOptions};

/// What the test must share with the prototype.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mode {
    /// `K_N` at both points, `K_T` at both edges at both points (default).
    #[default]
    Asymptotic,
    /// `K_N` at both points, the exact slip zones at both edges at the second point, the mean
    /// `K_T` over the points at each edge.
    Exact,
}

impl Mode {
    /// "asymptotic" or "exact".
    pub fn as_str(self) -> &'static str {
        match self {
            Mode::Asymptotic => "asymptotic",
            Mode::Exact => "exact",
        }
    }
}

/// Which side of a match a failure is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MatchSide {
    /// The cycle being reproduced.
    Prototype,
    /// The cycle the matching found.
    Test,
}

impl MatchSide {
    /// "prototype" or "test".
    pub fn as_str(self) -> &'static str {
        match self {
            MatchSide::Prototype => "prototype",
            MatchSide::Test => "test",
        }
    }
}

/// The condition a matched (or prototype) cycle fails, making the match invalid.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MatchConstraint {
    /// `|Q| >= f P` at an end, or a shear range that leaves no stick zone.
    GrossSliding,
    /// Slip does not keep one direction at an edge through a half-cycle (`docs/validity.md`).
    SlipReversal,
    /// The stick zone does not lie inside the smaller contact.
    StickZoneOutsideContact,
    /// The cycle sticks fully, so it has no slip zones to match (exact mode), or the slip zones
    /// asked for need a negative shear range.
    FullStick,
}

impl MatchConstraint {
    /// "gross-sliding", "slip-reversal", "stick-zone-outside-contact" or "full-stick".
    pub fn as_str(self) -> &'static str {
        match self {
            MatchConstraint::GrossSliding => "gross-sliding",
            MatchConstraint::SlipReversal => "slip-reversal",
            MatchConstraint::StickZoneOutsideContact => "stick-zone-outside-contact",
            MatchConstraint::FullStick => "full-stick",
        }
    }

    /// The constraint a steady-state error reports, if it is one of them.
    fn of(error: &Error) -> Option<Self> {
        match error {
            Error::GrossSliding { .. } | Error::NoStickZone { .. } => Some(Self::GrossSliding),
            Error::SlipReversesInHalf { .. } => Some(Self::SlipReversal),
            Error::StickZoneOutsideContact { .. } => Some(Self::StickZoneOutsideContact),
            _ => None,
        }
    }

    /// Wraps a steady-state error on `side` as [`Error::NoValidMatch`] when it names one of the
    /// constraints; any other error is returned as it is.
    pub(crate) fn wrap(side: MatchSide, error: Error) -> Error {
        match Self::of(&error) {
            Some(constraint) => Error::NoValidMatch {
                side,
                constraint,
                cause: Some(Box::new(error)),
            },
            None => error,
        }
    }
}

/// Which load a matching equation was solved for, in errors.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadIndex {
    /// A point of the cycle, as given.
    Point(GivenPoint),
    /// A row of a history, 1-based.
    Row(usize),
}

impl std::fmt::Display for LoadIndex {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LoadIndex::Point(GivenPoint::First) => f.write_str("point1"),
            LoadIndex::Point(GivenPoint::Second) => f.write_str("point2"),
            LoadIndex::Row(r) => write!(f, "history row {r}"),
        }
    }
}

display_as_str!(Mode, MatchSide, MatchConstraint);

/// Finds the test cycle on `test` that matches `cycle` on `prototype` in `mode`, analyses both
/// with [`crate::steady::analyse`] and compares them.
///
/// Errors:
/// - [`Error::NoValidMatch`] naming the side and the [`MatchConstraint`] when the prototype is
///   outside the steady-state analysis (or, in exact mode, sticks fully), or when the test found
///   slides, has slip reversing in a half, or needs a stick zone outside its contact;
/// - [`Error::MatchNotBracketed`] when no test contact has the prototype's `K_N` (a power law
///   with exponent 3/2 has one `K_N` at every load);
/// - the prototype's own errors otherwise (a profile table too short, for example).
pub fn match_cycle(
    prototype: &Contact,
    cycle: &Cycle,
    test: &Contact,
    mode: Mode,
) -> Result<MatchReport> {
    match_cycle_at(prototype, cycle, test, mode, None)
}

/// [`match_cycle`] at a chosen edge of the prototype: under a moment, or on an asymmetric
/// profile, K_N differs at the prototype's two edges, and a test without a moment (a centred
/// contact, one K_N) can reproduce only one of them. The test's P follows the prototype's `K_N`
/// at `edge`; Q and sigma still match K_T at both edges (K_T does not depend on the moment), or
/// the exact slip zones. `None`: the edge whose `K_T` changes more over the cycle (the one that
/// slips more). Without a moment on a symmetric prototype both edges give the same test.
pub fn match_cycle_at(
    prototype: &Contact,
    cycle: &Cycle,
    test: &Contact,
    mode: Mode,
    edge: Option<Edge>,
) -> Result<MatchReport> {
    let options = SteadyOptions::default();
    let proto = Side::analyse(prototype, cycle, &options, MatchSide::Prototype, edge)?;
    if mode == Mode::Exact && proto.steady.regime == Regime::FullStick {
        return Err(Error::NoValidMatch {
            side: MatchSide::Prototype,
            constraint: MatchConstraint::FullStick,
            cause: None,
        });
    }
    let test_cycle = match mode {
        Mode::Asymptotic => solve::asymptotic_cycle(&proto, test)?,
        Mode::Exact => solve::exact_cycle(&proto, test)?,
    };
    let test_side = Side::analyse(
        test,
        &test_cycle,
        &options,
        MatchSide::Test,
        Some(proto.edge),
    )?;
    // The exact test was built with the prototype's slip zones, but eq. (1) decides the regime
    // first: a cycle it calls full stick has none.
    if mode == Mode::Exact && test_side.steady.regime == Regime::FullStick {
        return Err(Error::NoValidMatch {
            side: MatchSide::Test,
            constraint: MatchConstraint::FullStick,
            cause: None,
        });
    }
    Ok(MatchReport::compare(mode, proto, test_side))
}
