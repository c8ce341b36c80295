//! The slip-zone map of the paper's Figure 5, as plain data: the right-edge slip zone at the
//! smaller contact against the shear range, over a grid of friction coefficients, P2/P1 ratios
//! and tension ranges.
//!
//! Each point is one in-phase cycle analysed by [`steady::analyse`]
//! (`docs/theory.md`, "Regime of an in-phase cycle" and "Permanent stick zone: eqs. (16) and
//! (23)"). With the conventions of `docs/theory.md` ("Conventions"): point 1 has normal load `P1`
//! and point 2 `P2 = (P2/P1) P1`; `P0 = (P1 + P2)/2` and `a0 = a(P0)`; the cycle is centred on
//! `Q = 0` and on `sigma = 0`, so `Q1 = -dQ/2`, `Q2 = dQ/2`, `sigma1 = dsigma/2` and
//! `sigma2 = -dsigma/2` (`dsigma = sigma1 - sigma2`). The point drawn is
//!
//! `x = dQ/(f P0)`, `y = (min(a1, a2) - n)/a0`,
//!
//! the slip zone at the right edge of the smaller contact (`n` the right end of the permanent
//! stick zone `[-m, n]`), and `y = 0` in full stick. At the smaller contact a larger P2/P1
//! shortens the slip zone, and with `dsigma = 0` the curves meet zero continuously at the
//! full-stick limit.
//!
//! Points where the analysis does not apply (gross sliding, slip zones that do not grow
//! monotonically through a half-cycle, a stick zone outside the contact: every error of
//! [`steady::analyse`]) are left out, which breaks a curve into pieces.
//! With tension the curves stop short of the full-stick limit, since monotone growth needs
//! `dQ - pi a_max |dsigma|/4 > f |dP|` (`docs/theory.md`, "Permanent stick zone", Validity).
//!
//! ```
//! use halfplane::slip_map::SlipMap;
//! use halfplane::{Contact, Friction, Material, Profile};
//!
//! let contact = Contact::new(Profile::hertz(50.0)?, Material::new(200_000.0, 0.3)?, Friction::new(0.6)?);
//! let map = SlipMap { normal: 1000.0, frictions: vec![0.6], ratios: vec![1.0], tensions: vec![0.0], samples: 10 };
//! let panels = map.sweep(&contact)?;
//! let curve = &panels[0].curves[0];
//! assert_eq!(curve.points().count(), 9); // x = 0.1, ..., 0.9: all in partial slip
//! # Ok::<(), halfplane::Error>(())
//! ```

use crate::error::Result;
use crate::load::{Cycle, LoadPoint};
use crate::material::Friction;
use crate::normal::Contact;
use crate::steady::{self, Regime, SteadyOptions};

/// Parameters of the slip-zone map (the paper's Figure 5).
#[derive(Debug, Clone, PartialEq)]
pub struct SlipMap {
    /// Normal load at point 1, P1 (force per length).
    pub normal: f64,
    /// Friction coefficients, one panel each (the paper: 0.3 and 0.6).
    pub frictions: Vec<f64>,
    /// P2/P1 values.
    pub ratios: Vec<f64>,
    /// dsigma/P1 values (1/length), with dsigma = sigma1 - sigma2.
    pub tensions: Vec<f64>,
    /// The points along `x = dQ/(f P0)` are `i/samples` for `i = 1, ..., samples - 1`, all in
    /// (0, 1).
    pub samples: usize,
}

/// The curves of one friction coefficient.
#[derive(Debug, Clone, PartialEq)]
pub struct SlipPanel {
    /// The friction coefficient f.
    pub friction: f64,
    /// One curve per (P2/P1, dsigma/P1), ratios outer and tensions inner, in the order given.
    pub curves: Vec<SlipCurve>,
}

/// One curve of the map: the slip zone against the shear range at a fixed P2/P1 and dsigma/P1.
#[derive(Debug, Clone, PartialEq)]
pub struct SlipCurve {
    /// P2/P1.
    pub ratio: f64,
    /// dsigma/P1 (1/length).
    pub tension: f64,
    /// Runs of consecutive points `(dQ/(f P0), (min(a1, a2) - n)/a0)` with increasing x; a new
    /// run starts after points where the analysis does not apply. No run is empty.
    pub pieces: Vec<Vec<(f64, f64)>>,
}

impl SlipCurve {
    /// All the points, run after run.
    pub fn points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.pieces.iter().flatten().copied()
    }
}

