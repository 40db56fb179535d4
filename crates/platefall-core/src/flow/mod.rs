//! Incompressible Navier–Stokes in the mixed frame on the body-fixed grid (docs/physics.md §3).
//!
//! Unknowns are the inertial velocity components along the body axes on a staggered (MAC) grid.
//! One step from tⁿ to tⁿ⁺¹ = tⁿ + Δt is split into two calls:
//!
//! 1. [`FlowSolver::prepare`]: fills ghost values for the state at tⁿ, evaluates the explicit
//!    right-hand side Hⁿ (convection on u − g, diffusion, the θ̇ terms, the near-wall correction and
//!    an optional body force) and returns the largest stable Δt. On return Hⁿ is stored.
//! 2. [`FlowSolver::advance`]: with the chosen Δt and the plate motion at tⁿ⁺¹, forms
//!    u* = uⁿ + Δt[(1 + r/2)Hⁿ − (r/2)Hⁿ⁻¹] (variable-step Adams–Bashforth 2, r = Δt/Δtⁿ⁻¹), imposes
//!    u* = g on the plate and the outer boundary values at tⁿ⁺¹, and projects. On return uⁿ⁺¹ is
//!    discretely divergence-free in every fluid cell, pⁿ⁺¹ is set and the loads are computed.
//!
//! With [`FarFieldScheme::Implicit`] (the default) the grid-velocity transport outside a near
//! field around the plate is taken implicitly instead (`zones.rs`, `implicit.rs`): phase 2 then
//! solves tridiagonal systems along the split rows and columns before the projection, and the
//! pressure is incremental. Inside the near field the scheme is the one above.
//!
//! The hot path allocates nothing after [`FlowSolver::new`]. The u and v halves of each phase run
//! in parallel (`rayon::join`); called from inside a rayon pool that allocates nothing either.
// The wall treatment (plate, pressure, added mass) is being reworked for plate shapes; its public
// items get their documentation with that work.
#[allow(missing_docs)]
mod added_mass;
mod advance_implicit;
mod array;
mod band;
mod boundary;
mod frame;
mod implicit;
mod metrics;
mod momentum;
#[allow(missing_docs)]
mod plate;
#[allow(missing_docs)]
mod pressure;
mod snapshot;
mod split_cholesky;
mod transport;
mod wake;
// The wall treatment is documented in its module; its public items are reached through
// `FlowSolver::wall`.
#[allow(missing_docs)]
pub mod wall;
mod zones;

pub use added_mass::AddedMass;
pub use array::{Padded, GHOST};
pub use boundary::{OuterBc, VelocityFn};
pub use frame::Frame;
pub use metrics::{Axis, Metrics};
/// The κ = 1/3 limited face value, shared with the three-dimensional solver (`flow3d`).
pub(crate) use momentum::face_value;
pub use plate::BodyAxesLoads;
pub use snapshot::{FlowState, StateMismatch};
pub use zones::PlateCrossing;

use boundary::Outflow;
use implicit::State;
use metrics::Component;
use momentum::RhsContext;
use pressure::Pressure;
use wall::Wall;
use zones::Zones;

use crate::grid::Grid;
use crate::param::{check_range, InputError, Param};

/// How the transport by the grid velocity is stepped away from the plate (docs/physics.md §3).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FarFieldScheme {
    /// Explicit everywhere: Δt is bound by |θ̇| × the extent.
    Explicit,
    /// Implicit along the lines outside the near field: Δt follows the near field.
    #[default]
    Implicit,
}

/// Numerical parameters of the flow solver.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FlowParams {
    /// Reynolds number U c / ν.
    pub re: f64,
    /// Courant number for the convective limit.
    pub cfl: f64,
    /// Fraction of the explicit viscous stability limit used.
    pub visc_safety: f64,
    /// How the grid transport is stepped outside the near field.
    #[serde(default)]
    pub far_field: FarFieldScheme,
    /// Half-widths of the near field (chords): columns with |x| > `near_x` and rows with
    /// |y| > `near_y` take the grid transport along them implicitly.
    #[serde(default = "default_near")]
    pub near_x: f64,
    /// See `near_x`.
    #[serde(default = "default_near")]
    pub near_y: f64,
}

/// The near field's default half-width (chords); see docs/performance.md.
pub const NEAR_DEFAULT: f64 = 1.0;

fn default_near() -> f64 {
    NEAR_DEFAULT
}

impl Default for FlowParams {
    fn default() -> Self {
        FlowParams {
            re: 5000.0,
            cfl: 0.5,
            visc_safety: 0.8,
            far_field: FarFieldScheme::Implicit,
            near_x: NEAR_DEFAULT,
            near_y: NEAR_DEFAULT,
        }
    }
}

