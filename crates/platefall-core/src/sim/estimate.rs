//! What a run will cost, estimated from its description alone before anything large is
//! allocated: cells, the pressure factor's size, memory, and a floor under the number of steps.
//! The grid's coordinates are cheap to build (O(nx + ny)); the flow solver and its Cholesky
//! factor are not, so the command line checks this estimate first (`src/cli/limits.rs`).
//!
//! The constants were measured on this code (docs/performance.md, "Memory", lists the runs and the
//! errors of the fits):
//! - factor nonzeros per cell ≈ 12.38 ln(min(nx, ny)) − 36.9 (faer's simplicial Cholesky with
//!   an AMD ordering; least-squares over 15 grids of 4 452 to 3.67 M cells, within ±11 % above
//!   10⁴ cells; the split order of `flow/split_cholesky.rs` adds 2–4 %);
//! - peak resident memory ≈ 8 MB + 180 B per cell + 12 B per factor nonzero (an f64 value and a
//!   u32 row index), plus 16 MB and 24 B per cell per queued field snapshot with a Rerun sink;
//! - a step costs ≈ 120 ns per cell (`platefall bench`, docs/performance.md).
use super::spec::ValidatedConfig;

/// Fixed memory of the program without a recording (bytes).
const BASE_BYTES: f64 = 8e6;
/// Solver memory per cell besides the factor: velocities, right-hand sides, metrics, pressure.
const BYTES_PER_CELL: f64 = 180.0;
/// Factor memory per nonzero: an f64 value and a u32 row index.
const BYTES_PER_NONZERO: f64 = 12.0;
/// Rerun SDK and the painter when a recording or stream is open.
const RECORDING_BYTES: f64 = 16e6;
/// One field snapshot in flight to the logger: u, v and p.
const SNAPSHOT_BYTES_PER_CELL: f64 = 24.0;
/// Cost of a step per cell (ns), for time estimates only.
pub const NS_PER_CELL_STEP: f64 = 120.0;
/// The factor's row indices are u32: it cannot hold more nonzeros than this.
pub const FACTOR_NONZERO_LIMIT: f64 = u32::MAX as f64;

/// The smallest time step the run can be forced down to, and why.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DtFloor {
    /// The time-step ceiling `dt_max`.
    Ceiling,
    /// The explicit viscous limit (∝ Re h²).
    Viscous,
}

/// The cost of a run, estimated from its description.
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    /// Cells along x.
    pub nx: usize,
    /// Cells along y.
    pub ny: usize,
    /// nx × ny.
    pub cells: u64,
    /// Nonzeros of the pressure Cholesky factor (estimated).
    pub factor_nonzeros: f64,
    /// The largest Δt any step may take: min(ceiling, viscous limit).
    pub dt_floor: f64,
    /// Which limit the floor is.
    pub dt_floor_from: DtFloor,
    /// At least this many steps reach t_end (the convective limit and the rotation rule only
    /// add steps).
    pub steps_min: f64,
}

impl Estimate {
    /// Peak resident memory in bytes; `snapshots_in_flight` is None without a Rerun sink.
    pub fn memory_bytes(&self, snapshots_in_flight: Option<usize>) -> f64 {
        let cells = self.cells as f64;
        let solver = BASE_BYTES + BYTES_PER_CELL * cells + BYTES_PER_NONZERO * self.factor_nonzeros;
        let recording = snapshots_in_flight.map_or(0.0, |n| {
            RECORDING_BYTES + n as f64 * SNAPSHOT_BYTES_PER_CELL * cells
        });
        solver + recording
    }

    /// Wall time of `steps_min` steps at [`NS_PER_CELL_STEP`] (seconds).
    pub fn seconds_min(&self) -> f64 {
        self.steps_min * self.cells as f64 * NS_PER_CELL_STEP * 1e-9
    }
}

/// Nonzeros of the pressure factor of an nx × ny grid (the fit above; at least 8 per cell).
pub fn factor_nonzeros(nx: usize, ny: usize) -> f64 {
    let per_cell = 12.38 * (nx.min(ny).max(2) as f64).ln() - 36.9;
    per_cell.max(8.0) * nx as f64 * ny as f64
}

/// Estimates a run's cost from its description and grid (nothing else is built).
pub fn estimate(config: &ValidatedConfig) -> Estimate {
    let grid = config.grid();
    let visc = crate::flow::viscous_dt_limit(grid, &config.flow);
    let (dt_floor, dt_floor_from) = if visc < config.time.dt_max {
        (visc, DtFloor::Viscous)
    } else {
        (config.time.dt_max, DtFloor::Ceiling)
    };
    Estimate {
        nx: grid.nx,
        ny: grid.ny,
        cells: grid.nx as u64 * grid.ny as u64,
        factor_nonzeros: factor_nonzeros(grid.nx, grid.ny),
        dt_floor,
        dt_floor_from,
        steps_min: (config.time.t_end / dt_floor).ceil(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::GridSpec;
    use crate::sim::{Case, RunConfig};

    #[test]
    fn a_tiny_reynolds_number_implies_an_astronomical_step_count() {
        let mut c = RunConfig::new(
            Case::Static {
                alpha: 0.4,
                kick: 0.0,
            },
            GridSpec::modern(16),
        );
        let e = estimate(&c.clone().validate().unwrap());
        assert_eq!((e.nx, e.ny, e.cells), (130, 115, 14950));
        assert_eq!(e.dt_floor_from, DtFloor::Ceiling);
        assert_eq!(e.steps_min, 8000.0);
        c.flow.re = 1e-300;
        let e = estimate(&c.validate().unwrap());
        assert_eq!(e.dt_floor_from, DtFloor::Viscous);
        assert!(e.steps_min > 1e300, "{}", e.steps_min);
    }
}
