//! The circular cylinder at Re 100 in the 2-D solver and, one span period of 1/8 diameter, in the
//! 3-D solver on the same cross-section grid (docs/three-d.md "The 2-D limit"):
//!
//! ```text
//! cargo run --release -p platefall-core --example periodic_cylinder -- N DT T_END
//! ```
//!
//! Both start impulsively and take the same fixed steps. Every 0.5 time units it prints the
//! pressure drag C_Dp of each flow as each solver's wall read-out gives it (the 3-D read-out of the
//! 2-D pressure repeated along the span, the 2-D read-out of the 3-D pressure at the first cell
//! layer), which separates a difference of the flows from one of the read-outs. First it reads
//! p = x³ with both: the exact force is −3πR⁴/4 per unit span.
use platefall_core::flow::{FlowParams, FlowSolver, Frame, OuterBc};
use platefall_core::flow3d::{
    FlowParams3, FlowSolver3, Frame3, Grid3, GridSpec3, OuterBc3, Shape3, Span, Stretch3,
};
use platefall_core::grid::{Grid, GridSpec, Stretch};
use platefall_core::shape::Shape;

/// The span period in diameters.
const PERIOD: f64 = 0.125;
/// The reach of the grid and the growth of its spacing.
const EXTENT: f64 = 8.0;
const GROWTH: f64 = 1.2;
const RE: f64 = 100.0;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse())
        .collect::<Result<_, _>>()?;
    let [n, dt, t_end] = args[..] else {
        return Err("give N DT T_END".into());
    };
    let resolution = n as usize;
    let spec3 = GridSpec3 {
        resolution,
        thickness: 1.0,
        span: Span::Periodic(PERIOD),
        extent: [EXTENT; 3],
        stretch: Stretch3::GrowthCap(GROWTH),
        memory_limit: 4e9,
        shape: Shape3::SpanCylinder,
    };
    let params3 = FlowParams3 {
        re: RE,
        ..FlowParams3::default()
    };
    let frame3 = Frame3::body([1.0, 0.0, 0.0], [0.0; 3]);
    let mut s3 = FlowSolver3::new(Grid3::new(&spec3)?, params3, OuterBc3::FarField, frame3)?;
    let spec = GridSpec {
        resolution,
        shape: Shape::Ellipse { thickness: 1.0 },
        extent_x: EXTENT,
        extent_y: EXTENT,
        stretch: Stretch::GrowthCap(GROWTH),
    };
    let params = FlowParams {
        re: RE,
        ..FlowParams::default()
    };
    let frame = Frame {
        u0: 1.0,
        v0: 0.0,
        omega: 0.0,
    };
    let mut s2 = FlowSolver::new(Grid::new(&spec)?, params, OuterBc::FarField, frame)?;
    let layer = s2.grid().nx * s2.grid().ny;
    if s3.grid().n[0] * s3.grid().n[1] != layer {
        return Err("the 3-D cross-section grid differs from the 2-D grid".into());
    }
    let nz = s3.grid().n[2];
    let along_span =
        |p2: &[f64]| -> Vec<f64> { (0..nz).flat_map(|_| p2.iter().copied()).collect() };
    // Force per unit span: the 2-D loads are per unit span, the 3-D ones per period.
    let cdp2 = |s: &FlowSolver, p: &[f64]| -2.0 * s.loads_for(p).fx_pressure;
    let cdp3 = |s: &FlowSolver3, p: &[f64]| -2.0 * s.loads_for(p).force_pressure[0] / PERIOD;

    let g = s2.grid();
    let cubic: Vec<f64> = (0..layer).map(|q| g.xc[q % g.nx].powi(3)).collect();
    println!(
        "p = x³: force −{:.6} exact, −{:.6} 2-D read-out, −{:.6} 3-D read-out",
        3.0 * std::f64::consts::PI * 0.5f64.powi(4) / 4.0,
        cdp2(&s2, &cubic) / 2.0,
        cdp3(&s3, &along_span(&cubic)) / 2.0
    );
    println!(
        "    t   C_Dp of the 2-D flow: 2-D read  3-D read | of the 3-D flow: 2-D read  3-D read"
    );
    let steps = (t_end / dt).round() as usize;
    let every = ((0.5 / dt).round() as usize).max(1);
    for k in 1..=steps {
        s3.begin_step()?;
        s3.advance(dt, frame3)?;
        s2.prepare()?;
        s2.advance(dt, frame)?;
        if k % every == 0 || k == steps {
            let (p2, p3) = (s2.p(), s3.p());
            println!(
                "{:5.2}   {:26.4} {:9.4} | {:26.4} {:9.4}",
                k as f64 * dt,
                cdp2(&s2, p2),
                cdp3(&s3, &along_span(p2)),
                cdp2(&s2, &p3[..layer]),
                cdp3(&s3, p3),
            );
        }
    }
    Ok(())
}
