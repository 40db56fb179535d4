//! The plate's cover of the grid lines the staggered unknowns lie on (docs/physics.md §4): vertical lines
//! through the nodes (u faces) and through the cell centres (v faces, pressure), horizontal lines
//! through the nodes (v faces) and the centres (u faces, pressure).
use crate::grid::Grid;
use crate::shape::{Covered, LineDir, Outline};

/// Grid lines more than this many cells outside the plate's box are not searched (nothing of
/// the plate lies on them).
const MARGIN: usize = 3;

/// The covered intervals of every grid line (empty away from the plate).
#[derive(Clone, Debug, Default)]
pub struct Lines {
    /// `x = xₙ[i]`, `i = 0..=nx`.
    pub v_nodes: Vec<Covered>,
    /// `x = x_c[i]`, `i = 0..nx`.
    pub v_centres: Vec<Covered>,
    /// `y = yₙ[j]`, `j = 0..=ny`.
    pub h_nodes: Vec<Covered>,
    /// `y = y_c[j]`, `j = 0..ny`.
    pub h_centres: Vec<Covered>,
}

impl Lines {
    /// The cover of every line by `body` on `grid`.
    pub fn new(grid: &Grid, body: &Outline) -> Lines {
        let near_x = grid.i0.saturating_sub(MARGIN)..(grid.i1 + MARGIN).min(grid.nx);
        let near_y = grid.j0.saturating_sub(MARGIN)..(grid.j1 + MARGIN).min(grid.ny);
        let cover = |dir: LineDir, coords: &[f64], near: &std::ops::Range<usize>| -> Vec<Covered> {
            coords
                .iter()
                .enumerate()
                .map(|(k, &c)| {
                    if near.contains(&k) || near.end == k {
                        body.covered(dir, c)
                    } else {
                        Covered::default()
                    }
                })
                .collect()
        };
        Lines {
            v_nodes: cover(LineDir::Vertical, &grid.xn, &near_x),
            v_centres: cover(LineDir::Vertical, &grid.xc, &near_x),
            h_nodes: cover(LineDir::Horizontal, &grid.yn, &near_y),
            h_centres: cover(LineDir::Horizontal, &grid.yc, &near_y),
        }
    }
}
