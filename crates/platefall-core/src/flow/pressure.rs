//! The pressure projection (docs/physics.md §3: u_x + v_y = 0).
//!
//! With the predicted velocity u*, find φ with  Σ_faces L_f A_f ∂φ/∂n = (the cell's outflow of u*)
//! in every cell that carries a pressure, then u = u* − ∇φ on the fluid faces and p = φ/Δt
//! (A_f: the face's open fraction, `wall::faces`; the outflow counts the part of a cut face
//! inside the plate with the plate's velocity). Faces on the outer boundary and the plate's held
//! faces carry prescribed normal velocities, so ∂φ/∂n = 0 there (Neumann). The operator is the same at every step because
//! the grid is rigid; it is factored once by a sparse Cholesky whose order splits the grid at its
//! middle column, so that both halves are solved at once (`split_cholesky.rs`). The Neumann null
//! space is removed by pinning φ = 0 in one far-field corner cell; the right-hand side is made
//! compatible beforehand by the outer boundary condition (zero net flux), so the pinned cell's own
//! equation holds too.
use faer::sparse::{SparseColMat, Triplet};

use super::array::Padded;
use super::frame::Frame;
use super::metrics::Metrics;
use super::split_cholesky::{FactorError, Part, SplitCholesky};
use super::wall::faces::Faces;
use super::wall::Wall;
use crate::grid::Grid;

const NONE: u32 = u32::MAX;

pub struct Pressure {
    nx: usize,
    ny: usize,
    /// Unknown number of each cell in the factor's order (NONE for plate cells and the pinned
    /// cell).
    unknown: Vec<u32>,
    /// Whether each cell is fluid.
    fluid: Vec<bool>,
    factor: SplitCholesky,
    /// Right-hand side / solution, one entry per unknown, in the factor's order.
    rhs: Vec<f64>,
    /// φ on all cells (0 on plate and pinned cells).
    pub phi: Vec<f64>,
}

/// Why the pressure operator could not be set up.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PressureError {
    /// faer refused the assembled matrix; `detail` is its own message.
    #[error("assembling the pressure matrix: {detail}")]
    Assembly {
        /// faer's message.
        detail: String,
    },
    /// The operator could not be ordered or factored.
    #[error(transparent)]
    Factor(#[from] FactorError),
}

/// How a projection sets the pressure from its potential φ.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PressureUpdate {
    /// p = φ/Δt.
    Replace,
    /// p += φ/Δt (incremental pressure).
    Increment,
}

impl Pressure {
    /// Assembles and factors −∇² with the Neumann conditions described above.
    ///
    /// # Errors
    /// [`PressureError::Assembly`] when faer refuses the assembled matrix, and
    /// [`PressureError::Factor`] when it cannot be ordered or factored (not positive definite).
    pub fn new(grid: &Grid, m: &Metrics, faces: &Faces) -> Result<Self, PressureError> {
        let (nx, ny) = (grid.nx, grid.ny);
        let fluid = faces.fluid.clone();
        let mut unknown = vec![NONE; nx * ny];
        let mut count = 0u32;
        // Cell 0 (a far-field corner) is pinned.
        for k in 1..nx * ny {
            if fluid[k] {
                unknown[k] = count;
                count += 1;
            }
        }
        let a = assemble(grid, m, faces, &unknown, count as usize)?;
        let mut part = vec![Part::Separator; count as usize];
        for (k, &r) in unknown.iter().enumerate().filter(|(_, &r)| r != NONE) {
            part[r as usize] = Part::of_column(k % nx, nx / 2);
        }
        let factor = SplitCholesky::new(a.as_ref(), &part)?;
        for r in unknown.iter_mut().filter(|r| **r != NONE) {
            *r = factor.position[*r as usize];
        }
        Ok(Pressure {
            nx,
            ny,
            unknown,
            fluid,
            factor,
            rhs: vec![0.0; count as usize],
            phi: vec![0.0; nx * ny],
        })
    }

    /// Number of unknowns.
    pub fn unknowns(&self) -> usize {
        self.rhs.len()
    }

