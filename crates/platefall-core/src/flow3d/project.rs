//! The projection (docs/physics.md §9): the predicted velocity u* is made discretely
//! divergence-free in every fluid cell by u = u* − Δt G p, with p from
//!
//! ```text
//!   Σ_faces (A_f / d_f) (p_P − p_nb) = −(1/Δt) Σ_faces A_f u*·n      (every fluid cell P)
//! ```
//!
//! (A_f the face's area, d_f the distance between the two centres; no term across the outer
//! boundary, where the normal velocity is given, nor across a plate face, where it is g). The
//! operator is symmetric and positive semi-definite (constants span its null space; the
//! right-hand side is made orthogonal to them). It is handed to a [`PoissonSolve`] as per-face
//! coefficients: [`super::MultigridCg`] (conjugate gradients preconditioned by a multigrid
//! V-cycle) by default, [`JacobiCg`] (a diagonal preconditioner) as a simple reference. The solve stops on the quantity that matters: the largest cell divergence the
//! correction would leave, |r_P| Δt / V_P.
use rayon::prelude::*;

use super::grid::Grid3;
use super::layout::{Layout, G};
use super::metrics::Metrics3;

/// The pressure operator as per-face coefficients over the cells, index i + nx (j + ny k).
#[derive(Clone, Debug)]
pub struct PoissonOperator {
    /// Cells along x, y, z.
    pub n: [usize; 3],
    /// Whether the last z-face of each column connects to the first.
    pub periodic_z: bool,
    /// A_f / d_f of the + face of each cell along x, y, z (zero where it connects nothing).
    pub coef: [Vec<f64>; 3],
    /// The sum of each cell's six coefficients (zero in solid cells: no unknown).
    pub diag: Vec<f64>,
    /// Cell volumes.
    pub volume: Vec<f64>,
    /// Cell widths along x, y, z (`n[a]` each).
    pub widths: [Vec<f64>; 3],
}

impl PoissonOperator {
    /// The operator of a grid (plate cells excluded).
    pub fn new(grid: &Grid3, m: &Metrics3) -> PoissonOperator {
        let n = grid.n;
        let cells = grid.cells();
        let mut coef: [Vec<f64>; 3] = std::array::from_fn(|_| vec![0.0; cells]);
        let mut diag = vec![0.0; cells];
        let mut volume = vec![0.0; cells];
        for idx in 0..cells {
            let c = [idx % n[0], (idx / n[0]) % n[1], idx / (n[0] * n[1])];
            let p = c.map(|v| v as isize);
            volume[idx] = (0..3).map(|a| m.axes[a].width(p[a])).product();
            if grid.solid(c) {
                continue;
            }
            for a in 0..3 {
                let wraps = a == 2 && grid.periodic_z;
                let mut nb = c;
                nb[a] += 1;
                if nb[a] == n[a] {
                    if !wraps {
                        continue;
                    }
                    nb[a] = 0;
                }
                if grid.solid(nb) {
                    continue;
                }
                let (b1, b2) = ((a + 1) % 3, (a + 2) % 3);
                let area = m.axes[b1].width(p[b1]) * m.axes[b2].width(p[b2]);
                let gap = m.axes[a].centre(p[a] + 1) - m.axes[a].centre(p[a]);
                let k = area / gap;
                coef[a][idx] = k;
                diag[idx] += k;
                diag[flat(n, nb)] += k;
            }
        }
        PoissonOperator {
            n,
            periodic_z: grid.periodic_z,
            coef,
            diag,
            volume,
            widths: std::array::from_fn(|a| {
                (0..n[a] as isize).map(|k| m.axes[a].width(k)).collect()
            }),
        }
    }

    /// Number of cells.
    pub fn cells(&self) -> usize {
        self.diag.len()
    }

    /// Multiplies the coefficient of the + face along a of cell `lo` by `factor` (a cut face's
    /// open fraction, 0 for a face the body holds); [`PoissonOperator::refresh_diagonal`] then
    /// brings the diagonal up to date.
    pub(super) fn scale_face(&mut self, a: usize, lo: usize, factor: f64) {
        self.coef[a][lo] *= factor;
    }

