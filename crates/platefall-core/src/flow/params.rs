//! The flow solver's numerical parameters (docs/physics.md §2–§3) and their checks.
use crate::param::{check_range, InputError, Param};

/// How the transport by the grid velocity is stepped away from the plate (docs/physics.md §3).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FarFieldScheme {
    /// Explicit everywhere: Δt is bound by |θ̇| × the extent.
    Explicit,
    /// Implicit along the lines outside the near field: Δt follows the near field.
    #[default]
    Implicit,
}

/// Numerical parameters of the flow solver.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FlowParams {
    /// Reynolds number U c / ν.
    pub re: f64,
    /// Courant number for the convective limit.
    pub cfl: f64,
    /// Fraction of the explicit viscous stability limit used.
    pub visc_safety: f64,
    /// How the grid transport is stepped outside the near field.
    #[serde(default)]
    pub far_field: FarFieldScheme,
    /// Half-widths of the near field (chords): columns with |x| > `near_x` and rows with
    /// |y| > `near_y` take the grid transport along them implicitly.
    #[serde(default = "default_near")]
    pub near_x: f64,
    /// See `near_x`.
    #[serde(default = "default_near")]
    pub near_y: f64,
}

/// The near field's default half-width (chords); see docs/performance.md.
pub const NEAR_DEFAULT: f64 = 1.0;

fn default_near() -> f64 {
    NEAR_DEFAULT
}

impl Default for FlowParams {
    fn default() -> Self {
        FlowParams {
            re: 5000.0,
            cfl: 0.5,
            visc_safety: 0.8,
            far_field: FarFieldScheme::Implicit,
            near_x: NEAR_DEFAULT,
            near_y: NEAR_DEFAULT,
        }
    }
}

impl FlowParams {
    /// Checks every value, naming the first bad one and its accepted range.
    ///
    /// # Errors
    /// [`InputError::OutOfRange`] for the first value outside its range.
    pub fn validate(&self) -> Result<(), InputError> {
        check_range(Param::Reynolds, self.re, 0.0, 1e5, true)?;
        check_range(Param::Cfl, self.cfl, 0.0, 1.0, true)?;
        check_range(Param::NearX, self.near_x, 0.5, 1000.0, false)?;
        check_range(Param::NearY, self.near_y, 0.5, 1000.0, false)
    }

    /// Today's explicit scheme everywhere (the byte-identical baseline).
    pub fn explicit(re: f64) -> FlowParams {
        FlowParams {
            re,
            far_field: FarFieldScheme::Explicit,
            ..FlowParams::default()
        }
    }

    /// The kinematic viscosity ν = 1/Re of the non-dimensional equations (docs/physics.md §2):
    /// the one place it is derived.
    pub fn nu(&self) -> f64 {
        1.0 / self.re
    }
}
