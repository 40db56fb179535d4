//! The typed description of a run (grid, fluid, plate, motion law, time control), and its
//! validation (docs/physics.md §1–§6) into the [`ValidatedConfig`] that
//! [`Simulation::new`](super::Simulation::new) takes. The constructors that fill one in for each
//! case with the command line's defaults are in [`crate::config::RunBuilder`].
use std::f64::consts::PI;
use std::ops::Deref;

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::checks::check_phases;
use super::motion::Case;
use crate::body::{AbStart, Coupling, PlateProps};
use crate::flow::{check_representable, FlowParams};
use crate::grid::{Grid, GridSpec};
use crate::param::{check_range, check_whole, rounded, InputError, Param};
use crate::shape::Shape;

/// The physical scales behind a run's units (docs/physics.md §2): the chord c and the velocity scale U in SI
/// units. Reports use them to give results in physical units; the solver never reads them.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ReferenceScales {
    /// c (m).
    pub chord_m: f64,
    /// U (m/s).
    pub speed_m_s: f64,
}

/// Where a plate's non-dimensional properties come from.
///
/// In the configuration JSON it is the `preset` key: `"card"`, the physical plate's description,
/// or `null`.
#[derive(Clone, Debug, PartialEq)]
pub enum PlateSource {
    /// The dissertation's card preset (docs/physics.md §8), possibly with some values overridden.
    Card,
    /// A plate described physically; its one-line description (sizes, density, fluid).
    Physical(String),
    /// m*, I*, g* given directly.
    NonDimensional,
}

impl PlateSource {
    /// How the run's title names the plate.
    fn describe(&self, props: &PlateProps) -> String {
        match self {
            PlateSource::Card => "the card".into(),
            PlateSource::Physical(text) => text.clone(),
            PlateSource::NonDimensional => format!(
                "m* {}, I* {}, g* {}",
                rounded(props.mass),
                rounded(props.inertia),
                rounded(props.gravity)
            ),
        }
    }
}

impl Serialize for PlateSource {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            PlateSource::Card => s.serialize_some("card"),
            PlateSource::Physical(text) => s.serialize_some(text),
            PlateSource::NonDimensional => s.serialize_none(),
        }
    }
}

impl<'de> Deserialize<'de> for PlateSource {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Ok(match Option::<String>::deserialize(d)? {
            None => PlateSource::NonDimensional,
            Some(text) if text == "card" => PlateSource::Card,
            Some(text) => PlateSource::Physical(text),
        })
    }
}

/// The plate's inertia and gravity (coupled cases), with where they came from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BodyConfig {
    /// Where the values come from (the JSON key is `preset`, as the command line's option).
    #[serde(rename = "preset")]
    pub source: PlateSource,
    /// The physical chord and velocity scale, when the plate has them.
    #[serde(default)]
    pub scales: Option<ReferenceScales>,
    /// m*, I*, g*, m_f* and the applied moment.
    pub props: PlateProps,
    /// Adams–Bashforth order (1..=6) of the plate's equations (docs/physics.md §6).
    pub ab_order: usize,
    /// How the Adams–Bashforth history is started at release.
    pub ab_start: AbStart,
    /// How the flow's loads enter the body's equations (docs/physics.md §6; default strong).
    #[serde(default)]
    pub coupling: Coupling,
}

/// When a run ends and how its time step is bounded (docs/physics.md §6 "Time step").
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TimeControl {
    /// End time in convective times c/U from the impulsive start (development included).
    pub t_end: f64,
    /// Stop after this many net turns of θ after release (coupled cases), if reached before t_end.
    pub turns: Option<f64>,
    /// Time-step ceiling (seed: 0.01).
    pub dt_max: f64,
    /// The dissertation's rotation rule Δt·|θ̇| ≤ C_c (seed: 0.005).
    pub cc: f64,
    /// A coupled run's summary averages over the whole turns from this complete turn after
    /// release on (1: from the first; docs/physics.md §7). Read by post-processing only.
    #[serde(default = "first_turn")]
    pub average_from_turn: usize,
}

/// The default of [`TimeControl::average_from_turn`].
fn first_turn() -> usize {
    1
}

impl Default for TimeControl {
    /// 80 convective times, no turn limit, the dissertation's ceiling Δt ≤ 0.01 and rotation rule 0.005.
    fn default() -> Self {
        TimeControl {
            t_end: 80.0,
            turns: None,
            dt_max: 0.01,
            cc: 0.005,
            average_from_turn: first_turn(),
        }
    }
}

/// Everything that defines a run; serialised into the recording and the summary.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunConfig {
    /// The motion law (docs/physics.md §1).
    pub case: Case,
    /// The body-fixed grid and the plate's thickness on it (docs/physics.md §4).
    pub grid: GridSpec,
    /// The fluid (Re) and the flow solver's numerical parameters.
    pub flow: FlowParams,
    /// The plate's properties (coupled cases only).
    pub body: Option<BodyConfig>,
    /// When the run ends and how its time step is bounded.
    pub time: TimeControl,
}

