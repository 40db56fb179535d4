//! Runs built by the library: one constructor per case (docs/physics.md §1), options as builder methods, and
//! [`RunBuilder::build`] validating everything into the [`ValidatedConfig`] that
//! [`Simulation::new`](crate::sim::Simulation::new) takes. The defaults are the command line's
//! (the CLI shows the constants of [`defaults`] in its help), so a builder with no options runs
//! exactly what the subcommand with no options runs:
//!
//! ```
//! use platefall_core::config::{Plate, RunBuilder};
//! // `platefall free --resolution 16 --turns 2`
//! let free = RunBuilder::free(Plate::card()).resolution(16).turns(2.0).build()?;
//! assert_eq!(free.flow.re.round(), 4770.0);
//! // `platefall static --alpha 0.3 --kick 0 --t-end 5`
//! let fixed = RunBuilder::static_plate(0.3).kick(0.0).t_end(5.0).build()?;
//! assert_eq!(fixed.time.t_end, 5.0);
//! # Ok::<(), platefall_core::param::InputError>(())
//! ```
//!
//! What depends on the case is worked out in `build`: the end time (static 80, forced spin-up +
//! three turns at most 200, pinned 60, free 80), the Reynolds number (5000, or the plate's), the
//! far-field scheme (explicit for a static plate, implicit for a turning one), the development
//! time (5, or 0 for a plate starting from rest), a free fall's launch speed (1, or 0 for a plate
//! described physically) and turn limit (10), and the plate's section (a rectangle 1/64 thick, or
//! a physical plate's own thickness; a physical plate's m*, m_f* and I* are then its section's).
use std::f64::consts::PI;

use super::plate::Plate;
use crate::body::{AbStart, Coupling, PlateProps};
use crate::flow::{FarFieldScheme, FlowParams};
use crate::grid::{GridSpec, Stretch};
use crate::param::{InputError, Param};
use crate::shape::Shape;
use crate::sim::{BodyConfig, Case, RunConfig, TimeControl, ValidatedConfig};

/// The defaults of every option (the command line shows them in its help).
pub mod defaults {
    /// Cells per chord N.
    pub const RESOLUTION: usize = 64;
    /// The thickness t/c of the default section, a rectangle (exact at every resolution).
    pub const THICKNESS: f64 = 1.0 / 64.0;
    /// Distance from the plate to the outer boundary (chords).
    pub const EXTENT: f64 = 15.0;
    /// Cap on the ratio of neighbouring cell sizes.
    pub const GROWTH: f64 = 1.045;
    /// Courant number of the convective limit.
    pub const CFL: f64 = 0.5;
    /// Time-step ceiling (the dissertation's).
    pub const DT_MAX: f64 = 0.01;
    /// The dissertation's rotation rule Δt·|θ̇| ≤ C_c.
    pub const CC: f64 = 0.005;
    /// Near-field half-width and half-height (chords).
    pub const NEAR: f64 = crate::flow::NEAR_DEFAULT;
    /// Reynolds number of the prescribed cases (and of a coupled one whose plate implies none).
    pub const REYNOLDS: f64 = 5000.0;
    /// Static: angle of attack α (rad).
    pub const ALPHA: f64 = 0.4;
    /// Static: the start-up pitch nudge ε (rad).
    pub const KICK: f64 = 0.05;
    /// Forced: the final rotation rate θ̇.
    pub const RATE: f64 = 1.0;
    /// Forced: the spin-up time.
    pub const SPINUP: f64 = 1.0;
    /// Pinned and free: the angle of attack held until release (rad).
    pub const ALPHA0: f64 = 0.1;
    /// Pinned: the translation speed (the wind tunnel's).
    pub const PINNED_SPEED: f64 = 1.0;
    /// Free: the launch flight-path angle γ₀ (rad; down and to the right).
    pub const GAMMA0: f64 = -std::f64::consts::FRAC_PI_4;
    /// Free: the launch speed of a plate given non-dimensionally or by the card preset.
    pub const V0: f64 = 1.0;
    /// Pinned and free: the development time before release of a plate launched at speed.
    pub const DEVELOP: f64 = 5.0;
    /// Free: the net turns after release that end the run.
    pub const FREE_TURNS: f64 = 10.0;
    /// Adams–Bashforth order of the plate's equations.
    pub const AB_ORDER: usize = 2;
    /// End times (convective times) of the static, pinned and free cases.
    pub const T_END_STATIC: f64 = 80.0;
    /// See [`T_END_STATIC`].
    pub const T_END_PINNED: f64 = 60.0;
    /// See [`T_END_STATIC`].
    pub const T_END_FREE: f64 = 80.0;
    /// A forced run ends three turns after its spin-up, at most at this time.
    pub const T_END_FORCED_MAX: f64 = 200.0;
}

