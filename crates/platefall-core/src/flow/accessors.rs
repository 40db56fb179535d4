//! What the flow solver tells about its state: fields, motion, time, loads and sizes.
use super::array::Padded;
use super::frame::Frame;
use super::metrics::Metrics;
use super::params::FlowParams;
use super::plate::{self, BodyAxesLoads};
use super::pressure::Pressure;
use super::FlowSolver;
use crate::grid::Grid;

impl FlowSolver {
    /// Loads on the plate at the current time level.
    pub fn loads(&self) -> BodyAxesLoads {
        self.loads
    }

    /// The loads the plate's read-out gives for the cell pressures `p` (index as [`Self::p`])
    /// with the current velocities: for comparing read-outs and pressure fields (the solver's own
    /// loads are those of its own pressure).
    pub fn loads_for(&self, p: &[f64]) -> BodyAxesLoads {
        self.wall
            .loads(&self.u, &self.v, p, &self.frame, self.params.nu())
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

    /// Whether each cell (index i + nx j) is fluid, i.e. carries a pressure; the plate's cells
    /// do not.
    pub fn fluid_cells(&self) -> &[bool] {
        &self.wall.faces.fluid
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
