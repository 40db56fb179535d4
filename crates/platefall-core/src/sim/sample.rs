//! One time step's scalars: the solver's per-step output, plain data.
use crate::body::{wrap_angle, BodyState};

/// One time step's scalars: a row of the CSV and of the recording's time series.
///
/// The plate's state is kept flat (the six fields of [`BodyState`] followed by the derived V, γ,
/// α) so that every column is one field that [`Quantity`](super::Quantity) can index;
/// [`StepSample::new`] fills them from a `BodyState` and [`StepSample::state`] gives it back.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct StepSample {
    /// Steps taken so far.
    pub step: u64,
    /// Convective time t U / c at the end of the step.
    pub t: f64,
    /// The step just taken.
    pub dt: f64,
    /// Lift coefficient on the reference speed (docs/physics.md §5).
    pub cl: f64,
    /// Drag coefficient.
    pub cd: f64,
    /// Moment coefficient about the centre (counter-clockwise positive).
    pub cm: f64,
    /// X of the plate's centre in the inertial frame.
    pub x: f64,
    /// Y of the centre (up).
    pub y: f64,
    /// Pitch angle θ (counter-clockwise positive).
    pub theta: f64,
    /// Ẋ.
    pub xdot: f64,
    /// Ẏ.
    pub ydot: f64,
    /// Pitch rate θ̇.
    pub omega: f64,
    /// Derived: the speed V.
    pub speed: f64,
    /// Derived: the flight-path angle γ = atan2(Ẏ, Ẋ).
    pub gamma: f64,
    /// Derived: the angle of attack α = θ − γ, wrapped to (−π, π].
    pub alpha: f64,
}

impl StepSample {
    /// The sample of step `step` ending at `t` after a step `dt`, with the coefficients
    /// (C_L, C_D, C_M) and the plate's state `s`.
    pub fn new(step: u64, t: f64, dt: f64, (cl, cd, cm): (f64, f64, f64), s: &BodyState) -> Self {
        let gamma = s.flight_path_angle();
        StepSample {
            step,
            t,
            dt,
            cl,
            cd,
            cm,
            x: s.x,
            y: s.y,
            theta: s.theta,
            xdot: s.xdot,
            ydot: s.ydot,
            omega: s.omega,
            speed: s.speed(),
            gamma,
            alpha: wrap_angle(s.theta - gamma),
        }
    }

    /// The plate's state at the end of the step.
    pub fn state(&self) -> BodyState {
        BodyState {
            x: self.x,
            y: self.y,
            theta: self.theta,
            xdot: self.xdot,
            ydot: self.ydot,
            omega: self.omega,
        }
    }
}
