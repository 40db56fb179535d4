//! `platefall bench --span …`: what a step of the three-dimensional flow costs (docs/performance.md
//! "Three-dimensional step").
//!
//! [`bench_one3`] times the 3-D step alone (prescribed motion, no output) on the card's plate
//! (thickness 1/16) with a finite or periodic span: nanoseconds per cell per step, the pressure
//! solver's iterations per step and the memory the solver took per cell (resident set growth
//! while it was built, Linux only).
use std::time::Instant;

use serde::Serialize;

use crate::pool;
use platefall_core::flow3d::{
    Flow3Error, FlowParams3, FlowSolver3, Frame3, Grid3, GridSpec3, OuterBc3, Span, Stretch3,
};

/// The plate's thickness (chords): the dissertation's card.
const THICKNESS: f64 = 1.0 / 16.0;
/// Distance to the outer boundary along each axis (chords).
const EXTENT: f64 = 5.0;
/// Largest ratio of neighbouring cell widths.
const GROWTH: f64 = 1.1;
/// Largest memory a benchmark grid may take (bytes).
const MEMORY_LIMIT: f64 = 16e9;
/// Steps run before timing.
const WARM_UP: usize = 3;

/// One grid's measurement.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct Bench3Row {
    pub(crate) resolution: usize,
    pub(crate) span: Span,
    pub(crate) n: [usize; 3],
    pub(crate) cells: usize,
    pub(crate) setup_seconds: f64,
    pub(crate) steps: usize,
    pub(crate) threads: usize,
    pub(crate) iterations_per_step: f64,
    pub(crate) total_ns_per_cell: f64,
    pub(crate) bytes_per_cell: Option<f64>,
}

/// Times `steps` steps of the plate translating at α = 0.4 in its own axes and turning about its
/// span at rate 1 (every term of the equations active) after [`WARM_UP`] steps, with `threads`
/// workers.
pub(crate) fn bench_one3(
    resolution: usize,
    span: Span,
    steps: usize,
    threads: usize,
) -> anyhow::Result<Bench3Row> {
    let pool = pool::pool(threads)?;
    let grid = bench_grid(resolution, span)?;
    let (n, cells) = (grid.n, grid.cells());
    let frame = Frame3::body([-(0.4f64.cos()), 0.4f64.sin(), 0.0], [0.0, 0.0, 1.0]);
    let t0 = Instant::now();
    let rss0 = resident_bytes();
    let mut flow = FlowSolver3::new(grid, FlowParams3::default(), OuterBc3::FarField, frame)?;
    let bytes_per_cell = rss0
        .zip(resident_bytes())
        .map(|(a, b)| b.saturating_sub(a) as f64 / cells as f64);
    let setup_seconds = t0.elapsed().as_secs_f64();
    let (seconds, iterations) = pool.install(|| time_steps(&mut flow, frame, steps))?;
    Ok(Bench3Row {
        resolution,
        span,
        n,
        cells,
        setup_seconds,
        steps,
        threads: pool.current_num_threads(),
        iterations_per_step: iterations as f64 / steps as f64,
        total_ns_per_cell: seconds * 1e9 / (steps as f64 * cells as f64),
        bytes_per_cell,
    })
}

/// The benchmark's grid at `resolution` cells per chord.
///
/// # Errors
/// The grid's own refusal: a span too short for the resolution, a resolution out of range, a
/// grid over the memory limit.
pub(crate) fn bench_grid(resolution: usize, span: Span) -> Result<Grid3, Flow3Error> {
    Grid3::new(&GridSpec3 {
        resolution,
        thickness: THICKNESS,
        span,
        extent: [EXTENT; 3],
        stretch: Stretch3::GrowthCap(GROWTH),
        memory_limit: MEMORY_LIMIT,
        shape: Default::default(),
    })
}

/// Seconds spent in `advance` and pressure iterations over `steps` steps after the warm-up.
fn time_steps(flow: &mut FlowSolver3, frame: Frame3, steps: usize) -> anyhow::Result<(f64, usize)> {
    let (mut seconds, mut iterations) = (0.0, 0);
    flow.begin_step()?;
    for k in 0..steps + WARM_UP {
        let dt = flow.stable_dt().min(0.01);
        let a = Instant::now();
        flow.advance(dt, frame)?;
        if k >= WARM_UP {
            seconds += a.elapsed().as_secs_f64();
            iterations += flow.solve_stats().iterations;
        }
    }
    Ok((seconds, iterations))
}

/// The process's resident set (bytes), from /proc/self/statm; None where it cannot be read.
fn resident_bytes() -> Option<u64> {
    let statm = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: u64 = statm.split_whitespace().nth(1)?.parse().ok()?;
    Some(pages * 4096)
}

/// A plain-text table of the rows.
pub(crate) fn table3(rows: &[Bench3Row]) -> String {
    let head = "   N  span              grid       cells  setup s  threads  CG/step  ns/cell/step  bytes/cell\n";
    head.to_string() + &rows.iter().map(|r| r.to_string()).collect::<String>()
}

impl std::fmt::Display for Bench3Row {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let span = match self.span {
            Span::Finite(b) => format!("{b}"),
            Span::Periodic(b) => format!("periodic:{b}"),
        };
        let grid = format!("{}x{}x{}", self.n[0], self.n[1], self.n[2]);
        let bytes = self
            .bytes_per_cell
            .map_or("-".to_string(), |b| format!("{b:.0}"));
        writeln!(
            f,
            "{:4}  {span:<12} {grid:>12} {:11} {:8.2} {:8} {:8.1} {:13.1} {bytes:>11}",
            self.resolution,
            self.cells,
            self.setup_seconds,
            self.threads,
            self.iterations_per_step,
            self.total_ns_per_cell
        )
    }
}
