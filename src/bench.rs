//! `platefall bench`: what a step and a turn cost.
//!
//! - [`bench_one`] times the flow step alone (prescribed motion, no output) on one grid and
//!   reports nanoseconds per cell per step, split into the explicit momentum phase
//!   ([`FlowSolver::prepare`]) and the rest ([`FlowSolver::advance`]: predictor with the implicit
//!   line solves, boundary values, pressure solve, velocity correction, loads).
//! - [`bench_card`] is the time to solution of a rotating plate: the card's free fall exactly as
//!   `platefall free --resolution N` runs it, through release and into autorotation; steps per
//!   turn over the developed turns, and the wall time per step and per turn on all cores and on
//!   one core.
//!
//! Both run inside a rayon pool of the requested size, as a run does (`crate::pool`).
use std::time::Instant;

use serde::Serialize;

use crate::pool;
use platefall_core::config::{Plate, RunBuilder};
use platefall_core::flow::{FarFieldScheme, FlowParams, FlowSolver, OuterBc};
use platefall_core::grid::{Grid, GridSpec};
use platefall_core::sim::{Case, Simulation};

#[derive(Clone, Debug, Serialize)]
pub(crate) struct BenchRow {
    pub(crate) resolution: usize,
    pub(crate) nx: usize,
    pub(crate) ny: usize,
    pub(crate) cells: usize,
    pub(crate) factor_nnz: usize,
    pub(crate) setup_seconds: f64,
    pub(crate) steps: usize,
    pub(crate) threads: usize,
    pub(crate) momentum_ns_per_cell: f64,
    pub(crate) pressure_ns_per_cell: f64,
    pub(crate) total_ns_per_cell: f64,
}

/// Times `steps` steps of a plate translating at α = 0.4 and spinning at θ̇ = 1 (so every term of the
/// mixed-frame equations is active) after 5 warm-up steps, with `threads` workers.
pub(crate) fn bench_one(
    resolution: usize,
    steps: usize,
    scheme: FarFieldScheme,
    threads: usize,
) -> anyhow::Result<BenchRow> {
    let pool = pool::pool(threads)?;
    let spec = GridSpec::modern(resolution);
    let grid = Grid::new(&spec)?;
    let (nx, ny, cells) = (grid.nx, grid.ny, grid.cells());
    let case = Case::Forced {
        omega: 1.0,
        spinup: 0.0,
    };
    let params = FlowParams {
        far_field: scheme,
        ..FlowParams::default()
    };
    let t0 = Instant::now();
    let frame = case.prescribed_state(0.4).frame();
    let mut flow = FlowSolver::new(grid, params, OuterBc::FarField, frame)?;
    let setup_seconds = t0.elapsed().as_secs_f64();
    let (t_mom, t_proj) = pool.install(|| time_steps(&mut flow, &case, steps))?;
    let per = 1e9 / (steps as f64 * cells as f64);
    Ok(BenchRow {
        resolution,
        nx,
        ny,
        cells,
        factor_nnz: flow.pressure_size().1,
        setup_seconds,
        steps,
        threads: pool.current_num_threads(),
        momentum_ns_per_cell: t_mom * per,
        pressure_ns_per_cell: t_proj * per,
        total_ns_per_cell: (t_mom + t_proj) * per,
    })
}

/// Seconds spent in `prepare` and in `advance` over `steps` steps after 5 warm-up steps.
fn time_steps(flow: &mut FlowSolver, case: &Case, steps: usize) -> anyhow::Result<(f64, f64)> {
    let (mut t_mom, mut t_proj) = (0.0, 0.0);
    for k in 0..steps + 5 {
        let a = Instant::now();
        let limit = flow.prepare()?;
        let b = Instant::now();
        let dt = limit.min(0.01);
        let next = case.prescribed_state(0.4 + flow.t() + dt).frame();
        flow.advance(dt, next)?;
        let c = Instant::now();
        if k >= 5 {
            t_mom += (b - a).as_secs_f64();
            t_proj += (c - b).as_secs_f64();
        }
    }
    Ok((t_mom, t_proj))
}

/// A plain-text table of the rows.
pub(crate) fn table(rows: &[BenchRow]) -> String {
    let head = "   N      grid     cells  factor nnz  setup s  threads   momentum  projection     total   (ns per cell per step)\n";
    head.to_string() + &rows.iter().map(|r| r.to_string()).collect::<String>()
}

impl std::fmt::Display for BenchRow {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let BenchRow {
            resolution: n,
            nx,
            ny,
            cells,
            factor_nnz: nnz,
            setup_seconds: setup,
            threads,
            momentum_ns_per_cell: mom,
            pressure_ns_per_cell: proj,
            total_ns_per_cell: total,
            ..
        } = self;
        writeln!(f, "{n:4} {nx:4}x{ny:<4} {cells:8} {nnz:11} {setup:8.2} {threads:8} {mom:10.1} {proj:11.1} {total:9.1}")
    }
}

