//! The coupled time loop (docs/physics.md §6 "Coupling"): each step the flow gives the loads for the current
//! motion, the rigid-body step gives the next motion, and that motion sets the flow's boundary for
//! the next flow step. With strong coupling (the default) the body step takes the loads without
//! the flow's instantaneous answer to the last change of motion and solves its equations with the
//! added mass implicit ([`StrongCoupling`]); with explicit coupling it takes the loads as they are.
//! Prescribed cases (and the development phase before a release) take the motion from their
//! formula instead ([`Case::prescribed_state`]).
//!
//! The physics core: no I/O and no clock. Results go to an [`Observer`], step by step.
//!
//! ```
//! use platefall_core::grid::GridSpec;
//! use platefall_core::sim::{Case, RunConfig, Simulation};
//! let mut config = RunConfig::new(Case::Static { alpha: 0.4, kick: 0.0 }, GridSpec::modern(8));
//! config.time.t_end = 0.05;
//! let mut sim = Simulation::new(config.validate()?)?;
//! while !sim.finished() {
//!     let sample = sim.step()?;
//!     println!("t = {:.3}  C_D = {:.3}", sample.t, sample.cd);
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
mod checkpoint;
mod checks;
mod error;
pub mod estimate;
mod history;
mod motion;
mod output;
mod sample;
mod saved;
mod spec;
mod timestep;
pub(crate) use timestep::land;
mod turns;

pub use error::SimError;
pub use history::{History, Quantity, DEFAULT_CAPACITY};
pub use motion::{Case, CaseKind};
pub use output::{FieldSnapshot, RunRecord, RunStatus, StatusKind};
pub use sample::StepSample;
pub use saved::{RestoreError, SimState};
pub use spec::{BodyConfig, PlateSource, ReferenceScales, RunConfig, TimeControl, ValidatedConfig};
pub use timestep::{choose_dt, MAX_GROWTH};
pub use turns::turns_done;

use crate::body::{BodyState, Coupling, Dof, InertialLoads, RigidBody, StrongCoupling};
use crate::flow::{AddedMass, FlowSolver, OuterBc};
use crate::param::{InputError, Param};

/// Receives the run as it happens.
pub trait Observer {
    /// Every step, in order.
    fn step(&mut self, sample: &StepSample);
    /// Whether a field snapshot is wanted at time t (called after every step).
    fn wants_field(&mut self, t: f64) -> bool;
    /// A field snapshot (only after `wants_field` returned true).
    fn field(&mut self, snapshot: FieldSnapshot);
    /// Polled every step: stop cleanly when true (Ctrl-C).
    fn should_stop(&self) -> bool;
    /// After every step (and its field snapshot): the run and the steps' history so far, e.g. to
    /// save a checkpoint ([`Simulation::save`]). Does nothing unless implemented.
    fn after_step(&mut self, _sim: &Simulation, _history: &History) {}
}

/// An observer that wants nothing and never stops the run: [`Simulation::run`] then returns the
/// run's [`RunRecord`] alone.
#[derive(Clone, Copy, Debug, Default)]
pub struct Silent;

impl Observer for Silent {
    fn step(&mut self, _: &StepSample) {}
    fn wants_field(&mut self, _: f64) -> bool {
        false
    }
    fn field(&mut self, _: FieldSnapshot) {}
    fn should_stop(&self) -> bool {
        false
    }
}

/// The plate's motion law at run time.
enum Motion {
    /// A formula of time (cases A, B).
    Prescribed,
    /// Held on a formula until the release, then integrated (cases C, D).
    Coupled {
        body: Box<RigidBody>,
        dof: Dof,
        released: bool,
        /// The added-mass-implicit body equations (strong coupling); `None` for explicit coupling.
        strong: Option<Box<StrongCoupling>>,
    },
}

