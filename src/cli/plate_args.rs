//! The plate's description on the command line (SPEC §2, §6): the card preset or non-dimensional
//! values ([`BodyArgs`](super::args::BodyArgs)), or a plate described physically
//! ([`PhysicalArgs`]: width, thickness, density, a named fluid, gravity), which `config::Strip`
//! turns into Re, m*, I*, g*, m_f*.
use clap::{Args, ValueEnum};

use super::args::{AbStartArg, BodyArgs, Preset};
use super::flags::ArgError;
use platefall_core::body::{AbStart, Coupling, PlateProps};
use platefall_core::config::{Fluid, PhysicalPlate, Strip};
use platefall_core::sim::{BodyConfig, RunConfig};

/// The three inputs that describe a plate physically; each of the physical options needs them all.
const PLATE: [&str; 3] = ["chord_mm", "thickness_mm", "plate_density"];

/// A plate described physically (pinned and free cases). Giving any of these describes the plate
/// by them: `--chord-mm`, `--thickness-mm` and `--plate-density` are then all needed, and Re, m*,
/// I*, g*, m_f* are derived (so `--preset`, `--mass`, `--inertia`, `--gravity`,
/// `--displaced-mass` and `--re` are refused).
#[derive(Args, Debug, Clone, Default)]
#[command(next_help_heading = "Physical plate (SI units; derives Re, m*, I*, g*, m_f*)")]
pub struct PhysicalArgs {
    /// Plate width (chord) c in mm.
    #[arg(long, value_name = "MM", allow_negative_numbers = true,
          requires_all = PLATE,
          conflicts_with_all = ["preset", "mass", "inertia", "gravity", "displaced_mass", "re"])]
    pub chord_mm: Option<f64>,
    /// Plate thickness t in mm (the section's thickness t/c, exact unless --thickness is given).
    #[arg(
        long,
        value_name = "MM",
        allow_negative_numbers = true,
        requires_all = PLATE
    )]
    pub thickness_mm: Option<f64>,
    /// Plate density ρs in kg/m³ (aluminium 2700, steel 7850, PMMA 1190, brass 8500).
    #[arg(
        long,
        value_name = "KG_M3",
        allow_negative_numbers = true,
        requires_all = PLATE
    )]
    pub plate_density: Option<f64>,
    /// The fluid [default: water].
    #[arg(long, value_enum, requires_all = PLATE)]
    pub fluid: Option<FluidArg>,
    /// Fluid density ρf in kg/m³ (overrides the fluid's).
    #[arg(
        long,
        value_name = "KG_M3",
        allow_negative_numbers = true,
        requires_all = PLATE
    )]
    pub fluid_density: Option<f64>,
    /// Fluid kinematic viscosity ν in mm²/s (overrides the fluid's; water 1.004).
    #[arg(
        long,
        value_name = "MM2_S",
        allow_negative_numbers = true,
        requires_all = PLATE
    )]
    pub viscosity: Option<f64>,
    /// Acceleration of gravity g in m/s².
    #[arg(
        long,
        value_name = "M_S2",
        default_value_t = 9.81,
        allow_negative_numbers = true
    )]
    pub g: f64,
}

/// The named fluids (values at 20 °C; see `config::fluid`).
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq)]
pub enum FluidArg {
    /// Water at 20 °C: 998.2 kg/m³, 1.004 mm²/s.
    Water,
    /// Dry air at 20 °C, 1 atm: 1.204 kg/m³, 15.16 mm²/s.
    Air,
    /// 50 % glycerol by mass in water at 20 °C: 1126.3 kg/m³, 5.33 mm²/s.
    GlycerolWater,
}

/// How the coupling of flow and body is chosen on the command line.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq)]
pub enum CouplingArg {
    /// The flow's added-mass answer implicit in the body's equations: stable for any m*, I* > 0.
    Strong,
    /// The seed's: loads taken as given; diverges for m* < π/4 or I* < π/128.
    Explicit,
}

