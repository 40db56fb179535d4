//! The plate's section as the viewer draws it: its outline (constant on-screen width, visible
//! when zoomed out) over a fill of horizontal strips that lie inside the section, for any shape.
use platefall_core::shape::{LineDir, Outline};
use rerun::components::Radius;
use rerun::{Color, LineStrips2D};

/// Points kept of an outline for drawing (a curved section's outline has thousands).
const DRAWN_POINTS: usize = 512;
/// Horizontal strips that fill the section.
const FILL_STRIPS: usize = 6;

/// The section in body coordinates, ready to draw.
#[derive(Clone, Debug)]
pub(super) struct SectionDrawing {
    /// The outline, closed (the first point repeated).
    outline: Vec<[f32; 2]>,
    /// The fill strips, each a segment inside the section.
    fill: Vec<[[f32; 2]; 2]>,
    /// Half the spacing of the fill strips (scene units).
    fill_radius: f32,
}

impl SectionDrawing {
    /// The drawing of `section` (body coordinates, chords).
    pub(super) fn new(section: &Outline) -> Self {
        let points = section.points();
        let stride = points.len().div_ceil(DRAWN_POINTS).max(1);
        let mut outline: Vec<[f32; 2]> = points
            .iter()
            .step_by(stride)
            .map(|&[x, y]| [x as f32, y as f32])
            .collect();
        if let Some(&first) = outline.first() {
            outline.push(first);
        }
        let ([_, y0], [_, y1]) = section.bounds();
        let spacing = (y1 - y0) / FILL_STRIPS as f64;
        let r = 0.5 * spacing;
        let mut fill = Vec::new();
        for k in 0..FILL_STRIPS {
            let y = y0 + (k as f64 + 0.5) * spacing;
            for piece in section.covered(LineDir::Horizontal, y).intervals {
                let (lo, hi) = (piece.lo + r, piece.hi - r);
                let (lo, hi) = if lo < hi {
                    (lo, hi)
                } else {
                    (0.5 * (lo + hi), 0.5 * (lo + hi))
                };
                fill.push([[lo as f32, y as f32], [hi as f32, y as f32]]);
            }
        }
        SectionDrawing {
            outline,
            fill,
            fill_radius: r as f32,
        }
    }

    /// The outline turned by `angle` and moved to (x, y): a strobe picture of the plate.
    pub(super) fn placed(&self, x: f64, y: f64, angle: f64) -> Vec<[f32; 2]> {
        let (s, c) = angle.sin_cos();
        self.outline
            .iter()
            .map(|&[px, py]| {
                let (px, py) = (f64::from(px), f64::from(py));
                [(x + c * px - s * py) as f32, (y + s * px + c * py) as f32]
            })
            .collect()
    }

    /// The plate drawn in a frame where it is turned by `angle`: the outline and its fill.
    pub(super) fn drawing(&self, angle: f64) -> LineStrips2D {
        let turn = |p: &[f32; 2]| -> [f32; 2] {
            let (s, c) = angle.sin_cos();
            let (x, y) = (f64::from(p[0]), f64::from(p[1]));
            [(c * x - s * y) as f32, (s * x + c * y) as f32]
        };
        let mut strips: Vec<Vec<[f32; 2]>> = vec![self.outline.iter().map(turn).collect()];
        let mut radii = vec![Radius::new_ui_points(1.5)];
        for segment in &self.fill {
            strips.push(segment.iter().map(turn).collect());
            radii.push(Radius::new_scene_units(self.fill_radius));
        }
        LineStrips2D::new(strips)
            .with_colors([Color::from_rgb(255, 255, 255)])
            .with_radii(radii)
            .with_draw_order(50.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use platefall_core::shape::Shape;

    #[test]
    fn the_fill_lies_inside_the_section_and_the_outline_is_closed() {
        for shape in [Shape::rect(0.1), Shape::Ellipse { thickness: 0.5 }] {
            let section = shape.outline();
            let d = SectionDrawing::new(&section);
            assert!(d.outline.len() <= DRAWN_POINTS + 2);
            assert_eq!(d.outline.first(), d.outline.last());
            for [a, b] in &d.fill {
                for p in [a, b] {
                    // A point of a strip with its radius stays within the section's extent.
                    let (x, y) = (f64::from(p[0]), f64::from(p[1]));
                    let r = f64::from(d.fill_radius);
                    let along = section.covered(LineDir::Horizontal, y);
                    assert!(
                        along
                            .intervals
                            .iter()
                            .any(|i| x - r >= i.lo - 1e-6 && x + r <= i.hi + 1e-6),
                        "{shape:?}: ({x}, {y}) r {r} outside"
                    );
                }
            }
        }
    }
}
