//! Where a 3-D step's time goes (docs/three-d.md "Cost"): the solver reads no clock; it tells a
//! marker the caller installs when each phase of `FlowSolver3::advance` begins and ends, and the
//! caller times them.

/// A boundary between the phases of a step: `Begin` when `advance` starts, then the end of each
/// phase in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase3 {
    /// `advance` starts.
    Begin,
    /// Ghost values and the explicit right-hand side Hⁿ (convection, diffusion, −ω × u) done.
    RightHandSide,
    /// The Adams–Bashforth predictor done.
    Predictor,
    /// No slip on the plate and the outer boundary's normal velocities done.
    Boundaries,
    /// The pressure equation's right-hand side, its solve and the velocity correction done.
    Pressure,
    /// The loads on the plate done (the step is over).
    Loads,
}

impl Phase3 {
    /// The phases a step is timed in, in order.
    pub const TIMED: [Phase3; 5] = [
        Phase3::RightHandSide,
        Phase3::Predictor,
        Phase3::Boundaries,
        Phase3::Pressure,
        Phase3::Loads,
    ];

    /// The phase's name in a report.
    pub fn name(self) -> &'static str {
        match self {
            Phase3::Begin => "begin",
            Phase3::RightHandSide => "right-hand side",
            Phase3::Predictor => "predictor",
            Phase3::Boundaries => "boundaries",
            Phase3::Pressure => "pressure",
            Phase3::Loads => "loads",
        }
    }
}

/// What the solver calls at each [`Phase3`] boundary.
pub type PhaseMarker = Box<dyn FnMut(Phase3) + Send + Sync>;
