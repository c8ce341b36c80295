//! The crack benchmark's loading, shared with `examples/profile_crack.rs`: the fatigue example's
//! cycle with 60 increments per half (120 per cycle) on 400 cells, and a crack's uncracked loads
//! over kept increments.

use halfplane::crack::CrackSolver;
use halfplane::history::{History, Ramp};
use halfplane::march::MarchOptions;
use halfplane::{stress, LoadPoint, Material};

/// The fatigue example's cycle with 60 increments per half: 120 per cycle.
pub fn history() -> History {
    History::in_phase(
        LoadPoint::new("point1", 1000.0, -300.0, -60.0).unwrap(),
        LoadPoint::new("point2", 1000.0, 300.0, 60.0).unwrap(),
        2,
        60,
        Ramp::NormalFirst,
        10,
    )
    .unwrap()
}

/// 400 cells.
pub fn options() -> MarchOptions {
    MarchOptions::default().with_cells(400).unwrap()
}

/// The uncracked `(normal, shear)` at the crack's collocation points under each increment, by
/// `stress::fields`.
pub fn loads(
    s: &CrackSolver,
    increments: &[(&stress::Traction, f64)],
    material: &Material,
) -> Vec<(Vec<f64>, Vec<f64>)> {
    stress::fields(increments, material, s.x(), s.z())
        .unwrap()
        .iter()
        .map(|f| {
            (0..f.len())
                .map(|i| s.resolve(f.sxx[i], f.szz[i], f.sxz[i]))
                .unzip()
        })
        .collect()
}
