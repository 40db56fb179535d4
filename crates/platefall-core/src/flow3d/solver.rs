//! [`FlowSolver3`]: the fields on the body-fixed 3-D grid and one step of the mixed-frame
//! equations (docs/physics.md §9), in the 2-D solver's order: begin_step → predict →
//! impose_boundaries → project → end_step → update_loads.
use super::added_mass::{AddedMass3, UnitResponses};
use super::boundary::{Outer, OuterBc3};
use super::coefficients::Coefficients3;
use super::error::{Flow3Error, BLOWUP_FACTOR};
use super::frame::Frame3;
use super::grid::Grid3;
use super::layout::Layout;
use super::loads::{LoadInput, Loads3};
use super::metrics::Metrics3;
use super::momentum::{explicit_rhs, RhsContext, RhsStats};
use super::multigrid::MultigridCg;
use super::params::FlowParams3;
use super::phases::{Phase3, PhaseMarker};
use super::plate::Plate;
use super::project::{
    cell_fluxes, correct, pressure_rhs, PoissonOperator, PoissonSolve, SolveStats, Stop,
};
use crate::flow::Ab2;

/// The outer boundary's view of the solver's fields (a macro: the borrows stay per field).
macro_rules! outer {
    ($s:expr) => {
        Outer {
            m: &$s.metrics,
            layout: &$s.layout,
            frame: &$s.frame,
            bc: &$s.outer,
            periodic_z: $s.grid.periodic_z,
        }
    };
}

/// A body force (x, t) ↦ f added to the momentum equations (manufactured solutions).
pub type ForceFn3 = Box<dyn Fn([f64; 3], f64) -> [f64; 3] + Send + Sync>;

/// The three-dimensional flow solver.
pub struct FlowSolver3 {
    pub(super) grid: Grid3,
    params: FlowParams3,
    metrics: Metrics3,
    layout: Layout,
    pub(super) vel: [Vec<f64>; 3],
    h: [Vec<f64>; 3],
    pub(super) h_old: [Vec<f64>; 3],
    /// Cell pressures (zero in the plate), index i + nx (j + ny k).
    pub(super) p: Vec<f64>,
    /// The pressures of the level before (the warm start's extrapolation).
    pub(super) p_old: Vec<f64>,
    /// The pressure's increment over the step, the projection's unknown.
    phi: Vec<f64>,
    /// The pressure equation's right-hand side and the divergence weights Δt / V.
    rhs: Vec<f64>,
    weight: Vec<f64>,
    pressure: Box<dyn PoissonSolve>,
    plate: Plate,
    outer: OuterBc3,
    forcing: Option<ForceFn3>,
    pub(super) frame: Frame3,
    pub(super) t: f64,
    pub(super) dt_prev: f64,
    pub(super) steps: u64,
    pub(super) rhs_stats: RhsStats,
    pub(super) solve_stats: SolveStats,
    dt_visc: f64,
    pub(super) loads: Loads3,
    marker: Option<PhaseMarker>,
}

impl FlowSolver3 {
    /// A fluid at rest around the plate moving with `frame` at time 0.
    pub fn new(
        grid: Grid3,
        params: FlowParams3,
        outer: OuterBc3,
        frame: Frame3,
    ) -> Result<FlowSolver3, Flow3Error> {
        params.validate()?;
        let metrics = Metrics3::new(&grid);
        let layout = Layout::new(grid.n);
        let nu = 1.0 / params.re;
        let plate = Plate::new(&grid, &metrics, &layout, nu);
        let mut op = PoissonOperator::new(&grid, &metrics);
        plate.shape_operator(&mut op);
        let cells = grid.cells();
        let min = grid.min_spacing();
        let dt_visc =
            params.visc_safety / (4.0 * nu * min.iter().map(|d| 1.0 / (d * d)).sum::<f64>());
        let mut s = FlowSolver3 {
            plate,
            vel: std::array::from_fn(|_| layout.zeros()),
            h: std::array::from_fn(|_| layout.zeros()),
            h_old: std::array::from_fn(|_| layout.zeros()),
            p: vec![0.0; cells],
            p_old: vec![0.0; cells],
            phi: vec![0.0; cells],
            rhs: vec![0.0; cells],
            weight: vec![0.0; cells],
            pressure: Box::new(MultigridCg::new(op)?),
            outer,
            forcing: None,
            frame,
            t: 0.0,
            dt_prev: 0.0,
            steps: 0,
            rhs_stats: RhsStats::default(),
            solve_stats: SolveStats::default(),
            dt_visc,
            loads: Loads3::default(),
            marker: None,
            grid,
            params,
            metrics,
            layout,
        };
        s.plate.hold(&mut s.vel, &s.metrics, &s.layout, &s.frame);
        Ok(s)
    }

