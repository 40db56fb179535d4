//! The plate's section, given by shape and size rather than by grid cells (docs/physics.md §1, §4).
//!
//! Every shape is measured in chords (the reference length c = 1) and placed with its centroid
//! at the body origin, the point the plate's motion and moments refer to. A rectangle is
//! [−½, ½] × [−t/2, t/2]; a rounded rectangle is the same box with its four corners rounded to a
//! radius r ≤ t/2; an ellipse has semi-axes ½ and t/2 (t = 1 is a circle of diameter c); a NACA
//! four-digit section has unit chord; a polygon is given by its vertices.
//!
//! The solver sees a shape through its [`Outline`] (a closed polygon, exact for rectangles and
//! polygons, finely sampled for curves) and through [`Shape::fits_grid`]: a rectangle's faces
//! lie on grid lines (the grid is fitted to them), every other shape cuts the grid's cells.
mod naca;
mod outline;

pub use naca::{NacaCode, NotNaca};
pub use outline::{Covered, Interval, LineDir, Outline};

use std::f64::consts::PI;

/// Points on each curved part of an outline: a quarter circle, or a whole ellipse / a NACA
/// surface. With 2048 points per quarter turn the polygon lies within 3·10⁻⁸ c of a curve of
/// radius ½, far below any grid's h².
const CURVE_POINTS: usize = 2048;

/// The section of the plate (chord units).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Shape {
    /// A rectangle of the chord by `thickness`, sharp corners.
    Rect {
        /// t/c, in (0, 1].
        thickness: f64,
    },
    /// A rectangle whose corners are rounded to `radius` (0 < r ≤ t/2; r = t/2 gives round ends).
    Rounded {
        /// t/c, in (0, 1].
        thickness: f64,
        /// r/c, in (0, t/2].
        radius: f64,
    },
    /// An ellipse of axes 1 (the chord) and `thickness`; thickness 1 is a circle.
    Ellipse {
        /// The minor axis over the chord, in (0, 1].
        thickness: f64,
    },
    /// A NACA four-digit section of unit chord.
    Naca {
        /// The four digits.
        code: NacaCode,
    },
    /// A closed polygon (the first vertex repeated at the end), in chord units.
    Polygon {
        /// The vertices (x, y), the first repeated at the end.
        points: Vec<[f64; 2]>,
    },
}

/// Why a shape cannot be built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ShapeError {
    /// The thickness is outside (0, 1].
    #[error("thickness {0} is out of range: accepted (0, 1] (chords)")]
    Thickness(f64),
    /// The edge radius is not in (0, t/2].
    #[error(
        "edge radius {radius} is out of range: accepted (0, {half}] (at most half the \
         thickness {thickness})"
    )]
    EdgeRadius {
        /// The radius given.
        radius: f64,
        /// The section's thickness.
        thickness: f64,
        /// The largest radius accepted, t/2.
        half: f64,
    },
    /// A polygon with fewer than three distinct vertices.
    #[error("a polygon needs at least 3 vertices besides the closing one; got {0}")]
    TooFewVertices(usize),
    /// The last vertex is not the first.
    #[error(
        "the polygon is not closed: its last vertex ({}, {}) must repeat its first ({}, {})",
        .last[0], .last[1], .first[0], .first[1]
    )]
    NotClosed {
        /// The first vertex.
        first: [f64; 2],
        /// The last vertex.
        last: [f64; 2],
    },
    /// A coordinate that is not a finite number or lies beyond ±10 chords.
    #[error("polygon vertex {index} ({x}, {y}) is out of range: accepted finite coordinates within ±10 chords")]
    Vertex {
        /// The vertex's index, from 0.
        index: usize,
        /// Its x.
        x: f64,
        /// Its y.
        y: f64,
    },
    /// Two edges cross or touch.
    #[error("the polygon intersects itself: edges {0} and {1} (numbered from 0) meet")]
    SelfIntersecting(usize, usize),
    /// No area.
    #[error("the polygon encloses no area")]
    NoArea,
}

