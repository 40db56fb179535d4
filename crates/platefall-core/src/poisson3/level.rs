//! One level of the hierarchy: a tensor-product grid with its face coefficients, the 7-point
//! operator, the residual and the red–black Gauss–Seidel smoother, each parallel over z-planes.
use rayon::prelude::*;

/// Below this many cells a level's loops run on the calling thread (rayon's split costs more).
const PARALLEL_MIN: usize = 16_384;

/// A grid level. Same layout as [`super::FaceCoefs3`]; with `periodic` and nz = 1 the z-faces
/// are zero (a cell joined to itself).
#[derive(Debug, Clone)]
pub(super) struct Level {
    pub n: [usize; 3],
    pub periodic: bool,
    /// Cell widths per axis.
    pub widths: [Vec<f64>; 3],
    pub cx: Vec<f64>,
    pub cy: Vec<f64>,
    pub cz: Vec<f64>,
    /// Σ of the cell's six face coefficients (the operator's diagonal).
    pub diag: Vec<f64>,
}

/// The transverse neighbours of a row: (start of the neighbour row in x, its coefficient row).
type Neighbours<'a> = ([(usize, &'a [f64]); 4], usize);

impl Level {
    /// A level from its parts; computes the diagonal.
    pub fn new(
        n: [usize; 3],
        periodic: bool,
        widths: [Vec<f64>; 3],
        cx: Vec<f64>,
        cy: Vec<f64>,
        mut cz: Vec<f64>,
    ) -> Level {
        if periodic && n[2] == 1 {
            cz.iter_mut().for_each(|c| *c = 0.0);
        }
        let mut level = Level {
            n,
            periodic,
            widths,
            cx,
            cy,
            cz,
            diag: Vec::new(),
        };
        level.diag = level.diagonal();
        level
    }

    pub fn cells(&self) -> usize {
        self.n[0] * self.n[1] * self.n[2]
    }

    fn plane(&self) -> usize {
        self.n[0] * self.n[1]
    }

    fn diagonal(&self) -> Vec<f64> {
        let [nx, ny, nz] = self.n;
        let mut d = vec![0.0; self.cells()];
        for k in 0..nz {
            for j in 0..ny {
                let xr = &self.cx[(nx + 1) * (j + ny * k)..][..nx + 1];
                let ylo = &self.cy[nx * (j + (ny + 1) * k)..][..nx];
                let yhi = &self.cy[nx * (j + 1 + (ny + 1) * k)..][..nx];
                let zlo = &self.cz[nx * (j + ny * k)..][..nx];
                let kh = if self.periodic && k + 1 == nz {
                    0
                } else {
                    k + 1
                };
                let zhi = &self.cz[nx * (j + ny * kh)..][..nx];
                let row = &mut d[nx * (j + ny * k)..][..nx];
                for i in 0..nx {
                    row[i] = xr[i] + xr[i + 1] + ylo[i] + yhi[i] + zlo[i] + zhi[i];
                }
            }
        }
        d
    }

