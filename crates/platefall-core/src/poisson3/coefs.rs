//! The operator's input: a stretched tensor-product grid and one coefficient per cell face.
use super::error::PoissonError;

/// One side of the grid's outer boundary.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// The x = x_min faces (face index i = 0).
    XMin,
    /// The x = x_max faces (i = nx).
    XMax,
    /// The y = y_min faces (j = 0).
    YMin,
    /// The y = y_max faces (j = ny).
    YMax,
    /// The z = z_min faces (k = 0); ignored when z is periodic.
    ZMin,
    /// The z = z_max faces (k = nz); ignored when z is periodic.
    ZMax,
}

/// A cell-centred grid of nx × ny × nz cells with widths `dx`, `dy`, `dz` (any positive,
/// monotone or not) and the coefficient of every face of the 7-point operator
///
/// (A φ)_P = Σ_faces c_f (φ_P − φ_N)  (+ c_f φ_P on an outer face: Dirichlet φ = 0 there),
///
/// i.e. −∇·∇φ integrated over cell P when c_f = face area / distance between the centres it joins
/// (half the cell width on an outer face). A zero coefficient is a wall (∂φ/∂n = 0): a face blocked
/// by a plate, an outer Neumann face, or every face of a solid cell (which then decouples).
///
/// Cells are numbered `i + nx·(j + ny·k)` (x fastest). Face arrays:
/// - `cx[i + (nx+1)·(j + ny·k)]`, i in 0..=nx: the face between cells i−1 and i (0 and nx outer);
/// - `cy[i + nx·(j + (ny+1)·k)]`, j in 0..=ny;
/// - `cz[i + nx·(j + ny·k)]`, k in 0..=nz. With `periodic_z`, face k = 0 joins cell nz−1 to
///   cell 0 and face nz is not used.
///
/// An inhomogeneous Dirichlet value φ_b on an outer face enters the right-hand side as c_f φ_b.
#[derive(Debug, Clone, PartialEq)]
pub struct FaceCoefs3 {
    /// Cell widths along x (nx entries).
    pub dx: Vec<f64>,
    /// Cell widths along y (ny entries).
    pub dy: Vec<f64>,
    /// Cell widths along z (nz entries).
    pub dz: Vec<f64>,
    /// Whether z is periodic (cell nz−1 joins cell 0 through face 0).
    pub periodic_z: bool,
    /// Coefficients of the x-faces, (nx+1)·ny·nz.
    pub cx: Vec<f64>,
    /// Coefficients of the y-faces, nx·(ny+1)·nz.
    pub cy: Vec<f64>,
    /// Coefficients of the z-faces, nx·ny·(nz+1).
    pub cz: Vec<f64>,
}

impl FaceCoefs3 {
    /// The open grid: every interior face c = area / centre distance, every outer face Neumann
    /// (c = 0). Errors on empty or non-positive widths.
    pub fn open(
        dx: Vec<f64>,
        dy: Vec<f64>,
        dz: Vec<f64>,
        periodic_z: bool,
    ) -> Result<Self, PoissonError> {
        check_widths(&dx, &dy, &dz)?;
        let (nx, ny, nz) = (dx.len(), dy.len(), dz.len());
        let mut f = FaceCoefs3 {
            cx: vec![0.0; (nx + 1) * ny * nz],
            cy: vec![0.0; nx * (ny + 1) * nz],
            cz: vec![0.0; nx * ny * (nz + 1)],
            dx,
            dy,
            dz,
            periodic_z,
        };
        for k in 0..nz {
            for j in 0..ny {
                for i in 1..nx {
                    let at = f.x_face(i, j, k);
                    f.cx[at] = f.dy[j] * f.dz[k] / link(&f.dx, i);
                }
            }
            for j in 1..ny {
                for i in 0..nx {
                    let at = f.y_face(i, j, k);
                    f.cy[at] = f.dx[i] * f.dz[k] / link(&f.dy, j);
                }
            }
        }
        let wrap = periodic_z && nz > 1;
        for k in (if wrap { 0 } else { 1 })..nz {
            let d = if k == 0 {
                0.5 * (f.dz[nz - 1] + f.dz[0])
            } else {
                link(&f.dz, k)
            };
            for j in 0..ny {
                for i in 0..nx {
                    let at = f.z_face(i, j, k);
                    f.cz[at] = f.dx[i] * f.dy[j] / d;
                }
            }
        }
        Ok(f)
    }

    /// Cells along x, y, z.
    pub fn shape(&self) -> [usize; 3] {
        [self.dx.len(), self.dy.len(), self.dz.len()]
    }

    /// Index of cell (i, j, k).
    pub fn cell(&self, i: usize, j: usize, k: usize) -> usize {
        let [nx, ny, _] = self.shape();
        i + nx * (j + ny * k)
    }

    /// Index in `cx` of the x-face i (between cells i−1 and i) of row (j, k).
    pub fn x_face(&self, i: usize, j: usize, k: usize) -> usize {
        let [nx, ny, _] = self.shape();
        i + (nx + 1) * (j + ny * k)
    }

    /// Index in `cy` of the y-face j of column (i, k).
    pub fn y_face(&self, i: usize, j: usize, k: usize) -> usize {
        let [nx, ny, _] = self.shape();
        i + nx * (j + (ny + 1) * k)
    }

