//! The implicit far field's state carried by the solver.
use super::part::Part;
use crate::flow::metrics::{Component, Metrics};

/// The implicit far field's state: the two components' workspaces, γ₂ of the last step, and a
/// cell-sized scratch for the pressure update.
pub struct State {
    pub u: Part,
    pub v: Part,
    pub g2: f64,
    pub cells: Vec<f64>,
}

impl State {
    pub fn new(nx: usize, ny: usize, m: &Metrics) -> State {
        State {
            u: Part::new(Component::U, nx + 1, ny, m),
            v: Part::new(Component::V, nx, ny + 1, m),
            g2: 0.5,
            cells: vec![0.0; nx * ny],
        }
    }
}
