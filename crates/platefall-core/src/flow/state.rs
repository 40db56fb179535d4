//! The flow solver's state between two steps as plain data ([`FlowState`]), for checkpoints: every
//! field that one step hands to the next, with its ghost layers, bit for bit. What is computed
//! once from the grid (metrics, the wall, the pressure factor, the zones) is not in it: a solver
//! built anew from the same grid and parameters has it already.
use super::frame::Frame;
use super::plate::BodyAxesLoads;

/// The flow solver's state between two steps; see the module docs.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FlowState {
    /// Velocities, pressure and the explicit right-hand sides of the last two steps, each with
    /// its ghost layers: u, v, p, Hu, Hv, Hu_old, Hv_old.
    pub fields: Vec<Vec<f64>>,
    /// The implicit far field's carried arrays (u's increment and L q, then v's), if it is used.
    pub implicit: Option<Vec<Vec<f64>>>,
    /// γ₂ of the last implicit step.
    pub g2: f64,
    /// The plate's motion at the current and the previous time level, and the extrapolated one.
    pub frames: [Frame; 3],
    /// Time, last step and step count.
    pub t: f64,
    /// The last step taken.
    pub dt_prev: f64,
    /// Steps taken.
    pub steps: u64,
    /// The loads at the current time level.
    pub loads: BodyAxesLoads,
}

/// A saved flow state does not fit this solver (another grid or far-field scheme).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("the saved flow state does not fit this grid and scheme ({0})")]
pub struct StateMismatch(pub &'static str);
