//! The time weights of one step of the implicit far field (see the module docs of `implicit`):
//! AB2 for the explicit part (`flow/ab2.rs`), the three-level weights for the implicit one.
use crate::flow::ab2::Ab2;

/// γ₀ of the three-level implicit weights.
pub const GAMMA_OLD: f64 = 0.125;

/// The weights of one step: AB2 for the explicit part, γ₂, γ₁, γ₀ for the implicit one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Weights {
    /// The explicit part's AB2 weights.
    pub ab: Ab2,
    /// γ₂, γ₁, γ₀: the implicit operator's weights at n+1, n and n−1.
    pub g2: f64,
    /// See `g2`.
    pub g1: f64,
    /// See `g2`.
    pub g0: f64,
}

impl Weights {
    /// Weights for a step `dt` after a step `dt_prev` (0 on the first step: Euler for the
    /// explicit part, Crank–Nicolson for the implicit one).
    pub fn new(dt: f64, dt_prev: f64) -> Weights {
        let ab = Ab2::new(dt, dt_prev);
        if dt_prev <= 0.0 {
            return Weights {
                ab,
                g2: 0.5,
                g1: 0.5,
                g0: 0.0,
            };
        }
        let r = dt / dt_prev;
        Weights {
            ab,
            g2: 0.5 + GAMMA_OLD / r,
            g1: 0.5 - GAMMA_OLD - GAMMA_OLD / r,
            g0: GAMMA_OLD,
        }
    }
}
