//! The named inputs of a run and the one error every layer reports a bad input with.
//!
//! The library names a bad value by the quantity it is ([`Param`]); the command line turns that
//! name into its flag (`cli::flags`), so the same check serves Rust callers and the CLI.
use std::fmt;

use crate::shape::ShapeError;

/// An input quantity of a run (docs/physics.md §2–§6), for error messages.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Param {
    /// Cells per chord N.
    Resolution,
    /// Plate thickness (chords).
    Thickness,
    /// The plate's section (its kind).
    Shape,
    /// Edge radius of a rounded plate (chords).
    EdgeRadius,
    /// The vertices of a polygonal plate.
    Polygon,
    /// Distance from the plate to the outer boundary along x (chords).
    ExtentX,
    /// Distance from the plate to the outer boundary along y (chords).
    ExtentY,
    /// Cap on the cell growth ratio.
    Growth,
    /// Number of stretched intervals of a patch.
    StretchIntervals,
    /// Reynolds number U c/ν.
    Reynolds,
    /// Courant number of the convective limit.
    Cfl,
    /// End time.
    TEnd,
    /// Time-step ceiling.
    DtMax,
    /// The dissertation's rotation rule C_c.
    Cc,
    /// Net turns after release that end the run.
    Turns,
    /// The complete turn after release from which the summary averages.
    AverageFromTurn,
    /// Angle of attack of a static plate.
    Alpha,
    /// The static plate's start-up nudge.
    Kick,
    /// The forced rotation rate θ̇.
    ForcedOmega,
    /// The forced rotation's spin-up time.
    Spinup,
    /// Angle of attack held until release.
    Alpha0,
    /// Time held before release.
    Develop,
    /// Launch (or translation) speed.
    V0,
    /// Launch flight-path angle.
    Gamma0,
    /// Mass ratio m*.
    Mass,
    /// Inertia ratio I*.
    Inertia,
    /// Gravity g*.
    Gravity,
    /// Displaced fluid mass m_f* (buoyancy).
    DisplacedMass,
    /// Applied moment on the plate.
    Torque,
    /// Adams–Bashforth order.
    AbOrder,
    /// Half-width of the near field along x (chords): beyond it the grid transport is implicit.
    NearX,
    /// Half-height of the near field along y (chords).
    NearY,
    /// Worker threads of a run.
    Threads,
    /// Physical plate width (chord).
    Chord,
    /// Physical plate thickness.
    PlateThickness,
    /// Physical plate span (3-D).
    PlateSpan,
    /// Plate density ρs.
    PlateDensity,
    /// Fluid density ρf.
    FluidDensity,
    /// Fluid kinematic viscosity ν.
    Viscosity,
    /// Acceleration of gravity g.
    GravityAccel,
}

impl Param {
    /// What the quantity is, in words (the library's name for it).
    pub fn describe(self) -> &'static str {
        match self {
            Param::Resolution => "resolution",
            Param::Thickness => "plate thickness (chords)",
            Param::Shape => "plate shape",
            Param::EdgeRadius => "edge radius (chords)",
            Param::Polygon => "polygon",
            Param::ExtentX => "extent along x (chords)",
            Param::ExtentY => "extent along y (chords)",
            Param::Growth => "growth cap",
            Param::StretchIntervals => "stretched intervals",
            Param::Reynolds => "Reynolds number",
            Param::Cfl => "Courant number",
            Param::TEnd => "end time",
            Param::DtMax => "time-step ceiling",
            Param::Cc => "rotation rule C_c",
            Param::Turns => "turns",
            Param::AverageFromTurn => "first averaged turn",
            Param::Alpha => "angle of attack α (rad)",
            Param::Kick => "start-up kick (rad)",
            Param::ForcedOmega => "forced rotation rate θ̇ (c/U)",
            Param::Spinup => "spin-up time",
            Param::Alpha0 => "launch angle of attack α₀ (rad)",
            Param::Develop => "development time",
            Param::V0 => "launch speed V₀ (on the reference speed)",
            Param::Gamma0 => "launch flight-path angle γ₀ (rad)",
            Param::Mass => "mass ratio m*",
            Param::Inertia => "inertia ratio I*",
            Param::Gravity => "gravity g*",
            Param::DisplacedMass => "displaced fluid mass m_f*",
            Param::Torque => "applied moment (by ρU²c²)",
            Param::AbOrder => "Adams–Bashforth order",
            Param::NearX => "near-field half-width along x (chords)",
            Param::NearY => "near-field half-height along y (chords)",
            Param::Threads => "worker threads (0: one per core)",
            Param::Chord => "plate width (chord, mm)",
            Param::PlateThickness => "plate thickness (mm)",
            Param::PlateSpan => "plate span (mm)",
            Param::PlateDensity => "plate density (kg/m³)",
            Param::FluidDensity => "fluid density (kg/m³)",
            Param::Viscosity => "fluid kinematic viscosity (mm²/s)",
            Param::GravityAccel => "gravity (m/s²)",
        }
    }
}

/// The accepted values of a quantity, as shown in messages.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Accepted {
    /// lo ≤ x ≤ hi, or lo < x ≤ hi when `open_lo`.
    Real {
        /// The lower bound.
        lo: f64,
        /// The upper bound.
        hi: f64,
        /// Whether the lower bound itself is excluded.
        open_lo: bool,
    },
    /// A whole number in lo..=hi.
    Whole {
        /// The smallest accepted.
        lo: usize,
        /// The largest accepted.
        hi: usize,
    },
}

