//! The case subcommands' options and their translation into the library's [`RunBuilder`]s.
use std::path::PathBuf;

use clap::{Args, ValueEnum};

use super::end_time;
use super::flags::ArgError;
use super::plate_args::{BodyArgs, CoupledBuilder};
use super::record_args::RecordArgs;
use super::shape_args::ShapeArgs;
use super::span_arg::parse_span;
use platefall_core::config::EndTime;
use platefall_core::config::{defaults, RunBuilder};
use platefall_core::flow::FarFieldScheme;
use platefall_core::flow3d::Span;
use platefall_core::sim::{ReferenceScales, ValidatedConfig};
use platefall_core::sim3::{EXTENT3, GROWTH3};

/// Options shared by every case.
#[derive(Args, Debug, Clone)]
pub struct SolverArgs {
    /// Reynolds number U c / ν [default: 5000, or the preset's for pinned/free].
    #[arg(long, allow_negative_numbers = true)]
    pub re: Option<f64>,
    /// Cells per chord N (h = c/N), 4 to 1024 (2 to 1024 with --span). The dissertation used 16; the
    /// free-fall rotation rate changes by 17 % between N = 32 and 64 (docs/verification.md), so the
    /// default is 64.
    #[arg(long, default_value_t = defaults::RESOLUTION)]
    pub resolution: usize,
    /// End time from the impulsive start, in convective times c/U (60), or in seconds for a plate
    /// with physical units (10.5s) [default depends on the case].
    #[arg(long, allow_negative_numbers = true)]
    pub t_end: Option<EndTime>,
    /// Write the run summary as JSON to this file.
    #[arg(long, value_name = "FILE")]
    pub summary: Option<PathBuf>,
    /// Use the dissertation's exact grid and plate (N = 16, a rectangle 1/16 thick, 24 × 27 stretched
    /// intervals over 10 chords); overrides --resolution, --extent and --growth.
    #[arg(long, conflicts_with_all = ["thickness", "extent", "growth", "shape", "edge_radius", "polygon"])]
    pub seed_grid: bool,
    #[command(flatten)]
    pub section: ShapeArgs,
    /// Distance from the plate to the outer boundary, in chords (with --span: along every
    /// direction) [default: 15; with --span 8].
    #[arg(long, allow_negative_numbers = true)]
    pub extent: Option<f64>,
    /// Cap on the ratio of neighbouring cell sizes in the stretched region [default: 1.045;
    /// with --span 1.2].
    #[arg(long, allow_negative_numbers = true)]
    pub growth: Option<f64>,
    /// Run the flow in three dimensions around a plate of this span (static, forced, free): B
    /// (a finite span of B chords, free tips) or periodic:P (an infinite span, periodic over P
    /// chords). The CSV, summary and report hold the six coefficients; the recording shows the
    /// plate, its path, the vortex iso-surface and two vorticity slices [default:
    /// recordings/<case>-3d.rrd].
    #[arg(long, value_parser = parse_span)]
    pub span: Option<Span>,
    /// Courant number of the convective time-step limit (AB2 with the limited κ = 1/3 scheme was
    /// measured stable at 0.6 and unstable at 0.8).
    #[arg(long, default_value_t = defaults::CFL, allow_negative_numbers = true)]
    pub cfl: f64,
    /// Time-step ceiling (seed: 0.01).
    #[arg(long, default_value_t = defaults::DT_MAX, allow_negative_numbers = true)]
    pub dt_max: f64,
    /// The dissertation's rotation rule Δt·|θ̇| ≤ CC.
    #[arg(long, default_value_t = defaults::CC, allow_negative_numbers = true)]
    pub cc: f64,
    /// How the transport by the grid velocity is stepped outside the near field: `implicit`
    /// (line solves; Δt follows the near field), `explicit` (explicit everywhere, so Δt is bound
    /// by the far field's grid speed |θ̇| × extent), or `auto`: implicit for the turning plates
    /// (forced, pinned, free), explicit for a static plate (whose grid does not move, so the
    /// implicit step would only cost more).
    #[arg(long, value_enum, default_value_t = FarFieldArg::Auto)]
    pub far_field: FarFieldArg,
    /// Half-width of the near field along x (chords): columns farther out take the grid
    /// transport along them implicitly (with --far-field implicit).
    #[arg(long, default_value_t = defaults::NEAR, allow_negative_numbers = true)]
    pub near_x: f64,
    /// Half-height of the near field along y (chords): rows farther out take the grid transport
    /// along them implicitly.
    #[arg(long, default_value_t = defaults::NEAR, allow_negative_numbers = true)]
    pub near_y: f64,
    /// Worker threads for the run, 0 to 256 (0: one per core); the results do not depend on it.
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    #[command(flatten)]
    pub limits: super::limits::LimitArgs,
    #[command(flatten)]
    pub checkpoint: CheckpointArgs,
}

