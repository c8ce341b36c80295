//! The `match` report: one nested record, prototype against test. The JSON is its
//! serialization; the table shows it in words.

use super::steady::{profile_report, ProfileReport};
use crate::matching::MatchConfig;
use crate::units::{Quantity, Units};
use halfplane::labels::{Edge, PerEdge, PerPoint};
use halfplane::matching::{Compared, MatchReport, Side};
use serde::Serialize;
use std::fmt::Write;

/// The `match` report.
#[derive(Serialize)]
pub struct MatchReportOut {
    mode: &'static str,
    /// The matched quantities, in words.
    matched: &'static str,
    /// The prototype's edge whose K_N the test takes ("left" or "right"; both edges' are equal
    /// without a moment on a symmetric prototype).
    matched_edge: &'static str,
    /// Whether the prototype's two edges have different K_N (table only).
    #[serde(skip)]
    edges_differ: bool,
    prototype_file: String,
    test_file: String,
    prototype: SideOut,
    test: SideOut,
    normal_intensity: Points<CompareOut>,
    shear_intensity: Edges<Points<CompareOut>>,
    mean_shear_intensity: Edges<CompareOut>,
    equivalent_shear: Edges<Points<CompareOut>>,
    edge_motion: CompareOut,
    slip_zones: Edges<Points<CompareOut>>,
    warnings: Vec<String>,
    units: Units,
}

#[derive(Serialize)]
struct SideOut {
    regime: &'static str,
    profile: ProfileReport,
    compliance: f64,
    friction: f64,
    points: Points<PointOut>,
    half_width: Points<f64>,
}

#[derive(Serialize)]
struct PointOut {
    normal: f64,
    shear: f64,
    bulk: f64,
    moment: f64,
}

#[derive(Serialize, Clone, Copy)]
struct Points<T> {
    at_point1: T,
    at_point2: T,
}

#[derive(Serialize, Clone, Copy)]
struct Edges<T> {
    left: T,
    right: T,
}

#[derive(Serialize, Clone, Copy)]
struct CompareOut {
    prototype: f64,
    test: f64,
    /// (test - prototype)/|prototype|; null when the prototype's value is zero.
    mismatch: Option<f64>,
}

fn cmp(c: Compared) -> CompareOut {
    CompareOut {
        prototype: c.prototype,
        test: c.test,
        mismatch: c.mismatch,
    }
}

fn points<T, U>(p: PerPoint<T>, f: impl Fn(T) -> U) -> Points<U> {
    Points {
        at_point1: f(p.first),
        at_point2: f(p.second),
    }
}

fn edges<T, U>(e: PerEdge<T>, f: impl Fn(T) -> U) -> Edges<U> {
    Edges {
        left: f(e.left),
        right: f(e.right),
    }
}

fn side(s: &Side) -> SideOut {
    let (first, second) = s.cycle.as_given();
    let point = |p: halfplane::LoadPoint| PointOut {
        normal: p.normal(),
        shear: p.shear(),
        bulk: p.bulk(),
        moment: p.moment(),
    };
    SideOut {
        regime: s.steady.regime.as_str(),
        profile: profile_report(&s.contact),
        compliance: s.contact.compliance().value(),
        friction: s.contact.friction().value(),
        points: Points {
            at_point1: point(first),
            at_point2: point(second),
        },
        half_width: points(s.steady.half_width, |a| a),
    }
}

impl MatchReportOut {
    /// The report of a match, with the files and the notes (warnings) to carry.
    pub fn new(report: &MatchReport, config: &MatchConfig, notes: &[String]) -> Self {
        let per_point = |p: PerPoint<Compared>| points(p, cmp);
        Self {
            mode: report.mode.as_str(),
            matched: match report.mode {
                halfplane::matching::Mode::Exact => {
                    "K_N at both points; exact slip zones at both edges at point2; mean K_T over \
                     the points at each edge"
                }
                _ => "K_N at both points; K_T at both edges at both points",
            },
            matched_edge: report.prototype.edge.as_str(),
            edges_differ: report.prototype.edges.iter().any(|e| {
                e.contact.normal_intensity(Edge::Left) != e.contact.normal_intensity(Edge::Right)
            }),
            prototype_file: config.prototype_path.display().to_string(),
            test_file: config.output.display().to_string(),
            prototype: side(&report.prototype),
            test: side(&report.test),
            normal_intensity: per_point(report.normal_intensity),
            shear_intensity: edges(report.shear_intensity, per_point),
            mean_shear_intensity: edges(report.mean_shear_intensity, cmp),
            equivalent_shear: edges(report.equivalent_shear, per_point),
            edge_motion: cmp(report.edge_motion),
            slip_zones: edges(report.slip_zones, per_point),
            warnings: notes.to_vec(),
            units: config.prototype.units.clone(),
        }
    }

