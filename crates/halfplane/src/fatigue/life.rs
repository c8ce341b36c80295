//! Cycles to initiation from the strain-life curves, solved for N by bisection in log(2N).

use super::constants::FatigueConstants;

/// Solves `curve(2N) = value` for N, the curve decreasing in N. `None` when the value is at or
/// below the curve at `2N = 1e20` (run-out) or not positive; 0.5 when it is above the curve at
/// `2N = 1` (initiation in the first reversal).
fn solve(value: f64, curve: impl Fn(f64) -> f64) -> Option<f64> {
    if value.is_nan() || value <= 0.0 || value <= curve(1e20) {
        return None;
    }
    if value >= curve(1.0) {
        return Some(0.5);
    }
    let (mut lo, mut hi) = (0.0f64, 20.0f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if curve(10f64.powf(mid)) > value {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * 10f64.powf(0.5 * (lo + hi)))
}

/// Cycles N from the Smith-Watson-Topper curve
/// `SWT = (sigma'_f^2/E)(2N)^(2b) + sigma'_f eps'_f (2N)^(b+c)` (Smith, Watson and Topper 1970).
pub fn swt_life(value: f64, youngs: f64, c: &FatigueConstants) -> Option<f64> {
    let (sf, b, ef, cc) = (
        c.fatigue_strength?,
        c.fatigue_strength_exponent?,
        c.fatigue_ductility?,
        c.fatigue_ductility_exponent?,
    );
    solve(value, |n2| {
        sf * sf / youngs * n2.powf(2.0 * b) + sf * ef * n2.powf(b + cc)
    })
}

/// Cycles N from the Fatemi-Socie curve `FS = (tau'_f/G)(2N)^b + gamma'_f (2N)^c` (Fatemi and
/// Socie 1988; the shear exponents taken equal to the axial ones, `b0 = b`, `c0 = c`).
pub fn fatemi_socie_life(value: f64, shear_modulus: f64, c: &FatigueConstants) -> Option<f64> {
    let (tf, b, gf, cc) = (
        c.shear_fatigue_strength?,
        c.fatigue_strength_exponent?,
        c.shear_fatigue_ductility?,
        c.fatigue_ductility_exponent?,
    );
    solve(value, |n2| {
        tf / shear_modulus * n2.powf(b) + gf * n2.powf(cc)
    })
}
