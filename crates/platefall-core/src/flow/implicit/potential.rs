//! The incremental pressure of the implicit far field (docs/physics.md §3): p += A φ/Δt.
use super::grid_velocity::line_velocity;
use super::part::Part;
use crate::flow::frame::Frame;
use crate::flow::metrics::{Component, Metrics};
use crate::flow::zones::Zones;
use crate::grid::Grid;

/// φ ← (I + t L_x)(I + t L_y) φ on the cell centres, with the transport of frame `f` along the
/// split cell rows (|y_c| > Y_cut, as the u-rows) and columns (|x_c| > X_cut, as the v-columns):
/// the factored operator of the predictor applied to the projection's potential, so that the
/// incremental pressure p += Aφ/Δt carries the gradient the velocity actually received. Adding
/// φ/Δt alone would feed the factorisation error back into the next predictor through the
/// pressure, which diverges where both directions are implicit at Courant numbers ≳ 1; on a
/// uniform grid A commutes with the gradient and the feedback cancels. The cells along y are the
/// points of u along y, along x those of v along x: the same operators (`part.u.oy`, `part.v.ox`).
/// Beyond the domain φ mirrors its edge value (its zero normal gradient).
#[allow(clippy::too_many_arguments)]
pub fn factored_potential(
    phi: &mut [f64],
    scratch: &mut [f64],
    (u, v): (&Part, &Part),
    grid: &Grid,
    m: &Metrics,
    z: &Zones,
    f: &Frame,
    t: f64,
) {
    let (nx, ny) = (grid.nx, grid.ny);
    scratch.copy_from_slice(phi);
    for i in (0..nx).filter(|&i| z.v_col[i]) {
        let w = -line_velocity(m, f, Component::V, false, i as isize);
        for j in 0..ny {
            let c = u.oy.implicit_row(j, w, t);
            scratch[i + nx * j] = (0..5)
                .map(|o| c[o] * phi[i + nx * (j + o).saturating_sub(2).min(ny - 1)])
                .sum();
        }
    }
    phi.copy_from_slice(scratch);
    for j in (0..ny).filter(|&j| z.u_row[j]) {
        let w = -line_velocity(m, f, Component::U, true, j as isize);
        let src = &scratch[nx * j..nx * (j + 1)];
        let dst = &mut phi[nx * j..nx * (j + 1)];
        for (i, out) in dst.iter_mut().enumerate() {
            let c = v.ox.implicit_row(i, w, t);
            *out = (0..5)
                .map(|o| c[o] * src[(i + o).saturating_sub(2).min(nx - 1)])
                .sum();
        }
    }
}
