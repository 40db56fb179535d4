//! Connected pieces of a level's grid (cells joined by faces of non-zero coefficient) and the
//! null space of the singular ones: a piece with no Dirichlet face has the constant as null vector
//! (a decoupled solid cell is such a piece of one cell).
use super::level::Level;

const NONE: u32 = u32::MAX;

/// The singular pieces of a level.
#[derive(Debug, Clone)]
pub(super) struct Pieces {
    /// Each cell's singular piece, or `u32::MAX` for cells of pieces that touch a Dirichlet face.
    pub id: Vec<u32>,
    /// Cells in each singular piece.
    pub size: Vec<f64>,
}

impl Pieces {
    /// Finds the pieces by union–find over the open faces.
    pub fn find(level: &Level) -> Pieces {
        let [nx, ny, nz] = level.n;
        let cell = |i: usize, j: usize, k: usize| i + nx * (j + ny * k);
        let mut root: Vec<u32> = (0..level.cells() as u32).collect();
        let mut grounded = vec![false; level.cells()];
        for k in 0..nz {
            for j in 0..ny {
                for i in 0..=nx {
                    let c = level.cx[i + (nx + 1) * (j + ny * k)];
                    link(
                        &mut root,
                        &mut grounded,
                        c,
                        (i > 0).then(|| cell(i - 1, j, k)),
                        (i < nx).then(|| cell(i, j, k)),
                    );
                }
            }
            for j in 0..=ny {
                for i in 0..nx {
                    let c = level.cy[i + nx * (j + (ny + 1) * k)];
                    link(
                        &mut root,
                        &mut grounded,
                        c,
                        (j > 0).then(|| cell(i, j - 1, k)),
                        (j < ny).then(|| cell(i, j, k)),
                    );
                }
            }
        }
        let faces = if level.periodic { nz } else { nz + 1 };
        for k in 0..faces {
            let below = match k {
                0 if level.periodic => Some(nz - 1),
                0 => None,
                k => Some(k - 1),
            };
            for j in 0..ny {
                for i in 0..nx {
                    let c = level.cz[i + nx * (j + ny * k)];
                    let above = (k < nz).then(|| cell(i, j, k));
                    link(
                        &mut root,
                        &mut grounded,
                        c,
                        below.map(|kb| cell(i, j, kb)),
                        above,
                    );
                }
            }
        }
        let mut number = vec![NONE; level.cells()];
        let (mut id, mut size) = (vec![NONE; level.cells()], Vec::new());
        for (p, id_p) in id.iter_mut().enumerate() {
            let r = find(&mut root, p as u32) as usize;
            if grounded[r] {
                continue;
            }
            if number[r] == NONE {
                number[r] = size.len() as u32;
                size.push(0.0);
            }
            *id_p = number[r];
            size[number[r] as usize] += 1.0;
        }
        Pieces { id, size }
    }

    /// Number of singular pieces.
    pub fn count(&self) -> usize {
        self.size.len()
    }

    /// Subtracts from v its mean over each singular piece (`sums`: one slot per piece).
    pub fn remove_means(&self, v: &mut [f64], sums: &mut [f64]) {
        if self.size.is_empty() {
            return;
        }
        sums.iter_mut().for_each(|s| *s = 0.0);
        for (&p, &x) in self.id.iter().zip(v.iter()) {
            if p != NONE {
                sums[p as usize] += x;
            }
        }
        for (s, &m) in sums.iter_mut().zip(&self.size) {
            *s /= m;
        }
        for (&p, x) in self.id.iter().zip(v.iter_mut()) {
            if p != NONE {
                *x -= sums[p as usize];
            }
        }
    }
}

/// Joins the two cells of an open face; an open face with one cell (outer) grounds it.
fn link(root: &mut [u32], grounded: &mut [bool], c: f64, a: Option<usize>, b: Option<usize>) {
    if c <= 0.0 {
        return;
    }
    match (a, b) {
        (Some(a), Some(b)) => {
            let (ra, rb) = (find(root, a as u32), find(root, b as u32));
            if ra != rb {
                root[ra as usize] = rb;
                grounded[rb as usize] |= grounded[ra as usize];
            }
        }
        (Some(a), None) | (None, Some(a)) => {
            let r = find(root, a as u32) as usize;
            grounded[r] = true;
        }
        (None, None) => {}
    }
}

/// The root of p, halving paths on the way.
fn find(root: &mut [u32], mut p: u32) -> u32 {
    while root[p as usize] != p {
        let up = root[root[p as usize] as usize];
        root[p as usize] = up;
        p = up;
    }
    p
}
