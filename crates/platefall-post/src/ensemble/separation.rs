//! Whether two ensembles' means are separated by more than their noise: Welch's t for two
//! means of unequal variances.
//!
//! The difference d = m_a − m_b has the standard error √(se_a² + se_b²) and Welch–Satterthwaite's
//! degrees of freedom ν = (se_a² + se_b²)² / (se_a⁴/ν_a + se_b⁴/ν_b). The means are separated
//! when |d| exceeds t(0.975; ν) times that standard error: the interval of the difference
//! excludes zero.
use serde::Serialize;

use super::pool::EnsembleInterval;
use crate::stats::t95;

/// The difference of two ensembles' means and whether it is resolved.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Separation {
    /// m_a − m_b.
    pub difference: f64,
    /// Half-width of the 95 % interval of the difference.
    pub half_width: f64,
    /// Welch–Satterthwaite degrees of freedom.
    pub dof: f64,
    /// Whether the interval of the difference excludes zero.
    pub resolved: bool,
}

/// The separation of `a` and `b` (their between-member intervals).
pub fn separation(a: &EnsembleInterval, b: &EnsembleInterval) -> Separation {
    let (va, vb) = (a.std_error.powi(2), b.std_error.powi(2));
    let difference = a.mean - b.mean;
    let denom = va * va / a.dof + vb * vb / b.dof;
    let dof = if denom > 0.0 {
        (va + vb).powi(2) / denom
    } else {
        a.dof + b.dof
    };
    let half_width = t95(dof) * (va + vb).sqrt();
    Separation {
        difference,
        half_width,
        dof,
        resolved: difference.abs() > half_width,
    }
}