    /// Replaces the pressure solver ([`MultigridCg`] by default) with one built from the same
    /// operator, e.g. [`super::JacobiCg::new`] as a reference.
    pub fn set_pressure_solver(
        &mut self,
        make: impl FnOnce(PoissonOperator) -> Box<dyn PoissonSolve>,
    ) {
        let op = self.pressure.operator().clone();
        self.pressure = make(op);
    }

    /// Adds a body force to the momentum equations.
    pub fn set_forcing(&mut self, f: ForceFn3) {
        self.forcing = Some(f);
    }

    /// Sets every point of component c to `f(x)[c]` (ghosts included), then the plate to g. Not
    /// projected: give a divergence-free field.
    pub fn set_velocity(&mut self, f: impl Fn([f64; 3]) -> [f64; 3]) {
        let lay = self.layout;
        for (c, q) in self.vel.iter_mut().enumerate() {
            for (idx, v) in q.iter_mut().enumerate() {
                let p = lay.point(idx);
                if (0..3).all(|a| p[a] < lay.points(c, a) + super::layout::G as isize) {
                    *v = f(self.metrics.position(c, p))[c];
                }
            }
        }
        if self.grid.periodic_z {
            outer!(self).fill_ghosts(&mut self.vel, self.t);
        }
        self.plate
            .hold(&mut self.vel, &self.metrics, &self.layout, &self.frame);
    }

    /// One step to t + dt with the body moving as `next` at the new time level.
    pub fn advance(&mut self, dt: f64, next: Frame3) -> Result<(), Flow3Error> {
        if !(dt > 0.0 && dt.is_finite()) {
            return Err(Flow3Error::BadStep { dt });
        }
        self.mark(Phase3::Begin);
        self.begin_step()?;
        self.mark(Phase3::RightHandSide);
        self.predict(dt);
        self.mark(Phase3::Predictor);
        self.impose_boundaries(dt, next);
        self.mark(Phase3::Boundaries);
        self.project(dt)?;
        self.mark(Phase3::Pressure);
        self.end_step(dt);
        self.update_loads()?;
        self.mark(Phase3::Loads);
        Ok(())
    }

    /// Installs `marker`, called at every phase boundary of [`FlowSolver3::advance`] (to time
    /// the phases: the solver reads no clock).
    pub fn set_phase_marker(&mut self, marker: PhaseMarker) {
        self.marker = Some(marker);
    }

    fn mark(&mut self, phase: Phase3) {
        if let Some(m) = &mut self.marker {
            m(phase);
        }
    }

    /// Ghost values and the explicit right-hand side Hⁿ of the state at tⁿ.
    pub fn begin_step(&mut self) -> Result<(), Flow3Error> {
        outer!(self).fill_ghosts(&mut self.vel, self.t);
        let vel = [&self.vel[0][..], &self.vel[1][..], &self.vel[2][..]];
        let context = RhsContext {
            m: &self.metrics,
            layout: &self.layout,
            frame: &self.frame,
            nu: 1.0 / self.params.re,
            periodic_z: self.grid.periodic_z,
        };
        let [h0, h1, h2] = &mut self.h;
        self.rhs_stats = explicit_rhs(vel, context, [h0, h1, h2]);
        let [h0, h1, h2] = &mut self.h;
        self.plate.correct_diffusion([h0, h1, h2], vel, &self.frame);
        if let Some(f) = &self.forcing {
            add_forcing(
                f,
                &self.metrics,
                &self.layout,
                self.t,
                &mut self.h,
                self.grid.periodic_z,
            );
        }
        let bound = BLOWUP_FACTOR * (1.0 + self.max_grid_speed());
        let seen = self.rhs_stats.max_speed;
        if seen.is_nan() || seen > bound || !self.rhs_stats.convective_rate.is_finite() {
            return Err(self.diverged(format!(
                "the largest velocity {seen:.3e} exceeds {bound:.1} = {BLOWUP_FACTOR} × (1 + |g|max)"
            )));
        }
        Ok(())
    }

    /// u* = uⁿ + Δt[(1 + r/2)Hⁿ − (r/2)Hⁿ⁻¹ − ∇pⁿ] (variable-step AB2, r = Δt/Δtⁿ⁻¹; Euler on
    /// the first step). H is zero outside the interior points, so those keep their values; the
    /// old pressure's gradient acts where the projection's does.
    fn predict(&mut self, dt: f64) {
        let dt_prev = if self.steps == 0 { 0.0 } else { self.dt_prev };
        let Ab2 {
            new: c_new,
            old: c_old,
        } = Ab2::new(dt, dt_prev);
        use rayon::prelude::*;
        for c in 0..3 {
            let (h, h_old) = (&self.h[c], &self.h_old[c]);
            self.vel[c]
                .par_iter_mut()
                .zip(h.par_iter().zip(h_old.par_iter()))
                .for_each(|(u, (h, ho))| *u += dt * (c_new * h + c_old * ho));
        }
        let op = self.pressure.operator();
        correct(&mut self.vel, &self.metrics, &self.layout, op, &self.p, dt);
    }

