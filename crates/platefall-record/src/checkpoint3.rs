//! The state of a 3-D run (`--span`) in a checkpoint (docs/three-d.md "On the command line"):
//! the flow's, or the flight's with its unwrapped pitch and the pitch at the release (the turn
//! count), and the steps' accumulators the summary is made of (the planar projection, the
//! lateral coefficients and the attitude), so a resumed run's summary is the whole run's.
use platefall_core::flow3d::FlowState3;
use platefall_core::sim::History;
use platefall_core::sim3::FlightState;
use platefall_post::summary3::Attitude;

/// A 3-D run between two steps.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SpanState {
    /// The flow, or the flight.
    pub run: SpanRun,
    /// Every step's planar sample so far.
    pub planar: History,
    /// Every step's lateral sample so far (side force, roll and yaw coefficients).
    pub lateral: History,
    /// Every step's attitude so far (a flight's; empty for a prescribed run).
    pub attitude: Vec<Attitude>,
}

/// What moves in a 3-D run.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum SpanRun {
    /// A static or forced case: the flow alone.
    Prescribed(Box<FlowState3>),
    /// A free case: the flight.
    Flight {
        /// The flow and the body.
        flight: Box<FlightState>,
        /// The pitch, unwrapped.
        pitch: f64,
        /// The pitch at the release (None before it).
        theta_release: Option<f64>,
    },
}

impl SpanState {
    /// Steps taken.
    pub fn steps(&self) -> u64 {
        self.flow().steps
    }

    /// The time.
    pub fn t(&self) -> f64 {
        self.flow().t
    }

    fn flow(&self) -> &FlowState3 {
        match &self.run {
            SpanRun::Prescribed(f) => f,
            SpanRun::Flight { flight, .. } => &flight.flow,
        }
    }
}