/// How the grid is given.
#[derive(Clone, Debug, PartialEq)]
enum GridChoice {
    /// The modern stretched grid ([`GridSpec::modern`]) with these settings; section `None`:
    /// a rectangle of the physical plate's thickness, or [`defaults::THICKNESS`].
    Modern {
        resolution: usize,
        section: Option<Section>,
        extent: f64,
        growth: f64,
    },
    /// The dissertation's exact grid and plate ([`GridSpec::seed`]).
    Seed,
}

/// The plate's section, as given.
#[derive(Clone, Debug, PartialEq)]
enum Section {
    /// A rectangle of this thickness.
    Thickness(f64),
    /// Any section.
    Shape(Shape),
}

/// The options every case has.
#[derive(Clone, Debug, PartialEq)]
struct Options {
    grid: GridChoice,
    re: Option<f64>,
    cfl: f64,
    dt_max: f64,
    cc: f64,
    far_field: Option<FarFieldScheme>,
    near_x: f64,
    near_y: f64,
    t_end: Option<f64>,
    /// The first grid option given after `seed_grid()`, refused by `build`.
    after_seed: Option<&'static str>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            grid: GridChoice::Modern {
                resolution: defaults::RESOLUTION,
                section: None,
                extent: defaults::EXTENT,
                growth: defaults::GROWTH,
            },
            re: None,
            cfl: defaults::CFL,
            dt_max: defaults::DT_MAX,
            cc: defaults::CC,
            far_field: None,
            near_x: defaults::NEAR,
            near_y: defaults::NEAR,
            t_end: None,
            after_seed: None,
        }
    }
}

/// Case A's parameters ([`RunBuilder::static_plate`]).
#[derive(Clone, Debug, PartialEq)]
pub struct StaticPlate {
    alpha: f64,
    kick: f64,
}

/// Case B's parameters ([`RunBuilder::forced`]).
#[derive(Clone, Debug, PartialEq)]
pub struct ForcedRotation {
    rate: f64,
    spinup: f64,
}

/// The body options of a coupled case.
#[derive(Clone, Debug, PartialEq)]
struct BodyOptions {
    plate: Plate,
    coupling: Coupling,
    ab_order: usize,
    ab_start: AbStart,
    develop: Option<f64>,
    turns: Option<f64>,
    average_from_turn: usize,
}

impl BodyOptions {
    fn new(plate: Plate, turns: Option<f64>) -> Self {
        BodyOptions {
            plate,
            coupling: Coupling::Strong,
            ab_order: defaults::AB_ORDER,
            ab_start: AbStart::Ramp,
            develop: None,
            turns,
            average_from_turn: 1,
        }
    }

    /// The development time: as given, else [`defaults::DEVELOP`] for a launch at speed and 0
    /// from rest.
    fn develop_for(&self, speed: f64) -> f64 {
        self.develop
            .unwrap_or(if speed == 0.0 { 0.0 } else { defaults::DEVELOP })
    }

    fn config(&self) -> BodyConfig {
        BodyConfig {
            source: self.plate.source().clone(),
            scales: self.plate.scales(),
            props: *self.plate.props(),
            ab_order: self.ab_order,
            ab_start: self.ab_start,
            coupling: self.coupling,
        }
    }
}

/// Case C's parameters ([`RunBuilder::pinned`]).
#[derive(Clone, Debug, PartialEq)]
pub struct PinnedPlate {
    alpha0: f64,
    speed: f64,
    body: BodyOptions,
}

