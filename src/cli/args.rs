//! The case subcommands' options and their translation into a [`RunConfig`].
use std::path::PathBuf;

use clap::{Args, ValueEnum};

use super::flags::ArgError;
use super::record_args::RecordArgs;
use super::Command;
use crate::body::{AbStart, PlateProps};
use crate::config::PhysicalPlate;
use crate::flow::FlowParams;
use crate::grid::{GridSpec, Stretch};
use crate::sim::{BodyConfig, Case, RunConfig, TimeControl};

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
    /// Use the seed's exact grid (N = 16, 24 × 27 stretched intervals over 10 chords); overrides
    /// --resolution, --extent and --growth.
    #[arg(long, conflicts_with_all = ["thickness", "extent", "growth"])]
    pub seed_grid: bool,
    /// Plate thickness as a chord fraction, rounded to whole cells [default: one cell, 1/N, the
    /// thinnest plate the grid holds; a real card is about 1/100 of its chord]. Plates two or more
    /// cells thick have blunt edges that can hold a leading-edge vortex in a high-lift state at
    /// α ≈ 0.4 (see the README).
    #[arg(long, allow_negative_numbers = true)]
    pub thickness: Option<f64>,
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
    #[command(flatten)]
    pub limits: super::limits::LimitArgs,
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

/// Plate properties and the body integrator (pinned and free cases).
#[derive(Args, Debug, Clone)]
pub struct BodyArgs {
    /// Physical preset giving Re, m*, I*, g*: `card` is the seed's card in sea-level air (SPEC §8).
    #[arg(long, value_enum, default_value_t = Preset::Card)]
    pub preset: Preset,
    /// Mass ratio m* = m/(ρc²b) (overrides the preset).
    #[arg(long, allow_negative_numbers = true)]
    pub mass: Option<f64>,
    /// Inertia ratio I* = I/(ρc⁴b) (overrides the preset).
    #[arg(long, allow_negative_numbers = true)]
    pub inertia: Option<f64>,
    /// Gravity g* = g c/U² (overrides the preset; ignored by `pinned`).
    #[arg(long, allow_negative_numbers = true)]
    pub gravity: Option<f64>,
    /// Adams–Bashforth order for the plate's equations of motion, 1..=6.
    #[arg(long, default_value_t = 2)]
    pub ab_order: usize,
    /// How the Adams–Bashforth history is started at release.
    #[arg(long, value_enum, default_value_t = AbStartArg::Ramp)]
    pub ab_start: AbStartArg,
    /// Hold the plate at its launch attitude for this long before release (flow development).
    #[arg(long, default_value_t = 5.0, allow_negative_numbers = true)]
    pub develop: f64,
    /// Stop after this many net turns after release, or at --t-end, whichever comes first
    /// [default: 10 for free, none for pinned].
    #[arg(long, allow_negative_numbers = true)]
    pub turns: Option<f64>,
}

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
    #[command(flatten)]
    pub body: BodyArgs,
    #[command(flatten)]
    pub solver: SolverArgs,
    #[command(flatten)]
    pub record: RecordArgs,
}

#[derive(Args, Debug)]
pub struct FreeArgs {
    /// Launch speed V₀ on the reference speed (the card: 1.0 = 3 ft/s).
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    pub v0: f64,
    /// Launch flight-path angle γ₀ (rad; −π/4 is down and to the right).
    #[arg(long, default_value_t = -std::f64::consts::FRAC_PI_4, allow_negative_numbers = true)]
    pub gamma0: f64,
    /// Launch angle of attack α₀ (rad); the plate is held at θ = γ₀ + α₀ until release.
    #[arg(long, default_value_t = 0.1, allow_negative_numbers = true)]
    pub alpha0: f64,
    #[command(flatten)]
    pub body: BodyArgs,
    #[command(flatten)]
    pub solver: SolverArgs,
    #[command(flatten)]
    pub record: RecordArgs,
}

#[derive(Args, Debug)]
pub struct BenchArgs {
    /// Cells per chord of the grids to time (each with the default extent and growth cap).
    #[arg(long, value_delimiter = ',', default_values_t = vec![32, 64, 128, 384])]
    pub resolutions: Vec<usize>,
    /// Steps timed per grid (after 5 warm-up steps).
    #[arg(long, default_value_t = 50)]
    pub steps: usize,
    /// Write the results as JSON to this file.
    #[arg(long, value_name = "FILE")]
    pub json: Option<PathBuf>,
}

