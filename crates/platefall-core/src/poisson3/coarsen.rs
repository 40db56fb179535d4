//! Coarsening for stretched grids: along each axis, neighbouring cells merge in pairs only where
//! the pair is no wider than the level's target spacing, which doubles level by level. Fine
//! strips coarsen first and wide cells wait, so each coarse grid is closer to isotropic than the
//! one before: where the cells are thin along one axis (strongly coupled along it) the grid
//! coarsens along that axis only — semi-coarsening chosen cell by cell — and point smoothing
//! suffices. Coarse operators are rediscretised from the fine face coefficients (docs:
//! docs/how-it-works.md, the 3-D pressure solver).
use super::level::{for_planes, parallel, Level};

/// A coarse level must hold at most this fraction of its fine level's cells (else the target
/// doubles again), which bounds a V-cycle's work by 1/(1 − 0.7) ≈ 3.3 fine-level sweeps.
const REDUCTION: f64 = 0.7;

/// The cells of one axis grouped into coarse cells of one or two.
#[derive(Debug, Clone)]
pub(super) struct AxisMap {
    /// Coarse cell of each fine cell.
    pub parent: Vec<usize>,
    /// First fine cell of each coarse cell, then the fine count (nc + 1 entries).
    pub start: Vec<usize>,
}

impl AxisMap {
    /// Pairs cell i with i + 1 (left to right) when w_i + w_{i+1} ≤ target.
    fn plan(widths: &[f64], target: f64) -> AxisMap {
        let n = widths.len();
        let (mut parent, mut start) = (vec![0; n], Vec::with_capacity(n + 1));
        let mut i = 0;
        while i < n {
            let c = start.len();
            start.push(i);
            parent[i] = c;
            if i + 1 < n && widths[i] + widths[i + 1] <= target {
                parent[i + 1] = c;
                i += 1;
            }
            i += 1;
        }
        start.push(n);
        AxisMap { parent, start }
    }

    fn coarse(&self) -> usize {
        self.start.len() - 1
    }

    /// Coarse widths: sums over the groups.
    fn widths(&self, fine: &[f64]) -> Vec<f64> {
        self.start
            .windows(2)
            .map(|g| fine[g[0]..g[1]].iter().sum())
            .collect()
    }

    /// The coarse face at each fine face (0..=n), if the fine face is one.
    fn faces(&self) -> Vec<Option<usize>> {
        let n = self.parent.len();
        (0..=n)
            .map(|f| match f {
                0 => Some(0),
                f if f == n => Some(self.coarse()),
                f => (self.parent[f] != self.parent[f - 1]).then_some(self.parent[f]),
            })
            .collect()
    }
}

/// Distance between the centres a face joins (half a width on an outer face; the wrap on a
/// periodic axis).
fn link(w: &[f64], face: usize, periodic: bool) -> f64 {
    let n = w.len();
    match face {
        0 if periodic => 0.5 * (w[n - 1] + w[0]),
        0 => 0.5 * w[0],
        f if f == n => 0.5 * w[n - 1],
        f => 0.5 * (w[f - 1] + w[f]),
    }
}

/// The grouping of one level into the next.
#[derive(Debug, Clone)]
pub(super) struct Transfer {
    pub maps: [AxisMap; 3],
    /// Fine and coarse shapes.
    fine: [usize; 3],
    coarse: [usize; 3],
}

impl Transfer {
    /// The groupings for `fine` at spacing `target`, doubled until the coarse level holds at
    /// most [`REDUCTION`] of the cells; `target` is left at the value used.
    pub fn plan(fine: &Level, target: &mut f64) -> Transfer {
        loop {
            let maps = [0, 1, 2].map(|a| AxisMap::plan(&fine.widths[a], *target));
            let coarse = [0, 1, 2].map(|a| maps[a].coarse());
            if (coarse.iter().product::<usize>() as f64) <= REDUCTION * fine.cells() as f64 {
                return Transfer {
                    maps,
                    fine: fine.n,
                    coarse,
                };
            }
            *target *= 2.0;
        }
    }

