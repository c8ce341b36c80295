//! The raw command line, as clap parses it: one struct per command (and per figure), each
//! resolved into a validated configuration by its command module (`commands::*`).
//!
//! The doc comments of the items below are the command's `--help` text, written for a terminal:
//! there `[history]` names a case-file section, not a link.
#![allow(rustdoc::broken_intra_doc_links)]
// clap turns doc comments into help text, so the command and argument structs carry theirs on
// the variants and options that show them; a doc comment on a struct or a flattened field would
// change or duplicate the help.
#![allow(missing_docs)]

use clap::{Args, Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// Frictional half-plane contact: steady-state stick zones, slip zones and their evolution.
#[derive(Parser, Debug)]
#[command(name = "halfplane", version)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Steady state of an in-phase cycle: regime, permanent stick zone, slip zones, asymptotics.
    Steady(SteadyArgs),
    /// Stick zone at evenly spaced points of each half-cycle (exact partial-path relation), with
    /// the asymptotic estimate beside it.
    Evolve(EvolveArgs),
    /// Numerical time marching through the load history in [history]: stick zones, tractions,
    /// slip and dissipated energy at every increment, slip amplitude per cycle.
    March(MarchArgs),
    /// Runs every row of a design (grid, random or Latin hypercube) over numeric fields of a case:
    /// the steady state (or a march) of each, on every core, streamed to CSV or Parquet.
    Sweep(SweepArgs),
    /// Draws a figure as SVG or PNG (by the output file name).
    #[command(subcommand)]
    #[command(subcommand_value_name = "FIGURE", subcommand_help_heading = "Figures")]
    Plot(PlotCommand),
}

/// How `steady`, `evolve` and `march` print their report.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// A readable table (the default).
    Table,
    /// Comma-separated values with a header row.
    Csv,
    /// One JSON object.
    Json,
}

/// `--format`, with `--csv` and `--json` as its older spellings.
#[derive(Args, Debug)]
pub struct FormatArgs {
    /// Output format [default: table].
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub format: Option<Format>,
    /// Same as --format csv.
    #[arg(long, conflicts_with_all = ["json", "format"])]
    pub csv: bool,
    /// Same as --format json.
    #[arg(long, conflicts_with = "format")]
    pub json: bool,
}

impl FormatArgs {
    /// The format asked for, by whichever spelling.
    pub fn format(&self) -> Format {
        match (self.format, self.csv, self.json) {
            (Some(f), _, _) => f,
            (None, true, _) => Format::Csv,
            (None, _, true) => Format::Json,
            _ => Format::Table,
        }
    }
}

#[derive(Args, Debug)]
pub struct SteadyArgs {
    /// Case file (TOML) with [material], [friction], [profile] and [cycle] (and optionally
    /// [units]).
    pub case: PathBuf,
    // csv: one header row and one data row, the JSON's numbers under dotted names.
    #[command(flatten)]
    pub format: FormatArgs,
}

#[derive(Args, Debug)]
pub struct EvolveArgs {
    /// Case file (TOML) with [material], [friction], [profile] and [cycle] (and optionally
    /// [units]).
    pub case: PathBuf,
    /// Points per half-cycle, ends included (2 to 100000).
    #[arg(long, default_value_t = 21)]
    pub points: usize,
    // csv and table: one row per point.
    #[command(flatten)]
    pub format: FormatArgs,
}

#[derive(Args, Debug)]
pub struct MarchArgs {
    /// Case file (TOML) with [material], [friction], [profile], [history] and optionally
    /// [cycle], [solver] and [units].
    pub case: PathBuf,
    // csv: one row per increment; table: a summary.
    #[command(flatten)]
    pub format: FormatArgs,
    /// Write the fields of every increment (x, pressure, traction, slip, slip_increment) as
    /// DIR/step_NNNNN.csv, and the slip amplitude of every cycle as DIR/slip_amplitude.csv.
    #[arg(long, value_name = "DIR")]
    pub fields: Option<PathBuf>,
    /// Cells across the largest contact (overrides [solver] cells; default 400).
    #[arg(long)]
    pub cells: Option<usize>,
}

#[derive(Args, Debug)]
pub struct SweepArgs {
    /// Sweep spec (TOML): a case file plus [sweep] (mode = "grid", "random" or
    /// "latin-hypercube"; samples and seed for the last two; analysis = "steady" or "march")
    /// and [sweep.vary] ("dotted.path" = [values] or { from, to, count, scale }).
    pub spec: PathBuf,
    /// Output file, ending in .csv or .parquet.
    #[arg(long, short)]
    pub output: PathBuf,
    /// Write only the I-th of N disjoint parts of the rows (1-based), e.g. in a Slurm job array
    /// --shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT.
    #[arg(long, value_name = "I/N", value_parser = crate::commands::sweep::parse_shard)]
    pub shard: Option<(u64, u64)>,
    /// Worker threads [default: HALFPLANE_NUM_THREADS if set, else every core].
    #[arg(long)]
    pub threads: Option<usize>,
}

