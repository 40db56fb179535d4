//! The dissertation's card (docs/physics.md §8, dissertation Table I) in physical units, and its non-dimensional parameters
//! (docs/physics.md §2). Units are the dissertation's: ft, lbf, slug, s.
//!
//! The card keeps the dissertation's scale, U = 3 ft/s (its launch speed), and the dissertation's weight, which is
//! taken as the apparent (buoyancy-corrected) weight in air: m_f* = 0, so W = m* g* exactly as before.
//! (Air's buoyancy on a card about 0.3 mm thick, ρ_air/ρ_card ≈ 0.002, is about 0.2 % of its
//! weight.)

use crate::body::PlateProps;
use crate::sim::ReferenceScales;

/// Metres per foot.
pub const FOOT_M: f64 = 0.3048;

/// A physical plate in a physical fluid (docs/physics.md §2, §8), feet–slug–second units.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PhysicalPlate {
    /// Chord c (ft).
    pub chord_ft: f64,
    /// Span b (ft).
    pub span_ft: f64,
    /// Weight W = m g (lbf).
    pub weight_lbf: f64,
    /// Pitch inertia I about the centre (slug·ft²).
    pub inertia_slug_ft2: f64,
    /// Fluid density ρ (slug/ft³).
    pub density_slug_ft3: f64,
    /// Kinematic viscosity ν (ft²/s).
    pub viscosity_ft2_s: f64,
    /// Reference (release) speed U (ft/s).
    pub speed_ft_s: f64,
    /// Gravity g (ft/s²).
    pub gravity_ft_s2: f64,
}

/// The non-dimensional parameters of a run (docs/physics.md §2) and the time unit.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct NonDimensional {
    /// Re = U c / ν.
    pub reynolds: f64,
    /// m*, I*, g*.
    pub props: PlateProps,
    /// Convective time c/U (s): one non-dimensional time unit.
    pub convective_time_s: f64,
}

impl PhysicalPlate {
    /// The dissertation's card (docs/physics.md §8): chord 3 in, span 8 in, 7.02e-3 lbf, 1.13e-6 slug·ft², sea-level
    /// air (ρ = 0.0023769 slug/ft³, ν = 1.5723e-4 ft²/s), U = 3 ft/s, g = 32.174 ft/s².
    pub fn card() -> Self {
        Self {
            chord_ft: 0.25,
            span_ft: 8.0 / 12.0,
            weight_lbf: 7.02e-3,
            inertia_slug_ft2: 1.13e-6,
            density_slug_ft3: 0.0023769,
            viscosity_ft2_s: 1.5723e-4,
            speed_ft_s: 3.0,
            gravity_ft_s2: 32.174,
        }
    }

    /// Mass m = W/g (slug).
    pub fn mass_slug(&self) -> f64 {
        self.weight_lbf / self.gravity_ft_s2
    }

    /// Re = U c / ν (docs/physics.md §2).
    pub fn reynolds(&self) -> f64 {
        self.speed_ft_s * self.chord_ft / self.viscosity_ft2_s
    }

    /// m* = m / (ρ c² b) (docs/physics.md §2).
    pub fn mass_ratio(&self) -> f64 {
        self.mass_slug() / (self.density_slug_ft3 * self.chord_ft.powi(2) * self.span_ft)
    }

    /// I* = I / (ρ c⁴ b) (docs/physics.md §2).
    pub fn inertia_ratio(&self) -> f64 {
        self.inertia_slug_ft2 / (self.density_slug_ft3 * self.chord_ft.powi(4) * self.span_ft)
    }

    /// g* = g c / U² (docs/physics.md §2).
    pub fn gravity_ratio(&self) -> f64 {
        self.gravity_ft_s2 * self.chord_ft / self.speed_ft_s.powi(2)
    }

    /// Convective time c/U (s), the unit of non-dimensional time (docs/physics.md §2).
    pub fn convective_time_s(&self) -> f64 {
        self.chord_ft / self.speed_ft_s
    }

    /// (m*, I*, g*) for the body equations; the weight is the apparent weight (m_f* = 0).
    pub fn props(&self) -> PlateProps {
        PlateProps::new(
            self.mass_ratio(),
            self.inertia_ratio(),
            self.gravity_ratio(),
        )
    }

    /// The chord and velocity scale in SI units, for reports in physical units.
    pub fn scales(&self) -> ReferenceScales {
        ReferenceScales {
            chord_m: self.chord_ft * FOOT_M,
            speed_m_s: self.speed_ft_s * FOOT_M,
        }
    }

    /// All non-dimensional parameters at once.
    pub fn nondimensional(&self) -> NonDimensional {
        NonDimensional {
            reynolds: self.reynolds(),
            props: self.props(),
            convective_time_s: self.convective_time_s(),
        }
    }

    /// Non-dimensional speed (by U) → ft/s.
    pub fn speed_to_ft_s(&self, v: f64) -> f64 {
        v * self.speed_ft_s
    }

    /// Non-dimensional rate (by U/c) → rad/s.
    pub fn rate_to_rad_s(&self, omega: f64) -> f64 {
        omega * self.speed_ft_s / self.chord_ft
    }

    /// Non-dimensional time (by c/U) → s.
    pub fn time_to_s(&self, t: f64) -> f64 {
        t * self.convective_time_s()
    }
}
