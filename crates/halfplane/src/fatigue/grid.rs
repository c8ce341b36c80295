//! Where the parameters are searched: the grid below the contact ([`FatigueGrid`]) and which
//! planes ([`Planes`]).

use crate::error::{Error, Result};

/// The grid the parameters are searched on: `nx` by `nz` points, x evenly from `-width` to
/// `width` and z evenly from 0 (the surface) to `depth`, both as multiples of the largest contact
/// half-width of the history; and the planes searched at each point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FatigueGrid {
    pub(crate) nx: usize,
    pub(crate) nz: usize,
    pub(crate) width: f64,
    pub(crate) depth: f64,
    pub(crate) planes: Planes,
}

impl Default for FatigueGrid {
    fn default() -> Self {
        Self {
            nx: 100,
            nz: 50,
            width: 1.5,
            depth: 1.0,
            planes: Planes::InPlane,
        }
    }
}

/// Most grid points (the stress history of every point over the cycle is held: 32 bytes per
/// point and increment).
pub const MAX_GRID_POINTS: usize = 1_000_000;

impl FatigueGrid {
    /// A grid of `nx` by `nz` points (each 2 or more, at most [`MAX_GRID_POINTS`] in all) over
    /// `|x - c| <= width a_max`, `0 <= z <= depth a_max` (`width`, `depth` from 0.01 to 100;
    /// `[c - a_max, c + a_max]` the span of the cycle's contacts, `c = 0` without a moment on a
    /// symmetric profile), searching the in-plane planes.
    pub fn new(nx: usize, nz: usize, width: f64, depth: f64) -> Result<Self> {
        for (field, n) in [("fatigue.nx", nx), ("fatigue.nz", nz)] {
            if !(2..=MAX_GRID_POINTS).contains(&n) {
                return Err(Error::InvalidCount {
                    field: field.into(),
                    value: n as u64,
                    min: 2,
                    max: MAX_GRID_POINTS as u64,
                });
            }
        }
        if nx.saturating_mul(nz) > MAX_GRID_POINTS {
            return Err(Error::InvalidCount {
                field: "fatigue.nx * fatigue.nz".into(),
                value: nx.saturating_mul(nz) as u64,
                min: 4,
                max: MAX_GRID_POINTS as u64,
            });
        }
        for (field, v) in [("fatigue.width", width), ("fatigue.depth", depth)] {
            if !(v.is_finite() && (0.01..=100.0).contains(&v)) {
                return Err(Error::InvalidInput {
                    field: field.into(),
                    value: v,
                    valid: "a multiple of the largest contact half-width from 0.01 to 100",
                });
            }
        }
        Ok(Self {
            nx,
            nz,
            width,
            depth,
            planes: Planes::InPlane,
        })
    }

    /// The same grid searching `planes`.
    pub fn with_planes(mut self, planes: Planes) -> Self {
        self.planes = planes;
        self
    }

    /// The planes searched.
    pub fn planes(&self) -> Planes {
        self.planes
    }
}

/// Which planes the critical-plane parameters are searched over.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Planes {
    /// The planes containing the out-of-plane axis `y` (normal in the x-z plane): the default.
    #[default]
    InPlane,
    /// Every plane, tilted towards `y` too, with the plane-strain `syy`.
    Full3d,
}

impl Planes {
    /// The names `[fatigue] planes` accepts.
    pub const VALID: &'static str =
        "\"in-plane\" (the default: planes containing y) or \"3d\" (every plane)";

    /// The name as the case file spells it.
    pub fn name(self) -> &'static str {
        match self {
            Planes::InPlane => "in-plane",
            Planes::Full3d => "3d",
        }
    }

    /// The planes named `name` (`"in-plane"` or `"3d"`); else an error naming `fatigue.planes`,
    /// the value and the valid names.
    pub fn from_name(name: &str) -> Result<Self> {
        match name {
            "in-plane" => Ok(Planes::InPlane),
            "3d" => Ok(Planes::Full3d),
            _ => Err(Error::InvalidText {
                field: "fatigue.planes".into(),
                value: name.into(),
                valid: Self::VALID,
            }),
        }
    }
}