/// How a free fall's attitude at launch is given.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Attitude {
    /// The angle of attack α₀.
    Alpha0(f64),
    /// The pitch angle θ₀ = γ₀ + α₀.
    Theta0(f64),
}

/// Case D's parameters ([`RunBuilder::free`]).
#[derive(Clone, Debug, PartialEq)]
pub struct FreeFall {
    v0: Option<f64>,
    gamma0: f64,
    attitude: Attitude,
    body: BodyOptions,
}

/// A run being described: its case (`C`, one of [`StaticPlate`], [`ForcedRotation`],
/// [`PinnedPlate`], [`FreeFall`]) and options; see the module docs.
#[derive(Clone, Debug, PartialEq)]
pub struct RunBuilder<C> {
    case: C,
    options: Options,
}

impl RunBuilder<StaticPlate> {
    /// Case A: a plate translating at U at the fixed angle of attack `alpha` (rad).
    pub fn static_plate(alpha: f64) -> Self {
        RunBuilder::with_case(StaticPlate {
            alpha,
            kick: defaults::KICK,
        })
    }

    /// The symmetry-breaking pitch nudge ε of the first convective time (rad).
    #[must_use]
    pub fn kick(mut self, kick: f64) -> Self {
        self.case.kick = kick;
        self
    }

    /// Validates the description into a run.
    ///
    /// # Errors
    /// [`InputError::Conflict`] for a grid option given after `seed_grid`, and any [`InputError`] of
    /// [`RunConfig::validate`](crate::sim::RunConfig::validate) for a value out of its range or
    /// inconsistent with the others.
    pub fn build(self) -> Result<ValidatedConfig, InputError> {
        let StaticPlate { alpha, kick } = self.case;
        let case = Case::Static { alpha, kick };
        let t_end = defaults::T_END_STATIC;
        self.options
            .checked()?
            .config(case, defaults::REYNOLDS, t_end, None, None, None)
            .validate()
    }
}

impl RunBuilder<ForcedRotation> {
    /// Case B: a plate translating at U, spun up from α = 0 at constant angular acceleration to
    /// the rate θ̇ = `rate`, then held.
    pub fn forced(rate: f64) -> Self {
        RunBuilder::with_case(ForcedRotation {
            rate,
            spinup: defaults::SPINUP,
        })
    }

    /// The spin-up time.
    #[must_use]
    pub fn spinup(mut self, spinup: f64) -> Self {
        self.case.spinup = spinup;
        self
    }

    /// Validates the description into a run.
    ///
    /// # Errors
    /// [`InputError::Conflict`] for a grid option given after `seed_grid`, and any [`InputError`] of
    /// [`RunConfig::validate`](crate::sim::RunConfig::validate) for a value out of its range or
    /// inconsistent with the others.
    pub fn build(self) -> Result<ValidatedConfig, InputError> {
        let ForcedRotation { rate, spinup } = self.case;
        let three_turns = spinup + 6.0 * PI / rate.abs().max(1e-3);
        let t_end = three_turns.min(defaults::T_END_FORCED_MAX);
        let case = Case::Forced {
            omega: rate,
            spinup,
        };
        self.options
            .checked()?
            .config(case, defaults::REYNOLDS, t_end, None, None, None)
            .validate()
    }
}

impl RunBuilder<PinnedPlate> {
    /// Case C: `plate` translating at U, held at α₀ while the flow develops, then free to rotate
    /// about its centre.
    pub fn pinned(plate: Plate) -> Self {
        RunBuilder::with_case(PinnedPlate {
            alpha0: defaults::ALPHA0,
            speed: defaults::PINNED_SPEED,
            body: BodyOptions::new(plate, None),
        })
    }

    /// The angle of attack held until release (rad).
    #[must_use]
    pub fn alpha0(mut self, alpha0: f64) -> Self {
        self.case.alpha0 = alpha0;
        self
    }

    /// The translation speed on the reference speed (0: a pin in still fluid).
    #[must_use]
    pub fn speed(mut self, speed: f64) -> Self {
        self.case.speed = speed;
        self
    }

