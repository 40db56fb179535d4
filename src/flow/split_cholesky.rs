//! The pressure operator's Cholesky factor, ordered for two threads (SPEC §3, the projection).
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
//! about half the time where memory bandwidth allows (README, "Performance").
use std::ops::Range;

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::perm::PermRef;
use faer::sparse::linalg::amd;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, SymbolicCholeskyRaw, SymmetricOrdering,
};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::{SparseColMat, SparseColMatRef, Triplet};
use faer::{Par, Side};

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

/// Columns `start..start + n` of L: their rows lie in the same block or in the separator.
struct Block {
    start: usize,
    /// Entries of column j: `ptr[j]..mid[j]` rows of this block (local index),
    /// `mid[j]..ptr[j + 1]` rows of the separator (index within the separator).
    ptr: Vec<u32>,
    mid: Vec<u32>,
    row: Vec<u32>,
    val: Vec<f64>,
    inv_diag: Vec<f64>,
    /// The forward solve's updates to the separator's right-hand side.
    to_separator: Vec<f64>,
    /// Size of the separator.
    ns: usize,
}

/// The factor of a symmetric positive definite matrix in the two-halves-and-separator order.
pub struct SplitCholesky {
    left: Block,
    right: Block,
    separator: Block,
    /// Position of each unknown (in the caller's numbering) in the factor's order.
    pub position: Vec<u32>,
    /// Nonzeros of L.
    pub nnz: usize,
}

impl SplitCholesky {
    /// Orders and factors `a` (its lower triangle, in the caller's numbering), `part[r]` naming the
    /// block of unknown r. Left and right unknowns must not be coupled.
    pub fn new(a: SparseColMatRef<'_, u32, f64>, part: &[Part]) -> Result<Self, String> {
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
        let l = factor(a, &order, &position)?;
        let block = |b: usize, end: usize| Block::from_factor(&l, starts[b]..end, starts[2]);
        Ok(SplitCholesky {
            left: block(0, starts[1])?,
            right: block(1, starts[2])?,
            separator: block(2, n)?,
            position,
            nnz: l.values.len(),
        })
    }

    /// Solves A x = b in place; `x` is in the factor's order (see [`SplitCholesky::position`]).
    pub fn solve_in_place(&mut self, x: &mut [f64]) {
        let (halves, sep) = x.split_at_mut(self.separator.start);
        let (xl, xr) = halves.split_at_mut(self.right.start);
        let (left, right) = (&mut self.left, &mut self.right);
        rayon::join(|| left.forward(xl), || right.forward(xr));
        for ((s, a), b) in sep
            .iter_mut()
            .zip(&left.to_separator)
            .zip(&right.to_separator)
        {
            *s += a + b;
        }
        self.separator.forward(sep);
        self.separator.backward(sep, &[]);
        let sep = &*sep;
        rayon::join(|| left.backward(xl, sep), || right.backward(xr, sep));
    }
}

impl Block {
    /// The given columns of L; rows at or beyond `sep_start` belong to the separator.
    fn from_factor(l: &Csc, columns: Range<usize>, sep_start: usize) -> Result<Block, String> {
        let (start, end) = (columns.start, columns.end);
        let (col_ptr, row_idx, values) = (&l.col_ptr, &l.row_idx, &l.values);
        let n = end - start;
        // The separator's own block has no rows outside it.
        let ns = if start == sep_start {
            0
        } else {
            l.col_ptr.len() - 1 - sep_start
        };
        let mut b = Block {
            start,
            ptr: Vec::with_capacity(n + 1),
            mid: Vec::with_capacity(n),
            row: Vec::new(),
            val: Vec::new(),
            inv_diag: Vec::with_capacity(n),
            to_separator: vec![0.0; ns],
            ns,
        };
        b.ptr.push(0);
        let mut outside = Vec::new();
        for c in start..end {
            let (lo, hi) = (col_ptr[c] as usize, col_ptr[c + 1] as usize);
            if row_idx[lo] as usize != c || values[lo] <= 0.0 {
                return Err(format!(
                    "column {c} of the factor does not start with its diagonal"
                ));
            }
            b.inv_diag.push(1.0 / values[lo]);
            outside.clear();
            for k in lo + 1..hi {
                let r = row_idx[k] as usize;
                if (start..end).contains(&r) {
                    b.row.push((r - start) as u32);
                    b.val.push(values[k]);
                } else if r >= sep_start {
                    outside.push(((r - sep_start) as u32, values[k]));
                } else {
                    return Err(format!(
                        "the factor couples the two halves (row {r}, column {c})"
                    ));
                }
            }
            b.mid.push(b.row.len() as u32);
            for &(r, v) in &outside {
                b.row.push(r);
                b.val.push(v);
            }
            b.ptr.push(b.row.len() as u32);
        }
        Ok(b)
    }

