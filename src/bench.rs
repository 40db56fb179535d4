//! `platefall bench`: times the flow step alone (prescribed motion, no output, one thread) on
//! several grids and reports nanoseconds per cell per step, split into the explicit momentum phase
//! ([`FlowSolver::prepare`]) and the projection phase ([`FlowSolver::advance`]: predictor, boundary
//! values, pressure solve, velocity correction, loads).
use std::time::Instant;

use serde::Serialize;

use crate::flow::{FlowParams, FlowSolver, OuterBc};
use crate::grid::{Grid, GridSpec};
use crate::sim::{Case, SimError};

#[derive(Clone, Debug, Serialize)]
pub struct BenchRow {
    pub resolution: usize,
    pub nx: usize,
    pub ny: usize,
    pub cells: usize,
    pub factor_nnz: usize,
    pub setup_seconds: f64,
    pub steps: usize,
    pub momentum_ns_per_cell: f64,
    pub pressure_ns_per_cell: f64,
    pub total_ns_per_cell: f64,
}

/// Times `steps` steps of a plate translating at α = 0.4 and spinning at θ̇ = 1 (so every term of the
/// mixed-frame equations is active) after 5 warm-up steps.
pub fn bench_one(resolution: usize, steps: usize) -> Result<BenchRow, SimError> {
    let spec = GridSpec::modern(resolution);
    let grid = Grid::new(&spec)?;
    let (nx, ny, cells) = (grid.nx, grid.ny, grid.cells());
    let case = Case::Forced {
        omega: 1.0,
        spinup: 0.0,
    };
    let t0 = Instant::now();
    let mut flow = FlowSolver::new(
        grid,
        FlowParams::default(),
        OuterBc::FarField,
        case.prescribed_state(0.4).frame(),
    )?;
    let setup_seconds = t0.elapsed().as_secs_f64();
    let (mut t_mom, mut t_proj) = (0.0, 0.0);
    for k in 0..steps + 5 {
        let a = Instant::now();
        let limit = flow.prepare()?;
        let b = Instant::now();
        let dt = limit.min(0.01);
        let next = case.prescribed_state(0.4 + flow.t + dt).frame();
        flow.advance(dt, next)?;
        let c = Instant::now();
        if k >= 5 {
            t_mom += (b - a).as_secs_f64();
            t_proj += (c - b).as_secs_f64();
        }
    }
    let per = 1e9 / (steps as f64 * cells as f64);
    Ok(BenchRow {
        resolution,
        nx,
        ny,
        cells,
        factor_nnz: flow.pressure_size().1,
        setup_seconds,
        steps,
        momentum_ns_per_cell: t_mom * per,
        pressure_ns_per_cell: t_proj * per,
        total_ns_per_cell: (t_mom + t_proj) * per,
    })
}

/// A plain-text table of the rows.
pub fn table(rows: &[BenchRow]) -> String {
    let mut s = String::from(
        "   N      grid     cells  factor nnz  setup s   momentum  projection     total   (ns per cell per step)\n",
    );
    for r in rows {
        s.push_str(&format!(
            "{:4} {:4}x{:<4} {:8} {:11} {:8.2} {:10.1} {:11.1} {:9.1}\n",
            r.resolution,
            r.nx,
            r.ny,
            r.cells,
            r.factor_nnz,
            r.setup_seconds,
            r.momentum_ns_per_cell,
            r.pressure_ns_per_cell,
            r.total_ns_per_cell
        ));
    }
    s
}
