//! The staggered arrays: one padded layout shared by the three velocity components and their
//! right-hand sides (docs/physics.md §9).
//!
//! Component a lives on the faces normal to axis a: at nodes along a and at cell centres along
//! the other two, so its index runs 0..=n[a] along a and 0..n[b] along b ≠ a. Every array has
//! room for (n + 1) points plus [`G`] ghost layers on each side along every axis, x fastest, so
//! a point (i, j, k) has the same flat index in every component and the neighbour along axis a
//! is one stride away: the stencils of the three components are one generic code.

/// Ghost layers on each side (the upwind-biased convection stencil reaches two points).
pub const G: usize = 2;

/// Sizes and strides of the padded arrays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// Cells along x, y, z.
    pub n: [usize; 3],
    /// Flat-index strides along x, y, z.
    pub stride: [usize; 3],
    /// Length of every array.
    pub len: usize,
}

impl Layout {
    /// The layout of a grid of `n` cells.
    pub fn new(n: [usize; 3]) -> Layout {
        let ext = n.map(|m| m + 1 + 2 * G);
        Layout {
            n,
            stride: [1, ext[0], ext[0] * ext[1]],
            len: ext[0] * ext[1] * ext[2],
        }
    }

    /// Flat index of (i, j, k); each index may run from −G to n + G.
    #[inline(always)]
    pub fn at(&self, p: [isize; 3]) -> usize {
        let g = G as isize;
        ((p[0] + g) + (p[1] + g) * self.stride[1] as isize + (p[2] + g) * self.stride[2] as isize)
            as usize
    }

    /// The (i, j, k) of a flat index.
    #[inline]
    pub fn point(&self, idx: usize) -> [isize; 3] {
        let g = G as isize;
        let k = (idx / self.stride[2]) as isize - g;
        let rem = idx % self.stride[2];
        [
            (rem % self.stride[1]) as isize - g,
            (rem / self.stride[1]) as isize - g,
            k,
        ]
    }

    /// Points of component `c` along axis `a`: `0..=n[a]` on its own axis, `0..n[a]` on the others.
    #[inline]
    pub fn points(&self, c: usize, a: usize) -> isize {
        (self.n[a] + usize::from(c == a)) as isize
    }

    /// A zero array.
    pub fn zeros(&self) -> Vec<f64> {
        vec![0.0; self.len]
    }
}
