//! The pressure operator's Cholesky factor, ordered for two threads (docs/physics.md §3, the projection).
//!
//! The unknowns are split by a separator — the column of cells at the middle of the grid — into a
//! left and a right part that do not touch each other. Ordered left part, right part, separator
//! (each half by AMD, the separator in its own order), the factor L of A = L Lᵀ is
//!
//! ```text
//!     ⎡ L_l        ⎤
//!     ⎢      L_r   ⎥      with no fill between the halves,
//!     ⎣ B_l  B_r  L_s⎦
//! ```
//!
//! so the forward solve runs both halves at once (each gathers its updates to the separator in its
//! own buffer), then the small separator block; the backward solve does the separator, then both
//! halves at once. The factor itself is faer's simplicial LLᵀ with this ordering (simplicial
//! measured faster than supernodal for the one right-hand side solved each step); only its two
//! triangular solves are done here. The result does not depend on the number of threads: every
//! sum is taken in the same order. Both cores stream half the factor each, so the solve takes
//! about half the time where memory bandwidth allows (docs/performance.md).
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::perm::PermRef;
use faer::sparse::linalg::amd;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, SymbolicCholesky, SymbolicCholeskyRaw,
    SymmetricOrdering,
};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::{SparseColMat, SparseColMatRef, Triplet};
use faer::{Par, Side};

/// Why the pressure operator could not be ordered or factored.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum FactorError {
    /// faer refused a step (`stage`: the sub-matrix of a half, AMD ordering, the symbolic or the
    /// numeric factorisation); `detail` is its own message.
    #[error("{stage}: {detail}")]
    Library {
        /// The step that failed.
        stage: &'static str,
        /// faer's message.
        detail: String,
    },
    /// A column of the factor does not start with a positive diagonal (the operator is not
    /// positive definite).
    #[error("column {column} of the factor does not start with its diagonal")]
    Diagonal {
        /// The column, in the factor's order.
        column: usize,
    },
    /// The rows of a column of the factor are not ascending.
    #[error("the rows of column {column} of the factor are not ascending")]
    Unsorted {
        /// The column, in the factor's order.
        column: usize,
    },
    /// The factor couples the left and right halves (the separator does not separate them).
    #[error("the factor couples the two halves (column {column})")]
    CouplesHalves {
        /// The column, in the factor's order.
        column: usize,
    },
    /// faer returned a supernodal factor where a simplicial one was forced.
    #[error("the Cholesky factor is not simplicial")]
    NotSimplicial,
}

impl FactorError {
    fn library(stage: &'static str, e: impl std::fmt::Debug) -> FactorError {
        FactorError::Library {
            stage,
            detail: format!("{e:?}"),
        }
    }
}

/// Which block an unknown belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    Left,
    Right,
    Separator,
}

impl Part {
    /// The block of a cell in `column` when the separator is column `middle`.
    pub fn of_column(column: usize, middle: usize) -> Part {
        match column.cmp(&middle) {
            std::cmp::Ordering::Less => Part::Left,
            std::cmp::Ordering::Greater => Part::Right,
            std::cmp::Ordering::Equal => Part::Separator,
        }
    }
}

/// Columns `start..end` of L, whose rows lie in the same block or in the separator, and the
/// forward solve's updates to the separator.
struct Block {
    start: usize,
    end: usize,
    to_separator: Vec<f64>,
}

/// L as faer's simplicial factor stores it (column by column, rows ascending, the diagonal
/// first), with where each column's separator rows begin and the inverse diagonal.
struct Factor {
    symbolic: SymbolicCholesky<u32>,
    values: Vec<f64>,
    /// Index of each column's first row in the separator (its end if none).
    mid: Vec<u32>,
    inv_diag: Vec<f64>,
    /// First column of the separator.
    sep_start: usize,
}

/// The factor of a symmetric positive definite matrix in the two-halves-and-separator order.
pub struct SplitCholesky {
    l: Factor,
    left: Block,
    right: Block,
    separator: Block,
    /// Position of each unknown (in the caller's numbering) in the factor's order.
    pub position: Vec<u32>,
}

