//! Incompressible Navier–Stokes in the mixed frame on the body-fixed grid (docs/physics.md §3).
//!
//! Unknowns are the inertial velocity components along the body axes on a staggered (MAC) grid.
//!
//! # One step, phase by phase
//!
//! A step from tⁿ to tⁿ⁺¹ = tⁿ + Δt is two calls. [`FlowSolver::prepare`] fills the ghost values
//! of the state at tⁿ, evaluates the explicit right-hand side Hⁿ (convection on u − g, diffusion,
//! the θ̇ terms, the near-wall fluxes and an optional body force) and returns the largest stable
//! Δt. [`FlowSolver::advance`] then takes the chosen Δt and the plate's motion at tⁿ⁺¹ and runs
//! the phases below, in this order; each states what holds on its return, and a solver in another
//! dimension follows the same contract:
//!
//! 1. `begin_step`: the frame is the motion at tⁿ⁺¹, the previous frame the motion at tⁿ, and the
//!    guess the motion extrapolated from the two steps before (the near-wall no-slip values
//!    follow it).
//! 2. `predict`: u* = uⁿ + Δt[(1 + r/2)Hⁿ − (r/2)Hⁿ⁻¹] (variable-step Adams–Bashforth 2,
//!    `ab2.rs`) on every interior face, and Hⁿ has become H⁻¹ of the next step. The far-field
//!    scheme ([`FarFieldScheme`]) is a variant of this phase alone: the implicit one
//!    (`implicit_step.rs`) adds the old pressure gradient and takes the grid transport along the
//!    split lines implicitly, with the outer normals at tⁿ⁺¹ as the known ends of its sweeps.
//! 3. `impose_boundaries`: u* = g on the plate's held faces and its forced points (no-slip), and
//!    the outer boundary's normal velocities at tⁿ⁺¹ with no net flux.
//! 4. `project`: uⁿ⁺¹ is discretely divergence-free in every fluid cell and pⁿ⁺¹ is set (the
//!    whole pressure, or its increment where the predictor carried the old gradient).
//! 5. `end_step`: the held faces carry the plate's velocity again; t, the last Δt and the step
//!    count include the step.
//! 6. `update_loads`: the force and moment on the plate at tⁿ⁺¹, or an error if not finite.
//!
//! Nothing in this contract depends on the dimension: a three-dimensional solver keeps the two
//! calls, the six phases in this order and what holds after each, adding the third component
//! to every phase, and shares the time weights ([`Ab2`]) and ν ([`FlowParams::nu`]).
//!
//! The hot path allocates nothing after [`FlowSolver::new`]. The u and v halves of each phase run
//! in parallel (`rayon::join`); called from inside a rayon pool that allocates nothing either.
//!
//! # Files
//!
//! `impl FlowSolver` is in these files:
//!
//! - this one: the struct, construction, `prepare` and the phases of `advance`;
//! - `implicit_step.rs`: the implicit far field's predictor and incremental projection;
//! - `accessors.rs`: the state read from outside (fields, motion, time, loads, sizes);
//! - `snapshot.rs`: checkpoints (the saved data in `state.rs`); `added_mass_response.rs`: the
//!   added-mass response (the matrices in `added_mass.rs`); `wake.rs`: the recirculation length.
//!
//! The other files hold no solver state: `params.rs` and `error.rs` (inputs and errors),
//! `far_field.rs` (the far-field scheme's start), `limits.rs` (stable Δt), `ab2.rs` (time
//! weights), `momentum.rs` and `transport.rs` (the explicit right-hand side and the line
//! operators), `implicit/` (the implicit far field's line solves), `zones.rs` (where it applies),
//! `boundary.rs` (outer boundary), `wall/` (the plate in the grid: faces, near-wall stencils,
//! loads, and [`check_representable`]), `pressure.rs` and `split_cholesky.rs` (the projection),
//! `metrics.rs`, `array.rs`, `band.rs`, `frame.rs` and `plate.rs` (geometry, storage, banded
//! solves, motion, load coefficients).
mod ab2;
mod accessors;
mod added_mass;
mod added_mass_response;
mod array;
mod band;
mod boundary;
mod error;
mod far_field;
mod frame;
mod implicit;
mod implicit_step;
mod limits;
mod metrics;
mod momentum;
mod params;
mod plate;
mod pressure;
mod snapshot;
mod split_cholesky;
mod state;
mod transport;
pub(crate) mod wake;
mod wall;
mod zones;