    /// The diagonal from the face coefficients (each cell's sum; zero where every face is
    /// closed: no unknown).
    pub(super) fn refresh_diagonal(&mut self) {
        let [nx, ny, nz] = self.n;
        self.diag.iter_mut().for_each(|d| *d = 0.0);
        for idx in 0..self.cells() {
            let c = [idx % nx, (idx / nx) % ny, idx / (nx * ny)];
            for a in 0..3 {
                let k = self.coef[a][idx];
                if k == 0.0 {
                    continue;
                }
                let mut nb = c;
                nb[a] = (nb[a] + 1) % [nx, ny, nz][a];
                self.diag[idx] += k;
                self.diag[flat(self.n, nb)] += k;
            }
        }
    }

    /// (A x)_P for the cells of one z-plane k, written to `y` (that plane's slice).
    fn apply_plane(&self, x: &[f64], k: usize, y: &mut [f64]) {
        let [nx, ny, nz] = self.n;
        let plane = nx * ny;
        let zs = |kk: usize| kk * plane;
        let below = if k > 0 {
            Some(k - 1)
        } else if self.periodic_z {
            Some(nz - 1)
        } else {
            None
        };
        let above = if k + 1 < nz {
            Some(k + 1)
        } else if self.periodic_z {
            Some(0)
        } else {
            None
        };
        for j in 0..ny {
            for i in 0..nx {
                let local = i + nx * j;
                let c = zs(k) + local;
                let mut s = self.diag[c] * x[c];
                if i + 1 < nx {
                    s -= self.coef[0][c] * x[c + 1];
                }
                if i > 0 {
                    s -= self.coef[0][c - 1] * x[c - 1];
                }
                if j + 1 < ny {
                    s -= self.coef[1][c] * x[c + nx];
                }
                if j > 0 {
                    s -= self.coef[1][c - nx] * x[c - nx];
                }
                if let Some(kk) = above {
                    s -= self.coef[2][c] * x[zs(kk) + local];
                }
                if let Some(kk) = below {
                    let b = zs(kk) + local;
                    s -= self.coef[2][b] * x[b];
                }
                y[local] = s;
            }
        }
    }

    /// y = A x, z-planes in parallel.
    pub fn apply(&self, x: &[f64], y: &mut [f64]) {
        let plane = self.n[0] * self.n[1];
        y.par_chunks_mut(plane)
            .enumerate()
            .for_each(|(k, yk)| self.apply_plane(x, k, yk));
    }
}

/// Flat cell index.
#[inline(always)]
pub fn flat(n: [usize; 3], c: [usize; 3]) -> usize {
    c[0] + n[0] * (c[1] + n[1] * c[2])
}

/// When a pressure solve stops.
#[derive(Clone, Copy, Debug)]
pub struct Stop<'a> {
    /// Per cell, the factor turning a residual into the divergence it leaves (Δt / V).
    pub weight: &'a [f64],
    /// Largest divergence accepted.
    pub tol: f64,
    /// Most iterations.
    pub max_iterations: usize,
}

/// What a solve did.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SolveStats {
    /// Iterations taken.
    pub iterations: usize,
    /// Largest divergence the solution leaves (|r| Δt / V).
    pub divergence: f64,
    /// Whether it reached the tolerance.
    pub converged: bool,
}

/// A solver of the pressure equation built from a [`PoissonOperator`]: solves A p = b from the
/// warm start in `p` (b orthogonal to constants on the fluid cells). Allocates nothing.
pub trait PoissonSolve: Send + Sync {
    /// Solves in place; `p` holds the previous solution on entry.
    fn solve(&mut self, rhs: &[f64], p: &mut [f64], stop: Stop) -> SolveStats;
    /// The operator it solves.
    fn operator(&self) -> &PoissonOperator;
}

