//! The bracketed route to the contact under P and M: an outer iteration on the contact's centre
//! with, at each centre, the half-width carrying P (both bracketed Newton iterations; the method
//! of [`Contact::normal_contact`](crate::Contact::normal_contact), and the fallback of
//! `contact_for` when its Newton iteration on both ends does not settle), and the limits a
//! tabulated profile sets on them.

use super::Resultants;
use crate::error::{Error, Result};
use crate::normal::Contact;
use crate::profile::Shape;

/// Where the inner solve at a fixed centre ended.
enum Fixed {
    Solved(f64, Resultants),
    /// No contact with this centre carries P inside the table.
    Beyond,
}

impl Contact {
    /// The outer iteration on the centre (see [`Contact::normal_contact`]).
    pub(super) fn solve_centre(
        &self,
        normal: f64,
        moment: f64,
        target_p: f64,
        target_m: f64,
    ) -> Result<(f64, f64, Resultants)> {
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        let mut c = moment / normal;
        let mut a = self.first_half_width(normal);
        let mut limits: Option<[(f64, f64); 2]> = None;
        for _ in 0..200 {
            let step = match self.half_width_at(c, a, target_p)? {
                Fixed::Solved(found, r) => {
                    a = found;
                    let residual = r.moment - target_m;
                    if residual > 0.0 {
                        hi = c;
                    } else {
                        lo = c;
                    }
                    let slope = r.moment_c - r.moment_a * r.load_c / r.load_a;
                    let newton = c - residual / slope;
                    if (newton - c).abs() <= 1e-15 * (a + c.abs()) || residual == 0.0 {
                        return Ok((c, a, r));
                    }
                    if newton > lo && newton < hi {
                        newton - c
                    } else if lo.is_finite() && hi.is_finite() {
                        0.5 * (lo + hi) - c
                    } else {
                        // Newton left an open bracket: move by one half-width towards the root.
                        -a * residual.signum()
                    }
                }
                Fixed::Beyond => {
                    // The contact reaches the table's end first: bound the centre by the contact
                    // with that end on the last (first) row, once M is known to be inside.
                    let [low, high] = match limits {
                        Some(l) => l,
                        None => {
                            let l = self.table_limits(target_p)?;
                            let a_comp = self.compliance().value();
                            let (smallest, largest) = (l[0].1 / a_comp, l[1].1 / a_comp);
                            if !(smallest..=largest).contains(&moment) {
                                return Err(Error::MomentOutsideTable {
                                    field: "moment".into(),
                                    value: moment,
                                    normal,
                                    smallest,
                                    largest,
                                });
                            }
                            limits = Some(l);
                            l
                        }
                    };
                    // Whichever side this centre was beyond, the root lies between the two
                    // pinned contacts' centres (M is inside their moments).
                    lo = lo.max(low.0);
                    hi = hi.min(high.0);
                    0.5 * (lo + hi) - c
                }
            };
            if hi - lo <= 1e-15 * (a + c.abs()) {
                let r = self.resultants(c, a)?;
                return Ok((c, a, r));
            }
            c += step;
        }
        Err(Error::NoConvergence {
            what: "contact centre under a moment",
            iterations: 200,
            last_step: (hi - lo) / a,
        })
    }

    /// A first half-width: the symmetric closed forms where they exist, the flat plus Hertz's
    /// half-width on the sharper edge radius for a flat-rounded pad (an upper bound of the
    /// symmetric one), and 0 (meaning: half the room) for a table.
    pub(super) fn first_half_width(&self, normal: f64) -> f64 {
        let a_comp = self.compliance().value();
        let hertz = |r: f64| crate::closed_form::hertz_half_width(a_comp, r, normal);
        match self.profile.shape() {
            Shape::Hertz { radius } => hertz(*radius),
            Shape::PowerLaw {
                coefficient,
                exponent,
            } => crate::closed_form::power_law_half_width(a_comp, *coefficient, *exponent, normal),
            Shape::FlatRounded {
                flat_half_width, ..
            } => {
                let (left, right) = self.profile.edge_radii().unwrap_or((1.0, 1.0));
                flat_half_width + hertz(left.min(right))
            }
            Shape::Tabulated { .. } => 0.0,
        }
    }