/// The figures `halfplane plot` draws, each with its own options.
#[derive(Subcommand, Debug)]
pub enum PlotCommand {
    /// P-Q trajectory with friction lines and the P-S trajectories of both edges (needs [cycle]).
    LoadSpace(FigureArgs),
    /// Right-edge slip zone against dQ/(f P0), the paper's Figure 5 (uses [material], [profile]).
    SlipMap(SlipMapArgs),
    /// Contact edges and stick boundaries over a cycle, the paper's Figure 6 (needs [cycle]).
    Evolution(EvolutionArgs),
    /// Shear traction and slip along x at chosen increments (needs [history]).
    MarchFields(MarchFieldsArgs),
    /// Stick intervals against increment number (needs [history]).
    MarchZones(MarchZonesArgs),
    /// A sweep's output over two varied paths: a regime map (--color regime, the default) or a
    /// colour map of any numeric column with contours (takes the sweep's output, not a case).
    DesignMap(DesignMapArgs),
}

/// What every figure takes: the case and the output file.
#[derive(Args, Debug)]
pub struct FigureArgs {
    /// Case file (TOML); the figure says which sections it needs. [units] names the axes' units.
    pub case: PathBuf,
    /// Output file, ending in .svg or .png.
    #[arg(long, short)]
    pub output: PathBuf,
}

#[derive(Args, Debug)]
pub struct SlipMapArgs {
    #[command(flatten)]
    pub figure: FigureArgs,
    /// Friction coefficients, one panel each (e.g. --frictions 0.3 0.6, or 0.3,0.6).
    #[arg(long, value_delimiter = ',', num_args = 1.., default_values_t = [0.3, 0.6])]
    pub frictions: Vec<f64>,
    /// P2/P1 values.
    #[arg(long, value_delimiter = ',', num_args = 1.., default_values_t = [1.0, 1.2, 1.5])]
    pub ratios: Vec<f64>,
    /// dsigma/P1 values (1/length), dsigma = sigma1 - sigma2.
    #[arg(long, value_delimiter = ',', num_args = 1.., default_values_t = [0.0, 0.02, 0.05])]
    pub tensions: Vec<f64>,
    /// P1 (force per length); default the smaller P of [cycle], or 1000.
    #[arg(long)]
    pub normal: Option<f64>,
}

#[derive(Args, Debug)]
pub struct EvolutionArgs {
    #[command(flatten)]
    pub figure: FigureArgs,
    /// Points per half-cycle (2 to 100000).
    #[arg(long, default_value_t = 41)]
    pub points: usize,
    /// Overlay the time-marching stick zone (needs [history] kind = "cycle").
    #[arg(long)]
    pub march: bool,
    /// Cells of the --march overlay (overrides [solver] cells).
    #[arg(long, requires = "march")]
    pub cells: Option<usize>,
}

#[derive(Args, Debug)]
pub struct MarchFieldsArgs {
    #[command(flatten)]
    pub figure: FigureArgs,
    /// Increments to draw, at most 20 (e.g. --steps 100 150, or 100,150; default: 1/4, 1/2, 3/4
    /// and the end of the last cycle, or the last increment).
    #[arg(long, value_delimiter = ',', num_args = 1..)]
    pub steps: Vec<usize>,
    /// Cells (overrides [solver] cells).
    #[arg(long)]
    pub cells: Option<usize>,
}

#[derive(Args, Debug)]
pub struct MarchZonesArgs {
    #[command(flatten)]
    pub figure: FigureArgs,
    /// Cells (overrides [solver] cells).
    #[arg(long)]
    pub cells: Option<usize>,
}

#[derive(Args, Debug)]
pub struct DesignMapArgs {
    /// A sweep's output (.csv or .parquet).
    pub sweep: PathBuf,
    /// Output file, ending in .svg or .png.
    #[arg(long, short)]
    pub output: PathBuf,
    /// Column on the x axis (a varied path, e.g. cycle.point2.shear).
    #[arg(long)]
    pub x: String,
    /// Column on the y axis (a varied path).
    #[arg(long)]
    pub y: String,
    /// Column that colours the map: regime (a regime map) or any numeric column, e.g.
    /// slip_right_1 (filled bands with contours).
    #[arg(long, default_value = "regime")]
    pub color: String,
    /// Keep only the rows where PATH equals VALUE, to fix a path the map does not show
    /// (repeatable, e.g. --where friction.coefficient=0.3).
    #[arg(long = "where", value_name = "PATH=VALUE")]
    pub filter: Vec<String>,
}

/// For an unknown command or figure, a line naming the valid ones (clap's message names only
/// the value, and suggests a name only when one is similar).
pub fn valid_subcommands(error: &clap::Error, args: &[String]) -> Option<String> {
    use clap::CommandFactory;
    if error.kind() != clap::error::ErrorKind::InvalidSubcommand {
        return None;
    }
    let cli = Cli::command();
    let (what, parent) = match args.get(1).map(String::as_str) {
        Some("plot") => ("figures", cli.find_subcommand("plot")?.clone()),
        _ => ("commands", cli),
    };
    let names: Vec<&str> = parent
        .get_subcommands()
        .map(|c| c.get_name())
        .filter(|n| *n != "help")
        .collect();
    Some(format!("valid {what}: {}", names.join(", ")))
}
