//! Physical units for reports (docs/physics.md §2): the run's non-dimensional results times its chord c and
//! velocity scale U. Known for physical plates ([`Strip`](super::Strip)) and the card preset.
use crate::sim::{ReferenceScales, RunConfig};

/// Conversions from the run's units (c, U, c/U) to SI-based report units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Units {
    /// The chord and velocity scale.
    pub scales: ReferenceScales,
}

impl Units {
    /// The units of a run, when its plate has physical scales.
    pub fn of(config: &RunConfig) -> Option<Units> {
        let scales = config.body.as_ref()?.scales?;
        Some(Units { scales })
    }

    /// Speed (by U) → cm/s.
    pub fn speed_cm_s(&self, v: f64) -> f64 {
        100.0 * v * self.scales.speed_m_s
    }

    /// Rate (by U/c) → rad/s.
    pub fn rate_rad_s(&self, omega: f64) -> f64 {
        omega * self.scales.speed_m_s / self.scales.chord_m
    }

    /// Time (by c/U) → s.
    pub fn time_s(&self, t: f64) -> f64 {
        t * self.scales.chord_m / self.scales.speed_m_s
    }

    /// Length (by c) → cm.
    pub fn length_cm(&self, x: f64) -> f64 {
        100.0 * x * self.scales.chord_m
    }
}