    /// The inner iteration: the half-width whose contact centred at `c` carries `A P =
    /// target_p`, from the guess `a` (0: half the room on a table), or the side the centre is
    /// `Beyond` when no contact inside a table carries it.
    fn half_width_at(&self, c: f64, a: f64, target_p: f64) -> Result<Fixed> {
        let (lower, upper) = self.profile.bounds();
        let room = (c - lower).min(upper - c);
        if room <= 0.0 {
            return Ok(Fixed::Beyond);
        }
        let (mut lo, mut hi) = (0.0, f64::INFINITY);
        if room.is_finite() {
            let r = self.resultants(c, room)?;
            if r.load < target_p {
                return Ok(Fixed::Beyond);
            }
            hi = room;
        }
        let mut a = if a > 0.0 && a < hi { a } else { 0.5 * room };
        for _ in 0..200 {
            let r = self.resultants(c, a)?;
            let residual = r.load - target_p;
            let newton = a - residual / r.load_a;
            if (newton - a).abs() <= 1e-15 * a || residual == 0.0 {
                return Ok(Fixed::Solved(a, r));
            }
            if residual > 0.0 {
                hi = a;
            } else {
                lo = a;
            }
            a = if newton > lo && newton < hi {
                newton
            } else if hi.is_finite() {
                0.5 * (lo + hi)
            } else {
                2.0 * a
            };
            // (An unbounded bracket, hi = inf, has not closed: inf <= inf would say it had.)
            if hi.is_finite() && hi - lo <= 1e-15 * hi {
                return Ok(Fixed::Solved(a, self.resultants(c, a)?));
            }
        }
        Err(Error::NoConvergence {
            what: "contact half-width under a moment",
            iterations: 200,
            last_step: (hi - lo) / hi,
        })
    }

    /// For a tabulated profile at `A P = target_p`: `(centre, A M)` of the contact with its left
    /// end on the first row and of the contact with its right end on the last row (the smallest
    /// and largest moments the table can carry at this P). Errors when even the whole table
    /// cannot carry P.
    fn table_limits(&self, target_p: f64) -> Result<[(f64, f64); 2]> {
        let (lower, upper) = self.profile.bounds();
        let whole = self.resultants(0.5 * (lower + upper), 0.5 * (upper - lower))?;
        if whole.load < target_p {
            return Err(Error::OutsideProfile {
                what: "contact under this normal load",
                needed: [f64::NEG_INFINITY, f64::INFINITY],
                defined: [lower, upper],
            });
        }
        // With one end pinned, P grows as the other end moves away from it: bisection with
        // Newton steps on the free end's distance to the pinned one, 2a in (0, upper - lower].
        let pinned = |free_sign: f64| -> Result<(f64, f64)> {
            let pin = if free_sign > 0.0 { lower } else { upper };
            let (mut lo, mut hi) = (0.0, upper - lower);
            let mut width = hi;
            for _ in 0..200 {
                let (c, a) = (pin + free_sign * 0.5 * width, 0.5 * width);
                let r = self.resultants(c, a)?;
                let residual = r.load - target_p;
                // d(AP)/d(width) = (P_a + sign P_c)/2.
                let newton = width - residual / (0.5 * (r.load_a + free_sign * r.load_c));
                if residual > 0.0 {
                    hi = width;
                } else {
                    lo = width;
                }
                if (newton - width).abs() <= 1e-15 * width || hi - lo <= 1e-15 * hi {
                    return Ok((c, r.moment));
                }
                width = if newton > lo && newton < hi {
                    newton
                } else {
                    0.5 * (lo + hi)
                };
            }
            Err(Error::NoConvergence {
                what: "contact with one end on the table's last row",
                iterations: 200,
                last_step: (hi - lo) / hi,
            })
        };
        Ok([pinned(1.0)?, pinned(-1.0)?])
    }
}
