//! Tridiagonal line solves for the implicit grid transport (`implicit.rs`), on preallocated data.
//!
//! Every system is (I + β_l·D) Δ = R along one grid line, β_l = a·g constant along the line and
//! D the transport difference of the line's control volumes,
//! D q_k = cv_k (c_{k+½} − c_{k−½}), c_{k+½} = (1 − θ_k) q_k + θ_k q_{k+1}
//! (cv_k the inverse control-volume length, θ_k the fractional position of the face between
//! points k and k+1). The sub- and super-diagonals β cv_k (1 − θ_{k−1}) and −β cv_k θ_k have
//! opposite signs, so the Thomas pivots are diag_k + |…|/d_{k−1}: no pivoting is needed at any
//! Courant number (the diagonal 1 − β cv_k (1 − θ_k − θ_{k−1}) departs from 1 only by the grid's
//! stretching). The value beyond each end is either known (a boundary face, or a prescribed
//! ghost) or tied to the end unknown by q_end = s·q_first (s = −1: zero on the wall between them,
//! rest inflow; s = +1: zero gradient, outflow), chosen so that it adds to the diagonal.
use std::ops::Range;

use super::array::Padded;

/// What lies beyond the end of a line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum End {
    /// The value there (a Δ) is stored in the array itself.
    Known,
    /// It equals `s` times the end unknown.
    Relation(f64),
}

/// The coefficients (lower, diagonal, upper) of row k of I + β D, from its cv and the face
/// positions below (θ_{k−1}) and above (θ_k).
#[inline(always)]
pub fn row(beta: f64, cv: f64, theta_lo: f64, theta_hi: f64) -> (f64, f64, f64) {
    let b = beta * cv;
    (
        b * (1.0 - theta_lo),
        1.0 - b * (1.0 - theta_hi - theta_lo),
        -b * theta_hi,
    )
}

/// Solves one line stored contiguously: unknowns `line[1..=n]`, the ends `line[0]` and
/// `line[n + 1]`; `cv[k − 1]` belongs to unknown k and `theta[k]` to the face between local
/// points k and k + 1 (k = 0..=n); `cp` is scratch of length ≥ n + 1.
pub fn solve_line(
    line: &mut [f64],
    cv: &[f64],
    theta: &[f64],
    beta: f64,
    ends: (End, End),
    cp: &mut [f64],
) {
    let n = line.len() - 2;
    debug_assert!(n >= 2 && cv.len() >= n && theta.len() > n && cp.len() > n);
    let first = row(beta, cv[0], theta[0], theta[1]);
    let last = row(beta, cv[n - 1], theta[n - 1], theta[n]);
    let t = EndTerms::new(
        [line[0], line[1], line[n], line[n + 1]],
        first.0,
        last.2,
        ends,
    );
    (line[1], line[n]) = (t.first, t.last);
    let (mut prev_cp, mut prev_d) = (0.0, 0.0);
    for k in 1..=n {
        let (lower, mut diag, upper) = row(beta, cv[k - 1], theta[k - 1], theta[k]);
        diag -= lower * prev_cp;
        if k == 1 {
            diag += t.lo_diag;
        }
        if k == n {
            diag += t.hi_diag;
        }
        prev_cp = upper / diag;
        prev_d = (line[k] - lower * prev_d) / diag;
        cp[k] = prev_cp;
        line[k] = prev_d;
    }
    for k in (1..n).rev() {
        line[k] -= cp[k] * line[k + 1];
    }
}

/// The ends of one line applied: the first and last right-hand sides with the known values moved
/// over, and what the relations add to the first and last diagonal.
struct EndTerms {
    first: f64,
    last: f64,
    lo_diag: f64,
    hi_diag: f64,
}

