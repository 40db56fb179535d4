//! The plate's description on the command line (docs/physics.md §2, §6): the card preset or non-dimensional
//! values ([`BodyArgs`]), or a plate described physically ([`PhysicalArgs`]: width, thickness,
//! density, a named fluid, gravity), which the library's [`Plate::strip`] turns into Re, m*, I*,
//! g*, m_f*; and the coupling and body-integrator options of the pinned and free cases.
use clap::{Args, ValueEnum};

use super::flags::ArgError;
use platefall_core::body::{AbStart, Coupling};
use platefall_core::config::{defaults, Fluid, FreeFall, PinnedPlate, Plate, RunBuilder, Strip};
use platefall_core::sim::ValidatedConfig;

/// Plate properties, the coupling and the body integrator (pinned and free cases).
#[derive(Args, Debug, Clone)]
#[command(next_help_heading = "Plate, coupling and release")]
pub struct BodyArgs {
    /// Preset giving Re, m*, I*, g*: `card` is the dissertation's card in sea-level air (docs/physics.md §8; its
    /// weight is the apparent weight, m_f* = 0) [default: card, unless the plate is described
    /// physically].
    #[arg(long, value_enum)]
    pub preset: Option<Preset>,
    /// Mass ratio m* = m/(ρc²b) (overrides the preset).
    #[arg(long, allow_negative_numbers = true)]
    pub mass: Option<f64>,
    /// Inertia ratio I* = I/(ρc⁴b) (overrides the preset).
    #[arg(long, allow_negative_numbers = true)]
    pub inertia: Option<f64>,
    /// Gravity g* = g c/U² (overrides the preset; ignored by `pinned`).
    #[arg(long, allow_negative_numbers = true)]
    pub gravity: Option<f64>,
    /// Displaced fluid mass m_f* = ρf × volume/(ρf c² b) (t/c for a plate of thickness t): the
    /// weight is (m* − m_f*) g* [default: 0, the weight given is the apparent weight].
    #[arg(long, allow_negative_numbers = true)]
    pub displaced_mass: Option<f64>,
    /// An applied moment on the plate, by ρU²c² (counter-clockwise positive).
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub torque: f64,
    /// How the flow's loads enter the plate's equations (`explicit` is the dissertation's scheme).
    #[arg(long, value_enum, default_value_t = CouplingArg::Strong)]
    pub coupling: CouplingArg,
    /// Adams–Bashforth order for the plate's equations of motion, 1..=6.
    #[arg(long, default_value_t = defaults::AB_ORDER)]
    pub ab_order: usize,
    /// How the Adams–Bashforth history is started at release.
    #[arg(long, value_enum, default_value_t = AbStartArg::Ramp)]
    pub ab_start: AbStartArg,
    /// Hold the plate at its launch attitude for this long before release (flow development)
    /// [default: 5, or 0 when it starts from rest].
    #[arg(long, allow_negative_numbers = true)]
    pub develop: Option<f64>,
    /// Stop after this many net turns after release, or at --t-end, whichever comes first
    /// [default: 10 for free, none for pinned].
    #[arg(long, allow_negative_numbers = true)]
    pub turns: Option<f64>,
    /// Average the summary's means and their intervals over the whole turns from this complete
    /// turn after release on, leaving the earlier turns to the transient (1..=turns−1).
    #[arg(long, default_value_t = 1)]
    pub average_from_turn: usize,
    #[command(flatten)]
    pub physical: PhysicalArgs,
}

/// `--preset`.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq)]
pub enum Preset {
    /// The dissertation's card: chord 3 in, span 8 in, 7.02e-3 lbf, U = 3 ft/s in sea-level air.
    Card,
    /// No preset: give --re, --mass, --inertia and --gravity.
    None,
}

/// `--ab-start`.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq)]
pub enum AbStartArg {
    /// Raise the order 1, 2, … over the first steps.
    Ramp,
    /// The dissertation's start: extrapolate the history linearly backwards.
    Extrapolate,
}

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
    /// Plate span b in mm, for a 3-D run (`--span`): with a finite `--span B` it must equal B
    /// times the chord (B = b/c), with `periodic:P` P times the chord [default: B (or P) times
    /// the chord].
    #[arg(
        long,
        value_name = "MM",
        allow_negative_numbers = true,
        requires_all = ["chord_mm", "thickness_mm", "plate_density", "span"]
    )]
    pub span_mm: Option<f64>,
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
    /// The dissertation's: loads taken as given; diverges for m* < π/4 or I* < π/128.
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

/// The builder methods the body options set, for both coupled cases.
pub trait CoupledBuilder: Sized {
    /// Applies the options of the plate's release, coupling and integrator.
    #[must_use]
    fn body_options(self, args: &BodyArgs) -> Self;
}

macro_rules! coupled_builder {
    ($case:ty) => {
        impl CoupledBuilder for RunBuilder<$case> {
            fn body_options(self, a: &BodyArgs) -> Self {
                let mut b = self
                    .coupling(match a.coupling {
                        CouplingArg::Strong => Coupling::Strong,
                        CouplingArg::Explicit => Coupling::Explicit,
                    })
                    .ab_order(a.ab_order)
                    .ab_start(match a.ab_start {
                        AbStartArg::Ramp => AbStart::Ramp,
                        AbStartArg::Extrapolate => AbStart::Extrapolate,
                    });
                if let Some(d) = a.develop {
                    b = b.develop(d);
                }
                if let Some(n) = a.turns {
                    b = b.turns(n);
                }
                b.average_from_turn(a.average_from_turn)
            }
        }
    };
}
coupled_builder!(PinnedPlate);
coupled_builder!(FreeFall);

impl BodyArgs {
    /// The plate: physical, or the preset's values overridden by explicit ones.
    pub fn plate(&self) -> Result<Plate, ArgError> {
        let plate = match self.physical.strip() {
            Some(strip) => Plate::strip(&strip)?,
            None if self.preset.unwrap_or(Preset::Card) == Preset::Card => {
                let mut card = Plate::card();
                if let Some(m) = self.mass {
                    card = card.mass(m);
                }
                if let Some(i) = self.inertia {
                    card = card.inertia(i);
                }
                if let Some(g) = self.gravity {
                    card = card.gravity(g);
                }
                card
            }
            None => {
                let need = |flag: &'static str, given: Option<f64>| {
                    given.ok_or(ArgError::Missing {
                        flag,
                        when: "with --preset none",
                    })
                };
                Plate::nondimensional(
                    need("--mass", self.mass)?,
                    need("--inertia", self.inertia)?,
                    need("--gravity", self.gravity)?,
                )
            }
        };
        let plate = match self.displaced_mass {
            Some(m) => plate.displaced(m),
            None => plate,
        };
        Ok(plate.torque(self.torque))
    }

    /// What to tell the user before the run: a physical plate's derivation of its parameters and
    /// its section; the explicit-coupling advice for a light plate.
    pub fn notes(&self, config: &ValidatedConfig) -> Vec<String> {
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