    /// The up-to-four transverse neighbour rows of row (j, k).
    fn neighbours(&self, j: usize, k: usize) -> Neighbours<'_> {
        let [nx, ny, nz] = self.n;
        let empty: &[f64] = &[];
        let mut out = [(0, empty); 4];
        let mut m = 0;
        if j > 0 {
            out[m] = (
                nx * (j - 1 + ny * k),
                &self.cy[nx * (j + (ny + 1) * k)..][..nx],
            );
            m += 1;
        }
        if j + 1 < ny {
            out[m] = (
                nx * (j + 1 + ny * k),
                &self.cy[nx * (j + 1 + (ny + 1) * k)..][..nx],
            );
            m += 1;
        }
        let below = if k > 0 {
            Some(k - 1)
        } else {
            self.periodic.then(|| nz - 1)
        };
        if let Some(kb) = below.filter(|&kb| kb != k) {
            out[m] = (nx * (j + ny * kb), &self.cz[nx * (j + ny * k)..][..nx]);
            m += 1;
        }
        let above = if k + 1 < nz {
            Some(k + 1)
        } else {
            self.periodic.then_some(0)
        };
        if let Some(ka) = above.filter(|&ka| ka != k) {
            let face = if ka == 0 { 0 } else { k + 1 };
            out[m] = (nx * (j + ny * ka), &self.cz[nx * (j + ny * face)..][..nx]);
            m += 1;
        }
        (out, m)
    }

    /// out[i] = Σ_neighbours c x_neighbour for the cells of row (j, k).
    fn neighbour_sum(&self, x: &[f64], j: usize, k: usize, out: &mut [f64]) {
        let [nx, ny, _] = self.n;
        let xr = &x[nx * (j + ny * k)..][..nx];
        let cr = &self.cx[(nx + 1) * (j + ny * k)..][..nx + 1];
        out[0] = 0.0;
        for i in 1..nx {
            out[i] = cr[i] * xr[i - 1];
        }
        for i in 0..nx - 1 {
            out[i] += cr[i + 1] * xr[i + 1];
        }
        let (nb, m) = self.neighbours(j, k);
        for &(start, c) in &nb[..m] {
            let xn = &x[start..][..nx];
            for i in 0..nx {
                out[i] += c[i] * xn[i];
            }
        }
    }

    /// Runs `f(k, plane of out)` over the z-planes, in parallel on large levels.
    fn planes<F>(&self, out: &mut [f64], f: F)
    where
        F: Fn(usize, &mut [f64]) + Sync + Send,
    {
        for_planes(out, self.plane(), parallel(self.cells()), f);
    }

    /// y = A x.
    pub fn apply(&self, x: &[f64], y: &mut [f64]) {
        let [nx, ny, _] = self.n;
        self.planes(y, |k, plane| {
            for j in 0..ny {
                let row = &mut plane[nx * j..][..nx];
                self.neighbour_sum(x, j, k, row);
                let at = nx * (j + ny * k);
                let (d, xr) = (&self.diag[at..][..nx], &x[at..][..nx]);
                for i in 0..nx {
                    row[i] = d[i] * xr[i] - row[i];
                }
            }
        });
    }

    /// r = b − A x.
    pub fn residual(&self, b: &[f64], x: &[f64], r: &mut [f64]) {
        let [nx, ny, _] = self.n;
        self.planes(r, |k, plane| {
            for j in 0..ny {
                let row = &mut plane[nx * j..][..nx];
                self.neighbour_sum(x, j, k, row);
                let at = nx * (j + ny * k);
                let (d, xr, br) = (&self.diag[at..][..nx], &x[at..][..nx], &b[at..][..nx]);
                for i in 0..nx {
                    row[i] += br[i] - d[i] * xr[i];
                }
            }
        });
    }

    /// The colour of a cell for Gauss–Seidel: the parity of i + j + k, plus 2 on the last plane
    /// of an odd periodic z (where the parity does not alternate across the wrap).
    fn colour(&self, i: usize, j: usize, k: usize) -> usize {
        let [_, _, nz] = self.n;
        let extra = if self.periodic && nz % 2 == 1 && k + 1 == nz && nz > 1 {
            2
        } else {
            0
        };
        (i + j + k) % 2 + extra
    }

    /// Number of colours the smoother sweeps (2, or 4 with an odd periodic z).
    pub fn colours(&self) -> usize {
        if self.periodic && self.n[2] % 2 == 1 && self.n[2] > 1 {
            4
        } else {
            2
        }
    }

    /// One Gauss–Seidel half-sweep over the cells of `colour`, out of place: `out` = `x` with the
    /// cells of that colour relaxed (they depend only on cells of the other colours). Cells with
    /// a zero diagonal (decoupled) keep their value. Only the relaxed cells' neighbour sums are
    /// formed, each in the order of [`Level::neighbour_sum`].
    pub fn relax(&self, b: &[f64], x: &[f64], out: &mut [f64], colour: usize) {
        let [nx, ny, _] = self.n;
        self.planes(out, |k, plane| {
            for j in 0..ny {
                let row = &mut plane[nx * j..][..nx];
                let at = nx * (j + ny * k);
                let (d, xr, br) = (&self.diag[at..][..nx], &x[at..][..nx], &b[at..][..nx]);
                row.copy_from_slice(xr);
                let Some(first) = (0..nx.min(2)).find(|&i| self.colour(i, j, k) == colour) else {
                    continue;
                };
                let cells = RowCells {
                    cx: &self.cx[(nx + 1) * (j + ny * k)..][..nx + 1],
                    x: xr,
                    b: br,
                    diag: d,
                    first,
                };
                let (nb, m) = self.neighbours(j, k);
                let transverse = |q: usize| (&x[nb[q].0..][..nx], &nb[q].1[..nx]);
                match m {
                    4 => relax_row::<4>(std::array::from_fn(transverse), &cells, row),
                    3 => relax_row::<3>(std::array::from_fn(transverse), &cells, row),
                    2 => relax_row::<2>(std::array::from_fn(transverse), &cells, row),
                    1 => relax_row::<1>(std::array::from_fn(transverse), &cells, row),
                    _ => relax_row::<0>([], &cells, row),
                }
            }
        });
    }
}

/// One row of a Gauss–Seidel half-sweep: its x-face coefficients, x and b, the diagonal, and
/// the first cell of the relaxed colour.
struct RowCells<'a> {
    cx: &'a [f64],
    x: &'a [f64],
    b: &'a [f64],
    diag: &'a [f64],
    first: usize,
}

/// Relaxes the cells `first`, `first` + 2, … of a row into `row`, with its `M` transverse
/// neighbour rows (x, coefficients), the sum in the order of [`Level::neighbour_sum`]: the x
/// faces, then the neighbours in turn. M is a constant so that the loop over them unrolls.
fn relax_row<const M: usize>(nb: [(&[f64], &[f64]); M], r: &RowCells, row: &mut [f64]) {
    let nx = row.len();
    let (cr, xr) = (&r.cx[..nx + 1], &r.x[..nx]);
    let (br, d) = (&r.b[..nx], &r.diag[..nx]);
    let nb = nb.map(|(xn, c)| (&xn[..nx], &c[..nx]));
    for i in (r.first..nx).step_by(2) {
        if d[i] <= 0.0 {
            continue;
        }
        let mut sum = if i > 0 { cr[i] * xr[i - 1] } else { 0.0 };
        if i + 1 < nx {
            sum += cr[i + 1] * xr[i + 1];
        }
        for (xn, c) in &nb {
            sum += c[i] * xn[i];
        }
        row[i] = (br[i] + sum) / d[i];
    }
}

/// Runs `f(k, chunk k of out)` over chunks of `plane` entries, in parallel when asked.
pub(super) fn for_planes<F>(out: &mut [f64], plane: usize, parallel: bool, f: F)
where
    F: Fn(usize, &mut [f64]) + Sync + Send,
{
    if parallel {
        out.par_chunks_mut(plane)
            .enumerate()
            .for_each(|(k, p)| f(k, p));
    } else {
        out.chunks_mut(plane).enumerate().for_each(|(k, p)| f(k, p));
    }
}

/// Whether loops over `cells` cells run in parallel.
pub(super) fn parallel(cells: usize) -> bool {
    cells >= PARALLEL_MIN
}
