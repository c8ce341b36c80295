//! A minimal complex number for the stress closed forms and expansions (`edge.rs`, `fast/`):
//! `C(re, im)`, principal branches.

use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

/// `re + i im`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(super) struct C(pub f64, pub f64);

impl Add for C {
    type Output = C;
    fn add(self, o: C) -> C {
        C(self.0 + o.0, self.1 + o.1)
    }
}
impl AddAssign for C {
    fn add_assign(&mut self, o: C) {
        self.0 += o.0;
        self.1 += o.1;
    }
}
impl Sub for C {
    type Output = C;
    fn sub(self, o: C) -> C {
        C(self.0 - o.0, self.1 - o.1)
    }
}
impl Neg for C {
    type Output = C;
    fn neg(self) -> C {
        C(-self.0, -self.1)
    }
}
impl Mul for C {
    type Output = C;
    fn mul(self, o: C) -> C {
        C(self.0 * o.0 - self.1 * o.1, self.0 * o.1 + self.1 * o.0)
    }
}
impl Div for C {
    type Output = C;
    fn div(self, o: C) -> C {
        let d = o.0 * o.0 + o.1 * o.1;
        C(
            (self.0 * o.0 + self.1 * o.1) / d,
            (self.1 * o.0 - self.0 * o.1) / d,
        )
    }
}
impl C {
    /// Principal logarithm. `ln |w|` from `hypot` where `|w|^2` underflows or overflows: at
    /// `|w| < 1e-154` (a point within 1e-154 h of an edge interval's end, found with the fuzz
    /// target `stress_points`) `ln 0 = -inf` made the edge form's cancelling logarithms NaN.
    pub fn ln(self) -> C {
        let d = self.0 * self.0 + self.1 * self.1;
        let re = if (f64::MIN_POSITIVE..=f64::MAX).contains(&d) {
            0.5 * d.ln()
        } else {
            self.0.hypot(self.1).ln()
        };
        C(re, self.1.atan2(self.0))
    }
    /// Principal square root; the imaginary part keeps the sign of the argument's (so +0 stays +0).
    /// The smaller part is `im/(2 re)` (or `|im|/(2 |im'|)`), never the root of a difference: near
    /// the positive real axis `sqrt((|w| - re)/2)` would cancel to nothing (a relative error of
    /// 1e-7 in the surface stresses 1e-8 deep, found against a 40-digit evaluation).
    pub fn sqrt(self) -> C {
        let r = self.0.hypot(self.1);
        if r == 0.0 {
            return C(0.0, 0.0);
        }
        if self.0 >= 0.0 {
            let re = (0.5 * (r + self.0)).sqrt();
            C(re, self.1 / (2.0 * re) + 0.0)
        } else {
            let im = (0.5 * (r - self.0)).sqrt();
            let im = if self.1 < 0.0 { -im } else { im };
            C((self.1 / (2.0 * im)).abs(), im)
        }
    }
    /// `k self` for real `k`.
    pub fn scale(self, k: f64) -> C {
        C(self.0 * k, self.1 * k)
    }
}
