//! The far field: the stresses at points far from the loaded span from the multipole expansion of
//! the whole traction about the span's centre (`docs/stress.md`, "Far from the contact").
//!
//! The closed form of `strip.rs` sums terms `(J_k + S_k w_k) log w_k` that grow like `r log r`
//! with the distance `r` and cancel to a field that decays like `1/r`: at `r = 1e6` spans the
//! rounding of the sum is larger than the field, at `1e12` it is all that is left. Beyond
//! [`FAR_RADII`] half-spans from the centre `c` both routes of [`crate::stress::field`] use
//! instead `F(zeta) = sum_n m_n / (zeta - c)^(n+1)` with the exact moments
//! `m_n = integral rho(xi) (xi - c)^n dxi` (the geometric series of `1/(zeta - xi)`; L. Greengard
//! and V. Rokhlin, J. Comput. Phys. 73, 1987, lemma 2.1, here for the Cauchy kernel). Every term
//! is then of the size of the field itself, whatever the distance: no cancellation is left.
//! Sign convention of [`crate::stress`].
//!
//! Truncation: the sources lie within one half-span `h` of `c` and the points at least
//! `FAR_RADII h` away, so the terms fall like `(1/FAR_RADII)^n`; after [`FAR_ORDER`] terms the
//! remainder of `F` is below `4^-32/(1 - 1/4) = 7e-20` of `integral |rho| / r`, and that of
//! `z F'` (each term `n + 1` times larger) below `3e-18` of it.

use super::fast::expansion::Expansions;
use super::strip::{stresses, Sums};
use super::traction::Traction;
use num_complex::Complex64;

/// Points at least this many half-spans from the span's centre take the far field.
pub(super) const FAR_RADII: f64 = 4.0;
/// Terms of the far-field expansion.
const FAR_ORDER: usize = 32;

/// Whether `(x, z)` is at least [`FAR_RADII`] half-spans from the centre of the span of `t`: the
/// points that take the far field, whichever route the others take (a traction without nodes has
/// no field, and no far field).
pub(super) fn is_far(t: &Traction, x: f64, z: f64) -> bool {
    match (t.nodes.first(), t.nodes.last()) {
        (Some(&x0), Some(&x1)) if x1 > x0 => beyond(0.5 * (x0 + x1), 0.5 * (x1 - x0), x, z),
        _ => false,
    }
}

fn beyond(centre: f64, scale: f64, x: f64, z: f64) -> bool {
    (x - centre).hypot(z) >= FAR_RADII * scale
}

/// The multipole expansion of a whole traction about the centre of its span.
pub(super) struct FarField {
    centre: f64,
    /// The half-span: the moments are scaled by it (`expansion.rs`).
    scale: f64,
    ex: Expansions,
    moments: Vec<f64>,
}

impl FarField {
    /// The expansion of `t`, or `None` for a traction without nodes (it has no field).
    pub fn new(t: &Traction) -> Option<Self> {
        let n = t.nodes.len();
        if n < 2 {
            return None;
        }
        let (x0, x1) = (t.nodes[0], t.nodes[n - 1]);
        let centre = 0.5 * (x0 + x1);
        let scale = 0.5 * (x1 - x0);
        let ex = Expansions::new(FAR_ORDER).ok()?;
        let mut moments = vec![0.0; 2 * FAR_ORDER];
        // The element values in order from the node form (steps and ramps), as `fast/` does.
        let (mut v, mut s) = ([0.0; 2], [0.0; 2]);
        for e in 0..n - 1 {
            for c in 0..2 {
                v[c] += t.jump[e][c];
                s[c] += t.kink[e][c];
            }
            let (xa, xb) = (t.nodes[e], t.nodes[e + 1]);
            ex.linear(&mut moments, centre, scale, xa, xb, v, s);
            for c in 0..2 {
                v[c] += s[c] * (xb - xa);
            }
        }
        for e in &t.edges {
            ex.edge(&mut moments, centre, scale, e);
        }
        Some(Self {
            centre,
            scale,
            ex,
            moments,
        })
    }

    /// Whether `(x, z)` is far enough for the expansion (see [`is_far`]).
    pub fn reaches(&self, x: f64, z: f64) -> bool {
        beyond(self.centre, self.scale, x, z)
    }

    /// `[sxx, szz, sxz]` from the traction at a point that [`FarField::reaches`] (`z >= 0`).
    pub fn in_plane(&self, x: f64, z: f64) -> [f64; 3] {
        let y = Complex64::new(self.scale, 0.0) / Complex64::new(x - self.centre, z);
        let f = self.ex.m2p(&self.moments, y, self.scale);
        let s = Sums {
            fp: [f[0].re, f[0].im],
            dp: [f[1].re, f[1].im],
            fq: [f[2].re, f[2].im],
            dq: [f[3].re, f[3].im],
        };
        stresses(&s, z)
    }
}