impl FlowParams {
    /// Checks every value, naming the first bad one and its accepted range.
    pub fn validate(&self) -> Result<(), InputError> {
        check_range(Param::Reynolds, self.re, 0.0, 1e5, true)?;
        check_range(Param::Cfl, self.cfl, 0.0, 1.0, true)?;
        check_range(Param::NearX, self.near_x, 0.5, 1000.0, false)?;
        check_range(Param::NearY, self.near_y, 0.5, 1000.0, false)
    }

    /// Today's explicit scheme everywhere (the byte-identical baseline).
    pub fn explicit(re: f64) -> FlowParams {
        FlowParams {
            re,
            far_field: FarFieldScheme::Explicit,
            ..FlowParams::default()
        }
    }
}

/// Velocities beyond this multiple of (1 + V + |θ̇|) mean the solution has blown up.
pub const BLOWUP_FACTOR: f64 = 25.0;

/// A body force (x, y, t) ↦ (f_x, f_y) added to the momentum equations (for manufactured solutions).
pub type ForceFn = Box<dyn Fn(f64, f64, f64) -> (f64, f64) + Send + Sync>;

/// Why the flow solver stopped or could not start.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FlowError {
    /// The solution blew up at time `t` (after `step` steps); `reason` says what was seen.
    #[error("the flow solution diverged at t = {t:.4} (step {step}): {reason}")]
    Diverged {
        /// The time of the last good step.
        t: f64,
        /// Steps taken.
        step: u64,
        /// What was seen.
        reason: String,
    },
    /// The solver could not be set up.
    #[error("the flow solver could not be set up: {0}")]
    Setup(SetupError),
}

/// Why the flow solver could not be set up.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SetupError {
    /// The pressure operator could not be assembled or factored; `reason` is the factorisation's
    /// own message.
    #[error("the pressure operator: {reason}")]
    Pressure {
        /// The factorisation's message.
        reason: String,
    },
    /// A line of the implicit far field would cross the plate (its line solves know no wall
    /// inside the domain): the near field must contain the plate.
    #[error(transparent)]
    NearField(zones::PlateCrossing),
}

/// The flow solver: the fields on the body-fixed grid and everything the step needs (see the
/// module docs for the two phases of a step). Its state is read through accessors.
pub struct FlowSolver {
    pub(crate) grid: Grid,
    pub(crate) params: FlowParams,
    pub(crate) metrics: Metrics,
    pub(crate) u: Padded,
    pub(crate) v: Padded,
    /// Pressure at cell centres (zero inside the plate), from the last projection.
    pub(crate) p: Vec<f64>,
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
    pub(crate) frame: Frame,
    /// Motion of the plate at the previous time level (`frame` before the first step); with
    /// `dt_prev` it gives the change of motion the last projection answered ([`AddedMass`]).
    pub(crate) frame_prev: Frame,
    /// The motion at the new time level extrapolated from the two before (the no-slip values
    /// next to the wall follow it, `wall::Wall::impose`).
    guess: Frame,
    /// Current time and the last step taken (0 before the first step).
    pub(crate) t: f64,
    pub(crate) dt_prev: f64,
    pub(crate) steps: u64,
    /// Convective rate max|w|/Δx from the last `prepare`.
    convective_rate: f64,
    dt_visc: f64,
    prepared: bool,
    loads: BodyAxesLoads,
}