    /// Validates the description into a run.
    ///
    /// # Errors
    /// [`InputError::Conflict`] for a grid option given after `seed_grid`, and any [`InputError`] of
    /// [`RunConfig::validate`](crate::sim::RunConfig::validate) for a value out of its range or
    /// inconsistent with the others.
    pub fn build(self) -> Result<ValidatedConfig, InputError> {
        let PinnedPlate {
            alpha0,
            speed,
            body,
        } = self.case;
        let case = Case::Pinned {
            alpha0,
            develop: body.develop_for(speed),
            speed,
        };
        self.options.coupled(case, &body, defaults::T_END_PINNED)
    }
}

impl RunBuilder<FreeFall> {
    /// Case D: `plate` launched at V₀ along γ₀ at α₀, held there while the flow develops, then
    /// falling freely.
    pub fn free(plate: Plate) -> Self {
        RunBuilder::with_case(FreeFall {
            v0: None,
            gamma0: defaults::GAMMA0,
            attitude: Attitude::Alpha0(defaults::ALPHA0),
            body: BodyOptions::new(plate, Some(defaults::FREE_TURNS)),
        })
    }

    /// The launch speed V₀ on the reference speed (0: released from rest) [default: 1, or 0 for
    /// a plate described physically].
    #[must_use]
    pub fn v0(mut self, v0: f64) -> Self {
        self.case.v0 = Some(v0);
        self
    }

    /// The launch flight-path angle γ₀ (rad).
    #[must_use]
    pub fn gamma0(mut self, gamma0: f64) -> Self {
        self.case.gamma0 = gamma0;
        self
    }

    /// The launch angle of attack α₀ (rad); the plate is held at θ = γ₀ + α₀ until release.
    #[must_use]
    pub fn alpha0(mut self, alpha0: f64) -> Self {
        self.case.attitude = Attitude::Alpha0(alpha0);
        self
    }

    /// The pitch angle θ₀ at release (rad), instead of α₀.
    #[must_use]
    pub fn theta0(mut self, theta0: f64) -> Self {
        self.case.attitude = Attitude::Theta0(theta0);
        self
    }

    /// Validates the description into a run.
    ///
    /// # Errors
    /// [`InputError::Conflict`] for a grid option given after `seed_grid`, and any [`InputError`] of
    /// [`RunConfig::validate`](crate::sim::RunConfig::validate) for a value out of its range or
    /// inconsistent with the others.
    pub fn build(self) -> Result<ValidatedConfig, InputError> {
        let FreeFall {
            v0,
            gamma0,
            attitude,
            body,
        } = self.case;
        let v0 = v0.unwrap_or(if body.plate.is_physical() {
            0.0
        } else {
            defaults::V0
        });
        let alpha0 = match attitude {
            Attitude::Alpha0(a) => a,
            Attitude::Theta0(theta) => theta - gamma0,
        };
        let case = Case::Free {
            v0,
            gamma0,
            alpha0,
            develop: body.develop_for(v0),
        };
        self.options.coupled(case, &body, defaults::T_END_FREE)
    }
}

/// The options of the coupled cases.
macro_rules! coupled_options {
    ($case:ty) => {
        impl RunBuilder<$case> {
            /// Hold the plate at its launch attitude for this long before release [default: 5,
            /// or 0 when it starts from rest].
            #[must_use]
            pub fn develop(mut self, develop: f64) -> Self {
                self.case.body.develop = Some(develop);
                self
            }

            /// Stop after this many net turns after release (or at the end time, whichever
            /// comes first) [default: 10 for a free fall, none for a pinned plate].
            #[must_use]
            pub fn turns(mut self, turns: f64) -> Self {
                self.case.body.turns = Some(turns);
                self
            }

            /// Average the summary over the whole turns from this complete turn after release on,
            /// leaving the earlier ones to the transient [default: 1].
            #[must_use]
            pub fn average_from_turn(mut self, turn: usize) -> Self {
                self.case.body.average_from_turn = turn;
                self
            }

            /// Run to the end time whatever the plate's turns.
            #[must_use]
            pub fn without_turn_limit(mut self) -> Self {
                self.case.body.turns = None;
                self
            }

            /// How the flow's loads enter the plate's equations [default: strong].
            #[must_use]
            pub fn coupling(mut self, coupling: Coupling) -> Self {
                self.case.body.coupling = coupling;
                self
            }

            /// The Adams–Bashforth order of the plate's equations (1..=6) [default: 2].
            #[must_use]
            pub fn ab_order(mut self, order: usize) -> Self {
                self.case.body.ab_order = order;
                self
            }

            /// How the Adams–Bashforth history is started at release [default: ramp].
            #[must_use]
            pub fn ab_start(mut self, start: AbStart) -> Self {
                self.case.body.ab_start = start;
                self
            }
        }
    };
}
coupled_options!(PinnedPlate);
coupled_options!(FreeFall);

