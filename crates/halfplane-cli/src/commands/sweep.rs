//! `halfplane sweep`: every row of a design over a case's numeric fields, on every core, streamed
//! to CSV or Parquet.

use crate::args::SweepArgs;
use crate::output::note;
use crate::progress::Progress;
use crate::sweep::csv::{part_path, CsvSink};
use crate::sweep::part;
use crate::sweep::size;
use crate::sweep::spec::{self, Analysis, Spec};
use crate::sweep::template::Template;
use crate::sweep::{Layout, RowSink};
use anyhow::{anyhow, bail, Context, Result};
use halfplane::batch::{self, Batch};
use halfplane::design;
use std::ops::{ControlFlow, Range};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Rows per chunk of a march sweep: a march takes a large fraction of a second, so chunks are
/// short enough that output and the progress bar follow closely; a steady sweep uses the
/// engine's default.
const MARCH_CHUNK_ROWS: usize = 64;

/// The output's format, from its file name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OutputFormat {
    /// Comma-separated values with a header line.
    Csv,
    /// Apache Parquet (needs the `parquet` feature, on by default).
    Parquet,
}

/// What `sweep` runs: the spec, its resolved case, the rows of this shard and where they go.
#[derive(Debug, Clone)]
pub struct SweepConfig {
    /// The parsed spec.
    pub spec: Spec,
    /// The resolved case and how each row's case is made.
    pub template: Template,
    /// Rows of the whole sweep that this run writes (`--shard`).
    pub rows: Range<u64>,
    /// The thread pool's size and the chunk length.
    pub batch: Batch,
    /// The output file.
    pub output: PathBuf,
    /// Its format.
    pub format: OutputFormat,
}

/// Parses `--shard I/N`.
pub fn parse_shard(text: &str) -> Result<(u64, u64), String> {
    let bad =
        || format!("invalid --shard {text:?}: must be I/N with 1 <= I <= N, e.g. --shard 3/10");
    let (i, n) = text.split_once('/').ok_or_else(bad)?;
    let i: u64 = i.trim().parse().map_err(|_| bad())?;
    let n: u64 = n.trim().parse().map_err(|_| bad())?;
    if n == 0 || i == 0 || i > n {
        return Err(bad());
    }
    Ok((i, n))
}

fn output_format(path: &Path) -> Result<OutputFormat> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("csv") => Ok(OutputFormat::Csv),
        Some("parquet") if cfg!(feature = "parquet") => Ok(OutputFormat::Parquet),
        Some("parquet") => bail!(
            "cannot write {}: this halfplane was built without Parquet output (the `parquet` \
             feature, on by default, was turned off with --no-default-features); build it with \
             --features parquet (cargo install --path crates/halfplane-cli --features parquet, or \
             cargo run --release -p halfplane-cli --features parquet -- sweep ...), or write .csv",
            path.display()
        ),
        _ => bail!(
            "cannot tell the output format of {}: the name must end in .csv or .parquet",
            path.display()
        ),
    }
}

/// Reads a spec file and resolves its case.
pub fn load(path: &Path) -> Result<(Spec, Template)> {
    let text = halfplane_case::case::read_text(path, "sweep spec")?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let resolve = || -> Result<(Spec, Template)> {
        let spec = spec::parse(text)?;
        let template = Template::new(&spec, &dir)?;
        Ok((spec, template))
    };
    resolve().with_context(|| format!("in sweep spec {}", path.display()))
}

/// `--threads`, else [`batch::THREADS_VARIABLE`] from the environment, else `None` (every core).
fn threads(given: Option<usize>) -> halfplane::Result<Option<usize>> {
    match given {
        Some(n) => Ok(Some(n)),
        None => {
            let value = std::env::var_os(batch::THREADS_VARIABLE).unwrap_or_default();
            batch::threads_from_text(&value.to_string_lossy())
        }
    }
}

impl SweepConfig {
    /// Reads the spec, checks it once, and picks this shard's rows.
    pub fn resolve(args: &SweepArgs) -> Result<Self> {
        let format = output_format(&args.output)?;
        let (spec, template) = load(&args.spec)?;
        let (index, count) = args.shard.unwrap_or((1, 1));
        let rows = design::shard(spec.design.rows(), index, count)?;
        if !args.no_size_limit {
            let dir = args.spec.parent().unwrap_or(Path::new(""));
            let run = size::Run {
                rows: rows.end - rows.start,
                shard: args.shard.is_some(),
                format,
                direct: template.is_direct(),
            };
            size::check(&spec, dir, run)?;
        }
        let mut batch = Batch::new(threads(args.threads)?)?;
        if spec.analysis != Analysis::Steady {
            batch = batch.with_chunk_rows(MARCH_CHUNK_ROWS)?;
        }
        Ok(Self {
            spec,
            template,
            rows,
            batch,
            output: args.output.clone(),
            format,
        })
    }

    /// The shape of the rows.
    pub fn layout(&self) -> Layout {
        Layout {
            varied: self.spec.varied.clone(),
            analysis: self.spec.analysis,
        }
    }
}

/// Runs the sweep into its output; says on stderr how many rows were written and how many failed.
pub fn run(config: &SweepConfig) -> Result<()> {
    let layout = config.layout();
    let part = part_path(&config.output);
    part::watch(&part);
    let outcome = match config.format {
        OutputFormat::Csv => {
            CsvSink::create(&config.output, &layout).and_then(|sink| run_into(sink, config))
        }
        #[cfg(feature = "parquet")]
        OutputFormat::Parquet => {
            crate::sweep::parquet::ParquetSink::create(&config.output, &layout)
                .and_then(|sink| run_into(sink, config))
        }
        #[cfg(not(feature = "parquet"))]
        OutputFormat::Parquet => Err(anyhow!("Parquet output needs the `parquet` feature")),
    };
    let failed = outcome.map_err(|e| part::abandon(&part, e))?;
    let rows = config.rows.end - config.rows.start;
    let failed = match failed {
        0 => String::new(),
        n => format!(" ({n} with an error: see the error column)"),
    };
    note(&format!(
        "wrote {rows} rows{failed} to {}",
        config.output.display()
    ));
    Ok(())
}

/// Solves this shard's rows on the pool and writes them in order; returns how many failed.
pub fn run_into<S: RowSink>(mut sink: S, config: &SweepConfig) -> Result<u64> {
    let layout = config.layout();
    let (first, rows) = (config.rows.start, config.rows.end - config.rows.start);
    let rows =
        usize::try_from(rows).map_err(|_| anyhow!("{rows} rows are too many for this machine"))?;
    let bar = Progress::new("sweep", "rows", rows as u64);
    let failed = AtomicU64::new(0);
    let axes = config.spec.design.axes();
    let stopped = config.batch.run(
        rows,
        |i| {
            let mut values = vec![0.0; axes];
            config.spec.design.values(first + i as u64, &mut values);
            for (v, varied) in values.iter_mut().zip(&layout.varied) {
                if varied.integer {
                    *v = v.round();
                }
            }
            let outcome = config.template.solve(&values);
            if !outcome.error.is_empty() {
                failed.fetch_add(1, Ordering::Relaxed);
            }
            bar.inc(1);
            S::encode(&layout, &values, outcome)
        },
        |_, items| {
            if let Err(e) = sink.write(items) {
                return ControlFlow::Break(e);
            }
            ControlFlow::Continue(())
        },
    )?;
    bar.finish();
    if let Some(e) = stopped {
        return Err(e);
    }
    part::commit(|| sink.finish())?;
    Ok(failed.into_inner())
}
