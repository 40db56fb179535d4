//! The case subcommands' options and their translation into a [`RunConfig`].
use std::path::PathBuf;

use clap::{Args, ValueEnum};

use super::flags::ArgError;
use super::plate_args::{CouplingArg, PhysicalArgs};
use super::record_args::RecordArgs;
use super::shape_args::ShapeArgs;
use super::Command;
use platefall_core::body::PlateProps;
use platefall_core::flow::{FarFieldScheme, FlowParams, NEAR_DEFAULT};
use platefall_core::grid::{GridSpec, Stretch};
use platefall_core::param::{check_whole, Param};
use platefall_core::sim::{BodyConfig, Case, RunConfig, TimeControl};

/// Options shared by every case.
#[derive(Args, Debug, Clone)]
pub struct SolverArgs {
    /// Reynolds number U c / ν [default: 5000, or the preset's for pinned/free].
    #[arg(long, allow_negative_numbers = true)]
    pub re: Option<f64>,
    /// Cells per chord N (h = c/N). The seed used 16; the free-fall rotation rate changes by 17 %
    /// between N = 32 and 64 (see the README), so the default is 64.
    #[arg(long, default_value_t = 64)]
    pub resolution: usize,
    /// End time in convective times c/U from the impulsive start [default depends on the case].
    #[arg(long, allow_negative_numbers = true)]
    pub t_end: Option<f64>,
    /// Write the run summary as JSON to this file.
    #[arg(long, value_name = "FILE")]
    pub summary: Option<PathBuf>,
    /// Use the seed's exact grid and plate (N = 16, a rectangle 1/16 thick, 24 × 27 stretched
    /// intervals over 10 chords); overrides --resolution, --extent and --growth.
    #[arg(long, conflicts_with_all = ["thickness", "extent", "growth", "shape", "edge_radius", "polygon"])]
    pub seed_grid: bool,
    #[command(flatten)]
    pub section: ShapeArgs,
    /// Distance from the plate to the outer boundary, in chords.
    #[arg(long, default_value_t = 15.0, allow_negative_numbers = true)]
    pub extent: f64,
    /// Cap on the ratio of neighbouring cell sizes in the stretched region.
    #[arg(long, default_value_t = 1.045, allow_negative_numbers = true)]
    pub growth: f64,
    /// Courant number of the convective time-step limit (AB2 with the limited κ = 1/3 scheme was
    /// measured stable at 0.6 and unstable at 0.8).
    #[arg(long, default_value_t = 0.5, allow_negative_numbers = true)]
    pub cfl: f64,
    /// Time-step ceiling (seed: 0.01).
    #[arg(long, default_value_t = 0.01, allow_negative_numbers = true)]
    pub dt_max: f64,
    /// The seed's rotation rule Δt·|θ̇| ≤ CC.
    #[arg(long, default_value_t = 0.005, allow_negative_numbers = true)]
    pub cc: f64,
    /// How the transport by the grid velocity is stepped outside the near field: `implicit`
    /// (line solves; Δt follows the near field), `explicit` (the scheme before issue 8, whose
    /// Δt is bound by the far field's grid speed |θ̇| × extent), or `auto`: implicit for the
    /// turning plates (forced, pinned, free), explicit for a static plate (whose grid does not
    /// move, so the implicit step would only cost more).
    #[arg(long, value_enum, default_value_t = FarFieldArg::Auto)]
    pub far_field: FarFieldArg,
    /// Half-width of the near field along x (chords): columns farther out take the grid
    /// transport along them implicitly (with --far-field implicit).
    #[arg(long, default_value_t = NEAR_DEFAULT, allow_negative_numbers = true)]
    pub near_x: f64,
    /// Half-height of the near field along y (chords): rows farther out take the grid transport
    /// along them implicitly.
    #[arg(long, default_value_t = NEAR_DEFAULT, allow_negative_numbers = true)]
    pub near_y: f64,
    /// Worker threads for the run (0: one per core); the results do not depend on it.
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    #[command(flatten)]
    pub limits: super::limits::LimitArgs,
}

/// `--far-field`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum FarFieldArg {
    Auto,
    Explicit,
    Implicit,
}

impl FarFieldArg {
    /// The scheme for a case; `auto` takes the implicit one unless the plate is static.
    pub fn scheme_for(self, case: &Case) -> FarFieldScheme {
        match (self, case) {
            (FarFieldArg::Explicit, _) | (FarFieldArg::Auto, Case::Static { .. }) => {
                FarFieldScheme::Explicit
            }
            _ => FarFieldScheme::Implicit,
        }
    }
}

