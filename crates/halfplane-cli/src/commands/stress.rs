//! `halfplane stress`: the stresses below the contact at a marched increment, at the points of a
//! CSV file or on a grid (`docs/stress.md`).

use crate::args::StressArgs;
use crate::output::emit;
use anyhow::{anyhow, bail, Result};
use halfplane::error::MAGNITUDE_LIMIT;
use halfplane::history::History;
use halfplane::march::MarchOptions;
use halfplane::stress;
use halfplane::Contact;
use halfplane_case::case::{read_csv, Table};
use halfplane_case::report::stress::{StressReport, StressRow};
use halfplane_case::report::Format;
use halfplane_case::stress::{check_step, MAX_POINTS};
use halfplane_case::units::Units;
use std::path::PathBuf;

/// What `stress` runs on.
#[derive(Debug, Clone)]
pub struct StressConfig {
    /// The contact.
    pub contact: Contact,
    /// The load history of `[history]`.
    pub history: History,
    /// `[solver]` with `--cells` applied.
    pub options: MarchOptions,
    /// The increment (1-based).
    pub step: usize,
    /// The points' x.
    pub x: Vec<f64>,
    /// The points' depth z.
    pub z: Vec<f64>,
    /// Where the points came from (for errors).
    pub origin: Origin,
    /// Unit names.
    pub units: Units,
    /// Table, CSV or JSON.
    pub format: Format,
}

impl StressConfig {
    /// Reads the case, the points (`--at`) or the grid (`--grid`) and checks `--step`.
    pub fn resolve(args: &StressArgs) -> Result<Self> {
        let case = halfplane_case::case::load(&args.case)?;
        let history = case.history()?;
        let options = case.solver_with_cells(args.cells)?;
        halfplane_case::limits::check_case_march(
            &history,
            &options,
            args.cells,
            args.no_size_limit,
        )?;
        let step = check_step(args.step, &history, "--step")?;
        let (x, z, origin) = match (&args.at, &args.grid) {
            (Some(path), _) => {
                let table = Table::File {
                    field: "--at".into(),
                    path: path.clone(),
                };
                let (values, lines) = read_csv(&table, &["x", "z"], MAX_POINTS)?;
                let (x, z): (Vec<f64>, Vec<f64>) = values.chunks(2).map(|c| (c[0], c[1])).unzip();
                let origin = Origin::File {
                    path: path.clone(),
                    lines,
                };
                for i in 0..x.len() {
                    stress::check_points(&x[i..=i], &z[i..=i])
                        .map_err(|e| point_error(&origin.name(i), &e))?;
                }
                (x, z, origin)
            }
            (None, Some(g)) => {
                let (x, z) = grid(g)?;
                (x, z, Origin::Grid)
            }
            (None, None) => {
                bail!("give the points with --at POINTS.csv or --grid X0,X1,NX,Z0,Z1,NZ")
            }
        };
        Ok(Self {
            options,
            contact: case.contact,
            history,
            step,
            x,
            z,
            origin,
            units: case.units,
            format: args.format.format().into(),
        })
    }
}

/// Where the points came from, to name one in an error as the user wrote it.
#[derive(Debug, Clone)]
pub enum Origin {
    /// `--at FILE`: the file's line (1-based) of every point.
    File {
        /// The file.
        path: PathBuf,
        /// The line of each point.
        lines: Vec<usize>,
    },
    /// `--grid`: points numbered from 1 along x, one depth after another.
    Grid,
}

impl Origin {
    /// Point `i` (0-based) as the user knows it.
    pub fn name(&self, i: usize) -> String {
        match self {
            Origin::File { path, lines } => format!("--at {}, line {}", path.display(), lines[i]),
            Origin::Grid => format!("--grid point {}", i + 1),
        }
    }
}

/// A library error about one point, re-worded for the point `name`: the coordinate (`x` or `z`),
/// the value and what is valid, without the library's 0-based point number.
fn point_error(name: &str, e: &halfplane::Error) -> anyhow::Error {
    match e {
        halfplane::Error::InvalidInput {
            field,
            value,
            valid,
        } => {
            let coordinate = field.rsplit(": ").next().unwrap_or(field);
            anyhow!(
                "{name}: invalid {coordinate} = {}: must be {valid}",
                number(*value)
            )
        }
        other => anyhow!("{name}: {other}"),
    }
}

