//! What the page computes, each from the text of a case file and each as the command computes
//! it: `steady` and `evolve` return the command's own reports (`halfplane_case::report`, the
//! same JSON as `--json`, and the table the command prints), `march` marches the case's
//! `[history]` as `halfplane march` does. The drawings' data come from the same library calls:
//! the pressure at both ends of the cycle (`contact`) and the regime the steady analysis finds
//! when point 2 is moved over the load space (`regime_map`).

use anyhow::{anyhow, bail, Result};
use halfplane::march;
use halfplane::record::MarchedCycle;
use halfplane::{asymptotic, evolution, steady, Cycle, Edge, LoadPoint, Regime, SteadyOptions};
use halfplane_case::case::{self, Case, FieldError};
use halfplane_case::limits;
use halfplane_case::report::evolve::EvolveReport;
use halfplane_case::report::steady::SteadyReport;
use serde_json::{json, Value};
use std::path::Path;

/// The longest march the page runs, in the command's own estimate of core time
/// ([`limits::march_seconds`]): 0.1 s estimated took about 0.3 s in the browser (BENCHMARKS.md), a
/// wait a page can afford between two edits of the form. Longer ones are for `halfplane march`.
pub const MARCH_SECONDS: f64 = 0.1;

/// The sections whose tables a page cannot read from a file.
const TABLES: [&str; 2] = ["profile", "history"];

/// Points on each contact's pressure curve ([`contact`]).
pub const PRESSURE_POINTS: usize = 121;

/// The case of `text`, read as the command reads a case file. A table given by its `file` is an
/// error naming that field: a page reads no files (the form loads a CSV into `data`).
pub fn parse(text: &str) -> Result<Case> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if let Ok(doc) = toml::from_str::<toml::Table>(text) {
        for section in TABLES {
            let file = doc
                .get(section)
                .and_then(|s| s.get("file"))
                .and_then(|f| f.as_str());
            if let Some(file) = file {
                let field = format!("{section}.file");
                let message = format!(
                    "{field} = \"{file}\": a web page reads no files; load the CSV into the form \
                     (or give its rows in the case file as {section}.data = \"\"\"...\"\"\")"
                );
                return Err(FieldError { field, message }.into());
            }
        }
    }
    case::parse(text, Path::new(""))
}

/// `halfplane steady --json` of the case (`report`), the table the command prints (`table`) and
/// the note it prints when the asymptotic estimate is unavailable (`note`).
pub fn steady(text: &str) -> Result<Value> {
    let case = parse(text)?;
    let cycle = case.cycle()?;
    let contact = &case.contact;
    let state = steady::analyse(contact, &cycle, &SteadyOptions::default())?;
    let asym = match state.regime {
        Regime::PartialSlip => Some(asymptotic::steady(contact, &cycle)),
        _ => None,
    };
    let asym_ok = asym.as_ref().and_then(|a| a.as_ref().ok());
    let report = SteadyReport::new(contact, &state, asym_ok, &case.units)?;
    let note = match asym {
        Some(Err(e)) => Some(format!("note: no asymptotic estimate: {e}")),
        _ => None,
    };
    Ok(json!({
        "report": serde_json::to_value(&report)?,
        "table": report.table(&state),
        "note": note,
    }))
}

/// `halfplane evolve --points POINTS --json` of the case (`report`, warnings included) and its
/// table (`table`). `points` is the text of the form's field; the library checks its range.
pub fn evolve(text: &str, points: &str) -> Result<Value> {
    let points: usize = points.trim().parse().map_err(|_| FieldError {
        field: "points".into(),
        message: format!(
            "invalid points = {:?}: must be a whole number (points per half-cycle, ends included)",
            points.trim()
        ),
    })?;
    let case = parse(text)?;
    let cycle = case.cycle()?;
    let ev = evolution::evolve(&case.contact, &cycle, points, &SteadyOptions::default())?;
    let report = EvolveReport::new(&ev, &case.units);
    Ok(json!({
        "report": serde_json::to_value(&report)?,
        "table": report.table(),
    }))
}

/// The pressure at both ends of the cycle as given: for each, the contact half-width `a`, its
/// ends `left` and `right` (b1, b2: `-a` and `a` without a moment on a symmetric profile), and
/// `x` and `pressure` at [`PRESSURE_POINTS`] points across the contact.
pub fn contact(text: &str) -> Result<Value> {
    let case = parse(text)?;
    let cycle = case.cycle()?;
    let (first, second) = cycle.as_given();
    let mut ends = Vec::new();
    for (point, name) in [(first, "cycle.point1"), (second, "cycle.point2")] {
        let state = case
            .contact
            .contact_at(&point)
            .map_err(|e| e.with_moment_field(&format!("{name}.moment")))?;
        let (left, right) = (state.end(Edge::Left), state.end(Edge::Right));
        let n = PRESSURE_POINTS - 1;
        let x: Vec<f64> = (0..=n)
            .map(|i| left + (right - left) * i as f64 / n as f64)
            .collect();
        let pressure = x
            .iter()
            .map(|&x| case.contact.pressure_at(&state, x))
            .collect::<halfplane::Result<Vec<f64>>>()?;
        ends.push(json!({
            "half_width": state.half_width(),
            "left": left,
            "right": right,
            "x": x,
            "pressure": pressure,
        }));
    }
    Ok(json!({ "at_point1": ends[0], "at_point2": ends[1] }))
}