impl From<FarFieldArg> for FarFieldScheme {
    /// The scheme for a turning plate (`auto` is implicit).
    fn from(a: FarFieldArg) -> FarFieldScheme {
        match a {
            FarFieldArg::Explicit => FarFieldScheme::Explicit,
            FarFieldArg::Auto | FarFieldArg::Implicit => FarFieldScheme::Implicit,
        }
    }
}

#[derive(Args, Debug)]
pub struct StaticArgs {
    /// Angle of attack α in radians, in [−π, π].
    #[arg(long, default_value_t = 0.4, allow_negative_numbers = true)]
    pub alpha: f64,
    /// Symmetry-breaking pitch nudge ε (rad): θ = α + ε sin²(πt) during the first convective time.
    #[arg(long, default_value_t = 0.05, allow_negative_numbers = true)]
    pub kick: f64,
    #[command(flatten)]
    pub solver: SolverArgs,
    #[command(flatten)]
    pub record: RecordArgs,
}

#[derive(Args, Debug)]
pub struct ForcedArgs {
    /// Final rotation rate θ̇ c/U (positive: counter-clockwise, nose up).
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    pub rate: f64,
    /// Spin-up time from α = 0 to the final rate at constant angular acceleration.
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    pub spinup: f64,
    #[command(flatten)]
    pub solver: SolverArgs,
    #[command(flatten)]
    pub record: RecordArgs,
}

/// Plate properties, the coupling and the body integrator (pinned and free cases).
#[derive(Args, Debug, Clone)]
#[command(next_help_heading = "Plate, coupling and release")]
pub struct BodyArgs {
    /// Preset giving Re, m*, I*, g*: `card` is the seed's card in sea-level air (SPEC §8; its
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
    /// How the flow's loads enter the plate's equations (`explicit` reproduces the seed's scheme
    /// and the earlier results).
    #[arg(long, value_enum, default_value_t = CouplingArg::Strong)]
    pub coupling: CouplingArg,
    /// Adams–Bashforth order for the plate's equations of motion, 1..=6.
    #[arg(long, default_value_t = 2)]
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
    #[command(flatten)]
    pub physical: PhysicalArgs,
}

impl BodyArgs {
    /// The development time: as given, else 5 for a launch at speed and 0 from rest.
    fn develop_for(&self, speed: f64) -> f64 {
        self.develop
            .unwrap_or(if speed == 0.0 { 0.0 } else { DEFAULT_DEVELOP })
    }
}

/// Development time before release for a plate launched at speed (c/U).
const DEFAULT_DEVELOP: f64 = 5.0;

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq)]
pub enum Preset {
    /// The seed's card: chord 3 in, span 8 in, 7.02e-3 lbf, U = 3 ft/s in sea-level air.
    Card,
    /// No preset: give --re, --mass, --inertia and --gravity.
    None,
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq)]
pub enum AbStartArg {
    /// Raise the order 1, 2, … over the first steps.
    Ramp,
    /// The seed's start: extrapolate the history linearly backwards.
    Extrapolate,
}

#[derive(Args, Debug)]
pub struct PinnedArgs {
    /// Angle of attack α₀ (rad) held during development, then released.
    #[arg(long, default_value_t = 0.1, allow_negative_numbers = true)]
    pub alpha0: f64,
    /// Translation speed on the reference speed (the wind tunnel's; 0: a plate on a pin in still
    /// fluid, e.g. driven by --torque).
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    pub v0: f64,
    #[command(flatten)]
    pub solver: SolverArgs,
    #[command(flatten)]
    pub body: BodyArgs,
    #[command(flatten)]
    pub record: RecordArgs,
}

#[derive(Args, Debug)]
pub struct FreeArgs {
    /// Launch speed V₀ on the reference speed [default: 1, the card's 3 ft/s; 0, released from
    /// rest, for a physically described plate].
    #[arg(long, allow_negative_numbers = true)]
    pub v0: Option<f64>,
    /// Launch flight-path angle γ₀ (rad; −π/4 is down and to the right).
    #[arg(long, default_value_t = -std::f64::consts::FRAC_PI_4, allow_negative_numbers = true)]
    pub gamma0: f64,
    /// Launch angle of attack α₀ (rad); the plate is held at θ = γ₀ + α₀ until release.
    #[arg(long, default_value_t = 0.1, allow_negative_numbers = true)]
    pub alpha0: f64,
    /// Pitch angle θ₀ at release (rad), instead of α₀ (α₀ = θ₀ − γ₀): the natural input for a plate
    /// released from rest.
    #[arg(long, allow_negative_numbers = true, conflicts_with = "alpha0")]
    pub theta0: Option<f64>,
    #[command(flatten)]
    pub solver: SolverArgs,
    #[command(flatten)]
    pub body: BodyArgs,
    #[command(flatten)]
    pub record: RecordArgs,
}

