//! Implicit grid-velocity transport in the outer zone (docs/physics.md §3; the zones are in `zones.rs`).
//!
//! Because ∂g_x/∂x = 0 and ∂g_y/∂y = 0 on the body-fixed grid, each directional flux splits
//! exactly: ∂x((u − g_x)q) = ∂x(u q) − g_x ∂x q and ∂y((v − g_y)q) = ∂y(v q) − g_y ∂y q. On a
//! split line the explicit right-hand side keeps ∂(u q) (the fluid's own, small, velocity) and
//! the transport by g, written q_t + L q = … with L q = ∂(w q), w = −g, is taken implicitly with
//! the κ = 1/3 upwind-biased operator of `transport.rs` (the explicit scheme's interpolation,
//! linear: same accuracy and grid-scale dissipation as the scheme it replaces).
//!
//! Time: Adams–Bashforth 2 for the explicit part (today's scheme, so the near field, where L = 0,
//! is exactly today's), and for L the three-level second-order weights
//! (γ₂ L^{n+1}q^{n+1} + γ₁ L^n q^n + γ₀ L^{n−1}q^{n−1}) with γ₀ = 1/8, γ₂ = ½ + γ₀/r,
//! γ₁ = ½ − γ₀ − γ₀/r (r = Δt/Δt_prev): the "modified Crank–Nicolson" family of Ascher, Ruuth &
//! Wetton. Plain Crank–Nicolson (γ₀ = 0) maps modes with a large implicit Courant number to
//! ξ ≈ −1, where the AB2 extrapolation of the explicit terms amplifies them (by ≈ 1 + 4|u|/|g| per
//! step: unstable); these weights send them to |ξ| ≤ 0.45 instead. The operator at each level
//! uses that level's frame (both are known in `advance`). In delta form, with approximate
//! factorisation (error O(Δt³)):
//!
//! ```text
//!   (I + γ₂Δt L_x^{n+1})(I + γ₂Δt L_y^{n+1}) Δ = Δt[AB2(E) − G p] − Δt[γ₂L^{n+1} + γ₁L^n]q^n − γ₀Δt L^{n−1}q^{n−1}
//! ```
//!
//! solved by banded sweeps along the split rows, then the split columns (`band.rs`).
//! The pressure is incremental (the old gradient G p is in the predictor and the projection adds
//! its increment, see `potential.rs`): without it the implicit operator would act on the pressure
//! gradient and the scheme would be first order in time. Boundary values of the normal velocity at n+1 are set
//! before the sweeps and enter them as known ends; tangential ghosts enter as relations (zero on
//! the wall where g carries fluid in, zero gradient where it carries it out) or, for prescribed
//! boundaries, as known values at n+1.
use super::band::End;
use super::boundary::OuterBc;
use super::frame::Frame;
use super::metrics::{Component, Metrics};

mod part;
mod potential;
mod sweeps;

pub use part::{Inputs, Part};
pub use potential::factored_potential;

/// γ₀ of the three-level implicit weights.
pub const GAMMA_OLD: f64 = 0.125;

/// The weights of one step: AB2 for the explicit part, γ₂, γ₁, γ₀ for the implicit one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Weights {
    pub ab_new: f64,
    pub ab_old: f64,
    pub g2: f64,
    pub g1: f64,
    pub g0: f64,
}

impl Weights {
    /// Weights for a step `dt` after a step `dt_prev` (0 on the first step: Euler for the
    /// explicit part, Crank–Nicolson for the implicit one).
    pub fn new(dt: f64, dt_prev: f64) -> Weights {
        if dt_prev <= 0.0 {
            return Weights {
                ab_new: 1.0,
                ab_old: 0.0,
                g2: 0.5,
                g1: 0.5,
                g0: 0.0,
            };
        }
        let r = dt / dt_prev;
        Weights {
            ab_new: 1.0 + 0.5 * r,
            ab_old: -0.5 * r,
            g2: 0.5 + GAMMA_OLD / r,
            g1: 0.5 - GAMMA_OLD - GAMMA_OLD / r,
            g0: GAMMA_OLD,
        }
    }
}

/// The grid velocity g that carries q along a line, for the frame `f`: along a u-row g_x at its
/// height; along a v-row and a u-column the flux-weighted mean of the two neighbours that the
/// explicit flux uses (`momentum.rs`); along a v-column g_y at its abscissa. The implicit
/// transport velocity is w = −g.
pub fn line_velocity(m: &Metrics, f: &Frame, c: Component, along_x: bool, k: isize) -> f64 {
    let ku = k as usize;
    match (c, along_x) {
        (Component::U, true) => f.gx(m.y.centre(k)),
        (Component::V, true) => {
            let w = m.wy_low[ku];
            w * f.gx(m.y.centre(k - 1)) + (1.0 - w) * f.gx(m.y.centre(k))
        }
        (Component::U, false) => {
            let w = m.wx_left[ku];
            w * f.gy(m.x.centre(k - 1)) + (1.0 - w) * f.gy(m.x.centre(k))
        }
        (Component::V, false) => f.gy(m.x.centre(k)),
    }
}

/// The frame whose grid velocity is a·g(f1) + b·g(f0) (g is affine in the frame).
pub fn blend(a: f64, f1: &Frame, b: f64, f0: &Frame) -> Frame {
    Frame {
        u0: a * f1.u0 + b * f0.u0,
        v0: a * f1.v0 + b * f0.v0,
        omega: a * f1.omega + b * f0.omega,
    }
}

/// How the tangential ghosts enter the line solves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GhostEnds {
    /// Far field: rest inflow / zero-gradient outflow, by the direction w carries fluid.
    Relation,
    /// Prescribed boundary: the ghost increments are known (written by
    /// [`Part::prescribed_ghosts`]).
    Known,
}

impl GhostEnds {
    /// Whether the outer boundary is prescribed (exact values) or the far field.
    pub fn of(bc: &OuterBc) -> GhostEnds {
        match bc {
            OuterBc::FarField => GhostEnds::Relation,
            OuterBc::Prescribed(_) => GhostEnds::Known,
        }
    }

    /// The ends of a line of tangential ghosts carried at w: zero gradient at the end w carries
    /// fluid out of, zero on the wall at the other (each adds to the diagonal).
    pub fn ends(self, w: f64) -> (End, End) {
        match self {
            GhostEnds::Known => (End::Known, End::Known),
            GhostEnds::Relation => {
                let s = if w > 0.0 { -1.0 } else { 1.0 };
                (End::Relation(s), End::Relation(-s))
            }
        }
    }
}

/// The implicit far field's state: the two components' workspaces, γ₂ of the last step, and a
/// cell-sized scratch for the pressure update.
pub struct State {
    pub u: Part,
    pub v: Part,
    pub g2: f64,
    pub cells: Vec<f64>,
}

impl State {
    pub fn new(nx: usize, ny: usize, m: &Metrics) -> State {
        State {
            u: Part::new(Component::U, nx + 1, ny, m),
            v: Part::new(Component::V, nx, ny + 1, m),
            g2: 0.5,
            cells: vec![0.0; nx * ny],
        }
    }
}
