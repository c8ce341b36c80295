//! Tractions of marched increments for the stress routes: [`marched`] runs
//! [`march::march`](crate::march::march) and keeps, at the increments asked for, the traction in
//! the surface-accurate form of [`Traction::from_march`] and the load reached.

use super::traction::Traction;
use crate::error::{Error, Result};
use crate::history::History;
use crate::labels::PerEdge;
use crate::load::LoadPoint;
use crate::march::{march, MarchOptions};
use crate::normal::Contact;

/// One kept increment.
#[derive(Debug, Clone, PartialEq)]
pub struct MarchedTraction {
    /// 1-based increment.
    pub step: usize,
    /// The load reached (its `bulk` is the tension to add to `sxx`).
    pub load: LoadPoint,
    /// Contact half-width.
    pub half_width: f64,
    /// The contact ends `[b1, b2]`.
    pub ends: PerEdge<f64>,
    /// The traction ([`Traction::from_march`]).
    pub traction: Traction,
}

/// Marches `history` and returns the tractions of the increments `steps` (1-based, in the order
/// made, each once). Errors: a step outside `1..=` the history's increments (field `step`), and
/// any error of the march.
pub fn marched(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    steps: &[usize],
) -> Result<Vec<MarchedTraction>> {
    let last = history.loads().len();
    if let Some(&bad) = steps.iter().find(|&&s| s == 0 || s > last) {
        return Err(Error::InvalidCount {
            field: "step".into(),
            value: bad as u64,
            min: 1,
            max: last as u64,
        });
    }
    let mut wanted = vec![false; last + 1];
    for &s in steps {
        wanted[s] = true;
    }
    let mut kept = Vec::with_capacity(steps.len());
    let mut failure = None;
    march(contact, history, options, |r, f| {
        if wanted[r.step] && failure.is_none() {
            match Traction::from_march_ends(r.ends, f) {
                Ok(traction) => kept.push(MarchedTraction {
                    step: r.step,
                    load: r.load,
                    half_width: r.half_width,
                    ends: r.ends,
                    traction,
                }),
                Err(e) => failure = Some(e),
            }
        }
    })?;
    match failure {
        Some(e) => Err(e),
        None => Ok(kept),
    }
}