impl Shape {
    /// A sharp-cornered rectangle of the given thickness (chords).
    pub fn rect(thickness: f64) -> Shape {
        Shape::Rect { thickness }
    }

    /// Checks the shape's numbers, naming the first bad one.
    ///
    /// # Errors
    /// [`ShapeError`] for the first bad number: a thickness outside its range, an edge radius not in
    /// (0, thickness/2], or a polygon that is not a simple outline.
    pub fn validate(&self) -> Result<(), ShapeError> {
        match self {
            Shape::Rect { thickness } | Shape::Ellipse { thickness } => check_thickness(*thickness),
            Shape::Rounded { thickness, radius } => {
                check_thickness(*thickness)?;
                let half = 0.5 * thickness;
                if !(radius.is_finite() && *radius > 0.0 && *radius <= half) {
                    return Err(ShapeError::EdgeRadius {
                        radius: *radius,
                        thickness: *thickness,
                        half,
                    });
                }
                Ok(())
            }
            Shape::Naca { .. } => Ok(()),
            Shape::Polygon { points } => check_polygon(points),
        }
    }

    /// The thickness across the chord (the extent along y), chords.
    pub fn thickness(&self) -> f64 {
        match self {
            Shape::Rect { thickness }
            | Shape::Rounded { thickness, .. }
            | Shape::Ellipse { thickness } => *thickness,
            Shape::Naca { .. } | Shape::Polygon { .. } => {
                let (lo, hi) = self.outline().bounds();
                hi[1] - lo[1]
            }
        }
    }

    /// The smallest radius of curvature of the section's rounded edges (chords): r of a rounded
    /// rectangle, b²/a = t²/2 at the tips of an ellipse, ½ for a circle; None for a section
    /// whose edges are corners (rectangle, polygon) or, for a NACA section, not computed.
    pub fn edge_radius(&self) -> Option<f64> {
        match self {
            Shape::Rounded { radius, .. } => Some(*radius),
            Shape::Ellipse { thickness } => Some(0.5 * thickness * thickness),
            Shape::Rect { .. } | Shape::Naca { .. } | Shape::Polygon { .. } => None,
        }
    }

    /// Whether the grid is fitted to the shape's faces (a rectangle: every face on a grid line,
    /// so no cell is cut).
    pub fn fits_grid(&self) -> bool {
        matches!(self, Shape::Rect { .. })
    }

    /// A short name with the defining numbers (for titles and reports).
    pub fn describe(&self) -> String {
        match self {
            Shape::Rect { thickness } => format!("rectangle t/c = {}", round4(*thickness)),
            Shape::Rounded { thickness, radius } => format!(
                "rounded rectangle t/c = {}, edge radius {} c",
                round4(*thickness),
                round4(*radius)
            ),
            Shape::Ellipse { thickness } if *thickness == 1.0 => "circle".to_string(),
            Shape::Ellipse { thickness } => format!("ellipse t/c = {}", round4(*thickness)),
            Shape::Naca { code } => code.to_string(),
            Shape::Polygon { points } => format!("polygon of {} vertices", points.len() - 1),
        }
    }

    /// The outline with its centroid at the origin (validate first; an invalid shape gives a
    /// meaningless outline).
    pub fn outline(&self) -> Outline {
        let raw = match self {
            Shape::Rect { thickness } => {
                let (a, b) = (0.5, 0.5 * thickness);
                // Exactly symmetric: the centroid is the origin, no shift.
                return Outline::new(vec![[-a, -b], [a, -b], [a, b], [-a, b]]);
            }
            Shape::Rounded { thickness, radius } => rounded(*thickness, *radius),
            Shape::Ellipse { thickness } => {
                let n = 4 * CURVE_POINTS;
                let (a, b) = (0.5, 0.5 * thickness);
                return Outline::new(
                    (0..n)
                        .map(|k| {
                            let (s, c) = (2.0 * PI * k as f64 / n as f64).sin_cos();
                            [a * c, b * s]
                        })
                        .collect(),
                );
            }
            Shape::Naca { code } => Outline::new(code.points(2 * CURVE_POINTS)),
            Shape::Polygon { points } => Outline::new(points[..points.len() - 1].to_vec()),
        };
        let c = raw.centroid();
        raw.shifted(-c[0], -c[1])
    }

