//! The pressure solver of the 3-D flow: the cell-centred Poisson problem A φ = b on a stretched
//! tensor-product grid (docs/physics.md §9), solved by conjugate gradients preconditioned with one
//! geometric-multigrid V-cycle.
//!
//! - The operator is the 7-point one of [`FaceCoefs3`]: a coefficient per face (area / centre
//!   distance; zero on walls — plate faces, outer Neumann faces, solid cells), optionally
//!   Dirichlet on outer faces, optionally periodic in z.
//! - Each connected piece of the grid without a Dirichlet face is singular (constants are its null
//!   space): the solver removes the right-hand side's mean over the piece (it solves the projected
//!   problem) and returns the solution of zero mean there.
//! - The V-cycle: red–black Gauss–Seidel, forward before and backward after the coarse
//!   correction (so the preconditioner is symmetric positive definite); coarse grids that merge
//!   cells along an axis only where they are thin along it (`coarsen.rs`), so stretched and
//!   high-aspect cells are coarsened along their strong direction; coarse operators
//!   rediscretised from the face coefficients; a dense Cholesky factor on the coarsest level.
//! - [`Poisson3::solve`] allocates nothing; the loops run in parallel over z-planes (rayon) on the
//!   larger levels, with results independent of the thread count.
//!
//! ```
//! use platefall_core::poisson3::{FaceCoefs3, Poisson3};
//!
//! // 8 × 6 × 4 cells, stretched in x, periodic in z, Neumann all round.
//! let dx: Vec<f64> = (0..8).map(|i| 0.1 * 1.2f64.powi(i)).collect();
//! let coefs = FaceCoefs3::open(dx, vec![0.2; 6], vec![0.25; 4], true)?;
//! let mut solver = Poisson3::new(&coefs)?;
//! let rhs: Vec<f64> = (0..solver.cells()).map(|p| (p as f64).sin()).collect();
//! let mut phi = vec![0.0; solver.cells()];
//! let stats = solver.solve(&rhs, &mut phi, 1e-10)?;
//! assert!(stats.residual <= 1e-10);
//! # Ok::<(), platefall_core::poisson3::PoissonError>(())
//! ```
mod axis;
mod coarsen;
mod coarsest;
mod coefs;
mod error;
mod level;
mod pieces;
mod target;
mod vecops;

pub use axis::plate_axis;
pub use coefs::{FaceCoefs3, Side};
pub use error::{PoissonError, SolveStats};
pub use target::Target;

use coarsen::Transfer;
use coarsest::Coarsest;
use level::Level;
use pieces::Pieces;
use target::Test;
use vecops::Planes;

/// At most this many cells on the coarsest level (its dense factor is solved every cycle).
const COARSEST_MAX: usize = 256;
/// Conjugate-gradient iterations before [`PoissonError::NotConverged`].
const MAX_ITERATIONS: usize = 500;
/// Gauss–Seidel sweeps (one red and one black half-sweep each) before and after the coarse
/// correction.
const SWEEPS: usize = 2;

/// Scratch of one level that has a coarser one: its residual and the smoother's second buffer,
/// and the coarser level's right-hand side and correction.
#[derive(Debug, Clone)]
struct Work {
    r: Vec<f64>,
    t: Vec<f64>,
    bc: Vec<f64>,
    xc: Vec<f64>,
}

/// The factored solver for one operator; build once, solve many times.
#[derive(Debug, Clone)]
pub struct Poisson3 {
    levels: Vec<Level>,
    transfers: Vec<Transfer>,
    work: Vec<Work>,
    coarsest: Coarsest,
    pieces: Pieces,
    sums: Vec<f64>,
    planes: Planes,
    r: Vec<f64>,
    z: Vec<f64>,
    p: Vec<f64>,
    q: Vec<f64>,
}

