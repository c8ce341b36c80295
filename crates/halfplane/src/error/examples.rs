//! One error of every variant, for front ends to test their mapping of errors (exception classes,
//! hints) against every variant there is. A test here reads the enum's declaration and fails when
//! a variant has no example.

use super::Error;
use crate::labels::{Edge, GivenPoint, Half};
use crate::matching::{LoadIndex, MatchConstraint, MatchSide};

/// One error of every variant, with made-up data (the values mean nothing; the messages are
/// well formed), grouped by kind: bad input, outside the analysis, solver failures.
pub fn one_of_each() -> Vec<Error> {
    let mut all = input();
    all.extend(outside_analysis());
    all.extend(solver());
    all
}

/// The [`crate::error::ErrorKind::Input`] variants.
fn input() -> Vec<Error> {
    vec![
        Error::InvalidInput {
            field: "friction".into(),
            value: -1.0,
            valid: "a finite number > 0",
        },
        Error::InvalidCount {
            field: "solver.cells".into(),
            value: 0,
            min: 4,
            max: 100_000,
        },
        Error::TooManyIncrements {
            field: "history.cycles".into(),
            max: 10,
        },
        Error::InvalidRow {
            table: "history",
            row: 2,
            column: "P",
            value: -1.0,
            valid: "a finite number > 0",
        },
        Error::EmptyTable { what: "history" },
        Error::TooManyRows {
            what: "tabulated profile",
            rows: 11,
            max: 10,
        },
        Error::InvalidTable {
            row: 3,
            problem: "x is not increasing".into(),
        },
        Error::BeyondTable {
            what: "contact",
            needed: 2.0,
            table_end: 1.0,
        },
        Error::NoCycle { what: "fatigue" },
        Error::InvalidText {
            field: "profile".into(),
            value: "round".into(),
            valid: "\"hertz\" or \"flat-rounded\"",
        },
        Error::InvalidRange {
            field: "sweep.axis".into(),
            from: 2.0,
            to: 1.0,
            problem: "from must be below to",
        },
        Error::NotUsed {
            field: "radius".into(),
            value: 1.0,
            kind: "power-law",
        },
        Error::MissingConstants {
            what: "fatigue analysis",
            fields: "fatigue.tau_f",
        },
        Error::UnequalColumns { rows: 3, other: 2 },
        Error::LengthMismatch {
            field: "z".into(),
            length: 2,
            expected: 3,
            per: "one depth z per x",
        },
        Error::OutsideProfile {
            what: "contact",
            needed: [-2.0, 1.0],
            defined: [-1.0, 1.0],
        },
        Error::MomentOutsideTable {
            field: "moment".into(),
            value: 10.0,
            normal: 1.0,
            smallest: -1.0,
            largest: 1.0,
        },
        Error::GridTooNarrow {
            field: "wear.span",
            end: -1.5,
        },
        Error::WearStopped {
            cycle: 12,
            cause: Box::new(Error::InvalidInput {
                field: "gap".into(),
                value: 1.0,
                valid: "a gap whose contact carries the load",
            }),
        },
    ]
}

/// The [`crate::error::ErrorKind::OutsideAnalysis`] variants.
fn outside_analysis() -> Vec<Error> {
    vec![
        Error::SlipReversesInHalf {
            half: Half::First,
            edge: Edge::Left,
            fraction: 0.5,
            boundary_rate: 0.1,
            limit_rate: 0.0,
        },
        Error::NoStickZone {
            shear_range: 2.0,
            limit: 1.0,
        },
        Error::StickZoneOutsideContact {
            left: -2.0,
            right: 0.5,
            common: [-1.0, 1.0],
        },
        Error::GrossSliding {
            point: GivenPoint::Second,
            shear: 2.0,
            limit: 1.0,
        },
        Error::AsymptoticBreakdown {
            edge: "left",
            p_k: -1.0,
        },
        Error::SlidesAtStep {
            step: 3,
            shear: 2.0,
            limit: 1.0,
        },
        Error::NoValidMatch {
            side: MatchSide::Test,
            constraint: MatchConstraint::GrossSliding,
            cause: Some(Box::new(Error::GrossSliding {
                point: GivenPoint::First,
                shear: 2.0,
                limit: 1.0,
            })),
        },
        Error::MatchNotBracketed {
            load: LoadIndex::Point(GivenPoint::First),
            target: 1.0,
            searched: [0.1, 10.0],
        },
        Error::AsymmetricProfile {
            what: "steady-state analysis",
        },
    ]
}

