//! The stability limits of the flow step (docs/physics.md §6 "Time step") and the blow-up bound.
use super::params::FlowParams;
use crate::grid::Grid;

/// Velocities beyond this multiple of (1 + V + |θ̇|) mean the solution has blown up.
pub const BLOWUP_FACTOR: f64 = 25.0;

/// The explicit viscous limit of the flow step, `visc_safety / (4ν (1/Δx² + 1/Δy²))` on the
/// smallest cells (docs/physics.md §6 "Time step").
pub fn viscous_dt_limit(grid: &Grid, params: &FlowParams) -> f64 {
    let min = |v: &[f64]| v.iter().copied().fold(f64::INFINITY, f64::min);
    let (dx, dy) = (min(&grid.dx), min(&grid.dy));
    let nu = params.nu();
    params.visc_safety / (4.0 * nu * (1.0 / (dx * dx) + 1.0 / (dy * dy)))
}

/// The largest stable Δt of the explicit (Adams–Bashforth 2) near field, docs/physics.md §6 "Time step":
/// the harmonic combination 1/Δt = 1/Δt_conv + 1/Δt_visc of the convective limit
/// Δt_conv = CFL / max(|w_x|/Δx + |w_y|/Δy) (`rate`: that maximum) and the viscous limit.
///
/// AB2 is stable on the negative real axis only down to λΔt = −1, and the grid's odd–even mode
/// feels both terms at once: the viscous term gives it −8ν/h² (−0.8/Δt at the viscous limit
/// with its safety 0.8) and the upwind-limited convection −2 × rate (−1/Δt at CFL ½). Each
/// limit alone keeps its own part inside, but the minimum of the two does not keep the sum
/// inside where both are close (Re ≈ 40 at N = 32: an odd–even pattern in time and space next to
/// a wall); the harmonic combination does: 0.8 Δt/Δt_visc + 2 CFL Δt/Δt_conv ≤ 1 for CFL ≤ ½.
/// Where one limit is far below the other (the card's Re 4770: the viscous limit is ≈ 40 times the
/// convective one at N = 64) the combination costs a few per cent of the step.
pub fn combined_dt_limit(cfl: f64, rate: f64, dt_visc: f64) -> f64 {
    let inv = rate / cfl + 1.0 / dt_visc;
    if inv > 0.0 {
        1.0 / inv
    } else {
        f64::INFINITY
    }
}