    /// Nonzeros in the Cholesky factor (reported by the benchmark).
    pub fn factor_nnz(&self) -> usize {
        self.factor.nnz()
    }

    /// Net volume flux out of cell (i, j) (the finite-volume divergence times the cell area).
    #[inline(always)]
    pub fn cell_flux(u: &Padded, v: &Padded, grid: &Grid, i: usize, j: usize) -> f64 {
        let (ii, jj) = (i as isize, j as isize);
        (u.get(ii + 1, jj) - u.get(ii, jj)) * grid.dy[j]
            + (v.get(ii, jj + 1) - v.get(ii, jj)) * grid.dx[i]
    }

    /// Projects (u, v) onto the discretely divergence-free space, in place, and sets p = φ/Δt.
    /// Only faces between two pressure cells change (the caller restores held faces); `plate`
    /// is the plate's motion, whose velocity the covered parts of cut faces carry.
    #[allow(clippy::too_many_arguments)]
    pub fn project(
        &mut self,
        u: &mut Padded,
        v: &mut Padded,
        grid: &Grid,
        m: &Metrics,
        (wall, plate): (&Wall, &Frame),
        dt: f64,
        p: &mut [f64],
    ) {
        self.project_velocity(u, v, grid, m, (wall, plate));
        self.set_pressure(dt, p, PressureUpdate::Replace);
    }

    /// Projects (u, v) in place and keeps the potential φ in [`Pressure::phi`] (where the caller
    /// may transform it before [`Pressure::set_pressure`]).
    pub fn project_velocity(
        &mut self,
        u: &mut Padded,
        v: &mut Padded,
        grid: &Grid,
        m: &Metrics,
        (wall, plate): (&Wall, &Frame),
    ) {
        self.solve_phi(u, v, grid, wall, plate);
        self.correct_velocity(u, v, m);
    }

    /// Sets p from the potential of the last projection: p = φ/Δt or p += φ/Δt.
    pub fn set_pressure(&self, dt: f64, p: &mut [f64], update: PressureUpdate) {
        self.pressure_from_phi(dt, p, update);
    }

    /// The potential of the gradient part of a field f given on the faces (zero on the outer and
    /// plate faces): p with ∇·(f − ∇p) = 0 in every fluid cell, p → 0 on the outer ring. Starts
    /// the incremental pressure of the implicit far field.
    pub fn potential(&mut self, fu: &Padded, fv: &Padded, grid: &Grid, wall: &Wall, p: &mut [f64]) {
        self.solve_phi(fu, fv, grid, wall, &Frame::default());
        self.pressure_from_phi(1.0, p, PressureUpdate::Replace);
    }

    /// Solves (−L) φ = −div u* and scatters φ onto the cells (0 on plate and pinned cells).
    fn solve_phi(&mut self, u: &Padded, v: &Padded, grid: &Grid, wall: &Wall, plate: &Frame) {
        let (nx, ny) = (self.nx, self.ny);
        for j in 0..ny {
            for i in 0..nx {
                let r = self.unknown[i + nx * j];
                if r != NONE {
                    self.rhs[r as usize] = -Self::cell_flux(u, v, grid, i, j);
                }
            }
        }
        let (unknown, rhs) = (&self.unknown, &mut self.rhs);
        wall.cut_flux(u, v, plate, &mut |k, add| {
            if unknown[k] != NONE {
                rhs[unknown[k] as usize] -= add;
            }
        });
        self.factor.solve_in_place(&mut self.rhs);
        for (k, phi) in self.phi.iter_mut().enumerate() {
            let r = self.unknown[k];
            *phi = if r != NONE { self.rhs[r as usize] } else { 0.0 };
        }
    }

