//! What the 3-D run tests share: a small flow at Re 200 around a plate one cell thick at N = 8
//! (1/8 chord), the outer boundary 2 chords away.
use platefall_core::flow3d::{
    FlowParams3, FlowSolver3, Frame3, Grid3, GridSpec3, OuterBc3, Span, Stretch3,
};

/// The flow at rest on the grid of `n` cells per chord with `span`, the plate moving as `frame`.
pub fn solver(n: usize, span: Span, frame: Frame3) -> FlowSolver3 {
    let spec = GridSpec3 {
        resolution: n,
        thickness: 0.125,
        span,
        extent: [2.0; 3],
        stretch: Stretch3::GrowthCap(1.2),
        memory_limit: 1e9,
        shape: Default::default(),
    };
    let params = FlowParams3 {
        re: 200.0,
        ..FlowParams3::default()
    };
    FlowSolver3::new(
        Grid3::new(&spec).unwrap(),
        params,
        OuterBc3::FarField,
        frame,
    )
    .unwrap()
}
