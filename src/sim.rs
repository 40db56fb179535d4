//! The coupled time loop (SPEC §6 "Coupling"): each step the flow gives the loads for the current
//! motion, the rigid-body step gives the next motion, and that motion sets the flow's boundary for
//! the next flow step. Prescribed cases (and the development phase before a release) take the
//! motion from a formula instead. No I/O: results go to an [`Observer`].
use std::f64::consts::PI;
use std::time::Instant;

use crate::body::{inertial_to_body, wrap_angle, BodyState, Dof, Loads as BodyLoads, RigidBody};
use crate::config::{Case, RunConfig};
use crate::flow::{FlowError, FlowSolver, Frame, OuterBc};
use crate::grid::Grid;
use crate::record::messages::{FieldSnapshot, RunStatus, StepSample};

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
}

/// How a run ended, with its time series.
pub struct RunRecord {
    pub status: RunStatus,
    pub samples: Vec<StepSample>,
    /// Time of release (coupled cases) or of the end of spin-up (forced); 0 for static.
    pub t_release: f64,
    pub wall_seconds: f64,
    pub cells: usize,
}

/// The plate's motion law.
enum Motion {
    /// A formula of time (cases A, B).
    Prescribed,
    /// Held on a formula until `release`, then integrated (cases C, D).
    Coupled {
        body: RigidBody,
        release: f64,
        dof: Dof,
        released: bool,
    },
}

pub struct Simulation {
    pub config: RunConfig,
    pub flow: FlowSolver,
    pub state: BodyState,
    motion: Motion,
}

impl Simulation {
    /// Builds the grid, the flow solver (fluid at rest) and the motion law.
    pub fn new(config: RunConfig) -> Result<Self, String> {
        config.validate().map_err(|e| e.0)?;
        let grid = Grid::new(&config.grid).map_err(|e| e.0)?;
        let state = prescribed_state(&config.case, 0.0);
        let flow = FlowSolver::new(
            grid,
            config.flow.clone(),
            OuterBc::FarField,
            frame_of(&state),
        )
        .map_err(|e| e.to_string())?;
        let motion = match &config.case {
            Case::Static { .. } | Case::Forced { .. } => Motion::Prescribed,
            Case::Pinned { develop, .. } | Case::Free { develop, .. } => {
                let b = config
                    .body
                    .as_ref()
                    .ok_or("a coupled case needs plate properties")?;
                let dof = if matches!(config.case, Case::Pinned { .. }) {
                    Dof::PitchOnly
                } else {
                    Dof::Free
                };
                let body = RigidBody::new(b.props, Dof::Prescribed, state, b.ab_order, b.ab_start)
                    .map_err(|e| e.to_string())?;
                Motion::Coupled {
                    body,
                    release: *develop,
                    dof,
                    released: false,
                }
            }
        };
        Ok(Simulation {
            config,
            flow,
            state,
            motion,
        })
    }

    /// The release time (coupled), end of spin-up (forced) or 0.
    pub fn release_time(&self) -> f64 {
        match (&self.motion, &self.config.case) {
            (Motion::Coupled { release, .. }, _) => *release,
            (_, Case::Forced { spinup, .. }) => *spinup,
            _ => 0.0,
        }
    }

    /// The sample describing the current state.
    pub fn sample(&self) -> StepSample {
        let (cl, cd, cm) = self.flow.coefficients();
        let s = &self.state;
        let gamma = s.flight_path_angle();
        StepSample {
            step: self.flow.steps,
            t: self.flow.t,
            dt: self.flow.dt_prev,
            cl,
            cd,
            cm,
            x: s.x,
            y: s.y,
            theta: s.theta,
            xdot: s.xdot,
            ydot: s.ydot,
            omega: s.omega,
            speed: s.speed(),
            gamma,
            alpha: wrap_angle(s.theta - gamma),
        }
    }

    /// A snapshot of the flow fields for the recording.
    pub fn snapshot(&self) -> FieldSnapshot {
        let (u, v) = self.flow.velocity_arrays();
        let f = &self.flow.frame;
        FieldSnapshot {
            step: self.flow.steps,
            t: self.flow.t,
            x: self.state.x,
            y: self.state.y,
            theta: self.state.theta,
            gx0: f.a,
            gy0: f.b,
            omega: f.omega,
            u,
            v,
            p: self.flow.p.clone(),
        }
    }

    /// Chooses Δt: the flow's own limit, the ceiling, the seed's rotation rule Δt|θ̇| ≤ C_c, at most
    /// 20 % growth per step, landing exactly on the release time and on t_end.
    fn choose_dt(&self, flow_limit: f64) -> f64 {
        let c = &self.config;
        let t = self.flow.t;
        let mut dt = flow_limit.min(c.dt_max);
        if self.state.omega != 0.0 {
            dt = dt.min(c.cc / self.state.omega.abs());
        }
        if self.flow.dt_prev > 0.0 {
            dt = dt.min(1.2 * self.flow.dt_prev);
        }
        // Land exactly on the release time and on t_end, without leaving a sliver of a step.
        for target in [self.release_time(), c.t_end] {
            let remaining = target - t;
            if remaining > 1e-9 {
                if remaining <= dt {
                    dt = remaining;
                } else if remaining < 2.0 * dt {
                    dt = 0.5 * remaining;
                }
            }
        }
        dt
    }