impl EndTerms {
    /// `[before, first, last, after]`: the end values and the first and last right-hand sides;
    /// `lower` is the first row's sub-diagonal, `upper` the last row's super-diagonal.
    fn new(v: [f64; 4], lower: f64, upper: f64, ends: (End, End)) -> EndTerms {
        let [before, mut first, mut last, after] = v;
        let lo_diag = match ends.0 {
            End::Known => {
                first -= lower * before;
                0.0
            }
            End::Relation(s) => s * lower,
        };
        let hi_diag = match ends.1 {
            End::Known => {
                last -= upper * after;
                0.0
            }
            End::Relation(s) => s * upper,
        };
        EndTerms {
            first,
            last,
            lo_diag,
            hi_diag,
        }
    }
}

/// The columns of one segment solved together, row by row (contiguous in memory): unknowns in
/// rows `rows`, ends in the rows just outside; `cv[j]` for row j, `theta[j + offset]` for the
/// face above row j, `beta[i]` and `ends[i]` for column i. `cp` has the layout of `d`; its rows
/// just outside `rows` hold the end terms.
pub struct Columns<'a> {
    pub cols: Range<isize>,
    pub rows: Range<isize>,
    pub cv: &'a [f64],
    pub theta: &'a [f64],
    pub theta_offset: isize,
    pub beta: &'a [f64],
    pub ends: &'a [(End, End)],
}

impl Columns<'_> {
    /// The coefficients of row j in column i.
    #[inline(always)]
    fn row(&self, i: isize, j: isize) -> (f64, f64, f64) {
        let t = |k: isize| self.theta[(k + self.theta_offset) as usize];
        row(self.beta[i as usize], self.cv[j as usize], t(j - 1), t(j))
    }

    /// Solves every column of the segment in place in `d`.
    pub fn solve(&self, d: &mut Padded, cp: &mut Padded) {
        let (j0, j1) = (self.rows.start, self.rows.end);
        if self.cols.is_empty() {
            return;
        }
        debug_assert!(j1 - j0 >= 2);
        self.apply_ends(d, cp);
        for j in j0..j1 {
            self.eliminate(d, cp, j);
        }
        for j in (j0..j1 - 1).rev() {
            let (r, next) = (d.at(self.cols.start, j), d.at(self.cols.start, j + 1));
            for q in 0..self.cols.len() {
                d.data[r + q] -= cp.data[r + q] * d.data[next + q];
            }
        }
    }

    /// Known ends go into the first and last right-hand sides; the relations' diagonal additions
    /// are kept in the rows of `cp` just outside the unknowns.
    fn apply_ends(&self, d: &mut Padded, cp: &mut Padded) {
        let (j0, j1) = (self.rows.start, self.rows.end);
        for i in self.cols.clone() {
            let (lower, upper) = (self.row(i, j0).0, self.row(i, j1 - 1).2);
            let v = [
                d.get(i, j0 - 1),
                d.get(i, j0),
                d.get(i, j1 - 1),
                d.get(i, j1),
            ];
            let t = EndTerms::new(v, lower, upper, self.ends[i as usize]);
            d.set(i, j0, t.first);
            d.set(i, j1 - 1, t.last);
            cp.set(i, j0 - 1, t.lo_diag);
            cp.set(i, j1, t.hi_diag);
        }
    }

    /// Forward elimination of row j for every column of the segment.
    fn eliminate(&self, d: &mut Padded, cp: &mut Padded, j: isize) {
        let (j0, j1) = (self.rows.start, self.rows.end);
        let (r, prev) = (d.at(self.cols.start, j), d.at(self.cols.start, j - 1));
        let hi = cp.at(self.cols.start, j1);
        for (q, i) in self.cols.clone().enumerate() {
            let (lower, mut diag, upper) = self.row(i, j);
            let pd = if j == j0 {
                diag += cp.data[prev + q];
                0.0
            } else {
                diag -= lower * cp.data[prev + q];
                d.data[prev + q]
            };
            if j == j1 - 1 {
                diag += cp.data[hi + q];
            }
            cp.data[r + q] = upper / diag;
            d.data[r + q] = (d.data[r + q] - lower * pd) / diag;
        }
    }
}
