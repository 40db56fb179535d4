//! The numerical parameters of the three-dimensional flow solver (docs/physics.md §9).
use super::error::Flow3Error;

/// Numerical parameters of the three-dimensional flow solver.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FlowParams3 {
    /// Reynolds number U c / ν.
    pub re: f64,
    /// Courant number of the convective limit.
    pub cfl: f64,
    /// Fraction of the explicit viscous stability limit used.
    pub visc_safety: f64,
    /// The pressure solve stops when every fluid cell's divergence after the correction is
    /// below this (non-dimensional, 1/time).
    pub div_tol: f64,
    /// Most iterations of the pressure solve per step.
    pub max_iterations: usize,
}

impl Default for FlowParams3 {
    fn default() -> Self {
        FlowParams3 {
            re: 5000.0,
            cfl: 0.5,
            visc_safety: 0.8,
            div_tol: 1e-11,
            max_iterations: 20_000,
        }
    }
}

impl FlowParams3 {
    /// Checks every value, naming the first bad one.
    pub fn validate(&self) -> Result<(), Flow3Error> {
        let bad = |name: &'static str, value: f64| Flow3Error::BadParameter { name, value };
        if !(self.re > 0.0 && self.re.is_finite()) {
            return Err(bad("re", self.re));
        }
        if !(self.cfl > 0.0 && self.cfl <= 1.0) {
            return Err(bad("cfl", self.cfl));
        }
        if !(self.visc_safety > 0.0 && self.visc_safety <= 1.0) {
            return Err(bad("visc_safety", self.visc_safety));
        }
        if !(self.div_tol > 0.0 && self.div_tol.is_finite()) {
            return Err(bad("div_tol", self.div_tol));
        }
        if self.max_iterations == 0 {
            return Err(bad("max_iterations", 0.0));
        }
        Ok(())
    }
}
