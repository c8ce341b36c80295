//! [`NormalContact`]: one solved normal contact under P and M (its ends, rotation, edge
//! intensities and loads), and what follows from it alone. Solved by the parent module.

use crate::labels::{Edge, PerEdge};
use std::f64::consts::PI;

/// The solved normal contact under P and M. Built only by [`Contact::normal_contact`](crate::Contact::normal_contact), so its
/// ends, rotation and intensities always belong to its loads.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NormalContact {
    pub(super) normal: f64,
    pub(super) moment: f64,
    pub(super) ends: PerEdge<f64>,
    pub(super) rotation: f64,
    pub(super) intensity: PerEdge<f64>,
    pub(super) on_flat: PerEdge<bool>,
    /// Solved by the symmetric contact law (symmetric profile, M = 0): `[-a, a]`, no rotation.
    pub(super) centred: bool,
}

impl NormalContact {
    /// The centred contact `[-a, a]` of a symmetric profile under P alone, with edge intensity
    /// `k_n` at both ends and no rotation.
    pub(crate) fn centred(normal: f64, a: f64, k_n: f64) -> Self {
        Self {
            normal,
            moment: 0.0,
            ends: PerEdge { left: -a, right: a },
            rotation: 0.0,
            intensity: PerEdge::from_fn(|_| k_n),
            on_flat: PerEdge::default(),
            centred: true,
        }
    }

    /// A contact solved on the marching grid (a worn gap, `march/gap.rs`): its ends the outer
    /// edges of the outermost touching cells, K_N not known there (0).
    pub(crate) fn on_grid(normal: f64, moment: f64, ends: PerEdge<f64>, rotation: f64) -> Self {
        Self {
            normal,
            moment,
            ends,
            rotation,
            intensity: PerEdge {
                left: 0.0,
                right: 0.0,
            },
            on_flat: PerEdge {
                left: false,
                right: false,
            },
            centred: false,
        }
    }

    /// The same contact with the end `edge` put at `x`, a rounding-size move: the march puts an
    /// end on a cell centre exactly where its solve found it there to 1e-13.
    pub(crate) fn with_end(mut self, edge: Edge, x: f64) -> Self {
        self.ends[edge] = x;
        self
    }

    /// The normal load P.
    pub fn normal(&self) -> f64 {
        self.normal
    }

    /// The moment M about x = 0.
    pub fn moment(&self) -> f64 {
        self.moment
    }

    /// The pressure centroid `M/P`.
    pub fn centroid(&self) -> f64 {
        self.moment / self.normal
    }

    /// The contact end at `edge`, as a signed x: `b1` (left) or `b2` (right).
    pub fn end(&self, edge: Edge) -> f64 {
        self.ends[edge]
    }

    /// Both ends, `b1` and `b2`.
    pub fn ends(&self) -> PerEdge<f64> {
        self.ends
    }

    /// The centre `c = (b1 + b2)/2`.
    pub fn centre(&self) -> f64 {
        0.5 * (self.ends.left + self.ends.right)
    }

    /// The half-width `a = (b2 - b1)/2`.
    pub fn half_width(&self) -> f64 {
        0.5 * (self.ends.right - self.ends.left)
    }

    /// The rigid rotation theta of the pad (radians, small): it adds `theta x` to the gap, so it
    /// is negative when the pad tilts down towards +x. Hertz: `-M/(P R)`.
    pub fn rotation(&self) -> f64 {
        self.rotation
    }

    /// The edge intensity K_N at `edge`: `p ~ K_N sqrt(s)` at distance s inside that end.
    pub fn normal_intensity(&self, edge: Edge) -> f64 {
        self.intensity[edge]
    }

    /// K_N at both ends.
    pub fn normal_intensities(&self) -> PerEdge<f64> {
        self.intensity
    }

    /// The change of the pressure's edge coefficient at each end, in units of
    /// `1/(pi sqrt(2a))`, when P changes by `d_normal` and M by `d_moment` from this contact:
    /// `dP - 2(dM - c dP)/a` at the left end and `dP + 2(dM - c dP)/a` at the right. To first
    /// order the pressure changes by `(dP + 2(dM - c dP)(x - c)/a^2)/(pi sqrt(a^2 - (x - c)^2))`,
    /// the bounded-ends solution of the integral equation for a uniform change of the gap's slope
    /// (the rotation) with the resultants dP and dM (docs/theory.md, "Moment"). For a centred
    /// contact under P alone both are dP, the classical `dp = dP/(pi sqrt(a^2 - x^2))`.
    pub fn edge_load_changes(&self, d_normal: f64, d_moment: f64) -> PerEdge<f64> {
        let a = self.half_width();
        let tilt = 2.0 * (d_moment - self.centre() * d_normal) / a;
        PerEdge {
            left: d_normal - tilt,
            right: d_normal + tilt,
        }
    }

    /// The change of the rotation theta when P changes by `d_normal` and M by `d_moment`, to
    /// first order: `dtheta = -2 A (dM - c dP)/(pi a^2)` with `compliance` = A (the uniform slope
    /// change whose bounded-ends pressure has the moment change `dM - c dP` about the centre,
    /// docs/theory.md, "Moment"). Hertz: `d(-M/(P R))`.
    pub fn rotation_change(&self, compliance: f64, d_normal: f64, d_moment: f64) -> f64 {
        let a = self.half_width();
        -2.0 * compliance * (d_moment - self.centre() * d_normal) / (PI * a * a)
    }

    /// Whether the contact was solved by the symmetric contact law (a symmetric profile under
    /// no moment): `[-a, a]` exactly, with no rotation.
    pub fn is_centred(&self) -> bool {
        self.centred
    }

    /// For a flat punch with rounded edges: whether each end lies on the flat (`|b| <= b_flat`),
    /// a regime where the pressure there is flat-punch-like although g' stays continuous (the
    /// solution is valid; only g'' jumps where the end crosses the flat's edge). False for every
    /// other profile.
    pub fn end_on_flat(&self) -> PerEdge<bool> {
        self.on_flat
    }
}
