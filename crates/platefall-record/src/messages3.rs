//! What a 3-D run sends its recording (docs/three-d.md "Recording"): the run's description once,
//! then every step's pose and coefficients ([`Step3`]) and the flow's snapshots
//! (`FieldSnapshot3`), on the solver → logger channel ([`Message3`]).
use std::sync::Arc;

use platefall_core::flow3d::{Coefficients3, FieldSnapshot3};
use platefall_core::sim::StepSample;
use platefall_core::sim3::{Sample3, Sample6};

use crate::messages::{FieldUse, RunOutcome};

/// Everything about a 3-D run that does not change while it runs.
#[derive(Clone, Debug)]
pub struct RunInfo3 {
    /// One line, e.g. "free fall, card, span 2.67, Re 4770, N=16".
    pub title: String,
    /// The run's description for the recording's configuration document (markdown).
    pub config_markdown: String,
    /// The plate's half sizes along the body axes (chord, thickness, span), chords.
    pub half_size: [f64; 3],
    /// The span is periodic (the plate spans the grid).
    pub periodic: bool,
    /// The time the run ends at (c/U), if known.
    pub t_end: Option<f64>,
    /// The Q level of the vortex iso-surface ((U/c)²).
    pub q_level: f64,
    /// The vorticity at which the slices' colour scale saturates (U/c).
    pub vorticity_scale: f64,
}

/// One step of a 3-D run as the recording shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Step3 {
    /// Steps taken.
    pub step: u64,
    /// Time at the end of the step (c/U).
    pub t: f64,
    /// The centre in inertial axes (chords; Y up).
    pub position: [f64; 3],
    /// The rotation from body to inertial axes as a unit quaternion (x, y, z, w).
    pub rotation: [f64; 4],
    /// The centre's velocity in inertial axes (U).
    pub velocity: [f64; 3],
    /// The angular velocity in body axes (U/c).
    pub omega: [f64; 3],
    /// Roll, yaw and the unwrapped pitch (rad).
    pub angles: [f64; 3],
    /// C_L, C_D, C_S, C_roll, C_yaw, C_pitch.
    pub coefficients: [f64; 6],
    /// Pressure iterations of the step.
    pub iterations: usize,
    /// Largest cell divergence the step left (U/c).
    pub divergence: f64,
}

/// One message on a 3-D run's solver → logger channel.
#[derive(Clone, Debug)]
pub enum Message3 {
    /// Every step, never dropped.
    Step(Step3),
    /// A snapshot of the flow and what it is for.
    Field(Arc<FieldSnapshot3>, FieldUse),
    /// The run is over.
    Finish(RunOutcome),
}

impl Step3 {
    /// A step of a free flight, with its unwrapped `pitch`.
    pub fn of_flight(s: &Sample6, pitch: f64) -> Step3 {
        let st = &s.state;
        let (roll, yaw, _) = st.orientation.euler_angles();
        let q = st.orientation.coords;
        Step3 {
            step: s.step,
            t: s.t,
            position: st.position.into(),
            rotation: [q.x, q.y, q.z, q.w],
            velocity: st.velocity.into(),
            omega: st.omega.into(),
            angles: [roll, yaw, pitch],
            coefficients: six(&s.coefficients),
            iterations: s.iterations,
            divergence: s.divergence,
        }
    }

    /// A step of a prescribed (static or forced) run, whose pose is the planar `p`.
    pub fn of_prescribed(s: &Sample3, p: &StepSample) -> Step3 {
        let half = 0.5 * p.theta;
        Step3 {
            step: s.step,
            t: s.t,
            position: [p.x, p.y, 0.0],
            rotation: [0.0, 0.0, half.sin(), half.cos()],
            velocity: [p.xdot, p.ydot, 0.0],
            omega: [0.0, 0.0, p.omega],
            angles: [0.0, 0.0, p.theta],
            coefficients: six(&s.coefficients),
            iterations: s.iterations,
            divergence: s.divergence,
        }
    }
}

/// C_L, C_D, C_S, C_roll, C_yaw, C_pitch.
fn six(c: &Coefficients3) -> [f64; 6] {
    [c.lift, c.drag, c.side, c.roll, c.yaw, c.pitch]
}
