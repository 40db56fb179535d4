//! A flight's state between two steps as plain data ([`FlightState`]), for checkpoints
//! (docs/three-d.md "On the command line"): the flow's ([`FlowState3`]), the body's
//! ([`Snapshot6`]: state, constraint, both Adams–Bashforth histories), the flow's frame one
//! level back and the step that left it (the instantaneous added-mass loads), and the hold.
//! The added-mass matrix and the coupling are rebuilt from the flow's operator.
use super::flight::{Flight3, Flight3Error};
use crate::body::six::{Constraint6, Snapshot6};
use crate::flow3d::{FlowState3, Frame3};

/// A [`Flight3`]'s changing part between two steps.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FlightState {
    /// The flow.
    pub flow: FlowState3,
    /// The body.
    pub body: Snapshot6,
    /// The flow's frame one level back.
    pub before: Frame3,
    /// The step that left it.
    pub dt_prev: f64,
    /// While held: the release time and the constraint the body takes then.
    pub release: Option<(f64, Constraint6)>,
}

impl Flight3 {
    /// The flight's state between two steps.
    pub fn save(&self) -> FlightState {
        FlightState {
            flow: self.flow.save_state(),
            body: self.body.save(),
            before: self.before,
            dt_prev: self.dt_prev,
            release: self.release,
        }
    }

    /// Puts back a state saved by [`save`](Self::save) from a flight of the same grid and
    /// plate; the next step is then the one the saved flight would have taken, bit for bit.
    ///
    /// # Errors
    /// The flow's [`crate::flow3d::Flow3Error::StateMismatch`] and the body's refusals of a
    /// snapshot that does not fit; the flight is left as it was then.
    pub fn restore(&mut self, s: &FlightState) -> Result<(), Flight3Error> {
        let mut body = self.body.clone();
        body.restore(&s.body)?;
        self.flow.restore_state(&s.flow)?;
        self.body = body;
        self.before = s.before;
        self.dt_prev = s.dt_prev;
        self.release = s.release;
        Ok(())
    }
}