    /// One JSON object.
    pub fn json(&self) -> serde_json::Result<String> {
        serde_json::to_string_pretty(self)
    }

    /// A readable table: prototype, test and mismatch per quantity.
    pub fn table(&self) -> String {
        let mut o = String::new();
        let u = &self.units;
        let _ = writeln!(o, "match        {} ({})", self.mode, self.matched);
        if self.edges_differ {
            let _ = writeln!(
                o,
                "edge         K_N at the prototype's {} edge (its two edges' differ under the moment; --edge chooses)",
                self.matched_edge
            );
        }
        for (name, s, file) in [
            ("prototype", &self.prototype, &self.prototype_file),
            ("test", &self.test, &self.test_file),
        ] {
            let _ = writeln!(
                o,
                "{name:<12} {:<13} A = {:.6e} 1/{}   f = {}   {}   ({file})",
                s.profile.kind, s.compliance, u.stress, s.friction, s.regime
            );
        }
        let _ = writeln!(
            o,
            "{:<26}{:>14} {:>14} {:>10}",
            "", "prototype", "test", "mismatch"
        );
        let force = u.of(Quantity::ForcePerLength);
        let (pp, tp) = (&self.prototype.points, &self.test.points);
        for (label, a, b) in [
            ("point1", &pp.at_point1, &tp.at_point1),
            ("point2", &pp.at_point2, &tp.at_point2),
        ] {
            pair(
                &mut o,
                &format!("{label} normal P"),
                a.normal,
                b.normal,
                &force,
            );
            pair(
                &mut o,
                &format!("{label} shear Q"),
                a.shear,
                b.shear,
                &force,
            );
            pair(
                &mut o,
                &format!("{label} bulk sigma"),
                a.bulk,
                b.bulk,
                &u.stress,
            );
        }
        let k = u.of(Quantity::Intensity);
        let len = u.of(Quantity::Length);
        let by_point = |o: &mut String, name: &str, p: &Points<CompareOut>, unit: &str| {
            compared(o, &format!("{name} at point1"), &p.at_point1, unit);
            compared(o, &format!("{name} at point2"), &p.at_point2, unit);
        };
        by_point(&mut o, "K_N", &self.normal_intensity, &k);
        for (edge, kt, s) in [
            (
                "left",
                &self.shear_intensity.left,
                &self.equivalent_shear.left,
            ),
            (
                "right",
                &self.shear_intensity.right,
                &self.equivalent_shear.right,
            ),
        ] {
            by_point(&mut o, &format!("K_T {edge}"), kt, &k);
            by_point(&mut o, &format!("S {edge}"), s, &force);
        }
        compared(&mut o, "mean K_T left", &self.mean_shear_intensity.left, &k);
        compared(
            &mut o,
            "mean K_T right",
            &self.mean_shear_intensity.right,
            &k,
        );
        compared(&mut o, "edge motion a2 - a1", &self.edge_motion, &len);
        by_point(&mut o, "slip zone left", &self.slip_zones.left, &len);
        by_point(&mut o, "slip zone right", &self.slip_zones.right, &len);
        o
    }
}

/// A row of two values without a mismatch (the loads, which differ by design).
fn pair(o: &mut String, label: &str, a: f64, b: f64, unit: &str) {
    let _ = writeln!(o, "{label:<26}{a:>14.6} {b:>14.6} {:>10}   {unit}", "");
}

/// A row of a compared quantity with its mismatch in percent.
fn compared(o: &mut String, label: &str, c: &CompareOut, unit: &str) {
    let m = c
        .mismatch
        .map_or("-".to_string(), |m| format!("{:+.3}%", 100.0 * m));
    let _ = writeln!(
        o,
        "{label:<26}{:>14.6} {:>14.6} {m:>10}   {unit}",
        c.prototype, c.test
    );
}
