//! [`FlowState3`]: the 3-D flow's state between two steps as plain data, for checkpoints
//! (docs/three-d.md "On the command line"), and [`FlowSolver3`]'s save and restore.
//!
//! A step reads the velocity, the pressures of the last two levels (the solve's warm start), the old right-hand side
//! Hⁿ⁻¹ (AB2), the frame, the clock (t, the last Δt, the step count), the last right-hand side's
//! statistics (the next stable Δt) and the loads (the flight's next body step). The new
//! right-hand side H is recomputed by the next step at every point it uses (elsewhere it stays
//! zero in both arrays), so it is not saved. Everything else (grid, metrics, operator, plate)
//! is rebuilt from the run's description.
use super::error::Flow3Error;
use super::frame::Frame3;
use super::loads::Loads3;
use super::momentum::RhsStats;
use super::project::SolveStats;
use super::solver::FlowSolver3;

/// A [`FlowSolver3`]'s changing part between two steps.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FlowState3 {
    /// Cells along x, y, z (the grid it fits).
    pub cells: [usize; 3],
    /// Whether the span is periodic.
    pub periodic_z: bool,
    /// The velocity components (padded arrays).
    pub vel: [Vec<f64>; 3],
    /// The previous step's right-hand side Hⁿ⁻¹.
    pub h_old: [Vec<f64>; 3],
    /// Cell pressures.
    pub p: Vec<f64>,
    /// Cell pressures of the level before.
    pub p_old: Vec<f64>,
    /// The body's motion at the current level.
    pub frame: Frame3,
    /// Time.
    pub t: f64,
    /// The last step.
    pub dt_prev: f64,
    /// Steps taken.
    pub steps: u64,
    /// The last right-hand side's largest convective rate and velocity.
    pub rhs_stats: (f64, f64),
    /// The last pressure solve.
    pub solve_stats: SolveStats,
    /// The loads at the current level.
    pub loads: Loads3,
}

impl FlowSolver3 {
    /// The state between two steps (after `advance`, or before the first one).
    pub fn save_state(&self) -> FlowState3 {
        FlowState3 {
            cells: self.grid.n,
            periodic_z: self.grid.periodic_z,
            vel: self.vel.clone(),
            h_old: self.h_old.clone(),
            p: self.p.clone(),
            p_old: self.p_old.clone(),
            frame: self.frame,
            t: self.t,
            dt_prev: self.dt_prev,
            steps: self.steps,
            rhs_stats: (self.rhs_stats.convective_rate, self.rhs_stats.max_speed),
            solve_stats: self.solve_stats,
            loads: self.loads,
        }
    }

    /// Puts back a state saved by [`save_state`](Self::save_state) from a solver of the same
    /// grid; the next step is then the one the saved solver would have taken, bit for bit.
    ///
    /// # Errors
    /// [`Flow3Error::StateMismatch`] when the grid or an array's length differs; the solver is
    /// left as it was then.
    pub fn restore_state(&mut self, s: &FlowState3) -> Result<(), Flow3Error> {
        let mismatch = |what, saved: String, ours: String| {
            Err(Flow3Error::StateMismatch { what, saved, ours })
        };
        if s.cells != self.grid.n || s.periodic_z != self.grid.periodic_z {
            let show = |n: [usize; 3], periodic: bool| format!("{n:?} (periodic span: {periodic})");
            return mismatch(
                "the grid",
                show(s.cells, s.periodic_z),
                show(self.grid.n, self.grid.periodic_z),
            );
        }
        let lengths = |a: &[Vec<f64>; 3]| a.iter().map(Vec::len).collect::<Vec<_>>();
        for (what, saved, ours) in [
            ("the velocity", lengths(&s.vel), lengths(&self.vel)),
            (
                "the old right-hand side",
                lengths(&s.h_old),
                lengths(&self.h_old),
            ),
            ("the pressure", vec![s.p.len()], vec![self.p.len()]),
            (
                "the earlier pressure",
                vec![s.p_old.len()],
                vec![self.p_old.len()],
            ),
        ] {
            if saved != ours {
                return mismatch(what, format!("{saved:?}"), format!("{ours:?}"));
            }
        }
        self.vel.clone_from(&s.vel);
        self.h_old.clone_from(&s.h_old);
        self.p.clone_from(&s.p);
        self.p_old.clone_from(&s.p_old);
        self.frame = s.frame;
        (self.t, self.dt_prev, self.steps) = (s.t, s.dt_prev, s.steps);
        self.rhs_stats = RhsStats {
            convective_rate: s.rhs_stats.0,
            max_speed: s.rhs_stats.1,
        };
        self.solve_stats = s.solve_stats;
        self.loads = s.loads;
        Ok(())
    }
}