impl SolverArgs {
    fn grid(&self) -> GridSpec {
        if self.seed_grid {
            return GridSpec::seed();
        }
        GridSpec {
            resolution: self.resolution,
            thickness: self
                .thickness
                .unwrap_or(1.0 / self.resolution.max(1) as f64),
            extent_x: self.extent,
            extent_y: self.extent,
            stretch: Stretch::GrowthCap(self.growth),
        }
    }

    fn config(
        &self,
        case: Case,
        default_re: f64,
        default_t_end: f64,
        body: Option<BodyConfig>,
        turns: Option<f64>,
    ) -> RunConfig {
        RunConfig {
            case,
            grid: self.grid(),
            flow: FlowParams {
                re: self.re.unwrap_or(default_re),
                cfl: self.cfl,
                ..FlowParams::default()
            },
            body,
            time: TimeControl {
                t_end: self.t_end.unwrap_or(default_t_end),
                turns,
                dt_max: self.dt_max,
                cc: self.cc,
            },
        }
    }
}

impl BodyArgs {
    /// Plate properties and default Re: the preset's, overridden by explicit values.
    fn resolve(&self) -> Result<(BodyConfig, Option<f64>), ArgError> {
        let (preset, base, re) = match self.preset {
            Preset::Card => {
                let card = PhysicalPlate::card();
                (
                    Some("card".to_string()),
                    Some(card.props()),
                    Some(card.reynolds()),
                )
            }
            Preset::None => (None, None, None),
        };
        let pick = |flag: &'static str, given: Option<f64>, from: Option<f64>| {
            given.or(from).ok_or(ArgError::Missing {
                flag,
                when: "with --preset none",
            })
        };
        let props = PlateProps {
            mass: pick("--mass", self.mass, base.map(|b| b.mass))?,
            inertia: pick("--inertia", self.inertia, base.map(|b| b.inertia))?,
            gravity: pick("--gravity", self.gravity, base.map(|b| b.gravity))?,
        };
        let start = match self.ab_start {
            AbStartArg::Ramp => AbStart::Ramp,
            AbStartArg::Extrapolate => AbStart::Extrapolate,
        };
        Ok((
            BodyConfig {
                preset,
                props,
                ab_order: self.ab_order,
                ab_start: start,
            },
            re,
        ))
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
            a.solver.config(case, 5000.0, 80.0, None, None)
        }
        Command::Forced(a) => {
            let t_end = a.spinup + 6.0 * std::f64::consts::PI / a.rate.abs().max(1e-3);
            let case = Case::Forced {
                omega: a.rate,
                spinup: a.spinup,
            };
            a.solver.config(case, 5000.0, t_end.min(200.0), None, None)
        }
        Command::Pinned(a) => {
            let case = Case::Pinned {
                alpha0: a.alpha0,
                develop: a.body.develop,
            };
            coupled_config(&a.solver, &a.body, case, 60.0, a.body.turns)?
        }
        Command::Free(a) => {
            let case = Case::Free {
                v0: a.v0,
                gamma0: a.gamma0,
                alpha0: a.alpha0,
                develop: a.body.develop,
            };
            let turns = Some(a.body.turns.unwrap_or(10.0));
            coupled_config(&a.solver, &a.body, case, 80.0, turns)?
        }
        Command::Bench(_) => return Err(ArgError::NotACase("bench")),
    };
    cfg.validate()?;
    Ok(cfg)
}

/// A pinned or free run: the plate from its preset and overrides, Re from --re or the preset.
fn coupled_config(
    solver: &SolverArgs,
    body: &BodyArgs,
    case: Case,
    default_t_end: f64,
    turns: Option<f64>,
) -> Result<RunConfig, ArgError> {
    let (body, preset_re) = body.resolve()?;
    let re = solver.re.or(preset_re).ok_or(ArgError::Missing {
        flag: "--re",
        when: "with --preset none",
    })?;
    Ok(solver.config(case, re, default_t_end, Some(body), turns))
}