impl<C> RunBuilder<C> {
    fn with_case(case: C) -> Self {
        RunBuilder {
            case,
            options: Options::default(),
        }
    }

    /// Cells per chord N (h = c/N) [default: 64].
    #[must_use]
    pub fn resolution(mut self, resolution: usize) -> Self {
        match &mut self.options.grid {
            GridChoice::Modern { resolution: n, .. } => *n = resolution,
            GridChoice::Seed => self.options.refuse_after_seed("resolution"),
        }
        self
    }

    /// A rectangular section of this thickness t/c, exact at every resolution [default: 1/64, or
    /// a physical plate's own].
    #[must_use]
    pub fn thickness(mut self, thickness: f64) -> Self {
        match &mut self.options.grid {
            GridChoice::Modern { section, .. } => *section = Some(Section::Thickness(thickness)),
            GridChoice::Seed => self.options.refuse_after_seed("thickness"),
        }
        self
    }

    /// The plate's section (rectangle, rounded, ellipse, NACA, polygon) [default: a rectangle
    /// 1/64 thick, or of a physical plate's thickness].
    #[must_use]
    pub fn shape(mut self, shape: Shape) -> Self {
        match &mut self.options.grid {
            GridChoice::Modern { section, .. } => *section = Some(Section::Shape(shape)),
            GridChoice::Seed => self.options.refuse_after_seed("shape"),
        }
        self
    }

    /// Distance from the plate to the outer boundary, in chords [default: 15].
    #[must_use]
    pub fn extent(mut self, extent: f64) -> Self {
        match &mut self.options.grid {
            GridChoice::Modern { extent: e, .. } => *e = extent,
            GridChoice::Seed => self.options.refuse_after_seed("extent"),
        }
        self
    }

    /// Cap on the ratio of neighbouring cell sizes in the stretched region [default: 1.045].
    #[must_use]
    pub fn growth(mut self, growth: f64) -> Self {
        match &mut self.options.grid {
            GridChoice::Modern { growth: g, .. } => *g = growth,
            GridChoice::Seed => self.options.refuse_after_seed("growth"),
        }
        self
    }

    /// The dissertation's exact grid and plate (N = 16, a rectangle 1/16 thick, 24 × 27 stretched
    /// intervals over 10 chords), instead of the resolution, section, extent and growth cap
    /// given before it; `build` refuses any of those given after it
    /// ([`InputError::Conflict`]).
    #[must_use]
    pub fn seed_grid(mut self) -> Self {
        self.options.grid = GridChoice::Seed;
        self
    }

    /// The Reynolds number U c/ν [default: 5000, or the plate's].
    #[must_use]
    pub fn re(mut self, re: f64) -> Self {
        self.options.re = Some(re);
        self
    }

    /// The Courant number of the convective time-step limit [default: 0.5].
    #[must_use]
    pub fn cfl(mut self, cfl: f64) -> Self {
        self.options.cfl = cfl;
        self
    }

    /// The time-step ceiling [default: 0.01].
    #[must_use]
    pub fn dt_max(mut self, dt_max: f64) -> Self {
        self.options.dt_max = dt_max;
        self
    }

    /// The dissertation's rotation rule Δt·|θ̇| ≤ C_c [default: 0.005].
    #[must_use]
    pub fn cc(mut self, cc: f64) -> Self {
        self.options.cc = cc;
        self
    }

    /// How the grid transport is stepped outside the near field [default: explicit for a static
    /// plate, implicit for a turning one].
    #[must_use]
    pub fn far_field(mut self, scheme: FarFieldScheme) -> Self {
        self.options.far_field = Some(scheme);
        self
    }

