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
use halfplane_case::matching::TestOptions;
use std::path::PathBuf;

mod plot;
pub use plot::*;

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
    /// Finds the loads at which a test geometry reproduces the prototype's contact-edge state
    /// (K_N, K_T, slip zones), writes the test case and prints prototype against test.
    Match(MatchArgs),
    /// Stresses below the contact (x, z with z the depth into the body that carries the bulk
    /// tension) at a marched increment: sxx, szz, syy, sxz at the points of --at or on --grid.
    Stress(StressArgs),
    /// Fretting-fatigue parameters over the last cycle of [history] (SWT, Fatemi-Socie, Findley,
    /// Crossland, Ruiz F1/F2, MWCM, max-plane Fatemi-Socie, McDiarmid; critical distances and
    /// lives with the constants of [fatigue]; a parameter left out is named on stderr).
    Fatigue(FatigueArgs),
    /// Will a crack grow? K_I and K_II of a straight surface-breaking crack ([crack]) over the
    /// last cycle of [history], with crack-face contact, against El Haddad's short-crack
    /// threshold from [fatigue] threshold and endurance_range; verdict over the lengths.
    Crack(CrackArgs),
    /// Fretting wear over [wear] cycles (Archard or dissipated-energy law, cycle jumping):
    /// worn volume, depth, energy, contact and stick zone at each checkpoint; --fields writes the
    /// worn profile, pressure, traction and slip range of each.
    Wear(WearArgs),
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

impl From<Format> for halfplane_case::report::Format {
    fn from(f: Format) -> Self {
        match f {
            Format::Table => Self::Table,
            Format::Csv => Self::Csv,
            Format::Json => Self::Json,
        }
    }
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
    /// Run even when the march is estimated to take more than 8 hours of one core, or --fields
    /// to write more than 100 GB (README, "Size limits").
    #[arg(long)]
    pub no_size_limit: bool,
}

#[derive(Args, Debug)]
pub struct WearArgs {
    /// Case file (TOML) with [material], [friction], [profile], [history] (one cycle, or kind =
    /// "sliding") and [wear], and optionally [solver] and [units].
    pub case: PathBuf,
    // csv: one row per checkpoint; table: the run, then the checkpoints.
    #[command(flatten)]
    pub format: FormatArgs,
    /// Write each checkpoint's fields (x, depth, depth_pad, depth_specimen, pressure, traction,
    /// slip_range) as DIR/checkpoint_CYCLE.csv.
    #[arg(long, value_name = "DIR")]
    pub fields: Option<PathBuf>,
    /// Cells across the grid (overrides [solver] cells; default 400).
    #[arg(long)]
    pub cells: Option<usize>,
    /// Evaluate the case's [fatigue] parameters over each checkpoint's cycle (on the grid of
    /// the unworn contact): each one's maximum, where, and its critical-distance values.
    #[arg(long)]
    pub fatigue: bool,
}

#[derive(Args, Debug)]
pub struct StressArgs {
    /// Case file (TOML) with [material], [friction], [profile], [history] and optionally
    /// [solver] and [units].
    pub case: PathBuf,
    /// Points file (CSV) with the header x,z (z >= 0, the depth); one output row per point, in
    /// order.
    #[arg(long, value_name = "POINTS.csv", conflicts_with = "grid")]
    pub at: Option<PathBuf>,
    /// A grid instead of --at: X0,X1,NX,Z0,Z1,NZ (NX x NZ evenly spaced points, ends included,
    /// X0 <= X1 and 0 <= Z0 <= Z1; rows run along x, one depth after another).
    #[arg(long, value_name = "X0,X1,NX,Z0,Z1,NZ", allow_hyphen_values = true)]
    pub grid: Option<String>,
    /// March increment whose state is used (1-based; default: the last).
    #[arg(long)]
    pub step: Option<usize>,
    /// Cells (overrides [solver] cells).
    #[arg(long)]
    pub cells: Option<usize>,
    /// Run even when the march it needs is estimated to take more than 8 hours of one core
    /// (README, "Size limits").
    #[arg(long)]
    pub no_size_limit: bool,
    // csv and table: one row per point, columns x,z,sxx,szz,syy,sxz.
    #[command(flatten)]
    pub format: FormatArgs,
}

#[derive(Args, Debug)]
pub struct FatigueArgs {
    /// Case file (TOML) with [material], [friction], [profile], a cyclic [history] and
    /// optionally [fatigue], [solver] and [units].
    pub case: PathBuf,
    /// Cells (overrides [solver] cells).
    #[arg(long)]
    pub cells: Option<usize>,
    /// Run even when the march it needs is estimated to take more than 8 hours of one core
    /// (README, "Size limits").
    #[arg(long)]
    pub no_size_limit: bool,
    // csv and table: one row per parameter.
    #[command(flatten)]
    pub format: FormatArgs,
}