impl SplitCholesky {
    /// Orders and factors `a` (its lower triangle, in the caller's numbering), `part[r]` naming the
    /// block of unknown r. Left and right unknowns must not be coupled.
    ///
    /// # Errors
    /// [`FactorError`] when faer refuses a step (sub-matrix, AMD ordering, symbolic or numeric
    /// factorisation) or the matrix is not positive definite.
    pub fn new(a: SparseColMatRef<'_, u32, f64>, part: &[Part]) -> Result<Self, FactorError> {
        let n = a.nrows();
        let blocks = [Part::Left, Part::Right, Part::Separator];
        let mut order: Vec<u32> = Vec::with_capacity(n);
        let mut starts = [0usize; 3];
        for (b, &which) in blocks.iter().enumerate() {
            starts[b] = order.len();
            let members: Vec<u32> = (0..n as u32)
                .filter(|&r| part[r as usize] == which)
                .collect();
            if which == Part::Separator {
                order.extend_from_slice(&members);
            } else {
                order.extend(
                    amd_order(a, &members)?
                        .into_iter()
                        .map(|k| members[k as usize]),
                );
            }
        }
        let mut position = vec![0u32; n];
        for (new, &old) in order.iter().enumerate() {
            position[old as usize] = new as u32;
        }
        let l = Factor::new(a, &order, &position, starts)?;
        let block = |start: usize, end: usize, to_separator: usize| Block {
            start,
            end,
            to_separator: vec![0.0; to_separator],
        };
        let ns = n - starts[2];
        Ok(SplitCholesky {
            left: block(0, starts[1], ns),
            right: block(starts[1], starts[2], ns),
            separator: block(starts[2], n, 0),
            l,
            position,
        })
    }

    /// Nonzeros of L.
    pub fn nnz(&self) -> usize {
        self.l.values.len()
    }

    /// Solves A x = b in place; `x` is in the factor's order (see [`SplitCholesky::position`]).
    pub fn solve_in_place(&mut self, x: &mut [f64]) {
        let l = self.l.view();
        let (halves, sep) = x.split_at_mut(self.separator.start);
        let (xl, xr) = halves.split_at_mut(self.right.start);
        let (left, right) = (&mut self.left, &mut self.right);
        rayon::join(|| left.forward(l, xl), || right.forward(l, xr));
        for ((s, a), b) in sep
            .iter_mut()
            .zip(&left.to_separator)
            .zip(&right.to_separator)
        {
            *s += a + b;
        }
        self.separator.forward(l, sep);
        self.separator.backward(l, sep, &[]);
        let sep = &*sep;
        rayon::join(|| left.backward(l, xl, sep), || right.backward(l, xr, sep));
    }
}

impl Factor {
    /// Factors `a` with unknown `order[k]` in place k (`position` is the inverse; the blocks
    /// start at `starts`) and checks that no column of a half has rows in the other half.
    fn new(
        a: SparseColMatRef<'_, u32, f64>,
        order: &[u32],
        position: &[u32],
        starts: [usize; 3],
    ) -> Result<Factor, FactorError> {
        let (symbolic, values) = factor(a, order, position)?;
        let (col_ptr, row_idx) = structure(&symbolic);
        let n = a.nrows();
        let mut mid = Vec::with_capacity(n);
        let mut inv_diag = Vec::with_capacity(n);
        for c in 0..n {
            let (lo, hi) = (col_ptr[c] as usize, col_ptr[c + 1] as usize);
            let rows = &row_idx[lo..hi];
            if rows.first() != Some(&(c as u32)) || values[lo] <= 0.0 {
                return Err(FactorError::Diagonal { column: c });
            }
            if rows.windows(2).any(|w| w[0] >= w[1]) {
                return Err(FactorError::Unsorted { column: c });
            }
            // Rows below the diagonal that lie outside the column's own block.
            let end = starts.iter().copied().find(|&s| s > c).unwrap_or(n);
            let own = rows.partition_point(|&r| (r as usize) < end);
            if own < rows.len() && (rows[own] as usize) < starts[2] {
                return Err(FactorError::CouplesHalves { column: c });
            }
            mid.push((lo + own) as u32);
            inv_diag.push(1.0 / values[lo]);
        }
        Ok(Factor {
            symbolic,
            values,
            mid,
            inv_diag,
            sep_start: starts[2],
        })
    }

    /// The factor's arrays, borrowed once for a whole solve.
    fn view(&self) -> View<'_> {
        let (col_ptr, row_idx) = structure(&self.symbolic);
        View {
            col_ptr,
            row_idx,
            values: &self.values,
            mid: &self.mid,
            inv_diag: &self.inv_diag,
            sep_start: self.sep_start,
        }
    }
}

/// Entries of part of a column: row indices and values.
type Entries<'a> = (&'a [u32], &'a [f64]);