/// Conjugate gradients preconditioned by the diagonal (Jacobi), with dot products summed per
/// z-plane and then in plane order (the same bits on any number of threads).
#[derive(Clone, Debug)]
pub struct JacobiCg {
    op: PoissonOperator,
    inv_diag: Vec<f64>,
    r: Vec<f64>,
    z: Vec<f64>,
    d: Vec<f64>,
    q: Vec<f64>,
    partial: Vec<f64>,
}

impl JacobiCg {
    /// The solver and its workspaces.
    pub fn new(op: PoissonOperator) -> JacobiCg {
        let n = op.cells();
        let inv_diag = op
            .diag
            .iter()
            .map(|&d| if d > 0.0 { 1.0 / d } else { 0.0 })
            .collect();
        JacobiCg {
            inv_diag,
            r: vec![0.0; n],
            z: vec![0.0; n],
            d: vec![0.0; n],
            q: vec![0.0; n],
            partial: vec![0.0; op.n[2]],
            op,
        }
    }

    /// Σ a·b, per plane in parallel and then in plane order.
    fn dot(partial: &mut [f64], plane: usize, a: &[f64], b: &[f64]) -> f64 {
        partial.par_iter_mut().enumerate().for_each(|(k, s)| {
            let r = k * plane..(k + 1) * plane;
            *s = a[r.clone()].iter().zip(&b[r]).map(|(x, y)| x * y).sum();
        });
        partial.iter().sum()
    }

    /// r = b − A p and the largest weighted residual.
    fn residual(&mut self, b: &[f64], p: &[f64], weight: &[f64]) -> f64 {
        weighted_residual(&self.op, b, p, weight, &mut self.r)
    }
}

impl PoissonSolve for JacobiCg {
    fn solve(&mut self, b: &[f64], p: &mut [f64], stop: Stop) -> SolveStats {
        let plane = self.op.n[0] * self.op.n[1];
        let mut stats = SolveStats::default();
        // Restarted from the true residual until it holds (the recursive one drifts).
        for _restart in 0..4 {
            stats.divergence = self.residual(b, p, stop.weight);
            if stats.divergence <= stop.tol || stats.iterations >= stop.max_iterations {
                break;
            }
            self.precondition_into_z();
            self.d.copy_from_slice(&self.z);
            let mut rz = Self::dot(&mut self.partial, plane, &self.r, &self.z);
            while stats.iterations < stop.max_iterations {
                self.op.apply(&self.d, &mut self.q);
                let dq = Self::dot(&mut self.partial, plane, &self.d, &self.q);
                // Not positive (or NaN): the search direction is exhausted.
                if dq.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                    break;
                }
                let alpha = rz / dq;
                let mut worst: f64 = 0.0;
                for (k, pk) in p.iter_mut().enumerate() {
                    *pk += alpha * self.d[k];
                    self.r[k] -= alpha * self.q[k];
                    worst = worst.max(self.r[k].abs() * stop.weight[k]);
                }
                stats.iterations += 1;
                if worst <= 0.5 * stop.tol {
                    break;
                }
                self.precondition_into_z();
                let rz_new = Self::dot(&mut self.partial, plane, &self.r, &self.z);
                let beta = rz_new / rz;
                rz = rz_new;
                for (d, &z) in self.d.iter_mut().zip(&self.z) {
                    *d = z + beta * *d;
                }
            }
        }
        stats.converged = stats.divergence <= stop.tol;
        stats
    }

    fn operator(&self) -> &PoissonOperator {
        &self.op
    }
}

impl JacobiCg {
    fn precondition_into_z(&mut self) {
        for ((z, &r), &m) in self.z.iter_mut().zip(&self.r).zip(&self.inv_diag) {
            *z = r * m;
        }
    }
}

/// r = b − A p into `r`, and the largest |r_P| w_P: the divergence the correction leaves when
/// w = Δt / V (the stopping test of every [`PoissonSolve`]).
pub(super) fn weighted_residual(
    op: &PoissonOperator,
    b: &[f64],
    p: &[f64],
    weight: &[f64],
    r: &mut [f64],
) -> f64 {
    op.apply(p, r);
    let mut worst: f64 = 0.0;
    for ((r, &b), &w) in r.iter_mut().zip(b).zip(weight) {
        *r = b - *r;
        worst = worst.max(r.abs() * w);
    }
    worst
}

