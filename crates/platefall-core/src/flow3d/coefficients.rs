//! The plate's force and moment coefficients in three dimensions (docs/three-d.md "Loads"),
//! extending the two-dimensional C_L, C_D, C_M of docs/physics.md §5.
//!
//! With ê the direction of the centre's velocity along the body axes, the drag is −F·ê, the lift
//! F·l̂ with l̂ = ẑ × ê normalised (perpendicular to the span and to the motion: "up" for a plate
//! moving along +x, as in 2-D) and the side force F·ŝ with ŝ = ê × l̂ (along +z when the motion
//! is in the x–y plane). Moments stay in body axes: roll about the chord (x), yaw about the
//! normal (y), pitch about the span (z, the 2-D C_M). All are on ½ρU²·S for forces and
//! ½ρU²·S·c for moments (c = 1, ρ = 1, U = 1), S the body's planform area (its projection on the
//! x–z plane): c·b for the plate and the cylinder along the span, b the span or the period of a
//! periodic span, so that a spanwise-uniform flow gives the 2-D coefficients; π c b / 4 for the
//! ellipsoid and the disk, so that a sphere's drag is on its frontal area, as usual.
use super::frame::Frame3;
use super::loads::Loads3;

/// Force and moment coefficients of the plate.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Coefficients3 {
    /// Lift C_L, along ẑ × ê.
    pub lift: f64,
    /// Drag C_D, along −ê.
    pub drag: f64,
    /// Side force C_S, along ê × l̂.
    pub side: f64,
    /// Rolling moment C_l about the chord axis x.
    pub roll: f64,
    /// Yawing moment C_n about the normal axis y.
    pub yaw: f64,
    /// Pitching moment C_m about the span axis z (the 2-D C_M).
    pub pitch: f64,
}

impl Coefficients3 {
    /// The coefficients of `loads` for a body moving as `frame`, of planform area `area`
    /// (chords², the span for a plate).
    pub fn new(loads: &Loads3, frame: &Frame3, area: f64) -> Coefficients3 {
        let [e, l, s] = wind_axes(frame.body_velocity());
        let f = loads.force;
        let dot = |a: [f64; 3]| a[0] * f[0] + a[1] * f[1] + a[2] * f[2];
        let scale = 2.0 / area;
        Coefficients3 {
            lift: scale * dot(l),
            drag: -scale * dot(e),
            side: scale * dot(s),
            roll: scale * loads.moment[0],
            yaw: scale * loads.moment[1],
            pitch: scale * loads.moment[2],
        }
    }
}

/// The right-handed wind axes (ê, l̂, ŝ) of a body-axis velocity; a plate at rest, or moving
/// along its span, takes ê = x̂ (and then l̂ = ŷ).
fn wind_axes(v: [f64; 3]) -> [[f64; 3]; 3] {
    let norm = |a: [f64; 3]| (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    let unit = |a: [f64; 3]| {
        let n = norm(a);
        a.map(|c| c / n)
    };
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let e = if norm(v) > 1e-12 {
        unit(v)
    } else {
        [1.0, 0.0, 0.0]
    };
    let up = cross([0.0, 0.0, 1.0], e);
    let l = if norm(up) > 1e-9 {
        unit(up)
    } else {
        [0.0, 1.0, 0.0]
    };
    [e, l, cross(e, l)]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn loads(force: [f64; 3], moment: [f64; 3]) -> Loads3 {
        Loads3 {
            force,
            moment,
            force_pressure: force,
        }
    }

    #[test]
    fn a_plate_moving_along_x_has_lift_up_drag_back_and_side_along_the_span() {
        let frame = Frame3::body([1.0, 0.0, 0.0], [0.0; 3]);
        let c = Coefficients3::new(&loads([-0.3, 0.8, 0.1], [0.2, -0.4, 0.6]), &frame, 2.0);
        let expected = Coefficients3 {
            lift: 0.8,
            drag: 0.3,
            side: 0.1,
            roll: 0.2,
            yaw: -0.4,
            pitch: 0.6,
        };
        assert_eq!(c, expected);
    }

    #[test]
    fn planar_motion_gives_the_two_dimensional_lift_and_drag_per_unit_span() {
        // The 2-D definitions (docs/physics.md §5): drag −F·ê, lift F·(−e_y, e_x), on ½ρU²c.
        for alpha in [0.0f64, 0.4, 1.3, 2.9, -2.0] {
            let e = [-alpha.cos(), alpha.sin()];
            let frame = Frame3::body([3.0 * e[0], 3.0 * e[1], 0.0], [0.0, 0.0, 1.0]);
            let f = [0.7, -1.1, 0.0];
            let span = 4.0;
            let c = Coefficients3::new(&loads(f.map(|v| v * span), [0.0; 3]), &frame, span);
            let drag = -2.0 * (f[0] * e[0] + f[1] * e[1]);
            let lift = 2.0 * (-f[0] * e[1] + f[1] * e[0]);
            assert!((c.drag - drag).abs() < 1e-14 && (c.lift - lift).abs() < 1e-14);
            assert!(c.side.abs() < 1e-14);
        }
    }

    #[test]
    fn wind_axes_are_orthonormal_and_right_handed() {
        for v in [
            [0.3, -0.2, 0.9],
            [0.0, 0.0, 2.0],
            [0.0; 3],
            [-1.0, 0.5, -0.1],
        ] {
            let [e, l, s] = wind_axes(v);
            let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
            for (a, b) in [(e, l), (l, s), (s, e)] {
                assert!(dot(a, b).abs() < 1e-14, "{v:?}");
            }
            for a in [e, l, s] {
                assert!((dot(a, a) - 1.0).abs() < 1e-14, "{v:?}");
            }
            // s = e × l, so det[e, l, s] = s · s = 1.
            let det = e[0] * (l[1] * s[2] - l[2] * s[1]) - e[1] * (l[0] * s[2] - l[2] * s[0])
                + e[2] * (l[0] * s[1] - l[1] * s[0]);
            assert!((det - 1.0).abs() < 1e-14, "{v:?}");
        }
    }
}
