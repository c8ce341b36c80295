//! The figures of `halfplane plot`: one struct of options per figure (see the parent module for
//! how these doc comments become the `--help` text).
#![allow(missing_docs)]

use super::TestArgs;
use clap::builder::PossibleValuesParser;
use clap::{Args, Subcommand, ValueEnum};
use halfplane_case::report::wear::WearRow;
use std::path::PathBuf;

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
    /// Load spaces of a prototype and its matched test side by side, with the P-S paths of both
    /// edges (needs [cycle]; test geometry options as `halfplane match`).
    Match(MatchFigureArgs),
    /// Filled contours of a stress component below the contact at a marched increment, with a
    /// colour bar and the maximum marked (needs [history]).
    StressMap(StressMapArgs),
    /// Filled contours of a fatigue parameter over the steady cycle, with a colour bar and the
    /// maximum marked (needs a cyclic [history] and the parameter's constants in [fatigue],
    /// whose grid it uses).
    FatigueMap(FatigueMapArgs),
    /// Surface sxx at four points of the steady cycle and Ruiz F2 along x (needs a cyclic
    /// [history]).
    SurfaceProfiles(SurfaceProfilesArgs),
    /// A crack's stress intensity ranges against its length with the short-crack threshold
    /// (log-log), beside the sxx map with the crack drawn (needs what `halfplane crack` needs).
    Crack(SurfaceProfilesArgs),
    /// The wear run of [wear] (as `halfplane wear`): wear depth and pressure along x at each
    /// checkpoint, beside a checkpoint quantity (--quantity) against cycles on a log axis.
    Wear(WearFigureArgs),
    /// A sweep's output over two varied paths: a regime map (--color regime, the default) or a
    /// filled-contour map of any numeric column with a colour bar (takes the sweep's output, not a
    /// case).
    DesignMap(DesignMapArgs),
}

/// The stress components a map can show.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Component {
    /// sxx, along the surface (with the bulk tension).
    Sxx,
    /// szz, normal to the surface.
    Szz,
    /// syy = nu (sxx + szz), out of plane.
    Syy,
    /// sxz, the in-plane shear.
    Sxz,
}

#[derive(Args, Debug)]
pub struct StressMapArgs {
    #[command(flatten)]
    pub figure: FigureArgs,
    /// The component to draw.
    #[arg(long, value_enum, default_value_t = Component::Sxx)]
    pub component: Component,
    /// March increment (1-based; default: the last).
    #[arg(long)]
    pub step: Option<usize>,
    /// Cells (overrides [solver] cells).
    #[arg(long)]
    pub cells: Option<usize>,
}

/// The parameters a fatigue map can show (the names of the `fatigue` report).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MapParameter {
    /// Smith-Watson-Topper.
    #[value(name = "swt")]
    Swt,
    /// Fatemi-Socie on the plane of the largest shear strain range, as its authors define it
    /// (needs fatemi_socie_k and yield_stress).
    #[value(name = "fatemi_socie")]
    FatemiSocie,
    /// The Fatemi-Socie product at its largest over the planes (same constants).
    #[value(name = "fatemi_socie_max_plane")]
    FatemiSocieMaxPlane,
    /// Findley (needs findley_k).
    #[value(name = "findley")]
    Findley,
    /// Crossland (needs crossland_alpha).
    #[value(name = "crossland")]
    Crossland,
    /// Modified Wohler Curve Method (needs axial_fatigue_limit and torsional_fatigue_limit).
    #[value(name = "mwcm")]
    Mwcm,
    /// McDiarmid (needs mcdiarmid_shear_limit and ultimate_strength).
    #[value(name = "mcdiarmid")]
    McDiarmid,
}

#[derive(Args, Debug)]
pub struct FatigueMapArgs {
    #[command(flatten)]
    pub figure: FigureArgs,
    /// The parameter to draw.
    #[arg(long, value_enum, default_value_t = MapParameter::Swt)]
    pub parameter: MapParameter,
    /// Cells (overrides [solver] cells).
    #[arg(long)]
    pub cells: Option<usize>,
}

#[derive(Args, Debug)]
pub struct SurfaceProfilesArgs {
    #[command(flatten)]
    pub figure: FigureArgs,
    /// Cells (overrides [solver] cells).
    #[arg(long)]
    pub cells: Option<usize>,
}

/// What every figure takes: the case and the output file.
#[derive(Args, Debug)]
pub struct FigureArgs {
    /// Case file (TOML); the figure says which sections it needs. [units] names the axes' units.
    pub case: PathBuf,
    /// Output file, ending in .svg or .png.
    #[arg(long, short)]
    pub output: PathBuf,
    /// Draw even when the march the figure needs is estimated to take more than 8 hours of one
    /// core (README, "Size limits").
    #[arg(long)]
    pub no_size_limit: bool,
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
pub struct WearFigureArgs {
    #[command(flatten)]
    pub figure: FigureArgs,
    /// The checkpoint quantity drawn against cycles: a column of `halfplane wear --format csv`.
    #[arg(long, default_value = "max_depth", value_parser = wear_quantities())]
    pub quantity: String,
    /// Cells across the grid (overrides [solver] cells; default 400).
    #[arg(long)]
    pub cells: Option<usize>,
}

/// The names `plot wear --quantity` takes: the checkpoint columns of the `wear` report, the cycle
/// (the figure's x) apart.
pub fn wear_quantity_names() -> impl Iterator<Item = &'static str> {
    WearRow::COLUMNS
        .iter()
        .map(|c| c.key)
        .filter(|k| *k != "cycle")
}

fn wear_quantities() -> PossibleValuesParser {
    PossibleValuesParser::new(wear_quantity_names())
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
pub struct MatchFigureArgs {
    #[command(flatten)]
    pub figure: FigureArgs,
    #[command(flatten)]
    pub test: TestArgs,
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
    /// Column that colours the map: regime (a regime map), crack.verdict (a crack-arrest map of
    /// a crack sweep) or any numeric column, e.g. slip_right_1 (filled contours with a colour
    /// bar).
    #[arg(long, default_value = "regime")]
    pub color: String,
    /// Keep only the rows where PATH equals VALUE, to fix a path the map does not show
    /// (repeatable, e.g. --where friction.coefficient=0.3).
    #[arg(long = "where", value_name = "PATH=VALUE")]
    pub filter: Vec<String>,
}