    /// Half-width and half-height of the near field (chords) [default: 1, 1].
    #[must_use]
    pub fn near_field(mut self, near_x: f64, near_y: f64) -> Self {
        self.options.near_x = near_x;
        self.options.near_y = near_y;
        self
    }

    /// The end time in convective times c/U from the impulsive start [default depends on the
    /// case; see the module docs].
    #[must_use]
    pub fn t_end(mut self, t_end: f64) -> Self {
        self.options.t_end = Some(t_end);
        self
    }
}

impl Options {
    /// Notes a grid option given after `seed_grid()` (the first one is reported).
    fn refuse_after_seed(&mut self, option: &'static str) {
        self.after_seed.get_or_insert(option);
    }

    /// The options, unless one contradicts another.
    fn checked(self) -> Result<Self, InputError> {
        match self.after_seed {
            Some(option) => Err(InputError::Conflict {
                option,
                earlier: "seed_grid",
                why: "the dissertation's grid fixes the resolution, the section, the extent and \
                      the growth",
            }),
            None => Ok(self),
        }
    }

    /// A pinned or free run: the plate's Reynolds number unless one is given, its thickness
    /// unless one is given.
    fn coupled(
        self,
        case: Case,
        body: &BodyOptions,
        default_t_end: f64,
    ) -> Result<ValidatedConfig, InputError> {
        let this = self.checked()?;
        let re = this
            .re
            .or(body.plate.reynolds())
            .ok_or(InputError::Missing {
                param: Param::Reynolds,
                why: "for a plate without a preset or physical description",
            })?;
        let thickness = body.plate.thickness();
        let modern = matches!(this.grid, GridChoice::Modern { .. });
        let mut config = this.config(
            case,
            re,
            default_t_end,
            Some(body.config()),
            body.turns,
            thickness,
        );
        config.time.average_from_turn = body.average_from_turn;
        // A physical plate's mass, buoyancy and inertia are those of its section (the dissertation's grid
        // keeps the plate's own rectangle).
        let strip = body.plate.physical_strip().filter(|_| modern);
        if let (Some(strip), Some(b)) = (strip, config.body.as_mut()) {
            config.grid.shape.validate()?;
            b.props = PlateProps {
                torque: b.props.torque,
                ..strip.props_of(&config.grid.shape)
            };
        }
        config.validate()
    }

