//! Multipole (Laurent) and local (Taylor) expansions of the Cauchy integrals
//! `F(zeta) = integral rho(xi)/(zeta - xi) dxi` of the pressure and the shear traction
//! (`docs/stress.md`, "Fast evaluation"), scaled by the box width `s` so that every coefficient is
//! of the size of the load whatever the units:
//!
//! - multipole of a source box centred at the real `c`: `m_n = integral rho(xi) ((xi - c)/s)^n dxi`,
//!   real, and `F(zeta) = (1/s) sum_n m_n y^(n+1)` with `y = s/(zeta - c)` (the geometric series of
//!   `1/(zeta - xi)`, convergent for `|zeta - c|` beyond the box's radius);
//! - local expansion about a target-box centre `t`: `F(zeta) = sum_m l_m tau^m`,
//!   `tau = (zeta - t)/s`, and `F' = (1/s) sum_m m l_m tau^(m-1)`.
//!
//! The translations are the classical ones of the fast multipole method for the Cauchy kernel
//! (L. Greengard and V. Rokhlin, J. Comput. Phys. 73, 1987, lemmas 2.3-2.5, written for
//! `log`; here for its derivative `1/(zeta - xi)`). A multipole holds `[m_p; m_q]` (2 `order`
//! reals), a local expansion `[l_p; l_q]` (2 `order` complex numbers).

use super::super::edge::SqrtEdge;
use crate::quadrature::Rule;
use num_complex::Complex64;

/// Most terms an expansion may have.
pub(super) const MAX_ORDER: usize = 64;

/// The expansion order and the tables its translations use.
pub(in crate::stress) struct Expansions {
    /// Terms per expansion.
    pub order: usize,
    /// `C(n + k, k)` at `k stride + n` (multipole to local), zero beyond `order`.
    m2l: Vec<f64>,
    /// `order` rounded up to a multiple of 4 (the lanes of the multipole-to-local products).
    stride: usize,
    /// `C(n, k)` at `n order + k` (multipole to multipole).
    m2m: Vec<f64>,
    /// Gauss-Legendre on [0, 1] for the square-root edge moments (exact to the order used).
    rule: Rule,
}

fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |c, j| c * (n - j) as f64 / (j + 1) as f64)
}

impl Expansions {
    /// Tables for `order` terms (at most [`MAX_ORDER`]).
    pub fn new(order: usize) -> crate::error::Result<Self> {
        let order = order.min(MAX_ORDER);
        let stride = order.div_ceil(4) * 4;
        let mut m2l = vec![0.0; order * stride];
        let mut m2m = vec![0.0; order * order];
        for a in 0..order {
            for b in 0..order {
                m2l[a * stride + b] = binomial(a + b, a);
                if b <= a {
                    m2m[a * order + b] = binomial(a, b);
                }
            }
        }
        // The edge moments integrate a polynomial of degree 2 order + 1 in u = sqrt(t/h).
        let rule = Rule::jacobi(order + 1, 0.0)?;
        Ok(Self {
            order,
            m2l,
            stride,
            m2m,
            rule,
        })
    }

    /// Adds to `m` (centre `c`, width `s`) the moments of the element `[xa, xb]` carrying
    /// `left + slope (xi - xa)` (pressure and shear): with `u = (xi - c)/s`,
    /// `m_n += s (rho(c) I_n + slope s I_(n+1))`, `I_n = (b^(n+1) - a^(n+1))/(n + 1)`.
    #[allow(clippy::too_many_arguments)]
    pub fn linear(
        &self,
        m: &mut [f64],
        c: f64,
        s: f64,
        xa: f64,
        xb: f64,
        left: [f64; 2],
        slope: [f64; 2],
    ) {
        let p = self.order;
        let (a, b) = ((xa - c) / s, (xb - c) / s);
        let centre = [left[0] + slope[0] * (c - xa), left[1] + slope[1] * (c - xa)];
        let (mut pa, mut pb) = (a, b);
        let mut i_n = b - a;
        for n in 0..p {
            pa *= a;
            pb *= b;
            let i_next = (pb - pa) / (n + 2) as f64;
            m[n] += s * (centre[0] * i_n + slope[0] * s * i_next);
            m[p + n] += s * (centre[1] * i_n + slope[1] * s * i_next);
            i_n = i_next;
        }
    }

    /// Adds to `m` (centre `c`, width `s`) the moments of the square-root edge correction `e`
    /// (`edge.rs`): with `t = h u^2` its moments are integrals of polynomials in `u`, which the
    /// Gauss-Legendre rule of `order + 1` points integrates exactly.
    pub fn edge(&self, m: &mut [f64], c: f64, s: f64, e: &SqrtEdge) {
        let p = self.order;
        let h = e.length.abs();
        let sign = e.length.signum();
        for (&u, &w) in self.rule.nodes.iter().zip(&self.rule.weights) {
            let xi = e.edge + sign * h * u * u;
            let weight = w * (u - u * u) * 2.0 * h * u;
            let v = (xi - c) / s;
            let mut power = weight;
            for n in 0..p {
                m[n] += e.value[0] * power;
                m[p + n] += e.value[1] * power;
                power *= v;
            }
        }
    }