/// The checkpoint cadence when only `--checkpoint FILE` is given (convective times); its cost is
/// in docs/user-guide.md (well under 1 % of the run).
pub const DEFAULT_CHECKPOINT_EVERY: f64 = 10.0;

/// Checkpoints: `--checkpoint-every`, `--checkpoint` (also `platefall resume`'s).
#[derive(Args, Debug, Clone, Default)]
#[command(next_help_heading = "Checkpoints")]
pub struct CheckpointArgs {
    /// Write a checkpoint every T convective times, and at the end, that `platefall resume`
    /// continues exactly; SIGTERM, SIGUSR1 and the first Ctrl-C then also write one before the
    /// outputs are finalised (exit code 75)
    #[arg(long, value_name = "T", allow_negative_numbers = true)]
    pub checkpoint_every: Option<f64>,

    /// The checkpoint file [default: the CSV's, else the recording's, else the summary's path
    /// with the extension .ckpt, else <case>.ckpt]; alone it checkpoints every 10 c/U
    #[arg(long, value_name = "FILE")]
    pub checkpoint: Option<PathBuf>,

    /// Test hook: stop (as SIGTERM does) after this many steps in all
    #[arg(long, value_name = "N", hide = true)]
    pub stop_after_steps: Option<u64>,
}

impl CheckpointArgs {
    /// Whether checkpoints are asked for at all.
    pub fn enabled(&self) -> bool {
        self.checkpoint_every.is_some() || self.checkpoint.is_some()
    }

    /// The cadence, checked: finite and > 0; [`DEFAULT_CHECKPOINT_EVERY`] when only the file
    /// is given.
    pub fn every(&self) -> Result<Option<f64>, ArgError> {
        let given = self.given_every()?;
        Ok(given.or(self.checkpoint.as_ref().map(|_| DEFAULT_CHECKPOINT_EVERY)))
    }

    /// `--checkpoint-every` as given, checked: finite and > 0.
    pub fn given_every(&self) -> Result<Option<f64>, ArgError> {
        match self.checkpoint_every {
            Some(t) if !(t.is_finite() && t > 0.0) => Err(ArgError::Invalid {
                flag: "--checkpoint-every",
                value: t.to_string(),
                accepted: "a finite number > 0 (convective times)".into(),
            }),
            other => Ok(other),
        }
    }
}

/// `--far-field`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum FarFieldArg {
    Auto,
    Explicit,
    Implicit,
}