/// A run: the flow, the plate and its motion law.
pub struct Simulation {
    config: RunConfig,
    flow: FlowSolver,
    state: BodyState,
    motion: Motion,
    /// θ at the release (coupled cases), for counting turns.
    theta_release: Option<f64>,
}

impl Simulation {
    /// Builds the flow solver (fluid at rest) on the validated description's grid, and the motion
    /// law.
    ///
    /// # Errors
    /// [`SimError::Flow`] when the flow solver cannot be set up (the pressure operator, the implicit
    /// far field's split lines), [`SimError::Input`] for a coupled case without a plate, and
    /// [`SimError::Body`] for an Adams–Bashforth order outside 1..=6.
    pub fn new(config: ValidatedConfig) -> Result<Self, SimError> {
        let (config, grid) = config.into_parts();
        let state = config.case.prescribed_state(0.0);
        let mut flow =
            FlowSolver::new(grid, config.flow.clone(), OuterBc::FarField, state.frame())?;
        let motion = match &config.case {
            Case::Static { .. } | Case::Forced { .. } => Motion::Prescribed,
            Case::Pinned { .. } | Case::Free { .. } => {
                let b = config.body.as_ref().ok_or(InputError::MissingPlate)?;
                let dof = if matches!(config.case, Case::Pinned { .. }) {
                    Dof::PitchOnly
                } else {
                    Dof::Free
                };
                let body = RigidBody::new(b.props, Dof::Prescribed, state, b.ab_order, b.ab_start)?;
                let strong = match b.coupling {
                    Coupling::Explicit => None,
                    Coupling::Strong => Some(Box::new(strong_coupling(b, &mut flow)?)),
                };
                Motion::Coupled {
                    body: Box::new(body),
                    dof,
                    released: false,
                    strong,
                }
            }
        };
        Ok(Simulation {
            config,
            flow,
            state,
            motion,
            theta_release: None,
        })
    }

    /// The run description.
    pub fn config(&self) -> &RunConfig {
        &self.config
    }

    /// The flow solver (its grid, fields, time and step count).
    pub fn flow(&self) -> &FlowSolver {
        &self.flow
    }

    /// The plate's state at the current time.
    pub fn state(&self) -> &BodyState {
        &self.state
    }

    /// The flow's added-mass matrix K when the run uses strong coupling.
    pub fn added_mass(&self) -> Option<AddedMass> {
        match &self.motion {
            Motion::Coupled {
                strong: Some(s), ..
            } => Some(s.added),
            _ => None,
        }
    }

    /// The release time (coupled), end of spin-up (forced) or 0.
    pub fn release_time(&self) -> f64 {
        self.config.case.release_time()
    }

    /// The sample describing the current state.
    pub fn sample(&self) -> StepSample {
        let f = &self.flow;
        StepSample::new(f.steps(), f.t(), f.dt_prev(), f.coefficients(), &self.state)
    }

    /// A snapshot of the flow fields.
    pub fn snapshot(&self) -> FieldSnapshot {
        let (u, v) = self.flow.velocity_arrays();
        FieldSnapshot {
            step: self.flow.steps(),
            t: self.flow.t(),
            x: self.state.x,
            y: self.state.y,
            theta: self.state.theta,
            frame: *self.flow.frame(),
            u,
            v,
            p: self.flow.p().to_vec(),
        }
    }

