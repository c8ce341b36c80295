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

/// The bodies' relative tangential displacement `delta` (pad minus specimen, datum `d`: see
/// [`crate::march::Marcher::relative_displacement`]) of the Cattaneo-Mindlin cylinder (Hertz,
/// contact half-width a, similar materials, composite compliance A) under constant P and Q
/// rising monotonically from zero:
///
/// `delta = sign(Q) (A f P/(pi a^2)) [a^2 (ln(2d/a) + 1/2) - c^2 (ln(2d/c) + 1/2)]`,
/// `c` = [`cattaneo_mindlin_stick_half_width`].
///
/// Derived here: the traction is `q = (f p0/a)[sqrt(a^2 - x^2) - sqrt(c^2 - x^2)]` (Johnson,
/// *Contact Mechanics*, section 7.1), and for `|x| <= b`
/// `integral_{-b}^{b} sqrt(b^2 - xi^2) ln|x - xi| dxi = (pi b^2/2)(ln(b/2) - 1/2) + pi x^2/2`
/// (its x-derivative is the finite Hilbert transform `pi x`; the constant from
/// `integral_0^1 sqrt(1 - t^2) ln t dt = -(pi/8)(1 + 2 ln 2)`), so the surfaces' displacement
/// `u = (A/pi) integral q ln(|x - xi|/d) dxi` is the same at every stick point (the `x^2` terms
/// cancel) and the stick condition `u + delta = 0` gives delta. Small Q: `delta = (A/pi) Q
/// ln(2d/a)`, the full-stick compliance.
pub fn cattaneo_mindlin_displacement(
    compliance: f64,
    half_width: f64,
    friction: f64,
    normal: f64,
    shear: f64,
    datum: f64,
) -> f64 {
    let a = half_width;
    let c = cattaneo_mindlin_stick_half_width(a, friction, normal, shear);
    let term = |b: f64| {
        if b > 0.0 {
            b * b * ((2.0 * datum / b).ln() + 0.5)
        } else {
            0.0
        }
    };
    shear.signum() * compliance * friction * normal / (PI * a * a) * (term(a) - term(c))
}

/// The steady fretting loop of the Cattaneo-Mindlin cylinder between `-amplitude` and
/// `+amplitude` of Q at constant P: on the rising branch `delta(Q) = -delta_0(Q*) + 2
/// delta_0((Q + Q*)/2)`, on the falling one `delta(Q) = delta_0(Q*) - 2 delta_0((Q* - Q)/2)`,
/// with `delta_0` = [`cattaneo_mindlin_displacement`] and `Q*` the amplitude (Mindlin and
/// Deresiewicz, *J. Appl. Mech.* 20, 1953, by the superposition of Ciavarella, *Int. J. Solids
/// Struct.* 35, 1998, which holds in plane strain for similar materials).
#[allow(clippy::too_many_arguments)]
pub fn cattaneo_mindlin_loop_displacement(
    compliance: f64,
    half_width: f64,
    friction: f64,
    normal: f64,
    amplitude: f64,
    shear: f64,
    rising: bool,
    datum: f64,
) -> f64 {
    let first =
        |q: f64| cattaneo_mindlin_displacement(compliance, half_width, friction, normal, q, datum);
    if rising {
        -first(amplitude) + 2.0 * first(0.5 * (shear + amplitude))
    } else {
        first(amplitude) - 2.0 * first(0.5 * (amplitude - shear))
    }
}

