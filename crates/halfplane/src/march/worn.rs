//! Marching over a gap that wears ([`Worn`], the march the wear loop of [`crate::wear`]
//! drives): the ramp on the profile's own normal problem, then each load cycle over the worn gap
//! `g(x) + h(x)`, whose contact is solved on the grid (`gap.rs`) once per cycle (the cycle keeps
//! P and M constant), the tangential problem carrying on from the previous cycle's state.
//!
//! Sliding cycles (gross slip): Q goes to `f P (1 - 1e-6)` by load increments, then the bodies
//! slide by the amplitude with every contact cell at `q = f p` (at constant P the pressure and
//! the traction do not change while they slide, so each cell slips by the sliding distance),
//! then back. The 1e-6 of `f P` left to the last load increment is the only approximation of the
//! sliding stage (a stick zone of that size vanishes at once).

use super::gap::Grid;
use super::marcher::{Cell, Marcher};
use super::types::MarchOptions;
use crate::error::{Error, Result};
use crate::fatigue::CycleTractions;
use crate::history::History;
use crate::labels::Edge;
use crate::load::LoadPoint;
use crate::normal::Contact;
use crate::quadrature::gauss_legendre;
use crate::wear::{CycleWear, LoopPoint, WornCycle};

/// The load just short of sliding: `f P (1 - SLIDE_MARGIN)` (see the module's docs).
const SLIDE_MARGIN: f64 = 1e-6;

/// One increment of a worn cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Increment {
    /// To this load, as `march` steps.
    Load(LoadPoint),
    /// The bodies slide by this signed distance at the current load (q = sign f p).
    Slide(f64),
}

/// A march over a gap that wears: [`WornCycle`] for [`crate::wear::run`].
pub struct Worn {
    marcher: Marcher,
    cycle: Vec<Increment>,
    base: Vec<f64>,
    approach: f64,
    slip_label: f64,
    /// The unworn contact's ends under the cycle's load.
    unworn: [f64; 2],
    /// The contact ends and bulk stress of the last increment (a slide keeps them).
    last: ([f64; 2], f64),
    /// The last cycle's increments, when recording ([`Worn::record_tractions`]).
    recorded: Option<Recorded>,
    /// The datum of the fretting loop's relative displacement.
    datum: f64,
}

/// An increment as recorded: the contact ends, the bulk stress, the pressure and the shear
/// traction of every cell.
type CellState = ([f64; 2], f64, Vec<f64>, Vec<f64>);

/// A cycle's increments as recorded, and the slip range over the cycle.
#[derive(Default)]
struct Recorded {
    increments: Vec<CellState>,
    slip_range: Vec<f64>,
}

impl Worn {
    /// The march of `history` (a ramp then cycles: its first cycle is the one repeated) over a
    /// grid `span` times the width of the history's contacts about their centre (the worn
    /// contact may grow: a sliding cylinder's scar widens), with `options.cells()` cells. The
    /// ramp is marched at once on the profile's normal problem.
    ///
    /// # Errors
    /// [`Error::NoCycle`] for a history without cycles; [`Error::InvalidInput`] naming
    /// `history.normal` when P or M change along the cycle, or `wear.span` outside 1 to 100;
    /// the march's errors.
    pub fn new(
        contact: &Contact,
        history: &History,
        options: &MarchOptions,
        span: f64,
    ) -> Result<Self> {
        let structure = history.cycles().ok_or(Error::NoCycle {
            what: "wear analysis",
        })?;
        let loads = history.loads();
        let first = structure.first_step();
        let cycle: Vec<LoadPoint> = loads[first..first + structure.steps_per_cycle()].to_vec();
        Self::build(
            contact,
            &loads[..first],
            cycle.into_iter().map(Increment::Load).collect(),
            options,
            span,
            false,
        )
    }

