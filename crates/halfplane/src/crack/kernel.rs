//! The stress of an edge dislocation in the half-plane with a traction-free surface: the kernel
//! of the distributed dislocation technique (Hills, Kelly, Dai and Korsunsky, *Solution of Crack
//! Problems: the Distributed Dislocation Technique*, 1996; the half-plane solution is Dundurs
//! and Mura's, 1964).
//!
//! Derived here with Muskhelishvili's potentials, in the coordinates of [`crate::stress`]: the
//! body is `z >= 0`, `w = x + i z`. Kolosov-Muskhelishvili (Muskhelishvili, *Some Basic Problems of the Mathematical Theory
//! of Elasticity*, 1953):
//! `sxx + szz = 4 Re Phi`, `szz - sxx + 2i sxz = 2 (conj(w) Phi' + Psi)`. The dislocation at `w0`
//! in the whole plane has `Phi0 = g/(w - w0)`, `Psi0 = conj(g)/(w - w0) + g conj(w0)/(w - w0)^2`
//! with `g = mu b / (i pi (kappa + 1))`, `b = bx + i bz` the displacement gained on a
//! counter-clockwise circuit of `w0` (in the `(x, z)` plane). Muskhelishvili's continuation
//! across the free surface (traction zero on `z = 0`) gives
//! `Phi = Phi0 + Phi1`, `Phi1 = -conj(Phi0)(w) - w conj(Phi0')(w) - conj(Psi0)(w)` and
//! `Psi = Psi0 - conj(Phi0)(w) - Phi1 - w Phi1'`, where `conj(F)(w)` means `conj(F(conj(w)))`.
//! The tests check both defining properties: zero traction on the surface, and the whole-plane
//! field near the dislocation.
//!
//! Stresses are returned in units of `A = 2 mu / (pi (kappa + 1))` (plane strain,
//! `kappa = 3 - 4 nu`): on its own glide line, in a frame `(e1, e2)` with `e2` a quarter turn
//! from `e1` towards `+z` from `+x`, a whole-plane dislocation gives `s22 = A b2 / r`,
//! `s12 = A b1 / r`, `r` the signed distance along `e1`.

/// The few complex operations the kernel needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct C {
    pub re: f64,
    pub im: f64,
}

impl C {
    pub const fn new(re: f64, im: f64) -> Self {
        Self { re, im }
    }
    fn conj(self) -> Self {
        Self::new(self.re, -self.im)
    }
    fn mul(self, o: Self) -> Self {
        Self::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }
    fn inv(self) -> Self {
        let d = self.re * self.re + self.im * self.im;
        Self::new(self.re / d, -self.im / d)
    }
    fn add(self, o: Self) -> Self {
        Self::new(self.re + o.re, self.im + o.im)
    }
    fn sub(self, o: Self) -> Self {
        Self::new(self.re - o.re, self.im - o.im)
    }
    fn scale(self, s: f64) -> Self {
        Self::new(self.re * s, self.im * s)
    }
}

