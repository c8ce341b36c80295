//! Gauss rules: a fixed 20-point Gauss-Legendre rule, and Gauss-Jacobi rules on [0, 1] with weight
//! `t^alpha` (built by Golub-Welsch) for integrands with an algebraic endpoint singularity, such as
//! the slope `|x|^(k-1)` of a power-law profile at x = 0.

use crate::error::{Error, Result};

/// Positive nodes of the 20-point Gauss-Legendre rule on [-1, 1] (computed to 40 digits with
/// mpmath; checked against Golub-Welsch in the tests).
#[allow(clippy::excessive_precision)] // the reference digits, rounded by the compiler
const GL_NODES: [f64; 10] = [
    0.076_526_521_133_497_333_755,
    0.227_785_851_141_645_078_08,
    0.373_706_088_715_419_560_67,
    0.510_867_001_950_827_098,
    0.636_053_680_726_515_025_45,
    0.746_331_906_460_150_792_61,
    0.839_116_971_822_218_823_39,
    0.912_234_428_251_325_905_87,
    0.963_971_927_277_913_791_27,
    0.993_128_599_185_094_924_79,
];
#[allow(clippy::excessive_precision)]
const GL_WEIGHTS: [f64; 10] = [
    0.152_753_387_130_725_850_7,
    0.149_172_986_472_603_746_79,
    0.142_096_109_318_382_051_33,
    0.131_688_638_449_176_626_9,
    0.118_194_531_961_518_417_31,
    0.101_930_119_817_240_435_04,
    0.083_276_741_576_704_748_725,
    0.062_672_048_334_109_063_57,
    0.040_601_429_800_386_941_331,
    0.017_614_007_139_152_118_312,
];

/// Integrates the `K` components of `f` over [a, b] with the 20-point Gauss-Legendre rule, exact
/// for polynomials of degree 39.
pub(crate) fn gauss_legendre<const K: usize>(
    a: f64,
    b: f64,
    mut f: impl FnMut(f64) -> [f64; K],
) -> [f64; K] {
    let mid = 0.5 * (a + b);
    let half = 0.5 * (b - a);
    let mut sum = [0.0; K];
    for (x, w) in GL_NODES.iter().zip(GL_WEIGHTS) {
        for value in [f(mid - half * x), f(mid + half * x)] {
            for (s, v) in sum.iter_mut().zip(value) {
                *s += w * v;
            }
        }
    }
    sum.map(|s| s * half)
}

/// A Gauss rule on [0, 1]: `integral_0^1 w(t) h(t) dt ~ sum weights[i] h(nodes[i])`.
#[derive(Debug, Clone, PartialEq)]
pub struct Rule {
    /// Nodes in (0, 1), ascending.
    pub nodes: Vec<f64>,
    /// Weights (they include the weight function).
    pub weights: Vec<f64>,
}

impl Rule {
    /// The `n`-point Gauss-Jacobi rule for the weight `t^alpha` on [0, 1] (alpha > -1), exact for
    /// polynomials of degree `2n - 1`. Golub & Welsch (1969), Math. Comp. 23, with the Jacobi
    /// recurrence for weight `(1+x)^alpha` on [-1, 1] mapped by `t = (1 + x)/2`.
    pub fn jacobi(n: usize, alpha: f64) -> Result<Rule> {
        // Monic Jacobi recurrence with (1-x)^a (1+x)^b, a = 0, b = alpha.
        let (a, b) = (0.0_f64, alpha);
        let mut diag = vec![0.0; n];
        let mut off = vec![0.0; n];
        for (i, di) in diag.iter_mut().enumerate() {
            let k = i as f64;
            let s = 2.0 * k + a + b;
            *di = if i == 0 {
                (b - a) / (a + b + 2.0)
            } else {
                (b * b - a * a) / (s * (s + 2.0))
            };
        }
        for (i, oi) in off.iter_mut().enumerate().take(n.saturating_sub(1)) {
            let k = (i + 1) as f64;
            let s = 2.0 * k + a + b;
            let beta = 4.0 * k * (k + a) * (k + b) * (k + a + b) / (s * s * (s + 1.0) * (s - 1.0));
            *oi = beta.sqrt();
        }
        let mut first = vec![0.0; n];
        if n > 0 {
            first[0] = 1.0;
        }
        tridiagonal_eigen(&mut diag, &mut off, &mut first)?;
        // Total mass of t^alpha on [0, 1].
        let mass = 1.0 / (alpha + 1.0);
        let mut pairs: Vec<(f64, f64)> = diag
            .iter()
            .zip(&first)
            .map(|(x, z)| (0.5 * (1.0 + x), mass * z * z))
            .collect();
        pairs.sort_by(|p, q| p.0.total_cmp(&q.0));
        Ok(Rule {
            nodes: pairs.iter().map(|p| p.0).collect(),
            weights: pairs.iter().map(|p| p.1).collect(),
        })
    }
}

