//! One time step's scalars: the solver's per-step output, plain data.

/// One time step's scalars.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepSample {
    pub step: u64,
    /// Convective time t U / c at the end of the step.
    pub t: f64,
    /// The step just taken.
    pub dt: f64,
    /// Lift, drag, moment coefficients on the reference speed (SPEC §5).
    pub cl: f64,
    pub cd: f64,
    pub cm: f64,
    /// Plate centre in the inertial frame (Y up) and pitch angle θ (CCW positive).
    pub x: f64,
    pub y: f64,
    pub theta: f64,
    /// Inertial velocity of the centre and pitch rate θ̇.
    pub xdot: f64,
    pub ydot: f64,
    pub omega: f64,
    /// Derived: speed V, flight-path angle γ = atan2(Ẏ, Ẋ), angle of attack α = θ − γ (wrapped to (−π, π]).
    pub speed: f64,
    pub gamma: f64,
    pub alpha: f64,
}
