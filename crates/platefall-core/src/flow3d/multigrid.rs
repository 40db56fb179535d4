//! The flow's pressure equation solved by [`Poisson3`] (conjugate gradients preconditioned by a
//! multigrid V-cycle, docs/pressure-3d.md), behind the [`PoissonSolve`] boundary.
//!
//! The flow stops on the largest cell divergence the correction leaves, max_P |r_P| Δt / V_P, and
//! [`Poisson3`] stops on that same quantity ([`Target::WeightedMax`]) for its own residual, aiming
//! at a fraction of the tolerance. The true weighted residual is measured after the solve and the
//! solve is repeated from its own result (a warm start) in the rare case that round-off leaves it
//! above the tolerance.
use crate::poisson3::{FaceCoefs3, Poisson3, PoissonError, Target};

use super::project::{flat, weighted_residual, PoissonOperator, PoissonSolve, SolveStats, Stop};

/// Bounds below this fraction of the right-hand side's largest weighted entry are not asked of
/// [`Poisson3`] (the round-off floor of its residual).
const REL_FLOOR: f64 = 1e-14;
/// The first solve aims at this fraction of the tolerance, each repeat at a tenth of the last.
const AIM: f64 = 0.5;
/// Solves from the previous result before giving up on the divergence tolerance.
const ATTEMPTS: usize = 3;

/// The pressure solver of the 3-D flow: [`Poisson3`] on the operator's own coefficients.
#[derive(Clone, Debug)]
pub struct MultigridCg {
    op: PoissonOperator,
    solver: Poisson3,
    r: Vec<f64>,
}

impl MultigridCg {
    /// Builds the multigrid hierarchy of `op`.
    ///
    /// # Errors
    /// [`PoissonError`] if the operator's coefficients are not a valid grid (an empty grid, or
    /// non-finite or negative coefficients).
    pub fn new(op: PoissonOperator) -> Result<MultigridCg, PoissonError> {
        let solver = Poisson3::new(&face_coefs(&op))?;
        Ok(MultigridCg {
            r: vec![0.0; op.cells()],
            solver,
            op,
        })
    }

    /// The multigrid levels' shapes, finest first.
    pub fn level_shapes(&self) -> impl Iterator<Item = [usize; 3]> + '_ {
        self.solver.level_shapes()
    }

    /// r = b − A p and the largest |r_P| w_P.
    fn weighted_residual(&mut self, b: &[f64], p: &[f64], weight: &[f64]) -> f64 {
        weighted_residual(&self.op, b, p, weight, &mut self.r)
    }
}

impl PoissonSolve for MultigridCg {
    fn solve(&mut self, b: &[f64], p: &mut [f64], stop: Stop) -> SolveStats {
        let mut stats = SolveStats {
            divergence: self.weighted_residual(b, p, stop.weight),
            ..SolveStats::default()
        };
        let floor = REL_FLOOR
            * b.iter()
                .zip(stop.weight)
                .fold(0.0f64, |m, (b, w)| m.max(b.abs() * w));
        let mut aim = (AIM * stop.tol).max(floor);
        for _ in 0..ATTEMPTS {
            if stats.divergence <= stop.tol || stats.iterations >= stop.max_iterations {
                break;
            }
            let target = Target::WeightedMax {
                weight: stop.weight,
                tol: aim,
            };
            match self.solver.solve_to(b, p, target) {
                Ok(s) => stats.iterations += s.iterations,
                // Both leave the last iterate in p: a breakdown at round-off (pᵀAp ≤ 0 with a
                // residual near the floor) is judged, like a stall, by the divergence left.
                Err(
                    PoissonError::NotConverged { iterations, .. }
                    | PoissonError::Breakdown { iterations, .. },
                ) => stats.iterations += iterations,
                Err(_) => break,
            }
            stats.divergence = self.weighted_residual(b, p, stop.weight);
            aim = (aim * 0.1).max(floor);
        }
        stats.converged = stats.divergence <= stop.tol;
        stats
    }

    fn operator(&self) -> &PoissonOperator {
        &self.op
    }
}

/// The operator's per-cell "+ face" coefficients as [`FaceCoefs3`]'s per-face arrays (the same
/// numbers; outer faces Neumann, faces of solid cells zero).
fn face_coefs(op: &PoissonOperator) -> FaceCoefs3 {
    let [nx, ny, nz] = op.n;
    let (x_faces, y_faces) = ((nx + 1) * ny * nz, nx * (ny + 1) * nz);
    let [dx, dy, dz] = op.widths.clone();
    let mut f = FaceCoefs3 {
        dx,
        dy,
        dz,
        periodic_z: op.periodic_z,
        cx: vec![0.0; x_faces],
        cy: vec![0.0; y_faces],
        cz: vec![0.0; nx * ny * (nz + 1)],
    };
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let c = flat(op.n, [i, j, k]);
                let x_face = f.x_face(i + 1, j, k);
                let y_face = f.y_face(i, j + 1, k);
                f.cx[x_face] = op.coef[0][c];
                f.cy[y_face] = op.coef[1][c];
                // The + z face of the last plane is face 0 when z wraps.
                let kz = if k + 1 == nz && op.periodic_z {
                    0
                } else {
                    k + 1
                };
                let z_face = f.z_face(i, j, kz);
                f.cz[z_face] = op.coef[2][c];
            }
        }
    }
    f
}
