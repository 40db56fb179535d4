//! The body's shape in the 3-D grid (docs/three-d.md "Bodies"): every shape is inscribed in the
//! box of the grid's uniform core, half-extents (½, t/2, b/2) along x, y, z (chord, thickness,
//! span), so its extreme points fall on grid nodes at every resolution.
//!
//! The box itself (the plate) has its faces on grid lines and is treated exactly
//! ([`super::plate`]); the curved shapes cut the cells ([`super::cut`]).

/// A body inscribed in the box of half-extents `half`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Shape3 {
    /// The box itself: the rectangular plate.
    #[default]
    Box,
    /// The ellipsoid (x/a)² + (y/b)² + (z/c)² ≤ 1 (a sphere when the three are equal).
    Ellipsoid,
    /// The elliptic cylinder (x/a)² + (y/b)² ≤ 1 along the span, with flat ends at ±c (the 2-D
    /// section `ellipse` or `circle` extruded; infinite on a periodic span).
    SpanCylinder,
    /// The elliptic cylinder (x/a)² + (z/c)² ≤ 1 across the thickness, flat faces at ±b: a disk
    /// (circular when chord and span are equal).
    Disk,
}

/// Bisections of a crossing: the fraction is exact to 2⁻⁶⁰ of the segment.
const BISECTIONS: usize = 60;

impl Shape3 {
    /// Whether the shape cuts cells (anything but the box).
    pub fn is_curved(self) -> bool {
        self != Shape3::Box
    }

    /// Whether the shape spans the whole period of a periodic z (only the box and the cylinder
    /// along the span do).
    pub fn spans_z(self) -> bool {
        matches!(self, Shape3::Box | Shape3::SpanCylinder)
    }

    /// Whether the body-axes point `x` is inside the shape or on its boundary.
    #[inline]
    pub fn contains(self, half: [f64; 3], x: [f64; 3]) -> bool {
        let q = |a: usize| (x[a] / half[a]) * (x[a] / half[a]);
        let within = |a: usize| x[a].abs() <= half[a];
        match self {
            Shape3::Box => (0..3).all(within),
            Shape3::Ellipsoid => q(0) + q(1) + q(2) <= 1.0,
            Shape3::SpanCylinder => q(0) + q(1) <= 1.0 && within(2),
            Shape3::Disk => q(0) + q(2) <= 1.0 && within(1),
        }
    }

    /// The volume (chords³).
    pub fn volume(self, half: [f64; 3]) -> f64 {
        let box_volume = 8.0 * half[0] * half[1] * half[2];
        let pi = std::f64::consts::PI;
        match self {
            Shape3::Box => box_volume,
            Shape3::Ellipsoid => box_volume * pi / 6.0,
            Shape3::SpanCylinder | Shape3::Disk => box_volume * pi / 4.0,
        }
    }

    /// Where the boundary crosses the segment from `outside` to `inside` (the first point
    /// outside, the second inside or on the boundary), as the fraction of the way from
    /// `outside`: the last point outside, to 2⁻⁶⁰ of the segment.
    pub fn crossing(self, half: [f64; 3], outside: [f64; 3], inside: [f64; 3]) -> f64 {
        let at = |s: f64| std::array::from_fn(|a| outside[a] + s * (inside[a] - outside[a]));
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..BISECTIONS {
            let mid = 0.5 * (lo + hi);
            if self.contains(half, at(mid)) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        hi
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const HALF: [f64; 3] = [0.5, 0.25, 1.0];

    #[test]
    fn every_shape_holds_its_centre_and_the_box_centres_of_its_faces() {
        for s in [
            Shape3::Box,
            Shape3::Ellipsoid,
            Shape3::SpanCylinder,
            Shape3::Disk,
        ] {
            assert!(s.contains(HALF, [0.0; 3]));
            for a in 0..3 {
                let mut x = [0.0; 3];
                x[a] = HALF[a];
                assert!(s.contains(HALF, x), "{s:?} axis {a}");
                x[a] *= 1.0 + 1e-12;
                assert!(!s.contains(HALF, x), "{s:?} axis {a}");
            }
        }
    }

    #[test]
    fn the_corners_of_the_box_are_inside_the_box_only() {
        let corner = [0.49, 0.24, 0.99];
        assert!(Shape3::Box.contains(HALF, corner));
        for s in [Shape3::Ellipsoid, Shape3::SpanCylinder, Shape3::Disk] {
            assert!(!s.contains(HALF, corner), "{s:?}");
        }
    }

    /// A sphere of radius ½ crossed along a diameter's line from 1 to 0: at 0.5 exactly.
    #[test]
    fn a_crossing_is_found_to_round_off() {
        let half = [0.5; 3];
        let s = Shape3::Ellipsoid.crossing(half, [0.0, 0.0, 1.0], [0.0; 3]);
        assert!((s - 0.5).abs() < 1e-15, "{s}");
        let s = Shape3::Disk.crossing(half, [0.3, 0.6, 0.0], [0.3, 0.2, 0.0]);
        assert!((s - 0.25).abs() < 1e-15, "{s}");
    }

    #[test]
    fn volumes_are_the_closed_forms() {
        let pi = std::f64::consts::PI;
        let v = Shape3::Ellipsoid.volume([0.5; 3]);
        assert!((v - pi / 6.0).abs() < 1e-15);
        let v = Shape3::Disk.volume([0.5, 0.05, 0.5]);
        assert!((v - pi * 0.25 * 0.1).abs() < 1e-15);
    }
}