    /// Index in `cz` of the z-face k of line (i, j).
    pub fn z_face(&self, i: usize, j: usize, k: usize) -> usize {
        let [nx, ny, _] = self.shape();
        i + nx * (j + ny * k)
    }

    /// Decouples cell (i, j, k) (a solid cell): its six faces become walls. Out-of-range indices
    /// are ignored.
    pub fn decouple(&mut self, i: usize, j: usize, k: usize) {
        let [nx, ny, nz] = self.shape();
        if i >= nx || j >= ny || k >= nz {
            return;
        }
        let (a, b) = (self.x_face(i, j, k), self.x_face(i + 1, j, k));
        self.cx[a] = 0.0;
        self.cx[b] = 0.0;
        let (a, b) = (self.y_face(i, j, k), self.y_face(i, j + 1, k));
        self.cy[a] = 0.0;
        self.cy[b] = 0.0;
        let upper = if self.periodic_z && k + 1 == nz {
            0
        } else {
            k + 1
        };
        let (a, b) = (self.z_face(i, j, k), self.z_face(i, j, upper));
        self.cz[a] = 0.0;
        self.cz[b] = 0.0;
    }

    /// Makes every face of one outer side Dirichlet (φ = 0 on the face): c = area / half width.
    pub fn set_dirichlet(&mut self, side: Side) {
        let [nx, ny, nz] = self.shape();
        let periodic = self.periodic_z;
        match side {
            Side::XMin | Side::XMax => {
                let i = if side == Side::XMin { 0 } else { nx };
                let d = if i == 0 { self.dx[0] } else { self.dx[nx - 1] };
                for k in 0..nz {
                    for j in 0..ny {
                        let at = self.x_face(i, j, k);
                        self.cx[at] = 2.0 * self.dy[j] * self.dz[k] / d;
                    }
                }
            }
            Side::YMin | Side::YMax => {
                let j = if side == Side::YMin { 0 } else { ny };
                let d = if j == 0 { self.dy[0] } else { self.dy[ny - 1] };
                for k in 0..nz {
                    for i in 0..nx {
                        let at = self.y_face(i, j, k);
                        self.cy[at] = 2.0 * self.dx[i] * self.dz[k] / d;
                    }
                }
            }
            Side::ZMin | Side::ZMax if !periodic => {
                let k = if side == Side::ZMin { 0 } else { nz };
                let d = if k == 0 { self.dz[0] } else { self.dz[nz - 1] };
                for j in 0..ny {
                    for i in 0..nx {
                        let at = self.z_face(i, j, k);
                        self.cz[at] = 2.0 * self.dx[i] * self.dy[j] / d;
                    }
                }
            }
            Side::ZMin | Side::ZMax => {}
        }
    }

    /// Checks lengths, finiteness and signs; returns the shape.
    pub(super) fn validate(&self) -> Result<[usize; 3], PoissonError> {
        check_widths(&self.dx, &self.dy, &self.dz)?;
        let [nx, ny, nz] = self.shape();
        for (what, v, expected) in [
            ("cx", &self.cx, (nx + 1) * ny * nz),
            ("cy", &self.cy, nx * (ny + 1) * nz),
            ("cz", &self.cz, nx * ny * (nz + 1)),
        ] {
            if v.len() != expected {
                return Err(PoissonError::SizeMismatch {
                    what,
                    expected,
                    found: v.len(),
                });
            }
            check_values(what, v, 0.0, true)?;
        }
        Ok([nx, ny, nz])
    }
}

/// Distance between the centres of cells a−1 and a.
fn link(d: &[f64], a: usize) -> f64 {
    0.5 * (d[a - 1] + d[a])
}

fn check_widths(dx: &[f64], dy: &[f64], dz: &[f64]) -> Result<(), PoissonError> {
    let (nx, ny, nz) = (dx.len(), dy.len(), dz.len());
    let cells = nx.checked_mul(ny).and_then(|a| a.checked_mul(nz));
    if nx == 0 || ny == 0 || nz == 0 || cells.is_none_or(|c| c >= u32::MAX as usize) {
        return Err(PoissonError::BadShape { nx, ny, nz });
    }
    check_values("dx", dx, 0.0, false)?;
    check_values("dy", dy, 0.0, false)?;
    check_values("dz", dz, 0.0, false)
}

/// Every entry finite and above `min` (or equal to it when `inclusive`).
fn check_values(
    what: &'static str,
    v: &[f64],
    min: f64,
    inclusive: bool,
) -> Result<(), PoissonError> {
    for (index, &value) in v.iter().enumerate() {
        if !value.is_finite() {
            return Err(PoissonError::NonFinite { what, index });
        }
        if value < min || (!inclusive && value == min) {
            return Err(PoissonError::OutOfRange { what, index, value });
        }
    }
    Ok(())
}

/// Every entry finite.
pub(super) fn check_finite(what: &'static str, v: &[f64]) -> Result<(), PoissonError> {
    match v.iter().position(|x| !x.is_finite()) {
        Some(index) => Err(PoissonError::NonFinite { what, index }),
        None => Ok(()),
    }
}
