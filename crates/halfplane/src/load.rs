//! Load points and the in-phase cycle between two of them.
//!
//! Sign conventions (docs/theory.md, "Conventions"): `normal` P > 0 compresses the contact;
//! `shear` Q and `bulk` sigma (tension in one body, parallel to the interface) are positive as in
//! the paper's Figure 1; `moment` M is the moment of the contact pressure about x = 0,
//! `M = integral p(x) x dx` (docs/theory.md, "Moment"), so the pressure centroid sits at M/P. The cycle's ends are labelled by Q: point 1 is the end with the smaller Q,
//! so `dQ = Q2 - Q1 >= 0`, and the paper's `dsigma = sigma1 - sigma2`.

use crate::error::{lazily_named, physical, physical_positive, Result, MAGNITUDE_LIMIT};

/// Normal force P (> 0), shear force Q (force per unit thickness), bulk tension sigma (stress)
/// and the moment M of the pressure about x = 0 (force times length per unit thickness; 0 unless
/// set with [`LoadPoint::with_moment`]).
///
/// Valid by construction: 1e-30 <= P <= 1e30 and |Q|, |sigma|, |M| <= 1e30
/// ([`crate::error::MAGNITUDE_LIMIT`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadPoint {
    normal: f64,
    shear: f64,
    bulk: f64,
    moment: f64,
}

impl LoadPoint {
    /// Validates P > 0 and that all three are finite. `name` prefixes the field names in errors
    /// (for example `cycle.point1`).
    pub fn new(name: &str, normal: f64, shear: f64, bulk: f64) -> Result<Self> {
        lazily_named(physical_positive, normal, || format!("{name}.normal"))?;
        lazily_named(physical, shear, || format!("{name}.shear"))?;
        lazily_named(physical, bulk, || format!("{name}.bulk"))?;
        Ok(Self {
            normal,
            shear,
            bulk,
            moment: 0.0,
        })
    }

    /// The same point with the moment `moment` (M about x = 0, any sign; finite, |M| <= 1e30).
    /// `name` prefixes the field name in errors, as in [`LoadPoint::new`].
    ///
    /// ```
    /// use halfplane::LoadPoint;
    ///
    /// let point = LoadPoint::new("cycle.point1", 1000.0, 200.0, 0.0)?.with_moment("cycle.point1", 150.0)?;
    /// assert_eq!(point.moment(), 150.0);
    /// assert_eq!(point.centroid(), 0.15);
    /// assert!(point.with_moment("cycle.point1", f64::NAN).is_err());
    /// # Ok::<(), halfplane::Error>(())
    /// ```
    pub fn with_moment(self, name: &str, moment: f64) -> Result<Self> {
        lazily_named(physical, moment, || format!("{name}.moment"))?;
        Ok(Self { moment, ..self })
    }

    /// Normal force per unit thickness P (N/mm), > 0.
    pub fn normal(&self) -> f64 {
        self.normal
    }

    /// Shear force per unit thickness Q (N/mm).
    pub fn shear(&self) -> f64 {
        self.shear
    }

    /// Bulk tension sigma in one body (MPa).
    pub fn bulk(&self) -> f64 {
        self.bulk
    }

    /// Moment M of the contact pressure about x = 0 (N mm/mm); 0 unless set.
    pub fn moment(&self) -> f64 {
        self.moment
    }

    /// The pressure centroid `M/P`, where the resultant normal force acts.
    pub fn centroid(&self) -> f64 {
        self.moment / self.normal
    }

    /// The point a fraction `t` of the way from `self` to `other` (in-phase loading is a straight
    /// segment in P-Q-sigma-M space). `t` is clamped to [0, 1], so the result is valid: P stays a
    /// weighted mean of two positive values.
    pub fn lerp(&self, other: &LoadPoint, t: f64) -> LoadPoint {
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        // The weighted-mean form cannot overflow for finite ends and is exact at t = 0 and 1.
        let mix = |a: f64, b: f64| (1.0 - t) * a + t * b;
        LoadPoint {
            normal: mix(self.normal, other.normal),
            shear: mix(self.shear, other.shear),
            bulk: mix(self.bulk, other.bulk),
            moment: mix(self.moment, other.moment),
        }
    }

    /// The point a fraction `t` in (0, 1] of the way from zero load to `self` (a proportional ramp
    /// from the unloaded state). `t` is clamped to [tiny, 1] and P to at least 1e-30, so that the
    /// point stays valid.
    pub fn scaled(&self, t: f64) -> LoadPoint {
        let t = if t.is_nan() {
            1.0
        } else {
            t.clamp(f64::MIN_POSITIVE, 1.0)
        };
        LoadPoint {
            normal: (t * self.normal).max(1.0 / MAGNITUDE_LIMIT),
            shear: t * self.shear,
            bulk: t * self.bulk,
            moment: t * self.moment,
        }
    }
}

/// An in-phase cycle between two load points, labelled internally by Q.
///
/// Valid by construction: [`Cycle::new`] orders the points, so `low().shear() <= high().shear()`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cycle {
    low: LoadPoint,
    high: LoadPoint,
    swapped: bool,
}

impl Cycle {
    /// Orders the two points by Q. Equal Q keeps the given order.
    pub fn new(first: LoadPoint, second: LoadPoint) -> Self {
        if second.shear >= first.shear {
            Self {
                low: first,
                high: second,
                swapped: false,
            }
        } else {
            Self {
                low: second,
                high: first,
                swapped: true,
            }
        }
    }

    /// The end with the smaller Q (point 1 of the analysis).
    pub fn low(&self) -> LoadPoint {
        self.low
    }

    /// The end with the larger Q (point 2 of the analysis).
    pub fn high(&self) -> LoadPoint {
        self.high
    }

    /// True when the caller's first point is `high` (the points were given in the other order).
    pub fn swapped(&self) -> bool {
        self.swapped
    }

    /// `dQ = Q2 - Q1 >= 0`.
    pub fn shear_range(&self) -> f64 {
        self.high.shear - self.low.shear
    }

    /// The paper's `dsigma = sigma1 - sigma2` (note the order).
    pub fn bulk_range(&self) -> f64 {
        self.low.bulk - self.high.bulk
    }

    /// `dP = P2 - P1` (either sign).
    pub fn normal_range(&self) -> f64 {
        self.high.normal - self.low.normal
    }

    /// Mean normal load `P0 = (P1 + P2)/2`.
    pub fn mean_normal(&self) -> f64 {
        0.5 * (self.low.normal + self.high.normal)
    }

    /// The caller's points, in the caller's order.
    pub fn as_given(&self) -> (LoadPoint, LoadPoint) {
        if self.swapped {
            (self.high, self.low)
        } else {
            (self.low, self.high)
        }
    }
}
