//! `stress`: the stresses below the contact at one marched increment (`docs/stress.md`), as the
//! command prints them and the Python package returns them.

use crate::report::stress::{StressReport, StressRow};
use crate::units::Units;
use anyhow::{anyhow, bail, Context, Result};
use halfplane::history::History;
use halfplane::march::MarchOptions;
use halfplane::stress;
use halfplane::Contact;

/// Most points a run takes (the points and the rows are held in memory: about 100 bytes each).
pub const MAX_POINTS: usize = 10_000_000;

/// The increment `step` names (1-based; the last when None), checked against the history's
/// increments; errors name the option or argument `name`.
pub fn check_step(step: Option<usize>, history: &History, name: &str) -> Result<usize> {
    let last = history.loads().len();
    let step = step.unwrap_or(last);
    if step == 0 || step > last {
        bail!("invalid {name} {step}: the history has increments 1 to {last}");
    }
    Ok(step)
}

/// Marches `history` to increment `step` (1-based) and evaluates the stresses at the points
/// `(x[i], z[i])` (z the depth, >= 0): the report `halfplane stress` prints, which the Python
/// package returns too. The stresses are those of [`stress::field`] (its sign conventions: tension
/// positive, the bulk tension included in sxx, syy = nu (sxx + szz) in plane strain).
pub fn report(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    step: usize,
    x: &[f64],
    z: &[f64],
    units: &Units,
) -> Result<StressReport> {
    if x.len() != z.len() {
        bail!(
            "the points have {} x values but {} z values; give one z per x",
            x.len(),
            z.len()
        );
    }
    let kept = stress::marched(contact, history, options, &[step])?;
    let state = kept
        .into_iter()
        .next()
        .ok_or_else(|| anyhow!("the march did not reach step {step}"))?;
    let bulk = state.load.bulk();
    let field = stress::field(&state.traction, bulk, &contact.material(), x, z)
        .context("evaluating the stresses")?;
    let points = (0..x.len())
        .map(|i| StressRow {
            x: x[i],
            z: z[i],
            sxx: field.sxx[i],
            szz: field.szz[i],
            syy: field.syy[i],
            sxz: field.sxz[i],
        })
        .collect();
    Ok(StressReport {
        step: state.step,
        normal: state.load.normal(),
        shear: state.load.shear(),
        bulk,
        half_width: state.half_width,
        moment: state.load.moment(),
        contact_left: state.ends.left,
        contact_right: state.ends.right,
        points,
        units: units.clone(),
    })
}
