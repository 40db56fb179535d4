//! The 3-D pressure solver's cost against grid size: conjugate gradients with the multigrid
//! V-cycle (`poisson3`) on a plate's grid — spacing h = c/N over the plate, growing by 1.1 per cell
//! out to 10 chords — with and without the plate's cells blocking the flow, periodic in z (span
//! one chord, uniform) or finite (span one chord, stretched beyond the tips).
//!
//! Prints cells, levels, CG iterations to a relative residual of 1e-10 and ns per cell per solve
//! at 1 and 2 threads.
//!
//! ```text
//! cargo run --release -p platefall-core --example poisson3_cost            # all sizes
//! cargo run --release -p platefall-core --example poisson3_cost -- 8 16    # periodic N, finite N/2
//! ```
use std::time::Instant;

use platefall_core::poisson3::{plate_axis, FaceCoefs3, Poisson3};

const GROWTH: f64 = 1.1;
const EXTENT: f64 = 10.0;
const TOL: f64 = 1e-10;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let sizes = if args.is_empty() {
        vec![8, 16, 32, 64]
    } else {
        args
    };
    println!(
        "case              N   nx×ny×nz        cells  levels  iters  ns/cell 1 thr  ns/cell 2 thr"
    );
    for periodic in [true, false] {
        for plate in [false, true] {
            for &n in &sizes {
                // The finite span's grid grows in z too: half the resolution for the same cells.
                let n = if periodic { n } else { (n / 2).max(2) };
                run(n, periodic, plate)?;
            }
        }
    }
    Ok(())
}

/// The plate's grid at resolution N (see the module's documentation).
fn grid(n: usize, periodic: bool, plate: bool) -> Result<FaceCoefs3, Box<dyn std::error::Error>> {
    let h = 1.0 / n as f64;
    let thick = (n / 16).max(1);
    let dx = plate_axis(n, h, EXTENT, GROWTH);
    let dy = plate_axis(thick + 2, h, EXTENT, GROWTH);
    let dz = if periodic {
        vec![h; n]
    } else {
        plate_axis(n, h, EXTENT, GROWTH)
    };
    let (sx, sy) = ((dx.len() - n) / 2, (dy.len() - thick - 2) / 2 + 1);
    let sz = if periodic { 0 } else { (dz.len() - n) / 2 };
    let mut coefs = FaceCoefs3::open(dx, dy, dz, periodic)?;
    if plate {
        for k in sz..sz + n {
            for j in sy..sy + thick {
                for i in sx..sx + n {
                    coefs.decouple(i, j, k);
                }
            }
        }
    }
    Ok(coefs)
}

fn run(n: usize, periodic: bool, plate: bool) -> Result<(), Box<dyn std::error::Error>> {
    let coefs = grid(n, periodic, plate)?;
    let [nx, ny, nz] = coefs.shape();
    let mut solver = Poisson3::new(&coefs)?;
    let cells = solver.cells();
    // A rough right-hand side: a smooth part and a hashed, grid-scale part.
    let rhs: Vec<f64> = (0..cells)
        .map(|p| {
            let hash = (p as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 40;
            (p as f64 * 1e-3).sin() + hash as f64 / (1u64 << 24) as f64 - 0.5
        })
        .collect();
    let mut x = vec![0.0; cells];
    let mut ns = [0.0; 2];
    let mut iterations = 0;
    for (slot, threads) in [1, 2].into_iter().enumerate() {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()?;
        let repeats = (2_000_000 / cells).clamp(1, 20);
        let mut best = f64::INFINITY;
        for _ in 0..repeats {
            x.iter_mut().for_each(|v| *v = 0.0);
            let start = Instant::now();
            let stats = pool.install(|| solver.solve(&rhs, &mut x, TOL))?;
            best = best.min(start.elapsed().as_secs_f64());
            iterations = stats.iterations;
        }
        ns[slot] = best * 1e9 / cells as f64;
    }
    let case = format!(
        "{} {}",
        if periodic { "periodic" } else { "finite  " },
        if plate { "plate" } else { "open " }
    );
    println!(
        "{case:<16} {n:>3}   {:<12} {cells:>8}  {:>6}  {iterations:>5}  {:>13.0}  {:>13.0}",
        format!("{nx}×{ny}×{nz}"),
        solver.level_shapes().count(),
        ns[0],
        ns[1]
    );
    Ok(())
}
