//! The coarsest level, solved directly: a dense Cholesky factor of its matrix, made definite on
//! each singular piece by adding (mean diagonal / cells) · 11ᵀ over the piece, which leaves the
//! solution of a compatible right-hand side unchanged and keeps the V-cycle symmetric positive
//! definite.
use nalgebra::{linalg::Cholesky, DMatrix, DVector, Dyn};

use super::error::PoissonError;
use super::level::Level;
use super::pieces::Pieces;

/// The factored coarsest level.
#[derive(Debug, Clone)]
pub(super) struct Coarsest {
    factor: Cholesky<f64, Dyn>,
    buffer: DVector<f64>,
}

impl Coarsest {
    /// Assembles and factors the level's matrix.
    pub fn new(level: &Level) -> Result<Coarsest, PoissonError> {
        let n = level.cells();
        let mut a = DMatrix::<f64>::zeros(n, n);
        let mut x = vec![0.0; n];
        let mut column = vec![0.0; n];
        // Column by column: A e_p.
        for p in 0..n {
            x[p] = 1.0;
            level.apply(&x, &mut column);
            x[p] = 0.0;
            a.column_mut(p).copy_from_slice(&column);
        }
        let pieces = Pieces::find(level);
        for piece in 0..pieces.count() {
            let cells: Vec<usize> = (0..n).filter(|&p| pieces.id[p] == piece as u32).collect();
            let diag = cells.iter().map(|&p| level.diag[p]).sum::<f64>() / cells.len() as f64;
            let shift = if diag > 0.0 { diag } else { 1.0 } / cells.len() as f64;
            for &p in &cells {
                for &q in &cells {
                    a[(p, q)] += shift;
                }
            }
        }
        let factor = Cholesky::new(a).ok_or(PoissonError::Coarsest(n))?;
        Ok(Coarsest {
            factor,
            buffer: DVector::zeros(n),
        })
    }

    /// x = A⁻¹ b (the shifted A).
    pub fn solve(&mut self, b: &[f64], x: &mut [f64]) {
        self.buffer.as_mut_slice().copy_from_slice(b);
        self.factor.solve_mut(&mut self.buffer);
        x.copy_from_slice(self.buffer.as_slice());
    }
}
