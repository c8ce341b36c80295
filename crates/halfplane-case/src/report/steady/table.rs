//! The `steady` report as a table to read: the points, the contact, the regime, the zones and
//! the asymptotic edge description, with units.

use super::SteadyReport;
use crate::units::Quantity;
use halfplane::steady::{GivenPoint, Regime, SteadyState};
use std::fmt::Write;

/// One labelled row of a two-column (point1, point2) table.
fn row(o: &mut String, label: &str, a: f64, b: f64, note: &str) {
    let _ = writeln!(o, "{label:<15}{a:>14.6} {b:>14.6}{note}");
}

impl SteadyReport {
    /// A readable table.
    pub fn table(&self, steady: &SteadyState) -> String {
        let mut o = String::new();
        let p = &self.points;
        // The unit after a row's numbers, and inside a line.
        let tail = |q: Quantity| format!("   {}", self.units.of(q));
        let len = &self.units.length;
        let _ = writeln!(
            o,
            "profile      {}   A = {:.6e} 1/{}   f = {}",
            self.profile.kind, self.compliance, self.units.stress, self.friction
        );
        let _ = writeln!(o, "               {:>14} {:>14}", "point1", "point2");
        let force = tail(Quantity::ForcePerLength);
        row(&mut o, "normal P", p.first.normal, p.second.normal, &force);
        row(&mut o, "shear Q", p.first.shear, p.second.shear, &force);
        let stress = tail(Quantity::Stress);
        row(&mut o, "bulk sigma", p.first.bulk, p.second.bulk, &stress);
        let centred = self.contact.centred();
        if !centred {
            let moment = tail(Quantity::Moment);
            row(&mut o, "moment M", p.first.moment, p.second.moment, &moment);
        }
        row(
            &mut o,
            "|Q|/P",
            self.criteria.shear_ratio_1,
            self.criteria.shear_ratio_2,
            &format!("   (gross sliding when >= f = {})", self.friction),
        );
        row(
            &mut o,
            "half-width a",
            self.contact.half_width_1,
            self.contact.half_width_2,
            &tail(Quantity::Length),
        );
        let k = &self.contact;
        let intensity = tail(Quantity::Intensity);
        if centred {
            let kn = |v: Option<f64>| v.unwrap_or(f64::NAN);
            row(
                &mut o,
                "K_N",
                kn(k.normal_intensity_1),
                kn(k.normal_intensity_2),
                &intensity,
            );
        } else {
            let length = tail(Quantity::Length);
            row(&mut o, "contact b1", k.left_1, k.left_2, &length);
            row(&mut o, "contact b2", k.right_1, k.right_2, &length);
            let yes = |on: bool| if on { "yes" } else { "no" };
            row(
                &mut o,
                "rotation",
                k.rotation_1,
                k.rotation_2,
                "   rad (the pad's tilt: + raises the right)",
            );
            row(
                &mut o,
                "K_N left",
                k.normal_intensity_left_1,
                k.normal_intensity_left_2,
                &intensity,
            );
            row(
                &mut o,
                "K_N right",
                k.normal_intensity_right_1,
                k.normal_intensity_right_2,
                &intensity,
            );
            for (edge, at_1, at_2) in [
                ("b1", k.on_flat_left_1, k.on_flat_left_2),
                ("b2", k.on_flat_right_1, k.on_flat_right_2),
            ] {
                if at_1 || at_2 {
                    let _ = writeln!(
                        o,
                        "  end {edge} on the flat: point1 {:<4} point2 {}   (flat-punch-like pressure there)",
                        yes(at_1),
                        yes(at_2)
                    );
                }
            }
        }
        let ratio = self
            .criteria
            .full_stick_ratio
            .map_or("infinite (dP = 0)".to_string(), |r| format!("{r:.6}"));
        if centred {
            let _ = writeln!(
                o,
                "eq. (1): (|dQ| + pi a_max |dsigma|/4)/|dP| = {ratio}   (full stick when <= f)"
            );
        } else {
            let _ = writeln!(
                o,
                "eq. (1) edge by edge: max |dS|/|dP_edge| along the cycle = {ratio}   (full stick when <= f)"
            );
        }
        let _ = writeln!(o);
        let regime = match steady.regime {
            Regime::GrossSliding { point } => format!(
                "gross sliding at {} (|Q| >= f P): no steady partial-slip state",
                if point == GivenPoint::First {
                    "point1"
                } else {
                    "point2"
                }
            ),
            Regime::FullStick => "full stick: no slip anywhere in the steady state".to_string(),
            Regime::PartialSlip => {
                "partial slip: permanent stick zone with slip at both edges".to_string()
            }
        };
        let _ = writeln!(o, "regime       {} — {regime}", self.regime);
        if let Some(z) = &self.stick_zone {
            let _ = writeln!(
                o,
                "stick zone   [-m, n] = [{:.6}, {:.6}] {len}   d = {:.6} {len}   e = {:.6} {len}",
                z.left, z.right, z.half_width, z.eccentricity
            );
        }
        if let Some(s) = &self.slip_zones {
            let _ = writeln!(o, "slip zones     {:>14} {:>14}", "at point1", "at point2");
            let length = tail(Quantity::Length);
            row(&mut o, "  left", s.left.first, s.left.second, &length);
            row(&mut o, "  right", s.right.first, s.right.second, &length);
        }
        if let Some(a) = &self.asymptotic {
            let _ = writeln!(o);
            let _ = writeln!(o, "asymptotic (edge) description");
            row(
                &mut o,
                "  K_T left",
                a.edges.first.shear_intensity_left,
                a.edges.second.shear_intensity_left,
                &tail(Quantity::Intensity),
            );
            row(
                &mut o,
                "  K_T right",
                a.edges.first.shear_intensity_right,
                a.edges.second.shear_intensity_right,
                &tail(Quantity::Intensity),
            );
            row(
                &mut o,
                "  S left",
                a.edges.first.equivalent_shear_left,
                a.edges.second.equivalent_shear_left,
                &force,
            );
            row(
                &mut o,
                "  S right",
                a.edges.first.equivalent_shear_right,
                a.edges.second.equivalent_shear_right,
                &force,
            );
            let _ = writeln!(
                o,
                "  P_K          left {:.6}   right {:.6}{force}",
                a.stick_load.left, a.stick_load.right
            );
            let _ = writeln!(
                o,
                "  stick zone   [{:.6}, {:.6}] {len}   vs exact: {:+.3}% left, {:+.3}% right",
                a.stick_zone.left,
                a.stick_zone.right,
                100.0 * a.stick_zone.relative_difference_left,
                100.0 * a.stick_zone.relative_difference_right
            );
            for (name, e) in [("left", &a.slip_zones.left), ("right", &a.slip_zones.right)] {
                for (point, c) in [("point1", &e.first), ("point2", &e.second)] {
                    let _ = writeln!(
                        o,
                        "  slip {name:<5} at {point}: w = {:.6} {len}   exact {:.6} {len}   ({:+.3}%)",
                        c.estimate,
                        c.exact,
                        100.0 * c.relative_difference
                    );
                }
            }
        }
        o
    }
}