/// Eigenvalues of a symmetric tridiagonal matrix by implicit QL with Wilkinson shifts (the `tqli`
/// algorithm of Numerical Recipes, 2nd ed., section 11.3), tracking only the first component of
/// each eigenvector in `first` (initially e_1), as Golub-Welsch needs. `off[i]` couples rows i and
/// i+1; `off[n-1]` is ignored. On return `diag` holds the eigenvalues.
fn tridiagonal_eigen(diag: &mut [f64], off: &mut [f64], first: &mut [f64]) -> Result<()> {
    let n = diag.len();
    if n == 0 {
        return Ok(());
    }
    off[n - 1] = 0.0;
    for l in 0..n {
        let mut iterations = 0;
        loop {
            let mut m = l;
            while m + 1 < n {
                let scale = diag[m].abs() + diag[m + 1].abs();
                if off[m].abs() <= f64::EPSILON * scale {
                    break;
                }
                m += 1;
            }
            if m == l {
                break;
            }
            iterations += 1;
            if iterations > 60 {
                return Err(Error::NoConvergence {
                    what: "Gauss-Jacobi eigenvalue iteration",
                    iterations,
                    last_step: off[l].abs(),
                });
            }
            let mut g = (diag[l + 1] - diag[l]) / (2.0 * off[l]);
            let mut r = g.hypot(1.0);
            g = diag[m] - diag[l] + off[l] / (g + r.copysign(g));
            let (mut s, mut c, mut p) = (1.0, 1.0, 0.0);
            let mut deflated = false;
            let mut i = m;
            while i > l {
                i -= 1;
                let f = s * off[i];
                let b = c * off[i];
                r = f.hypot(g);
                off[i + 1] = r;
                if r == 0.0 {
                    diag[i + 1] -= p;
                    off[m] = 0.0;
                    deflated = true;
                    break;
                }
                s = f / r;
                c = g / r;
                g = diag[i + 1] - p;
                r = (diag[i] - g) * s + 2.0 * c * b;
                p = s * r;
                diag[i + 1] = g + p;
                g = c * r - b;
                let z = first[i + 1];
                first[i + 1] = s * first[i] + c * z;
                first[i] = c * first[i] - s * z;
            }
            if deflated {
                continue;
            }
            diag[l] -= p;
            off[l] = g;
            off[m] = 0.0;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn golub_welsch_reproduces_the_legendre_table() {
        // alpha = 0 is Gauss-Legendre; the table and the eigen-solver are independent routes.
        let rule = Rule::jacobi(20, 0.0).unwrap();
        for (i, (x, w)) in GL_NODES.iter().zip(GL_WEIGHTS).enumerate() {
            let t = 0.5 * (1.0 + x);
            let j = 10 + i;
            assert!(
                (rule.nodes[j] - t).abs() < 1e-15,
                "node {i}: {} vs {t}",
                rule.nodes[j]
            );
            assert!((rule.weights[j] - 0.5 * w).abs() < 1e-15, "weight {i}");
        }
    }

    #[test]
    fn jacobi_rule_integrates_weighted_monomials_exactly() {
        // integral_0^1 t^alpha t^j dt = 1/(alpha + j + 1), exact for j <= 2n - 1; tolerance is
        // a few ulps times the number of terms.
        for alpha in [0.0, 0.3, 0.5, 1.7, 4.0] {
            let rule = Rule::jacobi(16, alpha).unwrap();
            for j in 0..32 {
                let sum: f64 = rule
                    .nodes
                    .iter()
                    .zip(&rule.weights)
                    .map(|(t, w)| w * t.powi(j))
                    .sum();
                let exact = 1.0 / (alpha + j as f64 + 1.0);
                assert!(
                    (sum - exact).abs() < 1e-14 * exact.max(1e-3),
                    "alpha {alpha}, j {j}: {sum} vs {exact}"
                );
            }
        }
    }

    #[test]
    fn legendre_integrates_cosine() {
        let [v] = gauss_legendre(0.0, std::f64::consts::FRAC_PI_2, |x| [x.cos()]);
        assert!((v - 1.0).abs() < 1e-15);
    }
}
