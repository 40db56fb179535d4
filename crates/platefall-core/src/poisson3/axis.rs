//! The model axis of a plate's grid, used by the tests and the cost example: uniform spacing h
//! over the plate, growing geometrically outward.

/// Cell widths along one axis: `core` cells of width h, and on each side cells growing by the
/// ratio `growth` from h·growth until the side reaches `extent` beyond the core (the last cell
/// may end past it).
pub fn plate_axis(core: usize, h: f64, extent: f64, growth: f64) -> Vec<f64> {
    let mut side = Vec::new();
    let (mut w, mut reach) = (h, 0.0);
    while reach < extent && growth > 1.0 && h > 0.0 {
        w *= growth;
        reach += w;
        side.push(w);
    }
    let mut widths: Vec<f64> = side.iter().rev().copied().collect();
    widths.extend(std::iter::repeat_n(h, core));
    widths.extend(side);
    widths
}