/// The arrays of [`Factor`], borrowed.
#[derive(Clone, Copy)]
struct View<'a> {
    col_ptr: &'a [u32],
    row_idx: &'a [u32],
    values: &'a [f64],
    mid: &'a [u32],
    inv_diag: &'a [f64],
    sep_start: usize,
}

impl View<'_> {
    /// Column c's entries below the diagonal: (rows, values) in its own block, then in the
    /// separator.
    #[inline(always)]
    fn column(&self, c: usize) -> (Entries<'_>, Entries<'_>) {
        let (lo, m, hi) = (
            self.col_ptr[c] as usize + 1,
            self.mid[c] as usize,
            self.col_ptr[c + 1] as usize,
        );
        (
            (&self.row_idx[lo..m], &self.values[lo..m]),
            (&self.row_idx[m..hi], &self.values[m..hi]),
        )
    }
}

impl Block {
    /// L_b y = x on this block's columns, in place (`x` holds this block's unknowns); the updates
    /// to the separator go to `to_separator`.
    fn forward(&mut self, l: View, x: &mut [f64]) {
        assert_eq!(
            x.len(),
            self.end - self.start,
            "a block solves its own unknowns"
        );
        self.to_separator.fill(0.0);
        for c in self.start..self.end {
            let j = c - self.start;
            let xj = x[j] * l.inv_diag[c];
            x[j] = xj;
            let ((rows, vals), (sep_rows, sep_vals)) = l.column(c);
            scatter(rows, vals, xj, x, self.start);
            scatter(sep_rows, sep_vals, xj, &mut self.to_separator, l.sep_start);
        }
    }

    /// L_bᵀ x = y on this block's columns, in place, with the separator's solution `sep` known.
    fn backward(&self, l: View, x: &mut [f64], sep: &[f64]) {
        assert_eq!(
            x.len(),
            self.end - self.start,
            "a block solves its own unknowns"
        );
        for c in (self.start..self.end).rev() {
            let ((rows, vals), (sep_rows, sep_vals)) = l.column(c);
            let outside = dot(sep_rows, sep_vals, sep, l.sep_start);
            let own = dot(rows, vals, x, self.start);
            let j = c - self.start;
            x[j] = (x[j] - own - outside) * l.inv_diag[c];
        }
    }
}

/// x[r_k − base] −= v_k s.
#[inline(always)]
fn scatter(rows: &[u32], vals: &[f64], s: f64, x: &mut [f64], base: usize) {
    for (&r, &v) in rows.iter().zip(vals) {
        x[r as usize - base] -= v * s;
    }
}

/// Σ v_k x[r_k − base], in four partial sums (one running sum would wait for each addition in
/// turn), from the last entry to the first: the backward solve then reads the factor in one
/// descending stream, which the hardware prefetches (ascending within descending columns measured
/// 2× slower once the factor no longer fits in the cache).
#[inline(always)]
fn dot(rows: &[u32], vals: &[f64], x: &[f64], base: usize) -> f64 {
    let at = |r: u32| x[r as usize - base];
    let (rc, vc) = (rows.rchunks_exact(4), vals.rchunks_exact(4));
    let (rr, vr) = (rc.remainder(), vc.remainder());
    let mut acc = [0.0; 4];
    for (r, v) in rc.zip(vc) {
        for l in (0..4).rev() {
            acc[l] += v[l] * at(r[l]);
        }
    }
    let mut tail = 0.0;
    for (&r, &v) in rr.iter().zip(vr).rev() {
        tail += v * at(r);
    }
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}

/// AMD order of the sub-matrix of `a` on `members`: the k-th entry is the index into `members`.
fn amd_order(a: SparseColMatRef<'_, u32, f64>, members: &[u32]) -> Result<Vec<u32>, FactorError> {
    let nh = members.len();
    let mut local = vec![u32::MAX; a.nrows()];
    for (k, &r) in members.iter().enumerate() {
        local[r as usize] = k as u32;
    }
    let mut trip = Vec::new();
    for &c in members {
        for &r in a.symbolic().row_idx_of_col_raw(c as usize) {
            if local[r as usize] != u32::MAX {
                trip.push(Triplet::new(local[r as usize], local[c as usize], 1.0));
            }
        }
    }
    let sub = SparseColMat::<u32, f64>::try_new_from_triplets(nh, nh, &trip)
        .map_err(|e| FactorError::library("a half of the pressure matrix", e))?;
    let (mut perm, mut perm_inv) = (vec![0u32; nh], vec![0u32; nh]);
    let mut mem = MemBuffer::new(amd::order_scratch::<u32>(nh, trip.len()));
    amd::order(
        &mut perm,
        &mut perm_inv,
        sub.symbolic(),
        amd::Control::default(),
        MemStack::new(&mut mem),
    )
    .map_err(|e| FactorError::library("AMD ordering", e))?;
    Ok(perm)
}

