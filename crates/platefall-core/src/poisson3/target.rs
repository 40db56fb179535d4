//! When conjugate gradients stop: on the relative residual, or on the largest weighted residual
//! (the flow's largest cell divergence after the pressure correction, docs/pressure-3d.md).
use super::coefs::check_finite;
use super::error::PoissonError;
use super::vecops::Planes;

/// The stopping test of [`super::Poisson3::solve_to`]; r = b̂ − A x (b̂: the right-hand side
/// with its mean removed on each singular piece).
#[derive(Debug, Clone, Copy)]
pub enum Target<'a> {
    /// ‖r‖₂ / ‖b̂‖₂ ≤ the tolerance, in (0, 1).
    Relative(f64),
    /// max_P |r_P| w_P ≤ `tol` (> 0), the weights w ≥ 0 one per cell.
    WeightedMax {
        /// The weights w_P (for the flow, Δt / V_P: r_P w_P is cell P's divergence).
        weight: &'a [f64],
        /// The bound on the largest weighted residual.
        tol: f64,
    },
}

/// A validated [`Target`], with what its test needs precomputed.
pub(super) enum Test<'a> {
    Relative(f64),
    /// The weights, the bound, the largest weight, and √cells (max |r| w ≤ ‖r‖₂ max w, so only
    /// a residual within √cells of meeting the bound that way can have met it).
    WeightedMax {
        weight: &'a [f64],
        tol: f64,
        w_max: f64,
        sqrt_cells: f64,
    },
}

impl<'a> Test<'a> {
    /// Checks the target against a grid of `cells` cells.
    pub fn new(target: Target<'a>, cells: usize) -> Result<Test<'a>, PoissonError> {
        match target {
            Target::Relative(tol) if tol > 0.0 && tol < 1.0 => Ok(Test::Relative(tol)),
            Target::Relative(tol) => Err(PoissonError::BadTolerance(tol)),
            Target::WeightedMax { weight, tol } => {
                if weight.len() != cells {
                    return Err(PoissonError::SizeMismatch {
                        what: "weight",
                        expected: cells,
                        found: weight.len(),
                    });
                }
                check_finite("weight", weight)?;
                if !(tol > 0.0 && tol.is_finite()) || weight.iter().any(|&w| w < 0.0) {
                    return Err(PoissonError::BadTolerance(tol));
                }
                Ok(Test::WeightedMax {
                    weight,
                    tol,
                    w_max: weight.iter().fold(0.0, |m: f64, &w| m.max(w)),
                    sqrt_cells: (cells as f64).sqrt(),
                })
            }
        }
    }

    /// Whether the residual `r` of 2-norm `norm_r` meets the target (‖b̂‖₂ = `norm_b`).
    pub fn met(&self, planes: &mut Planes, r: &[f64], norm_r: f64, norm_b: f64) -> bool {
        match *self {
            Test::Relative(tol) => norm_r / norm_b <= tol,
            Test::WeightedMax {
                weight,
                tol,
                w_max,
                sqrt_cells,
            } => {
                let bound = norm_r * w_max;
                bound <= tol || (bound <= tol * sqrt_cells && planes.max_weighted(r, weight) <= tol)
            }
        }
    }
}