impl fmt::Display for Accepted {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Accepted::Real { lo, hi, open_lo } => {
                write!(f, "{}{lo}, {hi}]", if open_lo { "(" } else { "[" })
            }
            Accepted::Whole { lo, hi } => write!(f, "{lo}..={hi}"),
        }
    }
}

/// A bad input value: which quantity, the value, and what is accepted (or why not).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum InputError {
    /// The value is outside the accepted range.
    #[error("{} {value} is out of range: accepted {accepted}", .param.describe())]
    OutOfRange {
        /// The quantity.
        param: Param,
        /// The value given.
        value: f64,
        /// What is accepted.
        accepted: Accepted,
    },
    /// The value is in range on its own but not together with the others; `why` says which.
    #[error("{} = {value} is not accepted: {why}", .param.describe())]
    Inconsistent {
        /// The quantity.
        param: Param,
        /// The value given.
        value: f64,
        /// Why it cannot work with the others, and what is accepted.
        why: String,
    },
    /// A coupled case without plate properties.
    #[error("a coupled case needs plate properties")]
    MissingPlate,
    /// A value the run needs and nothing gave; `why` says when it is needed.
    #[error("the {} is required {why}", .param.describe())]
    Missing {
        /// The quantity.
        param: Param,
        /// When it is needed.
        why: &'static str,
    },
    /// A builder option that contradicts one given before it (a grid option after the
    /// dissertation's grid, which fixes the grid and the plate).
    #[error("{option} cannot follow {earlier}: {why}")]
    Conflict {
        /// The option refused, e.g. `thickness`.
        option: &'static str,
        /// The option it contradicts, given before it.
        earlier: &'static str,
        /// What the earlier option fixes.
        why: &'static str,
    },
    /// The plate's section cannot be built (the error names the value and what is accepted).
    #[error(transparent)]
    Shape(#[from] ShapeError),
    /// The plate is thinner somewhere than the grid can follow at this resolution.
    #[error(
        "the plate is thinner near ({x:.4}, {y:.4}) than the grid can follow at N = {resolution} \
         (a grid face there would see fluid on both sides of it); {smallest}"
    )]
    TooThin {
        /// The resolution asked for.
        resolution: usize,
        /// Where the grid first fails to follow the plate (chords, body axes).
        x: f64,
        /// See `x`.
        y: f64,
        /// What resolution works, in words.
        smallest: String,
    },
}

impl InputError {
    /// The quantity the error is about, if any.
    pub fn param(&self) -> Option<Param> {
        match self {
            InputError::OutOfRange { param, .. } | InputError::Inconsistent { param, .. } => {
                Some(*param)
            }
            InputError::Missing { param, .. } => Some(*param),
            InputError::MissingPlate | InputError::Conflict { .. } => None,
            InputError::Shape(e) => Some(e.param()),
            InputError::TooThin { .. } => Some(Param::Resolution),
        }
    }
}

// The shapes sit below the named inputs: a shape's error learns which input it is about here.
impl ShapeError {
    /// The input the error is about.
    pub fn param(&self) -> Param {
        match self {
            ShapeError::Thickness(_) => Param::Thickness,
            ShapeError::EdgeRadius { .. } => Param::EdgeRadius,
            _ => Param::Polygon,
        }
    }
}

/// Checks that `value` is finite and in [lo, hi] (or (lo, hi] when `open_lo`).
///
/// # Errors
/// [`InputError::OutOfRange`] naming `param`, `value` and the accepted range when `value` is not
/// finite or outside it.
pub fn check_range(
    param: Param,
    value: f64,
    lo: f64,
    hi: f64,
    open_lo: bool,
) -> Result<(), InputError> {
    let ok = value.is_finite() && value <= hi && if open_lo { value > lo } else { value >= lo };
    if ok {
        Ok(())
    } else {
        Err(InputError::OutOfRange {
            param,
            value,
            accepted: Accepted::Real { lo, hi, open_lo },
        })
    }
}

/// Checks that a whole number lies in lo..=hi.
///
/// # Errors
/// [`InputError::OutOfRange`] naming `param`, `value` and lo..=hi when `value` is outside it.
pub fn check_whole(param: Param, value: usize, lo: usize, hi: usize) -> Result<(), InputError> {
    if (lo..=hi).contains(&value) {
        Ok(())
    } else {
        Err(InputError::OutOfRange {
            param,
            value: value as f64,
            accepted: Accepted::Whole { lo, hi },
        })
    }
}

/// A number for titles and messages: at most four significant digits, trailing zeros dropped
/// (`0.9853981633974482` → `0.9854`, `4770.3` → `4770`, `0.2` → `0.2`).
pub fn rounded(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor() as i32;
    if !(-4..6).contains(&magnitude) {
        return format!("{x:.3e}");
    }
    let decimals = (3 - magnitude).max(0) as usize;
    let text = format!("{x:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounded_keeps_four_significant_digits() {
        assert_eq!(rounded(0.9853981633974482), "0.9854");
        assert_eq!(rounded(-std::f64::consts::FRAC_PI_4), "-0.7854");
        assert_eq!(rounded(0.2), "0.2");
        assert_eq!(rounded(4770.33), "4770");
        assert_eq!(rounded(5000.0), "5000");
        assert_eq!(rounded(0.0), "0");
        assert_eq!(rounded(2.5e-7), "2.500e-7");
    }
}