pub use ab2::Ab2;
pub use added_mass::AddedMass;
pub use array::{Padded, GHOST};
pub use boundary::{OuterBc, VelocityFn};
pub use error::{FlowError, SetupError};
pub use frame::Frame;
pub use limits::{combined_dt_limit, viscous_dt_limit, BLOWUP_FACTOR};
pub use metrics::{Axis, Metrics};
/// The κ = 1/3 limited face value, shared with the three-dimensional solver (`flow3d`).
pub(crate) use momentum::face_value;
pub use params::{FarFieldScheme, FlowParams, NEAR_DEFAULT};
pub use plate::BodyAxesLoads;
pub use pressure::PressureError;
pub use split_cholesky::FactorError;
pub use state::{FlowState, StateMismatch};
pub use wall::check_representable;
pub use zones::PlateCrossing;

use boundary::Outflow;
use implicit::State;
use metrics::Component;
use momentum::RhsContext;
use pressure::Pressure;
use wall::Wall;
use zones::Zones;

use crate::grid::Grid;

/// A body force (x, y, t) ↦ (f_x, f_y) added to the momentum equations (for manufactured solutions).
pub type ForceFn = Box<dyn Fn(f64, f64, f64) -> (f64, f64) + Send + Sync>;

/// The flow solver: the fields on the body-fixed grid and everything the step needs (see the
/// module docs for the phases of a step). Its state is read through accessors (`accessors.rs`).
pub struct FlowSolver {
    grid: Grid,
    params: FlowParams,
    metrics: Metrics,
    u: Padded,
    v: Padded,
    /// Pressure at cell centres (zero inside the plate), from the last projection.
    p: Vec<f64>,
    hu: Padded,
    hv: Padded,
    hu_old: Padded,
    hv_old: Padded,
    pressure: Pressure,
    outer: OuterBc,
    forcing: Option<ForceFn>,
    /// The plate in the grid: held faces, near-wall stencils, load samples.
    wall: Wall,
    /// The lines with implicit grid transport (none in the explicit scheme) and their workspaces.
    zones: Zones,
    implicit: Option<Box<State>>,
    /// Motion of the plate at the current time level.
    frame: Frame,
    /// Motion of the plate at the previous time level (`frame` before the first step); with
    /// `dt_prev` it gives the change of motion the last projection answered ([`AddedMass`]).
    frame_prev: Frame,
    /// The motion at the new time level extrapolated from the two before (the no-slip values
    /// next to the wall follow it, `wall::Wall::impose`).
    guess: Frame,
    /// Current time and the last step taken (0 before the first step).
    t: f64,
    dt_prev: f64,
    steps: u64,
    /// Convective rate max|w|/Δx from the last `prepare`.
    convective_rate: f64,
    dt_visc: f64,
    prepared: bool,
    loads: BodyAxesLoads,
}

impl FlowSolver {
    /// A fluid at rest (u = 0) around a plate moving with `frame` at time 0.
    ///
    /// # Errors
    /// [`FlowError::Setup`] when the pressure operator cannot be factored or a split line of the
    /// implicit far field would cross the plate.
    pub fn new(
        grid: Grid,
        params: FlowParams,
        outer: OuterBc,
        frame: Frame,
    ) -> Result<Self, FlowError> {
        let metrics = Metrics::new(&grid);
        let wall = Wall::new(&grid, &metrics, params.nu());
        let pressure = Pressure::new(&grid, &metrics, &wall.faces).map_err(SetupError::Pressure)?;
        let dt_visc = viscous_dt_limit(&grid, &params);
        let (nx, ny) = (grid.nx, grid.ny);
        let (zones, implicit) = far_field::far_field_state(&grid, &params, &metrics)?;
        let mut s = FlowSolver {
            u: Padded::zeros(nx + 1, ny),
            v: Padded::zeros(nx, ny + 1),
            p: vec![0.0; nx * ny],
            hu: Padded::zeros(nx + 1, ny),
            hv: Padded::zeros(nx, ny + 1),
            hu_old: Padded::zeros(nx + 1, ny),
            hv_old: Padded::zeros(nx, ny + 1),
            pressure,
            outer,
            forcing: None,
            wall,
            zones,
            implicit,
            frame,
            frame_prev: frame,
            guess: frame,
            t: 0.0,
            dt_prev: 0.0,
            steps: 0,
            convective_rate: 0.0,
            dt_visc,
            prepared: false,
            loads: BodyAxesLoads::default(),
            grid,
            params,
            metrics,
        };
        s.impose_plate();
        Ok(s)
    }

