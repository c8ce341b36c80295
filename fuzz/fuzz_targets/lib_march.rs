//! march::march on arbitrary small histories (at most 12 explicit rows, or a short generated
//! in-phase cycle), 8 to 32 cells, both linear solvers, arbitrary floats in the contact.
#![no_main]

use arbitrary::Arbitrary;
use halfplane::history::{History, Ramp};
use halfplane::march::{self, LinearSolver, MarchOptions};
use halfplane::LoadPoint;
use halfplane_fuzz::{check_march, check_step, fuzzed_contact, Num, ProfileInput};
use libfuzzer_sys::fuzz_target;

#[derive(Debug, Arbitrary)]
enum HistoryInput {
    Rows(Vec<[Num; 3]>),
    InPhase {
        points: [[Num; 3]; 2],
        cycles: u8,
        steps_per_half: u8,
        normal_first: bool,
        ramp_steps: u8,
    },
}

#[derive(Debug, Arbitrary)]
struct Input {
    youngs_modulus: Num,
    poisson_ratio: Num,
    friction: Num,
    profile: ProfileInput,
    history: HistoryInput,
    cells: u8,
    dense: bool,
    slip_tolerance: Option<Num>,
}

fuzz_target!(|input: Input| {
    let Some(contact) = fuzzed_contact(
        input.youngs_modulus,
        input.poisson_ratio,
        input.friction,
        &input.profile,
    ) else {
        return;
    };
    let history = match &input.history {
        HistoryInput::Rows(rows) => {
            let rows: Vec<[f64; 3]> = rows.iter().take(12).map(|r| r.map(|v| v.0)).collect();
            History::from_rows(&rows)
        }
        HistoryInput::InPhase {
            points,
            cycles,
            steps_per_half,
            normal_first,
            ramp_steps,
        } => {
            let [p, q] = points.map(|p| LoadPoint::new("point", p[0].0, p[1].0, p[2].0));
            let (Ok(p), Ok(q)) = (p, q) else {
                return;
            };
            History::in_phase(
                p,
                q,
                usize::from(cycles % 3),
                usize::from(steps_per_half % 4),
                if *normal_first {
                    Ramp::NormalFirst
                } else {
                    Ramp::Proportional
                },
                usize::from(ramp_steps % 4),
            )
        }
    };
    let Ok(history) = history else {
        return;
    };
    // Out-of-range settings must be typed errors; fuzz them through the setters.
    let solver = if input.dense {
        LinearSolver::Dense
    } else {
        LinearSolver::Toeplitz
    };
    let mut options = match MarchOptions::default()
        .with_cells(6 + usize::from(input.cells % 27))
        .and_then(|o| o.with_solver(solver))
    {
        Ok(o) => o,
        Err(_) => return,
    };
    if let Some(t) = input.slip_tolerance {
        match options.with_slip_tolerance(t.0) {
            Ok(o) => options = o,
            Err(_) => return,
        }
    }
    if let Ok(m) = march::march(&contact, &history, &options, check_step) {
        check_march(&m);
    }
});