/// `[sxx, szz, sxz]` at `w` (body `Im w >= 0`) from a dislocation at `w0` (`Im w0 > 0`) with
/// Burgers vector `b` (components `(bx, bz)` as a complex number), in units of `A` (module
/// doc). Only differences of positions matter along the surface, so callers pass coordinates
/// relative to a nearby surface point to keep the cancellation in `w Phi1'` small.
pub(crate) fn dislocation_stress(w: C, w0: C, b: C) -> [f64; 3] {
    // g = b / (2i) in units of A: mu b/(i pi (kappa+1)) = (A/2) b / i.
    let g = C::new(b.im * 0.5, -b.re * 0.5);
    let gc = g.conj();
    let d = w.sub(w0).inv(); // 1/(w - w0)
    let e = w.sub(w0.conj()).inv(); // 1/(w - conj(w0))
    let d2 = d.mul(d);
    let e2 = e.mul(e);
    let phi0 = g.mul(d);
    let dphi0 = g.mul(d2).scale(-1.0);
    let psi0 = gc.mul(d).add(g.mul(w0.conj()).mul(d2));
    let gg = g.add(gc); // real: g + conj(g)
    let wmw0 = w.sub(w0);
    // Phi1 = -(g + conj g)/(w - conj w0) + conj(g) (w - w0)/(w - conj w0)^2
    let phi1 = gg.mul(e).scale(-1.0).add(gc.mul(wmw0).mul(e2));
    // Phi1' = (g + conj g + conj g)/(w - conj w0)^2 - 2 conj(g) (w - w0)/(w - conj w0)^3
    let dphi1 = gg
        .add(gc)
        .mul(e2)
        .sub(gc.mul(wmw0).mul(e2).mul(e).scale(2.0));
    let phi = phi0.add(phi1);
    let dphi = dphi0.add(dphi1);
    let psi = psi0.sub(gc.mul(e)).sub(phi1).sub(w.mul(dphi1));
    let sum = 4.0 * phi.re; // sxx + szz
    let dif = w.conj().mul(dphi).add(psi).scale(2.0); // szz - sxx + 2i sxz
    let szz = 0.5 * (sum + dif.re);
    let sxx = 0.5 * (sum - dif.re);
    [sxx, szz, 0.5 * dif.im]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The whole-plane field alone (the first terms), for comparison near the dislocation.
    fn whole_plane(w: C, w0: C, b: C) -> [f64; 3] {
        let g = C::new(b.im * 0.5, -b.re * 0.5);
        let d = w.sub(w0).inv();
        let phi = g.mul(d);
        let dphi = g.mul(d).mul(d).scale(-1.0);
        let psi = g.conj().mul(d).add(g.mul(w0.conj()).mul(d).mul(d));
        let sum = 4.0 * phi.re;
        let dif = w.conj().mul(dphi).add(psi).scale(2.0);
        [0.5 * (sum - dif.re), 0.5 * (sum + dif.re), 0.5 * dif.im]
    }

    #[test]
    fn the_surface_is_free_of_traction() {
        // szz and sxz on z = 0 vanish, for both Burgers components and several positions; the
        // scale is the field 1/(distance) ~ 1, so 1e-12 is rounding.
        let w0 = C::new(0.3, 0.7);
        for b in [C::new(1.0, 0.0), C::new(0.0, 1.0), C::new(0.6, -0.8)] {
            let mut largest_sxx: f64 = 0.0;
            for x in [-3.0, -0.5, 0.0, 0.3, 1.1, 4.0] {
                let [sxx, szz, sxz] = dislocation_stress(C::new(x, 0.0), w0, b);
                assert!(szz.abs() < 1e-12 && sxz.abs() < 1e-12, "{x} {szz} {sxz}");
                largest_sxx = largest_sxx.max(sxx.abs());
            }
            // The test is not vacuous: the surface does carry a hoop stress.
            assert!(largest_sxx > 0.1, "{largest_sxx}");
        }
    }

    #[test]
    fn near_the_dislocation_the_whole_plane_field_dominates() {
        // At distance r from the dislocation the image terms are O(1/depth) while the
        // whole-plane field is O(1/r): their difference stays bounded as r -> 0.
        let w0 = C::new(0.0, 1.0);
        let b = C::new(0.3, 1.0);
        for r in [1e-2, 1e-3, 1e-4] {
            let w = C::new(r * 0.6, 1.0 + r * 0.8);
            let h = dislocation_stress(w, w0, b);
            let f = whole_plane(w, w0, b);
            let diff = (0..3).map(|i| (h[i] - f[i]).abs()).fold(0.0, f64::max);
            assert!(diff < 2.0, "{r} {diff}");
            assert!(f.iter().map(|v| v.abs()).fold(0.0, f64::max) > 0.1 / r);
        }
    }

    #[test]
    fn on_its_glide_line_a_whole_plane_dislocation_gives_a_over_r() {
        // The normalisation of the module doc: s22 = b2 / r and s12 = b1 / r on the line (and
        // sxx = szz for a climb dislocation).
        let w0 = C::new(0.0, 0.0);
        for (b, expect) in [
            (C::new(0.0, 1.0), [2.0, 2.0, 0.0]),
            (C::new(1.0, 0.0), [0.0, 0.0, 2.0]),
        ] {
            let [sxx, szz, sxz] = whole_plane(C::new(0.5, 0.0), w0, b);
            assert!((sxx - expect[0]).abs() < 1e-12, "{sxx}");
            assert!((szz - expect[1]).abs() < 1e-12, "{szz}");
            assert!((sxz - expect[2]).abs() < 1e-12, "{sxz}");
        }
    }
}
