//! Numerical time marching of the partial-slip problem for any load history (beyond the paper;
//! `docs/theory.md`, "Time marching").
//!
//! Formulation: elastically similar bodies, so the pressure at each increment is the normal
//! solution for the current P. Tractions are piecewise constant on N equal cells spanning the
//! largest contact of the history, collocated at cell centres. The relative tangential surface
//! displacement is
//!
//! `h(x) = -(A/pi) integral q(xi) ln|xi - x| dxi + (A/4) sigma x + C`,
//!
//! with the rigid shift C fixed by `integral q = Q`. Lengths in the logarithm are scaled by
//! `l = 4L` (L the half-span), which changes only C and makes the cell matrix
//! `G_ij = -integral_cell_j ln(|xi - x_i|/l) dxi` symmetric positive definite Toeplitz.
//!
//! Each increment solves the Coulomb complementarity problem by an active set: cells that stick
//! keep `dh = 0` and `|q| <= f p`; cells that slip carry `q = f p sign(s)`, where the slip
//! increment `s = -dh` is positive in the sense positive Q drives (so friction opposes the relative
//! displacement increment, as `docs/theory.md`, "Time marching", states). Cells whose traction
//! exceeds the limit start to slip; slipping cells whose slip would reverse stick again; repeat
//! until nothing changes. The stick cells' linear system is solved exactly by the Toeplitz
//! inverse of each contiguous stick run (Gohberg-Semencul, O(n log n); its generator comes from
//! a cached run length by Levinson steps or, far from every cached length, by conjugate gradients
//! with a circulant preconditioner, so no step is O(n^2)), with preconditioned conjugate
//! gradients coupling several runs. A pass whose single run only lost cells at its ends (the
//! stick-slip boundary moving in by a cell or two) takes the last pass's solution cut to the
//! shorter run, O(n) per cell, instead of a new solve (`solve.rs`, `Toeplitz::cut`).
//!
//! Moving edges: each increment is split internally at the loads (linear within the increment)
//! where the contact half-width a(P) passes a cell centre. A cell joins the contact at that
//! moment, stuck with zero traction and zero pressure, and stays in contact until the receding
//! edge reaches its centre, where its pressure, and so its traction, is zero. The end state of
//! a sub-step does not depend on the path inside it; the energy dissipated, `integral f p |ds|`
//! over the slipping cells, does, and `dissipation.rs` integrates it to second order in the
//! step (onset times, start-set slip rates, and the curvature of the slipping tractions, which
//! costs one more stick solve unless the stick set is one run); it is never negative.
//!
//! Stick-slip boundaries inside cells (optional, `MarchOptions::with_sub_cell_boundaries`): the
//! cell-level active set puts every zone end at a cell edge, so the traction error near a
//! stick-slip boundary is of the order `K sqrt(w)` (K the square-root amplitude there). With the
//! option, each increment at an unchanged normal load, P and M (where either changes, the
//! cell-level solution is reported), has its last sub-step solved once more with each zone that
//! ends next to slipping cells bounded inside the cells, the traction there carrying the
//! boundary's square root, and the boundaries placed where the stick side's traction meets the
//! limit without a jump (`boundary.rs`); the increment reports that solution, the march goes on
//! from the cell-level one.
//!
//! Stick and slip are reported kinematically, by the slip increment: a cell is labelled stuck in
//! an increment when it slid less than `slip_tolerance` times `A f P`. That threshold labels only;
//! the active set reverses a slipping cell only when its slip would reverse by more than rounding.
//!
//! This module owns only the overview above and the public paths; the work is done by stage:
//! `types.rs` (options and reports), `kernel.rs` (the cell matrix and the special elements),
//! `solve.rs` (the stick cells' linear systems), `toeplitz/` (FFT products and exact inverses of
//! stick runs), `marcher.rs` (the active set and the moving-edge sub-steps), `dissipation.rs` (the
//! energy of a sub-step), `cycles.rs` (the driver, per-cycle slip ranges and shakedown), and for
//! the sub-cell boundaries `layout.rs`, `moments.rs`, `evaluate.rs`, `boundary.rs` and
//! `chain.rs`; `gap.rs` (the normal problem of a worn gap on the grid) and `worn.rs` (the march
//! over a worn gap) serve wear. It never holds code of its own, only declarations and re-exports.

// Without the `sub-cell` feature nothing calls the located boundaries (`marcher.rs`).
#[cfg_attr(not(feature = "sub-cell"), allow(dead_code))]
mod boundary;
#[cfg_attr(not(feature = "sub-cell"), allow(dead_code))]
mod chain;
mod crossings;
mod cycles;
mod dissipation;
#[cfg_attr(not(feature = "sub-cell"), allow(dead_code))]
mod evaluate;
pub(crate) mod gap;
mod intervals;
mod kernel;
mod layout;
mod marcher;
#[cfg_attr(not(feature = "sub-cell"), allow(dead_code))]
mod memory;
mod moments;
mod predict;
mod report;
mod solve;
mod toeplitz;
mod types;
mod worn;
mod worn_gap;

pub use boundary::TractionKink;
pub use cycles::{march, march_steady, march_steady_until, march_until};
pub use marcher::Marcher;
pub use types::{
    CycleReport, Fields, LinearSolver, MarchOptions, MarchResult, RelativeDisplacement, StepReport,
};
pub use worn::Worn;