impl Poisson3 {
    /// Validates the coefficients and builds the hierarchy and the coarsest factor.
    pub fn new(coefs: &FaceCoefs3) -> Result<Poisson3, PoissonError> {
        let n = coefs.validate()?;
        let widths = [coefs.dx.clone(), coefs.dy.clone(), coefs.dz.clone()];
        let mut cz = coefs.cz.clone();
        if coefs.periodic_z {
            // Face nz is not used with a periodic z.
            let plane = n[0] * n[1];
            cz[plane * n[2]..].iter_mut().for_each(|c| *c = 0.0);
        }
        let fine = Level::new(
            n,
            coefs.periodic_z,
            widths,
            coefs.cx.clone(),
            coefs.cy.clone(),
            cz,
        );
        let hmin = fine
            .widths
            .iter()
            .flatten()
            .fold(f64::INFINITY, |a, &b| a.min(b));
        let mut target = 3.0 * hmin;
        let (mut levels, mut transfers, mut work) = (vec![fine], Vec::new(), Vec::new());
        while let Some(last) = levels.last().filter(|l| l.cells() > COARSEST_MAX) {
            let transfer = Transfer::plan(last, &mut target);
            let coarse = transfer.coarsen(last);
            work.push(Work {
                r: vec![0.0; last.cells()],
                t: vec![0.0; last.cells()],
                bc: vec![0.0; coarse.cells()],
                xc: vec![0.0; coarse.cells()],
            });
            transfers.push(transfer);
            levels.push(coarse);
            target *= 2.0;
        }
        let coarsest = Coarsest::new(levels.last().expect("the finest level"))?;
        let pieces = Pieces::find(&levels[0]);
        let cells = levels[0].cells();
        Ok(Poisson3 {
            coarsest,
            sums: vec![0.0; pieces.count()],
            pieces,
            planes: Planes::new(n[2], n[0] * n[1]),
            r: vec![0.0; cells],
            z: vec![0.0; cells],
            p: vec![0.0; cells],
            q: vec![0.0; cells],
            levels,
            transfers,
            work,
        })
    }

    /// Cells of the finest level.
    pub fn cells(&self) -> usize {
        self.levels[0].cells()
    }