    /// Area and polar second moment of area about the centroid (chord², chord⁴): the plate's
    /// m*/(ρs/ρf) and I*/(ρs/ρf). Exact for rectangles and ellipses, from the outline otherwise.
    pub fn area_moments(&self) -> (f64, f64) {
        match self {
            Shape::Rect { thickness } => {
                (*thickness, thickness * (1.0 + thickness * thickness) / 12.0)
            }
            Shape::Ellipse { thickness } => {
                let (a, b) = (0.5, 0.5 * thickness);
                (PI * a * b, PI * a * b * (a * a + b * b) / 4.0)
            }
            _ => {
                let o = self.outline();
                (o.area(), o.polar_moment())
            }
        }
    }
}

/// `x` rounded to four decimals, for names.
pub(crate) fn round4(x: f64) -> f64 {
    (x * 1e4).round() / 1e4
}

fn check_thickness(t: f64) -> Result<(), ShapeError> {
    if t.is_finite() && t > 0.0 && t <= 1.0 {
        Ok(())
    } else {
        Err(ShapeError::Thickness(t))
    }
}

fn check_polygon(points: &[[f64; 2]]) -> Result<(), ShapeError> {
    for (index, p) in points.iter().enumerate() {
        if !(p[0].is_finite() && p[1].is_finite() && p[0].abs() <= 10.0 && p[1].abs() <= 10.0) {
            return Err(ShapeError::Vertex {
                index,
                x: p[0],
                y: p[1],
            });
        }
    }
    if points.len() < 4 {
        return Err(ShapeError::TooFewVertices(points.len().saturating_sub(1)));
    }
    let (first, last) = (points[0], points[points.len() - 1]);
    if first != last {
        return Err(ShapeError::NotClosed { first, last });
    }
    let o = Outline::new(points[..points.len() - 1].to_vec());
    if let Some((a, b)) = o.self_intersection() {
        return Err(ShapeError::SelfIntersecting(a, b));
    }
    if o.area().abs() < 1e-12 {
        return Err(ShapeError::NoArea);
    }
    Ok(())
}