    /// The description; `plate_thickness` is the default section's thickness.
    fn config(
        self,
        case: Case,
        default_re: f64,
        default_t_end: f64,
        body: Option<BodyConfig>,
        turns: Option<f64>,
        plate_thickness: Option<f64>,
    ) -> RunConfig {
        let grid = match self.grid {
            GridChoice::Seed => GridSpec::seed(),
            GridChoice::Modern {
                resolution,
                section,
                extent,
                growth,
            } => GridSpec {
                resolution,
                shape: match section {
                    Some(Section::Shape(shape)) => shape,
                    Some(Section::Thickness(t)) => Shape::rect(t),
                    None => Shape::rect(plate_thickness.unwrap_or(defaults::THICKNESS)),
                },
                extent_x: extent,
                extent_y: extent,
                stretch: Stretch::GrowthCap(growth),
            },
        };
        let far_field = self.far_field.unwrap_or(match case {
            Case::Static { .. } => FarFieldScheme::Explicit,
            _ => FarFieldScheme::Implicit,
        });
        RunConfig {
            grid,
            flow: FlowParams {
                re: self.re.unwrap_or(default_re),
                cfl: self.cfl,
                far_field,
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
                average_from_turn: 1,
            },
            case,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::{Fluid, Strip};

    #[test]
    fn grid_options_after_the_dissertations_grid_are_refused() {
        let refused = |e: InputError, name: &str| {
            assert!(
                matches!(e, InputError::Conflict { option, earlier: "seed_grid", .. } if option == name),
                "{name}: {e:?}"
            );
        };
        let stat = || RunBuilder::static_plate(0.4).seed_grid();
        refused(stat().thickness(0.1).build().unwrap_err(), "thickness");
        refused(stat().shape(Shape::rect(0.1)).build().unwrap_err(), "shape");
        refused(stat().extent(20.0).build().unwrap_err(), "extent");
        refused(stat().growth(1.1).build().unwrap_err(), "growth");
        refused(stat().resolution(32).build().unwrap_err(), "resolution");
        let forced = RunBuilder::forced(1.0).seed_grid().extent(12.0);
        refused(forced.build().unwrap_err(), "extent");
        let free = RunBuilder::free(Plate::card()).seed_grid().thickness(0.02);
        refused(free.build().unwrap_err(), "thickness");
        let pinned = RunBuilder::pinned(Plate::card()).seed_grid().growth(1.02);
        refused(pinned.build().unwrap_err(), "growth");
        // Given before it, they are replaced by the dissertation's grid, as documented.
        let seed = RunBuilder::static_plate(0.4)
            .resolution(32)
            .thickness(0.1)
            .seed_grid();
        assert_eq!(seed.build().unwrap().grid, GridSpec::seed());
    }

    #[test]
    fn the_defaults_follow_the_case() {
        let free = RunBuilder::free(Plate::card()).build().unwrap();
        assert_eq!(free.grid.resolution, 64);
        assert_eq!(free.time.turns, Some(10.0));
        assert_eq!(free.flow.far_field, FarFieldScheme::Implicit);
        assert!(matches!(free.case, Case::Free { v0, develop, .. } if v0 == 1.0 && develop == 5.0));
        let fixed = RunBuilder::static_plate(0.4).build().unwrap();
        assert_eq!(fixed.flow.far_field, FarFieldScheme::Explicit);
        assert_eq!((fixed.flow.re, fixed.time.t_end), (5000.0, 80.0));
        let forced = RunBuilder::forced(2.0).build().unwrap();
        assert!((forced.time.t_end - (1.0 + 3.0 * PI)).abs() < 1e-12);
        let pinned = RunBuilder::pinned(Plate::card())
            .speed(0.0)
            .build()
            .unwrap();
        assert!(matches!(pinned.case, Case::Pinned { develop, .. } if develop == 0.0));
        assert_eq!(pinned.time.turns, None);
    }

    #[test]
    fn a_physical_plate_starts_from_rest_and_gives_the_grid_its_thickness() {
        let strip = Strip {
            chord: 0.01,
            thickness: 5e-4,
            density: 2700.0,
            fluid: Fluid::water(),
            gravity: 9.81,
        };
        let plate = Plate::strip(&strip).unwrap();
        let run = RunBuilder::free(plate.clone())
            .theta0(0.2)
            .resolution(16)
            .build()
            .unwrap();
        assert!(matches!(run.case, Case::Free { v0, develop, .. } if v0 == 0.0 && develop == 0.0));
        assert_eq!(run.grid.shape, Shape::rect(0.05));
        assert!((run.flow.re - 911.0).abs() < 1.0);
        assert_eq!(
            run.title(),
            "free fall from rest at θ₀ = 0.2 rad, 10 × 0.5 mm plate of 2700 kg/m³ in water, \
             Re 911, N = 16"
        );
        let thin = RunBuilder::free(plate)
            .thickness(1.0 / 16.0)
            .build()
            .unwrap();
        assert_eq!(thin.grid.shape, Shape::rect(1.0 / 16.0));
    }

    #[test]
    fn a_plate_without_a_reynolds_number_needs_one() {
        let plate = Plate::nondimensional(1.0, 0.1, 1.0);
        let e = RunBuilder::free(plate.clone()).build().unwrap_err();
        assert_eq!(e.param(), Some(Param::Reynolds));
        assert!(RunBuilder::free(plate).re(100.0).build().is_ok());
    }

    #[test]
    fn bad_values_are_refused_by_name() {
        let e = RunBuilder::static_plate(4.0).build().unwrap_err();
        assert_eq!(e.param(), Some(Param::Alpha));
        let e = RunBuilder::free(Plate::card().mass(0.0))
            .build()
            .unwrap_err();
        assert_eq!(e.param(), Some(Param::Mass));
        let e = RunBuilder::pinned(Plate::card())
            .ab_order(7)
            .build()
            .unwrap_err();
        assert_eq!(e.param(), Some(Param::AbOrder));
    }
}