/// The slip `s(x)` of the Cattaneo-Mindlin cylinder (as [`cattaneo_mindlin_displacement`])
/// under constant P and Q rising monotonically from zero, positive in the sense Q drives:
///
/// `s = sign(Q) (A f p0/(2a)) [|x| sqrt(x^2 - c^2) - c^2 ln((|x| + sqrt(x^2 - c^2))/c)]`
///
/// in the slip zones `c < |x| <= a`, zero in the stick zone, and zero outside the contact
/// (where there is no slip). `p0 = 2P/(pi a)`, `c` = [`cattaneo_mindlin_stick_half_width`].
///
/// Derived here: the slip is `u(x) - u(0)` with u as in [`cattaneo_mindlin_displacement`]; its
/// gradient is `(A/pi)` times the finite Hilbert transform of the traction, `pi x` from the
/// `sqrt(a^2 - xi^2)` term and `pi (x - sign(x) sqrt(x^2 - c^2))` from the `sqrt(c^2 - xi^2)`
/// one for `|x| > c`, so `ds/dx = sign(x) (A f p0/a) sqrt(x^2 - c^2)`, whose integral from `c`
/// is the bracket. It grows like `|x - c|^(3/2)` from the stick zone. The steady loop's slip
/// range is twice the first loading's at the amplitude (Mindlin-Deresiewicz superposition).
pub fn cattaneo_mindlin_slip(
    compliance: f64,
    half_width: f64,
    friction: f64,
    normal: f64,
    shear: f64,
    x: f64,
) -> f64 {
    let a = half_width;
    let c = cattaneo_mindlin_stick_half_width(a, friction, normal, shear);
    let x = x.abs();
    if x <= c || x > a {
        return 0.0;
    }
    let root = ((x - c) * (x + c)).sqrt();
    let log = if c > 0.0 { ((x + root) / c).ln() } else { 0.0 };
    let p0 = 2.0 * normal / (PI * a);
    shear.signum() * compliance * friction * p0 / (2.0 * a) * (x * root - c * c * log)
}

/// The energy the Cattaneo-Mindlin cylinder dissipates per cycle of Q between `-amplitude` and
/// `+amplitude` at constant P (the area of the loop [`cattaneo_mindlin_loop_displacement`]):
///
/// `W = (A f^2 P^2/pi) (1 - k^4 + 4 k^2 ln k)`, `k = c/a = sqrt(1 - e)`, `e = Q*/(f P)`,
///
/// `= (A f^2 P^2/pi) sum_{n >= 3} 2 e^n/(n (n - 1))` (summed for `e < 0.1`, where the closed
/// form loses digits: `W ~ (A f^2 P^2/pi) e^3/3` for small amplitudes).
///
/// Derived here: `W = 4 Q* delta_0(Q*) - 8 integral_0^{Q*} delta_0(u) du` from the loop's two
/// branches, with `delta_0` = [`cattaneo_mindlin_displacement`] (the datum cancels); integrating
/// in `c^2` gives the closed form. Equally `W = 4 integral f p s dx` with
/// [`cattaneo_mindlin_slip`] at the amplitude (each half-cycle slips through the range `2 s` at
/// `|q| = f p`), which the tests check by quadrature.
pub fn cattaneo_mindlin_loop_energy(
    compliance: f64,
    friction: f64,
    normal: f64,
    amplitude: f64,
) -> f64 {
    let e = (amplitude.abs() / (friction * normal)).min(1.0);
    let shape = if e < 0.1 {
        (3..60)
            .map(|n| 2.0 * e.powi(n) / (n * (n - 1)) as f64)
            .sum::<f64>()
    } else {
        let k2 = 1.0 - e;
        // 4 k^2 ln k = 2 k^2 ln(k^2); zero at k = 0.
        let log = if k2 > 0.0 { 2.0 * k2 * k2.ln() } else { 0.0 };
        1.0 - k2 * k2 + log
    };
    compliance * (friction * normal).powi(2) / PI * shape
}

/// The normal contact `[left_end, right_end]` of a tilted flat punch with rounded edges of unequal
/// radii, in closed form: see [`flat_rounded_tilted`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TiltedContact {
    /// Normal load P.
    pub normal: f64,
    /// Moment M about x = 0 (`integral p x dx`).
    pub moment: f64,
    /// Rigid rotation theta (it adds `theta x` to the gap).
    pub rotation: f64,
    /// K_N at the left and right ends.
    pub intensity: [f64; 2],
}

