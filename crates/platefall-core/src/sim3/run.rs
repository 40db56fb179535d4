//! Stepping the 3-D flow through a prescribed planar motion (docs/three-d.md "Cases").
use std::ops::ControlFlow;

use super::planar::planar_frame;
use crate::flow3d::{Coefficients3, Flow3Error, FlowSolver3};
use crate::sim::{land, Case};

/// One step's outputs.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Sample3 {
    /// Steps taken.
    pub step: u64,
    /// Time at the end of the step (c/U).
    pub t: f64,
    /// The step (c/U).
    pub dt: f64,
    /// Pitch θ (rad).
    pub theta: f64,
    /// Rate θ̇ (U/c).
    pub omega: f64,
    /// Force and moment coefficients.
    pub coefficients: Coefficients3,
    /// Pressure-solver iterations of the step.
    pub iterations: usize,
    /// Largest cell divergence the step left (U/c).
    pub divergence: f64,
}

/// Steps `flow` (built at the case's state at t = 0, or restored between two steps of such a
/// run) to `t_end` with Δt = min(stable Δt, `dt_max`), the plate moving as `case` prescribes;
/// `observe` sees every step and the flow after it, and may stop the run.
///
/// # Errors
/// [`Flow3Error::BadParameter`] for a `case` that is not prescribed (pinned, free) or a
/// non-positive `dt_max`; otherwise the solver's own errors (divergence, a pressure solve that
/// does not converge).
pub fn run_prescribed(
    case: &Case,
    flow: &mut FlowSolver3,
    t_end: f64,
    dt_max: f64,
    mut observe: impl FnMut(&Sample3, &FlowSolver3) -> ControlFlow<()>,
) -> Result<(), Flow3Error> {
    if !matches!(case, Case::Static { .. } | Case::Forced { .. }) {
        return Err(Flow3Error::BadParameter {
            name: "case (static or forced only)",
            value: f64::NAN,
        });
    }
    if !(dt_max > 0.0 && dt_max.is_finite()) {
        return Err(Flow3Error::BadParameter {
            name: "dt_max",
            value: dt_max,
        });
    }
    if flow.steps() == 0 {
        // The first step's stable Δt; a restored flow keeps the one its last step left.
        flow.begin_step()?;
    }
    while flow.t() < t_end - 1e-9 {
        let dt = land(flow.t(), flow.stable_dt().min(dt_max), t_end);
        let state = case.prescribed_state(flow.t() + dt);
        flow.advance(dt, planar_frame(&state))?;
        let stats = flow.solve_stats();
        let sample = Sample3 {
            step: flow.steps(),
            t: flow.t(),
            dt,
            theta: state.theta,
            omega: state.omega,
            coefficients: flow.coefficients(),
            iterations: stats.iterations,
            divergence: stats.divergence,
        };
        if observe(&sample, flow).is_break() {
            break;
        }
    }
    Ok(())
}