    /// Adds the child multipole `child` (width `s/2`, centre `c + delta s`) to `parent` (width
    /// `s`, centre `c`): `m_n = sum_(k <= n) C(n, k) delta^(n-k) 2^(-k) m'_k`.
    #[inline]
    pub fn m2m(&self, parent: &mut [f64], child: &[f64], delta: f64) {
        let p = self.order;
        let mut pw = [0.0; MAX_ORDER];
        let mut half = [0.0; 2 * MAX_ORDER];
        let mut d = 1.0;
        let mut h = 1.0;
        for n in 0..p {
            pw[n] = d;
            d *= delta;
            half[n] = child[n] * h;
            half[p + n] = child[p + n] * h;
            h *= 0.5;
        }
        for n in 0..p {
            let row = &self.m2m[n * p..n * p + n + 1];
            let (mut sp, mut sq) = (0.0, 0.0);
            for (k, b) in row.iter().enumerate() {
                let f = b * pw[n - k];
                sp += f * half[k];
                sq += f * half[p + k];
            }
            parent[n] += sp;
            parent[p + n] += sq;
        }
    }

    /// Adds to the local expansion `local` (width `s`, centre `t`) the field of the multipole `m`
    /// (width `s`, centre `c`), `y0 = s/(t - c)`: `l_k += (1/s) (-y0)^k sum_n C(n + k, k) m_n y0^(n+1)`.
    pub fn m2l(&self, local: &mut [Complex64], m: &[f64], y0: Complex64, s: f64) {
        let (p, stride) = (self.order, self.stride);
        // a_n = m_n y0^(n+1) for p and q, real and imaginary parts apart (zero-padded lanes).
        let mut a = [[0.0; MAX_ORDER]; 4];
        let mut pw = y0;
        for n in 0..p {
            a[0][n] = pw.re * m[n];
            a[1][n] = pw.im * m[n];
            a[2][n] = pw.re * m[p + n];
            a[3][n] = pw.im * m[p + n];
            pw *= y0;
        }
        let mut f = Complex64::new(1.0 / s, 0.0);
        let minus = -y0;
        for k in 0..p {
            let row = &self.m2l[k * stride..(k + 1) * stride];
            let mut acc = [[0.0; 4]; 4];
            for (c, r) in row.chunks_exact(4).enumerate() {
                for (v, acc) in acc.iter_mut().enumerate() {
                    let av = &a[v][4 * c..4 * c + 4];
                    for lane in 0..4 {
                        acc[lane] += r[lane] * av[lane];
                    }
                }
            }
            let [sp_re, sp_im, sq_re, sq_im] = acc.map(|l| (l[0] + l[1]) + (l[2] + l[3]));
            local[k] += f * Complex64::new(sp_re, sp_im);
            local[p + k] += f * Complex64::new(sq_re, sq_im);
            f *= minus;
        }
    }

    /// The child's local expansion (width `s/2`, centre `t + delta s`) from its parent's (width
    /// `s`, centre `t`): a Taylor shift by `delta`, then `tau_parent = tau_child/2`.
    pub fn l2l(&self, child: &mut [Complex64], parent: &[Complex64], delta: Complex64) {
        let p = self.order;
        for half in [0, p] {
            let b = &mut child[half..half + p];
            b.copy_from_slice(&parent[half..half + p]);
            for i in 0..p - 1 {
                for j in (i..p - 1).rev() {
                    let next = b[j + 1];
                    b[j] += delta * next;
                }
            }
            let mut scale = 1.0;
            for v in b.iter_mut() {
                *v = v.scale(scale);
                scale *= 0.5;
            }
        }
    }

    /// `[F_p, F_p', F_q, F_q']` from the local expansion `local` (width `s`) at `tau`.
    pub fn l2p(&self, local: &[Complex64], tau: Complex64, s: f64) -> [Complex64; 4] {
        let p = self.order;
        let zero = Complex64::default();
        let (mut fp, mut dp, mut fq, mut dq) = (zero, zero, zero, zero);
        for m in (0..p).rev() {
            dp = dp * tau + fp;
            fp = fp * tau + local[m];
            dq = dq * tau + fq;
            fq = fq * tau + local[p + m];
        }
        [fp, dp.scale(1.0 / s), fq, dq.scale(1.0 / s)]
    }

    /// `[F_p, F_p', F_q, F_q']` from the multipole `m` (width `s`) at `y = s/(zeta - c)`:
    /// with `G(y) = sum_n m_n y^n`, `F = (y/s) G` and `F' = -(y/s)^2 (G + y G')`.
    pub fn m2p(&self, m: &[f64], y: Complex64, s: f64) -> [Complex64; 4] {
        let p = self.order;
        let zero = Complex64::default();
        let (mut gp, mut dp, mut gq, mut dq) = (zero, zero, zero, zero);
        for n in (0..p).rev() {
            dp = dp * y + gp;
            gp = gp * y + Complex64::new(m[n], 0.0);
            dq = dq * y + gq;
            gq = gq * y + Complex64::new(m[p + n], 0.0);
        }
        let ys = y.scale(1.0 / s);
        let ys2 = -(ys * ys);
        [ys * gp, ys2 * (gp + y * dp), ys * gq, ys2 * (gq + y * dq)]
    }
}