    /// L_b y = x on this block's columns, in place; the updates to the separator go to
    /// `to_separator`.
    fn forward(&mut self, x: &mut [f64]) {
        let n = self.inv_diag.len();
        assert_eq!(x.len(), n, "a block's forward solve needs its own unknowns");
        self.to_separator.fill(0.0);
        for j in 0..n {
            let xj = x[j] * self.inv_diag[j];
            x[j] = xj;
            let (a, m, b) = (
                self.ptr[j] as usize,
                self.mid[j] as usize,
                self.ptr[j + 1] as usize,
            );
            scatter(&self.row[a..m], &self.val[a..m], xj, x);
            scatter(&self.row[m..b], &self.val[m..b], xj, &mut self.to_separator);
        }
    }

    /// L_bᵀ x = y on this block's columns, in place, with the separator's solution `sep` known.
    fn backward(&self, x: &mut [f64], sep: &[f64]) {
        let n = self.inv_diag.len();
        assert_eq!(
            x.len(),
            n,
            "a block's backward solve needs its own unknowns"
        );
        assert_eq!(
            sep.len(),
            self.ns,
            "a block's backward solve needs the separator"
        );
        for j in (0..n).rev() {
            let (a, m, b) = (
                self.ptr[j] as usize,
                self.mid[j] as usize,
                self.ptr[j + 1] as usize,
            );
            let outside = dot(&self.row[m..b], &self.val[m..b], sep);
            let own = dot(&self.row[a..m], &self.val[a..m], x);
            x[j] = (x[j] - own - outside) * self.inv_diag[j];
        }
    }
}

/// x[r_k] −= v_k s.
#[inline(always)]
fn scatter(rows: &[u32], vals: &[f64], s: f64, x: &mut [f64]) {
    for (&r, &v) in rows.iter().zip(vals) {
        x[r as usize] -= v * s;
    }
}

/// Σ v_k x[r_k], in four partial sums (one running sum would wait for each addition in turn),
/// from the last entry to the first: the backward solve then reads the factor in one descending
/// stream, which the hardware prefetches (ascending within descending columns measured 2× slower
/// once the factor no longer fits in the cache).
#[inline(always)]
fn dot(rows: &[u32], vals: &[f64], x: &[f64]) -> f64 {
    let at = |r: u32| x[r as usize];
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
fn amd_order(a: SparseColMatRef<'_, u32, f64>, members: &[u32]) -> Result<Vec<u32>, String> {
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
        .map_err(|e| format!("a half of the pressure matrix: {e:?}"))?;
    let (mut perm, mut perm_inv) = (vec![0u32; nh], vec![0u32; nh]);
    let mut mem = MemBuffer::new(amd::order_scratch::<u32>(nh, trip.len()));
    amd::order(
        &mut perm,
        &mut perm_inv,
        sub.symbolic(),
        amd::Control::default(),
        MemStack::new(&mut mem),
    )
    .map_err(|e| format!("AMD ordering: {e:?}"))?;
    Ok(perm)
}

/// A lower-triangular factor, column by column, the diagonal first in each column.
struct Csc {
    col_ptr: Vec<u32>,
    row_idx: Vec<u32>,
    values: Vec<f64>,
}

/// Simplicial LLᵀ of `a` (lower triangle) with unknown `order[k]` in place k (`position` is the
/// inverse): the factor's column pointers, row indices and values.
fn factor(
    a: SparseColMatRef<'_, u32, f64>,
    order: &[u32],
    position: &[u32],
) -> Result<Csc, String> {
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
    .map_err(|e| format!("symbolic Cholesky: {e:?}"))?;
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
        .map_err(|e| format!("numeric Cholesky: {e:?}"))?;
    let SymbolicCholeskyRaw::Simplicial(s) = symbolic.raw() else {
        return Err("the Cholesky factor is not simplicial".into());
    };
    Ok(Csc {
        col_ptr: s.col_ptr().to_vec(),
        row_idx: s.row_idx().to_vec(),
        values,
    })
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
