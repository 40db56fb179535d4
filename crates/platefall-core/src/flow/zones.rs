//! Where the grid-velocity transport is taken implicitly (docs/physics.md §3, far field; see `implicit.rs`).
//!
//! On the body-fixed grid g_x = u0 − θ̇y is constant along each row and g_y = v0 + θ̇x along each
//! column. Far from the plate the rows through the plate keep Δy = h and the columns over the chord
//! keep Δx = h while |g| grows with the distance, so the explicit convective limit |w|/Δ is set
//! there. The grid is therefore split into a *near field* |x| ≤ X_cut, |y| ≤ Y_cut, where the
//! convection stays today's explicit scheme on u − g, and an outer zone where the transport by g
//! along a line is implicit: in the columns with |x| > X_cut along y, in the rows with |y| > Y_cut
//! along x (both in the corners). A line is classified by the coordinate of its own points: u-rows
//! lie at cell centres y_c, v-rows at nodes y_n, u-columns at nodes x_n, v-columns at centres x_c.
use std::ops::Range;

use crate::grid::Grid;

/// Which lines of u and v carry implicit grid transport, as flags and as contiguous column ranges.
#[derive(Clone, Debug)]
pub struct Zones {
    /// u-rows j = 0..ny: implicit along x.
    pub u_row: Vec<bool>,
    /// v-rows j = 0..=ny: implicit along x.
    pub v_row: Vec<bool>,
    /// u-columns i = 0..=nx: implicit along y.
    pub u_col: Vec<bool>,
    /// v-columns i = 0..nx: implicit along y.
    pub v_col: Vec<bool>,
    /// The near (explicit) u-columns and v-columns, [a, b): every column outside is split.
    pub u_near: Range<isize>,
    pub v_near: Range<isize>,
}

/// A range of columns and whether their y-transport is implicit.
pub type Segment = (Range<isize>, bool);

impl Zones {
    /// No implicit lines: today's explicit scheme everywhere.
    pub fn none(grid: &Grid) -> Zones {
        let (nx, ny) = (grid.nx, grid.ny);
        Zones {
            u_row: vec![false; ny],
            v_row: vec![false; ny + 1],
            u_col: vec![false; nx + 1],
            v_col: vec![false; nx],
            u_near: 0..nx as isize + 1,
            v_near: 0..nx as isize,
        }
    }

    /// Lines with |x| > x_cut (columns) and |y| > y_cut (rows) are split.
    pub fn new(grid: &Grid, x_cut: f64, y_cut: f64) -> Zones {
        let outside = |c: &[f64], cut: f64| c.iter().map(|z| z.abs() > cut).collect::<Vec<_>>();
        let u_col = outside(&grid.xn, x_cut);
        let v_col = outside(&grid.xc, x_cut);
        Zones {
            u_row: outside(&grid.yc, y_cut),
            v_row: outside(&grid.yn, y_cut),
            u_near: near_range(&grid.xn, &u_col),
            v_near: near_range(&grid.xc, &v_col),
            u_col,
            v_col,
        }
    }

    /// The columns `cols` cut into at most three segments: split, near, split.
    pub fn segments(near: &Range<isize>, cols: Range<isize>) -> [Segment; 3] {
        let a = near.start.clamp(cols.start, cols.end);
        let b = near.end.clamp(a, cols.end);
        [(cols.start..a, true), (a..b, false), (b..cols.end, true)]
    }

    /// The split lines must not cross the plate (their line solves know no interior wall): the
    /// first offending line, if any.
    ///
    /// # Errors
    /// [`PlateCrossing`] naming the first column or row through the plate that would be split.
    pub fn check_plate(&self, grid: &Grid) -> Result<(), PlateCrossing> {
        if !grid.has_plate() {
            return Ok(());
        }
        let (i0, i1, j0, j1) = (grid.i0, grid.i1, grid.j0, grid.j1);
        let bad_u_col = (i0..=i1).find(|&i| self.u_col[i]);
        let bad_v_col = (i0..i1).find(|&i| self.v_col[i]);
        let bad_u_row = (j0..j1).find(|&j| self.u_row[j]);
        let bad_v_row = (j0..=j1).find(|&j| self.v_row[j]);
        match (bad_u_col.or(bad_v_col), bad_u_row.or(bad_v_row)) {
            (Some(i), _) => Err(PlateCrossing::Column(i)),
            (_, Some(j)) => Err(PlateCrossing::Row(j)),
            _ => Ok(()),
        }
    }
}

/// A grid line through the plate that the implicit far field would split.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum PlateCrossing {
    /// Column `i` (constant x).
    #[error("column {0} through the plate would be implicit")]
    Column(usize),
    /// Row `j` (constant y).
    #[error("row {0} through the plate would be implicit")]
    Row(usize),
}

/// The contiguous range of unsplit indices (coordinates increase, so it is one range); when every
/// line is split, an empty range at the first positive coordinate.
fn near_range(coords: &[f64], split: &[bool]) -> Range<isize> {
    match (
        split.iter().position(|&s| !s),
        split.iter().rposition(|&s| !s),
    ) {
        (Some(a), Some(b)) => a as isize..b as isize + 1,
        _ => {
            let k = coords.iter().position(|&c| c > 0.0).unwrap_or(coords.len()) as isize;
            k..k
        }
    }
}