    /// A gross-sliding march: P (and M) ramped over `ramp_steps` increments, then cycles of Q
    /// rising to `f P` over `steps_per_half` increments, the bodies sliding by `amplitude`
    /// (> 0), Q falling to `-f P`, sliding back (docs/wear.md, "Gross sliding").
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `history.amplitude` when it is not finite and > 0;
    /// [`Error::InvalidCount`] naming `history.steps_per_half` or `history.ramp_steps`; the
    /// march's errors.
    pub fn sliding(
        contact: &Contact,
        load: LoadPoint,
        amplitude: f64,
        steps_per_half: usize,
        ramp_steps: usize,
        options: &MarchOptions,
        span: f64,
    ) -> Result<Self> {
        crate::error::physical_positive("history.amplitude", amplitude)?;
        for (field, n) in [
            ("history.steps_per_half", steps_per_half),
            ("history.ramp_steps", ramp_steps),
        ] {
            if !(1..=crate::history::MAX_INCREMENTS).contains(&n) {
                return Err(Error::InvalidCount {
                    field: field.into(),
                    value: n as u64,
                    min: 1,
                    max: crate::history::MAX_INCREMENTS as u64,
                });
            }
        }
        let f = contact.friction().value();
        let limit = f * load.normal() * (1.0 - SLIDE_MARGIN);
        let at = |q: f64| {
            LoadPoint::new("history", load.normal(), q, load.bulk())
                .and_then(|p| p.with_moment("history", load.moment()))
        };
        let ramp: Vec<LoadPoint> = (1..=ramp_steps)
            .map(|i| at(0.0).map(|p| p.scaled(i as f64 / ramp_steps as f64)))
            .collect::<Result<_>>()?;
        // The first rise starts from Q = 0; the cycle from -fP.
        let mut first_rise: Vec<LoadPoint> = (1..=steps_per_half)
            .map(|i| at(limit * i as f64 / steps_per_half as f64))
            .collect::<Result<_>>()?;
        let mut ramp = ramp;
        ramp.append(&mut first_rise);
        let mut cycle = vec![Increment::Slide(amplitude)];
        for (from, to, slide) in [(limit, -limit, -amplitude), (-limit, limit, amplitude)] {
            for i in 1..=2 * steps_per_half {
                let t = i as f64 / (2 * steps_per_half) as f64;
                cycle.push(Increment::Load(at(from + (to - from) * t)?));
            }
            cycle.push(Increment::Slide(slide));
        }
        // One cycle: slide +, fall, slide -, rise (the last slide + starts the next cycle).
        cycle.pop();
        Self::build(contact, &ramp, cycle, options, span, true)
    }

    fn build(
        contact: &Contact,
        ramp: &[LoadPoint],
        cycle: Vec<Increment>,
        options: &MarchOptions,
        span: f64,
        sliding: bool,
    ) -> Result<Self> {
        if !cfg!(feature = "wear") {
            return Err(Self::not_built());
        }
        if !(span.is_finite() && (1.0..=100.0).contains(&span)) {
            return Err(Error::InvalidInput {
                field: "wear.span".into(),
                value: span,
                valid: "a factor from 1 to 100 (the grid's width over the unworn contact's)",
            });
        }
        let loads: Vec<LoadPoint> = cycle
            .iter()
            .filter_map(|i| match i {
                Increment::Load(p) => Some(*p),
                Increment::Slide(_) => None,
            })
            .collect();
        let Some(&head) = loads.first() else {
            return Err(Error::NoCycle {
                what: "wear analysis",
            });
        };
        if let Some(p) = loads
            .iter()
            .find(|p| p.normal() != head.normal() || p.moment() != head.moment())
        {
            return Err(Error::InvalidInput {
                field: "history.normal".into(),
                value: p.normal(),
                valid: "the same normal load and moment all along the cycle (a worn gap's contact is solved for one load)",
            });
        }
        // The grid: the unworn contact under the cycle's load, widened `span` times.
        let unworn = contact.contact_at(&head)?;
        let (c, half) = (unworn.centre(), span * 1.01 * unworn.half_width());
        let mut marcher = Marcher::spanning(contact, [c - half, c + half], options)?;
        let mut last = ([0.0; 2], 0.0);
        let f = contact.friction().value();
        for load in ramp {
            // The first rise to sliding on the profile's pressure sampled at the cell centres,
            // whose sum falls short of P on a coarse grid: it stops short of that sum's limit
            // f sum(p) w as it stops short of f P (the worn gap's pressure carries P exactly).
            let carried = f * marcher.width * marcher.pressure.iter().sum::<f64>();
            let cap = carried * (1.0 - SLIDE_MARGIN);
            let load = match sliding && load.shear().abs() > cap && carried > 0.0 {
                true => LoadPoint::new(
                    "history",
                    load.normal(),
                    cap * load.shear().signum(),
                    load.bulk(),
                )?
                .with_moment("history", load.moment())?,
                false => *load,
            };
            let r = marcher.step(load)?;
            last = ([r.ends[Edge::Left], r.ends[Edge::Right]], load.bulk());
        }
        let base = gap_at(contact, &marcher.x)?;
        let approach = elastic_approach(&mut marcher, &base, &head)?;
        let slip_label = options.slip_tolerance()
            * contact.compliance().value()
            * contact.friction().value()
            * head.normal();
        let ends = unworn.ends();
        Ok(Self {
            marcher,
            cycle,
            base,
            approach,
            slip_label,
            unworn: [ends[Edge::Left], ends[Edge::Right]],
            last,
            recorded: None,
            datum: Self::DEFAULT_DATUM * unworn.half_width(),
        })
    }

