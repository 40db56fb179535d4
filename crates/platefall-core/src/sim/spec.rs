//! The typed description of a run (grid, fluid, plate, motion law, time control) that
//! [`Simulation::new`](super::Simulation::new) builds from, and its validation (SPEC §1–§6).
use std::f64::consts::PI;

use serde::{Deserialize, Serialize};

use super::motion::Case;
use crate::body::{AbStart, Coupling, PlateProps};
use crate::flow::FlowParams;
use crate::grid::GridSpec;
use crate::param::{check_range, check_whole, InputError, Param};

/// The physical scales behind a run's units (SPEC §2): the chord c and the velocity scale U in SI
/// units. Reports use them to give results in physical units; the solver never reads them.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ReferenceScales {
    /// c (m).
    pub chord_m: f64,
    /// U (m/s).
    pub speed_m_s: f64,
}

/// The plate's inertia and gravity (coupled cases), with where they came from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BodyConfig {
    /// "card" when the values come from the seed's card preset (possibly overridden); a short
    /// description of a physically described plate otherwise.
    pub preset: Option<String>,
    /// The physical chord and velocity scale, when the plate has them.
    #[serde(default)]
    pub scales: Option<ReferenceScales>,
    pub props: PlateProps,
    /// Adams–Bashforth order (1..=6) and start procedure (SPEC §6).
    pub ab_order: usize,
    pub ab_start: AbStart,
    /// How the flow's loads enter the body's equations (SPEC §6; default strong).
    #[serde(default)]
    pub coupling: Coupling,
}

/// When a run ends and how its time step is bounded (SPEC §6 "Time step").
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TimeControl {
    /// End time in convective times c/U from the impulsive start (development included).
    pub t_end: f64,
    /// Stop after this many net turns of θ after release (coupled cases), if reached before t_end.
    pub turns: Option<f64>,
    /// Time-step ceiling (seed: 0.01).
    pub dt_max: f64,
    /// The seed's rotation rule Δt·|θ̇| ≤ C_c (seed: 0.005).
    pub cc: f64,
}

impl Default for TimeControl {
    /// 80 convective times, no turn limit, the seed's ceiling Δt ≤ 0.01 and rotation rule 0.005.
    fn default() -> Self {
        TimeControl {
            t_end: 80.0,
            turns: None,
            dt_max: 0.01,
            cc: 0.005,
        }
    }
}

/// Everything that defines a run; serialised into the recording and the summary.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunConfig {
    /// The motion law (SPEC §1).
    pub case: Case,
    pub grid: GridSpec,
    /// The fluid (Re) and the flow solver's numerical parameters.
    pub flow: FlowParams,
    /// The plate's properties (coupled cases only).
    pub body: Option<BodyConfig>,
    pub time: TimeControl,
}

impl RunConfig {
    /// A prescribed-motion run (static or forced) on `grid` with the default fluid (Re 5000) and
    /// numerics and the default [`TimeControl`]; set `body` for a coupled case.
    pub fn new(case: Case, grid: GridSpec) -> RunConfig {
        RunConfig {
            case,
            grid,
            flow: FlowParams::default(),
            body: None,
            time: TimeControl::default(),
        }
    }

    /// Validates every value; the first bad one is reported.
    pub fn validate(&self) -> Result<(), InputError> {
        self.grid.validate()?;
        self.grid.check_representable()?;
        self.flow.validate()?;
        let t = &self.time;
        check_range(Param::TEnd, t.t_end, 0.0, 1e5, true)?;
        check_range(Param::DtMax, t.dt_max, 0.0, 1.0, true)?;
        check_range(Param::Cc, t.cc, 0.0, 1.0, true)?;
        if let Some(n) = t.turns {
            check_range(Param::Turns, n, 0.0, 1e4, true)?;
        }
        self.validate_case()?;
        super::checks::check_phases(self)?;
        if self.case.is_coupled() {
            let b = self.body.as_ref().ok_or(InputError::MissingPlate)?;
            check_range(Param::Mass, b.props.mass, 0.0, 1e6, true)?;
            check_range(Param::Inertia, b.props.inertia, 0.0, 1e6, true)?;
            check_range(Param::Gravity, b.props.gravity, 0.0, 1e9, false)?;
            check_range(Param::DisplacedMass, b.props.displaced, 0.0, 1e6, false)?;
            check_range(Param::Torque, b.props.torque, -1e3, 1e3, false)?;
            check_whole(Param::AbOrder, b.ab_order, 1, 6)?;
        }
        Ok(())
    }

    fn validate_case(&self) -> Result<(), InputError> {
        match self.case {
            Case::Static { alpha, kick } => {
                check_range(Param::Alpha, alpha, -PI, PI, false)?;
                check_range(Param::Kick, kick.abs(), 0.0, 0.2, false)
            }
            Case::Forced { omega, spinup } => {
                check_range(Param::ForcedOmega, omega.abs(), 0.0, 20.0, true)?;
                check_range(Param::Spinup, spinup, 0.0, 1e3, false)
            }
            Case::Pinned {
                alpha0,
                develop,
                speed,
            } => {
                check_range(Param::Alpha0, alpha0, -PI, PI, false)?;
                check_range(Param::Develop, develop, 0.0, 1e3, false)?;
                check_range(Param::V0, speed, 0.0, 10.0, false)
            }
            Case::Free {
                v0,
                gamma0,
                alpha0,
                develop,
            } => {
                check_range(Param::V0, v0, 0.0, 10.0, false)?;
                check_range(Param::Gamma0, gamma0, -PI, PI, false)?;
                check_range(Param::Alpha0, alpha0, -PI, PI, false)?;
                check_range(Param::Develop, develop, 0.0, 1e3, false)
            }
        }
    }

    /// A one-line description of the run.
    pub fn title(&self) -> String {
        let case = match &self.case {
            Case::Static { alpha, .. } => format!("static plate, α = {alpha:.4} rad"),
            Case::Forced { omega, spinup } => {
                format!("forced rotation, θ̇ = {omega}, spin-up {spinup}")
            }
            Case::Pinned { alpha0, .. } => {
                format!("pinned autorotation, released at α₀ = {alpha0}")
            }
            Case::Free {
                v0, gamma0, alpha0, ..
            } => {
                format!("free fall, V₀ = {v0}, γ₀ = {gamma0:.4}, α₀ = {alpha0}")
            }
        };
        let preset = self
            .body
            .as_ref()
            .and_then(|b| b.preset.as_deref())
            .map(|p| match p {
                "card" => ", card preset".to_string(),
                other => format!(", {other}"),
            })
            .unwrap_or_default();
        format!(
            "{case}{preset}, Re {:.0}, N = {}",
            self.flow.re, self.grid.resolution
        )
    }
}