    /// One coupled step. Returns the new sample.
    ///
    /// # Errors
    /// [`SimError::StepCollapsed`] when the stable time step falls to round-off of t,
    /// [`SimError::MotionNotFinite`] when the plate's motion is no longer finite, and
    /// [`SimError::Flow`] when the flow solution diverges.
    pub fn step(&mut self) -> Result<StepSample, SimError> {
        let limit = self.flow.prepare()?;
        let t = self.flow.t();
        let dt = timestep::choose_dt(
            t,
            limit,
            self.state.omega,
            self.flow.dt_prev(),
            self.release_time(),
            &self.config.time,
        );
        if dt <= 64.0 * f64::EPSILON * t.abs().max(1.0) {
            return Err(SimError::StepCollapsed { t, dt });
        }
        let next = self.next_state(t, dt);
        if !(next.x.is_finite()
            && next.y.is_finite()
            && next.theta.is_finite()
            && next.omega.is_finite())
        {
            return Err(SimError::MotionNotFinite { t: t + dt });
        }
        self.flow.advance(dt, next.frame())?;
        self.state = next;
        let s = self.sample();
        if self.theta_release.is_none()
            && self.config.case.is_coupled()
            && s.t >= self.release_time() - 1e-9
        {
            self.theta_release = Some(s.theta);
        }
        Ok(s)
    }

    /// The plate's state at t + dt: from the formula, or (after the release) from the body
    /// equations under the loads of the current flow.
    fn next_state(&mut self, t: f64, dt: f64) -> BodyState {
        let Motion::Coupled {
            body,
            dof,
            released,
            strong,
        } = &mut self.motion
        else {
            return self.config.case.prescribed_state(t + dt);
        };
        if !*released && t >= self.config.case.release_time() - 1e-9 {
            *released = true;
            body.state = self.state;
            body.set_dof(*dof);
        }
        if !*released {
            return self.config.case.prescribed_state(t + dt);
        }
        let (flow, l) = (&self.flow, self.flow.loads());
        match strong {
            Some(sc) => {
                let rest = sc
                    .added
                    .rest(&l, flow.frame(), flow.frame_prev(), flow.dt_prev());
                let f = sc.derivative(&body.props, *dof, &body.state, rest, dt);
                body.step_with(t, f, dt);
            }
            None => {
                let loads = InertialLoads::from_body_axes(self.state.theta, l.fx, l.fy, l.moment);
                body.step(t, &loads, dt);
            }
        }
        body.state
    }

    /// Whether the run is over (t_end reached, or the requested turns after release).
    pub fn finished(&self) -> bool {
        if self.flow.t() >= self.config.time.t_end - 1e-9 {
            return true;
        }
        turns_done(self.config.time.turns, self.state.theta, self.theta_release)
    }

    /// Runs to the end, reporting every step to `obs`.
    pub fn run(&mut self, obs: &mut dyn Observer) -> RunRecord {
        self.run_from(obs, History::default())
    }

    /// Runs to the end from where the run is, going on with the steps' history `samples` (empty
    /// for a new run; a checkpoint's for a restored one, [`Simulation::restore`]).
    pub fn run_from(&mut self, obs: &mut dyn Observer, mut samples: History) -> RunRecord {
        let status = loop {
            if obs.should_stop() {
                break RunStatus::Interrupted;
            }
            match self.step() {
                Ok(s) => {
                    obs.step(&s);
                    samples.push(s);
                    if obs.wants_field(s.t) {
                        obs.field(self.snapshot());
                    }
                    obs.after_step(self, &samples);
                    if self.finished() {
                        break RunStatus::Completed;
                    }
                }
                Err(e) => break RunStatus::Diverged(e),
            }
        };
        let recirculation_length = match self.config.case {
            Case::Static { .. } => self.flow.recirculation_length(),
            _ => None,
        };
        RunRecord {
            status,
            samples,
            t_release: self.release_time(),
            cells: self.flow.grid().cells(),
            recirculation_length,
        }
    }
}

/// The strong coupling of a plate: the flow's added-mass matrix (three projections) and the body's
/// equations with it on the left-hand side.
fn strong_coupling(b: &BodyConfig, flow: &mut FlowSolver) -> Result<StrongCoupling, SimError> {
    let added = flow.added_mass();
    StrongCoupling::new(&b.props, added).ok_or_else(|| {
        SimError::Input(InputError::Inconsistent {
            param: Param::Mass,
            value: b.props.mass,
            why: "the plate's mass plus the flow's added mass is singular".into(),
        })
    })
}
