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
mod ghost_ends;
mod grid_velocity;
mod part;
mod potential;
mod state;
mod sweeps;
mod weights;

pub use ghost_ends::GhostEnds;
pub use part::{Inputs, Part};
pub use potential::factored_potential;
pub use state::State;
pub use weights::Weights;