    /// The frame of the new level, no slip on the plate and the outer normals at tⁿ⁺¹.
    fn impose_boundaries(&mut self, dt: f64, next: Frame3) {
        self.frame = next;
        if self.grid.periodic_z {
            // The w face nz is face 0.
            let lay = self.layout;
            let nz = lay.n[2] as isize;
            for j in 0..lay.n[1] as isize {
                for i in 0..lay.n[0] as isize {
                    let v = self.vel[2][lay.at([i, j, 0])];
                    self.vel[2][lay.at([i, j, nz])] = v;
                }
            }
        }
        self.plate
            .impose(&mut self.vel, &self.metrics, &self.layout, &self.frame);
        outer!(self).set_normals(&mut self.vel, self.t + dt, dt);
    }

    /// Solves for the increment φ = pⁿ⁺¹ − pⁿ and corrects the velocity (an incremental
    /// projection, docs/three-d.md "The step"). The solve starts from the last increment scaled
    /// to this step, (Δt / Δtⁿ⁻¹)(pⁿ − pⁿ⁻¹) (zero on the first step).
    ///
    /// The predictor carries the old gradient, so the projection only adds the pressure's change:
    /// values imposed next to a curved wall (held and forced points, `cut.rs`) that differ from
    /// what the last projection left by O(Δt ∇φ) then disturb the new pressure by O(Δt), where a
    /// projection for the whole pressure would carry that difference over Δt.
    fn project(&mut self, dt: f64) -> Result<(), Flow3Error> {
        let ratio = if self.steps > 0 {
            dt / self.dt_prev
        } else {
            0.0
        };
        for ((phi, p), old) in self.phi.iter_mut().zip(&self.p).zip(&self.p_old) {
            *phi = ratio * (p - old);
        }
        let vel = [&self.vel[0][..], &self.vel[1][..], &self.vel[2][..]];
        let op = self.pressure.operator();
        cell_fluxes(vel, &self.metrics, &self.layout, op, &mut self.rhs);
        self.plate
            .cut_flux(vel, &self.frame, &op.diag, &mut self.rhs);
        pressure_rhs(op, dt, &mut self.rhs, &mut self.weight);
        let stop = Stop {
            weight: &self.weight,
            tol: self.params.div_tol,
            max_iterations: self.params.max_iterations,
        };
        self.solve_stats = self.pressure.solve(&self.rhs, &mut self.phi, stop);
        if !self.solve_stats.converged {
            return Err(Flow3Error::PressureNotConverged {
                iterations: self.solve_stats.iterations,
                divergence: self.solve_stats.divergence,
                tolerance: self.params.div_tol,
            });
        }
        let op = self.pressure.operator();
        correct(
            &mut self.vel,
            &self.metrics,
            &self.layout,
            op,
            &self.phi,
            dt,
        );
        for ((p, old), phi) in self.p.iter_mut().zip(self.p_old.iter_mut()).zip(&self.phi) {
            *old = *p;
            *p += phi;
        }
        self.plate.settle_pressure(&mut self.p);
        Ok(())
    }

    /// Hⁿ becomes the old right-hand side; the clock moves on.
    fn end_step(&mut self, dt: f64) {
        std::mem::swap(&mut self.h, &mut self.h_old);
        self.t += dt;
        self.dt_prev = dt;
        self.steps += 1;
    }

    /// The loads at the new level; an error if they are not finite.
    fn update_loads(&mut self) -> Result<(), Flow3Error> {
        self.loads = self.loads_for(&self.p);
        if !self.loads.is_finite() {
            return Err(self.diverged("the force on the plate is not finite".to_string()));
        }
        Ok(())
    }

    fn diverged(&self, reason: String) -> Flow3Error {
        Flow3Error::Diverged {
            t: self.t,
            step: self.steps,
            reason,
        }
    }

    /// Largest |g| over the domain.
    fn max_grid_speed(&self) -> f64 {
        let nodes = &self.grid.nodes;
        let lo = std::array::from_fn(|a| nodes[a][0]);
        let hi = std::array::from_fn(|a| nodes[a][nodes[a].len() - 1]);
        self.frame.max_speed_over(lo, hi)
    }