    /// The error of a build without the library's `wear` feature.
    pub(super) fn not_built() -> Error {
        Error::InvalidInput {
            field: "wear".into(),
            value: 1.0,
            valid: "no wear in this build: the library's `wear` feature (on by default, off in the web page) is left out",
        }
    }

    /// The default datum of the fretting loop, in half-widths of the unworn contact: far enough
    /// that the contact's traction acts on the datum points as a point load.
    pub const DEFAULT_DATUM: f64 = 10.0;

    /// The datum of the fretting loop's relative displacement (a length > 0; default
    /// [`Worn::DEFAULT_DATUM`] half-widths of the unworn contact): see
    /// [`crate::march::RelativeDisplacement`].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `wear.loop_datum` when it is not finite and > 0.
    pub fn with_loop_datum(self, datum: f64) -> Result<Self> {
        crate::error::physical_positive("wear.loop_datum", datum)?;
        Ok(Self { datum, ..self })
    }

    /// The datum of the fretting loop.
    pub fn loop_datum(&self) -> f64 {
        self.datum
    }

    /// From the next cycle on, keeps each cycle's tractions, increment by increment, for
    /// [`WornCycle::tractions`] (the fatigue parameters at the checkpoints): a copy of the
    /// cells' pressure and traction per increment, nothing while not recording.
    pub fn record_tractions(&mut self) {
        self.recorded.get_or_insert_with(Recorded::default);
    }

    /// The unworn contact's ends `[b1, b2]` under the cycle's load (the fatigue grid of every
    /// checkpoint is scaled on it).
    pub fn unworn_contact(&self) -> [f64; 2] {
        self.unworn
    }
}

/// The unworn gap at the cell centres, `g(x_i) - g(x_0)` (only differences matter: the
/// approach absorbs a constant), by 4-point Gauss-Legendre on the slope between neighbouring
/// centres (the slope is polynomial between kinks; the error of a kink inside an interval is
/// below 1e-6 of the gap's change over a cell).
fn gap_at(contact: &Contact, x: &[f64]) -> Result<Vec<f64>> {
    let profile = contact.profile();
    let mut g = Vec::with_capacity(x.len());
    let mut value = 0.0;
    let mut failure = None;
    g.push(0.0);
    for w in x.windows(2) {
        let [step] = gauss_legendre::<1>(w[0], w[1], |t| match profile.slope(t) {
            Ok(s) => [s],
            Err(e) => {
                failure.get_or_insert(e);
                [0.0]
            }
        });
        value += step;
        g.push(value);
    }
    match failure {
        Some(e) => Err(e),
        None => Ok(g),
    }
}

/// The elastic approach of the unworn contact under `load`: the largest gap closed inside the
/// contact, `max g - min g` over the touching cells (`a^2/(2R)` for Hertz).
fn elastic_approach(marcher: &mut Marcher, base: &[f64], load: &LoadPoint) -> Result<f64> {
    let mut grid = Grid {
        kernel: &mut marcher.kernel,
        x: &marcher.x,
        width: marcher.width,
        compliance: marcher.compliance,
    };
    let solution = grid.solve(base, load.normal(), load.moment(), None)?;
    let touching = base
        .iter()
        .zip(&solution.pressure)
        .filter(|(_, &p)| p > 0.0)
        .map(|(g, _)| *g);
    let (lo, hi) = touching.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), g| {
        (l.min(g), h.max(g))
    });
    Ok((hi - lo).max(f64::MIN_POSITIVE))
}

