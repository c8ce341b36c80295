//! A bracketed scalar root finder with a relative tolerance: Brent's method (R. P. Brent,
//! *Algorithms for Minimization without Derivatives*, Prentice-Hall 1973, chapter 4, procedure
//! `zero`), plus a geometric search for the bracket of a positive unknown. Private to the crate.

use crate::error::Result;

/// Where a bracket search for a positive unknown ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Bracket {
    /// `f` changes sign between the two (or is zero at the first).
    Found(f64, f64),
    /// No sign change between the smallest and largest x tried.
    NotFound {
        /// Smallest x evaluated successfully.
        low: f64,
        /// Largest x evaluated successfully.
        high: f64,
    },
}

/// Looks for a sign change of `f` on x > 0 by doubling and halving from `start` > 0, at most
/// `steps` times each way (`2^steps` either side). An evaluation error or a non-finite value ends
/// the search on that side (for example beyond a tabulated profile); an error at `start` is
/// returned.
pub(crate) fn bracket_positive(
    mut f: impl FnMut(f64) -> Result<f64>,
    start: f64,
    steps: usize,
) -> Result<Bracket> {
    let f0 = f(start)?;
    if f0 == 0.0 {
        return Ok(Bracket::Found(start, start));
    }
    let (mut low, mut high) = (start, start);
    let (mut down, mut up) = (true, true);
    for _ in 0..steps {
        if up {
            let x = 2.0 * high;
            match f(x) {
                Ok(v) if v.is_finite() => {
                    if v.signum() != f0.signum() {
                        return Ok(Bracket::Found(high, x));
                    }
                    high = x;
                }
                _ => up = false,
            }
        }
        if down {
            let x = 0.5 * low;
            match f(x) {
                Ok(v) if v.is_finite() && x > 0.0 => {
                    if v.signum() != f0.signum() {
                        return Ok(Bracket::Found(x, low));
                    }
                    low = x;
                }
                _ => down = false,
            }
        }
        if !(up || down) {
            break;
        }
    }
    Ok(Bracket::NotFound { low, high })
}

/// A root of `f` in `[a, b]`, where `f(a)` and `f(b)` differ in sign (or one is zero), to
/// `|x - root| <= 4 eps |x| + rel_tol |x|`: Brent's `zero` (inverse quadratic interpolation and
/// secant steps, safeguarded by bisection), which never leaves the bracket and converges in at
/// most about `log2((b - a)/tol)^2` evaluations. Errors only when `f` does.
pub(crate) fn brent(
    mut f: impl FnMut(f64) -> Result<f64>,
    a: f64,
    b: f64,
    rel_tol: f64,
) -> Result<f64> {
    let (mut a, mut b) = (a, b);
    let (mut fa, mut fb) = (f(a)?, f(b)?);
    if fa == 0.0 {
        return Ok(a);
    }
    let (mut c, mut fc) = (a, fa);
    let (mut d, mut e) = (b - a, b - a);
    for _ in 0..200 {
        if fb == 0.0 {
            return Ok(b);
        }
        if fb.signum() == fc.signum() {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, fa) = (b, fb);
            (b, fb) = (c, fc);
            (c, fc) = (a, fa);
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * rel_tol * b.abs();
        let m = 0.5 * (c - b);
        if m.abs() <= tol {
            return Ok(b);
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * m * s, 1.0 - s)
            } else {
                let (qa, r) = (fa / fc, fb / fc);
                (
                    s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0)),
                    (qa - 1.0) * (r - 1.0) * (s - 1.0),
                )
            };
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        (a, fa) = (b, fb);
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b)?;
    }
    Ok(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brent_finds_roots_to_the_relative_tolerance() {
        // x^3 = 2 (smooth), and a function flat on one side (as K_N is on a flat punch).
        let r = brent(|x| Ok(x * x * x - 2.0), 0.5, 4.0, 1e-15).unwrap();
        assert!((r - 2f64.cbrt()).abs() <= 4e-15 * r, "cube root {r}");
        let r = brent(|x| Ok((x - 1.3).max(0.0).sqrt() - 0.1), 0.1, 10.0, 1e-15).unwrap();
        assert!((r - 1.31).abs() <= 4e-15 * r, "kinked root {r}");
    }

    #[test]
    fn bracket_search_goes_both_ways_and_reports_failure() {
        let Bracket::Found(a, b) = bracket_positive(|x| Ok(x - 1e6), 1.0, 100).unwrap() else {
            panic!("root above the start not bracketed");
        };
        assert!(a < 1e6 && 1e6 <= b);
        let Bracket::Found(a, b) = bracket_positive(|x| Ok(1e-6 - x), 1.0, 100).unwrap() else {
            panic!("root below the start not bracketed");
        };
        assert!(a <= 1e-6 && 1e-6 < b);
        // A constant never changes sign: the search ends at 2^-10 and 2^10.
        assert_eq!(
            bracket_positive(|_| Ok(1.0), 1.0, 10).unwrap(),
            Bracket::NotFound {
                low: 1.0 / 1024.0,
                high: 1024.0
            }
        );
    }
}
