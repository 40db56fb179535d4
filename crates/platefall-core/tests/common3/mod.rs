//! What the 3-D run tests share: a body in a small grid ([`Body`]), the plate's among them: a
//! small flow at Re 200 around a plate one cell thick at N = 8 (1/8 chord), the outer boundary
//! 2 chords away ([`PLATE`]).
use platefall_core::flow3d::{
    FlowParams3, FlowSolver3, Frame3, Grid3, GridSpec3, OuterBc3, Shape3, Span, Stretch3,
};

/// The plate one cell thick at N = 8, Re 200, the outer boundary 2 chords away (the cut-cell
/// tests, which include this module too, make their own bodies).
#[allow(dead_code)]
pub const PLATE: Body = Body {
    shape: Shape3::Box,
    thickness: 0.125,
    extent: 2.0,
    re: 200.0,
};

/// A body in a grid whose spacing grows by at most 1.2, at a Reynolds number.
pub struct Body {
    pub shape: Shape3,
    /// In chords.
    pub thickness: f64,
    /// The outer boundary's distance in chords, every way.
    pub extent: f64,
    pub re: f64,
}

impl Body {
    /// The flow at rest on the grid of `n` cells per chord with `span`, the body moving as
    /// `frame`.
    pub fn solver(&self, n: usize, span: Span, frame: Frame3) -> FlowSolver3 {
        let spec = GridSpec3 {
            resolution: n,
            thickness: self.thickness,
            span,
            extent: [self.extent; 3],
            stretch: Stretch3::GrowthCap(1.2),
            memory_limit: 1e9,
            shape: self.shape,
        };
        let params = FlowParams3 {
            re: self.re,
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
}
