//! The incremental pressure of the implicit far field (SPEC §3): p += A φ/Δt.
use rayon::prelude::*;

use super::{line_velocity, Part};
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
    let columns = |j: usize, out: &mut [f64]| {
        out.copy_from_slice(&phi[nx * j..nx * (j + 1)]);
        for i in (0..nx).filter(|&i| z.v_col[i]) {
            let w = -line_velocity(m, f, Component::V, false, i as isize);
            let c = u.oy.implicit_row(j, w, t);
            out[i] = (0..5)
                .map(|o| c[o] * phi[i + nx * (j + o).saturating_sub(2).min(ny - 1)])
                .sum();
        }
    };
    by_rows(scratch, nx, columns);
    let rows = |j: usize, out: &mut [f64]| {
        let src = &scratch[nx * j..nx * (j + 1)];
        if !z.u_row[j] {
            out.copy_from_slice(src);
            return;
        }
        let w = -line_velocity(m, f, Component::U, true, j as isize);
        for (i, o) in out.iter_mut().enumerate() {
            let c = v.ox.implicit_row(i, w, t);
            *o = (0..5)
                .map(|k| c[k] * src[(i + k).saturating_sub(2).min(nx - 1)])
                .sum();
        }
    };
    by_rows(phi, nx, rows);
}

/// Fills `out` row by row (rows of `nx` cells, `fill(j, row)`), on the pool's threads.
fn by_rows(out: &mut [f64], nx: usize, fill: impl Fn(usize, &mut [f64]) + Sync) {
    out.par_chunks_mut(nx)
        .enumerate()
        .with_min_len(16)
        .for_each(|(j, row)| fill(j, row));
}