/// A rectangle of thickness t with corners rounded to radius r, counter-clockwise.
fn rounded(t: f64, r: f64) -> Outline {
    let (a, b) = (0.5, 0.5 * t);
    let centres = [
        [a - r, -b + r],
        [a - r, b - r],
        [-a + r, b - r],
        [-a + r, -b + r],
    ];
    let mut pts = Vec::with_capacity(4 * (CURVE_POINTS + 1));
    for (q, c) in centres.iter().enumerate() {
        // Quarter q runs from angle (q − 1)π/2 to qπ/2.
        let start = (q as f64 - 1.0) * 0.5 * PI;
        for k in 0..=CURVE_POINTS {
            let phi = start + 0.5 * PI * k as f64 / CURVE_POINTS as f64;
            let p = [c[0] + r * phi.cos(), c[1] + r * phi.sin()];
            // Round ends (r = t/2) make consecutive arcs meet: skip the repeated point.
            if pts
                .last()
                .is_none_or(|l: &[f64; 2]| (l[0] - p[0]).hypot(l[1] - p[1]) > 1e-15)
            {
                pts.push(p);
            }
        }
    }
    if (pts[0][0] - pts[pts.len() - 1][0]).hypot(pts[0][1] - pts[pts.len() - 1][1]) <= 1e-15 {
        pts.pop();
    }
    Outline::new(pts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_circle_is_as_wide_as_its_diameter_across_any_stream() {
        let circle = Shape::Ellipse { thickness: 1.0 }.outline();
        for a in [0.0, 0.4, -1.2, 0.5 * PI, 2.5] {
            let (s, c) = f64::sin_cos(a);
            assert!((circle.width_across([c, s]) - 1.0).abs() < 1e-3, "{a}");
        }
    }

    /// The radius of the circle through three points.
    fn circumradius(p: [f64; 2], q: [f64; 2], r: [f64; 2]) -> f64 {
        let d = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).hypot(a[1] - b[1]);
        let cross = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
        d(p, q) * d(q, r) * d(r, p) / (2.0 * cross.abs())
    }

    /// `edge_radius` is the outline's tightest curvature: the circle through three neighbouring
    /// outline points where it bends most has that radius.
    #[test]
    fn edge_radius_is_the_tightest_curvature_of_the_outline() {
        for shape in [
            Shape::Ellipse { thickness: 0.125 },
            Shape::Ellipse { thickness: 0.5 },
            Shape::Ellipse { thickness: 1.0 },
            Shape::Rounded {
                thickness: 0.1,
                radius: 0.02,
            },
            Shape::Rounded {
                thickness: 0.1,
                radius: 0.05,
            },
        ] {
            let pts = shape.outline().points().to_vec();
            let n = pts.len();
            let tightest = (0..n)
                .map(|i| circumradius(pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n]))
                .fold(f64::INFINITY, f64::min);
            let r = shape.edge_radius().unwrap();
            assert!(
                (tightest / r - 1.0).abs() < 1e-3,
                "{shape:?}: {tightest} against {r}"
            );
        }
        assert_eq!(Shape::rect(0.1).edge_radius(), None);
    }

    #[test]
    fn curved_outlines_match_their_exact_area_and_moment() {
        for t in [1.0, 0.5, 0.125] {
            let e = Shape::Ellipse { thickness: t };
            let (a, j) = e.area_moments();
            let o = e.outline();
            assert!(
                (o.area() - a).abs() < 1e-6 * a,
                "ellipse {t}: {} vs {a}",
                o.area()
            );
            assert!((o.polar_moment() - j).abs() < 1e-6 * j);
        }
        // Rounded with round ends: a stadium of length 1 and width t.
        let t: f64 = 0.2;
        let s = Shape::Rounded {
            thickness: t,
            radius: 0.1,
        };
        let area = (1.0 - t) * t + PI * 0.01;
        let o = s.outline();
        assert!((o.area() - area).abs() < 1e-7, "{} vs {area}", o.area());
        assert!(o.centroid()[0].abs() < 1e-12 && o.centroid()[1].abs() < 1e-12);
        let (lo, hi) = o.bounds();
        assert!((hi[1] - lo[1] - t).abs() < 1e-12 && (hi[0] - lo[0] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn bad_shapes_are_refused_with_the_value() {
        assert!(matches!(
            Shape::rect(0.0).validate(),
            Err(ShapeError::Thickness(_))
        ));
        assert!(matches!(
            Shape::rect(1.5).validate(),
            Err(ShapeError::Thickness(_))
        ));
        let r = Shape::Rounded {
            thickness: 0.1,
            radius: 0.06,
        };
        assert!(matches!(r.validate(), Err(ShapeError::EdgeRadius { .. })));
        let open = Shape::Polygon {
            points: vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
        };
        assert!(matches!(
            open.validate(),
            Err(ShapeError::TooFewVertices(_))
        ));
        let unclosed = Shape::Polygon {
            points: vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        };
        assert!(matches!(
            unclosed.validate(),
            Err(ShapeError::NotClosed { .. })
        ));
        let bow = Shape::Polygon {
            points: vec![[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0], [0.0, 0.0]],
        };
        assert!(matches!(
            bow.validate(),
            Err(ShapeError::SelfIntersecting(..))
        ));
        let tri = Shape::Polygon {
            points: vec![[0.0, 0.0], [1.0, 0.0], [0.0, 0.5], [0.0, 0.0]],
        };
        assert!(tri.validate().is_ok());
        let c = tri.outline().centroid();
        assert!(c[0].abs() < 1e-15 && c[1].abs() < 1e-15);
    }
}
