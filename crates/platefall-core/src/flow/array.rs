//! A 2-D array of f64 with [`GHOST`] ghost layers on every side, x fastest.
//!
//! Index (i, j) may run from −GHOST to n + GHOST − 1 in each direction, so stencils up to two
//! points wide read ghost values without branches.

/// Ghost layers on each side (the upwind-biased convection stencil reaches two points).
pub const GHOST: usize = 2;

/// A field on the MAC grid with its ghost layers (a velocity component, a right-hand side).
#[derive(Clone, Debug)]
pub struct Padded {
    /// Interior sizes.
    pub(crate) ni: usize,
    pub(crate) nj: usize,
    /// Row length including ghosts.
    pub(crate) stride: usize,
    pub(crate) data: Vec<f64>,
}

impl Padded {
    /// A field of `ni` × `nj` interior values, all zero.
    pub fn zeros(ni: usize, nj: usize) -> Self {
        let stride = ni + 2 * GHOST;
        Padded {
            ni,
            nj,
            stride,
            data: vec![0.0; stride * (nj + 2 * GHOST)],
        }
    }

    /// Flat index of (i, j), where i, j may be negative down to −GHOST.
    #[inline(always)]
    pub fn at(&self, i: isize, j: isize) -> usize {
        debug_assert!(i >= -(GHOST as isize) && i < (self.ni + GHOST) as isize);
        debug_assert!(j >= -(GHOST as isize) && j < (self.nj + GHOST) as isize);
        (j + GHOST as isize) as usize * self.stride + (i + GHOST as isize) as usize
    }

    /// The value at (i, j) (ghosts included: i, j from −GHOST).
    #[inline(always)]
    pub fn get(&self, i: isize, j: isize) -> f64 {
        self.data[self.at(i, j)]
    }

    /// Sets the value at (i, j).
    #[inline(always)]
    pub fn set(&mut self, i: isize, j: isize, value: f64) {
        let k = self.at(i, j);
        self.data[k] = value;
    }

    /// The interior values, row-major with i fastest (no ghosts).
    pub fn interior(&self) -> Vec<f64> {
        let mut out = Vec::with_capacity(self.ni * self.nj);
        for j in 0..self.nj as isize {
            let k = self.at(0, j);
            out.extend_from_slice(&self.data[k..k + self.ni]);
        }
        out
    }

    /// Largest absolute interior value (NaN if any value is NaN).
    pub fn max_abs_interior(&self) -> f64 {
        let mut m: f64 = 0.0;
        for j in 0..self.nj as isize {
            let k = self.at(0, j);
            for &x in &self.data[k..k + self.ni] {
                if x.is_nan() {
                    return f64::NAN;
                }
                m = m.max(x.abs());
            }
        }
        m
    }
}

/// Extends increasing node coordinates by GHOST mirrored nodes on each side
/// (x₋ₖ = 2x₀ − xₖ), so ghost cells have the size of their mirror images.
pub fn extend_nodes(nodes: &[f64]) -> Vec<f64> {
    let n = nodes.len();
    let g = GHOST;
    let mut out = Vec::with_capacity(n + 2 * g);
    for k in (1..=g).rev() {
        out.push(2.0 * nodes[0] - nodes[k]);
    }
    out.extend_from_slice(nodes);
    for k in 1..=g {
        out.push(2.0 * nodes[n - 1] - nodes[n - 1 - k]);
    }
    out
}