/// A number as a reader wants it: exponent notation only for very large or small magnitudes.
fn number(v: f64) -> String {
    if v != 0.0 && v.is_finite() && !(1e-5..1e15).contains(&v.abs()) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

/// The points of `--grid X0,X1,NX,Z0,Z1,NZ`: along x, one depth after another.
pub fn grid(text: &str) -> Result<(Vec<f64>, Vec<f64>)> {
    const NAMES: [&str; 6] = ["X0", "X1", "NX", "Z0", "Z1", "NZ"];
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    if parts.len() != 6 {
        bail!(
            "--grid takes six numbers X0,X1,NX,Z0,Z1,NZ, got {} (\"{text}\")",
            parts.len()
        );
    }
    let mut g = [0.0; 6];
    for (i, p) in parts.iter().enumerate() {
        g[i] = p
            .parse()
            .map_err(|_| anyhow!("invalid --grid {} = \"{p}\": not a number", NAMES[i]))?;
    }
    let [x0, x1, nx, z0, z1, nz] = &g;
    let count = |name: &str, v: f64| -> Result<usize> {
        if v.fract() != 0.0 || !(1.0..=MAX_POINTS as f64).contains(&v) {
            bail!("invalid --grid {name} = {v}: must be a whole number from 1 to {MAX_POINTS}");
        }
        Ok(v as usize)
    };
    let (nx, nz) = (count("NX", *nx)?, count("NZ", *nz)?);
    if nx * nz > MAX_POINTS {
        bail!(
            "--grid has NX x NZ = {} points, more than the {MAX_POINTS} a run takes",
            nx * nz
        );
    }
    for (name, v) in [("X0", x0), ("X1", x1), ("Z0", z0), ("Z1", z1)] {
        if !v.is_finite() || v.abs() > MAGNITUDE_LIMIT {
            bail!(
                "invalid --grid {name} = {}: must be a finite number of magnitude at most 1e30",
                number(*v)
            );
        }
    }
    if *z0 < 0.0 || *z1 < 0.0 {
        bail!(
            "invalid --grid depths Z0 = {}, Z1 = {}: must be >= 0 (z is the depth into the body)",
            number(*z0),
            number(*z1)
        );
    }
    for (first, last, a, b) in [("X0", "X1", x0, x1), ("Z0", "Z1", z0, z1)] {
        if b < a {
            bail!(
                "invalid --grid {last} = {}: must be at least {first} = {} (the grid runs from \
                 {first} to {last}, ends included)",
                number(*b),
                number(*a)
            );
        }
    }
    let at = |a: f64, b: f64, n: usize, i: usize| {
        if n == 1 {
            a
        } else {
            a + (b - a) * i as f64 / (n - 1) as f64
        }
    };
    let mut x = Vec::with_capacity(nx * nz);
    let mut z = Vec::with_capacity(nx * nz);
    for j in 0..nz {
        for i in 0..nx {
            x.push(at(*x0, *x1, nx, i));
            z.push(at(*z0, *z1, nz, j));
        }
    }
    Ok((x, z))
}

/// Points evaluated and written at a time: the output streams (a reader that stops after the
/// first lines, `| head`, ends the run after this many points, not after all of them).
const CHUNK: usize = 16_384;

/// Marches to the increment, then evaluates the stresses and prints them chunk by chunk.
pub fn run(config: &StressConfig) -> Result<()> {
    let kept = crate::progress::while_running("stress", || {
        stress::marched(
            &config.contact,
            &config.history,
            &config.options,
            &[config.step],
        )
    })?;
    let state = kept
        .into_iter()
        .next()
        .ok_or_else(|| anyhow!("the march did not reach step {}", config.step))?;
    let bulk = state.load.bulk();
    let evaluator = stress::Evaluator::new(&state.traction, bulk, &config.contact.material())?;
    let head = StressReport {
        step: state.step,
        normal: state.load.normal(),
        shear: state.load.shear(),
        bulk,
        half_width: state.half_width,
        moment: state.load.moment(),
        contact_left: state.ends.left,
        contact_right: state.ends.right,
        points: Vec::new(),
        units: config.units.clone(),
    };
    let mut pieces = head.pieces(config.format)?;
    let (x, z) = (&config.x, &config.z);
    for start in (0..x.len()).step_by(CHUNK) {
        let end = (start + CHUNK).min(x.len());
        let field = evaluator
            .field(&x[start..end], &z[start..end])
            .map_err(|_| first_failure(&evaluator, config, start, end))?;
        let rows: Vec<StressRow> = (start..end)
            .map(|i| {
                let s = field.at(i - start);
                StressRow {
                    x: x[i],
                    z: z[i],
                    sxx: s.sxx,
                    szz: s.szz,
                    syy: s.syy,
                    sxz: s.sxz,
                }
            })
            .collect();
        emit(&pieces.rows(&rows)?)?;
    }
    emit(pieces.end())
}

/// The error of the first point of `start..end` that the evaluator refuses, named as the user
/// wrote it (a surface point on a jump of the traction; the points were checked on reading).
fn first_failure(
    evaluator: &stress::Evaluator,
    config: &StressConfig,
    start: usize,
    end: usize,
) -> anyhow::Error {
    (start..end)
        .find_map(|i| {
            let e = evaluator.field(&config.x[i..=i], &config.z[i..=i]).err()?;
            Some(point_error(&config.origin.name(i), &e))
        })
        .unwrap_or_else(|| anyhow!("evaluating the stresses at points {} to {end}", start + 1))
}
