//! What the analysis reports: [`Parameter`], [`ParameterResult`], [`FatigueResult`].

/// Which parameter a result is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Parameter {
    /// Smith-Watson-Topper, `sigma_n,max d(eps_n)/2`.
    Swt,
    /// Fatemi-Socie as Fatemi and Socie (1988) define it, `(d(gamma)/2)(1 + k sigma_n,max/sigma_y)`
    /// on the plane of the largest shear strain range.
    FatemiSocie,
    /// Findley, `tau_a + k sigma_n,max`.
    Findley,
    /// Crossland, `sqrt(J2,a) + alpha sigma_H,max`.
    Crossland,
    /// Ruiz F1 = max(tau delta) on the surface.
    RuizF1,
    /// Ruiz F2 = max(sigma_xx tau delta) on the surface.
    RuizF2,
    /// Modified Wohler Curve Method, `tau_a + kappa rho` on the plane of the largest `tau_a`.
    Mwcm,
    /// The Fatemi-Socie product at its largest over all planes (a common variant, never below
    /// [`Parameter::FatemiSocie`]).
    FatemiSocieMaxPlane,
    /// McDiarmid, `tau_a + t_AB sigma_n,max/(2 sigma_u)` on the plane of the largest `tau_a`.
    McDiarmid,
}

impl Parameter {
    /// Every parameter, in the order the reports list them.
    pub const ALL: [Parameter; 9] = [
        Parameter::Swt,
        Parameter::FatemiSocie,
        Parameter::Findley,
        Parameter::Crossland,
        Parameter::RuizF1,
        Parameter::RuizF2,
        Parameter::Mwcm,
        Parameter::FatemiSocieMaxPlane,
        Parameter::McDiarmid,
    ];

    /// The name the reports print.
    pub fn name(self) -> &'static str {
        match self {
            Parameter::Swt => "swt",
            Parameter::FatemiSocie => "fatemi_socie",
            Parameter::Findley => "findley",
            Parameter::Crossland => "crossland",
            Parameter::RuizF1 => "ruiz_f1",
            Parameter::RuizF2 => "ruiz_f2",
            Parameter::Mwcm => "mwcm",
            Parameter::FatemiSocieMaxPlane => "fatemi_socie_max_plane",
            Parameter::McDiarmid => "mcdiarmid",
        }
    }
}

/// One parameter's maximum over the grid (or the surface, for Ruiz).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParameterResult {
    /// Which parameter.
    pub parameter: Parameter,
    /// Its maximum.
    pub value: f64,
    /// Where: x.
    pub x: f64,
    /// Where: depth z.
    pub z: f64,
    /// The critical plane's normal angle in degrees from `+x` towards `+z` (critical-plane
    /// parameters only).
    pub angle: Option<f64>,
    /// The critical plane's normal tilt towards `+y` in degrees (critical-plane parameters only;
    /// 0 in the in-plane search).
    pub tilt: Option<f64>,
    /// The increment (1-based march step) of the peak normal stress on the critical plane
    /// (Crossland: hydrostatic stress; Ruiz: surface `sxx` for F2, traction for F1).
    pub step: usize,
    /// Point method: the parameter at depth `L/2` below `x` (needs the critical distance).
    pub point_method: Option<f64>,
    /// Line method: its mean over depths 0 to `2L` below `x`.
    pub line_method: Option<f64>,
    /// Cycles to initiation from the SWT or Fatemi-Socie curve (both Fatemi-Socie variants), at
    /// the point-method value when the critical distance is known, else at the maximum; `None`
    /// without the constants or at run-out (beyond 5e19 cycles).
    pub cycles: Option<f64>,
}

/// The result of [`super::analyse`].
#[derive(Debug, Clone, PartialEq)]
pub struct FatigueResult {
    /// The critical distance `L`, when the constants give it.
    pub critical_distance: Option<f64>,
    /// The increments of the steady (last) cycle, 1-based.
    pub steps: Vec<usize>,
    /// One result per available parameter, in the order of [`Parameter`].
    pub parameters: Vec<ParameterResult>,
    /// The grid's x (one per column).
    pub grid_x: Vec<f64>,
    /// The grid's z (one per row).
    pub grid_z: Vec<f64>,
    /// SWT at every grid point, row after row (z outer, x inner).
    pub swt_map: Vec<f64>,
    /// Every grid parameter whose constants are given (all but Ruiz, in the order of
    /// [`Parameter`]) at every grid point, laid out as `swt_map`.
    pub maps: Vec<(Parameter, Vec<f64>)>,
    /// Cell centres in contact at some increment of the cycle (the surface profiles' x).
    pub surface_x: Vec<f64>,
    /// Largest surface `sxx` over the cycle at each of them.
    pub surface_sxx_max: Vec<f64>,
    /// `sxx_max |q|_max delta` at each of them (Ruiz F2's profile; delta the slip amplitude).
    pub ruiz_f2_profile: Vec<f64>,
    /// The surface `sxx` at each of them at every increment of the cycle: one row per entry of
    /// `steps`, one value per entry of `surface_x`.
    pub surface_sxx: Vec<Vec<f64>>,
}

impl FatigueResult {
    /// The map of `parameter` over the grid (row after row, z outer), when it was evaluated.
    pub fn map(&self, parameter: Parameter) -> Option<&[f64]> {
        self.maps
            .iter()
            .find(|(p, _)| *p == parameter)
            .map(|(_, m)| m.as_slice())
    }

    /// The result of `parameter`, when it was evaluated.
    pub fn parameter(&self, parameter: Parameter) -> Option<&ParameterResult> {
        self.parameters.iter().find(|p| p.parameter == parameter)
    }
}