/// The [`crate::error::ErrorKind::Solver`] variants.
fn solver() -> Vec<Error> {
    vec![
        Error::ActiveSet {
            step: 3,
            iterations: 100,
        },
        Error::NonPositivePivot { step: 3, index: 7 },
        Error::NoConvergence {
            what: crate::steady::STICK_ZONE_EQUATIONS,
            iterations: 60,
            last_step: 1e-3,
        },
        Error::NotSteady {
            max_cycles: 20,
            change: 1e-3,
            tolerance: 1e-6,
        },
        Error::ThreadPool {
            message: "no threads".into(),
        },
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::{Alternative, ErrorKind};
    use std::collections::BTreeSet;

    /// The variant names as the declaration of `Error` spells them, read from the source: an
    /// independent list to hold the examples and `Error::name` against.
    fn declared_variants() -> Vec<String> {
        let source = include_str!("../error.rs");
        let body = source
            .split_once("pub enum Error {")
            .and_then(|(_, rest)| rest.split_once("\n}\n"))
            .map(|(body, _)| body)
            .expect("the enum's declaration");
        body.lines()
            .filter_map(|line| line.strip_prefix("    "))
            .filter(|line| line.starts_with(|c: char| c.is_ascii_uppercase()))
            .filter_map(|line| line.split([' ', ',', '{', '(']).next())
            .map(str::to_string)
            .collect()
    }

    #[test]
    fn every_declared_variant_has_one_example_named_as_declared() {
        let declared = declared_variants();
        assert!(declared.len() >= 30, "parsed {declared:?}");
        let examples = one_of_each();
        let mut names: Vec<&str> = examples.iter().map(Error::name).collect();
        names.sort_unstable();
        let mut declared: Vec<&str> = declared.iter().map(String::as_str).collect();
        declared.sort_unstable();
        assert_eq!(names, declared, "one example per declared variant");
        let unique: BTreeSet<&str> = names.iter().copied().collect();
        assert_eq!(unique.len(), names.len(), "names are unique");
        for e in &examples {
            let debug = format!("{e:?}");
            assert!(
                debug.starts_with(&format!("{} ", e.name())),
                "name() {} is the variant's own: {debug}",
                e.name()
            );
            assert!(!e.to_string().is_empty());
        }
    }

    #[test]
    fn every_variant_has_the_kind_decided_for_it() {
        // The classification, written out by kind: bad input, valid cases the analysis does not
        // cover (matching's two errors among them: the case is valid, the matching is not
        // possible), and numerical failures.
        let outside = [
            "SlipReversesInHalf",
            "NoStickZone",
            "StickZoneOutsideContact",
            "GrossSliding",
            "AsymptoticBreakdown",
            "SlidesAtStep",
            "NoValidMatch",
            "MatchNotBracketed",
            "AsymmetricProfile",
        ];
        let solver = [
            "ActiveSet",
            "NonPositivePivot",
            "NoConvergence",
            "NotSteady",
            "ThreadPool",
        ];
        let mut seen = BTreeSet::new();
        for e in one_of_each() {
            let expected = if outside.contains(&e.name()) {
                ErrorKind::OutsideAnalysis
            } else if solver.contains(&e.name()) {
                ErrorKind::Solver
            } else {
                ErrorKind::Input
            };
            assert_eq!(e.kind(), expected, "{}", e.name());
            seen.insert(e.kind().as_str());
        }
        let all: BTreeSet<&str> = ErrorKind::ALL.iter().map(|k| k.as_str()).collect();
        assert_eq!(seen, all, "every kind is used");
    }

    #[test]
    fn only_cycles_the_steady_analysis_cannot_solve_and_failed_tests_have_alternatives() {
        for e in one_of_each() {
            let expected = match e.name() {
                // The example's NoConvergence is the stick-zone equations': a solver failure
                // (not a proven violation of the analysis), which the march may get past.
                "SlipReversesInHalf" | "StickZoneOutsideContact" | "NoConvergence" => {
                    Some(Alternative::March)
                }
                "NoValidMatch" | "MatchNotBracketed" => Some(Alternative::OtherTest),
                _ => None,
            };
            assert_eq!(e.alternative(), expected, "{}", e.name());
            if e.alternative().is_some() && e.name() != "NoConvergence" {
                assert_eq!(e.kind(), ErrorKind::OutsideAnalysis, "{}", e.name());
            }
        }
        let levinson = Error::NoConvergence {
            what: "Levinson recursion (kernel not positive definite)",
            iterations: 3,
            last_step: 1.0,
        };
        assert_eq!(
            levinson.alternative(),
            None,
            "only the stick-zone equations point to march"
        );
        let prototype = Error::NoValidMatch {
            side: MatchSide::Prototype,
            constraint: MatchConstraint::FullStick,
            cause: None,
        };
        assert_eq!(prototype.alternative(), None, "the prototype itself fails");
    }
}