impl FlowSolver {
    /// A fluid at rest (u = 0) around a plate moving with `frame` at time 0.
    pub fn new(
        grid: Grid,
        params: FlowParams,
        outer: OuterBc,
        frame: Frame,
    ) -> Result<Self, FlowError> {
        let metrics = Metrics::new(&grid);
        let nu = 1.0 / params.re;
        let wall = Wall::new(&grid, &metrics, nu);
        let pressure = Pressure::new(&grid, &metrics, &wall.faces)
            .map_err(|e| FlowError::Setup(SetupError::Pressure { reason: e.0 }))?;
        let dt_visc = viscous_dt_limit(&grid, &params);
        let (nx, ny) = (grid.nx, grid.ny);
        let (zones, implicit) = far_field_state(&grid, &params, &metrics)?;
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

    /// Phase 1 of a step (see the module docs). Returns the largest stable Δt: the convective and
    /// the explicit viscous limits combined ([`combined_dt_limit`]).
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
            nu: 1.0 / self.params.re,
            zones: &self.zones,
        };
        let stats = momentum::explicit_rhs(&self.u, &self.v, context, &mut self.hu, &mut self.hv);
        self.convective_rate = stats.convective_rate;
        self.wall
            .apply(&self.u, &self.v, &self.frame, &mut self.hu, &mut self.hv);
        if let Some(f) = &self.forcing {
            add_forcing(f, &self.metrics, self.t, &mut self.hu, &mut self.hv);
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

    /// Phase 2 of a step (see the module docs): advance to t + dt with the plate moving as `next`.
    pub fn advance(&mut self, dt: f64, next: Frame) -> Result<(), FlowError> {
        assert!(self.prepared, "FlowSolver::advance called without prepare");
        assert!(
            dt > 0.0 && dt.is_finite(),
            "FlowSolver::advance needs a positive finite dt, got {dt}"
        );
        self.prepared = false;
        let t_next = self.t + dt;
        self.guess = self.frame.extrapolated(&self.frame_prev, dt, self.dt_prev);
        self.frame_prev = self.frame;
        if self.implicit.is_some() {
            self.predict_implicit(dt, next);
            self.project_incremental(dt);
        } else {
            self.predict(dt);
            self.frame = next;
            self.impose_plate();
            self.set_outer_normals(t_next, dt, Outflow::Explicit);
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
        self.wall
            .hold(&mut self.u, &mut self.v, &self.frame, &self.guess);
        self.t = t_next;
        self.dt_prev = dt;
        self.steps += 1;
        self.update_loads()
    }

    /// The predictor u* = uⁿ + Δt[(1 + r/2)Hⁿ − (r/2)Hⁿ⁻¹] on the interior faces (variable-step
    /// AB2, r = Δt/Δtⁿ⁻¹; Euler on the first step); Hⁿ becomes the old right-hand side.
    fn predict(&mut self, dt: f64) {
        let (c_new, c_old) = if self.steps == 0 {
            (1.0, 0.0)
        } else {
            let r = dt / self.dt_prev;
            (1.0 + 0.5 * r, -0.5 * r)
        };
        let (nx, ny) = (self.grid.nx as isize, self.grid.ny as isize);
        let update = |vel: &mut Padded, h: &Padded, h_old: &Padded, is, js| {
            for j in js {
                for i in std::ops::Range::clone(&is) {
                    let k = vel.at(i, j);
                    vel.data[k] += dt * (c_new * h.data[k] + c_old * h_old.data[k]);
                }
            }
        };
        update(&mut self.u, &self.hu, &self.hu_old, 1..nx, 0..ny);
        update(&mut self.v, &self.hv, &self.hv_old, 0..nx, 1..ny);
        std::mem::swap(&mut self.hu, &mut self.hu_old);
        std::mem::swap(&mut self.hv, &mut self.hv_old);
    }

    /// The outer boundary's normal velocities at `t` for the current frame, net flux removed.
    pub(super) fn set_outer_normals(&mut self, t: f64, dt: f64, outflow: Outflow) {
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

    /// The loads on the plate after a projection; an error if they are not finite.
    fn update_loads(&mut self) -> Result<(), FlowError> {
        self.loads = self
            .wall
            .loads(&self.u, &self.v, &self.p, &self.frame, self.params.re);
        let l = &self.loads;
        if !(l.fx.is_finite() && l.fy.is_finite() && l.moment.is_finite()) {
            return Err(self.diverged("the force on the plate is not finite"));
        }
        Ok(())
    }

    /// No-slip: the held faces take the grid-point velocity g of this frame, the forced points
    /// their values between the wall and the fluid (`wall::stencils`).
    pub(super) fn impose_plate(&mut self) {
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

    /// Loads on the plate at the current time level.
    pub fn loads(&self) -> BodyAxesLoads {
        self.loads
    }

    /// C_L, C_D, C_M at the current time level (docs/physics.md §5).
    pub fn coefficients(&self) -> (f64, f64, f64) {
        plate::coefficients(&self.loads, &self.frame)
    }

    /// The body-fixed grid.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// The numerical parameters.
    pub fn params(&self) -> &FlowParams {
        &self.params
    }

    /// The grid's metrics (face and centre coordinates, spacings).
    pub fn metrics(&self) -> &Metrics {
        &self.metrics
    }

    /// The x-velocity on vertical faces, with its ghost layer.
    pub fn u(&self) -> &Padded {
        &self.u
    }

    /// The y-velocity on horizontal faces, with its ghost layer.
    pub fn v(&self) -> &Padded {
        &self.v
    }

    /// The pressure at cell centres (zero inside the plate), from the last projection; index
    /// i + nx j.
    pub fn p(&self) -> &[f64] {
        &self.p
    }

    /// The plate's motion at the current time level.
    pub fn frame(&self) -> &Frame {
        &self.frame
    }

    /// The plate's motion at the previous time level.
    pub fn frame_prev(&self) -> &Frame {
        &self.frame_prev
    }

    /// The current time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// The last step taken (0 before the first step).
    pub fn dt_prev(&self) -> f64 {
        self.dt_prev
    }

    /// Steps taken.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Largest |∇·u| over the pressure cells (the fluid's outflow divided by the cell's area).
    pub fn max_divergence(&self) -> f64 {
        let g = &self.grid;
        let fluid = &self.wall.faces.fluid;
        let mut flux: Vec<f64> = (0..g.cells())
            .map(|k| {
                let (i, j) = (k % g.nx, k / g.nx);
                Pressure::cell_flux(&self.u, &self.v, g, i, j)
            })
            .collect();
        self.wall
            .cut_flux(&self.u, &self.v, &self.frame, &mut |k, add| flux[k] += add);
        (0..g.cells())
            .filter(|&k| fluid[k])
            .map(|k| (flux[k] / (g.dx[k % g.nx] * g.dy[k / g.nx])).abs())
            .fold(0.0, f64::max)
    }

    /// The plate's description in the grid (faces, near-wall stencils, load samples).
    pub fn wall(&self) -> &Wall {
        &self.wall
    }

    /// Largest |u|, |v| over all faces.
    pub fn max_velocity(&self) -> f64 {
        self.u.max_abs_interior().max(self.v.max_abs_interior())
    }

    /// Number of pressure unknowns and nonzeros of the Cholesky factor.
    pub fn pressure_size(&self) -> (usize, usize) {
        (self.pressure.unknowns(), self.pressure.factor_nnz())
    }

    /// Interior u on vertical faces ((nx+1) × ny) and v on horizontal faces (nx × (ny+1)).
    pub fn velocity_arrays(&self) -> (Vec<f64>, Vec<f64>) {
        (self.u.interior(), self.v.interior())
    }
}

/// The split lines and the implicit workspaces for the far-field scheme of `params` (none for
/// the explicit scheme); the split lines must not cross the plate.
/// The explicit viscous limit of the flow step, `visc_safety / (4ν (1/Δx² + 1/Δy²))` on the
/// smallest cells (docs/physics.md §6 "Time step").
pub fn viscous_dt_limit(grid: &Grid, params: &FlowParams) -> f64 {
    let min = |v: &[f64]| v.iter().copied().fold(f64::INFINITY, f64::min);
    let (dx, dy) = (min(&grid.dx), min(&grid.dy));
    let nu = 1.0 / params.re;
    params.visc_safety / (4.0 * nu * (1.0 / (dx * dx) + 1.0 / (dy * dy)))
}

/// The largest stable Δt of the explicit (Adams–Bashforth 2) near field, docs/physics.md §6 "Time step":
/// the harmonic combination 1/Δt = 1/Δt_conv + 1/Δt_visc of the convective limit
/// Δt_conv = CFL / max(|w_x|/Δx + |w_y|/Δy) (`rate`: that maximum) and the viscous limit.
///
/// AB2 is stable on the negative real axis only down to λΔt = −1, and the grid's odd–even mode
/// feels both terms at once: the viscous term gives it −8ν/h² (−0.8/Δt at the viscous limit
/// with its safety 0.8) and the upwind-limited convection −2 × rate (−1/Δt at CFL ½). Each
/// limit alone keeps its own part inside, but the minimum of the two does not keep the sum
/// inside where both are close (Re ≈ 40 at N = 32: an odd–even pattern in time and space next to
/// a wall); the harmonic combination does: 0.8 Δt/Δt_visc + 2 CFL Δt/Δt_conv ≤ 1 for CFL ≤ ½.
/// Where one limit is far below the other (the card's Re 4770: the viscous limit is ≈ 40 times the
/// convective one at N = 64) the combination costs a few per cent of the step.
pub fn combined_dt_limit(cfl: f64, rate: f64, dt_visc: f64) -> f64 {
    let inv = rate / cfl + 1.0 / dt_visc;
    if inv > 0.0 {
        1.0 / inv
    } else {
        f64::INFINITY
    }
}

fn far_field_state(
    grid: &Grid,
    params: &FlowParams,
    metrics: &Metrics,
) -> Result<(Zones, Option<Box<State>>), FlowError> {
    match params.far_field {
        FarFieldScheme::Explicit => Ok((Zones::none(grid), None)),
        FarFieldScheme::Implicit => {
            let z = Zones::new(grid, params.near_x, params.near_y);
            z.check_plate(grid)
                .map_err(|e| FlowError::Setup(SetupError::NearField(e)))?;
            let state = State::new(grid.nx, grid.ny, metrics);
            Ok((z, Some(Box::new(state))))
        }
    }
}

/// Adds f(x, y, t) at every interior face to H.
fn add_forcing(f: &ForceFn, m: &Metrics, t: f64, hu: &mut Padded, hv: &mut Padded) {
    let (nx, ny) = (hv.ni as isize, hu.nj as isize);
    m.for_faces(Component::U, 1..nx, 0..ny, |i, j, x, y| {
        let k = hu.at(i, j);
        hu.data[k] += f(x, y, t).0;
    });
    m.for_faces(Component::V, 0..nx, 1..ny, |i, j, x, y| {
        let k = hv.at(i, j);
        hv.data[k] += f(x, y, t).1;
    });
}