impl SlipMap {
    /// The cycle behind the point `x = dQ/(f P0)` of the curve (ratio, tension) at friction `f`:
    /// `(P1, -dQ/2, dsigma/2)` to `(P2, dQ/2, -dsigma/2)` with `P2 = ratio P1`,
    /// `dsigma = tension P1` and `dQ = x f P0`.
    pub fn cycle(&self, friction: f64, ratio: f64, tension: f64, x: f64) -> Result<Cycle> {
        let (p1, p2) = (self.normal, ratio * self.normal);
        let p0 = 0.5 * (p1 + p2);
        let d_sigma = tension * p1;
        let dq = x * friction * p0;
        let low = LoadPoint::new("point1", p1, -0.5 * dq, 0.5 * d_sigma)?;
        let high = LoadPoint::new("point2", p2, 0.5 * dq, -0.5 * d_sigma)?;
        Ok(Cycle::new(low, high))
    }

    /// The whole map: one panel per friction coefficient, in the order given.
    ///
    /// Errors are those of invalid parameters (a friction coefficient, a load or a tension out of
    /// range); a cycle the steady analysis rejects only leaves its point out.
    pub fn sweep(&self, contact: &Contact) -> Result<Vec<SlipPanel>> {
        let mut panels = Vec::with_capacity(self.frictions.len());
        for &f in &self.frictions {
            let c = Contact {
                friction: Friction::new(f)?,
                ..contact.clone()
            };
            let mut curves = Vec::with_capacity(self.ratios.len() * self.tensions.len());
            for &ratio in &self.ratios {
                for &tension in &self.tensions {
                    curves.push(self.curve(&c, ratio, tension)?);
                }
            }
            panels.push(SlipPanel {
                friction: f,
                curves,
            });
        }
        Ok(panels)
    }

    /// One curve, at the friction of `contact`.
    fn curve(&self, contact: &Contact, ratio: f64, tension: f64) -> Result<SlipCurve> {
        let f = contact.friction.value();
        let a0 = contact.half_width(0.5 * (self.normal + ratio * self.normal))?;
        let mut pieces: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
        for i in 1..self.samples {
            let x = i as f64 / self.samples as f64;
            let cycle = self.cycle(f, ratio, tension, x)?;
            match right_slip_zone(contact, &cycle) {
                Some(w) => match pieces.last_mut() {
                    Some(last) => last.push((x, w / a0)),
                    None => pieces.push(vec![(x, w / a0)]),
                },
                None => {
                    if pieces.last().is_some_and(|p| !p.is_empty()) {
                        pieces.push(Vec::new());
                    }
                }
            }
        }
        pieces.retain(|p| !p.is_empty());
        Ok(SlipCurve {
            ratio,
            tension,
            pieces,
        })
    }
}