    /// The largest stable Δt from the last right-hand side: 1/Δt = rate/CFL + 1/Δt_visc
    /// (the 2-D solver's harmonic combination).
    pub fn stable_dt(&self) -> f64 {
        crate::flow::combined_dt_limit(
            self.params.cfl,
            self.rhs_stats.convective_rate,
            self.dt_visc,
        )
    }

    /// The flow's added-mass matrix K from six projections of the unit motions with this
    /// solver's own operator and pressure solver (set-up cost only; the flow is not touched).
    ///
    /// # Errors
    /// [`Flow3Error::PressureNotConverged`] when a solve does not reach the divergence tolerance.
    pub fn added_mass(&mut self) -> Result<AddedMass3, Flow3Error> {
        UnitResponses {
            grid: &self.grid,
            metrics: &self.metrics,
            layout: &self.layout,
            plate: &self.plate,
            pressure: self.pressure.as_mut(),
            max_iterations: self.params.max_iterations,
        }
        .added_mass()
    }

    /// Largest |∇·u| over the fluid cells.
    pub fn max_divergence(&self) -> f64 {
        let op = self.pressure.operator();
        let mut worst: f64 = 0.0;
        let vel = [&self.vel[0][..], &self.vel[1][..], &self.vel[2][..]];
        let mut div = vec![0.0; op.cells()];
        cell_fluxes(vel, &self.metrics, &self.layout, op, &mut div);
        self.plate.cut_flux(vel, &self.frame, &op.diag, &mut div);
        for (d, v) in div.iter().zip(&op.volume) {
            worst = worst.max((d / v).abs());
        }
        worst
    }

    /// The loads at the current level.
    pub fn loads(&self) -> Loads3 {
        self.loads
    }

    /// The loads the plate's read-out gives for the cell pressures `p` (index as [`Self::p`])
    /// with the current velocities: for comparing read-outs and pressure fields (the solver's own
    /// loads are those of its own pressure).
    pub fn loads_for(&self, p: &[f64]) -> Loads3 {
        self.plate.loads(&LoadInput {
            grid: &self.grid,
            m: &self.metrics,
            layout: &self.layout,
            vel: [&self.vel[0], &self.vel[1], &self.vel[2]],
            p,
            frame: &self.frame,
            nu: 1.0 / self.params.re,
        })
    }

    /// The loads at the current level as coefficients (lift, drag, side force; roll, yaw, pitch)
    /// on the body's planform area (the span, or the period of a periodic span, for a plate).
    pub fn coefficients(&self) -> Coefficients3 {
        Coefficients3::new(&self.loads, &self.frame, self.grid.planform_area())
    }

    /// The grid.
    pub fn grid(&self) -> &Grid3 {
        &self.grid
    }

    /// The metrics (coordinates and stencil coefficients).
    pub fn metrics(&self) -> &Metrics3 {
        &self.metrics
    }

    /// The array layout.
    pub fn layout(&self) -> &Layout {
        &self.layout
    }

    /// The velocity components (padded arrays, see [`Layout`]).
    pub fn velocity(&self) -> &[Vec<f64>; 3] {
        &self.vel
    }

    /// The right-hand side H of the last `begin_step` (before it is swapped: after `advance`
    /// it is the old one).
    pub fn rhs(&self) -> &[Vec<f64>; 3] {
        &self.h
    }

    /// The last right-hand side's statistics: (convective rate, largest velocity).
    pub fn rhs_stats(&self) -> (f64, f64) {
        (self.rhs_stats.convective_rate, self.rhs_stats.max_speed)
    }

    /// Cell pressures, index i + nx (j + ny k).
    pub fn p(&self) -> &[f64] {
        &self.p
    }

    /// The last pressure solve.
    pub fn solve_stats(&self) -> SolveStats {
        self.solve_stats
    }

    /// The current time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Steps taken.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The motion at the current level.
    pub fn frame(&self) -> &Frame3 {
        &self.frame
    }

    /// Whether point p of component c is held by the plate.
    pub fn is_held(&self, c: usize, p: [isize; 3]) -> bool {
        self.plate.is_held(c, p)
    }
}

/// Adds f(x, t) at every interior point to H.
fn add_forcing(
    f: &ForceFn3,
    m: &Metrics3,
    lay: &Layout,
    t: f64,
    h: &mut [Vec<f64>; 3],
    periodic_z: bool,
) {
    for (c, hc) in h.iter_mut().enumerate() {
        let first = |a: usize| isize::from(a == c && !(a == 2 && periodic_z));
        let last = |a: usize| lay.n[a] as isize;
        for k in first(2)..last(2) {
            for j in first(1)..last(1) {
                for i in first(0)..last(0) {
                    let p = [i, j, k];
                    hc[lay.at(p)] += f(m.position(c, p), t)[c];
                }
            }
        }
    }
}