    /// The shape (nx, ny, nz) of every level, finest first.
    pub fn level_shapes(&self) -> impl Iterator<Item = [usize; 3]> + '_ {
        self.levels.iter().map(|l| l.n)
    }

    /// Number of singular pieces (connected pieces without a Dirichlet face, decoupled cells
    /// included).
    pub fn singular_pieces(&self) -> usize {
        self.pieces.count()
    }

    /// y = A x.
    pub fn apply(&self, x: &[f64], y: &mut [f64]) -> Result<(), PoissonError> {
        self.check_len("x", x.len())?;
        self.check_len("y", y.len())?;
        self.levels[0].apply(x, y);
        Ok(())
    }

    /// z = M r: one V-cycle from zero (the preconditioner; symmetric positive definite).
    pub fn precondition(&mut self, r: &[f64], z: &mut [f64]) -> Result<(), PoissonError> {
        self.check_len("r", r.len())?;
        self.check_len("z", z.len())?;
        cycle(
            &self.levels,
            &self.transfers,
            &mut self.work,
            &mut self.coarsest,
            r,
            z,
        );
        Ok(())
    }

    /// Solves A x = b̂ (b̂: `rhs` with its mean removed on each singular piece) to the relative
    /// residual `tol`, starting from `x` (warm start) and leaving the solution in `x` (of zero
    /// mean on each singular piece). Allocates nothing.
    pub fn solve(
        &mut self,
        rhs: &[f64],
        x: &mut [f64],
        tol: f64,
    ) -> Result<SolveStats, PoissonError> {
        self.solve_to(rhs, x, Target::Relative(tol))
    }

    /// [`Poisson3::solve`] stopping on `target`: the relative residual, or the largest weighted
    /// residual. Allocates nothing.
    pub fn solve_to(
        &mut self,
        rhs: &[f64],
        x: &mut [f64],
        target: Target,
    ) -> Result<SolveStats, PoissonError> {
        self.check_len("rhs", rhs.len())?;
        self.check_len("x", x.len())?;
        coefs::check_finite("rhs", rhs)?;
        coefs::check_finite("x", x)?;
        let test = Test::new(target, self.cells())?;
        self.r.copy_from_slice(rhs);
        self.pieces.remove_means(&mut self.r, &mut self.sums);
        let norm_b = self.planes.dot(&self.r, &self.r).sqrt();
        if norm_b == 0.0 {
            x.iter_mut().for_each(|v| *v = 0.0);
            return Ok(SolveStats {
                iterations: 0,
                residual: 0.0,
            });
        }
        self.levels[0].apply(x, &mut self.q);
        self.planes.axpy(-1.0, &self.q, &mut self.r);
        let iterations = self.iterate(x, norm_b, &test)?;
        self.pieces.remove_means(x, &mut self.sums);
        // The true residual, from x (b̂ rebuilt in z).
        self.z.copy_from_slice(rhs);
        self.pieces.remove_means(&mut self.z, &mut self.sums);
        self.levels[0].residual(&self.z, x, &mut self.q);
        let residual = self.planes.dot(&self.q, &self.q).sqrt() / norm_b;
        Ok(SolveStats {
            iterations,
            residual,
        })
    }

    /// z = M r for the solver's own residual `r`.
    fn precondition_residual(&mut self) {
        cycle(
            &self.levels,
            &self.transfers,
            &mut self.work,
            &mut self.coarsest,
            &self.r,
            &mut self.z,
        );
    }

    /// Preconditioned conjugate gradients from the residual in `r`; returns the iterations.
    fn iterate(&mut self, x: &mut [f64], norm_b: f64, test: &Test) -> Result<usize, PoissonError> {
        let mut norm_r = self.planes.dot(&self.r, &self.r).sqrt();
        if test.met(&mut self.planes, &self.r, norm_r, norm_b) {
            return Ok(0);
        }
        self.precondition_residual();
        self.p.copy_from_slice(&self.z);
        let mut rz = self.planes.dot(&self.r, &self.z);
        for iterations in 1..=MAX_ITERATIONS {
            self.levels[0].apply(&self.p, &mut self.q);
            let curvature = self.planes.dot(&self.p, &self.q);
            // Not positive (or NaN): the operator or preconditioner is not definite here.
            if curvature.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                return Err(PoissonError::Breakdown {
                    iterations,
                    curvature,
                });
            }
            let alpha = rz / curvature;
            self.planes.axpy(alpha, &self.p, x);
            self.planes.axpy(-alpha, &self.q, &mut self.r);
            norm_r = self.planes.dot(&self.r, &self.r).sqrt();
            if test.met(&mut self.planes, &self.r, norm_r, norm_b) {
                return Ok(iterations);
            }
            self.precondition_residual();
            let rz_next = self.planes.dot(&self.r, &self.z);
            self.planes.xpby(&self.z, rz_next / rz, &mut self.p);
            rz = rz_next;
        }
        Err(PoissonError::NotConverged {
            iterations: MAX_ITERATIONS,
            residual: norm_r / norm_b,
        })
    }

    fn check_len(&self, what: &'static str, found: usize) -> Result<(), PoissonError> {
        let expected = self.cells();
        if found == expected {
            Ok(())
        } else {
            Err(PoissonError::SizeMismatch {
                what,
                expected,
                found,
            })
        }
    }
}

/// One V-cycle on `levels` (finest first) from x = 0: pre-smoothing, coarse correction (the
/// next levels' V-cycle, or the direct solve on the last), post-smoothing in reverse order.
fn cycle(
    levels: &[Level],
    transfers: &[Transfer],
    work: &mut [Work],
    coarsest: &mut Coarsest,
    b: &[f64],
    x: &mut [f64],
) {
    let Some((w, rest)) = work.split_first_mut() else {
        coarsest.solve(b, x);
        return;
    };
    let level = &levels[0];
    x.iter_mut().for_each(|v| *v = 0.0);
    smooth(level, b, x, &mut w.t, false);
    level.residual(b, x, &mut w.r);
    transfers[0].restrict(&w.r, &mut w.bc);
    cycle(
        &levels[1..],
        &transfers[1..],
        rest,
        coarsest,
        &w.bc,
        &mut w.xc,
    );
    transfers[0].prolong_add(&w.xc, x);
    smooth(level, b, x, &mut w.t, true);
}

/// [`SWEEPS`] Gauss–Seidel sweeps over the colours in order (or reversed): each half-sweep goes
/// from one buffer to the other, and an even number of them leaves the result in x.
fn smooth(level: &Level, b: &[f64], x: &mut [f64], t: &mut [f64], reverse: bool) {
    let colours = level.colours();
    for _ in 0..SWEEPS {
        for s in 0..colours {
            let c = if reverse { colours - 1 - s } else { s };
            if s % 2 == 0 {
                level.relax(b, x, t, c);
            } else {
                level.relax(b, t, x, c);
            }
        }
    }
}