#[derive(Args, Debug)]
pub struct CrackArgs {
    /// Case file (TOML) with [material], [friction], [profile], a cyclic [history], [fatigue]
    /// (threshold and endurance_range) and [crack]; optionally [solver] and [units].
    pub case: PathBuf,
    /// Cells (overrides [solver] cells).
    #[arg(long)]
    pub cells: Option<usize>,
    /// Run even when the march it needs is estimated to take more than 8 hours of one core
    /// (README, "Size limits").
    #[arg(long)]
    pub no_size_limit: bool,
    // csv and table: one row per crack length.
    #[command(flatten)]
    pub format: FormatArgs,
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
    /// Run even when the sweep is estimated to take more than 8 hours of one core or to write
    /// more than 100 GB (README, "Size limits").
    #[arg(long)]
    pub no_size_limit: bool,
}

/// The profile kinds a matched test may have.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum TestProfile {
    /// Parabolic, needs --radius.
    Hertz,
    /// Flat punch with rounded edges, needs --flat-half-width and --radius.
    FlatRounded,
    /// g = B|x|^k, needs --coefficient and --exponent.
    PowerLaw,
}

/// The test geometry and how to match it (shared by `match` and `plot match`).
#[derive(Args, Debug)]
pub struct TestArgs {
    /// The test's profile kind.
    #[arg(long, value_enum)]
    pub profile: TestProfile,
    /// hertz: radius R; flat-rounded: edge radius R (length).
    #[arg(long, allow_hyphen_values = true)]
    pub radius: Option<f64>,
    /// flat-rounded: flat half-width b >= 0 (length).
    #[arg(long, allow_hyphen_values = true)]
    pub flat_half_width: Option<f64>,
    /// power-law: B > 0 in g = B|x|^k.
    #[arg(long, allow_hyphen_values = true)]
    pub coefficient: Option<f64>,
    /// power-law: k in g = B|x|^k, 1 <= k <= 64 (k = 1.5 has one K_N at every load: no match).
    #[arg(long, allow_hyphen_values = true)]
    pub exponent: Option<f64>,
    /// The test's Young's modulus E (default: the prototype's).
    #[arg(long, allow_hyphen_values = true)]
    pub youngs_modulus: Option<f64>,
    /// The test's Poisson's ratio (default: the prototype's).
    #[arg(long, allow_hyphen_values = true)]
    pub poisson_ratio: Option<f64>,
    /// The test's friction coefficient f (default: the prototype's).
    #[arg(long, allow_hyphen_values = true)]
    pub friction: Option<f64>,
    /// Exact match: K_N at both points, the exact slip zones at both edges at point2, the mean
    /// K_T over the points at each edge (default: K_N at both points and K_T at both edges at
    /// both points, the asymptotic match).
    #[arg(long)]
    pub exact: bool,
    /// Under a moment (or on an asymmetric prototype) K_N differs at the prototype's two edges,
    /// and a test without a moment has one: the edge whose K_N the test takes (default: the
    /// edge whose K_T changes more over the cycle).
    #[arg(long, value_enum)]
    pub edge: Option<MatchEdge>,
}

/// A prototype's edge, for `--edge`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MatchEdge {
    /// The edge at smaller x (b1).
    Left,
    /// The edge at larger x (b2).
    Right,
}

impl TestArgs {
    /// The options as `halfplane_case::matching` takes them.
    pub fn options(&self) -> TestOptions {
        TestOptions {
            profile: match self.profile {
                TestProfile::Hertz => halfplane_case::matching::TestProfile::Hertz,
                TestProfile::FlatRounded => halfplane_case::matching::TestProfile::FlatRounded,
                TestProfile::PowerLaw => halfplane_case::matching::TestProfile::PowerLaw,
            },
            radius: self.radius,
            flat_half_width: self.flat_half_width,
            coefficient: self.coefficient,
            exponent: self.exponent,
            youngs_modulus: self.youngs_modulus,
            poisson_ratio: self.poisson_ratio,
            friction: self.friction,
            exact: self.exact,
            edge: self.edge.map(|e| match e {
                MatchEdge::Left => halfplane::Edge::Left,
                MatchEdge::Right => halfplane::Edge::Right,
            }),
        }
    }
}

#[derive(Args, Debug)]
pub struct MatchArgs {
    /// The prototype's case file (TOML) with [material], [friction], [profile] and [cycle] (and
    /// optionally [history], [solver], [units], carried over to the test).
    pub case: PathBuf,
    #[command(flatten)]
    pub test: TestArgs,
    /// The test case file to write (TOML), accepted by `steady`, `evolve` and `march`.
    #[arg(long, short)]
    pub output: PathBuf,
    /// Print the report as one JSON object instead of a table.
    #[arg(long)]
    pub json: bool,
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
