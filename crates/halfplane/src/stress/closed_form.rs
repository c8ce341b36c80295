//! Closed-form stress fields of the half-plane, used as independent references by the tests and
//! the documentation (`docs/stress.md`): the Flamant line loads, McEwen's fields under Hertzian
//! pressure and shear, and the Nowell-Hills partial-slip superposition with a stick-zone offset.
//!
//! Conventions (those of [`crate::stress`]): the body occupies `z >= 0` (z the depth), `x` runs
//! along the surface in the sense of positive Q; the pressure `p` is compressive positive and the
//! shear traction `q` is the one the other body exerts on this surface, positive in `+x`. Stresses
//! are tension positive. Each function returns `[sxx, szz, sxz]` (in-plane components; plane strain
//! gives `syy = nu (sxx + szz)`). None of them calls the general route of [`crate::stress`]: they
//! must stay independent of what they check.

use std::f64::consts::PI;

/// Stresses of a unit compressive line load at the origin, `[sxx, szz, sxz]` at `(x, z)`, `z > 0`:
/// `sxx = -(2/pi) x^2 z/r^4`, `szz = -(2/pi) z^3/r^4`, `sxz = -(2/pi) x z^2/r^4`, `r^2 = x^2 + z^2`
/// (Flamant; Johnson, *Contact Mechanics*, 1985, eq. 2.15, rewritten in Cartesian components).
pub fn flamant_normal(x: f64, z: f64) -> [f64; 3] {
    let r2 = x * x + z * z;
    let c = -2.0 / (PI * r2 * r2);
    [c * x * x * z, c * z * z * z, c * x * z * z]
}

/// Stresses of a unit tangential line load in `+x` at the origin, `[sxx, szz, sxz]` at `(x, z)`,
/// `z > 0`: `sxx = -(2/pi) x^3/r^4`, `szz = -(2/pi) x z^2/r^4`, `sxz = -(2/pi) x^2 z/r^4`
/// (Johnson, *Contact Mechanics*, eq. 2.19, in Cartesian components).
pub fn flamant_tangential(x: f64, z: f64) -> [f64; 3] {
    let r2 = x * x + z * z;
    let c = -2.0 / (PI * r2 * r2);
    [c * x * x * x, c * x * z * z, c * x * x * z]
}

/// McEwen's auxiliary quantities `(m, n)` at `(x, z)` for a strip of half-width `a` centred at
/// the origin: `m^2 = (R' + A')/2`, `n^2 = (R' - A')/2` with `A' = a^2 - x^2 + z^2` and
/// `R' = sqrt(A'^2 + 4 x^2 z^2)`; `m >= 0` and `n` takes the sign of `x` (McEwen, Phil. Mag. 40,
/// 1949; Johnson, *Contact Mechanics*, eqs. 7.16-7.18, in the body `z >= 0`).
fn mcewen_mn(a: f64, x: f64, z: f64) -> (f64, f64) {
    let big_a = a * a - x * x + z * z;
    let big_r = (big_a * big_a + 4.0 * x * x * z * z).sqrt();
    let m = (0.5 * (big_r + big_a)).max(0.0).sqrt();
    let n = (0.5 * (big_r - big_a)).max(0.0).sqrt();
    (m, if x < 0.0 { -n } else { n })
}

/// Stresses under the Hertzian pressure `p = p0 sqrt(1 - x^2/a^2)` on `|x| < a`, as
/// `[sxx, szz, sxz]` (McEwen 1949; Johnson, *Contact Mechanics*, eq. 7.16):
/// `sxx = -(p0/a)[m(1 + (z^2 + n^2)/D) - 2z]`, `szz = -(p0/a) m (1 - (z^2 + n^2)/D)`,
/// `sxz = -(p0/a) n (m^2 - z^2)/D`, `D = m^2 + n^2`. On the surface inside the contact
/// `sxx = szz = -p(x)`; on the axis `szz(0, z) = -p0 a/sqrt(a^2 + z^2)`.
pub fn mcewen_pressure(p0: f64, a: f64, x: f64, z: f64) -> [f64; 3] {
    let (m, n) = mcewen_mn(a, x, z);
    let d = m * m + n * n;
    if d == 0.0 {
        // The contact edges on the surface, where the pressure is zero and continuous.
        return [0.0; 3];
    }
    let k = p0 / a;
    [
        -k * (m * (1.0 + (z * z + n * n) / d) - 2.0 * z),
        -k * m * (1.0 - (z * z + n * n) / d),
        -k * n * (m * m - z * z) / d,
    ]
}