/// The regimes of the map, in the order of [`regime_map`]'s codes.
pub const REGIMES: [&str; 5] = [
    "partial-slip",
    "full-stick",
    "gross-sliding",
    "outside-analysis",
    "solver",
];

/// The regime the steady analysis finds with point 2 moved to each cell of a `columns` x `rows`
/// grid over the load space (P from 0 to 1.25 max(P1, P2), Q from -f to f times that), point 1,
/// point 2's bulk tension and its centroid M/P as given (its moment scales with P): `codes` (row after row, Q rising, each an index into
/// `regimes`; an error of kind outside-analysis or solver is a regime of its own), with the
/// grid's `normal` and `shear` cell edges.
pub fn regime_map(text: &str, columns: usize, rows: usize) -> Result<Value> {
    if !(1..=200).contains(&columns) || !(1..=200).contains(&rows) {
        bail!("invalid map size {columns} x {rows}: must be 1 to 200 cells each way");
    }
    let case = parse(text)?;
    let cycle = case.cycle()?;
    let (first, second) = cycle.as_given();
    let f = case.contact.friction().value();
    let top = 1.25 * first.normal().max(second.normal());
    let normal: Vec<f64> = (0..=columns)
        .map(|i| top * i as f64 / columns as f64)
        .collect();
    let shear: Vec<f64> = (0..=rows)
        .map(|j| f * top * (2.0 * j as f64 / rows as f64 - 1.0))
        .collect();
    let options = SteadyOptions::default();
    let mut codes = Vec::with_capacity(columns * rows);
    for j in 0..rows {
        let q = 0.5 * (shear[j] + shear[j + 1]);
        for i in 0..columns {
            let p = 0.5 * (normal[i] + normal[i + 1]);
            let moved = LoadPoint::new("point2", p, q, second.bulk())?
                .with_moment("point2", second.centroid() * p)?;
            let regime = match steady::analyse(&case.contact, &Cycle::new(first, moved), &options) {
                Ok(s) => match s.regime {
                    Regime::PartialSlip => "partial-slip",
                    Regime::FullStick => "full-stick",
                    Regime::GrossSliding { .. } => "gross-sliding",
                },
                Err(e) => e.kind().as_str(),
            };
            let code = REGIMES.iter().position(|r| *r == regime).ok_or_else(|| {
                anyhow!("the steady analysis failed at P = {p}, Q = {q}: {regime}")
            })?;
            codes.push(code);
        }
    }
    Ok(json!({
        "normal": normal,
        "shear": shear,
        "codes": codes,
        "regimes": REGIMES,
    }))
}

/// `halfplane march` of the case's `[history]` with its `[solver]`: the stick interval over the
/// last cycle (`stick`: `[t, left, right]`, t from 0 to 2 over its two halves, as
/// [`MarchedCycle`]), the energy dissipated in each cycle, and the size of the run. Refused when
/// the command's estimate of its time exceeds [`MARCH_SECONDS`], naming `solver.cells`.
pub fn march(text: &str) -> Result<Value> {
    let case = parse(text)?;
    let (history, until_steady) = case.march_history()?;
    if until_steady.is_some() {
        bail!("history.cycles = \"steady\" is not marched on the page: give a number of cycles");
    }
    let options = case.solver;
    let increments = history.loads().len();
    let estimate = limits::march_seconds(options.cells(), increments);
    if estimate > MARCH_SECONDS {
        let message = format!(
            "a march of {} cells x {increments} increments is estimated at {estimate:.2} s of \
             computing, more than the {MARCH_SECONDS} s the page runs: use fewer cells or \
             increments, or `halfplane march` on the downloaded case",
            options.cells()
        );
        let field = "solver.cells".into();
        return Err(FieldError { field, message }.into());
    }
    let result = march::march(&case.contact, &history, &options, |_, _| {})?;
    let stick = MarchedCycle::last_cycle(&result, &history).map(|c| c.points);
    let energy: Vec<f64> = result.cycles.iter().map(|c| c.energy).collect();
    Ok(json!({
        "cells": options.cells(),
        "increments": increments,
        "stick": stick,
        "cycle_energy": energy,
    }))
}
