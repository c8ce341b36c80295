//! Closed-form reference solutions. They are first-class: the solvers use them where they apply
//! (Hertz), and the tests and documentation check the general routes against them.
//!
//! Conventions: plane strain, composite compliance `A = 4(1 - nu^2)/E`, half-widths in the length
//! unit of the profile, P and Q per unit thickness; `dsigma = sigma1 - sigma2` and
//! `dQ = Q2 - Q1 >= 0` with point 1 the end of smaller Q (docs/theory.md).

use std::f64::consts::PI;

/// Hertz contact law `a^2 = 2 P A R / pi` (paper eq. (24)).
pub fn hertz_half_width(compliance: f64, radius: f64, normal: f64) -> f64 {
    (2.0 * normal * compliance * radius / PI).sqrt()
}

/// Hertz pressure `p(x) = sqrt(a^2 - x^2)/(A R)`, zero outside the contact (Johnson, Contact
/// Mechanics, eq. 2.46 with `A = 4/E*`; it integrates to `pi a^2/(2 A R) = P`).
pub fn hertz_pressure(compliance: f64, radius: f64, half_width: f64, x: f64) -> f64 {
    let r = half_width * half_width - x * x;
    if r > 0.0 {
        r.sqrt() / (compliance * radius)
    } else {
        0.0
    }
}

/// Hertz permanent stick zone `(d, e)`: `e = -A R dsigma/(8 f)` (paper eq. (28)),
/// `d^2 = (A R/pi)(P1 + P2 - dQ/f)` (eq. (30)). `None` when `d^2 <= 0` (no stick zone).
pub fn hertz_stick_zone(
    compliance: f64,
    radius: f64,
    friction: f64,
    normal_sum: f64,
    shear_range: f64,
    bulk_range: f64,
) -> Option<(f64, f64)> {
    let e = -compliance * radius * bulk_range / (8.0 * friction);
    let d2 = compliance * radius / PI * (normal_sum - shear_range / friction);
    (d2 > 0.0).then(|| (d2.sqrt(), e))
}

/// Flat punch with rounded edges: `P = (a^2/(A R)) [pi/2 - phi0 - sin phi0 cos phi0]`,
/// `sin phi0 = b/a` (docs/theory.md, "Normal contact"; Ciavarella, Hills & Monno 1998). Zero for a <= b.
pub fn flat_rounded_load(
    compliance: f64,
    flat_half_width: f64,
    edge_radius: f64,
    half_width: f64,
) -> f64 {
    if half_width <= flat_half_width {
        return 0.0;
    }
    let phi0 = (flat_half_width / half_width).asin();
    half_width * half_width / (compliance * edge_radius)
        * (0.5 * PI - phi0 - phi0.sin() * phi0.cos())
}

/// The Wallis integral `W_k = integral_0^{pi/2} sin^k phi dphi
/// = (sqrt(pi)/2) Gamma((k+1)/2)/Gamma(k/2 + 1)` for real `k > -1` (Abramowitz & Stegun 6.2.1
/// and 6.2.2 with `B(a, b) = 2 integral_0^{pi/2} sin^(2a-1) cos^(2b-1)`; for whole k, Wallis's
/// formulas). Also `integral_0^pi |cos t|^k dt = 2 W_k`, the contact-law moment of the power law.
pub fn wallis_integral(k: f64) -> f64 {
    0.5 * PI.sqrt() * libm::tgamma(0.5 * (k + 1.0)) / libm::tgamma(0.5 * k + 1.0)
}

/// Power law `g = B|x|^k`: `P = (2 B k a^k / A) W_k` with the Wallis integral `W_k`
/// ([`wallis_integral`]), from `P = (1/A) integral x g'(x)/sqrt(a^2 - x^2) dx` (docs/theory.md).
pub fn power_law_load(compliance: f64, coefficient: f64, exponent: f64, half_width: f64) -> f64 {
    let k = exponent;
    let wallis = wallis_integral(k);
    2.0 * coefficient * k * half_width.powf(k) * wallis / compliance
}

/// Inverse of [`power_law_load`].
pub fn power_law_half_width(compliance: f64, coefficient: f64, exponent: f64, normal: f64) -> f64 {
    let unit = power_law_load(compliance, coefficient, exponent, 1.0);
    (normal / unit).powf(1.0 / exponent)
}

/// Cattaneo-Mindlin stick zone half-width under constant P and monotonic Q from zero:
/// `c = a sqrt(1 - |Q|/(f P))` (Johnson, Contact Mechanics, section 7.1; plane-strain form).
pub fn cattaneo_mindlin_stick_half_width(
    half_width: f64,
    friction: f64,
    normal: f64,
    shear: f64,
) -> f64 {
    half_width * (1.0 - shear.abs() / (friction * normal)).max(0.0).sqrt()
}