impl PhysicalArgs {
    /// The physical plate, when one is described.
    pub fn strip(&self) -> Option<Strip> {
        let chord = self.chord_mm?;
        let fluid = match self.fluid.unwrap_or(FluidArg::Water) {
            FluidArg::Water => Fluid::water(),
            FluidArg::Air => Fluid::air(),
            FluidArg::GlycerolWater => Fluid::glycerol_water(),
        };
        Some(Strip {
            chord: chord * 1e-3,
            thickness: self.thickness_mm.unwrap_or(f64::NAN) * 1e-3,
            density: self.plate_density.unwrap_or(f64::NAN),
            fluid: fluid.overridden(self.fluid_density, self.viscosity.map(|v| v * 1e-6)),
            gravity: self.g,
        })
    }
}

/// A plate resolved from the command line: its description, the Reynolds number it implies (if
/// any) and, for a physical plate, the strip it was derived from.
pub struct ResolvedBody {
    pub body: BodyConfig,
    pub re: Option<f64>,
    pub strip: Option<Strip>,
}

impl BodyArgs {
    /// The plate: physical, or the preset's values overridden by explicit ones.
    pub fn resolve(&self) -> Result<ResolvedBody, ArgError> {
        if let Some(strip) = self.physical.strip() {
            strip.validate()?;
            let props = PlateProps {
                torque: self.torque,
                ..strip.props()
            };
            return Ok(ResolvedBody {
                body: self.body_config(Some(label(&strip)), Some(strip.scales()), props),
                re: Some(strip.reynolds()),
                strip: Some(strip),
            });
        }
        let card = PhysicalPlate::card();
        let preset = self.preset.unwrap_or(Preset::Card) == Preset::Card;
        let base = preset.then(|| card.props());
        let pick = |flag: &'static str, given: Option<f64>, from: Option<f64>| {
            given.or(from).ok_or(ArgError::Missing {
                flag,
                when: "with --preset none",
            })
        };
        let props = PlateProps {
            displaced: self.displaced_mass.unwrap_or(0.0),
            torque: self.torque,
            ..PlateProps::new(
                pick("--mass", self.mass, base.map(|b| b.mass))?,
                pick("--inertia", self.inertia, base.map(|b| b.inertia))?,
                pick("--gravity", self.gravity, base.map(|b| b.gravity))?,
            )
        };
        Ok(ResolvedBody {
            body: self.body_config(
                preset.then(|| "card".to_string()),
                preset.then(|| card.scales()),
                props,
            ),
            re: preset.then(|| card.reynolds()),
            strip: None,
        })
    }

    fn body_config(
        &self,
        preset: Option<String>,
        scales: Option<platefall_core::sim::ReferenceScales>,
        props: PlateProps,
    ) -> BodyConfig {
        BodyConfig {
            preset,
            scales,
            props,
            ab_order: self.ab_order,
            ab_start: match self.ab_start {
                AbStartArg::Ramp => AbStart::Ramp,
                AbStartArg::Extrapolate => AbStart::Extrapolate,
            },
            coupling: match self.coupling {
                CouplingArg::Strong => Coupling::Strong,
                CouplingArg::Explicit => Coupling::Explicit,
            },
        }
    }

    /// What to tell the user before the run: a physical plate's derivation of its parameters and
    /// how the grid draws its thickness; the explicit-coupling advice for a light plate.
    pub fn notes(&self, config: &RunConfig) -> Vec<String> {
        let mut lines = Vec::new();
        if let Some(strip) = self.physical.strip() {
            lines.extend(strip.derivation());
            let shape = &config.grid.shape;
            if let Some(b) = &config.body {
                lines.push(format!(
                    "section: {} (exact at every N); m* = {:.4}, m_f* = {:.4}, I* = {:.5} from its \
                     area and polar moment",
                    shape.describe(),
                    b.props.mass,
                    b.props.displaced,
                    b.props.inertia
                ));
            }
        }
        if let Some(b) = config
            .body
            .as_ref()
            .filter(|b| b.coupling == Coupling::Explicit)
        {
            if let Some(advice) = platefall_core::body::coupling_advice(&b.props) {
                lines.push(format!(
                    "warning: {advice}; the default --coupling strong is not"
                ));
            }
        }
        lines
    }
}

/// A one-line name for a physical plate (the run's title).
fn label(s: &Strip) -> String {
    format!(
        "{} × {} mm plate of {} kg/m³ in {}",
        s.chord * 1e3,
        s.thickness * 1e3,
        s.density,
        s.fluid.name
    )
}
