//! The wall loads alone against manufactured fields (docs/physics.md §5): pressure and velocity fields
//! given analytically at the grid's own points around an ellipse that cuts the cells, whose
//! force and moment on the ellipse follow exactly from the divergence theorem. The loads are
//! second order in the spacing, so their errors must fall by ≥ 2^1.8 per halving of h.
use std::f64::consts::PI;

use super::faces::Faces;
use super::lines::Lines;
use super::loads::Loads;
use super::stencils::Stencils;
use crate::flow::array::Padded;
use crate::flow::frame::Frame;
use crate::flow::metrics::Metrics;
use crate::grid::{Grid, GridSpec, Stretch};
use crate::shape::Shape;

/// Semi-axes of the ellipse (unit chord, thickness ½): b/a = ½, no cell face follows it.
const A: f64 = 0.5;
const B: f64 = 0.25;

/// φ = x²/a² + y²/b² − 1 vanishes on the ellipse; its Laplacian is constant.
fn phi(x: f64, y: f64) -> f64 {
    x * x / (A * A) + y * y / (B * B) - 1.0
}
const LAPLACE_PHI: f64 = 2.0 / (A * A) + 2.0 / (B * B);

/// The pressure p = x²y + xy: F = −∫∇p dA = (0, −πa³b/4), M = −∫(x ∂p/∂y − y ∂p/∂x) dA
/// = −πab(a² − b²)/4.
fn pressure(x: f64, y: f64) -> f64 {
    x * x * y + x * y
}
const PRESSURE_LOADS: [f64; 3] = [
    0.0,
    -PI * A * A * A * B / 4.0,
    -PI * A * B * (A * A - B * B) / 4.0,
];

/// The velocity u = (1 + y)φ, v = x²φ, zero on the wall (the plate at rest). The traction is
/// μ ∂u/∂n = μ f |∇φ| for u = fφ, and ∮ f |∇φ| ds = ∫ (∇f·∇φ + f Δφ) dA, which gives, with μ = 1,
/// F_x = πab Δφ, F_y = (πa³b/4)(4/a² + Δφ), M = ∮ (x t_y − y t_x) ds = −πab − Δφ πab³/4.
fn velocity(x: f64, y: f64) -> (f64, f64) {
    ((1.0 + y) * phi(x, y), x * x * phi(x, y))
}
const VISCOUS_LOADS: [f64; 3] = [
    PI * A * B * LAPLACE_PHI,
    PI * A * A * A * B / 4.0 * (4.0 / (A * A) + LAPLACE_PHI),
    -PI * A * B - LAPLACE_PHI * PI * A * B * B * B / 4.0,
];

/// The relative errors (force x, force y, moment; on the larger force for a zero component) of
/// the pressure and the viscous loads at resolution `n`.
fn errors(n: usize) -> ([f64; 3], [f64; 3]) {
    let spec = GridSpec {
        resolution: n,
        shape: Shape::Ellipse { thickness: 2.0 * B },
        extent_x: 2.0,
        extent_y: 2.0,
        stretch: Stretch::GrowthCap(1.045),
    };
    let grid = Grid::new(&spec).expect("grid");
    let body = grid.body.clone().expect("a body");
    let tol = 1e-9 * grid.h;
    let lines = Lines::new(&grid, &body);
    let faces = Faces::new(&grid, &body, &lines, tol);
    let loads = Loads::new(
        &grid,
        &body,
        &lines,
        (
            &faces,
            &Stencils::new(
                &grid,
                &body,
                &Metrics::new(&grid),
                &lines,
                (&faces.u_open, &faces.v_open),
                1.0,
            )
            .forced,
        ),
        tol,
    );
    let (nx, ny) = (grid.nx, grid.ny);
    let mut u = Padded::zeros(nx + 1, ny);
    let mut v = Padded::zeros(nx, ny + 1);
    let mut p = vec![0.0; nx * ny];
    for j in 0..ny {
        for i in 0..=nx {
            u.set(i as isize, j as isize, velocity(grid.xn[i], grid.yc[j]).0);
        }
        for i in 0..nx {
            p[i + nx * j] = pressure(grid.xc[i], grid.yc[j]);
        }
    }
    for j in 0..=ny {
        for i in 0..nx {
            v.set(i as isize, j as isize, velocity(grid.xc[i], grid.yn[j]).1);
        }
    }
    let frame = Frame::default();
    let dry = loads.evaluate(&u, &v, &p, nx, &frame, 0.0);
    let wet = loads.evaluate(&u, &v, &p, nx, &frame, 1.0);
    let relative = |got: [f64; 3], want: [f64; 3]| {
        let scale = want[0].abs().max(want[1].abs());
        let rel = |k: usize| (got[k] - want[k]).abs() / want[k].abs().max(scale);
        [rel(0), rel(1), rel(2)]
    };
    let pressure = relative([dry.fx, dry.fy, dry.moment], PRESSURE_LOADS);
    let viscous = relative(
        [wet.fx - dry.fx, wet.fy - dry.fy, wet.moment - dry.moment],
        VISCOUS_LOADS,
    );
    (pressure, viscous)
}

/// The resolutions of the study: the order is the least-squares slope of log error against
/// log h over all of them, since a cut cell's error depends on where the wall crosses it and
/// scatters by a factor of about two around its h² trend from one grid to the next.
const LEVELS: [usize; 7] = [16, 24, 32, 48, 64, 96, 128];

/// Below this relative error the fields no longer vanish on the discrete wall: the outline is a
/// polygon of 2048 vertices, whose edges lie inside the ellipse by up to 1.4e-6 chords (the
/// sagitta (Δs)²κ/8 at the tips), so the wall's φ ≈ −|∇φ| × 1.4e-6 ≈ −2e-5 bounds what a
/// sample can resolve there.
const FLOOR: f64 = 1e-4;

fn observed_order(e: &[f64]) -> f64 {
    let x: Vec<f64> = LEVELS.iter().map(|&n| -(n as f64).ln()).collect();
    let y: Vec<f64> = e.iter().map(|v| v.ln()).collect();
    let (mx, my) = (mean(&x), mean(&y));
    let sxy: f64 = x.iter().zip(&y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len() as f64
}

#[test]
fn wall_loads_converge_at_second_order_on_a_cut_ellipse() {
    let levels: Vec<_> = LEVELS.iter().map(|&n| errors(n)).collect();
    for (name, pick) in [("pressure", 0), ("viscous", 1)] {
        for (k, what) in ["F_x", "F_y", "M"].iter().enumerate() {
            let e: Vec<f64> = levels
                .iter()
                .map(|l| if pick == 0 { l.0[k] } else { l.1[k] })
                .collect();
            let largest = e.iter().copied().fold(0.0, f64::max);
            if largest < FLOOR {
                // Exact by symmetry (round-off) or at the polygon's floor: no order to measure.
                println!("{name} {what}: errors ≤ {largest:.1e} on every grid");
                continue;
            }
            let order = observed_order(&e);
            let shown: Vec<String> = e.iter().map(|v| format!("{v:.1e}")).collect();
            println!(
                "{name} {what}: errors {}, observed order {order:.2}",
                shown.join(" ")
            );
            assert!(
                order >= 1.8,
                "{name} {what}: observed order {order:.2} (errors {e:?})"
            );
        }
    }
}