/// The right-edge slip zone at the smaller contact, `min(a1, a2) - n`, of the steady state of
/// `cycle` (`docs/theory.md`, "Conventions": the slip zone at the right edge at point i is
/// `a_i - n`); 0 in full stick. `None` where the analysis does not apply: gross sliding, or any
/// error of [`steady::analyse`] with default options.
pub fn right_slip_zone(contact: &Contact, cycle: &Cycle) -> Option<f64> {
    let s = steady::analyse(contact, cycle, &SteadyOptions::default()).ok()?;
    match s.regime {
        Regime::FullStick => Some(0.0),
        Regime::PartialSlip => {
            let right = s.stick_zone.map_or(0.0, |z| z.right);
            Some(s.half_width.first.min(s.half_width.second) - right)
        }
        Regime::GrossSliding { .. } => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::hertz as contact;

    fn map() -> SlipMap {
        SlipMap {
            normal: 1000.0,
            frictions: vec![0.3, 0.6],
            ratios: vec![1.0, 1.5],
            tensions: vec![0.0, 0.02],
            samples: 20,
        }
    }

    #[test]
    fn layout_follows_the_parameters() {
        let panels = map().sweep(&contact()).unwrap();
        assert_eq!(panels.len(), 2);
        assert_eq!(panels[0].friction, 0.3);
        assert_eq!(panels[1].friction, 0.6);
        for p in &panels {
            let params: Vec<_> = p.curves.iter().map(|c| (c.ratio, c.tension)).collect();
            assert_eq!(
                params,
                vec![(1.0, 0.0), (1.0, 0.02), (1.5, 0.0), (1.5, 0.02)]
            );
            for c in &p.curves {
                assert!(c.pieces.iter().all(|r| !r.is_empty()));
                let xs: Vec<f64> = c.points().map(|q| q.0).collect();
                assert!(xs.windows(2).all(|w| w[0] < w[1]));
                assert!(xs.iter().all(|&x| x > 0.0 && x < 1.0));
            }
        }
    }

    #[test]
    fn without_tension_at_equal_loads_the_curve_is_mindlins() {
        // dsigma = 0, P2 = P1: the steady slip zone is Mindlin's, (a - a(P_K))/a with
        // P_K = P0 (1 - dQ/(2 f P0)), at every x, and no point is left out.
        let c = contact();
        let a = c.half_width(1000.0).unwrap();
        for panel in map().sweep(&c).unwrap() {
            let curve = &panel.curves[0];
            assert_eq!((curve.ratio, curve.tension), (1.0, 0.0));
            assert_eq!(curve.pieces.len(), 1);
            assert_eq!(curve.pieces[0].len(), 19);
            for (x, y) in curve.points() {
                let mindlin = (a - c.half_width(1000.0 * (1.0 - x / 2.0)).unwrap()) / a;
                assert!((y - mindlin).abs() < 1e-12, "x = {x}: {y} vs {mindlin}");
            }
        }
    }

    #[test]
    fn full_stick_points_are_zero() {
        // P2/P1 = 2 with dsigma = 0: eq. (1) holds for small dQ (the contact grows more than the
        // shear needs), so the first points stick wholly and are drawn at 0.
        let c = contact();
        let m = SlipMap {
            ratios: vec![2.0],
            tensions: vec![0.0],
            frictions: vec![0.6],
            ..map()
        };
        let curve = &m.sweep(&c).unwrap()[0].curves[0];
        let mut zeros = 0;
        for (x, y) in curve.points() {
            let cycle = m.cycle(0.6, 2.0, 0.0, x).unwrap();
            let s = steady::analyse(&c, &cycle, &SteadyOptions::default()).unwrap();
            if s.regime == Regime::FullStick {
                assert_eq!(y, 0.0, "x = {x}");
                zeros += 1;
            } else {
                assert!(y > 0.0, "x = {x}: {y}");
            }
        }
        assert!(zeros > 0, "the sweep should reach full stick: {curve:?}");
    }

    #[test]
    fn a_point_is_the_steady_analysis() {
        let c = contact();
        let m = map();
        let panels = m.sweep(&c).unwrap();
        // f = 0.6, P2/P1 = 1.5, dsigma/P1 = 0.02, at x = 0.9.
        let curve = &panels[1].curves[3];
        assert_eq!((curve.ratio, curve.tension), (1.5, 0.02));
        let (x, y) = curve.points().find(|p| (p.0 - 0.9).abs() < 1e-12).unwrap();
        let (p1, p2) = (1000.0, 1500.0);
        let p0 = 0.5 * (p1 + p2);
        let dq = x * 0.6 * p0;
        let cycle = Cycle::new(
            LoadPoint::new("point1", p1, -0.5 * dq, 0.5 * 20.0).unwrap(),
            LoadPoint::new("point2", p2, 0.5 * dq, -0.5 * 20.0).unwrap(),
        );
        let s = steady::analyse(&c, &cycle, &SteadyOptions::default()).unwrap();
        assert_eq!(s.regime, Regime::PartialSlip);
        let n = s.stick_zone.unwrap().right;
        let expected =
            (s.half_width.first.min(s.half_width.second) - n) / c.half_width(p0).unwrap();
        assert!((y - expected).abs() < 1e-12, "{y} vs {expected}");
    }

    #[test]
    fn points_the_analysis_rejects_are_left_out() {
        // Much tension: near the full-stick limit slip reverses within a half-cycle, so the
        // curve stops short of x = 0 and those points are not drawn.
        let c = contact();
        let m = SlipMap {
            tensions: vec![0.2],
            ratios: vec![1.0],
            frictions: vec![0.6],
            ..map()
        };
        let curve = &m.sweep(&c).unwrap()[0].curves[0];
        let drawn: Vec<f64> = curve.points().map(|p| p.0).collect();
        assert!(drawn.len() < 19, "{drawn:?}");
        for i in 1..20 {
            let x = i as f64 / 20.0;
            let cycle = m.cycle(0.6, 1.0, 0.2, x).unwrap();
            assert_eq!(
                drawn.contains(&x),
                right_slip_zone(&c, &cycle).is_some(),
                "x = {x}"
            );
        }
    }

    #[test]
    fn invalid_parameters_are_errors() {
        let m = SlipMap {
            frictions: vec![-0.1],
            ..map()
        };
        assert!(m.sweep(&contact()).is_err());
    }
}