impl SolverArgs {
    /// The grid; `physical` is a physical plate's t/c (its thickness unless --thickness is given).
    fn grid(&self, physical: Option<f64>) -> Result<GridSpec, ArgError> {
        if self.seed_grid {
            return Ok(GridSpec::seed());
        }
        Ok(GridSpec {
            resolution: self.resolution,
            shape: self.section.shape(physical)?,
            extent_x: self.extent,
            extent_y: self.extent,
            stretch: Stretch::GrowthCap(self.growth),
        })
    }

    fn config(
        &self,
        case: Case,
        default_re: f64,
        default_t_end: f64,
        body: Option<BodyConfig>,
        turns: Option<f64>,
        physical: Option<f64>,
    ) -> Result<RunConfig, ArgError> {
        Ok(RunConfig {
            grid: self.grid(physical)?,
            flow: FlowParams {
                re: self.re.unwrap_or(default_re),
                cfl: self.cfl,
                far_field: self.far_field.scheme_for(&case),
                near_x: self.near_x,
                near_y: self.near_y,
                ..FlowParams::default()
            },
            body,
            time: TimeControl {
                t_end: self.t_end.unwrap_or(default_t_end),
                turns,
                dt_max: self.dt_max,
                cc: self.cc,
            },
            case,
        })
    }
}

/// The run configuration of a case subcommand, validated.
pub fn run_config(cmd: &Command) -> Result<RunConfig, ArgError> {
    let cfg = match cmd {
        Command::Static(a) => {
            let case = Case::Static {
                alpha: a.alpha,
                kick: a.kick,
            };
            a.solver.config(case, 5000.0, 80.0, None, None, None)?
        }
        Command::Forced(a) => {
            let t_end = a.spinup + 6.0 * std::f64::consts::PI / a.rate.abs().max(1e-3);
            let case = Case::Forced {
                omega: a.rate,
                spinup: a.spinup,
            };
            a.solver
                .config(case, 5000.0, t_end.min(200.0), None, None, None)?
        }
        Command::Pinned(a) => {
            let case = Case::Pinned {
                alpha0: a.alpha0,
                develop: a.body.develop_for(a.v0),
                speed: a.v0,
            };
            coupled_config(&a.solver, &a.body, case, 60.0, a.body.turns)?
        }
        Command::Free(a) => {
            let physical = a.body.physical.chord_mm.is_some();
            let v0 = a.v0.unwrap_or(if physical { 0.0 } else { 1.0 });
            let case = Case::Free {
                v0,
                gamma0: a.gamma0,
                alpha0: a.theta0.map_or(a.alpha0, |th| th - a.gamma0),
                develop: a.body.develop_for(v0),
            };
            let turns = Some(a.body.turns.unwrap_or(10.0));
            coupled_config(&a.solver, &a.body, case, 80.0, turns)?
        }
        Command::Bench(_) => return Err(ArgError::NotACase("bench")),
        Command::Sweep(_) => return Err(ArgError::NotACase("sweep")),
    };
    cfg.validate()?;
    if let Some((solver, _)) = cmd.case_args() {
        check_whole(Param::Threads, solver.threads, 0, 256)?;
    }
    Ok(cfg)
}

/// A pinned or free run: the plate from its preset and overrides or its physical description; Re
/// from --re or the plate; a physical plate's thickness for the grid unless --thickness is given.
fn coupled_config(
    solver: &SolverArgs,
    body: &BodyArgs,
    case: Case,
    default_t_end: f64,
    turns: Option<f64>,
) -> Result<RunConfig, ArgError> {
    let resolved = body.resolve()?;
    let re = solver.re.or(resolved.re).ok_or(ArgError::Missing {
        flag: "--re",
        when: "with --preset none",
    })?;
    let mut cfg = solver.config(
        case,
        re,
        default_t_end,
        Some(resolved.body),
        turns,
        resolved.strip.as_ref().map(|s| s.aspect()),
    )?;
    // A physical plate's mass and inertia are those of its section.
    if let (Some(strip), Some(body)) = (&resolved.strip, cfg.body.as_mut()) {
        body.props = PlateProps {
            torque: body.props.torque,
            ..strip.props_of(&cfg.grid.shape)
        };
    }
    Ok(cfg)
}

/// What to tell the user about the plate before a run (see [`BodyArgs::notes`]).
pub fn plate_notes(cmd: &Command, config: &RunConfig) -> Vec<String> {
    match cmd {
        Command::Pinned(a) => a.body.notes(config),
        Command::Free(a) => a.body.notes(config),
        _ => Vec::new(),
    }
}
