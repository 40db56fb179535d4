//! A plate described physically (docs/physics.md §2): a strip of width c, thickness t and density ρs in a
//! fluid of density ρf and kinematic viscosity ν, under gravity g, released from rest. SI units
//! inside; the command line takes millimetres.
//!
//! The velocity scale does not depend on the launch (docs/physics.md §2):
//!
//! ```text
//!     U = √(|ρs/ρf − 1| g t)        (U = √(g t) for a neutrally buoyant plate)
//! ```
//!
//! so that the buoyancy-corrected weight per span, (ρs − ρf) g t c, is exactly ±1 in units of
//! ρf U² c (+1 sinks, −1 rises). Then Re = U c/ν, m* = (ρs/ρf)(t/c), m_f* = t/c (the displaced
//! fluid), I* = m*(1 + (t/c)²)/12 (a rectangle about its centre) and g* = g c/U².
use super::fluid::Fluid;
use crate::body::PlateProps;
use crate::param::{check_range, rounded, InputError, Param};
use crate::shape::Shape;
use crate::sim::ReferenceScales;

/// A physical plate in a physical fluid (SI units).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Strip {
    /// Width c (m), the chord.
    pub chord: f64,
    /// Thickness t (m).
    pub thickness: f64,
    /// ρs (kg/m³).
    pub density: f64,
    /// The fluid the plate falls through.
    pub fluid: Fluid,
    /// g (m/s²).
    pub gravity: f64,
}

/// The solver's range of Reynolds numbers (as `RunConfig::validate` checks it).
const RE_MAX: f64 = 1e5;

impl Strip {
    /// ρs/ρf.
    pub fn density_ratio(&self) -> f64 {
        self.density / self.fluid.density
    }

    /// t/c.
    pub fn aspect(&self) -> f64 {
        self.thickness / self.chord
    }

    /// The velocity scale U (m/s) of the module docs.
    pub fn speed_scale(&self) -> f64 {
        let excess = (self.density_ratio() - 1.0).abs();
        let factor = if excess > 0.0 { excess } else { 1.0 };
        (factor * self.gravity * self.thickness).sqrt()
    }

    /// Re = U c/ν.
    pub fn reynolds(&self) -> f64 {
        self.speed_scale() * self.chord / self.fluid.viscosity
    }

    /// m*, I*, g*, m_f* (no applied moment) of a rectangular strip.
    pub fn props(&self) -> PlateProps {
        self.props_of(&Shape::rect(self.aspect()))
    }

    /// m*, I*, g*, m_f* of a strip of this section (thickness t/c): m_f* is the section's area
    /// A/c², m* = (ρs/ρf) m_f*, I* = (ρs/ρf) J/c⁴ with J its polar moment about the centroid.
    pub fn props_of(&self, shape: &Shape) -> PlateProps {
        let r = self.density_ratio();
        let (area, inertia) = match shape {
            // m*(1 + (t/c)²)/12, the rectangle's I* in this order of operations.
            Shape::Rect { thickness } => {
                (*thickness, r * thickness * (1.0 + thickness.powi(2)) / 12.0)
            }
            _ => {
                let (area, polar) = shape.area_moments();
                (area, r * polar)
            }
        };
        let u = self.speed_scale();
        PlateProps {
            displaced: area,
            ..PlateProps::new(r * area, inertia, self.gravity * self.chord / (u * u))
        }
    }

    /// The chord and velocity scale, for reports in physical units.
    pub fn scales(&self) -> ReferenceScales {
        ReferenceScales {
            chord_m: self.chord,
            speed_m_s: self.speed_scale(),
        }
    }

    /// Checks every input and the derived Reynolds number, naming the input to change.
    ///
    /// # Errors
    /// [`InputError::OutOfRange`] for the first input outside its range;
    /// [`InputError::Inconsistent`] when the thickness exceeds the width or the derived Reynolds
    /// number is above the solver's limit.
    pub fn validate(&self) -> Result<(), InputError> {
        check_range(Param::Chord, self.chord * 1e3, 0.0, 1e4, true)?;
        check_range(Param::PlateThickness, self.thickness * 1e3, 0.0, 1e4, true)?;
        check_range(Param::PlateDensity, self.density, 0.0, 1e5, true)?;
        check_range(Param::FluidDensity, self.fluid.density, 0.0, 1e5, true)?;
        check_range(Param::Viscosity, self.fluid.viscosity * 1e6, 0.0, 1e6, true)?;
        check_range(Param::GravityAccel, self.gravity, 0.0, 1e3, true)?;
        if self.aspect() > 1.0 {
            return Err(InputError::Inconsistent {
                param: Param::PlateThickness,
                value: self.thickness * 1e3,
                why: format!(
                    "the thickness is at most the width ({:.4} mm); accepted (0, {}]",
                    self.chord * 1e3,
                    self.chord * 1e3
                ),
            });
        }
        let re = self.reynolds();
        if re > RE_MAX {
            return Err(InputError::Inconsistent {
                param: Param::Viscosity,
                value: self.fluid.viscosity * 1e6,
                why: format!(
                    "the plate's Reynolds number U c/ν = {re:.4e} is above the solver's {RE_MAX:e}; \
                     a more viscous fluid or a smaller plate"
                ),
            });
        }
        Ok(())
    }