impl WornCycle for Worn {
    fn x(&self) -> &[f64] {
        &self.marcher.x
    }

    fn width(&self) -> f64 {
        self.marcher.width
    }

    fn elastic_approach(&self) -> f64 {
        self.approach
    }

    fn pressure_stiffness(&self) -> f64 {
        std::f64::consts::PI
            / (self.marcher.compliance
                * super::kernel::smallest_eigenvalue_bound(self.marcher.width))
    }

    fn cycle(&mut self, depth: &[f64]) -> Result<CycleWear> {
        let n = self.base.len();
        let gap: Vec<f64> = self.base.iter().zip(depth).map(|(g, d)| g + d).collect();
        self.marcher.set_gap(gap);
        self.marcher.take_pressure_slip();
        let (mut low, mut high) = (self.marcher.slip.clone(), self.marcher.slip.clone());
        if let Some(r) = &mut self.recorded {
            r.increments.clear();
        }
        let mut fretting_loop = Vec::with_capacity(self.cycle.len() + 1);
        fretting_loop.push(self.loop_point()?);
        for increment in self.cycle.clone() {
            match increment {
                Increment::Load(load) => {
                    let report = self.marcher.step(load)?;
                    let ends = [report.ends[Edge::Left], report.ends[Edge::Right]];
                    self.last = (ends, load.bulk());
                }
                Increment::Slide(distance) => self.marcher.slide(distance)?,
            }
            fretting_loop.push(self.loop_point()?);
            for i in 0..n {
                low[i] = low[i].min(self.marcher.slip[i]);
                high[i] = high[i].max(self.marcher.slip[i]);
            }
            if let Some(r) = &mut self.recorded {
                let (ends, bulk) = self.last;
                let (p, q) = (&self.marcher.pressure, &self.marcher.traction);
                r.increments.push((ends, bulk, p.clone(), q.clone()));
            }
        }
        let ends = self.last.0;
        let slip_range: Vec<f64> = high.iter().zip(&low).map(|(h, l)| h - l).collect();
        if let Some(r) = &mut self.recorded {
            r.slip_range.clone_from(&slip_range);
        }
        let w = self.marcher.width;
        let sticks: Vec<bool> = self
            .marcher
            .cells
            .iter()
            .zip(&slip_range)
            .map(|(c, s)| *c != Cell::Out && *s <= self.slip_label)
            .collect();
        let best = longest_run(&sticks)
            .map(|(a, b)| [self.marcher.x[a] - 0.5 * w, self.marcher.x[b] + 0.5 * w]);
        Ok(CycleWear {
            pressure_slip: self.marcher.take_pressure_slip(),
            friction: self.marcher.friction,
            pressure: self.marcher.pressure.clone(),
            traction: self.marcher.traction.clone(),
            slip_range,
            stick: best,
            contact: ends,
            fretting_loop,
        })
    }

    fn tractions(&mut self) -> Result<Option<CycleTractions>> {
        let Some(r) = &mut self.recorded else {
            return Ok(None);
        };
        let mut cycle =
            CycleTractions::new(self.marcher.x.clone(), std::mem::take(&mut r.slip_range))?;
        for (ends, bulk, p, q) in r.increments.drain(..) {
            cycle.push(ends, bulk, p, q)?;
        }
        Ok(Some(cycle))
    }
}

impl Worn {
    /// Q and the relative displacement now.
    fn loop_point(&self) -> Result<LoopPoint> {
        let d = self.marcher.relative_displacement();
        Ok(LoopPoint {
            shear: d.shear(),
            relative_displacement: d.at(self.datum)?,
        })
    }
}

/// The first and last index of the longest run of `true` (the first of equal runs).
fn longest_run(flags: &[bool]) -> Option<(usize, usize)> {
    let mut best: Option<(usize, usize)> = None;
    let mut start = None;
    for (i, &f) in flags.iter().chain([&false]).enumerate() {
        match (f, start) {
            (true, None) => start = Some(i),
            (false, Some(a)) => {
                if best.is_none_or(|(b0, b1)| i - 1 - a > b1 - b0) {
                    best = Some((a, i - 1));
                }
                start = None;
            }
            _ => {}
        }
    }
    best
}