/// Flat `[-b, b]` with edge radii `R_L` (x < -b) and `R_R` (x > b), contact `[b1, b2]` (either
/// end may lie on the flat or on an arc): the loads, rotation and edge intensities in closed
/// form. With `c = (b1 + b2)/2`, `a = (b2 - b1)/2`, `xi = c + a cos(phi)`, the arcs are
/// `phi < phi_R` (`xi > b`) and `phi > phi_L` (`xi < -b`), where g' is linear in cos(phi), so
/// `I_j = integral_0^pi g' cos(j phi) dphi` is a sum of `integral cos(n phi) = sin(n phi)/n` and
/// `A P = a I_1`, `A M = c A P + a^2 I_2/2`, `theta = -I_0/pi` (Johnson, Contact Mechanics, eq.
/// 2.25a with the consistency condition; the tilted flat-and-rounded punch of Andresen, Hills &
/// Vázquez, Int. J. Mech. Sci. 2019, closed-form solutions for tilted three-part
/// piecewise-quadratic half-plane contacts). The intensities are
/// `K_right = sqrt(2/a)/(pi A) integral [g'(b2) - g'(xi)]/(1 - cos phi) dphi` and
/// `K_left = sqrt(2/a)/(pi A) integral [g'(xi) - g'(b1)]/(1 + cos phi) dphi`, whose pieces
/// integrate to `cot(phi/2)` and `tan(phi/2)`. Sign conventions as [`crate::normal_moment`].
pub fn flat_rounded_tilted(
    compliance: f64,
    flat_half_width: f64,
    radii: (f64, f64),
    left_end: f64,
    right_end: f64,
) -> TiltedContact {
    let (b, (r_left, r_right)) = (flat_half_width, radii);
    let (c, a) = (0.5 * (left_end + right_end), 0.5 * (right_end - left_end));
    let angle = |x: f64| ((x - c) / a).clamp(-1.0, 1.0).acos();
    let (phi_r, phi_l) = (angle(b), angle(-b));
    // The arcs: (u, 1/R, from, to) with g' = (u + a cos phi)/R on [from, to].
    let arcs = [
        (c - b, 1.0 / r_right, 0.0, phi_r),
        (c + b, 1.0 / r_left, phi_l, PI),
    ];
    let integral_cos = |n: usize, from: f64, to: f64| match n {
        0 => to - from,
        _ => ((n as f64 * to).sin() - (n as f64 * from).sin()) / n as f64,
    };
    let mut i = [0.0; 3];
    for &(u, k, from, to) in &arcs {
        for (j, v) in i.iter_mut().enumerate() {
            let harmonic = integral_cos(j.abs_diff(1), from, to) + integral_cos(j + 1, from, to);
            *v += k * (u * integral_cos(j, from, to) + 0.5 * a * harmonic);
        }
    }
    // g' at the ends (phi = 0 and pi): on an arc when it is not empty there, else on the flat.
    // (Computed as in the loop below, so that the term of the piece holding an end is exactly 0.)
    let [(u_right, k_right, ..), (u_left, k_left, ..)] = arcs;
    let slope_right = if phi_r > 0.0 {
        (u_right + a) * k_right
    } else if right_end >= -b {
        0.0
    } else {
        (u_left + a) * k_left
    };
    let slope_left = if phi_l < PI {
        (u_left - a) * k_left
    } else if left_end <= b {
        0.0
    } else {
        (u_right - a) * k_right
    };
    let cot = |t: f64| (0.5 * t).cos() / (0.5 * t).sin();
    let tan = |t: f64| (0.5 * t).tan();
    // A piece with g' = (u + a cos)/R on [from, to] (k = 1/R; the flat has k = 0):
    // [g'(b2) - g']/(1 - cos) = (g'(b2) - (u + a) k)/(1 - cos) + a k, and
    // [g' - g'(b1)]/(1 + cos) = ((u - a) k - g'(b1))/(1 + cos) + a k.
    let segments = [arcs[0], (0.0, 0.0, phi_r, phi_l), arcs[1]];
    let (mut right, mut left) = (0.0, 0.0);
    for &(u, k, from, to) in &segments {
        if to <= from {
            continue;
        }
        let towards_right = slope_right - (u + a) * k;
        if towards_right != 0.0 {
            right += towards_right * (cot(from) - cot(to));
        }
        let towards_left = (u - a) * k - slope_left;
        if towards_left != 0.0 {
            left += towards_left * (tan(to) - tan(from));
        }
        right += a * k * (to - from);
        left += a * k * (to - from);
    }
    let scale = (2.0 / a).sqrt() / (PI * compliance);
    let normal = a * i[1] / compliance;
    TiltedContact {
        normal,
        moment: c * normal + 0.5 * a * a * i[2] / compliance,
        rotation: -i[0] / PI,
        intensity: [scale * left, scale * right],
    }
}