    /// Adds a body force to the momentum equations (used with manufactured solutions).
    pub fn set_forcing(&mut self, f: ForceFn) {
        self.forcing = Some(f);
    }

    /// Sets the velocity field from a function of (x, y) (body axes) on every face, then the plate
    /// faces to g. The field is not projected: give a divergence-free one.
    pub fn set_velocity(&mut self, f: impl Fn(f64, f64) -> (f64, f64)) {
        let (nx, ny) = (self.grid.nx as isize, self.grid.ny as isize);
        let (m, u, v) = (&self.metrics, &mut self.u, &mut self.v);
        m.for_faces(Component::U, 0..nx + 1, 0..ny, |i, j, x, y| {
            u.set(i, j, f(x, y).0)
        });
        m.for_faces(Component::V, 0..nx, 0..ny + 1, |i, j, x, y| {
            v.set(i, j, f(x, y).1)
        });
        self.impose_plate();
    }

    /// The first call of a step (see the module docs): on return Hⁿ is stored. Returns the
    /// largest stable Δt: the convective and the explicit viscous limits combined
    /// ([`combined_dt_limit`]).
    ///
    /// # Errors
    /// [`FlowError::Diverged`] when a velocity is far beyond the plate's own speeds or not finite.
    pub fn prepare(&mut self) -> Result<f64, FlowError> {
        boundary::fill_ghosts(
            &mut self.u,
            &mut self.v,
            &self.metrics,
            &self.frame,
            &self.outer,
            self.t,
        );
        let context = RhsContext {
            m: &self.metrics,
            frame: &self.frame,
            nu: self.params.nu(),
            zones: &self.zones,
        };
        let stats = momentum::explicit_rhs(&self.u, &self.v, context, &mut self.hu, &mut self.hv);
        self.convective_rate = stats.convective_rate;
        self.wall
            .apply(&self.u, &self.v, &self.frame, &mut self.hu, &mut self.hv);
        if let Some(f) = &self.forcing {
            momentum::add_forcing(&**f, &self.metrics, self.t, &mut self.hu, &mut self.hv);
        }
        // Fluid velocities are bounded by a few times the plate's own speeds; far beyond that the
        // explicit scheme has gone unstable.
        let f = &self.frame;
        let bound = BLOWUP_FACTOR * (1.0 + f.speed() + f.omega.abs());
        if stats.max_speed.is_nan() || stats.max_speed > bound || !self.convective_rate.is_finite()
        {
            return Err(self.diverged(&format!(
                "the largest velocity {:.3e} exceeds {bound:.1} = {BLOWUP_FACTOR} × (1 + V + |θ̇|)",
                stats.max_speed
            )));
        }
        self.prepared = true;
        Ok(combined_dt_limit(
            self.params.cfl,
            self.convective_rate,
            self.dt_visc,
        ))
    }

    /// The second call of a step: advances to t + `dt` with the plate moving as `next`, phase by
    /// phase (see the module docs for what holds after each).
    ///
    /// # Errors
    /// [`FlowError::Diverged`] when the loads on the plate are not finite.
    ///
    /// # Panics
    /// Without a [`prepare`](Self::prepare) since the last step, or for a `dt` that is not
    /// positive and finite (the caller's contract, not an input).
    pub fn advance(&mut self, dt: f64, next: Frame) -> Result<(), FlowError> {
        self.begin_step(dt, next);
        self.predict(dt);
        self.impose_boundaries(dt);
        self.project(dt);
        self.end_step(dt);
        self.update_loads()
    }

    /// Phase 1: the frame moves to `next`; on return `frame_prev` is the motion at tⁿ and `guess`
    /// the motion at tⁿ⁺¹ extrapolated from tⁿ and tⁿ⁻¹.
    fn begin_step(&mut self, dt: f64, next: Frame) {
        assert!(self.prepared, "FlowSolver::advance called without prepare");
        assert!(
            dt > 0.0 && dt.is_finite(),
            "FlowSolver::advance needs a positive finite dt, got {dt}"
        );
        self.prepared = false;
        self.guess = self.frame.extrapolated(&self.frame_prev, dt, self.dt_prev);
        self.frame_prev = self.frame;
        self.frame = next;
    }

