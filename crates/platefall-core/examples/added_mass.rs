//! The added-mass matrix K (the discrete flow's pressure answer to a unit change of motion)
//! against potential-flow theory for ellipses, at several resolutions:
//!
//! ```text
//! cargo run --release -p platefall-core --example added_mass -- ellipse 1,0.5,0.125 32,64,128 [EXTENT]
//! ```
//!
//! prints, for each axis ratio b/a (for `rect`: thickness) and N, the added masses along,
//! across and in pitch with their differences from π b², π a², π (a² − b²)²/8 (exact for the
//! ellipse; for a rectangle, the ellipse of the same axes).
use std::f64::consts::PI;

use platefall_core::flow::{FlowParams, FlowSolver, Frame, OuterBc};
use platefall_core::grid::{Grid, GridSpec, Stretch};
use platefall_core::shape::Shape;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let list = |k: usize, default: &str| -> Vec<String> {
        args.get(k)
            .map(String::as_str)
            .unwrap_or(default)
            .split(',')
            .map(str::to_string)
            .collect()
    };
    let rect = args.get(1).is_some_and(|s| s == "rect");
    let ratios: Vec<f64> = list(2, "1,0.5,0.125")
        .iter()
        .map(|s| s.parse())
        .collect::<Result<_, _>>()?;
    let extent: f64 = args.get(4).map_or(Ok(15.0), |s| s.parse())?;
    let ns: Vec<usize> = list(3, "32,64,128")
        .iter()
        .map(|s| s.parse())
        .collect::<Result<_, _>>()?;
    println!("b/a     N    along (err %)        across (err %)       pitch (err %)");
    for &r in &ratios {
        let (a, b) = (0.5, 0.5 * r);
        let exact = [PI * b * b, PI * a * a, PI * (a * a - b * b).powi(2) / 8.0];
        for &n in &ns {
            let spec = GridSpec {
                resolution: n,
                shape: if rect {
                    Shape::rect(r)
                } else {
                    Shape::Ellipse { thickness: r }
                },
                extent_x: extent,
                extent_y: extent,
                stretch: Stretch::GrowthCap(1.045),
            };
            let grid = Grid::new(&spec)?;
            let mut flow = FlowSolver::new(
                grid,
                FlowParams::explicit(5000.0),
                OuterBc::FarField,
                Frame::default(),
            )?;
            let k = flow.added_mass();
            let got = [-k.k[0][0], -k.k[1][1], -k.k[2][2]];
            let cell = |d: usize| {
                if exact[d] > 0.0 {
                    format!("{:.5} ({:+.2})", got[d], 100.0 * (got[d] / exact[d] - 1.0))
                } else {
                    format!("{:.5} (exact 0)", got[d])
                }
            };
            println!(
                "{r:<6} {n:>4}    {:<20} {:<20} {}",
                cell(0),
                cell(1),
                cell(2)
            );
        }
    }
    Ok(())
}