    /// The coarse level: widths summed, each coarse face's coefficient the sum of the fine ones
    /// on it scaled by fine/coarse centre distance (exact rediscretisation where the fine faces
    /// are open; walls stay walls).
    pub fn coarsen(&self, fine: &Level) -> Level {
        let widths = [0, 1, 2].map(|a| self.maps[a].widths(&fine.widths[a]));
        let [nx, ny, nz] = self.fine;
        let [cx, cy, cz] = self.coarse;
        let [px, py, pz] = [0, 1, 2].map(|a| &self.maps[a].parent);
        let face_maps = [0, 1, 2].map(|a| self.maps[a].faces());
        let ratio = |a: usize, f: usize, c: usize| {
            let periodic = a == 2 && fine.periodic;
            link(&fine.widths[a], f, periodic) / link(&widths[a], c, periodic)
        };
        let mut ccx = vec![0.0; (cx + 1) * cy * cz];
        let mut ccy = vec![0.0; cx * (cy + 1) * cz];
        let mut ccz = vec![0.0; cx * cy * (cz + 1)];
        for k in 0..nz {
            for j in 0..ny {
                for (i, face) in face_maps[0].iter().enumerate() {
                    if let Some(c) = *face {
                        let w = ratio(0, i, c) * fine.cx[i + (nx + 1) * (j + ny * k)];
                        ccx[c + (cx + 1) * (py[j] + cy * pz[k])] += w;
                    }
                }
            }
            for (j, face) in face_maps[1].iter().enumerate() {
                if let Some(c) = *face {
                    let s = ratio(1, j, c);
                    for i in 0..nx {
                        ccy[px[i] + cx * (c + (cy + 1) * pz[k])] +=
                            s * fine.cy[i + nx * (j + (ny + 1) * k)];
                    }
                }
            }
        }
        for (k, face) in face_maps[2].iter().enumerate() {
            if let Some(c) = *face {
                let s = ratio(2, k, c);
                for j in 0..ny {
                    for i in 0..nx {
                        ccz[px[i] + cx * (py[j] + cy * c)] += s * fine.cz[i + nx * (j + ny * k)];
                    }
                }
            }
        }
        Level::new(self.coarse, fine.periodic, widths, ccx, ccy, ccz)
    }

    /// b_coarse = Σ of r over each coarse cell's fine cells (the transpose of
    /// [`Transfer::prolong_add`]).
    pub fn restrict(&self, r: &[f64], b: &mut [f64]) {
        let [nx, ny, _] = self.fine;
        let [cx, cy, _] = self.coarse;
        let [px, py, _] = [0, 1, 2].map(|a| &self.maps[a].parent);
        let zs = &self.maps[2].start;
        for_planes(b, cx * cy, parallel(r.len()), |kc, plane| {
            plane.iter_mut().for_each(|v| *v = 0.0);
            for k in zs[kc]..zs[kc + 1] {
                for j in 0..ny {
                    let row = &mut plane[cx * py[j]..][..cx];
                    let fine = &r[nx * (j + ny * k)..][..nx];
                    for i in 0..nx {
                        row[px[i]] += fine[i];
                    }
                }
            }
        });
    }

    /// x += the coarse correction, constant over each coarse cell.
    pub fn prolong_add(&self, xc: &[f64], x: &mut [f64]) {
        let [nx, ny, _] = self.fine;
        let [cx, cy, _] = self.coarse;
        let [px, py, pz] = [0, 1, 2].map(|a| &self.maps[a].parent);
        for_planes(x, nx * ny, parallel(x.len()), |k, plane| {
            for j in 0..ny {
                let coarse = &xc[cx * (py[j] + cy * pz[k])..][..cx];
                let row = &mut plane[nx * j..][..nx];
                for i in 0..nx {
                    row[i] += coarse[px[i]];
                }
            }
        });
    }
}