    /// One coupled step. Returns the new sample.
    pub fn step(&mut self) -> Result<StepSample, FlowError> {
        let limit = self.flow.prepare()?;
        let dt = self.choose_dt(limit);
        let t = self.flow.t;
        let loads = self.flow.loads();
        let next = match &mut self.motion {
            Motion::Prescribed => prescribed_state(&self.config.case, t + dt),
            Motion::Coupled {
                body,
                release,
                dof,
                released,
            } => {
                if !*released && t >= *release - 1e-9 {
                    *released = true;
                    body.state = self.state;
                    body.set_dof(*dof);
                }
                if *released {
                    let l = BodyLoads::from_body_axes(
                        self.state.theta,
                        loads.fx,
                        loads.fy,
                        loads.moment,
                    );
                    body.step(t, &l, dt);
                    body.state
                } else {
                    prescribed_state(&self.config.case, t + dt)
                }
            }
        };
        if !(next.x.is_finite()
            && next.y.is_finite()
            && next.theta.is_finite()
            && next.omega.is_finite())
        {
            return Err(FlowError::Diverged(format!(
                "the plate's motion is not finite at t = {:.4}",
                t + dt
            )));
        }
        self.flow.advance(dt, frame_of(&next))?;
        self.state = next;
        Ok(self.sample())
    }

    /// Whether the run is over (t_end reached, or the requested turns after release).
    pub fn finished(&self, theta_release: Option<f64>) -> bool {
        if self.flow.t >= self.config.t_end - 1e-9 {
            return true;
        }
        match (self.config.turns, theta_release) {
            (Some(n), Some(th)) => (self.state.theta - th).abs() >= 2.0 * std::f64::consts::PI * n,
            _ => false,
        }
    }

    /// Runs to the end, reporting every step to `obs`.
    pub fn run(&mut self, obs: &mut dyn Observer) -> RunRecord {
        let start = Instant::now();
        let mut samples = Vec::new();
        let release = self.release_time();
        let mut theta_release = None;
        let status = loop {
            if obs.should_stop() {
                break RunStatus::Interrupted;
            }
            match self.step() {
                Ok(s) => {
                    obs.step(&s);
                    samples.push(s);
                    if theta_release.is_none()
                        && self.config.case.is_coupled()
                        && s.t >= release - 1e-9
                    {
                        theta_release = Some(s.theta);
                    }
                    if obs.wants_field(s.t) {
                        obs.field(self.snapshot());
                    }
                    if self.finished(theta_release) {
                        break RunStatus::Completed;
                    }
                }
                Err(FlowError::Diverged(msg)) | Err(FlowError::Setup(msg)) => {
                    break RunStatus::Diverged(msg)
                }
            }
        };
        RunRecord {
            status,
            samples,
            t_release: release,
            wall_seconds: start.elapsed().as_secs_f64(),
            cells: self.flow.grid.cells(),
        }
    }
}

/// The flow solver's view of the motion: the centre's velocity in body axes and θ̇ (SPEC §3).
pub fn frame_of(s: &BodyState) -> Frame {
    let (a, b) = inertial_to_body(s.theta, s.xdot, s.ydot);
    Frame {
        a,
        b,
        omega: s.omega,
    }
}

/// The prescribed motion at time t: cases A and B, and the development phase of C and D.
///
/// A: X = t, θ = α (+ the start-up kick ε sin²(πt) for t < 1). B: X = t, θ̈ = R/T_s for t < T_s, then θ̇ = R. C: X = t, θ = α₀.
/// D: moving at V₀ along γ₀ with θ = γ₀ + α₀.
pub fn prescribed_state(case: &Case, t: f64) -> BodyState {
    let translate = |v: f64, gamma: f64, theta: f64, omega: f64| BodyState {
        x: v * gamma.cos() * t,
        y: v * gamma.sin() * t,
        theta,
        xdot: v * gamma.cos(),
        ydot: v * gamma.sin(),
        omega,
    };
    match *case {
        Case::Static { alpha, kick } => {
            let (theta, omega) = if t < 1.0 {
                let s = (PI * t).sin();
                (alpha + kick * s * s, kick * PI * (2.0 * PI * t).sin())
            } else {
                (alpha, 0.0)
            };
            translate(1.0, 0.0, theta, omega)
        }
        Case::Forced { rate, spinup } => {
            let (theta, omega) = if t < spinup {
                (0.5 * rate / spinup * t * t, rate * t / spinup)
            } else {
                (0.5 * rate * spinup + rate * (t - spinup), rate)
            };
            translate(1.0, 0.0, theta, omega)
        }
        Case::Pinned { alpha0, .. } => translate(1.0, 0.0, alpha0, 0.0),
        Case::Free {
            v0, gamma0, alpha0, ..
        } => translate(v0, gamma0, gamma0 + alpha0, 0.0),
    }
}