/// [`TimeControl::average_from_turn`]: a whole number of turns, and below the turn limit so that
/// at least one whole turn follows it.
fn check_average_from_turn(t: &TimeControl) -> Result<(), InputError> {
    let k = t.average_from_turn;
    let most = t
        .turns
        .map_or(10_000, |n| (n.ceil() as usize).saturating_sub(1).max(1));
    check_whole(Param::AverageFromTurn, k, 1, most)
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

    /// Validates every value (the first bad one is reported) and builds the grid: the run
    /// description [`Simulation::new`](super::Simulation::new) takes.
    ///
    /// # Errors
    /// [`InputError`] for the first value out of its range or inconsistent with the others (the
    /// grid, the flow parameters, the times, the case and the plate), or a grid that cannot be built.
    pub fn validate(self) -> Result<ValidatedConfig, InputError> {
        self.check()?;
        let grid = Grid::new(&self.grid)?;
        Ok(ValidatedConfig { config: self, grid })
    }

    /// Checks every value; the first bad one is reported.
    fn check(&self) -> Result<(), InputError> {
        self.grid.validate()?;
        check_representable(&self.grid)?;
        self.flow.validate()?;
        let t = &self.time;
        check_range(Param::TEnd, t.t_end, 0.0, 1e5, true)?;
        check_range(Param::DtMax, t.dt_max, 0.0, 1.0, true)?;
        check_range(Param::Cc, t.cc, 0.0, 1.0, true)?;
        if let Some(n) = t.turns {
            check_range(Param::Turns, n, 0.0, 1e4, true)?;
        }
        check_average_from_turn(t)?;
        self.validate_case()?;
        check_phases(&self.case, t.t_end)?;
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

    /// A one-line description of the run: what defines it (the case and its parameters, the
    /// plate and fluid of a coupled case), the Reynolds number and the resolution, with numbers
    /// rounded to four significant digits.
    pub fn title(&self) -> String {
        // A rectangle is the plate of every case unless said otherwise; other sections are named.
        let section = match &self.grid.shape {
            Shape::Rect { .. } => None,
            shape => Some(shape.describe()),
        };
        self.title_naming(section)
    }

    /// The title with `body` named after the case (none: the plate, unnamed).
    pub fn title_naming(&self, body: Option<String>) -> String {
        let r = |x: f64| rounded(x);
        let case = match self.case {
            Case::Static { alpha, .. } => format!("static plate at α = {} rad", r(alpha)),
            Case::Forced { omega, spinup } => {
                format!(
                    "forced rotation to θ̇ = {} over a spin-up of {}",
                    r(omega),
                    r(spinup)
                )
            }
            Case::Pinned {
                alpha0, speed: 0.0, ..
            } => {
                format!(
                    "pinned plate in still fluid, released at θ₀ = {} rad",
                    r(alpha0)
                )
            }
            Case::Pinned { alpha0, speed, .. } => format!(
                "pinned autorotation at speed {}, released at α₀ = {} rad",
                r(speed),
                r(alpha0)
            ),
            Case::Free {
                v0: 0.0,
                gamma0,
                alpha0,
                ..
            } => format!("free fall from rest at θ₀ = {} rad", r(gamma0 + alpha0)),
            Case::Free {
                v0, gamma0, alpha0, ..
            } => format!(
                "free fall launched at V₀ = {}, γ₀ = {} rad, α₀ = {} rad",
                r(v0),
                r(gamma0),
                r(alpha0)
            ),
        };
        let plate = match &self.body {
            Some(b) if self.case.is_coupled() => format!(", {}", b.source.describe(&b.props)),
            _ => String::new(),
        };
        let section = body.map_or(String::new(), |b| format!(", {b}"));
        format!(
            "{case}{section}{plate}, Re {}, N = {}",
            r(self.flow.re),
            self.grid.resolution
        )
    }
}

/// A run description whose every value has been checked, with the grid it defines (built once,
/// here): what [`Simulation::new`](super::Simulation::new) takes. Made by
/// [`RunConfig::validate`] (or [`crate::config::RunBuilder::build`]); it dereferences to the
/// [`RunConfig`].
#[derive(Clone, Debug)]
pub struct ValidatedConfig {
    config: RunConfig,
    grid: Grid,
}

impl ValidatedConfig {
    /// The run description.
    pub fn config(&self) -> &RunConfig {
        &self.config
    }

    /// The body-fixed grid of the run.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// The description and the grid, taken apart.
    pub fn into_parts(self) -> (RunConfig, Grid) {
        (self.config, self.grid)
    }
}

impl Deref for ValidatedConfig {
    type Target = RunConfig;
    fn deref(&self) -> &RunConfig {
        &self.config
    }
}

impl Serialize for ValidatedConfig {
    /// As its [`RunConfig`].
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.config.serialize(s)
    }
}