    /// Phase 2: on return u* holds on every interior face and Hⁿ is the old right-hand side;
    /// the implicit far field has also set the outer normals at tⁿ⁺¹ (its sweeps' known ends).
    fn predict(&mut self, dt: f64) {
        if self.implicit.is_some() {
            self.predict_implicit(dt);
        } else {
            self.predict_explicit(dt);
        }
    }

    /// Phase 3: on return u* = g on the plate (held faces and forced points) and the outer
    /// boundary's normal velocities at tⁿ⁺¹ carry no net flux.
    fn impose_boundaries(&mut self, dt: f64) {
        self.impose_plate();
        if self.implicit.is_none() {
            self.set_outer_normals(self.t + dt, dt, Outflow::Explicit);
        }
    }

    /// Phase 4: on return uⁿ⁺¹ is discretely divergence-free in every fluid cell and pⁿ⁺¹ is set
    /// (p = φ/Δt, or p += its increment after the implicit predictor).
    fn project(&mut self, dt: f64) {
        if self.implicit.is_some() {
            self.project_incremental(dt);
        } else {
            self.pressure.project(
                &mut self.u,
                &mut self.v,
                &self.grid,
                &self.metrics,
                (&self.wall, &self.frame),
                dt,
                &mut self.p,
            );
        }
    }

    /// Phase 5: on return the held faces carry the plate's velocity again (the projection moved
    /// them) and t, the last Δt and the step count include this step.
    fn end_step(&mut self, dt: f64) {
        self.wall
            .hold(&mut self.u, &mut self.v, &self.frame, &self.guess);
        self.t += dt;
        self.dt_prev = dt;
        self.steps += 1;
    }

    /// Phase 6: the loads on the plate after a projection; an error if they are not finite.
    fn update_loads(&mut self) -> Result<(), FlowError> {
        self.loads = self.loads_for(&self.p);
        let l = &self.loads;
        if !(l.fx.is_finite() && l.fy.is_finite() && l.moment.is_finite()) {
            return Err(self.diverged("the force on the plate is not finite"));
        }
        Ok(())
    }

    /// The explicit predictor: u* = uⁿ + Δt (a Hⁿ + b Hⁿ⁻¹) on the interior faces with the AB2
    /// weights ([`Ab2`], Euler on the first step); Hⁿ becomes the old right-hand side.
    fn predict_explicit(&mut self, dt: f64) {
        let w = Ab2::new(dt, if self.steps == 0 { 0.0 } else { self.dt_prev });
        let (nx, ny) = (self.grid.nx as isize, self.grid.ny as isize);
        let update = |vel: &mut Padded, h: &Padded, h_old: &Padded, is, js| {
            for j in js {
                for i in std::ops::Range::clone(&is) {
                    let k = vel.at(i, j);
                    vel.data[k] += dt * (w.new * h.data[k] + w.old * h_old.data[k]);
                }
            }
        };
        update(&mut self.u, &self.hu, &self.hu_old, 1..nx, 0..ny);
        update(&mut self.v, &self.hv, &self.hv_old, 0..nx, 1..ny);
        std::mem::swap(&mut self.hu, &mut self.hu_old);
        std::mem::swap(&mut self.hv, &mut self.hv_old);
    }

    /// The outer boundary's normal velocities at `t` for the current frame, net flux removed.
    fn set_outer_normals(&mut self, t: f64, dt: f64, outflow: Outflow) {
        boundary::set_outer_normals(
            &mut self.u,
            &mut self.v,
            &self.metrics,
            &self.frame,
            &self.outer,
            t,
            dt,
            outflow,
        );
    }

    /// No-slip: the held faces take the grid-point velocity g of this frame, the forced points
    /// their values between the wall and the fluid (`wall::stencils`).
    fn impose_plate(&mut self) {
        self.wall
            .impose(&mut self.u, &mut self.v, &self.frame, &self.guess);
    }

    fn diverged(&self, reason: &str) -> FlowError {
        FlowError::Diverged {
            t: self.t,
            step: self.steps,
            reason: reason.to_string(),
        }
    }
}