/// The pressure equation's right-hand side from the cells' net outflows in `rhs` (in place):
/// b = −outflow / Δt with its mean over the fluid cells removed (the all-Neumann equation's
/// compatibility), zero in solid cells; and the divergence weights Δt / V of [`Stop`].
pub(super) fn pressure_rhs(op: &PoissonOperator, dt: f64, rhs: &mut [f64], weight: &mut [f64]) {
    let (mut sum, mut count) = (0.0, 0usize);
    for (k, b) in rhs.iter_mut().enumerate() {
        *b *= -1.0 / dt;
        if op.diag[k] > 0.0 {
            sum += *b;
            count += 1;
        }
    }
    let mean = if count > 0 { sum / count as f64 } else { 0.0 };
    for ((b, w), (&d, &v)) in rhs
        .iter_mut()
        .zip(weight.iter_mut())
        .zip(op.diag.iter().zip(&op.volume))
    {
        let active = d > 0.0;
        *b = if active { *b - mean } else { 0.0 };
        *w = if active { dt / v } else { 0.0 };
    }
}

/// Net outflow Σ A u·n of every cell (zero in solid cells), into `div`.
pub fn cell_fluxes(
    vel: [&[f64]; 3],
    m: &Metrics3,
    lay: &Layout,
    op: &PoissonOperator,
    div: &mut [f64],
) {
    let n = op.n;
    let plane = n[0] * n[1];
    div.par_chunks_mut(plane).enumerate().for_each(|(k, dk)| {
        for j in 0..n[1] {
            for i in 0..n[0] {
                let local = i + n[0] * j;
                if op.diag[k * plane + local] == 0.0 {
                    dk[local] = 0.0;
                    continue;
                }
                let p = [i as isize, j as isize, k as isize];
                let mut s = 0.0;
                for (a, q) in vel.iter().enumerate() {
                    let (b1, b2) = ((a + 1) % 3, (a + 2) % 3);
                    let area = m.axes[b1].width(p[b1]) * m.axes[b2].width(p[b2]);
                    let at = lay.at(p);
                    s += (q[at + lay.stride[a]] - q[at]) * area;
                }
                dk[local] = s;
            }
        }
    });
}

/// u −= Δt G p on every face between two fluid cells (the periodic z face 0 and its copy nz).
pub fn correct(
    vel: &mut [Vec<f64>; 3],
    m: &Metrics3,
    lay: &Layout,
    op: &PoissonOperator,
    p: &[f64],
    dt: f64,
) {
    let n = op.n;
    let sk = lay.stride[2];
    for (a, q) in vel.iter_mut().enumerate() {
        let periodic = a == 2 && op.periodic_z;
        q.par_chunks_mut(sk).enumerate().for_each(|(kk, slice)| {
            let k = kk as isize - G as isize;
            if k < 0 || k >= lay.points(a, 2) {
                return;
            }
            for j in 0..lay.points(a, 1) {
                for i in 0..lay.points(a, 0) {
                    let f = [i, j, k];
                    // Cells on either side of face f along a.
                    let mut lo = f;
                    lo[a] -= 1;
                    if lo[a] < 0 {
                        if !periodic {
                            continue;
                        }
                        lo[a] = n[a] as isize - 1;
                    }
                    if f[a] == n[a] as isize && !periodic {
                        continue;
                    }
                    let mut hi = f;
                    hi[a] %= n[a] as isize;
                    let cl = flat(n, lo.map(|v| v as usize));
                    let k_face = op.coef[a][cl];
                    if k_face == 0.0 {
                        continue;
                    }
                    let ch = flat(n, hi.map(|v| v as usize));
                    let gap = m.axes[a].centre(f[a]) - m.axes[a].centre(f[a] - 1);
                    slice[lay.at(f) - kk * sk] -= dt * (p[ch] - p[cl]) / gap;
                }
            }
        });
    }
}