/// Time to solution of the card's free fall at one resolution.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct CardRow {
    pub(crate) resolution: usize,
    pub(crate) cells: usize,
    pub(crate) far_field: FarFieldScheme,
    /// Whole turns after the first complete turn after release that were timed.
    pub(crate) turns_timed: usize,
    pub(crate) steps_per_turn: f64,
    /// Workers of the all-core pool.
    pub(crate) threads: usize,
    pub(crate) ns_per_cell_step_all: f64,
    pub(crate) ns_per_cell_step_one: f64,
    pub(crate) seconds_per_turn_all: f64,
    pub(crate) seconds_per_turn_one: f64,
    /// Steps and seconds of the whole run (development, release, `turns` turns) on all cores.
    pub(crate) steps: u64,
    pub(crate) wall_seconds: f64,
}

/// Runs the card's free fall as `platefall free --resolution N --turns T` does (no output) on all cores (`threads`, 0 = one
/// per core): the developed turns 2..=T give steps per turn and the time per step; then
/// `single_steps` more steps on one core give the single-core time per step.
pub(crate) fn bench_card(
    resolution: usize,
    turns: usize,
    scheme: FarFieldScheme,
    threads: usize,
    single_steps: usize,
) -> anyhow::Result<CardRow> {
    let config = RunBuilder::free(Plate::card())
        .resolution(resolution)
        .turns(turns as f64)
        .far_field(scheme)
        .build()?;
    let mut sim = Simulation::new(config)?;
    let cells = sim.flow().grid().cells();
    let all = pool::pool(threads)?;
    let start = Instant::now();
    let marks = all.install(|| turn_marks(&mut sim, turns))?;
    let wall_seconds = start.elapsed().as_secs_f64();
    let one = pool::pool(1)?;
    let t1 = Instant::now();
    one.install(|| (0..single_steps).try_for_each(|_| sim.step().map(|_| ())))?;
    let one_per_step = t1.elapsed().as_secs_f64() / single_steps.max(1) as f64;
    let (first, last) = (marks[1], marks[turns]);
    let timed = (turns - 1).max(1);
    let steps_per_turn = (last.0 - first.0) as f64 / timed as f64;
    let all_per_step = (last.1 - first.1) / (last.0 - first.0).max(1) as f64;
    Ok(CardRow {
        resolution,
        cells,
        far_field: scheme,
        turns_timed: timed,
        steps_per_turn,
        threads: all.current_num_threads(),
        ns_per_cell_step_all: 1e9 * all_per_step / cells as f64,
        ns_per_cell_step_one: 1e9 * one_per_step / cells as f64,
        seconds_per_turn_all: steps_per_turn * all_per_step,
        seconds_per_turn_one: steps_per_turn * one_per_step,
        steps: sim.flow().steps(),
        wall_seconds,
    })
}

/// Steps the run to its end; for k = 0..=turns, (step, seconds since start) when the plate had
/// turned k whole turns since release (k = 0: the release).
fn turn_marks(sim: &mut Simulation, turns: usize) -> anyhow::Result<Vec<(u64, f64)>> {
    let start = Instant::now();
    let release = sim.release_time();
    let mut theta0 = None;
    let mut marks = Vec::with_capacity(turns + 1);
    while !sim.finished() {
        let s = sim.step()?;
        if s.t < release - 1e-9 {
            continue;
        }
        let th0 = *theta0.get_or_insert(s.theta);
        let k = ((s.theta - th0).abs() / std::f64::consts::TAU) as usize;
        while marks.len() <= k.min(turns) {
            marks.push((s.step, start.elapsed().as_secs_f64()));
        }
    }
    anyhow::ensure!(
        marks.len() > turns,
        "the run ended after {} of {turns} turns",
        marks.len().saturating_sub(1)
    );
    Ok(marks)
}

/// A plain-text table of the card rows.
pub(crate) fn card_table(rows: &[CardRow]) -> String {
    let head = "   N    cells  far field  steps/turn  threads  ns/cell/step (all, 1)  s per turn (all, 1)   run steps   run s\n";
    head.to_string() + &rows.iter().map(|r| r.to_string()).collect::<String>()
}

impl std::fmt::Display for CardRow {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let far = format!("{:?}", self.far_field).to_lowercase();
        let (n, cells, spt, threads) = (
            self.resolution,
            self.cells,
            self.steps_per_turn,
            self.threads,
        );
        let (all, one) = (self.ns_per_cell_step_all, self.ns_per_cell_step_one);
        let (turn_all, turn_one) = (self.seconds_per_turn_all, self.seconds_per_turn_one);
        let (steps, wall) = (self.steps, self.wall_seconds);
        writeln!(f, "{n:4} {cells:8}  {far:9} {spt:10.0} {threads:8} {all:11.1} {one:9.1} {turn_all:10.2} {turn_one:8.2} {steps:11} {wall:7.1}")
    }
}
