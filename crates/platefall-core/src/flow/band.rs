//! Banded line solves for the implicit grid transport (`implicit/`), on preallocated data.
//!
//! Each system is (I + t L) Δ = R along one grid line, L the five-point operator of
//! `transport.rs` (at most two points on the upwind side, one on the other). Gaussian
//! elimination without pivoting, top to bottom: for the upwind-biased transport operator the
//! pivots stay ≥ 1 + (Courant number)/2 in either direction of transport, so it is stable at any
//! Courant number. The value beyond each end of a line is either known (a boundary face or a
//! prescribed ghost; its increment is stored in the array) or tied to the end unknown by
//! q_end = s·q_first (s = −1: zero on the wall between them, rest inflow; s = +1: zero gradient,
//! outflow), chosen so that it adds to the diagonal.
use std::ops::Range;

use super::array::Padded;
use super::transport::Stencil;

/// What lies beyond the end of a line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum End {
    /// The value there (a Δ) is stored in the array itself.
    Known,
    /// It equals `s` times the end unknown.
    Relation(f64),
}

/// Row k's stencil with the ends of the line (unknowns `first..=last`, end values `lo`, `hi` at
/// first − 1 and last + 1) taken out: known values go to the right-hand side (returned), relations
/// onto the end unknown's coefficient.
#[inline(always)]
pub fn with_ends(
    mut c: Stencil,
    k: isize,
    (first, last): (isize, isize),
    ends: (End, End),
    (lo, hi): (f64, f64),
) -> (Stencil, f64) {
    let mut rhs = 0.0;
    for (end, value, at, tie) in [(ends.0, lo, first - 1, first), (ends.1, hi, last + 1, last)] {
        let off = at - k;
        if off.abs() > 2 {
            continue;
        }
        let slot = (off + 2) as usize;
        let coef = std::mem::take(&mut c[slot]);
        match end {
            End::Known => rhs -= coef * value,
            End::Relation(s) => c[(tie - k + 2) as usize] += s * coef,
        }
    }
    (c, rhs)
}

/// One elimination step: row (a₂, a₁, a₀, b₁, b₂; r) against the two rows above it, reduced to
/// x_k + γ x_{k+1} + δ x_{k+2} = ρ. `prev` holds (γ, δ, ρ) of rows k−2 and k−1.
#[inline(always)]
fn eliminate(c: Stencil, r: f64, prev: [(f64, f64, f64); 2]) -> (f64, f64, f64) {
    let [(g2, d2, r2), (g1, d1, r1)] = prev;
    let a1 = c[1] - c[0] * g2;
    let a0 = c[2] - c[0] * d2;
    let rr = r - c[0] * r2;
    let piv = a0 - a1 * g1;
    let b1 = c[3] - a1 * d1;
    ((b1) / piv, c[4] / piv, (rr - a1 * r1) / piv)
}

/// Solves one line stored contiguously at `line[1..=n]` (ends at `line[0]`, `line[n + 1]`), row k
/// from `row(k)`; `gamma` and `delta` are scratch of length ≥ n + 1.
pub fn solve_line(
    line: &mut [f64],
    row: impl Fn(usize) -> Stencil,
    ends: (End, End),
    gamma: &mut [f64],
    delta: &mut [f64],
) {
    let n = line.len() - 2;
    debug_assert!(n >= 3 && gamma.len() > n && delta.len() > n);
    let (lo, hi) = (line[0], line[n + 1]);
    let mut prev = [(0.0, 0.0, 0.0); 2];
    for k in 1..=n {
        let (c, dr) = with_ends(row(k), k as isize, (1, n as isize), ends, (lo, hi));
        let e = eliminate(c, line[k] + dr, prev);
        (gamma[k], delta[k], line[k]) = e;
        prev = [prev[1], e];
    }
    for k in (1..n).rev() {
        let next2 = if k + 2 <= n { line[k + 2] } else { 0.0 };
        line[k] -= gamma[k] * line[k + 1] + delta[k] * next2;
    }
}

/// The columns `cols` solved together, row by row (contiguous in memory): unknowns in rows
/// `rows`, ends in the rows just outside; `row(i, j)` is the stencil of column i at row j and
/// `ends[i]` its ends. `gamma` and `delta` have the layout of `d`.
pub fn solve_columns(
    d: &mut Padded,
    (gamma, delta): (&mut Padded, &mut Padded),
    cols: Range<isize>,
    rows: Range<isize>,
    row: impl Fn(isize, isize) -> Stencil,
    ends: &[(End, End)],
) {
    if cols.is_empty() {
        return;
    }
    let (first, last) = (rows.start, rows.end - 1);
    debug_assert!(last - first >= 2);
    for j in rows.clone() {
        let (r0, r1, r2) = (
            d.at(cols.start, j),
            d.at(cols.start, j - 1),
            d.at(cols.start, j - 2),
        );
        for (q, i) in cols.clone().enumerate() {
            let e = ends[i as usize];
            let bounds = (d.get(i, first - 1), d.get(i, last + 1));
            let (c, dr) = with_ends(row(i, j), j, (first, last), e, bounds);
            let at = |k: usize, o: isize| -> (f64, f64, f64) {
                if j - o < first {
                    (0.0, 0.0, 0.0)
                } else {
                    (gamma.data[k + q], delta.data[k + q], d.data[k + q])
                }
            };
            let prev = [at(r2, 2), at(r1, 1)];
            let (g, dl, rho) = eliminate(c, d.data[r0 + q] + dr, prev);
            (gamma.data[r0 + q], delta.data[r0 + q], d.data[r0 + q]) = (g, dl, rho);
        }
    }
    for j in (first..last).rev() {
        let (r0, r1) = (d.at(cols.start, j), d.at(cols.start, j + 1));
        let r2 = if j + 2 <= last {
            Some(d.at(cols.start, j + 2))
        } else {
            None
        };
        for q in 0..cols.len() {
            let next2 = r2.map_or(0.0, |r| d.data[r + q]);
            d.data[r0 + q] -= gamma.data[r0 + q] * d.data[r1 + q] + delta.data[r0 + q] * next2;
        }
    }
}