    /// u = u* − ∇φ on every face between two fluid cells.
    fn correct_velocity(&self, u: &mut Padded, v: &mut Padded, m: &Metrics) {
        let (nx, ny) = (self.nx, self.ny);
        let (phi, fluid) = (&self.phi, &self.fluid);
        for j in 0..ny {
            let jj = j as isize;
            for i in 1..nx {
                let k = i + nx * j;
                if fluid[k] && fluid[k - 1] {
                    let g = (phi[k] - phi[k - 1]) / m.x.centre_gap(i as isize);
                    let idx = u.at(i as isize, jj);
                    u.data[idx] -= g;
                }
            }
        }
        for j in 1..ny {
            let inv = 1.0 / m.y.centre_gap(j as isize);
            for i in 0..nx {
                let k = i + nx * j;
                if fluid[k] && fluid[k - nx] {
                    let idx = v.at(i as isize, j as isize);
                    v.data[idx] -= (phi[k] - phi[k - nx]) * inv;
                }
            }
        }
    }

    /// p = φ/Δt (or p += φ/Δt), φ shifted so that its mean over the outermost ring of cells is
    /// zero (p → 0 far away); zero inside the plate.
    fn pressure_from_phi(&self, dt: f64, p: &mut [f64], update: PressureUpdate) {
        let (nx, ny) = (self.nx, self.ny);
        let (phi, fluid) = (&self.phi, &self.fluid);
        let inv_dt = 1.0 / dt;
        let mut ring = 0.0;
        let mut count = 0usize;
        for j in 0..ny {
            for i in 0..nx {
                if i == 0 || j == 0 || i == nx - 1 || j == ny - 1 {
                    ring += phi[i + nx * j];
                    count += 1;
                }
            }
        }
        let shift = ring / count as f64;
        for (k, pk) in p.iter_mut().enumerate() {
            *pk = match (fluid[k], update) {
                (false, _) => 0.0,
                (true, PressureUpdate::Replace) => (phi[k] - shift) * inv_dt,
                (true, PressureUpdate::Increment) => *pk + (phi[k] - shift) * inv_dt,
            };
        }
    }
}

/// The lower triangle of −∇² over the pressure cells: the two cells of each fluid face are
/// coupled with L_f A_f / d; held faces and the outer boundary carry no flux (Neumann).
fn assemble(
    grid: &Grid,
    m: &Metrics,
    faces: &Faces,
    unknown: &[u32],
    n: usize,
) -> Result<SparseColMat<u32, f64>, PressureError> {
    let fluid = &faces.fluid;
    let (nx, ny) = (grid.nx, grid.ny);
    let mut trip: Vec<Triplet<u32, u32, f64>> = Vec::with_capacity(3 * n);
    let mut diag = vec![0.0; n];
    let mut couple = |a: usize, b: usize, c: f64| {
        let (ua, ub) = (unknown[a], unknown[b]);
        if ua != NONE {
            diag[ua as usize] += c;
        }
        if ub != NONE {
            diag[ub as usize] += c;
        }
        if ua != NONE && ub != NONE {
            let (r, col) = if ua > ub { (ua, ub) } else { (ub, ua) };
            trip.push(Triplet::new(r, col, -c));
        }
    };
    for j in 0..ny {
        for i in 0..nx {
            let k = i + nx * j;
            if !fluid[k] {
                continue;
            }
            let open_u = faces.u_open[i + 1 + (nx + 1) * j];
            if i + 1 < nx && fluid[k + 1] && open_u > 0.0 {
                couple(
                    k,
                    k + 1,
                    open_u * grid.dy[j] / m.x.centre_gap(i as isize + 1),
                );
            }
            let open_v = faces.v_open[i + nx * (j + 1)];
            if j + 1 < ny && fluid[k + nx] && open_v > 0.0 {
                couple(
                    k,
                    k + nx,
                    open_v * grid.dx[i] / m.y.centre_gap(j as isize + 1),
                );
            }
        }
    }
    for (r, d) in diag.iter().enumerate() {
        trip.push(Triplet::new(r as u32, r as u32, *d));
    }
    SparseColMat::<u32, f64>::try_new_from_triplets(n, n, &trip).map_err(|e| {
        PressureError::Assembly {
            detail: format!("{e:?}"),
        }
    })
}
