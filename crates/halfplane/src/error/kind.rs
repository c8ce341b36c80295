//! Each error's stable name, its kind and the other route that may succeed: the one place front
//! ends learn how to classify an error, written as exhaustive matches so that a new variant cannot
//! be added without deciding all three.

use super::Error;
use crate::matching::MatchSide;

/// What kind of failure an error is, which says who can act on it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ErrorKind {
    /// The input is invalid: a value, count, text, range, table or length outside what is
    /// valid, or constants an analysis needs and was not given. Changing the input fixes it; the
    /// message names the input, its value and what would be valid.
    Input,
    /// The input is valid but the case lies outside what the analysis covers: the contact slides
    /// where partial slip is needed, slip reverses inside a half-cycle, the stick zone leaves the
    /// smaller contact, an estimate breaks down, a profile is asymmetric where symmetry is
    /// assumed, or no test matches the prototype. Another route
    /// ([`Error::alternative`]) or another design may cover it; no numerical setting will.
    OutsideAnalysis,
    /// A numerical procedure failed on a case inside the analysis: an iteration did not converge
    /// or settle, a factorisation met a non-positive pivot, a march did not reach a steady cycle,
    /// or the worker threads could not be started. Solver settings (cells, increments,
    /// iterations, threads) may fix it.
    Solver,
}

impl ErrorKind {
    /// Every kind, in the order of the declaration.
    pub const ALL: [ErrorKind; 3] = [
        ErrorKind::Input,
        ErrorKind::OutsideAnalysis,
        ErrorKind::Solver,
    ];

    /// "input", "outside-analysis" or "solver".
    pub fn as_str(self) -> &'static str {
        match self {
            ErrorKind::Input => "input",
            ErrorKind::OutsideAnalysis => "outside-analysis",
            ErrorKind::Solver => "solver",
        }
    }
}

crate::labels::display_as_str!(ErrorKind);

/// Another route of this library that may succeed where an error's route stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Alternative {
    /// Time marching ([`crate::march`]) makes none of the steady-state analysis's assumptions
    /// about the slip direction and the place of the stick zone; it needs the case as a history.
    March,
    /// The prototype is inside the analysis, but no test of this geometry matches it by this
    /// route: another test geometry, or the other matching route (exact or asymptotic), may.
    OtherTest,
}