/// Column pointers and row indices of a simplicial factor (as [`factor`] returns).
fn structure(symbolic: &SymbolicCholesky<u32>) -> (&[u32], &[u32]) {
    match symbolic.raw() {
        SymbolicCholeskyRaw::Simplicial(s) => (s.col_ptr(), s.row_idx()),
        SymbolicCholeskyRaw::Supernodal(_) => unreachable!("`factor` refuses a supernodal factor"),
    }
}

/// Simplicial LLᵀ of `a` (lower triangle) with unknown `order[k]` in place k (`position` is the
/// inverse): its structure and values.
fn factor(
    a: SparseColMatRef<'_, u32, f64>,
    order: &[u32],
    position: &[u32],
) -> Result<(SymbolicCholesky<u32>, Vec<f64>), FactorError> {
    let perm = PermRef::new_checked(order, position, order.len());
    let params = CholeskySymbolicParams {
        supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SIMPLICIAL,
        ..Default::default()
    };
    let symbolic = factorize_symbolic_cholesky(
        a.symbolic(),
        Side::Lower,
        SymmetricOrdering::Custom(perm),
        params,
    )
    .map_err(|e| FactorError::library("symbolic Cholesky", e))?;
    let mut values = vec![0.0; symbolic.len_val()];
    let req = symbolic.factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default());
    let mut stack = MemBuffer::new(req);
    symbolic
        .factorize_numeric_llt(
            &mut values,
            a,
            Side::Lower,
            LltRegularization::default(),
            Par::Seq,
            MemStack::new(&mut stack),
            Default::default(),
        )
        .map_err(|e| FactorError::library("numeric Cholesky", e))?;
    if !matches!(symbolic.raw(), SymbolicCholeskyRaw::Simplicial(_)) {
        return Err(FactorError::NotSimplicial);
    }
    Ok((symbolic, values))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 5-point Laplacian of an nx × ny grid (Dirichlet outside), lower triangle.
    fn laplacian(nx: usize, ny: usize) -> SparseColMat<u32, f64> {
        let mut trip = Vec::new();
        for j in 0..ny {
            for i in 0..nx {
                let k = (i + nx * j) as u32;
                trip.push(Triplet::new(k, k, 4.0 + 0.01 * i as f64));
                if i + 1 < nx {
                    trip.push(Triplet::new(k + 1, k, -1.0));
                }
                if j + 1 < ny {
                    trip.push(Triplet::new(k + nx as u32, k, -1.0));
                }
            }
        }
        SparseColMat::try_new_from_triplets(nx * ny, nx * ny, &trip).unwrap()
    }

    #[test]
    fn solves_a_laplacian_split_by_its_middle_column() {
        let (nx, ny) = (23, 17);
        let a = laplacian(nx, ny);
        let part: Vec<Part> = (0..nx * ny)
            .map(|k| Part::of_column(k % nx, nx / 2))
            .collect();
        let mut f = SplitCholesky::new(a.as_ref(), &part).unwrap();
        let exact: Vec<f64> = (0..nx * ny)
            .map(|k| ((k * 7919) % 101) as f64 - 50.0)
            .collect();
        // b = A x with A symmetric, from its lower triangle.
        let mut b = vec![0.0; nx * ny];
        for c in 0..nx * ny {
            for (&r, &v) in a
                .symbolic()
                .row_idx_of_col_raw(c)
                .iter()
                .zip(a.val_of_col(c))
            {
                let r = r as usize;
                b[r] += v * exact[c];
                if r != c {
                    b[c] += v * exact[r];
                }
            }
        }
        let mut x = vec![0.0; nx * ny];
        for (k, &bk) in b.iter().enumerate() {
            x[f.position[k] as usize] = bk;
        }
        f.solve_in_place(&mut x);
        for (k, &e) in exact.iter().enumerate() {
            let got = x[f.position[k] as usize];
            assert!((got - e).abs() < 1e-11 * 50.0, "unknown {k}: {got} vs {e}");
        }
    }

    #[test]
    fn refuses_coupled_halves() {
        let a = laplacian(4, 3);
        let part: Vec<Part> = (0..12)
            .map(|k| if k % 4 < 2 { Part::Left } else { Part::Right })
            .collect();
        assert!(SplitCholesky::new(a.as_ref(), &part).is_err());
    }
}