impl FarFieldArg {
    /// The scheme asked for; None for `auto` (the library's choice for the case: implicit unless
    /// the plate is static).
    pub fn scheme(self) -> Option<FarFieldScheme> {
        match self {
            FarFieldArg::Auto => None,
            FarFieldArg::Explicit => Some(FarFieldScheme::Explicit),
            FarFieldArg::Implicit => Some(FarFieldScheme::Implicit),
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
    #[arg(long, default_value_t = defaults::ALPHA, allow_negative_numbers = true)]
    pub alpha: f64,
    /// Symmetry-breaking pitch nudge ε (rad): θ = α + ε sin²(πt) during the first convective time.
    #[arg(long, default_value_t = defaults::KICK, allow_negative_numbers = true)]
    pub kick: f64,
    #[command(flatten)]
    pub solver: SolverArgs,
    #[command(flatten)]
    pub record: RecordArgs,
}

#[derive(Args, Debug)]
pub struct ForcedArgs {
    /// Final rotation rate θ̇ c/U (positive: counter-clockwise, nose up).
    #[arg(long, default_value_t = defaults::RATE, allow_negative_numbers = true)]
    pub rate: f64,
    /// Spin-up time from α = 0 to the final rate at constant angular acceleration.
    #[arg(long, default_value_t = defaults::SPINUP, allow_negative_numbers = true)]
    pub spinup: f64,
    #[command(flatten)]
    pub solver: SolverArgs,
    #[command(flatten)]
    pub record: RecordArgs,
}

#[derive(Args, Debug)]
pub struct PinnedArgs {
    /// Angle of attack α₀ (rad) held during development, then released.
    #[arg(long, default_value_t = defaults::ALPHA0, allow_negative_numbers = true)]
    pub alpha0: f64,
    /// Translation speed on the reference speed (the wind tunnel's; 0: a plate on a pin in still
    /// fluid, e.g. driven by --torque).
    #[arg(long, default_value_t = defaults::PINNED_SPEED, allow_negative_numbers = true)]
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
    #[arg(long, default_value_t = defaults::GAMMA0, allow_negative_numbers = true)]
    pub gamma0: f64,
    /// Launch angle of attack α₀ (rad); the plate is held at θ = γ₀ + α₀ until release.
    #[arg(long, default_value_t = defaults::ALPHA0, allow_negative_numbers = true)]
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
    /// `--extent`, or the default of a 2-D run or, with `--span`, of a 3-D one.
    pub fn extent(&self) -> f64 {
        let default = match self.span {
            Some(_) => EXTENT3,
            None => defaults::EXTENT,
        };
        self.extent.unwrap_or(default)
    }

    /// `--growth`, or the default of a 2-D run or, with `--span`, of a 3-D one.
    pub fn growth(&self) -> f64 {
        let default = match self.span {
            Some(_) => GROWTH3,
            None => defaults::GROWTH,
        };
        self.growth.unwrap_or(default)
    }

    /// Applies the solver options to a run of any case; `physical` is a physical plate's t/c,
    /// the section's thickness unless --thickness is given; `scales` the plate's physical units
    /// (an end time in seconds needs them).
    fn apply<C>(
        &self,
        mut b: RunBuilder<C>,
        physical: Option<f64>,
        scales: Option<ReferenceScales>,
    ) -> Result<RunBuilder<C>, ArgError> {
        b = b
            .resolution(self.resolution)
            .extent(self.extent())
            .growth(self.growth())
            .cfl(self.cfl)
            .dt_max(self.dt_max)
            .cc(self.cc)
            .near_field(self.near_x, self.near_y);
        b = if self.seed_grid {
            b.seed_grid()
        } else {
            b.shape(self.section.shape(physical)?)
        };
        if let Some(re) = self.re {
            b = b.re(re);
        }
        if let Some(scheme) = self.far_field.scheme() {
            b = b.far_field(scheme);
        }
        if let Some(t) = self.t_end {
            b = b.t_end(end_time::convective(t, scales)?);
        }
        Ok(b)
    }
}

impl StaticArgs {
    /// The validated run.
    pub fn config(&self) -> Result<ValidatedConfig, ArgError> {
        let b = RunBuilder::static_plate(self.alpha).kick(self.kick);
        Ok(self.solver.apply(b, None, None)?.build()?)
    }
}

impl ForcedArgs {
    /// The validated run.
    pub fn config(&self) -> Result<ValidatedConfig, ArgError> {
        let b = RunBuilder::forced(self.rate).spinup(self.spinup);
        Ok(self.solver.apply(b, None, None)?.build()?)
    }
}

impl PinnedArgs {
    /// The validated run.
    pub fn config(&self) -> Result<ValidatedConfig, ArgError> {
        let plate = self.body.plate()?;
        let (physical, scales) = (plate.thickness(), plate.scales());
        let b = RunBuilder::pinned(plate)
            .alpha0(self.alpha0)
            .speed(self.v0)
            .body_options(&self.body);
        Ok(self.solver.apply(b, physical, scales)?.build()?)
    }
}

impl FreeArgs {
    /// The validated run.
    pub fn config(&self) -> Result<ValidatedConfig, ArgError> {
        let plate = self.body.plate()?;
        let (physical, scales) = (plate.thickness(), plate.scales());
        let mut b = RunBuilder::free(plate)
            .gamma0(self.gamma0)
            .body_options(&self.body);
        b = match self.theta0 {
            Some(theta) => b.theta0(theta),
            None => b.alpha0(self.alpha0),
        };
        if let Some(v0) = self.v0 {
            b = b.v0(v0);
        }
        Ok(self.solver.apply(b, physical, scales)?.build()?)
    }
}