/// Stresses under the shear traction `q = q0 sqrt(1 - x^2/a^2)` on `|x| < a`, positive in `+x`,
/// as `[sxx, szz, sxz]` (McEwen 1949; Johnson, *Contact Mechanics*, eq. 7.18):
/// `sxx = (q0/a)[n(2 - (z^2 - m^2)/D) - 2x]`, `szz = -(q0/a) n (m^2 - z^2)/D`,
/// `sxz = -(q0/a)[m(1 + (z^2 + n^2)/D) - 2z]`. On the surface inside the contact
/// `sxx = -2 q0 x/a`, so the trailing edge `x = -a` carries the tension `2 q0`.
pub fn mcewen_shear(q0: f64, a: f64, x: f64, z: f64) -> [f64; 3] {
    let (m, n) = mcewen_mn(a, x, z);
    let d = m * m + n * n;
    let k = q0 / a;
    if d == 0.0 {
        return [-2.0 * k * x, 0.0, 0.0];
    }
    [
        k * (n * (2.0 - (z * z - m * m) / d) - 2.0 * x),
        -k * n * (m * m - z * z) / d,
        -k * (m * (1.0 + (z * z + n * n) / d) - 2.0 * z),
    ]
}

/// The Nowell-Hills partial-slip state of a Hertzian contact under constant P, with Q and the
/// bulk tension applied together after P (Nowell & Hills, Int. J. Mech. Sci. 29, 1987; Hills &
/// Nowell, *Mechanics of Fretting Fatigue*, 1994, ch. 4): the shear traction is `f p(x)` over the
/// contact minus `f p0 (c/a) sqrt(1 - ((x - e)/c)^2)` over the stick zone of half-width
/// `c = a sqrt(1 - Q/(f P))` centred at `e = sigma a/(4 f p0)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NowellHills {
    /// Peak pressure `p0`.
    pub peak_pressure: f64,
    /// Contact half-width `a`.
    pub half_width: f64,
    /// Friction coefficient `f`.
    pub friction: f64,
    /// Stick-zone half-width `c`.
    pub stick_half_width: f64,
    /// Stick-zone centre `e`.
    pub offset: f64,
    /// Bulk tension `sigma` added to `sxx`.
    pub bulk: f64,
}

impl NowellHills {
    /// The state for Hertz with `P`, `Q >= 0` below `f P`, and `sigma` (`p0 = 2P/(pi a)`,
    /// `c = a sqrt(1 - Q/(f P))`, `e = sigma a/(4 f p0)`).
    pub fn hertz(half_width: f64, friction: f64, normal: f64, shear: f64, bulk: f64) -> Self {
        let p0 = 2.0 * normal / (PI * half_width);
        Self {
            peak_pressure: p0,
            half_width,
            friction,
            stick_half_width: half_width * (1.0 - shear / (friction * normal)).max(0.0).sqrt(),
            offset: bulk * half_width / (4.0 * friction * p0),
            bulk,
        }
    }

    /// `[sxx, szz, sxz]` at `(x, z)`: McEwen's pressure field, plus the sliding shear field
    /// `f p0` over the contact, minus the stick-zone correction (McEwen's shear field of
    /// half-width c shifted to e, amplitude `f p0 c/a`), plus the bulk tension in `sxx`.
    pub fn stress(&self, x: f64, z: f64) -> [f64; 3] {
        let (a, f, p0, c) = (
            self.half_width,
            self.friction,
            self.peak_pressure,
            self.stick_half_width,
        );
        let p = mcewen_pressure(p0, a, x, z);
        let slide = mcewen_shear(f * p0, a, x, z);
        let stick = if c > 0.0 {
            mcewen_shear(f * p0 * c / a, c, x - self.offset, z)
        } else {
            [0.0; 3]
        };
        [
            p[0] + slide[0] - stick[0] + self.bulk,
            p[1] + slide[1] - stick[1],
            p[2] + slide[2] - stick[2],
        ]
    }

    /// The peak of the surface `sxx`, at the trailing edge `x = -a`:
    /// `2 f p0 [sqrt((1 + e/a)^2 - (c/a)^2) - e/a] + sigma` (Hills & Nowell 1994, from McEwen's
    /// surface stress outside a strip, `sxx = -2 q0 (x - sign(x) sqrt(x^2 - c^2))/c` for `|x| > c`).
    pub fn trailing_edge_peak(&self) -> f64 {
        let (a, c, e) = (self.half_width, self.stick_half_width, self.offset);
        let ea = e / a;
        let ca = c / a;
        2.0 * self.friction * self.peak_pressure * (((1.0 + ea).powi(2) - ca * ca).sqrt() - ea)
            + self.bulk
    }

    /// The shear traction `q(x)` this state puts on the surface (positive in `+x`).
    pub fn traction(&self, x: f64) -> f64 {
        let (a, f, p0, c) = (
            self.half_width,
            self.friction,
            self.peak_pressure,
            self.stick_half_width,
        );
        let outer = (1.0 - (x / a).powi(2)).max(0.0).sqrt();
        let inner = if c > 0.0 {
            (1.0 - ((x - self.offset) / c).powi(2)).max(0.0).sqrt()
        } else {
            0.0
        };
        f * p0 * (outer - (c / a) * inner)
    }

    /// The Hertzian pressure `p0 sqrt(1 - x^2/a^2)`.
    pub fn pressure(&self, x: f64) -> f64 {
        self.peak_pressure * (1.0 - (x / self.half_width).powi(2)).max(0.0).sqrt()
    }
}