    /// A one-line description (the run's title): "10 × 0.5 mm plate of 2700 kg/m³ in water".
    pub fn describe(&self) -> String {
        format!(
            "{} × {} mm plate of {} kg/m³ in {}",
            rounded(self.chord * 1e3),
            rounded(self.thickness * 1e3),
            rounded(self.density),
            self.fluid.name
        )
    }

    /// The inputs and every derived parameter with its formula, one item a line.
    pub fn derivation(&self) -> Vec<String> {
        let p = self.props();
        let (u, r, a) = (self.speed_scale(), self.density_ratio(), self.aspect());
        let scale = if r != 1.0 {
            format!(
                "√(|ρs/ρf − 1| g t) = √({:.4} × {} × {:.4e})",
                (r - 1.0).abs(),
                self.gravity,
                self.thickness
            )
        } else {
            format!(
                "√(g t) (neutrally buoyant) = √({} × {:.4e})",
                self.gravity, self.thickness
            )
        };
        let f = &self.fluid;
        vec![
            format!(
                "plate: width c = {} mm, thickness t = {} mm, density ρs = {} kg/m³; g = {} m/s²",
                self.chord * 1e3,
                self.thickness * 1e3,
                self.density,
                self.gravity
            ),
            format!(
                "fluid: {}: ρf = {} kg/m³, ν = {:.4} mm²/s ({})",
                f.name,
                f.density,
                f.viscosity * 1e6,
                f.source
            ),
            format!(
                "velocity scale U = {scale} = {:.4} cm/s; time unit c/U = {:.4} s",
                u * 100.0,
                self.chord / u
            ),
            format!("Re = U c/ν = {:.1}", self.reynolds()),
            format!(
                "m* = (ρs/ρf)(t/c) = {r:.4} × {a:.4} = {:.4}; m_f* = t/c = {a:.4}; \
                 I* = m*(1 + (t/c)²)/12 = {:.5}",
                p.mass, p.inertia
            ),
            format!(
                "g* = g c/U² = {:.4}; buoyancy-corrected weight (m* − m_f*) g* = {:+.4} ({})",
                p.gravity,
                p.weight(),
                if p.weight() > 0.0 {
                    "sinks"
                } else if p.weight() < 0.0 {
                    "rises"
                } else {
                    "neutrally buoyant"
                }
            ),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn strip(density: f64) -> Strip {
        Strip {
            chord: 0.01,
            thickness: 5e-4,
            density,
            fluid: Fluid::water(),
            gravity: 9.81,
        }
    }

    #[test]
    fn weight_is_plus_or_minus_one_in_flow_units() {
        for (rho, w) in [(2700.0, 1.0), (500.0, -1.0), (7850.0, 1.0)] {
            let p = strip(rho).props();
            assert!(
                (p.weight() - w).abs() < 1e-12,
                "ρs {rho}: weight {}",
                p.weight()
            );
        }
        let neutral = strip(998.2).props();
        assert_eq!(neutral.weight(), 0.0);
        assert_eq!(neutral.mass, neutral.displaced);
    }

    #[test]
    fn aluminium_in_water_parameters() {
        // U = √(1.705 × 9.81 × 5e-4) = 9.146 cm/s, Re = U c/ν = 911, m* = 2.705 × 0.05 = 0.135.
        let s = strip(2700.0);
        assert!(
            (s.speed_scale() - 0.09146).abs() < 1e-4,
            "{}",
            s.speed_scale()
        );
        assert!((s.reynolds() - 911.0).abs() < 1.0, "{}", s.reynolds());
        let p = s.props();
        assert!((p.mass - 0.13525).abs() < 1e-4 && (p.displaced - 0.05).abs() < 1e-15);
        assert!((p.inertia - p.mass * 1.0025 / 12.0).abs() < 1e-15);
        assert!(s.validate().is_ok());
        let thick = Strip {
            thickness: 0.012,
            ..s
        };
        assert_eq!(
            thick.validate().unwrap_err().param(),
            Some(Param::PlateThickness)
        );
    }
}