impl Error {
    /// The variant's stable name, spelled as the variant (`"MomentOutsideTable"`): front ends
    /// show it (Python's `HalfplaneError.variant`) so that programs tell errors apart without
    /// reading messages. Names are never reused or changed.
    pub fn name(&self) -> &'static str {
        match self {
            Error::InvalidInput { .. } => "InvalidInput",
            Error::InvalidCount { .. } => "InvalidCount",
            Error::TooManyIncrements { .. } => "TooManyIncrements",
            Error::InvalidRow { .. } => "InvalidRow",
            Error::EmptyTable { .. } => "EmptyTable",
            Error::TooManyRows { .. } => "TooManyRows",
            Error::InvalidTable { .. } => "InvalidTable",
            Error::BeyondTable { .. } => "BeyondTable",
            Error::SlipReversesInHalf { .. } => "SlipReversesInHalf",
            Error::NoStickZone { .. } => "NoStickZone",
            Error::StickZoneOutsideContact { .. } => "StickZoneOutsideContact",
            Error::GrossSliding { .. } => "GrossSliding",
            Error::AsymptoticBreakdown { .. } => "AsymptoticBreakdown",
            Error::SlidesAtStep { .. } => "SlidesAtStep",
            Error::ActiveSet { .. } => "ActiveSet",
            Error::NonPositivePivot { .. } => "NonPositivePivot",
            Error::NoCycle { .. } => "NoCycle",
            Error::NoConvergence { .. } => "NoConvergence",
            Error::NotSteady { .. } => "NotSteady",
            Error::InvalidText { .. } => "InvalidText",
            Error::InvalidRange { .. } => "InvalidRange",
            Error::NotUsed { .. } => "NotUsed",
            Error::MissingConstants { .. } => "MissingConstants",
            Error::ThreadPool { .. } => "ThreadPool",
            Error::UnequalColumns { .. } => "UnequalColumns",
            Error::LengthMismatch { .. } => "LengthMismatch",
            Error::NoValidMatch { .. } => "NoValidMatch",
            Error::MatchNotBracketed { .. } => "MatchNotBracketed",
            Error::OutsideProfile { .. } => "OutsideProfile",
            Error::AsymmetricProfile { .. } => "AsymmetricProfile",
            Error::MomentOutsideTable { .. } => "MomentOutsideTable",
            Error::WearStopped { .. } => "WearStopped",
            Error::GridTooNarrow { .. } => "GridTooNarrow",
        }
    }

    /// The kind of failure (see [`ErrorKind`] for what each means). A table that is too short
    /// for the contact (`BeyondTable`, `OutsideProfile`, `MomentOutsideTable`) is bad input:
    /// the table has to be extended.
    pub fn kind(&self) -> ErrorKind {
        match self {
            // A wear run that stopped is whatever stopped it.
            Error::WearStopped { cause, .. } => cause.kind(),
            Error::InvalidInput { .. }
            | Error::InvalidCount { .. }
            | Error::TooManyIncrements { .. }
            | Error::InvalidRow { .. }
            | Error::EmptyTable { .. }
            | Error::TooManyRows { .. }
            | Error::InvalidTable { .. }
            | Error::BeyondTable { .. }
            | Error::NoCycle { .. }
            | Error::InvalidText { .. }
            | Error::InvalidRange { .. }
            | Error::NotUsed { .. }
            | Error::MissingConstants { .. }
            | Error::UnequalColumns { .. }
            | Error::LengthMismatch { .. }
            | Error::OutsideProfile { .. }
            | Error::MomentOutsideTable { .. }
            | Error::GridTooNarrow { .. } => ErrorKind::Input,
            Error::SlipReversesInHalf { .. }
            | Error::NoStickZone { .. }
            | Error::StickZoneOutsideContact { .. }
            | Error::GrossSliding { .. }
            | Error::AsymptoticBreakdown { .. }
            | Error::SlidesAtStep { .. }
            | Error::NoValidMatch { .. }
            | Error::MatchNotBracketed { .. }
            | Error::AsymmetricProfile { .. } => ErrorKind::OutsideAnalysis,
            Error::ActiveSet { .. }
            | Error::NonPositivePivot { .. }
            | Error::NoConvergence { .. }
            | Error::NotSteady { .. }
            | Error::ThreadPool { .. } => ErrorKind::Solver,
        }
    }

    /// Another route of this library that may succeed where this one stopped, if there is one:
    /// [`Alternative::March`] for a cycle outside the steady-state analysis's assumptions (slip
    /// reversing inside a half, a stick zone outside the smaller contact: `docs/validity.md`),
    /// or the stick-zone equations finding no solution (as with an edge radius of 1e12 times the
    /// flat, whose stick zone leaves the contact), [`Alternative::OtherTest`] when matching finds
    /// no valid test although the prototype is valid. Gross sliding has none: the march slides
    /// too.
    pub fn alternative(&self) -> Option<Alternative> {
        match self {
            Error::WearStopped { .. } => None,
            Error::NoConvergence { what, .. } if *what == crate::steady::STICK_ZONE_EQUATIONS => {
                Some(Alternative::March)
            }
            Error::SlipReversesInHalf { .. } | Error::StickZoneOutsideContact { .. } => {
                Some(Alternative::March)
            }
            Error::NoValidMatch { side, .. } => match side {
                MatchSide::Test => Some(Alternative::OtherTest),
                MatchSide::Prototype => None,
            },
            Error::MatchNotBracketed { .. } => Some(Alternative::OtherTest),
            Error::InvalidInput { .. }
            | Error::InvalidCount { .. }
            | Error::TooManyIncrements { .. }
            | Error::InvalidRow { .. }
            | Error::EmptyTable { .. }
            | Error::TooManyRows { .. }
            | Error::InvalidTable { .. }
            | Error::BeyondTable { .. }
            | Error::NoStickZone { .. }
            | Error::GrossSliding { .. }
            | Error::AsymptoticBreakdown { .. }
            | Error::SlidesAtStep { .. }
            | Error::ActiveSet { .. }
            | Error::NonPositivePivot { .. }
            | Error::NoCycle { .. }
            | Error::NoConvergence { .. }
            | Error::NotSteady { .. }
            | Error::InvalidText { .. }
            | Error::InvalidRange { .. }
            | Error::NotUsed { .. }
            | Error::MissingConstants { .. }
            | Error::ThreadPool { .. }
            | Error::UnequalColumns { .. }
            | Error::LengthMismatch { .. }
            | Error::OutsideProfile { .. }
            | Error::AsymmetricProfile { .. }
            | Error::MomentOutsideTable { .. }
            | Error::GridTooNarrow { .. } => None,
        }
    }
}
