//! A case of the command line on a 3-D grid (docs/three-d.md "Cases"): the 2-D run's description
//! (case, fluid, CFL, end, step cap, resolution and thickness) with a span, its grid and its
//! flow, and each step's projection onto the 2-D [`StepSample`].
use std::ops::ControlFlow;

use super::run::{run_prescribed, Sample3};
use super::{frame_of, planar_frame, Flight3, Flight3Error, Sample6};
use crate::body::six::{Constraint6, Plate6, RigidBody6, State6};
use crate::body::{wrap_angle, BodyState};
use crate::flow3d::{
    Coefficients3, Flow3Error, FlowParams3, FlowSolver3, Grid3, GridSpec3, OuterBc3, Span, Stretch3,
};
use crate::sim::{Case, RunConfig, StepSample};

/// Distance to the outer boundary along each axis when none is given (chords): the 3-D cell
/// count grows with its cube, so it is shorter than the 2-D default.
pub const EXTENT3: f64 = 8.0;
/// Cap on the ratio of neighbouring cell widths when none is given.
pub const GROWTH3: f64 = 1.2;

/// A run of the 2-D description `config` on a 3-D grid.
#[derive(Clone, Debug)]
pub struct Run3<'a> {
    /// The case, fluid, numerics and time control (the grid's resolution and the plate's
    /// thickness are read from it too).
    pub config: &'a RunConfig,
    /// The 3-D grid.
    pub grid: GridSpec3,
}

impl<'a> Run3<'a> {
    /// The run of `config` with `span`, the outer boundary `extent` chords away along every
    /// axis, growth capped at `growth`, refused above `memory_limit` bytes.
    pub fn new(
        config: &'a RunConfig,
        span: Span,
        extent: f64,
        growth: f64,
        memory_limit: f64,
    ) -> Self {
        let grid = GridSpec3 {
            resolution: config.grid.resolution,
            thickness: config.grid.shape.thickness(),
            span,
            extent: [extent; 3],
            stretch: Stretch3::GrowthCap(growth),
            memory_limit,
            shape: Default::default(),
        };
        Run3 { config, grid }
    }

    /// The run's one-line title: the 2-D title with the span, or with the curved body named
    /// in place of the section.
    pub fn title(&self) -> String {
        let g = &self.grid;
        if g.shape.is_curved() {
            return self
                .config
                .title_naming(Some(g.shape.describe(g.thickness, g.span)));
        }
        match g.span {
            Span::Finite(b) => format!("{}, span {b} chords", self.config.title()),
            Span::Periodic(p) => format!("{}, periodic span {p} chords", self.config.title()),
        }
    }

    /// The flow's parameters: the run's Reynolds number and Courant number.
    pub fn params(&self) -> FlowParams3 {
        FlowParams3 {
            re: self.config.flow.re,
            cfl: self.config.flow.cfl,
            ..FlowParams3::default()
        }
    }

    /// The flow at rest around the plate at the case's state at t = 0 (a prescribed case).
    ///
    /// # Errors
    /// The grid's refusals (span too short, memory) and the parameters'.
    pub fn flow(&self) -> Result<FlowSolver3, Flow3Error> {
        let frame = planar_frame(&self.config.case.prescribed_state(0.0));
        let grid = Grid3::new(&self.grid)?;
        FlowSolver3::new(grid, self.params(), OuterBc3::FarField, frame)
    }

    /// Runs a static or forced case to the run's end with its step cap (see [`run_prescribed`]).
    ///
    /// # Errors
    /// As [`run_prescribed`].
    pub fn run(
        &self,
        flow: &mut FlowSolver3,
        observe: impl FnMut(&Sample3, &FlowSolver3) -> ControlFlow<()>,
    ) -> Result<(), Flow3Error> {
        let time = &self.config.time;
        run_prescribed(&self.config.case, flow, time.t_end, time.dt_max, observe)
    }
}

impl Run3<'_> {
    /// The flight of a free case: `plate` launched as the 2-D free fall (V₀ along γ₀ at α₀, held
    /// until the release), flying with six degrees of freedom on a finite span and planar on a
    /// periodic one, with the case's Adams–Bashforth order and start.
    ///
    /// # Errors
    /// [`Flow3Error::BadParameter`] for a case that is not free; the grid's, the body's and the
    /// coupling's refusals.
    pub fn flight(&self, plate: Plate6) -> Result<Flight3, Flight3Error> {
        let (
            Case::Free {
                v0,
                gamma0,
                alpha0,
                develop,
            },
            Some(b),
        ) = (&self.config.case, &self.config.body)
        else {
            let e = Flow3Error::BadParameter {
                name: "case (free only)",
                value: f64::NAN,
            };
            return Err(e.into());
        };
        let start = State6::release(*v0, *gamma0, *alpha0);
        let constraint = match self.grid.span {
            Span::Finite(_) => Constraint6::Free,
            Span::Periodic(_) => Constraint6::Planar,
        };
        let grid = Grid3::new(&self.grid)?;
        let flow = FlowSolver3::new(grid, self.params(), OuterBc3::FarField, frame_of(&start))?;
        let body = RigidBody6::new(plate, constraint, start, b.ab_order, b.ab_start)?;
        Flight3::new(flow, body)?.hold_until(*develop)
    }
}

/// The pitch angle of `s` continued from `previous` (no jumps of 2π): the 2-D θ of a flight.
pub fn unwrapped_pitch(previous: f64, s: &State6) -> f64 {
    previous + wrap_angle(s.orientation.euler_angles().2 - previous)
}

/// The 2-D sample of a step of the plate at `state` with the coefficients `c` (C_L, C_D and
/// C_M = the pitching moment).
fn planar_sample(
    step: u64,
    (t, dt): (f64, f64),
    c: &Coefficients3,
    state: &BodyState,
) -> StepSample {
    StepSample::new(step, t, dt, (c.lift, c.drag, c.pitch), state)
}

impl Sample3 {
    /// The 2-D sample of this step of `case`: lift, drag and pitching moment, and the plate's
    /// prescribed planar motion.
    pub fn planar(&self, case: &Case) -> StepSample {
        let c = &self.coefficients;
        let state = case.prescribed_state(self.t);
        planar_sample(self.step, (self.t, self.dt), c, &state)
    }
}

impl Sample6 {
    /// The 2-D sample of this step: lift, drag and pitching moment, the position and velocity in
    /// the X–Y plane, θ = `pitch` (unwrapped by the caller) and θ̇ = ω_z.
    pub fn planar(&self, pitch: f64) -> StepSample {
        let (c, s) = (&self.coefficients, &self.state);
        let state = BodyState {
            x: s.position.x,
            y: s.position.y,
            theta: pitch,
            xdot: s.velocity.x,
            ydot: s.velocity.y,
            omega: s.omega.z,
        };
        planar_sample(self.step, (self.t, self.dt), c, &state)
    }
}
